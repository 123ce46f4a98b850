//! [`CrackLaw`]: v(k, beta) and dv/dbeta by interpolation of a table built once per k.
//!
//! Each branch is tabulated at alpha nodes uniform in `ln alpha` (alpha from [`ALPHA_MIN`] to
//! [`ALPHA_MAX`], step [`LN_ALPHA_STEP`]). The integrals J3, 1 - J3 and K at the nodes do not
//! depend on k: `build.rs` computes them once with the crate's quadrature, so building a
//! `CrackLaw` is only algebra (a fraction of a millisecond). In the coordinates
//! ```text
//! zeta = ln|beta - 1| - ln(distance of beta to k or 1/k),      w = ln|v|
//! ```
//! `w(zeta)` is smooth and close to linear at both ends (`|v| ~ 1/(beta - k)` near the limit and
//! `|v| ~ |beta - 1| / ln alpha` near beta = 1), so local polynomial interpolation of degree
//! [`STENCIL`]` - 1` on the (non-uniform) zeta nodes is accurate to better than 1e-8 relative in v
//! (measured by the `crack_law` tests against direct evaluation between the nodes). The
//! interpolants are stored as Newton divided differences per interval and found through a uniform
//! bucket index, so an evaluation is a few dozen flops, a logarithm and an exponential.
//!
//! The solvers call [`CrackLaw::speed_unchecked`] millions of times, so each branch also keeps a
//! second representation of the same table: |v| as cubic Hermite cells in `r = e^zeta`, 128 per
//! octave of r, indexed by the bits of r (no logarithm, no exponential) and filled from the table
//! eight cells at a time, the first time a trajectory enters them (`FAST_BLOCK_BITS`). It follows
//! the table to 1e-9 relative (`FAST_BITS`).
//! Outside the table (alpha beyond its range) w is extrapolated linearly, which keeps v and its
//! derivative finite, monotone and of the right sign up to the bounds.

use crate::integrals::JIntegrals;
use crate::law::{check_beta, check_k, Branch, CrackPoint};
use crate::GreenwoodError;
use std::sync::{Arc, OnceLock};

pub use crate::quad::{ALPHA_MAX, ALPHA_MIN, LN_ALPHA_STEP};

// `J_NODES[i] = [alpha, J3, 1 - J3, K]` at alpha = `crate::quad::node_alpha(i)`, computed by
// `build.rs` with the quadrature of `crate::quad` (the values do not depend on k; alpha too, so
// that a table of k costs no exponential and uses the very alpha the integrals were computed
// at, also in a cross-compiled build).
include!(concat!(env!("OUT_DIR"), "/j_nodes.rs"));
// The bucket index holds interval indices as `u32`: every table has fewer nodes than that
// (checked when the crate compiles).
const _: () = assert!(J_NODES.len() < u32::MAX as usize);

/// Number of nodes in each interpolation stencil.
pub const STENCIL: usize = 6;

/// The crack speed and its slope at one beta.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrackSpeed {
    /// Normalized crack speed v (dimensionless).
    pub v: f64,
    /// dv/dbeta (dimensionless).
    pub dv_dbeta: f64,
}

/// One branch's table: nodes sorted by increasing zeta, with, for every interval, the Newton
/// divided differences of the [`STENCIL`]-point interpolant used on it, and a uniform bucket index
/// over zeta for O(1) lookup.
#[derive(Debug, Clone)]
struct BranchTable {
    zeta: Vec<f64>,
    w: Vec<f64>,
    /// `newton[s]`: the Newton coefficients of the stencil of nodes `s .. s + STENCIL`, the
    /// divided differences `f[zeta_s .. zeta_(s+j)]`, `j < STENCIL`.
    newton: Vec<[f64; STENCIL]>,
    /// `bucket[b]`: the interval containing the left end of bucket `b` (a table has a few
    /// thousand intervals: `u32` halves the index, which a law built for one collision fills).
    bucket: Vec<u32>,
    bucket_origin: f64,
    bucket_inv_width: f64,
}

