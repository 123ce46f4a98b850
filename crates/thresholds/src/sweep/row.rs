//! The rows of a sweep and their file form: the columns ([`COLUMNS`], [`UNITS`]), the header
//! that identifies a sweep ([`header_lines`], [`header_text`]), one row as one line of CSV or
//! JSON Lines ([`row_text`]), and the hint a written row gives the next point of its chunk
//! ([`hint_of`]), so that a resumed file equals an uninterrupted one byte for byte.
//!
//! CSV goes through the `csv` crate: a field is quoted when it holds a comma, a quote, a line
//! break or `#` (so that `pandas.read_csv(path, comment="#")` reads it whole); numbers are
//! written in the workspace's one format ([`numerics::format::number`]); an empty field has no
//! value.

use super::{Grid, Point};
use crate::Hint;
use numerics::format::number;

/// The results of one point (SI); `None` where a value does not exist.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The point.
    pub point: Point,
    /// V_stick (m/s).
    pub v_stick: Option<f64>,
    /// V_double_onset (m/s).
    pub v_double_onset: Option<f64>,
    /// V_stick,JKR (m/s).
    pub v_stick_jkr: f64,
    /// V_frag = 10 V_stick (m/s).
    pub v_frag: Option<f64>,
    /// The search limit when nothing bounced (m/s).
    pub no_bouncing_below: Option<f64>,
    /// The model's warnings for this point.
    pub warnings: Vec<String>,
    /// Which answered: the exact search or the master table.
    pub method: crate::ThresholdMethod,
}

/// The columns of a sweep's rows, in order: the inputs, then the results.
pub const COLUMNS: [&str; 17] = [
    "material",
    "gamma_sv",
    "young",
    "poisson",
    "density",
    "radius",
    "radius2",
    "wall",
    "t_vis",
    "k",
    "v_stick",
    "v_double_onset",
    "v_stick_jkr",
    "v_frag",
    "no_bouncing_below",
    "method",
    "warnings",
];

/// The SI units of [`COLUMNS`], for headers.
pub const UNITS: &str = "gamma_sv [J/m^2], young [Pa], poisson [dimensionless], density [kg/m^3], radius, radius2 [m], t_vis [s], k [dimensionless], v_stick, v_double_onset, v_stick_jkr, v_frag, no_bouncing_below [m/s]";

/// The file formats of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Comma-separated values after `#` header lines (pandas: `read_csv(path, comment="#")`).
    Csv,
    /// One JSON object a line, after a first line `{"sweep": {"header": [...], "columns": [...]}}`.
    Jsonl,
}

impl Format {
    /// `csv` or `jsonl`.
    pub fn name(&self) -> &'static str {
        match self {
            Format::Csv => "csv",
            Format::Jsonl => "jsonl",
        }
    }
}

/// The header lines that identify a sweep of `grid` made by `command` (the command line as it
/// determines the rows, with axes in [`super::canonical`] form): what the file is, the command,
/// the grid's order and size, the units, and what an empty field means. No timestamps: the same
/// sweep gives the same bytes.
pub fn header_lines(command: &str, grid: &Grid) -> Vec<String> {
    vec![
        "stickiness sweep: V_stick, V_double_onset, V_stick,JKR and V_frag = 10 V_stick over a grid (Arakawa & Krijt 2021)".to_string(),
        format!("command: {command}"),
        format!(
            "grid: material, gamma_sv, radius, radius2, t_vis, k (outermost first), {} {}; each T_vis seeded by its neighbour's thresholds",
            grid.len(),
            if grid.len() == 1 { "point" } else { "points" }
        ),
        format!("units: {UNITS}"),
        "an empty field has no value: v_stick, v_double_onset, v_frag without bouncing up to no_bouncing_below (else empty); radius2 on a wall".into(),
    ]
}

/// The header as written at the top of a file: `# ` lines and the column names (CSV), or one
/// JSON line holding both.
pub fn header_text(format: Format, lines: &[String]) -> String {
    match format {
        Format::Csv => {
            let mut out: String = lines.iter().map(|l| format!("# {l}\n")).collect();
            out.push_str(&COLUMNS.join(","));
            out.push('\n');
            out
        }
        Format::Jsonl => {
            let value = serde_json::json!({"sweep": {"header": lines, "columns": COLUMNS}});
            format!("{value}\n")
        }
    }
}

/// One CSV record as a line, quoted where needed (see the module documentation).
fn csv_line(fields: &[String]) -> String {
    let mut writer = csv::WriterBuilder::new()
        .comment(Some(b'#'))
        .from_writer(Vec::new());
    // writing to a Vec cannot fail, and every field is UTF-8
    let bytes = writer
        .write_record(fields)
        .ok()
        .and_then(|()| writer.into_inner().ok())
        .unwrap_or_default();
    String::from_utf8(bytes).unwrap_or_default()
}

/// One cell of a row: the value of one of [`COLUMNS`].
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A name (the material).
    Text(String),
    /// A number (SI); `None` where the value does not exist.
    Number(Option<f64>),
    /// A flag (the wall).
    Flag(bool),
    /// A list of messages (the warnings).
    List(Vec<String>),
}

/// The input cells of a point (the first [`INPUT_COLUMNS`] of [`COLUMNS`]), its material named
/// as in `grid`: what a row of the point must hold.
pub fn point_cells(grid: &Grid, p: &Point) -> [Cell; INPUT_COLUMNS] {
    let m = &p.constants;
    let n = |v: f64| Cell::Number(Some(v));
    [
        Cell::Text(grid.materials[p.material].name.clone()),
        n(m.gamma_sv),
        n(m.young),
        n(m.poisson),
        n(m.density),
        n(p.geometry.r1()),
        Cell::Number(p.geometry.r2()),
        Cell::Flag(p.geometry.is_wall()),
        n(p.t_vis),
        n(p.k),
    ]
}

