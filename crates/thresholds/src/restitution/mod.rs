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
//! 5e-5, half the 1e-4 promised), and each interval between tables of neighbouring k likewise;
//! elsewhere (near the cliff, a double-collision window narrower than 1e-4 of V_stick, speeds
//! beyond 9.5 e-folds above V_stick, within 1e-5 of V_stick ([`STICK_MARGIN`]) or below the
//! first channel (sigma or nu = 1e-4), within 1e-4 of the onset, within 0.05 in x of the cliff
//! ([`CLIFF_MARGIN`])) the caller integrates the ODE.
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

pub mod build;
pub mod check;
pub mod format;
pub mod refine;

use crate::master::interp::{
    interval, lagrange, lagrange_weight, local_cubic, stencil_start, weights4,
};
use crate::master::{MasterTables, F_TOP};
use contact::Contact;
use dynamics::Outcome;
use format::Table;
use std::sync::OnceLock;

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
/// double collision) the ODE decides.
pub const ONSET_MARGIN: f64 = 1e-4;

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

/// Closer to the cliff than this (in x = log10 c_D, from the row's end x_s) the ODE answers:
/// there the rebound just above V_stick changes fast with x and y (V_out is nearly flat in V_in
/// and tiny), and the checks at the cells' centres do not hold for the whole cell (e = 7.8e-4
/// from the table against 1.8e-4 from the ODE at 0.013 from x_s, y = -0.8, k = 0.01, with
/// the cells vouched; `examples/restitution_accuracy.rs`).
pub const CLIFF_MARGIN: f64 = 0.05;

/// Two k closer than this (relative) are the same k.
const SAME_K: f64 = 1e-12;

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

    /// The k of the tables.
    pub fn table_k(&self) -> &[f64] {
        &self.k
    }

    /// Whether the k cells (the checks between tables of neighbouring k) are built for every
    /// interval, so that every k between the first and the last table is answered (else only
    /// the tables' own k).
    pub fn k_checked(&self) -> bool {
        self.k.len() >= 4
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
        let r = masters.ratios_at(x, y, k, F_TOP * (1.0 - 1e-3))?;
        let (f, f_on) = (r.v_stick?, r.v_double_onset?);
        if s < f_on * (1.0 - ONSET_MARGIN) {
            return Some((Outcome::Sticking, 0.0));
        }
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
        if let Some(i) = ks.iter().position(|&t| (k / t - 1.0).abs() < SAME_K) {
            return Stencil::new(self.table(i)?, x, y, side, coord, checked, false)?.h(y);
        }
        let n = ks.len();
        if n < 4 || !(k > ks[0] && k < ks[n - 1]) {
            return None;
        }
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

/// Where an answer lies along a table's channels: the (at most) four channels around its
/// coordinate, as an offset into a node's h values, and their Lagrange weights. The same for
/// every node of the table, so found once an answer instead of once a node (sixteen nodes a
/// table: a fifth of an answer).
struct Channels {
    /// The first channel's index among a node's values (bouncing channels first).
    first: usize,
    /// How many channels (four, fewer only on a grid of fewer).
    len: usize,
    /// Their weights at the coordinate ([`lagrange`]'s).
    weights: [f64; 4],
}

impl Channels {
    /// The channels of `t` around `coord` (ln sigma + sigma or logit nu) on `side`; `None`
    /// outside the channels.
    fn around(t: &Table, side: Side, coord: f64) -> Option<Channels> {
        let (grid, offset) = match side {
            Side::Bouncing => (&t.sigma, 0),
            Side::Double => (&t.nu, t.sigma.len()),
        };
        if !(coord >= grid[0] && coord <= grid[grid.len() - 1]) {
            return None;
        }
        let s = stencil_start(interval(grid, coord), grid.len());
        let e = (s + 4).min(grid.len());
        let mut weights = [0.0; 4];
        if e - s == 4 {
            weights = weights4(&grid[s..e], coord);
        } else {
            for (j, w) in weights.iter_mut().enumerate().take(e - s) {
                *w = lagrange_weight(&grid[s..e], j, coord);
            }
        }
        Some(Channels {
            first: offset + s,
            len: e - s,
            weights,
        })
    }

    /// h of node `node` of `row` of `t` at the coordinate (the local cubic along the channels).
    fn h(&self, t: &Table, row: &format::Row, node: usize) -> Option<f64> {
        let at = node * (t.sigma.len() + t.nu.len()) + self.first;
        let v = row.h.get(at..at + self.len)?;
        if v.iter().any(|h| !h.is_finite()) {
            return None;
        }
        Some(v.iter().zip(&self.weights).map(|(h, w)| w * h).sum())
    }
}

/// Where one table's answer at `(x, y)` reads: the four rows around y (from `first_row`), on
/// each the four nodes around u = ln(x_s - x) (from `first_node`), and the channels around the
/// coordinate. Found for every table of an answer before any value is read, so that the
/// sixty-four nodes' values (scattered over 6 MB a table) are fetched together and not one
/// after the other.
struct Stencil<'a> {
    table: &'a Table,
    first_row: usize,
    first_node: [usize; 4],
    u: [f64; 4],
    channels: Channels,
}

