//! `cargo xtask master-table --check`: a sample of the committed nodes and end points recomputed
//! with the build's own search, which is deterministic, so that a change of the model cannot
//! leave stale tables.

use super::ends::{x_on, x_s};
use super::{grid_k, node, BuildConfig, Point};
use crate::master::format::{EndsData, TableData};
use crate::ThresholdsError;
use greenwood::CrackLaw;
use rayon::prelude::*;

/// A committed value and the same recomputed: where, what was stored, what the model gives now.
#[derive(Debug, Clone, PartialEq)]
pub struct Recomputed {
    /// What it is (`"F at x = .., y = .."`).
    pub what: String,
    /// The committed value.
    pub stored: f64,
    /// The value computed now (NaN where the computation failed).
    pub now: f64,
    /// How far it may lie from `stored`: the root's tolerance, or where the root is
    /// ill-conditioned (the end curves below [`ILL_CONDITIONED_BELOW_Y`]) that of its conditioning.
    pub tol: f64,
}

impl Recomputed {
    /// Whether it moved beyond its tolerance (or could not be recomputed).
    pub fn moved(&self) -> bool {
        let off = (self.now - self.stored).abs();
        off.is_nan() || off > self.tol
    }
}

/// A recomputed node must equal the committed one to this relative tolerance: the node is the
/// exact search at `rel_tol` 1e-8, and recomputed on its own (the build shares collisions
/// between neighbouring nodes) it lands elsewhere within the search's reach: near the cliff, where
/// V_out is nearly flat in V_in, its root moves most (5.8e-8 seen at F = 2433, 2.6e-9 at F_on =
/// 715). A change of the model moves the well-conditioned end points ([`END_TOL`]) and nodes by
/// more; the tables' own tolerance is 2e-6.
pub const NODE_REL_TOL: f64 = 1e-6;

/// Below this y the second kind of bouncing sets in near the cliff, and the collision at the top
/// of the search is noisy enough (about 1e-7 in V_out) that the end curves' roots move by up to a
/// few 1e-6 in x with the bracket they start from (seen at y = -6.5, k = 0.005: 5e-7, then 2e-6
/// from a guess moved by 5e-7). The tables vouch there only far from the end (d of 1.6 to 2.6 in
/// x), so these points are held to [`ILL_CONDITIONED_TOL`] instead of the roots' 1e-9.
pub const ILL_CONDITIONED_BELOW_Y: f64 = -4.5;

/// The tolerance of the end points below [`ILL_CONDITIONED_BELOW_Y`] (in x = log10 c_D).
pub const ILL_CONDITIONED_TOL: f64 = 1e-5;

/// The tolerance of the end points elsewhere (the roots' own, 1e-11, with room for rounding).
pub const END_TOL: f64 = 1e-9;

/// Every `every`-th node of `table` (body and strip, F and F_on) recomputed.
pub fn check_nodes(table: &TableData, every: usize) -> Result<Vec<Recomputed>, ThresholdsError> {
    let cfg = BuildConfig::standard();
    let law = CrackLaw::new(table.k)?;
    let mut points = Vec::new();
    for r in &table.rows {
        for (p, strip) in [(&r.body, false), (&r.strip, true)] {
            for i in 0..p.x.len() {
                points.push((r.y, p.x[i], strip, p.f_stick[i], p.f_onset[i]));
            }
        }
    }
    Ok(points
        .par_iter()
        .step_by(every.max(1))
        .flat_map_iter(|&(y, x, strip, f, f_on)| {
            let p = node(&cfg, &law, x, y);
            let at = format!("x = {x}, y = {y}, k = {}", table.k);
            let mut out = vec![Recomputed {
                what: format!("F_on at {at}"),
                stored: f_on,
                now: p.onset().unwrap_or(f64::NAN),
                tol: NODE_REL_TOL * f_on.abs(),
            }];
            if !strip {
                out.push(Recomputed {
                    what: format!("F at {at}"),
                    stored: f,
                    now: match p {
                        Point::Bounce { f_stick, .. } => f_stick,
                        _ => f64::NAN,
                    },
                    tol: NODE_REL_TOL * f.abs(),
                });
            }
            out
        })
        .collect())
}

/// Every `every`-th point of the end curves recomputed (from a guess 1e-3 away, so that the
/// root is found anew).
pub fn check_ends(ends: &EndsData, every: usize) -> Result<Vec<Recomputed>, ThresholdsError> {
    let cfg = BuildConfig::standard();
    let points: Vec<(usize, usize)> = (0..ends.nk)
        .flat_map(|j| (0..ends.ny).map(move |i| (j, i)))
        .filter(|&(j, i)| ends.x_s[j * ends.ny + i].is_finite())
        .step_by(every.max(1))
        .collect();
    points
        .par_iter()
        .map(|&(j, i)| {
            let k = grid_k(ends.k0, ends.per_octave, j);
            let y = ends.y0 + i as f64 * ends.dy;
            let law = CrackLaw::new(k)?;
            let at = j * ends.ny + i;
            let tol = if y < ILL_CONDITIONED_BELOW_Y {
                ILL_CONDITIONED_TOL
            } else {
                END_TOL
            };
            let s = x_s(&cfg, &law, y, Some(ends.x_s[at] + 1e-3));
            let o = s.and_then(|s| x_on(&cfg, &law, y, s, Some(ends.x_on[at])));
            Ok(vec![
                Recomputed {
                    what: format!("x_s at y = {y}, k = {k}"),
                    stored: ends.x_s[at],
                    now: s.unwrap_or(f64::NAN),
                    tol,
                },
                Recomputed {
                    what: format!("x_on at y = {y}, k = {k}"),
                    stored: ends.x_on[at],
                    now: o.unwrap_or(f64::NAN),
                    tol,
                },
            ])
        })
        .collect::<Result<Vec<_>, ThresholdsError>>()
        .map(|v| v.into_iter().flatten().collect())
}