impl BranchTable {
    /// The table through the nodes `(zeta, w)`, sorted by increasing zeta (what
    /// [`BranchTable::from_points`] sorts them into).
    fn from_sorted(zeta: Vec<f64>, w: Vec<f64>) -> Self {
        let n = zeta.len();
        let intervals = n - 1;
        // the Newton coefficients of every stencil: the divided differences f[zeta_a ..
        // zeta_(a+m)] of each order m, each computed once for the stencils that share it (a
        // third of the divisions of a table per stencil, the same values): `newton[a][m]`; the
        // last STENCIL - 1 nodes start no stencil, and their rows are dropped
        let stencils = n - STENCIL + 1;
        let mut newton = vec![[0.0; STENCIL]; n];
        for (d, &wa) in newton.iter_mut().zip(&w) {
            d[0] = wa;
        }
        for m in 1..STENCIL {
            for a in 0..n - m {
                newton[a][m] = (newton[a + 1][m - 1] - newton[a][m - 1]) / (zeta[a + m] - zeta[a]);
            }
        }
        newton.truncate(stencils);
        // buckets no wider than the narrowest interval: at most one interval boundary per bucket
        let min_gap = zeta
            .windows(2)
            .map(|p| p[1] - p[0])
            .fold(f64::INFINITY, f64::min);
        let span = zeta[n - 1] - zeta[0];
        let buckets = ((span / min_gap).ceil() as usize).clamp(1, 1 << 20);
        let bucket_inv_width = buckets as f64 / span;
        let mut bucket = Vec::with_capacity(buckets);
        let mut i = 0;
        for b in 0..buckets {
            let left = zeta[0] + b as f64 / bucket_inv_width;
            while i + 1 < intervals && zeta[i + 1] <= left {
                i += 1;
            }
            // i < intervals < J_NODES.len(), which fits in u32 (asserted at compile time)
            bucket.push(i as u32);
        }
        Self {
            bucket_origin: zeta[0],
            zeta,
            w,
            newton,
            bucket,
            bucket_inv_width,
        }
    }

    /// The table through the nodes `(zeta[i], w[i])`, given in decreasing alpha: as they come
    /// if zeta increases strictly (no sort, no copy: a law built for one collision spends a
    /// third of its table on page faults of fresh memory), else sorted by zeta as
    /// [`BranchTable::from_points`] sorts the nodes in increasing alpha, stably (the same table).
    fn from_nodes(zeta: Vec<f64>, w: Vec<f64>) -> Self {
        if zeta.windows(2).all(|p| p[0] < p[1]) {
            Self::from_sorted(zeta, w)
        } else {
            Self::from_points(zeta.into_iter().zip(w).rev().collect())
        }
    }

    /// The table through `points` `(zeta, w)` in any order (sorted by zeta first, stably).
    fn from_points(mut points: Vec<(f64, f64)>) -> Self {
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (zeta, w): (Vec<f64>, Vec<f64>) = points.into_iter().unzip();
        Self::from_sorted(zeta, w)
    }

    /// The first node of the stencil of interval `i` of `n` nodes: centred on it (nodes i-2 ..=
    /// i+3), shifted inside the table.
    fn stencil_start(i: usize, n: usize) -> usize {
        (i as isize + 1 - (STENCIL / 2) as isize).clamp(0, (n - STENCIL) as isize) as usize
    }

    /// `(w, dw/dzeta)` at `z`.
    fn eval(&self, z: f64) -> (f64, f64) {
        let n = self.zeta.len();
        let last = n - 1;
        if z <= self.zeta[0] {
            let s = (self.w[1] - self.w[0]) / (self.zeta[1] - self.zeta[0]);
            return (self.w[0] + s * (z - self.zeta[0]), s);
        }
        if z >= self.zeta[last] {
            let s = (self.w[last] - self.w[last - 1]) / (self.zeta[last] - self.zeta[last - 1]);
            return (self.w[last] + s * (z - self.zeta[last]), s);
        }
        let b = (((z - self.bucket_origin) * self.bucket_inv_width) as usize)
            .min(self.bucket.len() - 1);
        let mut i = self.bucket[b] as usize;
        while i + 1 < last && self.zeta[i + 1] <= z {
            i += 1;
        }
        let s = Self::stencil_start(i, n);
        let dd = &self.newton[s];
        let xs = &self.zeta[s..s + STENCIL];
        // Horner on the Newton form, carrying the derivative along
        let mut value = dd[STENCIL - 1];
        let mut slope = 0.0;
        for j in (0..STENCIL - 1).rev() {
            let t = z - xs[j];
            slope = slope * t + value;
            value = value * t + dd[j];
        }
        (value, slope)
    }
}

