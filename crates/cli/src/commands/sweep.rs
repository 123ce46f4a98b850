//! `stickiness sweep`: a grid of V_stick searches into a CSV (or JSON Lines) file that survives
//! being killed.
//!
//! The grid and its chunks come from `thresholds::sweep` (shared with the Python package, so
//! both give the same numbers). Chunks run on all cores; rows are written in grid order as soon
//! as they and every row before them are done, each with one `write` call. `--resume` keeps the
//! complete rows of an existing file (dropping a torn last line), restores each chunk's hints
//! from its last written rows, and computes only the rest, so that a resumed file equals an
//! uninterrupted one byte for byte.

use crate::args::Overrides;
use crate::error::CliError;
use crate::output::Report;
use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use numerics::format::number;
use numerics::OutOfRange;
use std::collections::BTreeMap;
use std::fs::OpenOptions;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};
use thresholds::sweep::{Chunk, Grid, Laws, NamedMaterial, Partner, Row, TVisAxis, COLUMNS, UNITS};
use thresholds::{Hint, SearchOptions, TVisLaw, ThresholdsError, HINT_NEIGHBOURS};

/// Seconds between two progress lines when stderr is not a terminal.
const PLAIN_PROGRESS_EVERY: Duration = Duration::from_secs(5);

/// File format of the rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Comma-separated values after `#` header lines (pandas: `read_csv(path, comment="#")`).
    Csv,
    /// One JSON object a line, after a first line `{"sweep": {header}}`.
    Jsonl,
}

/// Arguments of `stickiness sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Materials: a comma list of presets (co2, h2o) and JSON file paths.
    #[arg(long, default_value = "co2")]
    pub material: String,
    /// Surface free energies gamma_SV (J/m^2) replacing each material's: a comma list or
    /// START:STOP:N (N log-spaced values, both ends included).
    #[arg(long, allow_hyphen_values = true)]
    pub gamma_sv: Option<String>,
    /// Radii R1 (m): a comma list or START:STOP:N.
    #[arg(long, default_value = "0.00006", allow_hyphen_values = true)]
    pub radius: String,
    /// Radii R2 of the second sphere (m): a comma list or START:STOP:N; default: R2 = R1.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "wall")]
    pub radius2: Option<String>,
    /// A sphere on a flat wall of the same material at every point.
    #[arg(long)]
    pub wall: bool,
    /// Relaxation times T_vis (s): a comma list or START:STOP:N.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "t_vis_law")]
    pub t_vis: Option<String>,
    /// T_vis from the size law of Section 5.3 at each radius instead of a T_vis axis.
    #[arg(long, value_enum, ignore_case = true)]
    pub t_vis_law: Option<crate::args::LawName>,
    /// Modulus ratios k (dimensionless): a comma list or START:STOP:N.
    #[arg(long, default_value = "0.01", allow_hyphen_values = true)]
    pub k: String,
    /// Relative tolerance of the threshold brackets (dimensionless).
    #[arg(long, default_value = "1e-6", allow_hyphen_values = true)]
    pub rel_tol: f64,
    /// Highest impact speed searched for bouncing (m/s; default 1000 V_stick,JKR; at most 10000.0).
    #[arg(long, allow_hyphen_values = true)]
    pub v_max: Option<f64>,
    /// The output file.
    #[arg(long, value_name = "FILE.csv")]
    pub out: PathBuf,
    /// Continue an existing file of the same sweep: keep its complete rows, compute the rest.
    #[arg(long, conflicts_with = "force")]
    pub resume: bool,
    /// Overwrite an existing file.
    #[arg(long)]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Format of the output file.
    #[arg(long, value_enum, ignore_case = true, default_value = "csv")]
    pub format: Format,
    /// Override Young's modulus E (Pa) of every material.
    #[arg(long, allow_hyphen_values = true)]
    pub young: Option<f64>,
    /// Override the Poisson ratio nu (dimensionless, -1 < nu < 0.5) of every material.
    #[arg(long, allow_hyphen_values = true)]
    pub poisson: Option<f64>,
    /// Override the density rho (kg/m^3) of every material.
    #[arg(long, allow_hyphen_values = true)]
    pub density: Option<f64>,
}

