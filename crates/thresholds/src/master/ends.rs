//! The end curves x_s(y, k) (where F = V_stick/V_stick,JKR reaches [`super::F_TOP`]) and
//! x_on(y, k) (where F_on does), interpolated from their grid in y and ln k.
//!
//! Near its end F is steep in x (V_stick diverges at the cliff, roughly as a power of
//! ln(1/(x_c - x))), so the tables interpolate it at a fixed distance `d = x_s - x` to the end,
//! and a query needs x_s at its own (y, k) far more precisely than the rows' spacing would give:
//! the grid is fine (1/64 in y, 12 steps an octave of k) and each point is a root found to
//! 1e-10 in x, so that the bicubic interpolant is good to about 1e-9.

use super::format::EndsData;
use super::interp::{cell_of, uniform_weights};

/// Where the end curves are not interpolated (next to the kink where the cliff changes regime),
/// a point this far (in x) beyond the largest end of the four grid points around it is beyond
/// its end. Next to the kink each curve is the larger of two branches (the cliff of the first
/// kind of bouncing, and the end of the second), each monotone in y and in k, so that over a
/// cell of the grid it is largest at a corner; the margin covers only the fuzz of the ends there
/// (5e-7, where F rises as a power of c_D) twenty times over. Measured on the committed grid:
/// over every cell two, three and four steps wide that touches the kink band, no grid point
/// inside lies above the largest of the cell's corners (`the_kink_bound_holds_on_coarser_cells`).
pub const KINK_MARGIN: f64 = 1e-5;

/// What [`EndCurves::at`] was last asked on a thread: the curves' id and the bits of y and k.
type Asked = (u64, u64, u64);

thread_local! {
    /// The last question [`EndCurves::at`] answered on this thread, and its answer.
    static LAST_ENDS: std::cell::Cell<Option<(Asked, Option<Ends>)>> =
        const { std::cell::Cell::new(None) };
}

/// The end curves, ready to interpolate.
#[derive(Debug, Clone)]
pub struct EndCurves {
    /// Which curves these are, for the per-thread memo of [`EndCurves::at`]: an address can be
    /// reused by other curves once these are dropped, an id is not.
    id: u64,
    data: EndsData,
    /// ln of the first k.
    ln_k0: f64,
    /// k steps per unit of ln k.
    per_ln: f64,
}

/// Equal curves are equal data (whatever their ids).
impl PartialEq for EndCurves {
    fn eq(&self, other: &Self) -> bool {
        self.data == other.data
    }
}

/// x_s and x_on at one (y, k).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ends {
    /// log10 c_D where F = V_stick/V_stick,JKR reaches [`super::F_TOP`].
    pub x_s: f64,
    /// log10 c_D where F_on = V_double_onset/V_stick,JKR reaches it (at least `x_s`).
    pub x_on: f64,
}

impl EndCurves {
    /// The interpolation form of `data`.
    pub fn new(data: EndsData) -> Self {
        static NEXT_ID: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
        Self {
            id: NEXT_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
            ln_k0: data.k0.ln(),
            per_ln: data.per_octave as f64 / std::f64::consts::LN_2,
            data,
        }
    }

    /// The grid's data.
    pub fn data(&self) -> &EndsData {
        &self.data
    }

    /// The k of grid column `j`.
    pub fn k_at(&self, j: usize) -> f64 {
        self.data.k0 * 2f64.powf(j as f64 / self.data.per_octave as f64)
    }

    /// The range of k the grid spans.
    pub fn k_range(&self) -> (f64, f64) {
        (self.data.k0, self.k_at(self.data.nk - 1))
    }

    /// The y of grid row `i`.
    pub fn y_at(&self, i: usize) -> f64 {
        self.data.y0 + i as f64 * self.data.dy
    }

    /// The end curves at `(y, k)` by the bicubic interpolant of the grid; `None` outside the
    /// grid, where a value of the 4 x 4 stencil is missing, or next to a kink of the curves.
    /// The last answer of each thread is kept: the elements of an array at one radius ask at
    /// the same `(y, k)` (a sixth of a table answer, saved).
    pub fn at(&self, y: f64, k: f64) -> Option<Ends> {
        let key = (self.id, y.to_bits(), k.to_bits());
        if let Some((at, ends)) = LAST_ENDS.with(|c| c.get()) {
            if at == key {
                return ends;
            }
        }
        let ends = self.interpolate(y, k);
        LAST_ENDS.with(|c| c.set(Some((key, ends))));
        ends
    }

