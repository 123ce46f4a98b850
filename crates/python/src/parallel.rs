//! Elementwise work over all cores, with the GIL released and Ctrl-C checked between chunks.

use crate::args::Warned;
use crate::error::Error;
use pyo3::prelude::*;
use rayon::prelude::*;
use std::ops::Range;
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
/// Each chunk ends when its slowest thread does, the others waiting: a million CO2 points
/// (`examples/python/table_speed.py`, 18 of them searches of about 13 ms) kept two cores busy
/// 1.77-1.90 of the wall time with 20 ms chunks, 1.89-1.96 with 60 ms (2026-11-28, release
/// wheels alternating).
const CHUNK_TIME: Duration = Duration::from_millis(60);

/// The most elements in one chunk.
const MAX_CHUNK: usize = 1 << 20;

/// What [`drive`] fills, element by element on the calling thread or a range of elements on
/// all cores.
trait Sink: Send {
    /// Element `i`, on the calling thread.
    fn one(&mut self, i: usize) -> Result<(), Error>;
    /// The elements of `range`, on all cores; the first error in index order.
    fn many(&mut self, range: Range<usize>) -> Result<(), Error>;
}

/// Fills `sink` with elements `0..n` with the GIL released: first one after the other for
/// [`SEQUENTIAL_PROBE`] (and on to the end if the rest is shorter than [`SEQUENTIAL_REST`]),
/// then the rest on all cores in chunks with a check for signals (Ctrl-C raises
/// `KeyboardInterrupt`) after each; the first error in index order is returned.
fn drive(py: Python<'_>, n: usize, sink: &mut impl Sink) -> PyResult<()> {
    let began = Instant::now();
    let mut start = 0;
    py.detach(|| {
        while start < n {
            // at least one element measured (the chunks' size comes from its rate); the clock
            // read after each of the first few, then every CLOCK_EVERY-th (a read costs a
            // tenth of a table answer)
            if start > 0 && (start < CLOCK_EVERY || start.is_multiple_of(CLOCK_EVERY)) {
                let elapsed = began.elapsed();
                let per_element = elapsed.as_secs_f64() / start as f64;
                if elapsed >= SEQUENTIAL_PROBE
                    && per_element * (n - start) as f64 >= SEQUENTIAL_REST.as_secs_f64()
                {
                    break;
                }
            }
            sink.one(start)?;
            start += 1;
        }
        Ok::<(), Error>(())
    })?;
    py.check_signals()?;
    let threads = rayon::current_num_threads().max(1);
    // elements a thread computes in CHUNK_TIME at the rate seen so far
    let per_element = began.elapsed().as_secs_f64() / start.max(1) as f64;
    let mut chunk = ((CHUNK_TIME.as_secs_f64() / per_element.max(1e-9)) as usize * threads)
        .clamp(batch(), MAX_CHUNK);
    while start < n {
        let end = (start + chunk).min(n);
        let t = Instant::now();
        py.detach(|| sink.many(start..end))?;
        py.check_signals()?;
        let per_element = t.elapsed().as_secs_f64() / (end - start) as f64 * threads as f64;
        chunk = ((CHUNK_TIME.as_secs_f64() / per_element.max(1e-9)) as usize * threads)
            .clamp(batch(), MAX_CHUNK);
        start = end;
    }
    Ok(())
}

/// `f(0), ..., f(n - 1)` on all cores as [`drive`] computes them.
pub fn map<T, F>(py: Python<'_>, n: usize, f: F) -> PyResult<Vec<T>>
where
    T: Send,
    F: Fn(usize) -> Result<T, Error> + Sync + Send,
{
    let mut sink = Collect {
        f: &f,
        out: Vec::with_capacity(n),
    };
    drive(py, n, &mut sink)?;
    Ok(sink.out)
}

/// [`map`]'s results: each chunk's collected on all cores, then moved into `out` (a vector of
/// exactly the results' size: numpy keeps it). The threshold functions, whose millions of
/// table answers this move would slow by a tenth, use [`map_rows`].
struct Collect<'f, T, F> {
    f: &'f F,
    out: Vec<T>,
}