/// Cells per octave of `r` in a [`FastBranch`]: 2^7 = 128, so that a cell spans 0.0078 in zeta
/// and the cubic Hermite interpolant of |v| in it follows the table to 1e-9 relative, a tenth of
/// the table's own error (4e-9 in the one cell across each end node of the table, where its slope
/// jumps to the linear extrapolation; test `fast_cells_reproduce_the_table`).
const FAST_BITS: u32 = 7;
/// Smallest octave of `r` a [`FastBranch`] covers, `r >= 2^FAST_MIN_EXP` (about 3.6e-15, beta
/// within 4e-15 of 1 at most: trajectories sit at |beta - 1| ~ 1/lambda > 1e-10); smaller `r`
/// goes through the table directly.
const FAST_MIN_EXP: i32 = -48;
/// One past the largest octave, `r < 2^FAST_MAX_EXP` (about 1.7e7: beta within 6e-8 (1 - k) of
/// k or 1/k, beyond the start and the end of every contact); larger `r` goes through the table.
const FAST_MAX_EXP: i32 = 24;

/// Cells filled at once: the first evaluation in a block of `2^FAST_BLOCK_BITS` = 8 cells
/// fills that block from the table (9 edges, 256 bytes of its own). A lone collision with a
/// law of its own (the restitution's ODE fallback at a random k) touches few of an octave's 128
/// cells, and whole octaves (4 KB each) made its law a third of its cost: 1343 such collisions
/// took 1.64 s with whole octaves, 1.47 s with blocks of eight (1.52 s with two cells, 1.46 s
/// with four, 1.50 s with sixteen: one run each, within the noise of eight) and 1.10 s with
/// warm laws; a search, which shares its law, 0.4 % more
/// instructions (docs/performance.md, "The crack law of each k"). The cells' values do not
/// depend on how many are filled at once.
const FAST_BLOCK_BITS: u32 = 3;
/// Cells a block holds.
const FAST_BLOCK: usize = 1 << FAST_BLOCK_BITS;
/// Blocks an octave holds.
const FAST_BLOCKS_PER_OCTAVE: usize = 1 << (FAST_BITS - FAST_BLOCK_BITS);

/// The coefficients `[c0, c1, c2, c3]` of |v| in each cell of a block, in the cell's local
/// variable `t = (r - r0) / h` in [0, 1).
type Block = [[f64; 4]; FAST_BLOCK];

/// A second, faster representation of one branch: |v| as a cubic Hermite interpolant in
/// `r = |beta - 1| / (distance of beta to its bound)` (so `zeta = ln r`) on cells uniform within
/// each octave of r, found from the bits of r: no logarithm, no exponential. Its nodes are values
/// and slopes of the table itself, computed the first time a trajectory enters a block of cells.
#[derive(Debug)]
struct FastBranch {
    /// Per block of [`FAST_BLOCK`] cells ([`FAST_BLOCKS_PER_OCTAVE`] an octave, octave by
    /// octave), its cells, filled on first use.
    blocks: Vec<OnceLock<Box<Block>>>,
}

impl FastBranch {
    fn new() -> Self {
        let n = (FAST_MAX_EXP - FAST_MIN_EXP) as usize * FAST_BLOCKS_PER_OCTAVE;
        Self {
            blocks: (0..n).map(|_| OnceLock::new()).collect(),
        }
    }

    /// `(|v|, d|v|/dr)` at `r`, or `None` outside the octaves covered.
    #[inline]
    fn eval(&self, r: f64, table: &BranchTable) -> Option<(f64, f64)> {
        let bits = r.to_bits();
        // biased exponent of r; r > 0 and finite here (NaN and infinities fall outside)
        let biased = (bits >> 52) as i64;
        let octave = usize::try_from(biased - 1023 - FAST_MIN_EXP as i64).ok()?;
        let shift = 52 - FAST_BITS;
        let j = ((bits >> shift) & ((1 << FAST_BITS) - 1)) as usize;
        let b = j >> FAST_BLOCK_BITS;
        let block = self.blocks.get(octave * FAST_BLOCKS_PER_OCTAVE + b)?;
        let cells = match block.get() {
            Some(cells) => cells,
            None => Self::fill(block, biased, b << FAST_BLOCK_BITS, table),
        };
        // r0: r with the mantissa bits below the cell index cleared; h = 2^(e - FAST_BITS)
        let r0 = f64::from_bits((bits >> shift) << shift);
        let inv_h = f64::from_bits(((2046 - biased + FAST_BITS as i64) as u64) << 52);
        let t = (r - r0) * inv_h;
        let [c0, c1, c2, c3] = cells[j & (FAST_BLOCK - 1)];
        let f = c0 + t * (c1 + t * (c2 + t * c3));
        let df_dt = c1 + t * (2.0 * c2 + 3.0 * t * c3);
        Some((f, df_dt * inv_h))
    }

