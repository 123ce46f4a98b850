//! Resuming a sweep: the complete rows of a file written before an interruption, checked
//! against the grid points they stand for ([`check_rows`], and by recomputing a sample:
//! [`verify_rows`]), and what is left of each chunk with the hints its written rows give, so
//! that the rest is computed exactly as an uninterrupted run would have ([`remaining`]). File
//! I/O stays with the caller.
//!
//! What the checks find: a row deleted, duplicated or moved (its inputs are those of another
//! grid point), an input edited, a result that does not read as its column's type, rows beyond
//! the grid; with [`verify_rows`], a result edited in a row it recomputes. What they cannot
//! find: an edited result in a row not recomputed, if it still reads as a number.

use super::row::{point_cells, row_fields, INPUT_COLUMNS};
use super::{hint_of, Chunk, Format, Grid, Laws, Point, COLUMNS};
use crate::{Hint, SearchOptions, ThresholdMethod, ThresholdsError, HINT_NEIGHBOURS};

/// The rows already in a file of a sweep.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    /// The complete rows (lines without their line break), in grid order.
    pub rows: Vec<String>,
    /// The length (bytes) of the file up to its last complete row: a torn last line (a kill
    /// mid-write) lies beyond it and is to be cut off. 0 when not even the header is complete.
    pub complete_len: usize,
}

impl Written {
    /// Whether the file's header is complete and kept: `false` for a file killed before its
    /// header was (then the header is to be written again).
    pub fn keeps_header(&self) -> bool {
        self.complete_len > 0
    }
}

/// The text of a sweep file as read (bytes): all of it, or all but a character a kill tore at
/// its end (a non-ASCII path or name cut mid-write; the torn line is cut off anyway); `None`
/// if it is not UTF-8 elsewhere (not a file of a sweep).
///
/// # Example
/// ```
/// use thresholds::sweep::file_text;
/// let whole = "# glac\u{e9}.json\n".as_bytes();
/// assert_eq!(file_text(&whole[..7]), Some("# glac"));
/// assert_eq!(file_text(whole), Some("# glac\u{e9}.json\n"));
/// assert_eq!(file_text(b"# \xff rest"), None);
/// ```
pub fn file_text(bytes: &[u8]) -> Option<&str> {
    match std::str::from_utf8(bytes) {
        Ok(text) => Some(text),
        // error_len None: the input ended inside a character
        Err(e) if e.error_len().is_none() => std::str::from_utf8(&bytes[..e.valid_up_to()]).ok(),
        Err(_) => None,
    }
}

/// The complete rows of the file `text` if it holds the sweep whose header is `header` (as
/// [`super::header_text`] writes it); `None` if it holds another sweep.
///
/// A file killed before its header was complete (empty, or a beginning of `header`) holds no
/// rows of any sweep: it is this sweep's with no rows and `complete_len` 0 (the header is to
/// be written again).
///
/// # Example
/// ```
/// use thresholds::sweep::written_rows;
/// let w = written_rows("# h\nrow 1\nrow 2\nrow", "# h\n").unwrap();
/// assert_eq!(w.rows, ["row 1", "row 2"]);
/// assert_eq!(w.complete_len, "# h\nrow 1\nrow 2\n".len()); // the torn "row" is cut off
/// assert!(written_rows("# other\n", "# h\n").is_none());
/// // killed while writing the header; the beginning of another sweep's header is refused
/// assert!(!written_rows("# ", "# h\n").unwrap().keeps_header());
/// assert!(written_rows("# o", "# h\n").is_none());
/// ```
pub fn written_rows(text: &str, header: &str) -> Option<Written> {
    if text.len() < header.len() && header.starts_with(text) {
        return Some(Written {
            rows: Vec::new(),
            complete_len: 0,
        });
    }
    let rest = text.strip_prefix(header)?;
    let complete = rest.rfind('\n').map_or(0, |i| i + 1);
    Some(Written {
        rows: rest[..complete].lines().map(str::to_string).collect(),
        complete_len: header.len() + complete,
    })
}

