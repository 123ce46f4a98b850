//! Instant restitution: the rebound of a collision, V_out and e, from tables, in microseconds
//! instead of the milliseconds of the ODE (Section 4).
//!
//! In the JKR units of `docs/model.md` a collision depends on (c_D, c_a, k) and on the impact
//! speed in units of V_stick,JKR, so `w = V_out / V_stick` is one function of
//! `(x = log10 c_D, y = log10(c_D c_a), k, V_in)` for every material, size and geometry. Along
//! the impact speed it changes sign at V_stick (from the master tables,
//! [`crate::MasterTables`]); on each side the tables hold `h = ln |w|` against the log of the
//! distance to V_stick:
//! ```text
//! bouncing    V_in > V_stick:          sigma = ln(V_in / V_stick)                 in [1e-4, 9.5]
//! double      V_on < V_in < V_stick:   nu = ln(V_stick / V_in) / ln(F / F_on)     in [1e-4, 0.999]
//! h = ln(|V_out| / V_stick), channels evenly in ln sigma + sigma and logit nu = ln(nu/(1 - nu))
//! ```
//! (|V_out| grows linearly with the distance to V_stick where the contact dissipates, as its
//! square root in the JKR limit, saturates far above V_stick and rises about as ln(1/(1 - nu))
//! towards the onset: straight stretches in these coordinates), and below V_on every collision
//! sticks (e = 0). The tables hold h at the channels on nodes of rows of constant y (in u = ln(x_s - x), as the master tables) for every
//! table k; an answer is the local cubic along the channels, along the row, across rows and
//! across k. Each cell between two rows was checked at its centre against the ODE (e within
//! 5e-5, half the 1e-4 promised), and at its quarters at denser speeds
//! (`check::check_quarters`), and each interval between tables of neighbouring k at its centre;
//! elsewhere (near the cliff, a double-collision window narrower than 1e-4 of V_stick, speeds
//! beyond 9.5 e-folds above V_stick, within 1e-5 of V_stick ([`STICK_MARGIN`]) or below the
//! first channel (sigma or nu = 1e-4), within 3e-4 of the onset ([`ONSET_MARGIN`]), within
//! 0.03 in x of the cliff ([`CLIFF_MARGIN`])) the caller integrates the ODE.
//!
//! # Example
//! ```
//! use thresholds::restitution::collision;
//! use thresholds::{Contact, CrackLaw, Geometry, Material, Outcome, SolverOptions, ThresholdMethod};
//! let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
//! let law = CrackLaw::new(0.01)?;
//! let table = ThresholdMethod::Table;
//! // from the tables where they are built and vouch, else the ODE; `by` says which
//! let (r, by) = collision(&c, &law, 1e-9, 0.045, &SolverOptions::default(), table)?;
//! assert_eq!(r.outcome, Outcome::Bouncing); // Section 4: 4.5 cm/s bounces
//! assert!(r.e > 0.0 && r.e < 1.0);
//! # let _ = by;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// public for `cargo xtask restitution-table` (the builder and its checks), not part of the API
// a user calls
#[doc(hidden)]
pub mod build;
#[doc(hidden)]
pub mod check;
pub mod format;
#[doc(hidden)]
pub mod refine;
mod stencil;

use crate::k_axis;
use crate::master::interp::{interval, lagrange, stencil_start};
use crate::master::{MasterTables, F_TOP};
use contact::Contact;
use dynamics::Outcome;
use format::Table;
use std::sync::OnceLock;
use stencil::Stencil;

/// The tables' binary form, made by the build script from `data/restitution_k*.csv`, aligned for
/// `f64` so that each table's arrays are borrowed in place on first use (a table is 5.9 MB:
/// copied, its first answer cost 5-7 ms).
static ALIGNED: &crate::master::Aligned<[u8]> = &crate::master::Aligned(*include_bytes!(concat!(
    env!("OUT_DIR"),
    "/restitution.bin"
)));

/// [`ALIGNED`]'s bytes.
static BYTES: &[u8] = &ALIGNED.0;

