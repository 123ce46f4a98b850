//! Printing a result: aligned `name = value unit` lines by default, one JSON object with `--json`.

use crate::error::CliError;
use serde_json::{Map, Value};

/// One command's result: named numbers with units, plus free-form JSON fields and warnings.
#[derive(Debug, Default)]
pub struct Report {
    title: String,
    rows: Vec<(String, Value, &'static str)>,
    warnings: Vec<String>,
}

impl Report {
    /// An empty report with a one-line title for the human-readable form.
    pub fn new(title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            rows: Vec::new(),
            warnings: Vec::new(),
        }
    }

    /// Adds a number (SI `unit`). A NaN or infinity is refused: the CLI never prints one.
    pub fn number(&mut self, key: &str, value: f64, unit: &'static str) -> Result<(), CliError> {
        if !value.is_finite() {
            return Err(CliError::Compute(format!(
                "internal error: {key} = {value} is not finite"
            )));
        }
        self.rows.push((key.to_string(), Value::from(value), unit));
        Ok(())
    }

    /// Adds any JSON value (a string, a list, null).
    pub fn value(&mut self, key: &str, value: Value, unit: &'static str) {
        self.rows.push((key.to_string(), value, unit));
    }

    /// Adds the model's warnings for a contact (printed on stderr, listed in JSON).
    pub fn warn_about(&mut self, contact: &contact::Contact) {
        self.warnings
            .extend(contact.warnings().iter().map(|w| w.to_string()));
    }

    /// The report as one JSON object (keys in insertion order), with a `warnings` list.
    pub fn to_json(&self) -> String {
        let mut map = Map::new();
        for (k, v, _) in &self.rows {
            map.insert(k.clone(), v.clone());
        }
        map.insert(
            "warnings".into(),
            Value::Array(self.warnings.iter().cloned().map(Value::from).collect()),
        );
        Value::Object(map).to_string()
    }

    /// The report as aligned human-readable lines.
    pub fn to_human(&self) -> String {
        let width = self.rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
        let mut out = format!("{}\n", self.title);
        for (k, v, unit) in &self.rows {
            let shown = match v {
                Value::Number(n) => n.as_f64().map_or_else(|| n.to_string(), significant),
                Value::String(s) => s.clone(),
                Value::Null => "none".into(),
                other => other.to_string(),
            };
            out.push_str(&format!("  {k:<width$} = {shown} {unit}\n"));
        }
        out
    }

    /// Prints the report in the requested form; warnings also go to stderr.
    pub fn print(&self, json: bool) {
        for w in &self.warnings {
            eprintln!("warning: {w}");
        }
        if json {
            println!("{}", self.to_json());
        } else {
            print!("{}", self.to_human());
        }
    }
}

/// `x` with 7 significant figures: fixed notation for 1e-3 <= |x| < 1e5, scientific otherwise.
fn significant(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let exponent = x.abs().log10().floor();
    if (-3.0..5.0).contains(&exponent) {
        let decimals = (6.0 - exponent).max(0.0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.6e}")
    }
}

#[cfg(test)]
mod tests {
    use super::significant;

    #[test]
    fn seven_significant_figures() {
        assert_eq!(significant(9.517010630424188), "9.517011");
        assert_eq!(significant(0.01659400272627634), "0.01659400");
        assert_eq!(significant(7.076616500642095e-7), "7.076617e-7");
        assert_eq!(significant(0.0), "0");
        assert_eq!(significant(-0.5947867075549149), "-0.5947867");
        assert_eq!(significant(1234.5678), "1234.568");
    }
}