impl<T, F> Sink for Collect<'_, T, F>
where
    T: Send,
    F: Fn(usize) -> Result<T, Error> + Sync + Send,
{
    fn one(&mut self, i: usize) -> Result<(), Error> {
        self.out.push((self.f)(i)?);
        Ok(())
    }

    fn many(&mut self, range: Range<usize>) -> Result<(), Error> {
        let part: Vec<Result<T, Error>> = range.into_par_iter().map(self.f).collect();
        for r in part {
            self.out.push(r?);
        }
        Ok(())
    }
}

/// What an element of a threshold function gives: its row of `N` floats with the code of the
/// method that answered, and its warnings.
pub type Row<const N: usize> = (([f64; N], u8), Warned);

/// The columns of [`map_rows`]: `N` float columns, the method codes and the warnings.
pub struct Columns {
    /// The float columns, each of every element.
    pub values: Vec<Vec<f64>>,
    /// The method code of every element.
    pub codes: Vec<u8>,
    /// The warnings, in the order of the elements.
    pub warnings: Warned,
}

/// The most elements a thread computes in one piece in [`map_rows`], writing their rows into
/// every column; a chunk is cut into at least four blocks a thread, so that a chunk of slow
/// elements (searches: a chunk is 60 ms of work) is still shared among the threads.
const BLOCK: usize = 4096;

/// Blocks a thread at least, of a chunk (for rayon to balance).
const BLOCKS_PER_THREAD: usize = 4;

/// `f(0), ..., f(n - 1)` on all cores as [`drive`] computes them, each row written straight
/// into its columns (41 bytes an element for five columns, against the 80 of a row kept first
/// and copied into columns after: page faults of fresh memory were a sixth of a million table
/// answers).
pub fn map_rows<const N: usize, F>(py: Python<'_>, n: usize, f: F) -> PyResult<Columns>
where
    F: Fn(usize) -> Result<Row<N>, Error> + Sync + Send,
{
    let mut sink = IntoColumns {
        f: &f,
        columns: Columns {
            values: (0..N).map(|_| vec![0.0; n]).collect(),
            codes: vec![0; n],
            warnings: Warned::new(),
        },
    };
    drive(py, n, &mut sink)?;
    Ok(sink.columns)
}

/// A block of [`map_rows`]: its first element, its piece of every float column and of the codes.
type Block<'a> = (usize, Vec<&'a mut [f64]>, &'a mut [u8]);

/// [`map_rows`]'s sink.
struct IntoColumns<'f, F> {
    f: &'f F,
    columns: Columns,
}

impl<const N: usize, F> Sink for IntoColumns<'_, F>
where
    F: Fn(usize) -> Result<Row<N>, Error> + Sync + Send,
{
    fn one(&mut self, i: usize) -> Result<(), Error> {
        let ((row, code), w) = (self.f)(i)?;
        for (column, v) in self.columns.values.iter_mut().zip(row) {
            column[i] = v;
        }
        self.columns.codes[i] = code;
        self.columns.warnings.extend(w);
        Ok(())
    }

    fn many(&mut self, range: Range<usize>) -> Result<(), Error> {
        // each block's piece of every column, handed to one thread
        let Columns {
            values,
            codes,
            warnings,
        } = &mut self.columns;
        let threads = rayon::current_num_threads().max(1);
        let block = range
            .len()
            .div_ceil(threads * BLOCKS_PER_THREAD)
            .clamp(1, BLOCK);
        let mut pieces: Vec<_> = values
            .iter_mut()
            .map(|c| c[range.clone()].chunks_mut(block))
            .collect();
        let blocks: Vec<Block> = codes[range.clone()]
            .chunks_mut(block)
            .enumerate()
            .map(|(b, codes)| {
                let parts = pieces.iter_mut().filter_map(Iterator::next).collect();
                (range.start + b * block, parts, codes)
            })
            .collect();
        let f = self.f;
        let found: Vec<Result<Warned, Error>> = blocks
            .into_par_iter()
            .map(|(first, mut parts, codes)| {
                let mut found = Warned::new();
                for (q, code) in codes.iter_mut().enumerate() {
                    let ((row, c), w) = f(first + q)?;
                    for (part, v) in parts.iter_mut().zip(row) {
                        part[q] = v;
                    }
                    *code = c;
                    found.extend(w);
                }
                Ok(found)
            })
            .collect();
        // the blocks in order: the first error is the first in index order
        for w in found {
            warnings.extend(w?);
        }
        Ok(())
    }
}
