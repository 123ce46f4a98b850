//! `stickiness sweep`: a grid of V_stick searches into a CSV (or JSON Lines) file that survives
//! being killed.
//!
//! Everything about the sweep itself (axes, grid, chunks, rows, header, resuming) is
//! `thresholds::sweep`, shared with the Python package, so both give the same numbers. This
//! file keeps what a command does with it: the file, the threads and the progress. Chunks run
//! on all cores; rows are written in grid order as soon as they and every row before them are
//! done, each with one `write` call. `--resume` keeps the complete rows of an existing file
//! (cutting off a torn last line) once each stands for its grid point (`--verify N`: and N of
//! them recompute to what is written), and computes only the rest, so that a resumed file
//! equals an uninterrupted one byte for byte; a file it cannot vouch for is refused untouched.

mod args;

use args::Format;
pub use args::SweepArgs;

use crate::error::CliError;
use crate::output::Report;
use crate::progress::Progress;
use std::collections::BTreeMap;
use std::fs::OpenOptions;
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use thresholds::sweep::{
    check_rows, file_text, remaining, row_text, verify_rows, written_rows, Grid, Laws, Row,
    VerifyError, Written,
};
use thresholds::{SearchOptions, ThresholdsError};

/// What an existing file holds for the sweep with `header`: its complete rows and the length up
/// to them (a torn last line beyond; no header kept when a kill cut it short), or `None` for a
/// fresh file. Nothing is written here.
fn existing_rows(args: &SweepArgs, path: &Path, header: &str) -> Result<Option<Written>, CliError> {
    let exists = path.exists();
    if exists && !args.resume && !args.force {
        return Err(CliError::Usage(format!(
            "--out {}: the file exists; pass --resume to continue it or --force to overwrite it",
            path.display()
        )));
    }
    if !(exists && args.resume) {
        return Ok(None);
    }
    let bytes = std::fs::read(path)
        .map_err(|e| CliError::Usage(format!("--resume: cannot read {}: {e}", path.display())))?;
    let Some(text) = file_text(&bytes) else {
        return Err(CliError::Usage(format!(
            "--resume: {} is not a text file of a sweep (not UTF-8); use another --out, or --force to overwrite it",
            path.display()
        )));
    };
    match written_rows(text, header) {
        Some(w) => Ok(Some(w)),
        None => {
            // a file of the other format is named as such (its first byte tells: `#` or `{`)
            let other = match (text.trim_start().chars().next(), args.format) {
                (Some('{'), Format::Csv) => Some("jsonl"),
                (Some('#'), Format::Jsonl) => Some("csv"),
                _ => None,
            };
            let why = match other {
                Some(f) => format!("holds a sweep in the other format (--format {f})"),
                None => "holds another sweep (its header differs from this command's)".into(),
            };
            Err(CliError::Usage(format!(
                "--resume: {} {why}; use another --out, or --force to overwrite it",
                path.display()
            )))
        }
    }
}

/// Checks the kept rows against the grid (and recomputes `--verify` of them); the first that
/// cannot be kept is refused, naming the file, the line and the column.
fn check_kept(
    args: &SweepArgs,
    grid: &Grid,
    options: &SearchOptions,
    header: &str,
    written: &Written,
) -> Result<(), CliError> {
    let path = args.out.display();
    let format = args.format.into();
    let first_line = header.lines().count() + 1;
    check_rows(grid, &written.rows, format, first_line)
        .map_err(|e| CliError::Usage(format!("--resume: {path}, {e}; nothing was written")))?;
    let Some(n) = args.verify else {
        return Ok(());
    };
    let rows = written.rows.len();
    let mut picks: Vec<usize> = sample(rows.saturating_sub(1), n);
    picks.extend(rows.checked_sub(1));
    verify_rows(grid, &written.rows, format, first_line, &picks, options).map_err(|e| match e {
        VerifyError::Differs(bad) => CliError::Usage(format!(
            "--resume --verify: {path}, {bad}; nothing was written"
        )),
        VerifyError::Compute(e) => e.into(),
    })
}

/// `n` distinct indices below `len` drawn at random (all of them when `n >= len`).
fn sample(len: usize, n: usize) -> Vec<usize> {
    let mut all: Vec<usize> = (0..len).collect();
    let mut state = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0x5EED, |d| d.as_nanos() as u64);
    // a partial Fisher-Yates shuffle with SplitMix64
    for i in 0..n.min(len) {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        let j = i + ((z ^ (z >> 31)) % (len - i) as u64) as usize;
        all.swap(i, j);
    }
    all.truncate(n.min(len));
    all
}

