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

/// A chunk that took less than this grows fourfold for the next: elements from the master table
/// take microseconds, and a chunk of 8 of them would spend its time in taking the GIL back and
/// in rayon's start (1e6 elements: seconds); chunks of searches stay small, so Ctrl-C still
/// stops them within about a second.
const QUICK_CHUNK: std::time::Duration = std::time::Duration::from_millis(20);

/// `f(0), ..., f(n - 1)` on all cores with the GIL released, in chunks with a check for signals
/// (Ctrl-C raises `KeyboardInterrupt`) after each; the first error in index order is returned.
/// Chunks start at [`batch`] elements and grow while they are quick ([`QUICK_CHUNK`]).
pub fn map<T, F>(py: Python<'_>, n: usize, f: F) -> PyResult<Vec<T>>
where
    T: Send,
    F: Fn(usize) -> Result<T, Error> + Sync + Send,
{
    let mut chunk = batch();
    let mut out = Vec::with_capacity(n);
    let mut start = 0;
    while start < n {
        let end = (start + chunk).min(n);
        let began = std::time::Instant::now();
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
        if began.elapsed() < QUICK_CHUNK {
            chunk = chunk.saturating_mul(4);
        }
        start = end;
    }
    Ok(out)
}
