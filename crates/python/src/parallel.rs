//! Elementwise work over all cores, with the GIL released and Ctrl-C checked between chunks.

use crate::error::Error;
use pyo3::prelude::*;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Elements per thread in one chunk. Between chunks the GIL is taken back to check for Ctrl-C:
/// 4 elements a thread is about 20 ms for V_stick searches and well under a second for T_vis
/// fits, the slowest element (about 100 ms), while the pause costs microseconds.
const ELEMENTS_PER_THREAD: usize = 4;

/// Elements computed between two checks for Ctrl-C: [`ELEMENTS_PER_THREAD`] a thread.
pub fn batch() -> usize {
    (rayon::current_num_threads() * ELEMENTS_PER_THREAD).max(1)
}

/// The elements are first computed one after the other on the calling thread for at least
/// this long: answers from the master tables take a microsecond, and an array of a few dozen of
/// them is done before the thread pool would have woken (64 elements: 50 us instead of
/// 140 us).
const SEQUENTIAL_PROBE: Duration = Duration::from_micros(50);

/// After the probe the rest is also computed on the calling thread if it would take less than
/// this at the rate seen so far: waking the pool costs 50-90 us, so only a longer rest is worth
/// sharing (an inference step's 1024 table answers, 0.5 ms: 0.3 ms on two cores). The first
/// slow element (a search: milliseconds) ends the start.
const SEQUENTIAL_REST: Duration = Duration::from_micros(250);

/// During the sequential start the clock is read after each of the first this-many elements,
/// then after every this-many-th: a table answer takes about a microsecond, a read of the
/// clock a tenth of that.
const CLOCK_EVERY: usize = 4;

/// After the start, a chunk holds about this much work on every core (from the rate measured
/// so far), so that Ctrl-C is checked every few tens of milliseconds whatever an element costs.
const CHUNK_TIME: Duration = Duration::from_millis(20);

/// The most elements in one chunk.
const MAX_CHUNK: usize = 1 << 20;

/// `f(0), ..., f(n - 1)` with the GIL released: first one after the other for
/// [`SEQUENTIAL_PROBE`] (and on to the end if the rest is shorter than
/// [`SEQUENTIAL_REST`]), then the rest on all cores in chunks with a check for signals
/// (Ctrl-C raises `KeyboardInterrupt`) after each; the first error in index order is
/// returned.
pub fn map<T, F>(py: Python<'_>, n: usize, f: F) -> PyResult<Vec<T>>
where
    T: Send,
    F: Fn(usize) -> Result<T, Error> + Sync + Send,
{
    // every result is written once, where it ends (the chunks' in parallel): a million table
    // answers moved through a second vector cost a tenth of the call, on one thread
    let mut out: Vec<Result<T, Error>> = Vec::with_capacity(n);
    let began = Instant::now();
    py.detach(|| {
        while out.len() < n {
            // at least one element measured (the chunks' size comes from its rate); the clock
            // read after each of the first few, then every CLOCK_EVERY-th (a read costs a
            // tenth of a table answer)
            let done = out.len();
            if done > 0 && (done < CLOCK_EVERY || done.is_multiple_of(CLOCK_EVERY)) {
                let elapsed = began.elapsed();
                let per_element = elapsed.as_secs_f64() / done as f64;
                if elapsed >= SEQUENTIAL_PROBE
                    && per_element * (n - done) as f64 >= SEQUENTIAL_REST.as_secs_f64()
                {
                    break;
                }
            }
            let r = f(done);
            let failed = r.is_err();
            out.push(r);
            if failed {
                break;
            }
        }
    });
    let mut start = out.len();
    if out.last().is_some_and(Result::is_err) {
        return Err(first_error(out, 0));
    }
    py.check_signals()?;
    let threads = rayon::current_num_threads().max(1);
    // elements a thread computes in CHUNK_TIME at the rate seen so far
    let per_element = began.elapsed().as_secs_f64() / start.max(1) as f64;
    let mut chunk = ((CHUNK_TIME.as_secs_f64() / per_element.max(1e-9)) as usize * threads)
        .clamp(batch(), MAX_CHUNK);
    while start < n {
        let end = (start + chunk).min(n);
        let t = Instant::now();
        let failed = AtomicBool::new(false);
        py.detach(|| {
            out.par_extend((start..end).into_par_iter().map(|i| {
                let r = f(i);
                if r.is_err() {
                    failed.store(true, Ordering::Relaxed);
                }
                r
            }))
        });
        if failed.into_inner() {
            return Err(first_error(out, start));
        }
        py.check_signals()?;
        let per_element = t.elapsed().as_secs_f64() / (end - start) as f64 * threads as f64;
        chunk = ((CHUNK_TIME.as_secs_f64() / per_element.max(1e-9)) as usize * threads)
            .clamp(batch(), MAX_CHUNK);
        start = end;
    }
    // every one is Ok here; the same allocation reused (in place)
    out.into_iter()
        .collect::<Result<Vec<T>, Error>>()
        .map_err(Into::into)
}

/// The first error of `results` from index `from` on, in index order (there is one).
fn first_error<T>(results: Vec<Result<T, Error>>, from: usize) -> PyErr {
    match results.into_iter().skip(from).find_map(Result::err) {
        Some(e) => e.into(),
        None => pyo3::exceptions::PyRuntimeError::new_err("an element failed without an error"),
    }
}
