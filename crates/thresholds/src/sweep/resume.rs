//! Resuming a sweep: the complete rows of a file written before an interruption, and what is
//! left of each chunk with the hints its written rows give, so that the rest is computed exactly
//! as an uninterrupted run would have ([`remaining`]). File I/O stays with the caller.

use super::{hint_of, Chunk, Format, Grid};
use crate::{Hint, HINT_NEIGHBOURS};

/// The rows already in a file of a sweep.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    /// The complete rows (lines without their line break), in grid order.
    pub rows: Vec<String>,
    /// The length (bytes) of the file up to its last complete row: a torn last line (a kill
    /// mid-write) lies beyond it and is to be cut off.
    pub complete_len: usize,
}

/// The complete rows of the file `text` if it holds the sweep whose header is `header` (as
/// [`super::header_text`] writes it); `None` if it holds another sweep.
///
/// # Example
/// ```
/// use thresholds::sweep::written_rows;
/// let w = written_rows("# h\nrow 1\nrow 2\nrow", "# h\n").unwrap();
/// assert_eq!(w.rows, ["row 1", "row 2"]);
/// assert_eq!(w.complete_len, "# h\nrow 1\nrow 2\n".len()); // the torn "row" is cut off
/// assert!(written_rows("# other\n", "# h\n").is_none());
/// ```
pub fn written_rows(text: &str, header: &str) -> Option<Written> {
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
