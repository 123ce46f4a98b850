//! Progress of long work on stderr: a bar on a terminal, a plain line every few seconds
//! otherwise (a log, a pipe, CI).

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// Seconds between two progress lines when stderr is not a terminal.
const PLAIN_PROGRESS_EVERY: Duration = Duration::from_secs(5);

/// Progress of `total` items (`unit`, e.g. "rows") of a task (`name`, e.g. "sweep").
pub struct Progress {
    name: &'static str,
    unit: &'static str,
    bar: Option<ProgressBar>,
    total: usize,
    start: Instant,
    last: Instant,
    done_at_start: usize,
}

impl Progress {
    /// Progress from `done` of `total` items.
    pub fn new(name: &'static str, unit: &'static str, total: usize, done: usize) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let b = ProgressBar::new(total as u64);
            let template = format!("{{bar:40}} {{pos}}/{{len}} {unit}, {{per_sec}}, ETA {{eta}}");
            if let Ok(style) = ProgressStyle::with_template(&template) {
                b.set_style(style);
            }
            b.set_position(done as u64);
            b
        });
        let now = Instant::now();
        Self {
            name,
            unit,
            bar,
            total,
            start: now,
            last: now,
            done_at_start: done,
        }
    }

    /// `done` items are done.
    pub fn update(&mut self, done: usize) {
        match &self.bar {
            Some(b) => b.set_position(done as u64),
            None if self.last.elapsed() >= PLAIN_PROGRESS_EVERY || done == self.total => {
                self.last = Instant::now();
                let secs = self.start.elapsed().as_secs_f64().max(1e-9);
                let rate = (done - self.done_at_start) as f64 / secs;
                let eta = if rate > 0.0 {
                    format!("{:.0} s", (self.total - done) as f64 / rate)
                } else {
                    "?".into()
                };
                eprintln!(
                    "{}: {done}/{} {} ({:.1} %), {rate:.1} {}/s, ETA {eta}",
                    self.name,
                    self.total,
                    self.unit,
                    100.0 * done as f64 / self.total.max(1) as f64,
                    self.unit
                );
            }
            None => {}
        }
    }

    /// Ends the bar.
    pub fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish();
        }
    }
}