/// Within this relative distance of V_double_onset (where the outcome jumps from sticking to a
/// double collision) the ODE decides. Just above the onset e changes fast with V_in and the
/// onset is known to the master tables' 2e-6: with 1e-4 here, 2 of 69 160 random collisions
/// compared missed e by 1.1e-4 and 1.4e-4 at 1.6e-4 and 2.2e-4 above the onset; with 3e-4 the
/// largest miss of 64 553 is 6.0e-5 (`examples/restitution_accuracy.rs -- 100000 100000`).
pub const ONSET_MARGIN: f64 = 3e-4;

/// A double-collision window narrower than this (relative, `ln(F/F_on)`: the JKR limit, where
/// it is 4e-6 wide) is not tabulated; the ODE answers inside it.
pub const MIN_WINDOW: f64 = 1e-4;

/// Within this relative distance of V_stick, where the master tables' V_stick (good to 2e-6)
/// may lie on the wrong side, the ODE decides between bouncing and a double collision.
pub const STICK_MARGIN: f64 = 1e-5;

/// The side (bouncing or not) and channel coordinate (sigma or nu) of an impact at `s`
/// V_stick,JKR with the thresholds `f`, `f_on` (V_stick,JKR), above the onset; `None` where the
/// tables do not answer (the ODE does): within [`ONSET_MARGIN`] of the onset, within
/// [`STICK_MARGIN`] of V_stick, or in a double-collision window narrower than [`MIN_WINDOW`].
pub fn channel_of(s: f64, f: f64, f_on: f64) -> Option<(bool, f64)> {
    let from_stick = (s / f).ln();
    if s <= f_on * (1.0 + ONSET_MARGIN) || from_stick.abs() < STICK_MARGIN {
        return None;
    }
    if from_stick > 0.0 {
        return Some((true, from_stick));
    }
    let window = (f / f_on).ln();
    (window >= MIN_WINDOW).then(|| (false, -from_stick / window))
}

/// Closer to the cliff than this (in x = log10 c_D, from the ends x_s of both rows of the cell
/// that holds the point: below the kink the end moves by up to 0.5 in x a row step) the ODE
/// answers: there the rebound just above V_stick changes fast with x and y (V_out is nearly
/// flat in V_in and tiny), and the checks of a cell (at mid-y) do not hold for the whole cell.
/// Measured with the cells checked at their quarters (1.2e5 random collisions within 0.05 of
/// the cliff, random and the tables' own k, three kinds of impact speeds; a probe with no
/// margin): closer than 0.03, 19 of 25 898 answers missed the ODE's e by 1.0e-4 to 1.9e-3 (the
/// farthest at 0.0236 from x_s; k = 0.01, y = -1.3, sigma = 0.82: e = 7.8e-4 against 2.7e-3);
/// from 0.03 to 0.05, none of 40 073 by more than 5.3e-5 (another draw of 1.2e5 with this
/// margin, `examples/cliff_margin.rs`: none of 31 714 by more than 4.9e-5). The margin was 0.05
/// while the cells were checked at their centres alone (misses up to 1.3e-3, 1.9e-3 to 3.9e-2
/// from the end then).
pub const CLIFF_MARGIN: f64 = 0.03;

/// The rebound of one collision from the tables (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableRebound {
    /// Sticking, double collision or bouncing.
    pub outcome: Outcome,
    /// V_out (m/s): the approach speed when the contact ends (< 0: bouncing; 0: sticking).
    pub v_out: f64,
    /// e = -V_out / V_in (dimensionless; < 0 for a double collision, 0 for sticking).
    pub e: f64,
}

/// Which piece of the rebound.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    Bouncing,
    Double,
}

/// The restitution tables of every k (see the module documentation), read from the embedded
/// binary form, each on first use.
#[derive(Debug)]
pub struct RestitutionTables {
    bytes: &'static [u8],
    k: Vec<f64>,
    /// ln k of the tables (the polynomial in ln k), computed once.
    ln_k: Vec<f64>,
    tables: Vec<OnceLock<Option<Table>>>,
}