/// The file ready for appending: a fresh one holding the header (also when a kill left the
/// header incomplete), or the kept one with its torn last line cut off.
fn prepare(path: &Path, header: &str, written: Option<&Written>) -> Result<(), CliError> {
    let Some(w) = written.filter(|w| w.keeps_header()) else {
        return std::fs::write(path, header).map_err(|e| {
            CliError::Usage(format!(
                "--out {}: cannot write the file: {e}",
                path.display()
            ))
        });
    };
    let len = std::fs::metadata(path)
        .map_err(|e| CliError::Usage(format!("--resume: cannot read {}: {e}", path.display())))?
        .len();
    if (w.complete_len as u64) < len {
        let f = OpenOptions::new().write(true).open(path).map_err(|e| {
            CliError::Usage(format!("--resume: cannot write {}: {e}", path.display()))
        })?;
        f.set_len(w.complete_len as u64)
            .map_err(|e| CliError::Compute(format!("cannot truncate {}: {e}", path.display())))?;
    }
    Ok(())
}

/// Runs the command.
pub fn run(args: &SweepArgs) -> Result<Report, CliError> {
    // every bad input before any work starts (or any file is written)
    let (grid, options, header) = args.grid()?;
    if args.jobs == Some(0) {
        return Err(CliError::Usage("--jobs = 0: must be >= 1".into()));
    }
    let path = &args.out;
    let kept = existing_rows(args, path, &header)?;
    if let Some(w) = &kept {
        check_kept(args, &grid, &options, &header, w)?;
    }
    prepare(path, &header, kept.as_ref())?;
    let written = kept.map(|w| w.rows).unwrap_or_default();
    let (total, done) = (grid.len(), written.len());
    let mut file = OpenOptions::new().append(true).open(path).map_err(|e| {
        CliError::Usage(format!(
            "--out {}: cannot write the file: {e}",
            path.display()
        ))
    })?;
    let format = args.format.into();
    let work = remaining(&grid, &written, format);
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .map_err(|e| CliError::Compute(format!("cannot start {jobs} threads: {e}")))?;
    let laws = Laws::new(&grid.k)?;
    let law = |k: f64| laws.get(k);
    let mut progress = Progress::new("sweep", "rows", total, done);
    let (tx, rx) = mpsc::channel::<Result<Row, ThresholdsError>>();
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    // rows computed with warnings: how many, and the first (its grid index and warnings)
    let mut warned: (usize, Option<(usize, String)>) = (0, None);
    let outcome = std::thread::scope(|scope| -> Result<(), CliError> {
        // workers: each takes the next chunk left and sends its rows as they are found
        scope.spawn(|| {
            pool.scope(|s| {
                for _ in 0..jobs {
                    let tx = tx.clone();
                    let (next, stop, work, law, options) = (&next, &stop, &work, &law, &options);
                    s.spawn(move |_| loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        if i >= work.len() || stop.load(Ordering::Relaxed) {
                            break;
                        }
                        let w = &work[i];
                        let mut send = |row: &Row| {
                            let _ = tx.send(Ok(row.clone()));
                        };
                        let run =
                            w.chunk
                                .compute_from(w.start, &w.previous, law, options, &mut send);
                        if let Err(e) = run {
                            let _ = tx.send(Err(e));
                            stop.store(true, Ordering::Relaxed);
                        }
                    });
                }
            });
            drop(tx);
        });
        // the writer: rows in grid order as soon as they and all before them are done
        let mut pending: BTreeMap<usize, Row> = BTreeMap::new();
        let mut next_row = done;
        for received in rx {
            let row = received.inspect_err(|_| stop.store(true, Ordering::Relaxed))?;
            pending.insert(row.point.index, row);
            while let Some(row) = pending.remove(&next_row) {
                if !row.warnings.is_empty() {
                    warned.0 += 1;
                    warned
                        .1
                        .get_or_insert_with(|| (row.point.index, row.warnings.join("; ")));
                }
                file.write_all(row_text(format, &grid, &row).as_bytes())
                    .map_err(|e| {
                        stop.store(true, Ordering::Relaxed);
                        CliError::Compute(format!("cannot write {}: {e}", path.display()))
                    })?;
                next_row += 1;
            }
            progress.update(next_row);
        }
        Ok(())
    });
    progress.finish();
    outcome?;
    let points = if total == 1 { "point" } else { "points" };
    let mut r = Report::new(format!("Sweep of {total} {points} into {}", path.display()));
    r.count("points", total);
    r.count("computed", total - done);
    r.count("resumed", done);
    r.text("out", &path.display().to_string());
    // a slip of units (a radius of 60 m) is not left to be found in the file's column
    if let (n, Some((index, first))) = warned {
        r.warn([format!(
            "rows computed with warnings: {n} of {} (the file's warnings column); the first, \
             row {index}: {first}",
            total - done
        )]);
    }
    Ok(r)
}
