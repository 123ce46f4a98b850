//! A figure's data table and its CSV form: `#` comment lines (figure, material, parameters,
//! units), one header row of snake_case names, then rows. `pandas.read_csv(path, comment="#")` and
//! `numpy.genfromtxt(path, delimiter=",", names=True, comments="#", dtype=None)` read it; a missing
//! value (for example V_stick where no collision bounces) is an empty field, read as NaN.

use std::fmt::Write as _;

/// Columns compared relative to their largest magnitude by [`Table::compare`].
pub const SCALED_COLUMNS: [&str; 6] = ["t", "a", "delta", "delta_dot", "e", "e_computed"];

/// One cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A number (SI).
    Num(f64),
    /// A label (an outcome, a panel).
    Text(String),
    /// No value (for example no bouncing below the search limit).
    Missing,
}

impl From<f64> for Cell {
    fn from(v: f64) -> Self {
        if v.is_finite() {
            Cell::Num(v)
        } else {
            Cell::Missing
        }
    }
}

impl From<Option<f64>> for Cell {
    fn from(v: Option<f64>) -> Self {
        v.map_or(Cell::Missing, Cell::from)
    }
}

impl From<&str> for Cell {
    fn from(v: &str) -> Self {
        Cell::Text(v.to_string())
    }
}

/// A table written to `data/<file>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// File name, e.g. `fig4.csv`.
    pub file: String,
    /// Comment lines without the leading `# `.
    pub comments: Vec<String>,
    /// Column names.
    pub columns: Vec<String>,
    /// Rows, one cell per column.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// An empty table.
    pub fn new(file: &str, comments: Vec<String>, columns: &[&str]) -> Self {
        Self {
            file: file.to_string(),
            comments,
            columns: columns.iter().map(|c| c.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Appends a row.
    pub fn push(&mut self, row: Vec<Cell>) {
        self.rows.push(row);
    }

    /// The CSV text, numbers with `digits` significant figures.
    pub fn to_csv(&self, digits: usize) -> String {
        let mut out = String::new();
        for c in &self.comments {
            let _ = writeln!(out, "# {c}");
        }
        let _ = writeln!(out, "{}", self.columns.join(","));
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|c| match c {
                    Cell::Num(v) => format!("{:.*e}", digits.saturating_sub(1), v),
                    Cell::Text(t) => t.clone(),
                    Cell::Missing => String::new(),
                })
                .collect();
            let _ = writeln!(out, "{}", cells.join(","));
        }
        out
    }

    /// Parses the CSV form (comments are kept, numbers parsed, other fields kept as text).
    pub fn from_csv(file: &str, text: &str) -> Result<Self, String> {
        let mut comments = Vec::new();
        let mut lines = text.lines();
        let header = loop {
            match lines.next() {
                Some(l) if l.starts_with('#') => {
                    comments.push(l.trim_start_matches('#').trim_start().to_string())
                }
                Some(l) => break l,
                None => return Err(format!("{file}: no header row")),
            }
        };
        let columns: Vec<String> = header.split(',').map(str::to_string).collect();
        let mut rows = Vec::new();
        for (i, l) in lines.enumerate() {
            let cells: Vec<Cell> = l
                .split(',')
                .map(|f| {
                    if f.is_empty() {
                        Cell::Missing
                    } else if let Ok(v) = f.parse::<f64>() {
                        Cell::Num(v)
                    } else {
                        Cell::Text(f.to_string())
                    }
                })
                .collect();
            if cells.len() != columns.len() {
                return Err(format!(
                    "{file}: row {} has {} fields, expected {}",
                    i + 1,
                    cells.len(),
                    columns.len()
                ));
            }
            rows.push(cells);
        }
        Ok(Self {
            file: file.to_string(),
            comments,
            columns,
            rows,
        })
    }

    /// Compares with `expected`: same columns and rows, texts and missing cells equal, numbers
    /// within `rel_tol` relative to the larger of the two magnitudes, except in the columns of
    /// [`SCALED_COLUMNS`] (trajectories and restitution coefficients, which cross zero and whose
    /// resampled points carry interpolation noise), where `rel_tol` is relative to the column's
    /// largest magnitude. Returns the differences found (at most 10).
    pub fn compare(&self, expected: &Table, rel_tol: f64) -> Vec<String> {
        let mut diffs = Vec::new();
        if self.columns != expected.columns {
            diffs.push(format!(
                "{}: columns {:?} != expected {:?}",
                self.file, self.columns, expected.columns
            ));
            return diffs;
        }
        if self.rows.len() != expected.rows.len() {
            diffs.push(format!(
                "{}: {} rows, expected {}",
                self.file,
                self.rows.len(),
                expected.rows.len()
            ));
            return diffs;
        }
        let floor: Vec<f64> = self
            .columns
            .iter()
            .enumerate()
            .map(|(j, name)| {
                if !SCALED_COLUMNS.contains(&name.as_str()) {
                    return 0.0;
                }
                expected
                    .rows
                    .iter()
                    .filter_map(|r| match r[j] {
                        Cell::Num(v) => Some(v.abs()),
                        _ => None,
                    })
                    .fold(0.0, f64::max)
            })
            .collect();
        for (i, (a, b)) in self.rows.iter().zip(&expected.rows).enumerate() {
            for (j, (x, y)) in a.iter().zip(b).enumerate() {
                let same = match (x, y) {
                    (Cell::Num(x), Cell::Num(y)) => {
                        let size = x.abs().max(y.abs()).max(floor[j]);
                        (x - y).abs() <= rel_tol * size || x == y
                    }
                    _ => x == y,
                };
                if !same && diffs.len() < 10 {
                    diffs.push(format!(
                        "{} row {} column {}: computed {:?}, committed {:?}",
                        self.file,
                        i + 1,
                        self.columns[j],
                        x,
                        y
                    ));
                }
            }
        }
        diffs
    }
}
