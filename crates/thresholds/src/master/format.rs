//! The master tables as data: their text form (the committed CSV files) and their binary form
//! (what the library embeds), with nothing but `std`, so that the build script
//! (`crates/thresholds/build.rs`, which includes this file) and the library read them with the
//! same code.
//!
//! A table of one k, as text (`#` lines first, one record a line):
//! ```text
//! k,<k>
//! row,<y>,<x_s>,<x_on>,<monotone 0|1>[,<none_beyond>]       a row of constant y = log10(c_D c_a)
//! body,<d_lo F>,<d_lo F_on>[,<d_lb F>,<d_lb F_on>]          the row's body (d = x_s - x)
//! node,<x>,<F>,<F_on>                                        x = log10 c_D, F = V_stick/V_stick,JKR
//! strip,<d_lo F_on>[,<d_lb F_on>]                           the row's strip (d = x_on - x)
//! snode,<x>,<F_on>
//! cell,<x_hi F>,<x_hi F_on>,<d_lo F>,<d_lo F_on>,<d_lo strip F_on>[,<d_lb F>,<d_lb F_on>,<d_lb strip F_on>]
//!                                                            between this row and the next
//! ```
//! x_s is where F reaches [`F_TOP`], x_on where F_on does. A piece is vouched for where its
//! distance to its end is at least its `d_lo` (`inf`: nowhere). A cell is vouched for in plain
//! x (rows interpolated at the same x) up to `x_hi`, and at a fixed distance to the end (the
//! end interpolated in y) down to `d_lo`. The optional `d_lb` (`cargo xtask master-table --part
//! bounds`; absent: `d_lo`) reach closer to the end for lower bounds only: there the
//! interpolation was checked against the exact nodes but the default search strays from them
//! by more than the tables promise, so the tables answer only "above the search limit" from it
//! (`MasterTables::ratios`, `BOUND_MARGIN`).
//!
//! The end curves x_s(y, k) and x_on(y, k) on a uniform grid in y and ln k:
//! ```text
//! grid,<y0>,<dy>,<ny>,<k0>,<steps per octave of k>,<nk>
//! k,<k>                                                      then ny lines:
//! <x_s>,<x_on>,<valid 0|1>
//! kgrid,<y0>,<dy>,<ny>                                       the y bins of the k checks
//! kcheck,<x_hi F>,<x_hi F_on>,<d_lo F>,<d_lo F_on>,<d_lo strip F_on>   per k interval, y bin
//! ```
//!
//! The form the library interpolates, and the binary form it embeds: [`super::binary`].

/// The largest ratio the tables hold: each row ends where F = V_stick/V_stick,JKR (and where
/// F_on) reaches it. Beyond, nothing bounces (double-collides) below this many V_stick,JKR.
/// 1e4: ten times the default search limit (1000 V_stick,JKR), so that any `v_max` up to it is
/// answered; above it a search can meet the hyper-speed bouncing of large soft grains (from about
/// 5e5 V_stick,JKR at y = -4).
pub const F_TOP: f64 = 1e4;

/// One piece of a row: nodes in x with their ratios, vouched for down to a distance to the
/// piece's end.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PieceData {
    /// log10 c_D of the nodes, increasing.
    pub x: Vec<f64>,
    /// F = V_stick / V_stick,JKR at the nodes (NaN in a strip, which has none).
    pub f_stick: Vec<f64>,
    /// F_on = V_double_onset / V_stick,JKR at the nodes.
    pub f_onset: Vec<f64>,
    /// `[F, F_on]`: the interpolation is vouched for where the distance to the piece's end is at
    /// least this (infinite: nowhere).
    pub d_lo: [f64; 2],
    /// `[F, F_on]`: closer to the end than `d_lo`, the interpolation is within the build's
    /// tolerance of the exact nodes down to this distance (`--part bounds`), a lower bound
    /// only; `None`: `d_lo`.
    pub d_lb: Option<[f64; 2]>,
}

impl PieceData {
    /// The distance to the end down to which ratio `v` (0: F, 1: F_on) serves as a lower
    /// bound: `d_lb`, else `d_lo`.
    pub fn bound_limit(&self, v: usize) -> f64 {
        self.d_lb.map_or(self.d_lo[v], |d| d[v])
    }
}