/// An axis as given: a comma list, or `START:STOP:N` with N log-spaced values, both ends
/// included, computed as `numpy.geomspace` does (`10^(log10 START + i step)`, ends exact).
pub fn parse_axis(flag: &str, spec: &str) -> Result<Vec<f64>, CliError> {
    let bad = |what: &str| CliError::Usage(format!("{flag} = {spec}: {what}"));
    let number = |s: &str| -> Result<f64, CliError> {
        s.trim()
            .parse::<f64>()
            .map_err(|_| bad(&format!("'{}' is not a number", s.trim())))
    };
    if spec.contains(':') {
        let parts: Vec<&str> = spec.split(':').collect();
        let [start, stop, n] = parts.as_slice() else {
            return Err(bad("a range is START:STOP:N"));
        };
        let (start, stop) = (number(start)?, number(stop)?);
        let n: usize = match n.trim().parse() {
            Ok(n) if n >= 1 => n,
            _ => return Err(bad("N must be a whole number >= 1")),
        };
        if !(start.is_finite() && stop.is_finite() && start > 0.0 && stop > 0.0) {
            return Err(bad(
                "a log-spaced range needs START and STOP > 0 and finite",
            ));
        }
        Ok(geomspace(start, stop, n))
    } else {
        spec.split(',').map(number).collect()
    }
}

/// `n` values from `start` to `stop` evenly spaced in log, as `numpy.geomspace(start, stop, n)`.
pub fn geomspace(start: f64, stop: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![start];
    }
    let (a, b) = (start.log10(), stop.log10());
    let step = (b - a) / (n - 1) as f64;
    let mut out: Vec<f64> = (0..n)
        .map(|i| {
            let y = if i == n - 1 { b } else { i as f64 * step + a };
            10f64.powf(y)
        })
        .collect();
    out[0] = start;
    out[n - 1] = stop;
    out
}

/// The axis in the canonical form the header records: a list of shortest numbers, or the range
/// `START:STOP:N` (an axis is parsed, and so valid, before this is called).
fn canonical(spec: &str) -> String {
    let shortest = |x: &str| x.trim().parse::<f64>().map_or(x.trim().to_string(), number);
    match spec.split(':').collect::<Vec<_>>().as_slice() {
        [start, stop, n] => format!("{}:{}:{}", shortest(start), shortest(stop), n.trim()),
        _ => spec.split(',').map(shortest).collect::<Vec<_>>().join(","),
    }
}

