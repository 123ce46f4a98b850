//! Printing a result: aligned `name = value unit` lines by default, one JSON object with `--json`.
//!
//! Every number is printed in the workspace's one format ([`numerics::format::number`]: the
//! shortest form that reads back to the same value, as in JSON), in text as in JSON.

use crate::error::CliError;
use numerics::format::number;
use serde_json::{Map, Value};

/// One line of a report.
#[derive(Debug)]
struct Row {
    key: String,
    value: Value,
    unit: &'static str,
    /// What the text form says for a `null` value.
    none: String,
    /// Shown in the text form too (false: JSON only).
    in_text: bool,
}

/// One command's result: an `"input"` object, named values with units, and warnings.
#[derive(Debug, Default)]
pub struct Report {
    title: String,
    input: Option<Map<String, Value>>,
    rows: Vec<Row>,
    warnings: Vec<String>,
}

impl Report {
    /// An empty report with a one-line title for the text form.
    pub fn new(title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            ..Self::default()
        }
    }

    /// Sets the `"input"` object (the inputs as used).
    pub fn input(&mut self, input: Map<String, Value>) {
        self.input = Some(input);
    }

    /// Adds a number (SI `unit`). A NaN or infinity is refused: the CLI never prints one.
    pub fn number(&mut self, key: &str, value: f64, unit: &'static str) -> Result<(), CliError> {
        if !value.is_finite() {
            return Err(CliError::Compute(format!(
                "internal error: {key} = {} is not finite",
                number(value)
            )));
        }
        self.push(key, Value::from(value), unit, "");
        Ok(())
    }

    /// Adds a number that may be absent: `null` in JSON, `none` (a sentence) in text.
    pub fn optional(
        &mut self,
        key: &str,
        value: Option<f64>,
        unit: &'static str,
        none: impl Into<String>,
    ) -> Result<(), CliError> {
        match value {
            Some(v) => self.number(key, v, unit),
            None => {
                self.push(key, Value::Null, unit, &none.into());
                Ok(())
            }
        }
    }

    /// Adds a count (an integer).
    pub fn count(&mut self, key: &str, n: usize) {
        self.push(key, Value::from(n), "", "");
    }

    /// Adds a string.
    pub fn text(&mut self, key: &str, value: &str) {
        self.push(key, Value::from(value), "", "");
    }

    /// Adds a value to the JSON form only (the text form says it another way).
    pub fn json_only(&mut self, key: &str, value: Value) {
        self.push(key, value, "", "");
        if let Some(r) = self.rows.last_mut() {
            r.in_text = false;
        }
    }

    fn push(&mut self, key: &str, value: Value, unit: &'static str, none: &str) {
        self.rows.push(Row {
            key: key.into(),
            value,
            unit,
            none: none.into(),
            in_text: true,
        });
    }

    /// Adds warnings (printed on stderr, listed in JSON).
    pub fn warn(&mut self, warnings: impl IntoIterator<Item = impl ToString>) {
        self.warnings
            .extend(warnings.into_iter().map(|w| w.to_string()));
    }

    /// The report as one JSON object: `"input"` first, then the values in order, then `"warnings"`.
    pub fn to_json(&self) -> String {
        let mut map = Map::new();
        if let Some(input) = &self.input {
            map.insert("input".into(), Value::Object(input.clone()));
        }
        for r in &self.rows {
            map.insert(r.key.clone(), r.value.clone());
        }
        map.insert(
            "warnings".into(),
            Value::Array(self.warnings.iter().cloned().map(Value::from).collect()),
        );
        Value::Object(map).to_string()
    }

    /// The report as aligned text lines, without trailing spaces.
    pub fn to_human(&self) -> String {
        let shown = || self.rows.iter().filter(|r| r.in_text);
        let width = shown().map(|r| r.key.len()).max().unwrap_or(0);
        let mut out = format!("{}\n", self.title);
        for r in shown() {
            let shown = match &r.value {
                Value::Number(n) if n.is_f64() => n.as_f64().map_or_else(|| n.to_string(), number),
                Value::Number(n) => n.to_string(),
                Value::String(s) => s.clone(),
                Value::Null => r.none.clone(),
                other => other.to_string(),
            };
            let unit = if r.value.is_number() { r.unit } else { "" };
            let line = format!("  {:<width$} = {shown} {unit}", r.key);
            out.push_str(line.trim_end());
            out.push('\n');
        }
        out
    }

    /// Prints the report in the requested form; warnings also go to stderr.
    pub fn print(&self, json: bool) {
        print_warnings(&self.warnings);
        if json {
            println!("{}", self.to_json());
        } else {
            print!("{}", self.to_human());
        }
    }
}

/// Warnings on stderr, one line each, as every command prints them.
pub fn print_warnings(warnings: &[String]) {
    for w in warnings {
        eprintln!("warning: {w}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_form_uses_the_json_number_format_and_no_trailing_spaces() {
        let mut r = Report::new("title");
        r.number("a_eq", 7.076616500642095e-7, "m").unwrap();
        r.number("tabor", 9.5, "").unwrap();
        r.optional("v_stick", None, "m/s", "no bouncing up to 2.0 m/s")
            .unwrap();
        let text = r.to_human();
        assert!(
            text.contains("a_eq    = 7.076616500642095e-7 m\n"),
            "{text}"
        );
        assert!(text.contains("tabor   = 9.5\n"), "{text}");
        assert!(
            text.contains("v_stick = no bouncing up to 2.0 m/s\n"),
            "{text}"
        );
        assert!(text.lines().all(|l| !l.ends_with(' ')));
        let json: Value = serde_json::from_str(&r.to_json()).unwrap();
        assert_eq!(json["v_stick"], Value::Null);
        assert_eq!(json["warnings"], Value::Array(vec![]));
    }
}