impl RestitutionTables {
    /// The committed tables (empty if the library was built without them: the ODE answers).
    pub fn standard() -> &'static RestitutionTables {
        static STANDARD: OnceLock<RestitutionTables> = OnceLock::new();
        STANDARD.get_or_init(|| {
            let index = format::index(BYTES).unwrap_or_default();
            RestitutionTables {
                bytes: BYTES,
                k: index.iter().map(|e| e.0).collect(),
                ln_k: index.iter().map(|e| e.0.ln()).collect(),
                tables: index.iter().map(|_| OnceLock::new()).collect(),
            }
        })
    }

    /// Tables already in memory (the build's).
    pub fn from_parts(tables: Vec<Table>) -> RestitutionTables {
        RestitutionTables {
            bytes: &[],
            k: tables.iter().map(|t| t.k).collect(),
            ln_k: tables.iter().map(|t| t.k.ln()).collect(),
            tables: tables
                .into_iter()
                .map(|t| {
                    let c = OnceLock::new();
                    let _ = c.set(Some(t));
                    c
                })
                .collect(),
        }
    }

    /// Whether the tables answer at `k` anywhere: one of their own k, or (with four tables or
    /// more) a k between the first and the last, as [`RestitutionTables::rebound`] takes it.
    pub fn covers(&self, k: f64) -> bool {
        k_axis::covered(&self.k, k)
    }

    /// The k of the tables.
    pub fn table_k(&self) -> &[f64] {
        &self.k
    }

    /// Whether the k cells (the checks between tables of neighbouring k) are built for every
    /// interval, so that every k between the first and the last table is answered (else only
    /// the tables' own k).
    pub fn k_checked(&self) -> bool {
        self.k.len() >= k_axis::MIN_TABLES_BETWEEN
            && (0..self.k.len() - 1).all(|i| {
                self.table(i)
                    .is_some_and(|t| t.rows.iter().any(|r| !r.cells.k_all.is_empty()))
            })
    }

    /// Table `i`.
    pub fn table(&self, i: usize) -> Option<&Table> {
        self.tables
            .get(i)?
            .get_or_init(|| format::table_from_bytes(self.bytes, i))
            .as_ref()
    }

    /// The rebound of `contact` at relaxation time `t_vis` (s) and impact speed `v_in` (m/s)
    /// for the modulus ratio `k`; `None` where the tables do not vouch for it (the caller then
    /// integrates the collision).
    pub fn rebound(
        &self,
        contact: &Contact,
        k: f64,
        t_vis: f64,
        v_in: f64,
    ) -> Option<TableRebound> {
        if !(t_vis > 0.0 && v_in > 0.0 && t_vis.is_finite() && v_in.is_finite()) {
            return None;
        }
        let d = contact.dimensionless(t_vis);
        if !(d.c_d > 0.0 && d.c_a > 0.0 && d.c_d.is_finite() && d.c_a.is_finite()) {
            return None;
        }
        let x = d.c_d.log10();
        let jkr = contact.v_stick_jkr();
        // y as the master tables' answer takes it (from the product c_D c_a: the same bits at
        // every T_vis), so that both give the same V_stick
        let (outcome, w) = self.rebound_at(
            x,
            contact.drag_crack_product().log10(),
            k,
            v_in / jkr,
            MasterTables::standard(),
        )?;
        let v_out = w * jkr;
        let e = if outcome == Outcome::Sticking {
            0.0
        } else {
            -v_out / v_in
        };
        Some(TableRebound { outcome, v_out, e })
    }

    /// The outcome and V_out / V_stick,JKR at `(x, y, k)` and `s = V_in / V_stick,JKR`, with the
    /// thresholds from `masters`.
    pub fn rebound_at(
        &self,
        x: f64,
        y: f64,
        k: f64,
        s: f64,
        masters: &MasterTables,
    ) -> Option<(Outcome, f64)> {
        let f_max = F_TOP * (1.0 - 1e-3);
        let r = masters.ratios_at(x, y, k, f_max)?;
        // below the onset of double collisions every collision sticks (along V_in the outcomes
        // come in the order sticking, double, bouncing), and where the master tables vouch
        // that none double-collides below the limit (beyond the cliff), every one up to it
        let onset = r.v_double_onset.unwrap_or(f_max);
        if s < onset * (1.0 - ONSET_MARGIN) {
            return Some((Outcome::Sticking, 0.0));
        }
        let (f, f_on) = (r.v_stick?, r.v_double_onset?);
        let (bouncing, coord) = channel_of(s, f, f_on)?;
        let side = if bouncing {
            Side::Bouncing
        } else {
            Side::Double
        };
        // h = ln(|V_out| / V_stick), interpolated in ln sigma + sigma (logit nu)
        let z = format::channel_coordinate(side == Side::Bouncing, coord);
        let h = self.h(x, y, k, side, z, true)?;
        Some(match side {
            Side::Bouncing => (Outcome::Bouncing, -h.exp() * f),
            Side::Double => (Outcome::DoubleCollision, h.exp() * f),
        })
    }

    /// h at `(x, y, k)` on `side` at channel coordinate `coord` (ln sigma or logit nu), from the
    /// tables around k;
    /// `checked`: only where the cells (and the k cells) were vouched for.
    fn h(&self, x: f64, y: f64, k: f64, side: Side, coord: f64, checked: bool) -> Option<f64> {
        let ks = &self.k;
        if let Some(i) = k_axis::own_table(ks, k) {
            return Stencil::new(self.table(i)?, x, y, side, coord, checked, false)?.h(y);
        }
        if !k_axis::between_tables(ks, k) {
            return None;
        }
        let n = ks.len();
        let ln = &self.ln_k;
        let i = interval(ln, k.ln());
        let s = stencil_start(i, n);
        // every table's stencil before any value is read (see [`Stencil`])
        let stencil = |t: usize| {
            Stencil::new(
                self.table(t)?,
                x,
                y,
                side,
                coord,
                checked,
                checked && t == i,
            )
        };
        let stencils = [
            stencil(s)?,
            stencil(s + 1)?,
            stencil(s + 2)?,
            stencil(s + 3)?,
        ];
        std::hint::black_box(stencils.iter().map(Stencil::prefetch).sum::<f64>());
        let mut h = [0.0; 4];
        for (q, stencil) in stencils.iter().enumerate() {
            h[q] = stencil.h(y)?;
        }
        Some(lagrange(&ln[s..s + 4], &h, k.ln()))
    }

    /// h without the checks, at channel `q` (sigma or nu): for the build, which computes them.
    pub fn h_unchecked(&self, x: f64, y: f64, k: f64, bouncing: bool, q: f64) -> Option<f64> {
        let side = if bouncing {
            Side::Bouncing
        } else {
            Side::Double
        };
        self.h(
            x,
            y,
            k,
            side,
            format::channel_coordinate(bouncing, q),
            false,
        )
    }
}