impl SweepArgs {
    /// The grid (validated) and the header lines that identify this sweep.
    fn grid(&self) -> Result<(Grid, Vec<String>), CliError> {
        // gamma_SV is an axis of the sweep; the other constants are overrides
        let overrides = Overrides {
            gamma_sv: None,
            young: self.young,
            poisson: self.poisson,
            density: self.density,
        };
        let materials = self
            .material
            .split(',')
            .map(|name| {
                let named = overrides.resolve(name.trim(), crate::args::MATERIAL_PREFIX)?;
                Ok(NamedMaterial {
                    name: named.given,
                    material: named.material,
                })
            })
            .collect::<Result<Vec<_>, CliError>>()?;
        let gamma_sv = self
            .gamma_sv
            .as_deref()
            .map(|s| parse_axis("--gamma-sv", s))
            .transpose()?;
        let radius = parse_axis("--radius", &self.radius)?;
        let partner = match (&self.radius2, self.wall) {
            (Some(s), _) => Partner::Radii(parse_axis("--radius2", s)?),
            (None, true) => Partner::Wall,
            (None, false) => Partner::Same,
        };
        let t_vis = match (&self.t_vis, self.t_vis_law) {
            (Some(s), _) => TVisAxis::Values(parse_axis("--t-vis", s)?),
            (None, Some(law)) => TVisAxis::Law(TVisLaw::from(law)),
            (None, None) => {
                return Err(CliError::Usage(
                    "one of --t-vis or --t-vis-law is required".into(),
                ))
            }
        };
        let k = parse_axis("--k", &self.k)?;
        let grid = Grid {
            materials,
            gamma_sv,
            radius,
            partner,
            t_vis,
            k,
        };
        grid.validate().map_err(|e: OutOfRange| CliError::from(e))?;
        let options = SearchOptions {
            rel_tol: self.rel_tol,
            v_max: self.v_max,
            ..SearchOptions::default()
        };
        options.validate()?;
        // the command as it determines the rows (not --out, --resume, --force, --jobs)
        let mut command = vec![format!("--material {}", self.material)];
        for (flag, v) in [
            ("--young", self.young),
            ("--poisson", self.poisson),
            ("--density", self.density),
        ] {
            if let Some(v) = v {
                command.push(format!("{flag} {}", number(v)));
            }
        }
        if let Some(s) = &self.gamma_sv {
            command.push(format!("--gamma-sv {}", canonical(s)));
        }
        command.push(format!("--radius {}", canonical(&self.radius)));
        match (&self.radius2, self.wall) {
            (Some(s), _) => command.push(format!("--radius2 {}", canonical(s))),
            (None, true) => command.push("--wall".into()),
            (None, false) => {}
        }
        match (&self.t_vis, self.t_vis_law) {
            (Some(s), _) => command.push(format!("--t-vis {}", canonical(s))),
            (None, Some(l)) => command.push(format!("--t-vis-law {}", TVisLaw::from(l).name())),
            (None, None) => {}
        }
        command.push(format!("--k {}", canonical(&self.k)));
        command.push(format!("--rel-tol {}", number(self.rel_tol)));
        if let Some(v) = self.v_max {
            command.push(format!("--v-max {}", number(v)));
        }
        let header = vec![
            "stickiness sweep: V_stick, V_double_onset, V_stick,JKR and V_frag = 10 V_stick over a grid (Arakawa & Krijt 2021)".to_string(),
            format!(
                "command: stickiness sweep {} --format {}",
                command.join(" "),
                match self.format {
                    Format::Csv => "csv",
                    Format::Jsonl => "jsonl",
                }
            ),
            format!(
                "grid: material, gamma_sv, radius, radius2, t_vis, k (outermost first), {} points; each T_vis seeded by its neighbour's thresholds",
                grid.len()
            ),
            format!("units: {UNITS}"),
            "an empty field has no value: v_stick, v_double_onset, v_frag without bouncing up to no_bouncing_below (else empty); radius2 on a wall".into(),
        ];
        Ok((grid, header))
    }
}

/// The header as written to the file.
fn header_text(format: Format, header: &[String]) -> String {
    match format {
        Format::Csv => {
            let mut out: String = header.iter().map(|l| format!("# {l}\n")).collect();
            out.push_str(&COLUMNS.join(","));
            out.push('\n');
            out
        }
        Format::Jsonl => {
            let value = serde_json::json!({"sweep": {"header": header, "columns": COLUMNS}});
            format!("{value}\n")
        }
    }
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// One row as a line of the file.
fn row_text(format: Format, grid: &Grid, row: &Row) -> String {
    let p = &row.point;
    let m = &p.constants;
    let name = &grid.materials[p.material].name;
    let radius2 = p.geometry.r2();
    let warnings = row.warnings.join("; ");
    match format {
        Format::Csv => {
            let opt = |v: Option<f64>| v.map_or(String::new(), number);
            let fields = [
                csv_field(name),
                number(m.gamma_sv),
                number(m.young),
                number(m.poisson),
                number(m.density),
                number(p.geometry.r1()),
                opt(radius2),
                p.geometry.is_wall().to_string(),
                number(p.t_vis),
                number(p.k),
                opt(row.v_stick),
                opt(row.v_double_onset),
                number(row.v_stick_jkr),
                opt(row.v_frag),
                opt(row.no_bouncing_below),
                csv_field(&warnings),
            ];
            format!("{}\n", fields.join(","))
        }
        Format::Jsonl => {
            let value = serde_json::json!({
                "material": name,
                "gamma_sv": m.gamma_sv,
                "young": m.young,
                "poisson": m.poisson,
                "density": m.density,
                "radius": p.geometry.r1(),
                "radius2": radius2,
                "wall": p.geometry.is_wall(),
                "t_vis": p.t_vis,
                "k": p.k,
                "v_stick": row.v_stick,
                "v_double_onset": row.v_double_onset,
                "v_stick_jkr": row.v_stick_jkr,
                "v_frag": row.v_frag,
                "no_bouncing_below": row.no_bouncing_below,
                "warnings": row.warnings,
            });
            format!("{value}\n")
        }
    }
}

/// The fields of a CSV line (quotes as [`csv_field`] writes them).
fn csv_split(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut field = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut field)),
            _ => field.push(c),
        }
    }
    out.push(field);
    out
}