    /// `block` filled on its first visit (see [`FastBranch::block`]).
    #[cold]
    #[inline(never)]
    fn fill<'a>(
        block: &'a OnceLock<Box<Block>>,
        biased: i64,
        first: usize,
        table: &BranchTable,
    ) -> &'a Block {
        block.get_or_init(|| Box::new(Self::block(biased, first, table)))
    }

    /// The cells `first .. first + FAST_BLOCK` of the octave with biased exponent `biased`,
    /// from the table's values and slopes at the cell edges.
    fn block(biased: i64, first: usize, table: &BranchTable) -> Block {
        let n = 1usize << FAST_BITS;
        let base = f64::from_bits((biased as u64) << 52);
        let h = base / n as f64;
        // |v| and d|v|/dt (t in cell units) at each edge
        let edge = |j: usize| {
            let r = base + j as f64 * h;
            let (w, dw) = table.eval(r.ln());
            let f = w.exp();
            (f, f * dw / r * h)
        };
        let mut cells = [[0.0; 4]; FAST_BLOCK];
        let mut left = edge(first);
        for (q, cell) in cells.iter_mut().enumerate() {
            let right = edge(first + q + 1);
            let ((f0, d0), (f1, d1)) = (left, right);
            *cell = [
                f0,
                d0,
                3.0 * (f1 - f0) - 2.0 * d0 - d1,
                2.0 * (f0 - f1) + d0 + d1,
            ];
            left = right;
        }
        cells
    }
}

/// Greenwood's crack law `v(k, beta)` for one k, evaluated by table interpolation.
///
/// Make it once per k and share it: its table is built on the first evaluation (0.1 ms in a
/// warm loop, about 0.2 ms among other work: the quadratures were done at build time), so a
/// law that is never evaluated (a threshold the master tables answer) costs nothing.
/// Evaluation is a cubic polynomial in a cell found from the bits of its argument (the first
/// visit of a block of eight cells fills them from the table). The tables sit behind an
/// [`Arc`], so a clone (or `CrackLaw::from(&law)`) shares them, with the cells filled so far,
/// instead of copying.
#[derive(Debug, Clone)]
pub struct CrackLaw {
    k: f64,
    tables: Arc<OnceLock<Tables>>,
}

/// The two branches' tables of one k, each with its fast representation.
#[derive(Debug)]
struct Tables {
    closing: BranchTable,
    opening: BranchTable,
    closing_fast: FastBranch,
    opening_fast: FastBranch,
}

impl Tables {
    /// The tables of `k` (checked: 0 < k < 1).
    fn new(k: f64) -> Self {
        let n = J_NODES.len();
        let mut nodes = [Branch::Closing, Branch::Opening]
            .map(|branch| (branch, Vec::with_capacity(n), Vec::with_capacity(n)));
        // zeta falls as alpha grows on both branches, so the nodes taken in decreasing alpha
        // come sorted by zeta (`BranchTable::from_nodes` makes sure)
        for &[alpha, j3, one_minus_j3, k_log] in J_NODES.iter().rev() {
            let j = JIntegrals::from_parts(alpha, j3, one_minus_j3, k_log);
            for (branch, zeta, w) in &mut nodes {
                // k was checked by `CrackLaw::new`, so every point exists
                if let Ok(p) = CrackPoint::from_integrals(k, &j, *branch) {
                    zeta.push(p.zeta());
                    w.push(p.v.abs().ln());
                }
            }
        }
        let [closing, opening] = nodes.map(|(_, zeta, w)| BranchTable::from_nodes(zeta, w));
        Tables {
            closing,
            opening,
            closing_fast: FastBranch::new(),
            opening_fast: FastBranch::new(),
        }
    }
}

impl From<&CrackLaw> for CrackLaw {
    /// Shares the tables of `law` (a reference-count increment, no copy).
    fn from(law: &CrackLaw) -> Self {
        law.clone()
    }
}

