//! The master table's text form: `#` header lines, then one record a line:
//! ```text
//! k,0.01
//! row,<y>,<x_hi>,<cliff>          a row of constant y = log10(c_D c_a)
//! node,<x>,<F>,<F_on>             a node of the row above: x = log10 c_D, F = V_stick/V_stick,JKR,
//!                                 F_on = V_double_onset/V_stick,JKR
//! cell,<x_hi>                     between the row above and the next: vouched up to x_hi
//! ```
//! Numbers in the workspace's one format (shortest round trip); `inf` for no cliff found.

use super::{MasterTable, Row};
use numerics::format::number;

/// Significant figures of the ratios written: 13, far below the nodes' own error (about 2e-7).
const DIGITS: usize = 13;

/// `v` rounded to [`DIGITS`] significant figures.
fn rounded(v: f64) -> f64 {
    format!("{:.*e}", DIGITS - 1, v).parse().unwrap_or(v)
}

/// A table file that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("master table, line {line}: {problem}")]
pub struct TableFileError {
    /// 1-based line number.
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

impl MasterTable {
    /// The table as text (see the module documentation of `master::file`).
    pub fn to_text(&self) -> String {
        let mut out: String = self.header.iter().map(|h| format!("# {h}\n")).collect();
        out.push_str(&format!("k,{}\n", number(self.k)));
        for (j, r) in self.rows.iter().enumerate() {
            out.push_str(&format!(
                "row,{},{},{}\n",
                number(r.y),
                number(r.x_hi),
                number(r.cliff)
            ));
            for i in 0..r.x.len() {
                out.push_str(&format!(
                    "node,{},{},{}\n",
                    number(r.x[i]),
                    number(rounded(1.0 + r.g_stick[i].exp())),
                    number(rounded(1.0 + r.g_onset[i].exp()))
                ));
            }
            if let Some(c) = self.cells.get(j) {
                out.push_str(&format!("cell,{}\n", number(*c)));
            }
        }
        out
    }

    /// Reads a table from its text (`bytes`, UTF-8).
    pub fn parse(bytes: &[u8]) -> Result<MasterTable, TableFileError> {
        let text = std::str::from_utf8(bytes).map_err(|e| TableFileError {
            line: 0,
            problem: e.to_string(),
        })?;
        let mut table = MasterTable::new(f64::NAN, Vec::new(), Vec::new(), Vec::new());
        for (i, line) in text.lines().enumerate() {
            let bad = |problem: &str| TableFileError {
                line: i + 1,
                problem: problem.to_string(),
            };
            if let Some(h) = line.strip_prefix('#') {
                table.header.push(h.trim_start().to_string());
                continue;
            }
            let fields: Vec<&str> = line.split(',').collect();
            let num = |j: usize| -> Result<f64, TableFileError> {
                fields
                    .get(j)
                    .and_then(|f| f.trim().parse::<f64>().ok())
                    .ok_or_else(|| bad(&format!("field {j} is not a number")))
            };
            let g = |f: f64| -> Result<f64, TableFileError> {
                if f > 1.0 && f.is_finite() {
                    Ok((f - 1.0).ln())
                } else {
                    Err(bad("a ratio must be > 1"))
                }
            };
            match fields[0] {
                "k" => table.k = num(1)?,
                "row" => table.rows.push(Row {
                    y: num(1)?,
                    x: Vec::new(),
                    g_stick: Vec::new(),
                    g_onset: Vec::new(),
                    x_hi: num(2)?,
                    cliff: num(3)?,
                }),
                "node" => {
                    let r = table
                        .rows
                        .last_mut()
                        .ok_or_else(|| bad("a node before any row"))?;
                    let x = num(1)?;
                    if r.x.last().is_some_and(|&p| p >= x) {
                        return Err(bad("nodes must increase in x"));
                    }
                    r.x.push(x);
                    r.g_stick.push(g(num(2)?)?);
                    r.g_onset.push(g(num(3)?)?);
                }
                "cell" => table.cells.push(num(1)?),
                "" => {}
                other => return Err(bad(&format!("unknown record '{other}'"))),
            }
        }
        let ordered = table.rows.windows(2).all(|w| w[0].y < w[1].y);
        let sized = table.cells.len() + 1 == table.rows.len() || table.rows.is_empty();
        let filled = table.rows.iter().all(|r| r.x.len() >= 2);
        if !(table.k > 0.0 && table.k < 1.0 && ordered && sized && filled) {
            return Err(TableFileError {
                line: 0,
                problem: "a table needs k in (0, 1), rows increasing in y with two nodes or more, and a cell between each two rows".into(),
            });
        }
        Ok(MasterTable::new(
            table.k,
            table.header,
            table.rows,
            table.cells,
        ))
    }
}