/// The hint a written row gives the next point of its chunk.
fn hint_of(format: Format, line: &str) -> Option<Hint> {
    let (onset, stick) = match format {
        Format::Csv => {
            let f = csv_split(line);
            let at = |name: &str| -> Option<f64> {
                let i = COLUMNS.iter().position(|c| *c == name)?;
                f.get(i)?.parse().ok()
            };
            (at("v_double_onset")?, at("v_stick")?)
        }
        Format::Jsonl => {
            let v: serde_json::Value = serde_json::from_str(line).ok()?;
            (v["v_double_onset"].as_f64()?, v["v_stick"].as_f64()?)
        }
    };
    Some(Hint::from_neighbour(onset, stick))
}

/// The complete rows of an existing file of the same sweep: checks the header, drops a torn
/// last line (truncating the file to the last complete one), returns the rows' lines.
fn existing_rows(path: &Path, header: &str) -> Result<Vec<String>, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("--resume: cannot read {}: {e}", path.display())))?;
    let Some(rest) = text.strip_prefix(header) else {
        return Err(CliError::Usage(format!(
            "--resume: {} holds another sweep (its header differs from this command's); use another --out, or --force to overwrite it",
            path.display()
        )));
    };
    let complete = rest.rfind('\n').map_or(0, |i| i + 1);
    let keep = header.len() + complete;
    if keep < text.len() {
        let f = OpenOptions::new().write(true).open(path).map_err(|e| {
            CliError::Usage(format!("--resume: cannot write {}: {e}", path.display()))
        })?;
        f.set_len(keep as u64)
            .map_err(|e| CliError::Compute(format!("cannot truncate {}: {e}", path.display())))?;
    }
    Ok(rest[..complete].lines().map(str::to_string).collect())
}

/// Progress on stderr: a bar on a terminal, a plain line every few seconds otherwise.
struct Progress {
    bar: Option<ProgressBar>,
    total: usize,
    start: Instant,
    last: Instant,
    done_at_start: usize,
}

impl Progress {
    fn new(total: usize, done: usize) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let b = ProgressBar::new(total as u64);
            if let Ok(style) =
                ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {per_sec}, ETA {eta}")
            {
                b.set_style(style);
            }
            b.set_position(done as u64);
            b
        });
        let now = Instant::now();
        Self {
            bar,
            total,
            start: now,
            last: now,
            done_at_start: done,
        }
    }

    fn update(&mut self, done: usize) {
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
                    "sweep: {done}/{} rows ({:.1} %), {rate:.1} rows/s, ETA {eta}",
                    self.total,
                    100.0 * done as f64 / self.total.max(1) as f64
                );
            }
            None => {}
        }
    }

    fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish();
        }
    }
}

