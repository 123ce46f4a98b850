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
//! end interpolated in y) from `d_lo` up to [`SHEARED_REACH`] (the checks reach no farther).
//! The optional `d_lb` (`cargo xtask master-table --part bounds`; absent: `d_lo`) reach closer
//! to the end for lower bounds only: there the interpolation was checked against the exact
//! nodes but the default search strays from them by more than the tables promise, so the tables
//! answer only "above the search limit" from it (`MasterTables::ratios`, `BOUND_MARGIN`).
//!
//! The end curves x_s(y, k) and x_on(y, k) on a uniform grid in y and ln k:
//! ```text
//! grid,<y0>,<dy>,<ny>,<k0>,<steps per octave of k>,<nk>
//! k,<k>                                                      then ny lines:
//! <x_s>,<x_on>,<valid 0|1>
//! kgrid,<y0>,<dy>,<ny>                                       the y bins of the k checks
//! kcheck,<x_hi F>,<x_hi F_on>,<d_lo F>,<d_lo F_on>,<d_lo strip F_on>[,<d_lb ...> x 3]
//!                                                            per k interval, y bin
//! ```
//!
//! The reader: `parse.rs` (its items are re-exported here). The form the library
//! interpolates, and the binary form it embeds: [`super::binary`].

/// The largest ratio the tables hold: each row ends where F = V_stick/V_stick,JKR (and where
/// F_on) reaches it. Beyond, nothing bounces (double-collides) below this many V_stick,JKR.
/// 1e4: ten times the default search limit (1000 V_stick,JKR), so that any `v_max` up to it is
/// answered; above it a search can meet the hyper-speed bouncing of large soft grains (from about
/// 5e5 V_stick,JKR at y = -4).
pub const F_TOP: f64 = 1e4;

/// How far from the end (in x) the checks at a fixed distance to it reach, the cells' and the k
/// checks': a cell's or a k check's `d_lo` vouches for the sheared interpolation from `d_lo` up
/// to this distance only; farther from the end only plain x was checked. (Until 2026-11-28 the
/// answer read the sheared form at any distance beyond `d_lo`: next to the kink, where a cell's
/// plain checks stop at a crossing of the two kinds of bouncing 0.1-0.3 in x below x_s - 2, that
/// answered F up to 3.7 % off, k = 0.0317, x = -0.562, y = -4.678, F = 87.70 against 90.94.)
pub const SHEARED_REACH: f64 = 2.0;

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

    /// The nodes as `(x, [F, F_on])`, x increasing (what a build's interpolation takes).
    pub fn nodes(&self) -> Vec<(f64, [f64; 2])> {
        (0..self.x.len())
            .map(|i| (self.x[i], [self.f_stick[i], self.f_onset[i]]))
            .collect()
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

    /// The vouched limits as [`VOUCHED_LIMITS`] numbers: `x_hi` then `d_lo`.
    pub fn vouched(&self) -> [f64; VOUCHED_LIMITS] {
        [
            self.x_hi[0],
            self.x_hi[1],
            self.d_lo[0],
            self.d_lo[1],
            self.d_lo[2],
        ]
    }

    /// As numbers: [`CellData::vouched`], then `d_lb` where it is given (a `cell` or `kcheck`
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

/// How many numbers a cell's vouched limits are ([`CellData::vouched`]).
pub const VOUCHED_LIMITS: usize = 5;

/// How many numbers a cell's limits are in the interpolation form ([`CellData::limits`]): the
/// vouched ones and the three lower-bound limits.
pub const CELL_LIMITS: usize = VOUCHED_LIMITS + 3;

/// In the interpolation form ([`CellData::limits`]), each sheared limit's lower-bound limit
/// stands this many places after it.
pub const LOWER_BOUND_OFFSET: usize = 3;

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

pub use super::parse::{parse_ends, parse_table, FormatError};
