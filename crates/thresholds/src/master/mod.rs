//! The master tables: V_stick and V_double_onset for every material, size, geometry, T_vis and
//! k from 0.005 to 0.05, in about a microsecond, up to the cliff beyond which nothing bounces.
//!
//! In the JKR units of `docs/model.md` (a/a_eq, delta/delta_eq, time t0) a collision is
//! ```text
//! D'' = -(A D - A^3) - c_D A D',   A' = c_a v(k, beta),   beta = (9/4)(A^2 - D/3)^2/A
//! c_D = 2 (T_vis/nu^2) E* a_eq t0/m*,   c_a = E* gamma t0/(sigma0^2 T_vis a_eq)
//! ```
//! (eps = 0.01 fixed; [`contact::Contact::dimensionless`]), and V_stick,JKR is a fixed multiple
//! of the speed unit. So `F = V_stick / V_stick,JKR` and `F_on = V_double_onset / V_stick,JKR`
//! are functions of `(c_D, c_a; k)` alone, the same for every material, radius and geometry, in
//! the coordinates
//! ```text
//! x = log10 c_D           (at fixed material and size it moves only with T_vis)
//! y = log10 (c_D c_a)     (independent of T_vis and of the density)
//! ```
//!
//! - **The cliff.** Far above V_stick the rebound speed saturates (e falls as 1/V_in); where
//!   that saturated rebound vanishes, at x_c(y), V_stick diverges (about as a power of
//!   ln(1/(x_c - x))) and beyond it nothing bounces; double collisions go on a little further,
//!   so F_on diverges at a second curve. The tables end each ratio where it reaches
//!   [`F_TOP`] = 1e4: x_s(y, k) for F, x_on(y, k) for F_on, each a root in x of one collision at
//!   F_TOP V_stick,JKR found to 1e-10 and tabulated on a fine grid ([`ends`]).
//! - **Coordinates that keep the local cubic honest.** Each row of constant y holds F and F_on
//!   against u = ln(x_s - x), the log of the distance to the end (in which F is smooth all the
//!   way to the cliff), and F_on between x_s and x_on against w = ln(x_on - x) (the *strip*),
//!   all as `ln(ratio - 1)` (F > 1.00015 everywhere: the T_vis -> 0 limit lies 1.5e-4 above
//!   the rounded 14.18 of V_stick,JKR). A query interpolates at its own distance to the end
//!   (the end curves at its (y, k)): the local cubic in u on the four rows around y, the cubic
//!   in y, then the quintic in ln k through the six tables around k (11 tables, k = 0.005
//!   2^(i/3); `answer::K_STENCIL`), the sextic through seven in the first and the last interval
//!   of k (`answer::K_STENCIL_EDGE`).
//! - **Vouching.** Every node is an exact search (`build`); every interval of a row, every
//!   cell between rows and every interval between tables of neighbouring k was checked at its
//!   midpoint, and the default search agrees with each node; the tables answer only where those
//!   checks passed, and say nothing elsewhere (a thin band at the ends, where the search itself
//!   is uncertain, and next to a change of regime of the cliff). Beyond an end a ratio exceeds
//!   F_TOP, so below that search limit "nothing bounces" is an answer too. Closer to the end
//!   than vouched, a ratio is at least its value at the closest vouched point; and where a
//!   table was checked against its exact nodes closer still but the default search strays
//!   from them (`build::revouch`, `--part bounds`), at least its value there, which answers
//!   "nothing below the search limit" with a margin of 1 % ([`BOUND_MARGIN`]). Wherever the
//!   interpolation declines (next to the kink where the two kinds of bouncing meet, the band at
//!   the cliff), a floor under both ratios read off the nodes ([`floor`]) answers that too,
//!   with the same margin, for search limits up to [`floor::FLOOR_F_MAX`].
//! - **The JKR corner.** Where c_a > 1e8 (T_vis below about 1.3e-17 s for 60 um CO2, grains of a
//!   centimetre at 1e-16 s) the exact search needs millions of steps or is refused, while F has
//!   converged in c_a to a few 1e-7: the nodes there are computed at c_a = 1e8 and the tables
//!   answer with that converged value; below x = -17 (T_vis -> 0) with the value at -17.
//!
//! # Example
//! ```
//! use thresholds::{Contact, Geometry, MasterTables, Material};
//! let tables = MasterTables::standard();
//! let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
//! let d = c.dimensionless(1e-9);
//! let r = tables.ratios(d.c_d, d.c_a, 0.01, 1000.0).expect("the tables vouch here");
//! let v_stick = r.v_stick.expect("bounces below 1000 V_stick,JKR") * c.v_stick_jkr(); // m/s
//! assert!((v_stick / 0.041376 - 1.0).abs() < 1e-4); // Section 4.4: 4.14 cm/s
//! # Ok::<(), thresholds::ContactError>(())
//! ```