/// How many of [`COLUMNS`] are inputs (the point); the rest are results.
pub const INPUT_COLUMNS: usize = 10;

impl Row {
    /// The row's cells, in the order of [`COLUMNS`] (its material named as in `grid`): the one
    /// place that maps a row to its columns, for the CSV and JSON Lines forms and the Python
    /// DataFrame alike.
    pub fn cells(&self, grid: &Grid) -> [Cell; COLUMNS.len()] {
        let [a, b, c, d, e, f, g, h, i, j] = point_cells(grid, &self.point);
        [
            a,
            b,
            c,
            d,
            e,
            f,
            g,
            h,
            i,
            j,
            Cell::Number(self.v_stick),
            Cell::Number(self.v_double_onset),
            Cell::Number(Some(self.v_stick_jkr)),
            Cell::Number(self.v_frag),
            Cell::Number(self.no_bouncing_below),
            Cell::Text(self.method.name().to_string()),
            Cell::List(self.warnings.clone()),
        ]
    }
}

impl Cell {
    /// The cell as a CSV field (before quoting).
    pub fn csv_field(&self) -> String {
        match self {
            Cell::Text(s) => s.clone(),
            Cell::Number(v) => v.map_or(String::new(), number),
            Cell::Flag(b) => b.to_string(),
            Cell::List(l) => l.join(WARNINGS_SEPARATOR),
        }
    }

    /// The cell as a JSON value.
    pub fn json(&self) -> serde_json::Value {
        match self {
            Cell::Text(s) => s.clone().into(),
            Cell::Number(v) => (*v).into(),
            Cell::Flag(b) => (*b).into(),
            Cell::List(l) => l.clone().into(),
        }
    }
}

/// The separator of the warnings of one row in a CSV field (and a Python DataFrame).
pub const WARNINGS_SEPARATOR: &str = "; ";

/// One row of `grid` as a line of the file (with its line break).
pub fn row_text(format: Format, grid: &Grid, row: &Row) -> String {
    let cells = row.cells(grid);
    match format {
        Format::Csv => csv_line(&cells.iter().map(Cell::csv_field).collect::<Vec<_>>()),
        Format::Jsonl => {
            let object: serde_json::Map<String, serde_json::Value> = COLUMNS
                .iter()
                .zip(&cells)
                .map(|(name, c)| (name.to_string(), c.json()))
                .collect();
            format!("{}\n", serde_json::Value::Object(object))
        }
    }
}

/// A written CSV line (without its line break) read back as one record.
fn csv_record(line: &str) -> Option<csv::StringRecord> {
    csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(line.as_bytes())
        .records()
        .next()?
        .ok()
}

/// The fields of a written row (one line, without its line break) by column: the CSV fields as
/// text, or the JSON object's values; `None` if the line is not a row of [`COLUMNS`].
pub fn row_fields(format: Format, line: &str) -> Option<Vec<serde_json::Value>> {
    match format {
        Format::Csv => {
            let record = csv_record(line)?;
            (record.len() == COLUMNS.len())
                .then(|| record.iter().map(|f| f.to_string().into()).collect())
        }
        Format::Jsonl => {
            let v: serde_json::Value = serde_json::from_str(line).ok()?;
            let o = v.as_object()?;
            (o.len() == COLUMNS.len())
                .then(|| COLUMNS.iter().map(|c| o.get(*c).cloned()).collect())
                .flatten()
        }
    }
}

/// The hint a written row (one line of the file, without its line break) gives the next point
/// of its chunk: its two thresholds, when it has both.
pub fn hint_of(format: Format, line: &str) -> Option<Hint> {
    let (onset, stick) = match format {
        Format::Csv => {
            let record = csv_record(line)?;
            let at = |name: &str| -> Option<f64> {
                let i = COLUMNS.iter().position(|c| *c == name)?;
                record.get(i)?.parse().ok()
            };
            (at("v_double_onset"), at("v_stick"))
        }
        Format::Jsonl => {
            let v: serde_json::Value = serde_json::from_str(line).ok()?;
            (v["v_double_onset"].as_f64(), v["v_stick"].as_f64())
        }
    };
    Hint::from_thresholds(onset, stick)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// RFC 4180 quoting, and `#` quoted so that pandas' `comment="#"` cannot cut a row.
    #[test]
    fn csv_fields_are_quoted_where_needed() {
        let line = csv_line(&[
            "co2".into(),
            "a, b".into(),
            "say \"hi\"".into(),
            "#1".into(),
            String::new(),
        ]);
        assert_eq!(line, "co2,\"a, b\",\"say \"\"hi\"\"\",\"#1\",\n");
    }

    /// A written CSV row reads back to its thresholds (quoted fields before them included).
    #[test]
    fn hints_read_back_from_rows() {
        let mut fields = vec![String::new(); COLUMNS.len()];
        fields[0] = "odd, \"name\"".into();
        fields[10] = "0.0414".into(); // v_stick
        fields[11] = "0.0403".into(); // v_double_onset
        let line = csv_line(&fields);
        let h = hint_of(Format::Csv, line.trim_end()).unwrap();
        assert_eq!((h.v_double_onset, h.v_stick), (0.0403, 0.0414));
        fields[10] = String::new();
        assert_eq!(hint_of(Format::Csv, csv_line(&fields).trim_end()), None);
        let json = r#"{"v_stick": 0.0414, "v_double_onset": 0.0403}"#;
        assert_eq!(
            hint_of(Format::Jsonl, json).map(|h| h.v_stick),
            Some(0.0414)
        );
    }
}