/// What is left of one chunk of the grid.
struct Remaining {
    chunk: Chunk,
    /// Index in `chunk.points` of its first point not yet written.
    start: usize,
    /// `(t_vis, thresholds)` of the chunk's last one or two written points, the hints of an
    /// uninterrupted run (see `thresholds::Hint::extrapolated`).
    previous: Vec<(f64, Hint)>,
}

/// Runs the command.
pub fn run(args: &SweepArgs) -> Result<Report, CliError> {
    let (grid, header) = args.grid()?;
    // every bad input before any work starts (or any file is written)
    if args.jobs == Some(0) {
        return Err(CliError::Usage("--jobs = 0: must be >= 1".into()));
    }
    let header = header_text(args.format, &header);
    let path = &args.out;
    let exists = path.exists();
    if exists && !args.resume && !args.force {
        return Err(CliError::Usage(format!(
            "--out {}: the file exists; pass --resume to continue it or --force to overwrite it",
            path.display()
        )));
    }
    let written = if exists && args.resume {
        existing_rows(path, &header)?
    } else {
        std::fs::write(path, &header).map_err(|e| {
            CliError::Usage(format!(
                "--out {}: cannot write the file: {e}",
                path.display()
            ))
        })?;
        Vec::new()
    };
    let total = grid.len();
    if written.len() > total {
        return Err(CliError::Usage(format!(
            "--resume: {} holds {} rows, more than the {total} of this sweep",
            path.display(),
            written.len()
        )));
    }
    let mut file = OpenOptions::new().append(true).open(path).map_err(|e| {
        CliError::Usage(format!(
            "--out {}: cannot write the file: {e}",
            path.display()
        ))
    })?;
    let options = SearchOptions {
        rel_tol: args.rel_tol,
        v_max: args.v_max,
        ..SearchOptions::default()
    };
    // what is left of each chunk, with the thresholds of its last written rows (the hints of an
    // uninterrupted run)
    let done = written.len();
    let work: Vec<Remaining> = grid
        .chunks()
        .into_iter()
        .filter_map(|c| {
            let start = c.points.iter().take_while(|p| p.index < done).count();
            (start < c.points.len()).then(|| {
                let mut previous: Vec<(f64, Hint)> = c.points[..start]
                    .iter()
                    .rev()
                    .take(HINT_NEIGHBOURS)
                    .map_while(|p| {
                        let hint = written.get(p.index).and_then(|l| hint_of(args.format, l))?;
                        Some((p.t_vis, hint))
                    })
                    .collect();
                previous.reverse();
                Remaining {
                    chunk: c,
                    start,
                    previous,
                }
            })
        })
        .collect();
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .map_err(|e| CliError::Compute(format!("cannot start {jobs} threads: {e}")))?;
    let laws = Laws::new(&grid.k)?;
    let law = |k: f64| laws.get(k);
    let mut progress = Progress::new(total, done);
    let (tx, rx) = mpsc::channel::<Result<Row, ThresholdsError>>();
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let outcome = std::thread::scope(|scope| -> Result<(), CliError> {
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
                        let Remaining {
                            chunk,
                            start,
                            previous,
                        } = &work[i];
                        let mut send = |row: &Row| {
                            let _ = tx.send(Ok(row.clone()));
                        };
                        if let Err(e) =
                            chunk.compute_from(*start, previous, law, options, &mut send)
                        {
                            let _ = tx.send(Err(e));
                            stop.store(true, Ordering::Relaxed);
                        }
                    });
                }
            });
            drop(tx);
        });
        // write rows in grid order as soon as they and all before them are done
        let mut pending: BTreeMap<usize, Row> = BTreeMap::new();
        let mut next_row = done;
        for received in rx {
            let row = match received {
                Ok(row) => row,
                Err(e) => {
                    stop.store(true, Ordering::Relaxed);
                    return Err(e.into());
                }
            };
            pending.insert(row.point.index, row);
            while let Some(row) = pending.remove(&next_row) {
                file.write_all(row_text(args.format, &grid, &row).as_bytes())
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
