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
//! bucket index, so an evaluation is a few dozen flops, two logarithms and one exponential.
//! Outside the table (alpha beyond its range) w is extrapolated linearly, which keeps v and its
//! derivative finite, monotone and of the right sign up to the bounds.

use crate::integrals::JIntegrals;
use crate::law::{check_beta, check_k, zeta_of_beta, Branch, CrackPoint};
use crate::GreenwoodError;
use std::sync::Arc;

pub use crate::quad::{ALPHA_MAX, ALPHA_MIN, LN_ALPHA_STEP};

// `J_NODES[i] = [J3, 1 - J3, K]` at `crate::quad::node_alpha(i)`, computed by `build.rs` with the
// quadrature of `crate::quad` (the values do not depend on k).
include!(concat!(env!("OUT_DIR"), "/j_nodes.rs"));
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
    /// `newton[i]`: divided differences of the stencil of interval `[zeta[i], zeta[i+1])`.
    newton: Vec<[f64; STENCIL]>,
    /// First node of each stencil.
    start: Vec<usize>,
    /// `bucket[b]`: the interval containing the left end of bucket `b`.
    bucket: Vec<usize>,
    bucket_origin: f64,
    bucket_inv_width: f64,
}

impl BranchTable {
    fn from_points(mut points: Vec<(f64, f64)>) -> Self {
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (zeta, w): (Vec<f64>, Vec<f64>) = points.into_iter().unzip();
        let n = zeta.len();
        let intervals = n - 1;
        let mut newton = Vec::with_capacity(intervals);
        let mut start = Vec::with_capacity(intervals);
        for i in 0..intervals {
            // the stencil centred on interval i: nodes i-2 ..= i+3, shifted inside the table
            let s =
                (i as isize + 1 - (STENCIL / 2) as isize).clamp(0, (n - STENCIL) as isize) as usize;
            let xs = &zeta[s..s + STENCIL];
            let mut dd = [0.0; STENCIL];
            dd.copy_from_slice(&w[s..s + STENCIL]);
            for order in 1..STENCIL {
                for j in (order..STENCIL).rev() {
                    dd[j] = (dd[j] - dd[j - 1]) / (xs[j] - xs[j - order]);
                }
            }
            newton.push(dd);
            start.push(s);
        }
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
            bucket.push(i);
        }
        Self {
            bucket_origin: zeta[0],
            zeta,
            w,
            newton,
            start,
            bucket,
            bucket_inv_width,
        }
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
        let mut i = self.bucket[b];
        while i + 1 < last && self.zeta[i + 1] <= z {
            i += 1;
        }
        let dd = &self.newton[i];
        let xs = &self.zeta[self.start[i]..self.start[i] + STENCIL];
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

/// Greenwood's crack law `v(k, beta)` for one k, evaluated by table interpolation.
///
/// Build it once per k (0.17 ms: the quadratures were done at build time) and share it:
/// evaluation is a bucket lookup and a small polynomial in Newton form (about 30 ns). The tables
/// sit behind an [`Arc`], so a clone (or `CrackLaw::from(&law)`) shares them instead of copying.
#[derive(Debug, Clone)]
pub struct CrackLaw {
    k: f64,
    tables: Arc<Tables>,
}

/// The two branches' tables of one k.
#[derive(Debug)]
struct Tables {
    closing: BranchTable,
    opening: BranchTable,
}

impl From<&CrackLaw> for CrackLaw {
    /// Shares the tables of `law` (a reference-count increment, no copy).
    fn from(law: &CrackLaw) -> Self {
        law.clone()
    }
}

impl CrackLaw {
    /// Tabulates the crack law for the modulus ratio `k` (dimensionless, 0 < k < 1).
    ///
    /// Cost: a few thousand logarithms; the quadratures were done at build time.
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
        let mut closing = Vec::with_capacity(J_NODES.len());
        let mut opening = Vec::with_capacity(J_NODES.len());
        for (i, &[j3, one_minus_j3, k_log]) in J_NODES.iter().enumerate() {
            let j = JIntegrals::from_parts(crate::quad::node_alpha(i), j3, one_minus_j3, k_log);
            for (branch, out) in [
                (Branch::Closing, &mut closing),
                (Branch::Opening, &mut opening),
            ] {
                let p = CrackPoint::from_integrals(k, &j, branch)?;
                out.push((p.zeta(), p.v.abs().ln()));
            }
        }
        Ok(Self {
            k,
            tables: Arc::new(Tables {
                closing: BranchTable::from_points(closing),
                opening: BranchTable::from_points(opening),
            }),
        })
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
        let (branch, zeta) = zeta_of_beta(k, beta);
        match branch {
            Branch::Closing => {
                let (w, dw) = self.tables.closing.eval(zeta);
                let v = w.exp();
                // zeta = ln(1 - beta) - ln(beta - k)
                let dzeta = -1.0 / (1.0 - beta) - 1.0 / (beta - k);
                CrackSpeed {
                    v,
                    dv_dbeta: v * dw * dzeta,
                }
            }
            Branch::Opening => {
                let (w, dw) = self.tables.opening.eval(zeta);
                let v = -w.exp();
                // zeta = ln(beta - 1) - ln(1/k - beta)
                let dzeta = 1.0 / (beta - 1.0) + 1.0 / (1.0 / k - beta);
                CrackSpeed {
                    v,
                    dv_dbeta: v * dw * dzeta,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::J_NODES;
    use crate::quad::{j3_complement_log_term, node_alpha, node_count};

    /// The build-time table holds exactly what the quadrature gives now.
    #[test]
    fn build_time_nodes_equal_the_quadrature() {
        assert_eq!(J_NODES.len(), node_count());
        for i in (0..J_NODES.len()).step_by(97) {
            let (j3, m, k) = j3_complement_log_term(node_alpha(i));
            assert_eq!(J_NODES[i], [j3, m, k], "node {i}");
        }
    }
}