    /// [`EndCurves::at`], computed.
    fn interpolate(&self, y: f64, k: f64) -> Option<Ends> {
        let d = &self.data;
        let fy = (y - d.y0) / d.dy;
        let fk = (k.ln() - self.ln_k0) * self.per_ln;
        let (iy, wy) = uniform_weights(fy, d.ny)?;
        let (ik, wk) = uniform_weights(fk, d.nk)?;
        let (mut s, mut o) = (0.0, 0.0);
        for (a, &w_k) in wk.iter().enumerate() {
            for (b, &w_y) in wy.iter().enumerate() {
                let at = (ik + a) * d.ny + iy + b;
                if !d.is_valid(at) {
                    return None;
                }
                s += w_k * w_y * d.x_s[at];
                o += w_k * w_y * d.x_on[at];
            }
        }
        (s.is_finite() && o.is_finite()).then_some(Ends {
            x_s: s,
            x_on: o.max(s),
        })
    }

    /// Upper bounds of the end curves at `(y, k)` that hold next to a kink, where [`Self::at`]
    /// declines: the largest of each curve at the four grid points around `(y, k)` plus
    /// [`KINK_MARGIN`]; `None` outside the grid or where a value is missing.
    pub fn upper_bound(&self, y: f64, k: f64) -> Option<Ends> {
        let d = &self.data;
        let iy = cell_of((y - d.y0) / d.dy, d.ny)?;
        let ik = cell_of((k.ln() - self.ln_k0) * self.per_ln, d.nk)?;
        let corners = [(ik, iy), (ik, iy + 1), (ik + 1, iy), (ik + 1, iy + 1)];
        let (mut s, mut o) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        for (j, i) in corners {
            let at = j * d.ny + i;
            if !(d.x_s[at].is_finite() && d.x_on[at].is_finite()) {
                return None;
            }
            s = s.max(d.x_s[at]);
            o = o.max(d.x_on[at]);
        }
        Some(Ends {
            x_s: s + KINK_MARGIN,
            x_on: o.max(s) + KINK_MARGIN,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::MasterTables;

    /// The bound next to the kink ([`KINK_MARGIN`]): over cells of the committed grid two,
    /// three and four steps wide that touch the points where the curves are not interpolated,
    /// no grid point inside lies above the largest of the cell's four corners (each curve the
    /// larger of two branches monotone in y and k), so that on the grid's own cells the corners
    /// bound the curves too.
    #[test]
    fn the_kink_bound_holds_on_coarser_cells() {
        let ends = MasterTables::standard()
            .ends()
            .expect("the embedded end curves");
        let d = ends.data();
        let at = |j: usize, i: usize| j * d.ny + i;
        let mut cells = 0;
        for s in 2..=4 {
            for j in 0..d.nk - s {
                for i in 0..d.ny - s {
                    let inside =
                        || (j..=j + s).flat_map(move |a| (i..=i + s).map(move |b| at(a, b)));
                    if inside().all(|p| d.is_valid(p)) {
                        continue;
                    }
                    cells += 1;
                    for curve in [&d.x_s, &d.x_on] {
                        let corners = [at(j, i), at(j, i + s), at(j + s, i), at(j + s, i + s)]
                            .map(|p| curve[p])
                            .into_iter()
                            .fold(f64::NEG_INFINITY, f64::max);
                        let top = inside().map(|p| curve[p]).fold(f64::NEG_INFINITY, f64::max);
                        assert!(
                            top <= corners,
                            "k index {j}, y index {i}, {s} steps: {top} > {corners}"
                        );
                    }
                }
            }
        }
        // measured: 2119 + 2226 + 2325 cells of the committed grid touch the kink band
        assert!(cells > 6000, "{cells} cells");
    }

    /// The per-thread memo answers each set of curves with its own values: two curves asked
    /// in turn at one (y, k), the second the first moved by 1 in x, stay 1 apart; and the
    /// memo's answer is the interpolation's.
    #[test]
    fn the_memo_keeps_curves_apart() {
        let ends = MasterTables::standard()
            .ends()
            .expect("the embedded end curves");
        let mut moved = ends.data().clone();
        moved.x_s.to_mut().iter_mut().for_each(|x| *x += 1.0);
        moved.x_on.to_mut().iter_mut().for_each(|x| *x += 1.0);
        let moved = EndCurves::new(moved);
        let (y, k) = (-1.17, 0.01);
        let direct = ends.interpolate(y, k).expect("inside the grid");
        for _ in 0..3 {
            let (a, b) = (ends.at(y, k).expect("a"), moved.at(y, k).expect("b"));
            assert_eq!(a, direct);
            assert!((b.x_s - a.x_s - 1.0).abs() < 1e-12 && (b.x_on - a.x_on - 1.0).abs() < 1e-12);
        }
        // clones are equal (the same data), and answer alike
        assert_eq!(ends.clone(), *ends);
        assert_eq!(ends.clone().at(y, k), Some(direct));
    }
}
