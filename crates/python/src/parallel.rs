//! Elementwise work over all cores, with the GIL released and Ctrl-C checked between chunks.

use crate::error::Error;
use pyo3::prelude::*;
use rayon::prelude::*;

/// Elements per thread in one chunk. Between chunks the GIL is taken back to check for Ctrl-C:
/// 4 elements a thread is about 20 ms for V_stick searches and well under a second for T_vis
/// fits, the slowest element (about 100 ms), while the pause costs microseconds.
const ELEMENTS_PER_THREAD: usize = 4;

/// Elements computed between two checks for Ctrl-C: [`ELEMENTS_PER_THREAD`] a thread.
pub fn batch() -> usize {
    (rayon::current_num_threads() * ELEMENTS_PER_THREAD).max(1)
}

/// `f(0), ..., f(n - 1)` on all cores with the GIL released, in chunks with a check for signals
/// (Ctrl-C raises `KeyboardInterrupt`) after each; the first error in index order is returned.
pub fn map<T, F>(py: Python<'_>, n: usize, f: F) -> PyResult<Vec<T>>
where
    T: Send,
    F: Fn(usize) -> Result<T, Error> + Sync + Send,
{
    let chunk = batch();
    let mut out = Vec::with_capacity(n);
    let mut start = 0;
    while start < n {
        let end = (start + chunk).min(n);
        let part: Vec<Result<T, Error>> = py.detach(|| {
            if end - start == 1 {
                vec![f(start)]
            } else {
                (start..end).into_par_iter().map(&f).collect()
            }
        });
        for r in part {
            out.push(r?);
        }
        py.check_signals()?;
        start = end;
    }
    Ok(out)
}
