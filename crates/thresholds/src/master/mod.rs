//! The master table: V_stick and V_double_onset for every material, size, geometry and T_vis
//! from the model's two dimensionless numbers, in microseconds.
//!
//! In the JKR units of `docs/model.md` (a/a_eq, delta/delta_eq, time t0) a collision is
//! ```text
//! D'' = -(A D - A^3) - c_D A D',   A' = c_a v(k, beta),   beta = (9/4)(A^2 - D/3)^2/A
//! c_D = 2 (T_vis/nu^2) E* a_eq t0/m*,   c_a = E* gamma t0/(sigma0^2 T_vis a_eq)
//! ```
//! (eps = 0.01 fixed; [`contact::Contact::dimensionless`]), and V_stick,JKR is a fixed multiple
//! of the speed unit a_eq/t0. So `F = V_stick / V_stick,JKR` and `F_on = V_double_onset /
//! V_stick,JKR` are functions of `(c_D, c_a; k)` alone, the same for every material, radius and
//! geometry. The table holds them for k = 0.01 and 0.02 ([`MasterTable::standard`]) in the
//! coordinates
//! ```text
//! x = log10 c_D           (at fixed material and size it moves only with T_vis)
//! y = log10 (c_D c_a)     (independent of T_vis and of the density)
//! ```
//! as `ln(F - 1)` and `ln(F_on - 1)` (F > 1.00015 everywhere: the T_vis -> 0 limit of the
//! model lies 1.5e-4 above the rounded 14.18 of V_stick,JKR), each row of constant y on its
//! own nodes in x, computed by the exact search at `rel_tol` 1e-8 ([`build`]).
//!
//! - **Interpolation**: the local cubic through four nodes in x on each of the four rows around
//!   y, then the cubic through those four values in y ([`MasterTable::ratios`]).
//! - **Vouching**: every interval of a row and every cell between two rows was checked at its
//!   midpoint against the exact search; the table answers only where those checks passed within
//!   [`build::BuildConfig::tol`] (2e-6 of F), and says `None` elsewhere: beyond its domain, and
//!   near the cliff (c_D of 0.2-1 depending on y) where F climbs steeply and then nothing
//!   bounces. The caller then runs the exact search.
//! - **The JKR corner**: where c_a > 1e8 (T_vis below about 1e-14 s for 60 um CO2, grains of a
//!   centimetre at 1e-16 s) the exact search needs millions of steps or fails, while F has
//!   converged in c_a to a few 1e-7: the nodes there are computed at c_a = 1e8
//!   ([`build::BuildConfig::z_clamp`]; F moves by 2-4e-7 from c_a = 1e8 to 1e10).
//!
//! # Example
//! ```
//! use thresholds::{Contact, Geometry, MasterTable, Material};
//! let table = MasterTable::standard(0.01).expect("k = 0.01 is tabulated");
//! let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
//! let d = c.dimensionless(1e-9);
//! let r = table.ratios(d.c_d, d.c_a).expect("inside the vouched domain");
//! let v_stick = r.v_stick * c.v_stick_jkr(); // m/s
//! assert!((v_stick / 0.041376 - 1.0).abs() < 1e-4); // Section 4.4: 4.14 cm/s
//! # Ok::<(), thresholds::ContactError>(())
//! ```

mod answer;
pub mod build;
mod file;
mod interp;

use interp::{interval, lagrange, local_cubic, stencil_start};
use std::sync::OnceLock;

pub(crate) use answer::from_table;
pub use file::TableFileError;

/// The k values with a committed table.
pub const STANDARD_K: [f64; 2] = [0.01, 0.02];

/// The committed tables (`crates/thresholds/data/`, written by `cargo xtask master-table`).
const STANDARD_FILES: [&[u8]; 2] = [
    include_bytes!("../../data/master_k0.01.csv"),
    include_bytes!("../../data/master_k0.02.csv"),
];

/// V_stick / V_stick,JKR and V_double_onset / V_stick,JKR at one point of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ratios {
    /// V_stick / V_stick,JKR (dimensionless).
    pub v_stick: f64,
    /// V_double_onset / V_stick,JKR (dimensionless), at most `v_stick`.
    pub v_double_onset: f64,
}

/// One row of the table: constant y, its own nodes in x.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Row {
    /// log10 (c_D c_a).
    pub(crate) y: f64,
    /// log10 c_D of the nodes, increasing.
    pub(crate) x: Vec<f64>,
    /// ln(F - 1) at the nodes.
    pub(crate) g_stick: Vec<f64>,
    /// ln(F_on - 1) at the nodes.
    pub(crate) g_onset: Vec<f64>,
    /// The row's interpolation is vouched for from `x[0]` up to here.
    pub(crate) x_hi: f64,
    /// The smallest x found without bouncing up to 1000 V_stick,JKR (the cliff); infinite when
    /// bouncing was found up to the end of the row.
    pub(crate) cliff: f64,
}