/// Significant figures of h written: 8, far below what e = 1e-4 needs.
const DIGITS: usize = 8;

/// The text of one restitution table (see [`mod@format`]).
pub fn to_text(t: &format::TableData) -> String {
    use numerics::format::number;
    use std::fmt::Write as _;
    let rounded = |v: f64| -> String {
        if v.is_finite() {
            number(format!("{:.*e}", DIGITS - 1, v).parse().unwrap_or(v))
        } else {
            "nan".into()
        }
    };
    let list = |v: &[f64]| v.iter().map(|&x| number(x)).collect::<Vec<_>>().join(",");
    let flags = |v: &[bool]| {
        v.iter()
            .map(|&b| if b { '1' } else { '0' })
            .collect::<String>()
    };
    let mut out = String::new();
    for h in &t.header {
        let _ = writeln!(out, "# {h}");
    }
    let _ = writeln!(out, "k,{}", number(t.k));
    let _ = writeln!(out, "sigma,{}", list(&t.sigma));
    let _ = writeln!(out, "nu,{}", list(&t.nu));
    for r in &t.rows {
        let _ = writeln!(out, "row,{},{}", number(r.y), number(r.x_s));
        for p in &r.nodes {
            let h: Vec<String> = p.h.iter().map(|&v| rounded(v)).collect();
            let _ = writeln!(
                out,
                "rnode,{},{},{},{}",
                number(p.x),
                rounded(p.f),
                rounded(p.f_on),
                h.join(",")
            );
        }
        // a record that is empty, or equal to the one it falls back on, is left out
        let [all, bouncing, k_all, k_bouncing] = r.cells.records();
        let _ = writeln!(out, "{},{}", all.0, flags(all.1));
        for ((name, own), fallback) in [
            (bouncing, all.1),
            (k_all, &Vec::new()),
            (k_bouncing, k_all.1),
        ] {
            if !own.is_empty() && own != fallback {
                let _ = writeln!(out, "{name},{}", flags(own));
            }
        }
    }
    out
}