impl CrackLaw {
    /// The crack law for the modulus ratio `k` (dimensionless, 0 < k < 1).
    ///
    /// Cost: nothing until the first evaluation, which tabulates it (a few thousand
    /// logarithms; the quadratures were done at build time).
    ///
    /// # Example
    /// ```
    /// use greenwood::CrackLaw;
    /// let law = CrackLaw::new(0.01)?;
    /// // near beta = 1, v changes sign with slope dv/dbeta < 0 (Figure 1, right panel)
    /// let s = law.speed(0.999)?;
    /// assert!(s.v > 0.0 && s.dv_dbeta < 0.0);
    /// // the table agrees with the direct inversion by quadrature (Appendix A) to 1e-8
    /// let direct = greenwood::v_direct(0.01, 0.3)?;
    /// assert!((law.v(0.3)? / direct - 1.0).abs() < 1e-8);
    /// // k outside (0, 1) is refused with a message that names it
    /// assert_eq!(
    ///     CrackLaw::new(1.5).unwrap_err().to_string(),
    ///     "k = 1.5: must be 0 < k < 1 (dimensionless)"
    /// );
    /// # Ok::<(), greenwood::GreenwoodError>(())
    /// ```
    pub fn new(k: f64) -> Result<Self, GreenwoodError> {
        check_k(k)?;
        Ok(Self {
            k,
            tables: Arc::new(OnceLock::new()),
        })
    }

    /// The tables, built on first use.
    fn tables(&self) -> &Tables {
        self.tables.get_or_init(|| Tables::new(self.k))
    }

    /// The modulus ratio k this table was built for (dimensionless).
    pub fn k(&self) -> f64 {
        self.k
    }

    /// Lower bound of beta, `k` (dimensionless).
    pub fn beta_min(&self) -> f64 {
        self.k
    }

    /// Upper bound of beta, `1/k` (dimensionless).
    pub fn beta_max(&self) -> f64 {
        1.0 / self.k
    }

    /// `v(k, beta)` and `dv/dbeta` for `k < beta < 1/k` (dimensionless); an error outside.
    pub fn speed(&self, beta: f64) -> Result<CrackSpeed, GreenwoodError> {
        check_beta(self.k, beta)?;
        Ok(self.speed_unchecked(beta))
    }

    /// `v(k, beta)` for `k < beta < 1/k` (dimensionless); an error outside.
    pub fn v(&self, beta: f64) -> Result<f64, GreenwoodError> {
        Ok(self.speed(beta)?.v)
    }

    /// `v` and `dv/dbeta` without the range check, for use inside solvers whose trial states may
    /// step outside `(k, 1/k)`: at or beyond the bounds it returns `v = +inf` (beta <= k) or
    /// `v = -inf` (beta >= 1/k) with `dv/dbeta = 0`; NaN gives NaN.
    pub fn speed_unchecked(&self, beta: f64) -> CrackSpeed {
        let k = self.k;
        if beta.is_nan() {
            return CrackSpeed {
                v: f64::NAN,
                dv_dbeta: f64::NAN,
            };
        }
        if beta <= k {
            return CrackSpeed {
                v: f64::INFINITY,
                dv_dbeta: 0.0,
            };
        }
        if beta >= 1.0 / k {
            return CrackSpeed {
                v: f64::NEG_INFINITY,
                dv_dbeta: 0.0,
            };
        }
        if beta == 1.0 {
            return CrackSpeed {
                v: 0.0,
                dv_dbeta: 0.0,
            };
        }
        // r = |beta - 1| / (distance to the branch's bound), zeta = ln r (see `crate::law::zeta_of_beta`)
        let (branch, r, dr_dbeta) = if beta < 1.0 {
            let d = beta - k;
            (Branch::Closing, (1.0 - beta) / d, -(1.0 - k) / (d * d))
        } else {
            let d = 1.0 / k - beta;
            (Branch::Opening, (beta - 1.0) / d, (1.0 / k - 1.0) / (d * d))
        };
        let (table, fast, sign) = match branch {
            Branch::Closing => {
                let t = self.tables();
                (&t.closing, &t.closing_fast, 1.0)
            }
            Branch::Opening => {
                let t = self.tables();
                (&t.opening, &t.opening_fast, -1.0)
            }
        };
        let (f, df_dr) = fast.eval(r, table).unwrap_or_else(|| {
            let (w, dw) = table.eval(r.ln());
            let f = w.exp();
            (f, f * dw / r)
        });
        CrackSpeed {
            v: sign * f,
            dv_dbeta: sign * df_dr * dr_dbeta,
        }
    }
}

#[cfg(test)]
#[path = "table_tests.rs"]
mod tests;
