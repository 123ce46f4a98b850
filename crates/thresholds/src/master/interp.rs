//! Local cubic interpolation on nonuniform nodes: the interpolant of the master table in each
//! direction.

/// The index `i` of the interval `[xs[i], xs[i + 1]]` that holds `x` (`xs` increasing, at least
/// two nodes), clamped to the first and last intervals.
pub(crate) fn interval(xs: &[f64], x: f64) -> usize {
    interval_of(xs.partition_point(|&v| v <= x), xs.len())
}

/// The interval of `n` nodes whose partition point (how many nodes are <= x) is `p`, clamped
/// to the first and last intervals.
fn interval_of(p: usize, n: usize) -> usize {
    match p {
        0 => 0,
        p if p >= n => n - 2,
        p => p - 1,
    }
}

/// [`interval`] in each of four arrays at once: the four searches step together, so that their
/// loads (the rows of a stencil lie far apart in a table of megabytes) wait on memory side by
/// side instead of one after the other. The same intervals as four calls of [`interval`].
pub(crate) fn intervals4(xs: [&[f64]; 4], x: [f64; 4]) -> [usize; 4] {
    // a branchless lower bound: `base` is the last node <= x (or 0), halving `size`
    let mut base = [0usize; 4];
    let mut size = xs.map(<[f64]>::len);
    while size.iter().any(|&s| s > 1) {
        for q in 0..4 {
            if size[q] > 1 {
                let half = size[q] / 2;
                let mid = base[q] + half;
                base[q] = if xs[q][mid] <= x[q] { mid } else { base[q] };
                size[q] -= half;
            }
        }
    }
    std::array::from_fn(|q| {
        let n = xs[q].len();
        // the partition point: how many nodes are <= x
        interval_of(base[q] + usize::from(n > 0 && xs[q][base[q]] <= x[q]), n)
    })
}

/// The first of the (at most) four nodes around interval `i` of `n` nodes: `i - 1`, shifted
/// inward at the ends so that the stencil stays inside.
pub(crate) fn stencil_start(i: usize, n: usize) -> usize {
    let width = n.min(4);
    i.saturating_sub(1).min(n - width)
}

/// The value at `x` of the polynomial through `(xs[j], ys[j])` (Lagrange form; two or more
/// points, four written out).
pub(crate) fn lagrange(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if xs.len() == 4 {
        let w = weights4(xs, x);
        return w[0] * ys[0] + w[1] * ys[1] + w[2] * ys[2] + w[3] * ys[3];
    }
    ys.iter()
        .enumerate()
        .map(|(j, &yj)| lagrange_weight(xs, j, x) * yj)
        .sum()
}

/// The Lagrange basis polynomial of node `j` of `xs` at `x` (one division): the weight of
/// `ys[j]` in the interpolant through `(xs, ys)` (public for the examples that interpolate
/// reference nodes the same way, `kink_lattice`).
pub fn lagrange_weight(xs: &[f64], j: usize, x: f64) -> f64 {
    let (mut num, mut den) = (1.0, 1.0);
    for (m, &xm) in xs.iter().enumerate() {
        if m != j {
            num *= x - xm;
            den *= xs[j] - xm;
        }
    }
    num / den
}

/// The cubic Lagrange weights of the four nodes `xs` at `x`, written out (the answer's hot
/// loop: one division a node, no branches).
pub(crate) fn weights4(xs: &[f64], x: f64) -> [f64; 4] {
    let (x0, x1, x2, x3) = (xs[0], xs[1], xs[2], xs[3]);
    let (d0, d1, d2, d3) = (x - x0, x - x1, x - x2, x - x3);
    [
        d1 * d2 * d3 / ((x0 - x1) * (x0 - x2) * (x0 - x3)),
        d0 * d2 * d3 / ((x1 - x0) * (x1 - x2) * (x1 - x3)),
        d0 * d1 * d3 / ((x2 - x0) * (x2 - x1) * (x2 - x3)),
        d0 * d1 * d2 / ((x3 - x0) * (x3 - x1) * (x3 - x2)),
    ]
}

/// The local cubic through the four nodes around `x` of `(xs, ys)` (`xs` increasing, at least
/// two nodes; fewer than four give a lower degree).
pub(crate) fn local_cubic(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len();
    let s = stencil_start(interval(xs, x), n);
    let e = (s + 4).min(n);
    lagrange(&xs[s..e], &ys[s..e], x)
}

/// [`local_cubic`] of two value arrays on the same nodes, in the interval `i` of `xs` that
/// holds `x` (found once for both, by [`interval`] or [`intervals4`]).
pub(crate) fn local_cubic_both(xs: &[f64], ys: [&[f64]; 2], x: f64, i: usize) -> [f64; 2] {
    let n = xs.len();
    let s = stencil_start(i, n);
    let e = (s + 4).min(n);
    if e - s == 4 {
        let w = weights4(&xs[s..e], x);
        let dot = |v: &[f64]| w[0] * v[s] + w[1] * v[s + 1] + w[2] * v[s + 2] + w[3] * v[s + 3];
        return [dot(ys[0]), dot(ys[1])];
    }
    [
        lagrange(&xs[s..e], &ys[0][s..e], x),
        lagrange(&xs[s..e], &ys[1][s..e], x),
    ]
}

/// Whether the fractional position `f` lies on a uniform grid of `n` nodes (at 0, 1, ...,
/// n - 1): a position up to 1e-9 steps outside is taken as its end (rounding).
fn on_grid(f: f64, n: usize) -> bool {
    const EDGE: f64 = 1e-9;
    f >= -EDGE && f <= (n as f64 - 1.0) + EDGE
}