/// One row of constant y.
#[derive(Debug, Clone, PartialEq)]
pub struct RowData {
    /// log10 (c_D c_a).
    pub y: f64,
    /// log10 c_D where F = [`F_TOP`]: the end of the body.
    pub x_s: f64,
    /// log10 c_D where F_on = [`F_TOP`]: the end of the strip (at least `x_s`).
    pub x_on: f64,
    /// Both ratios increase with x over the row's nodes, so a point closer to the end than the
    /// vouched nodes has a ratio at least that of the last vouched one.
    pub monotone: bool,
    /// For a row that is not `monotone`: nothing bounces (double-collides) beyond its ends up to
    /// this ratio, as the build checked it (the row record's optional sixth number; 0: not
    /// checked). A monotone row's is [`F_TOP`].
    pub none_beyond: f64,
    /// Nodes with x < x_s, both ratios, interpolated in u = ln(x_s - x).
    pub body: PieceData,
    /// Nodes between x_s and x_on (the strip where double collisions but no bouncing remain
    /// up to F_TOP), F_on only, interpolated in w = ln(x_on - x); empty where the strip is too
    /// narrow to tabulate.
    pub strip: PieceData,
}

impl RowData {
    /// The ratio up to which the row's ratios increase towards its ends, every piece and both
    /// ratios ([`increasing_up_to`]).
    pub fn increasing_up_to(&self) -> f64 {
        increasing_up_to(&self.body.f_stick)
            .min(increasing_up_to(&self.body.f_onset))
            .min(increasing_up_to(&self.strip.f_onset))
    }
}

/// A ratio may fall by this (relative) from one node to the next and still count as increasing:
/// on the JKR plateau (F = 1.000155) the nodes scatter by a few 1e-9.
pub const NODE_NOISE: f64 = 1e-8;

/// The ratio up to which `ratios` (nodes in increasing x, towards the end) increase: the least
/// of the nodes after the first that falls (by more than [`NODE_NOISE`]), infinite where none
/// falls. At every node the ratio is then at least the smaller of its value at any earlier node
/// and this. Next to the kink of the cliff a row's F is the lower of two thresholds and falls
/// where the second takes over (at F of 30-800); elsewhere the rows are flat to a few 1e-6 at
/// F_TOP (F of 9990-9999.9), where the search's noise makes them fall a little: increasing up to
/// there serves every `v_max` below it.
pub fn increasing_up_to(ratios: &[f64]) -> f64 {
    // pairs with a NaN (a ratio the search had no value for) count as increasing
    match ratios
        .windows(2)
        .position(|w| w[1] < w[0] * (1.0 - NODE_NOISE))
    {
        Some(i) => ratios[i + 1..]
            .iter()
            .filter(|r| !r.is_nan())
            .fold(f64::INFINITY, |a, &b| a.min(b)),
        None => f64::INFINITY,
    }
}

/// The vouched limits of the cell between two rows, or of a k interval in a bin of y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellData {
    /// `[F, F_on]` interpolated at the same x on every row: vouched for up to this x
    /// (`-inf`: nowhere).
    pub x_hi: [f64; 2],
    /// `[body F, body F_on, strip F_on]` at a fixed distance to the end: vouched for where the
    /// distance is at least this (`inf`: nowhere).
    pub d_lo: [f64; 3],
    /// `[body F, body F_on, strip F_on]`: checked against the exact nodes down to this
    /// distance, for lower bounds only (see [`PieceData::d_lb`]); `None`: `d_lo`.
    pub d_lb: Option<[f64; 3]>,
}

impl CellData {
    /// Nothing vouched for.
    pub const NONE: CellData = CellData {
        x_hi: [f64::NEG_INFINITY; 2],
        d_lo: [f64::INFINITY; 3],
        d_lb: None,
    };

    /// The vouched limits as [`VOUCHED_LIMITS`] numbers: `x_hi` then `d_lo` (a k check's
    /// record).
    pub fn vouched(&self) -> [f64; VOUCHED_LIMITS] {
        [
            self.x_hi[0],
            self.x_hi[1],
            self.d_lo[0],
            self.d_lo[1],
            self.d_lo[2],
        ]
    }

