//! `stickiness sweep`: a grid of V_stick searches into a CSV (or JSON Lines) file that survives
//! being killed.
//!
//! Everything about the sweep itself (axes, grid, chunks, rows, header, resuming) is
//! `thresholds::sweep`, shared with the Python package, so both give the same numbers. This
//! file keeps what a command does with it: the file, the threads and the progress. Chunks run
//! on all cores; rows are written in grid order as soon as they and every row before them are
//! done, each with one `write` call. `--resume` keeps the complete rows of an existing file
//! (cutting off a torn last line) and computes only the rest, so that a resumed file equals an
//! uninterrupted one byte for byte.

mod args;

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
use thresholds::sweep::{remaining, row_text, written_rows, Laws, Row};
use thresholds::ThresholdsError;

/// The rows already written to `path` for the sweep with `header` (cutting off a torn last
/// line), or a fresh file holding only the header.
fn open_rows(args: &SweepArgs, path: &Path, header: &str) -> Result<Vec<String>, CliError> {
    let exists = path.exists();
    if exists && !args.resume && !args.force {
        return Err(CliError::Usage(format!(
            "--out {}: the file exists; pass --resume to continue it or --force to overwrite it",
            path.display()
        )));
    }
    if !(exists && args.resume) {
        std::fs::write(path, header).map_err(|e| {
            CliError::Usage(format!(
                "--out {}: cannot write the file: {e}",
                path.display()
            ))
        })?;
        return Ok(Vec::new());
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("--resume: cannot read {}: {e}", path.display())))?;
    let Some(written) = written_rows(&text, header) else {
        return Err(CliError::Usage(format!(
            "--resume: {} holds another sweep (its header differs from this command's); use another --out, or --force to overwrite it",
            path.display()
        )));
    };
    if written.complete_len < text.len() {
        let f = OpenOptions::new().write(true).open(path).map_err(|e| {
            CliError::Usage(format!("--resume: cannot write {}: {e}", path.display()))
        })?;
        f.set_len(written.complete_len as u64)
            .map_err(|e| CliError::Compute(format!("cannot truncate {}: {e}", path.display())))?;
    }
    Ok(written.rows)
}

/// Runs the command.
pub fn run(args: &SweepArgs) -> Result<Report, CliError> {
    // every bad input before any work starts (or any file is written)
    let (grid, options, header) = args.grid()?;
    if args.jobs == Some(0) {
        return Err(CliError::Usage("--jobs = 0: must be >= 1".into()));
    }
    let path = &args.out;
    let written = open_rows(args, path, &header)?;
    let (total, done) = (grid.len(), written.len());
    if done > total {
        return Err(CliError::Usage(format!(
            "--resume: {} holds {done} rows, more than the {total} of this sweep",
            path.display()
        )));
    }
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
    let mut r = Report::new(format!("Sweep of {total} points into {}", path.display()));
    r.count("points", total);
    r.count("computed", total - done);
    r.count("resumed", done);
    r.text("out", &path.display().to_string());
    Ok(r)
}