/// What is left of one chunk of a grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Remaining {
    /// The chunk.
    pub chunk: Chunk,
    /// Index in `chunk.points` of its first point not yet written.
    pub start: usize,
    /// `(t_vis, thresholds)` of the chunk's last [`HINT_NEIGHBOURS`] written points (fewer at its
    /// start), the hints of an uninterrupted run ([`Chunk::compute_from`]).
    pub previous: Vec<(f64, Hint)>,
}

/// The chunks of `grid` that still have points after the `written` rows (lines in `format`, in
/// grid order), each from its first missing point, with the hints its written rows give.
pub fn remaining(grid: &Grid, written: &[String], format: Format) -> Vec<Remaining> {
    let done = written.len();
    grid.chunks()
        .into_iter()
        .filter_map(|chunk| {
            let start = chunk.points.iter().take_while(|p| p.index < done).count();
            if start == chunk.points.len() {
                return None;
            }
            let mut previous: Vec<(f64, Hint)> = chunk.points[..start]
                .iter()
                .rev()
                .take(HINT_NEIGHBOURS)
                .map_while(|p| Some((p.t_vis, hint_of(format, written.get(p.index)?)?)))
                .collect();
            previous.reverse();
            Some(Remaining {
                chunk,
                start,
                previous,
            })
        })
        .collect()
}

/// A written row that a resume cannot keep: where it is and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line}, column {column}: {problem}")]
pub struct BadRow {
    /// Line number in the file (1-based).
    pub line: usize,
    /// The column (one of [`COLUMNS`]), or `"row"` for the line as a whole.
    pub column: String,
    /// What was found and what was expected.
    pub problem: String,
}

/// The grid's points in grid order.
fn points_in_order(grid: &Grid) -> Vec<Point> {
    let mut points: Vec<Point> = grid.chunks().into_iter().flat_map(|c| c.points).collect();
    points.sort_by_key(|p| p.index);
    points
}