    /// As numbers: [`CellData::vouched`], then `d_lb` where it is given (a table's `cell`
    /// record).
    pub fn numbers(&self) -> Vec<f64> {
        let mut v = self.vouched().to_vec();
        v.extend(self.d_lb.into_iter().flatten());
        v
    }

    /// From [`VOUCHED_LIMITS`] or [`CELL_LIMITS`] numbers ([`CellData::numbers`]).
    pub fn from_numbers(v: &[f64]) -> CellData {
        CellData {
            x_hi: [v[0], v[1]],
            d_lo: [v[2], v[3], v[4]],
            d_lb: (v.len() == CELL_LIMITS).then(|| [v[5], v[6], v[7]]),
        }
    }

    /// The distance down to which limit `c` (0: body F, 1: body F_on, 2: strip F_on) serves
    /// as a lower bound: `d_lb`, else `d_lo`.
    pub fn bound_limit(&self, c: usize) -> f64 {
        self.d_lb.map_or(self.d_lo[c], |d| d[c])
    }

    /// The interpolation form: `[x_hi F, x_hi F_on, u_lo F, u_lo F_on, u_lo strip, u_lb F,
    /// u_lb F_on, u_lb strip]` (u = ln d).
    pub fn limits(&self) -> [f64; CELL_LIMITS] {
        [
            self.x_hi[0],
            self.x_hi[1],
            self.d_lo[0].ln(),
            self.d_lo[1].ln(),
            self.d_lo[2].ln(),
            self.bound_limit(0).ln(),
            self.bound_limit(1).ln(),
            self.bound_limit(2).ln(),
        ]
    }
}

/// How many numbers a cell's vouched limits are ([`CellData::vouched`]): all a k check has.
pub const VOUCHED_LIMITS: usize = 5;

/// How many numbers a cell's limits are in the interpolation form ([`CellData::limits`]): the
/// vouched ones and the three lower-bound limits.
pub const CELL_LIMITS: usize = VOUCHED_LIMITS + 3;

/// The table of one k.
#[derive(Debug, Clone, PartialEq)]
pub struct TableData {
    /// The modulus ratio k.
    pub k: f64,
    /// The `#` lines: the command, the commit, the settings.
    pub header: Vec<String>,
    /// Rows in increasing y.
    pub rows: Vec<RowData>,
    /// `rows.len() - 1` cells.
    pub cells: Vec<CellData>,
}

/// The end curves on their grid.
#[derive(Debug, Clone, PartialEq)]
pub struct EndsData {
    /// The `#` lines.
    pub header: Vec<String>,
    /// The first y and the y step.
    pub y0: f64,
    /// The y step.
    pub dy: f64,
    /// The number of y values.
    pub ny: usize,
    /// The first k.
    pub k0: f64,
    /// k steps per octave (k_j = k0 2^(j / per_octave)).
    pub per_octave: usize,
    /// The number of k values.
    pub nk: usize,
    /// x_s at (k_j, y_i), index `j * ny + i` (NaN where it could not be computed).
    pub x_s: std::borrow::Cow<'static, [f64]>,
    /// x_on likewise.
    pub x_on: std::borrow::Cow<'static, [f64]>,
    /// Whether a cubic through the point and its neighbours is trusted there: 1.0, or 0.0 next
    /// to a kink of the curves, where the regime of the cliff changes (numbers, as the binary
    /// form holds them, so that they are borrowed in place; [`EndsData::is_valid`]).
    pub valid: std::borrow::Cow<'static, [f64]>,
    /// The y bins of the checks between tables of neighbouring k: first y, step, count.
    pub kcheck_y: (f64, f64, usize),
    /// For the k interval between tables i and i + 1 and y bin b (index `i * count + b`): where
    /// the polynomial in ln k (through the six tables around k) is vouched for.
    pub kcheck: Vec<CellData>,
}

impl EndsData {
    /// Whether point `at` of the grid is valid ([`EndsData::valid`]).
    pub fn is_valid(&self, at: usize) -> bool {
        self.valid.get(at) == Some(&1.0)
    }