impl Row {
    fn at(&self, x: f64) -> (f64, f64) {
        (
            local_cubic(&self.x, &self.g_stick, x),
            local_cubic(&self.x, &self.g_onset, x),
        )
    }
}

/// The master table of one k (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct MasterTable {
    k: f64,
    header: Vec<String>,
    rows: Vec<Row>,
    /// The y of each row (kept apart for the interval search of every query).
    ys: Vec<f64>,
    /// For the cell between rows `j` and `j + 1`: its y-interpolation is vouched for up to this x.
    cells: Vec<f64>,
}

impl MasterTable {
    /// A table of `k` from its rows and cells.
    pub(crate) fn new(k: f64, header: Vec<String>, rows: Vec<Row>, cells: Vec<f64>) -> Self {
        let ys = rows.iter().map(|r| r.y).collect();
        Self {
            k,
            header,
            rows,
            ys,
            cells,
        }
    }

    /// The committed table of `k` (0.01 or 0.02, [`STANDARD_K`]); `None` for any other k.
    /// Parsed once, on first use.
    pub fn standard(k: f64) -> Option<&'static MasterTable> {
        static TABLES: [OnceLock<Option<MasterTable>>; 2] = [OnceLock::new(), OnceLock::new()];
        let i = STANDARD_K.iter().position(|&s| s == k)?;
        TABLES[i]
            .get_or_init(|| MasterTable::parse(STANDARD_FILES[i]).ok())
            .as_ref()
    }

    /// The modulus ratio k of this table.
    pub fn k(&self) -> f64 {
        self.k
    }

    /// The `#` header lines of the table's file: the command that made it, its commit, the
    /// tolerances and the domain.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// Puts `lines` before the header lines (the command and commit that built the table).
    pub fn prepend_header(&mut self, lines: &[String]) {
        self.header.splice(0..0, lines.iter().cloned());
    }

    /// The range of y = log10(c_D c_a) the table's rows span.
    pub fn y_range(&self) -> (f64, f64) {
        match (self.rows.first(), self.rows.last()) {
            (Some(a), Some(b)) => (a.y, b.y),
            _ => (f64::NAN, f64::NAN),
        }
    }

    /// `(y, cliff)` of each row: the smallest x = log10 c_D found without bouncing up to
    /// 1000 V_stick,JKR (infinite where bouncing was found up to the end of the row).
    pub fn cliff(&self) -> Vec<(f64, f64)> {
        self.rows.iter().map(|r| (r.y, r.cliff)).collect()
    }

    /// `F = V_stick / V_stick,JKR` and `F_on = V_double_onset / V_stick,JKR` for the drag number
    /// `c_d` and the crack-speed number `c_a` ([`contact::Contact::dimensionless`]); `None` where
    /// the table does not vouch for its accuracy (outside its domain, near the cliff).
    pub fn ratios(&self, c_d: f64, c_a: f64) -> Option<Ratios> {
        if !(c_d > 0.0 && c_a > 0.0 && c_d.is_finite() && c_a.is_finite()) {
            return None;
        }
        let x = c_d.log10();
        self.ratios_at(x, x + c_a.log10())
    }

    /// [`MasterTable::ratios`] at `x = log10 c_D`, `y = log10 (c_D c_a)`.
    pub fn ratios_at(&self, x: f64, y: f64) -> Option<Ratios> {
        let (g_stick, g_onset) = self.g_at(x, y)?;
        let v_stick = 1.0 + g_stick.exp();
        let v_double_onset = (1.0 + g_onset.exp()).min(v_stick);
        Some(Ratios {
            v_stick,
            v_double_onset,
        })
    }

    /// `(ln(F - 1), ln(F_on - 1))` interpolated at `(x, y)`, where vouched.
    fn g_at(&self, x: f64, y: f64) -> Option<(f64, f64)> {
        let n = self.rows.len();
        if n < 4 {
            return None;
        }
        let ys = &self.ys;
        // only cells with a full stencil of rows, and not the two end cells
        if !(y >= ys[1] && y <= ys[n - 2]) {
            return None;
        }
        let j = interval(ys, y);
        let s = stencil_start(j, n);
        let stencil = &self.rows[s..s + 4];
        let x_lo = stencil
            .iter()
            .map(|r| r.x[0])
            .fold(f64::NEG_INFINITY, f64::max);
        let x_hi = stencil.iter().map(|r| r.x_hi).fold(self.cells[j], f64::min);
        if !(x >= x_lo && x <= x_hi) {
            return None;
        }
        let mut gs = [0.0; 4];
        let mut go = [0.0; 4];
        for (i, r) in stencil.iter().enumerate() {
            (gs[i], go[i]) = r.at(x);
        }
        let sy = &ys[s..s + 4];
        Some((lagrange(sy, &gs, y), lagrange(sy, &go, y)))
    }
}