/// The integrator of the collisions the tables decline under [`crate::ThresholdMethod::Table`]
/// at a k they cover ([`RestitutionTables::covers`]) when `solver` leaves the choice to
/// [`dynamics::Method::Auto`] (at other k every collision is declined, and `Auto` is kept: for
/// ordinary collisions its explicit Tsit45 takes fewer steps). Those collisions lie next to the
/// cliff and the kink of the two kinds of bouncing (strong damping, a slow crack: lambda small),
/// where `Auto` tries the explicit Tsit45 first and ends with BDF at three quarters of them,
/// mostly after spending its step budget on Tsit45. Measured on the 1353 collisions of 1e5 that
/// the tables decline (`examples/restitution_accuracy.rs -- 100000 0 wide`; `docs/performance.md`,
/// "BDF for the collisions the tables decline"): BDF alone 0.49 s of one core against
/// 1.46 s for `Auto` (0.57 against 1.22 ms a collision, median), the same outcome at every one,
/// e within 1.3e-6 of `Auto`'s, and against BDF at rtol 1e-12 within 1.9e-6 for both (median
/// 3.4e-9 and 1.1e-9): well inside the 1e-4 in e the tables promise.
pub const DECLINED_METHOD: dynamics::Method = dynamics::Method::Bdf;

/// One collision of `contact` at `t_vis` (s) and `v_in` (m/s) with the crack law `law`: from
/// the restitution tables with [`crate::ThresholdMethod::Table`] where they vouch for it (and
/// no trajectory or `decide_after` is asked of `solver`: those need the integration), else
/// integrated with `solver` (where the tables decline at a k they cover, with
/// [`DECLINED_METHOD`] if `solver` says `Auto`); and which answered: `Table`, or `Search` for
/// the ODE (the names the threshold searches share; the CLI and Python call it `ode`). A table
/// answer has the outcome, e and V_out only ([`dynamics::Collision::from_rebound`]).
pub fn collision(
    contact: &Contact,
    law: &greenwood::CrackLaw,
    t_vis: f64,
    v_in: f64,
    solver: &dynamics::SolverOptions,
    method: crate::ThresholdMethod,
) -> Result<(dynamics::Collision, crate::ThresholdMethod), crate::ThresholdsError> {
    let plain = !solver.record_trajectory && solver.decide_after == 0.0;
    let mut solver = *solver;
    if method == crate::ThresholdMethod::Table && plain {
        let tables = RestitutionTables::standard();
        if let Some(r) = tables.rebound(contact, law.k(), t_vis, v_in) {
            let c = dynamics::Collision::from_rebound(r.outcome, r.e, r.v_out);
            return Ok((c, crate::ThresholdMethod::Table));
        }
        if solver.method == dynamics::Method::Auto && tables.covers(law.k()) {
            solver.method = DECLINED_METHOD;
        }
    }
    let collider = dynamics::Collider::new(*contact, law, t_vis)?.with_options(solver)?;
    Ok((collider.collide(v_in)?, crate::ThresholdMethod::Search))
}