mod answer;
pub mod binary;
// public for `cargo xtask master-table` (the builder), not part of the API a user calls
#[doc(hidden)]
pub mod build;
pub mod ends;
mod file;
pub mod floor;
pub mod format;
pub mod interp;
mod parse;
mod table;
mod verdict;

use binary::Table;
use format::EndsData;
use std::sync::OnceLock;

pub(crate) use answer::from_table;
pub use answer::{K_STENCIL, K_STENCIL_EDGE, TABLE_REL_TOL};
pub use ends::{EndCurves, Ends};
pub use file::{ends_to_text, table_to_text};
pub use format::{FormatError, F_TOP};
pub use table::Curve;
pub use verdict::{BOUND_MARGIN, V_MAX_MARGIN};

/// Bytes aligned for `f64`: the embedded binary form's arrays are borrowed in place
/// ([`binary::Floats`]) instead of copied on first use (1.2 ms for the end curves and a table,
/// most of it the kernel's zeroing of fresh pages).
#[repr(C, align(8))]
pub(crate) struct Aligned<B: ?Sized>(pub(crate) B);

/// The tables' binary form, made by the build script from the committed text files
/// (`crates/thresholds/data/master_*.csv`), aligned for `f64`.
static ALIGNED: &Aligned<[u8]> = &Aligned(*include_bytes!(concat!(env!("OUT_DIR"), "/master.bin")));

/// [`ALIGNED`]'s bytes.
static BYTES: &[u8] = &ALIGNED.0;

/// The ratios to V_stick,JKR at one point: `None` for a ratio above the search limit (nothing
/// bounces, or double-collides, below it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ratios {
    /// V_stick / V_stick,JKR (dimensionless).
    pub v_stick: Option<f64>,
    /// V_double_onset / V_stick,JKR (dimensionless), at most `v_stick`.
    pub v_double_onset: Option<f64>,
}

/// The master tables of every k and their end curves (see the module documentation), read
/// from the embedded binary form: its index at once, each table and the end curves on first
/// use, read in place (0.06 ms for the end curves, 0.2-0.3 ms a table).
#[derive(Debug)]
pub struct MasterTables {
    bytes: &'static [u8],
    /// k of each table, increasing.
    k: Vec<f64>,
    tables: Vec<OnceLock<Option<Table>>>,
    ends: OnceLock<Option<EndCurves>>,
}