/// A field as written: the CSV text, or the JSON value's text.
fn shown(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Checks that every written row stands for its grid point: its input columns equal the
/// point's (material, gamma_sv, young, poisson, density, radius, radius2, wall, t_vis, k, as
/// written), and its results read as their columns' types (numbers, empty where allowed, the
/// method `search` or `table`). `first_line` is the file's line number of the first row.
pub fn check_rows(
    grid: &Grid,
    written: &[String],
    format: Format,
    first_line: usize,
) -> Result<(), BadRow> {
    let points = points_in_order(grid);
    for (i, line) in written.iter().enumerate() {
        let at = |column: &str, problem: String| BadRow {
            line: first_line + i,
            column: column.to_string(),
            problem,
        };
        let Some(p) = points.get(i) else {
            return Err(at(
                "row",
                format!("a row beyond the {} points of this sweep", points.len()),
            ));
        };
        let Some(fields) = row_fields(format, line) else {
            return Err(at(
                "row",
                format!(
                    "not a row of the {} columns of a sweep ({})",
                    COLUMNS.len(),
                    format.name()
                ),
            ));
        };
        for (j, cell) in point_cells(grid, p).iter().enumerate() {
            let expected = match format {
                Format::Csv => cell.csv_field().into(),
                Format::Jsonl => cell.json(),
            };
            if fields[j] != expected {
                return Err(at(
                    COLUMNS[j],
                    format!(
                        "'{}' where grid point {} of this sweep has '{}' (a row missing, repeated, moved or edited)",
                        shown(&fields[j]),
                        i + 1,
                        shown(&expected)
                    ),
                ));
            }
        }
        for (j, f) in fields.iter().enumerate().skip(INPUT_COLUMNS) {
            let column = COLUMNS[j];
            let text = shown(f);
            let ok = match column {
                "method" => {
                    ThresholdMethod::from_name(&text).is_some() && text == text.to_lowercase()
                }
                "warnings" => matches!(format, Format::Csv) || f.is_array(),
                // a value that must exist
                "v_stick_jkr" => number_of(f).is_some(),
                _ => number_of(f).is_some() || is_empty(f),
            };
            if !ok {
                return Err(at(
                    column,
                    format!("'{text}' does not read as a {column} value"),
                ));
            }
        }
    }
    Ok(())
}

/// The number in a field: a finite number, or (CSV) text that parses as one.
fn number_of(v: &serde_json::Value) -> Option<f64> {
    let x = v.as_f64().or_else(|| v.as_str()?.parse().ok())?;
    x.is_finite().then_some(x)
}

/// An empty field: `""` (CSV) or `null` (JSON Lines).
fn is_empty(v: &serde_json::Value) -> bool {
    v.is_null() || v.as_str() == Some("")
}

/// The relative difference a recomputed result may have from a written one: the tables are
/// deterministic (their own promise, 1e-5, as a bound); a search seeded differently (a row
/// recomputed alone, without its neighbours' hints) lands anywhere in its final bracket, so
/// twice its width and the solver's error.
fn tolerance(method: ThresholdMethod, rel_tol: f64) -> f64 {
    match method {
        ThresholdMethod::Table => crate::master::TABLE_REL_TOL,
        ThresholdMethod::Search => 4.0 * rel_tol + 1e-7,
    }
}

/// Recomputes the written rows at `indices` (each alone, without hints) and compares their
/// results with what is written: the same method, the same values within the method's
/// tolerance, a value where one was written and none where none was. `first_line` as in
/// [`check_rows`]; the rows must have passed it.
pub fn verify_rows(
    grid: &Grid,
    written: &[String],
    format: Format,
    first_line: usize,
    indices: &[usize],
    opts: &SearchOptions,
) -> Result<(), VerifyError> {
    let points = points_in_order(grid);
    let laws = Laws::new(&grid.k)?;
    for &i in indices {
        let (Some(p), Some(line)) = (points.get(i), written.get(i)) else {
            continue;
        };
        let fields = row_fields(format, line).unwrap_or_default();
        // the rows' warnings are not compared: no caution needed
        let chunk = Chunk {
            points: vec![p.clone()],
            caution: None,
        };
        let rows = chunk.compute(&|k| laws.get(k), opts)?;
        let Some(again) = rows.first() else { continue };
        let cells = again.cells(grid);
        let method_written = fields.get(COLUMNS.len() - 2).map(shown).unwrap_or_default();
        let tol = tolerance(again.method, opts.rel_tol);
        for (j, cell) in cells.iter().enumerate().skip(INPUT_COLUMNS) {
            let column = COLUMNS[j];
            let found = fields.get(j).cloned().unwrap_or_default();
            let bad = match (column, cell) {
                ("method", _) => method_written != again.method.name(),
                (_, super::Cell::Number(now)) => match (number_of(&found), now) {
                    (Some(a), Some(b)) => ((a - b) / b).abs() > tol,
                    (None, None) => false,
                    _ => true,
                },
                _ => false,
            };
            if bad {
                return Err(VerifyError::Differs(BadRow {
                    line: first_line + i,
                    column: column.to_string(),
                    problem: format!(
                        "'{}' written, '{}' recomputed ({} method, tolerance {}): the file was edited or made by another version",
                        shown(&found),
                        shown(&cell.json()),
                        again.method.name(),
                        numerics::format::number(tol)
                    ),
                }));
            }
        }
    }
    Ok(())
}

/// Why [`verify_rows`] refused.
#[derive(Debug, thiserror::Error)]
pub enum VerifyError {
    /// A recomputed row differs from the written one.
    #[error(transparent)]
    Differs(BadRow),
    /// The recomputation itself failed.
    #[error(transparent)]
    Compute(#[from] ThresholdsError),
}