    /// No grid and no values yet (NaN numbers, zero counts).
    pub fn empty() -> EndsData {
        EndsData {
            header: Vec::new(),
            y0: f64::NAN,
            dy: f64::NAN,
            ny: 0,
            k0: f64::NAN,
            per_octave: 0,
            nk: 0,
            x_s: Vec::new().into(),
            x_on: Vec::new().into(),
            valid: Vec::new().into(),
            kcheck_y: (f64::NAN, f64::NAN, 0),
            kcheck: Vec::new(),
        }
    }
}

/// A file that cannot be read: its line (1-based; 0 for the whole file) and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FormatError {
    /// 1-based line number (0: the file as a whole).
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

fn bad(line: usize, problem: impl Into<String>) -> FormatError {
    FormatError {
        line,
        problem: problem.into(),
    }
}

/// The fields of a record line after its name, as numbers (`inf`, `nan` accepted).
fn numbers(line: usize, fields: &[&str], n: usize) -> Result<Vec<f64>, FormatError> {
    if fields.len() != n {
        return Err(bad(
            line,
            format!("expected {n} numbers, found {}", fields.len()),
        ));
    }
    fields
        .iter()
        .map(|f| {
            f.trim()
                .parse::<f64>()
                .map_err(|_| bad(line, format!("'{f}' is not a number")))
        })
        .collect()
}

/// Lower-bound limits `lb` (none, or one for each of the vouched limits `lo`), each a
/// distance above 0 and at most its vouched one: a NaN or a larger one would loosen the
/// tables' answers unnoticed.
fn bounds_within(line: usize, lo: &[f64], lb: &[f64]) -> Result<(), FormatError> {
    if lb.iter().zip(lo).all(|(&b, &l)| b > 0.0 && b <= l) {
        Ok(())
    } else {
        Err(bad(
            line,
            "a lower-bound limit (d_lb) must be above 0 and at most its d_lo",
        ))
    }
}

/// Reads a table from its text.
pub fn parse_table(text: &str) -> Result<TableData, FormatError> {
    let mut t = TableData {
        k: f64::NAN,
        header: Vec::new(),
        rows: Vec::new(),
        cells: Vec::new(),
    };
    // which piece the nodes go to: false = body, true = strip
    let mut in_strip = false;
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        if let Some(h) = line.strip_prefix('#') {
            t.header.push(h.trim_start().to_string());
            continue;
        }
        if line.trim().is_empty() {
            continue;
        }
        let mut fields = line.split(',');
        let name = fields.next().unwrap_or("");
        let rest: Vec<&str> = fields.collect();
        let row = |t: &mut TableData| -> Result<usize, FormatError> {
            t.rows
                .len()
                .checked_sub(1)
                .ok_or_else(|| bad(n, "a record before any row"))
        };
        match name {
            "k" => t.k = numbers(n, &rest, 1)?[0],
            "row" => {
                // the sixth number (none_beyond) only where a row that is not monotone was checked
                let v = numbers(n, &rest, if rest.len() == 5 { 5 } else { 4 })?;
                let monotone = v[3] == 1.0;
                t.rows.push(RowData {
                    y: v[0],
                    x_s: v[1],
                    x_on: v[2],
                    monotone,
                    none_beyond: match v.get(4) {
                        _ if monotone => F_TOP,
                        Some(&f) => f,
                        None => 0.0,
                    },
                    body: PieceData::default(),
                    strip: PieceData::default(),
                });
                in_strip = false;
            }
            "body" => {
                let j = row(&mut t)?;
                let v = numbers(n, &rest, if rest.len() == 4 { 4 } else { 2 })?;
                bounds_within(n, &v[..2], &v[2..])?;
                t.rows[j].body.d_lo = [v[0], v[1]];
                t.rows[j].body.d_lb = (v.len() == 4).then(|| [v[2], v[3]]);
                in_strip = false;
            }
            "strip" => {
                let j = row(&mut t)?;
                let v = numbers(n, &rest, if rest.len() == 2 { 2 } else { 1 })?;
                bounds_within(n, &v[..1], &v[1..])?;
                t.rows[j].strip.d_lo = [f64::INFINITY, v[0]];
                t.rows[j].strip.d_lb = v.get(1).map(|&d| [f64::INFINITY, d]);
                in_strip = true;
            }
            "node" | "snode" => {
                let j = row(&mut t)?;
                let (x, s, o) = if name == "node" {
                    let v = numbers(n, &rest, 3)?;
                    (v[0], v[1], v[2])
                } else {
                    let v = numbers(n, &rest, 2)?;
                    (v[0], f64::NAN, v[1])
                };
                if (name == "snode") != in_strip {
                    return Err(bad(n, format!("a {name} record outside its piece")));
                }
                let p = if in_strip {
                    &mut t.rows[j].strip
                } else {
                    &mut t.rows[j].body
                };
                if p.x.last().is_some_and(|&last| last >= x) {
                    return Err(bad(n, "nodes must increase in x"));
                }
                let ratio_ok = |r: f64| r > 1.0 && r.is_finite();
                if !(ratio_ok(o) && (in_strip || ratio_ok(s))) {
                    return Err(bad(n, "a ratio must be > 1 and finite"));
                }
                p.x.push(x);
                p.f_stick.push(s);
                p.f_onset.push(o);
            }
            "cell" => {
                let with_bounds = rest.len() == CELL_LIMITS;
                let v = numbers(
                    n,
                    &rest,
                    if with_bounds {
                        CELL_LIMITS
                    } else {
                        VOUCHED_LIMITS
                    },
                )?;
                bounds_within(n, &v[2..VOUCHED_LIMITS], &v[VOUCHED_LIMITS..])?;
                t.cells.push(CellData::from_numbers(&v));
            }
            other => return Err(bad(n, format!("unknown record '{other}'"))),
        }
    }
    let ordered = t.rows.windows(2).all(|w| w[0].y < w[1].y);
    let sized = t.cells.len() + 1 == t.rows.len();
    let ends = t
        .rows
        .iter()
        .all(|r| r.x_s <= r.x_on && r.body.x.last().is_none_or(|&x| x < r.x_s));
    if !(t.k > 0.0 && t.k < 1.0 && ordered && sized && ends) {
        return Err(bad(
            0,
            "a table needs k in (0, 1), rows increasing in y, body nodes below x_s <= x_on, and a cell between each two rows",
        ));
    }
    Ok(t)
}