impl MasterTables {
    /// The committed tables (empty, so that every threshold is searched, if the library was
    /// built without them).
    pub fn standard() -> &'static MasterTables {
        static STANDARD: OnceLock<MasterTables> = OnceLock::new();
        STANDARD.get_or_init(|| MasterTables::from_bytes(BYTES))
    }

    /// Tables from their binary form ([`binary::to_bytes`]); empty where it cannot be read.
    pub fn from_bytes(bytes: &'static [u8]) -> MasterTables {
        let index = binary::index(bytes).unwrap_or_default();
        MasterTables {
            bytes,
            k: index.iter().map(|e| e.0).collect(),
            tables: index.iter().map(|_| OnceLock::new()).collect(),
            ends: OnceLock::new(),
        }
    }

    /// Tables already in memory (the build's, before they are written), with their end curves.
    #[doc(hidden)]
    pub fn from_parts(tables: Vec<Table>, ends: EndCurves) -> MasterTables {
        fn filled<T>(v: T) -> OnceLock<Option<T>> {
            let c = OnceLock::new();
            let _ = c.set(Some(v));
            c
        }
        MasterTables {
            bytes: &[],
            k: tables.iter().map(|t| t.k).collect(),
            tables: tables.into_iter().map(filled).collect(),
            ends: filled(ends),
        }
    }

    /// The k of the tables, increasing.
    pub fn table_k(&self) -> &[f64] {
        &self.k
    }

    /// The range of k answered: from the first table's k to the last's (empty: NaN).
    pub fn k_range(&self) -> (f64, f64) {
        match (self.k.first(), self.k.last()) {
            (Some(&a), Some(&b)) => (a, b),
            _ => (f64::NAN, f64::NAN),
        }
    }

    /// Table `i` (in increasing k).
    pub fn table(&self, i: usize) -> Option<&Table> {
        self.tables
            .get(i)?
            .get_or_init(|| binary::table_from_bytes(self.bytes, i))
            .as_ref()
    }

    /// The end curves.
    pub fn ends(&self) -> Option<&EndCurves> {
        self.ends
            .get_or_init(|| binary::ends_from_bytes(self.bytes).map(EndCurves::new))
            .as_ref()
    }

    /// Whether the k checks cover every interval between the tables, so that every k of
    /// [`MasterTables::k_range`] is answered (else only the tables' own k).
    pub fn k_checked(&self) -> bool {
        let Some(e) = self.ends() else { return false };
        let e: &EndsData = e.data();
        self.k.len() >= crate::k_axis::MIN_TABLES_BETWEEN
            && e.kcheck_y.2 > 0
            && e.kcheck.len() == (self.k.len() - 1) * e.kcheck_y.2
    }

    /// The limits of the polynomial in ln k between tables `i` and `i + 1` at `y`, as a table's
    /// cell ([`format::CellData::limits`]); `None` where it was not checked.
    fn k_check(&self, i: usize, y: f64) -> Option<[f64; format::CELL_LIMITS]> {
        let e: &EndsData = self.ends()?.data();
        let (y0, dy, ny) = e.kcheck_y;
        // checks made for another set of tables vouch for nothing
        if e.kcheck.len() != self.k.len().saturating_sub(1) * ny {
            return None;
        }
        let b = ((y - y0) / dy).floor();
        if !(b >= 0.0 && b < ny as f64) {
            return None;
        }
        Some(e.kcheck.get(i * ny + b as usize)?.limits())
    }

    /// F and F_on at the drag number `c_d` and the crack-speed number `c_a`
    /// ([`contact::Contact::dimensionless`]) for the modulus ratio `k`, with the search limit
    /// `f_max` = v_max / V_stick,JKR: a ratio above it is `None` (nothing below v_max). `None`
    /// altogether where the tables do not vouch for the answer (k outside 0.005-0.05, the thin
    /// bands at the ends, within [`V_MAX_MARGIN`] of the limit), and for a `c_d` or `c_a` that
    /// is not positive and finite: the tables vouch for no such point, and
    /// [`crate::sticking_thresholds`] then leaves it to the search, which names the bad input.
    pub fn ratios(&self, c_d: f64, c_a: f64, k: f64, f_max: f64) -> Option<Ratios> {
        if !(c_d > 0.0 && c_a > 0.0 && c_d.is_finite() && c_a.is_finite()) {
            return None;
        }
        let x = c_d.log10();
        self.ratios_at(x, x + c_a.log10(), k, f_max)
    }

    /// [`MasterTables::ratios`] at `x = log10 c_D`, `y = log10 (c_D c_a)`.
    pub fn ratios_at(&self, x: f64, y: f64, k: f64, f_max: f64) -> Option<Ratios> {
        let (s, o) = self.answer(x, y, k, f_max)?;
        Some(Ratios {
            v_stick: s,
            v_double_onset: o,
        })
    }

    /// [`MasterTables::ratios_at`] from the interpolation alone, without the nodes' floor
    /// ([`floor`]): what the tables answered before it, for the tests and checks that tell
    /// the floor's verdicts apart.
    pub fn interpolated_at(&self, x: f64, y: f64, k: f64, f_max: f64) -> Option<Ratios> {
        let (s, o) = self.interpolate(x, y, k, f_max)?;
        Some(Ratios {
            v_stick: s,
            v_double_onset: o,
        })
    }
}