impl<'a> Stencil<'a> {
    /// The stencil of `t` at `(x, y)` on `side` at `coord`; `None` outside the rows or the
    /// channels, or (`checked`) where the cell holding x (and `k_checked`, its k cell) was not
    /// vouched for.
    fn new(
        t: &'a Table,
        x: f64,
        y: f64,
        side: Side,
        coord: f64,
        checked: bool,
        k_checked: bool,
    ) -> Option<Self> {
        let n = t.rows.len();
        if n < 4 || !(y >= t.ys[1] && y <= t.ys[n - 2]) {
            return None;
        }
        let j = interval(&t.ys, y);
        if checked {
            // the cell of row j (to row j + 1) that holds x
            let r = &t.rows[j];
            if r.x_s - x < CLIFF_MARGIN {
                return None;
            }
            let u = (r.x_s - x).ln().min(r.u[r.u.len() - 1]);
            if u.is_nan() || u < r.u[0] {
                return None;
            }
            let i = interval(&r.u, u);
            // bouncing needs its own channels vouched; a double collision every channel
            let (cells, kcells) = r.cells.side(side == Side::Bouncing);
            if !cells.get(i).copied().unwrap_or(false)
                || (k_checked && !kcells.get(i).copied().unwrap_or(false))
            {
                return None;
            }
        }
        let channels = Channels::around(t, side, coord)?;
        let first_row = stencil_start(j, n);
        let (mut first_node, mut us) = ([0; 4], [0.0; 4]);
        for (q, r) in t.rows[first_row..first_row + 4].iter().enumerate() {
            let u = (r.x_s - x).ln().min(r.u[r.u.len() - 1]);
            if u.is_nan() || u < r.u[0] || r.u.len() < 4 {
                return None;
            }
            first_node[q] = stencil_start(interval(&r.u, u), r.u.len());
            us[q] = u;
        }
        Some(Stencil {
            table: t,
            first_row,
            first_node,
            u: us,
            channels,
        })
    }

    /// Reads the first and the last of the channels' values of each of the sixteen nodes and
    /// returns their sum: called for every table of an answer before [`Stencil::h`], it sends
    /// the sixty-four nodes' cache misses out together (a prefetch without `unsafe`). Random
    /// collisions between tables: 3.6 -> 2.6 us an answer (`examples/restitution_accuracy.rs`),
    /// 5.3 -> 4.2 us with the stencils found first but no prefetch.
    fn prefetch(&self) -> f64 {
        let t = self.table;
        let per = t.sigma.len() + t.nu.len();
        let mut sum = 0.0;
        for (q, r) in t.rows[self.first_row..self.first_row + 4]
            .iter()
            .enumerate()
        {
            for node in self.first_node[q]..self.first_node[q] + 4 {
                let at = node * per + self.channels.first;
                sum += r.h.get(at).copied().unwrap_or(0.0);
                sum += r.h.get(at + self.channels.len - 1).copied().unwrap_or(0.0);
            }
        }
        sum
    }

    /// h at the stencil's point: the local cubic along the channels at each node, along each
    /// row, across the rows.
    fn h(&self, y: f64) -> Option<f64> {
        let t = self.table;
        let rows = &t.rows[self.first_row..self.first_row + 4];
        let mut across = [0.0; 4];
        for (q, r) in rows.iter().enumerate() {
            let a = self.first_node[q];
            let mut along = [0.0; 4];
            for (p, node) in (a..a + 4).enumerate() {
                along[p] = self.channels.h(t, r, node)?;
            }
            across[q] = local_cubic(&r.u[a..a + 4], &along, self.u[q]);
        }
        let h = lagrange(&t.ys[self.first_row..self.first_row + 4], &across, y);
        h.is_finite().then_some(h)
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

/// One collision of `contact` at `t_vis` (s) and `v_in` (m/s) with the crack law `law`: from
/// the restitution tables with [`crate::ThresholdMethod::Table`] where they vouch for it (and
/// no trajectory or `decide_after` is asked of `solver`: those need the integration), else
/// integrated with `solver`; and which answered. A table answer has the outcome, e and V_out
/// only ([`dynamics::Collision::from_rebound`]).
pub fn collision(
    contact: &Contact,
    law: &greenwood::CrackLaw,
    t_vis: f64,
    v_in: f64,
    solver: &dynamics::SolverOptions,
    method: crate::ThresholdMethod,
) -> Result<(dynamics::Collision, crate::ThresholdMethod), crate::ThresholdsError> {
    let plain = !solver.record_trajectory && solver.decide_after == 0.0;
    if method == crate::ThresholdMethod::Table && plain {
        if let Some(r) = RestitutionTables::standard().rebound(contact, law.k(), t_vis, v_in) {
            let c = dynamics::Collision::from_rebound(r.outcome, r.e, r.v_out);
            return Ok((c, crate::ThresholdMethod::Table));
        }
    }
    let collider = dynamics::Collider::new(*contact, law, t_vis)?.with_options(*solver)?;
    Ok((collider.collide(v_in)?, crate::ThresholdMethod::Search))
}