/// Reads the end curves from their text.
pub fn parse_ends(text: &str) -> Result<EndsData, FormatError> {
    let mut e = EndsData::empty();
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        if let Some(h) = line.strip_prefix('#') {
            e.header.push(h.trim_start().to_string());
            continue;
        }
        let fields: Vec<&str> = line.split(',').collect();
        match fields[0] {
            "" => {}
            "grid" => {
                let v = numbers(n, &fields[1..], 6)?;
                (e.y0, e.dy, e.ny, e.k0, e.per_octave, e.nk) = (
                    v[0],
                    v[1],
                    v[2] as usize,
                    v[3],
                    v[4] as usize,
                    v[5] as usize,
                );
            }
            "k" => {
                let k = numbers(n, &fields[1..], 1)?[0];
                let expected = e.k0 * 2f64.powf(e.x_s.len() as f64 / (e.ny * e.per_octave) as f64);
                if e.ny == 0
                    || !e.x_s.len().is_multiple_of(e.ny)
                    || (k / expected - 1.0).abs() > 1e-9
                {
                    return Err(bad(n, format!("k = {k} is not the next k of the grid")));
                }
            }
            "kgrid" => {
                let v = numbers(n, &fields[1..], 3)?;
                e.kcheck_y = (v[0], v[1], v[2] as usize);
            }
            "kcheck" => {
                let v = numbers(n, &fields[1..], VOUCHED_LIMITS)?;
                e.kcheck.push(CellData::from_numbers(&v));
            }
            _ => {
                let v = numbers(n, &fields, 3)?;
                e.x_s.to_mut().push(v[0]);
                e.x_on.to_mut().push(v[1]);
                e.valid.to_mut().push(if v[2] == 1.0 { 1.0 } else { 0.0 });
            }
        }
    }
    if !(e.ny >= 4 && e.nk >= 4 && e.dy > 0.0 && e.k0 > 0.0 && e.per_octave > 0)
        || e.x_s.len() != e.ny * e.nk
        || (e.kcheck_y.2 > 0 && !e.kcheck.len().is_multiple_of(e.kcheck_y.2))
    {
        return Err(bad(
            0,
            "the end curves need a grid of at least 4 x 4 and every value of it",
        ));
    }
    Ok(e)
}