/// The first node of the interval of a uniform grid of `n` nodes (at 0, 1, ..., n - 1) that
/// holds the fractional position `f` (the last interval at the last node); `None` outside the
/// grid or with fewer than two nodes.
pub(crate) fn cell_of(f: f64, n: usize) -> Option<usize> {
    (n >= 2 && on_grid(f, n)).then(|| (f.max(0.0).floor() as usize).min(n - 2))
}

/// The first of the four nodes of a uniform grid of `n` nodes (at 0, 1, ..., n - 1) around the
/// fractional position `f`, and the cubic Lagrange weights of those four nodes at `f`; `None`
/// when `f` lies outside the grid (beyond a rounding margin) or the grid has fewer than four
/// nodes.
pub(crate) fn uniform_weights(f: f64, n: usize) -> Option<(usize, [f64; 4])> {
    if n < 4 || !on_grid(f, n) {
        return None;
    }
    let i0 = (f.floor() as i64 - 1).clamp(0, n as i64 - 4) as usize;
    let t = f - i0 as f64;
    let w = [
        -(t - 1.0) * (t - 2.0) * (t - 3.0) / 6.0,
        t * (t - 2.0) * (t - 3.0) / 2.0,
        -t * (t - 1.0) * (t - 3.0) / 2.0,
        t * (t - 1.0) * (t - 2.0) / 6.0,
    ];
    Some((i0, w))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic is reproduced exactly (to rounding) on a nonuniform grid, inside and at the ends;
    /// the interval search clamps outside the nodes.
    #[test]
    fn cubics_are_exact() {
        let xs = [0.0, 0.3, 1.0, 1.2, 2.5, 4.0];
        let f = |x: f64| 2.0 - x + 0.5 * x * x - 0.25 * x * x * x;
        let ys: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        for x in [0.1, 0.65, 1.1, 2.0, 3.9, 4.0, 0.0] {
            assert!((local_cubic(&xs, &ys, x) - f(x)).abs() < 1e-12, "{x}");
        }
        assert_eq!(interval(&xs, -1.0), 0);
        assert_eq!(interval(&xs, 9.0), 4);
        assert_eq!(interval(&xs, 1.0), 2);
        assert_eq!(
            (
                stencil_start(0, 6),
                stencil_start(4, 6),
                stencil_start(2, 6)
            ),
            (0, 2, 1)
        );
    }

    /// The four searches in step find the intervals of four separate searches (std's
    /// `partition_point`), for rows of different lengths, at nodes, between them, outside them
    /// and at NaN.
    #[test]
    fn four_searches_in_step_find_the_same_intervals() {
        let rows: [Vec<f64>; 4] = [
            vec![0.0, 1.0],
            vec![-3.0, -1.0, 0.5, 2.0, 2.5],
            (0..37).map(|i| (i as f64).powf(1.3) - 4.0).collect(),
            (0..200).map(|i| 0.1 * i as f64 - 7.0).collect(),
        ];
        let probes = [
            -100.0,
            -7.0,
            -4.0,
            -3.0,
            -1.0,
            0.0,
            0.25,
            0.5,
            1.0,
            2.0,
            2.2,
            12.9,
            13.0,
            1e9,
            f64::NAN,
        ];
        for (a, &x0) in probes.iter().enumerate() {
            for &x1 in &probes[a..] {
                let x = [x0, x1, x0, x1];
                let found = intervals4(std::array::from_fn(|q| &rows[q][..]), x);
                for q in 0..4 {
                    assert_eq!(found[q], interval(&rows[q], x[q]), "row {q} at {}", x[q]);
                }
            }
        }
    }

    /// Uniform weights reproduce a cubic, give a node's value at the node, and refuse outside.
    #[test]
    fn uniform_weights_are_cubic_lagrange() {
        let f = |x: f64| 1.0 - 2.0 * x + 0.3 * x * x * x;
        for pos in [0.0, 0.5, 3.0, 4.25, 7.0] {
            let (i0, w) = uniform_weights(pos, 8).unwrap();
            let v: f64 = (0..4).map(|q| w[q] * f((i0 + q) as f64)).sum();
            assert!((v - f(pos)).abs() < 1e-12, "{pos}");
        }
        let (i0, w) = uniform_weights(5.0, 8).unwrap();
        assert_eq!((i0, w), (4, [0.0, 1.0, 0.0, 0.0]));
        assert!(uniform_weights(-0.1, 8).is_none() && uniform_weights(7.1, 8).is_none());
        assert!(uniform_weights(1.0, 3).is_none());
    }

    /// The interpolation error of a smooth function falls as h^4 (halving the spacing divides it
    /// by about 16): the basis of the table's refinement.
    #[test]
    fn error_falls_as_the_fourth_power() {
        let err = |h: f64| {
            let xs: Vec<f64> = (0..80).map(|i| i as f64 * h).collect();
            let ys: Vec<f64> = xs.iter().map(|x| x.sin()).collect();
            // the largest error over [1, 2], between the nodes
            (0..200)
                .map(|i| 1.0 + i as f64 / 200.0 + 0.37 * h)
                .map(|x| (local_cubic(&xs, &ys, x) - x.sin()).abs())
                .fold(0.0, f64::max)
        };
        let ratio = err(0.1) / err(0.05);
        assert!(ratio > 12.0 && ratio < 20.0, "{ratio}");
    }
}
