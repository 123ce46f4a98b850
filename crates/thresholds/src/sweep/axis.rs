//! The axes of a sweep as a user writes them: a comma list (`1e-6,3e-6`) or a log-spaced range
//! `START:STOP:N` ([`parse_axis`], [`geomspace`]), and the canonical form a file header records
//! ([`canonical`]).

use numerics::format::number;

/// An axis that cannot be read: which (a flag or argument name), as written, and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{axis} = {spec}: {problem}")]
pub struct AxisError {
    /// The axis' name as the user wrote it (`--radius`, `radius`).
    pub axis: String,
    /// The text given.
    pub spec: String,
    /// What is wrong with it.
    pub problem: String,
}

/// The most values a `START:STOP:N` range may have: 1e7 (80 MB for the axis alone; a sweep
/// over it takes minutes even where the master tables answer every point), so that a typo
/// such as `1e-6:1e-4:1000000000` is refused at once instead of exhausting the memory.
pub const MAX_AXIS_VALUES: usize = 10_000_000;

/// The values of an axis written as a comma list, or as `START:STOP:N` for N values evenly
/// spaced in log from START to STOP, both ends included ([`geomspace`]). `axis` names it in
/// errors. Only the form is checked here; the values' ranges are checked with the grid
/// ([`crate::sweep::Grid::validate`]).
///
/// # Example
/// ```
/// use thresholds::sweep::parse_axis;
/// assert_eq!(parse_axis("--k", "0.01, 0.02")?, vec![0.01, 0.02]);
/// assert_eq!(parse_axis("--radius", "1e-6:1e-4:3")?, vec![1e-6, 1e-5, 1e-4]);
/// let e = parse_axis("--t-vis", "1e-9:1e-8").unwrap_err();
/// assert_eq!(e.to_string(), "--t-vis = 1e-9:1e-8: a range is START:STOP:N");
/// # Ok::<(), thresholds::sweep::AxisError>(())
/// ```
pub fn parse_axis(axis: &str, spec: &str) -> Result<Vec<f64>, AxisError> {
    let bad = |problem: &str| AxisError {
        axis: axis.to_string(),
        spec: spec.to_string(),
        problem: problem.to_string(),
    };
    let value = |s: &str| -> Result<f64, AxisError> {
        s.trim()
            .parse::<f64>()
            .map_err(|_| bad(&format!("'{}' is not a number", s.trim())))
    };
    if !spec.contains(':') {
        return spec.split(',').map(value).collect();
    }
    let parts: Vec<&str> = spec.split(':').collect();
    let [start, stop, n] = parts.as_slice() else {
        return Err(bad("a range is START:STOP:N"));
    };
    let (start, stop) = (value(start)?, value(stop)?);
    let n: usize = match n.trim().parse() {
        Ok(n) if (1..=MAX_AXIS_VALUES).contains(&n) => n,
        _ => {
            let max = MAX_AXIS_VALUES;
            return Err(bad(&format!("N must be a whole number from 1 to {max}")));
        }
    };
    if !(start.is_finite() && stop.is_finite() && start > 0.0 && stop > 0.0) {
        return Err(bad(
            "a log-spaced range needs START and STOP > 0 and finite",
        ));
    }
    Ok(geomspace(start, stop, n))
}

/// `n` values from `start` to `stop` (both > 0 and finite, else the values between are NaN;
/// [`parse_axis`] checks them) evenly spaced in log, both ends exact, computed as
/// `numpy.geomspace(start, stop, n)` does: `10^(log10 start + i step)`; none for `n = 0`. The
/// one log grid of the workspace (sweeps, figures).
///
/// # Example
/// ```
/// use thresholds::sweep::geomspace;
/// assert_eq!(geomspace(1e-12, 1e-8, 5), vec![1e-12, 1e-11, 1e-10, 1e-9, 1e-8]);
/// assert_eq!(geomspace(2.0, 8.0, 1), vec![2.0]);
/// assert!(geomspace(2.0, 8.0, 0).is_empty());
/// ```
pub fn geomspace(start: f64, stop: f64, n: usize) -> Vec<f64> {
    match n {
        0 => return Vec::new(),
        1 => return vec![start],
        _ => {}
    }
    let (a, b) = (start.log10(), stop.log10());
    let step = (b - a) / (n - 1) as f64;
    let mut out: Vec<f64> = (0..n)
        .map(|i| {
            let y = if i == n - 1 { b } else { i as f64 * step + a };
            10f64.powf(y)
        })
        .collect();
    out[0] = start;
    out[n - 1] = stop;
    out
}

/// The axis in the canonical form a file header records, so that two ways of writing the same
/// sweep (`6e-5` and `0.00006`, spaces after commas) read the same: each number in the
/// workspace's one format, a range as `START:STOP:N`. Call it on an axis [`parse_axis`] reads.
///
/// # Example
/// ```
/// use thresholds::sweep::canonical;
/// assert_eq!(canonical("6e-5, 1E-4"), "0.00006,0.0001");
/// assert_eq!(canonical("1e-12 : 1e-08 : 5"), "1e-12:1e-8:5");
/// ```
pub fn canonical(spec: &str) -> String {
    let shortest = |x: &str| x.trim().parse::<f64>().map_or(x.trim().to_string(), number);
    match spec.split(':').collect::<Vec<_>>().as_slice() {
        [start, stop, n] => format!("{}:{}:{}", shortest(start), shortest(stop), n.trim()),
        _ => spec.split(',').map(shortest).collect::<Vec<_>>().join(","),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// numpy.geomspace(1e-12, 1e-8, 33) has every eighth point at a whole decade, the ends
    /// exact, and a constant ratio 10^(1/8) between neighbours.
    #[test]
    fn geomspace_is_evenly_spaced_in_log() {
        let g = geomspace(1e-12, 1e-8, 33);
        assert_eq!((g[0], g[32]), (1e-12, 1e-8));
        for (i, decade) in [(8, 1e-11), (16, 1e-10), (24, 1e-9)] {
            assert!((g[i] / decade - 1.0).abs() < 1e-14, "{i}: {}", g[i]);
        }
        for w in g.windows(2) {
            assert!((w[1] / w[0] / 10f64.powf(0.125) - 1.0).abs() < 1e-13);
        }
    }

    #[test]
    fn malformed_axes_name_the_axis_and_the_problem() {
        let e = |s: &str| parse_axis("--k", s).unwrap_err().to_string();
        assert_eq!(e("0.01,x"), "--k = 0.01,x: 'x' is not a number");
        assert_eq!(
            e("1:2:0"),
            "--k = 1:2:0: N must be a whole number from 1 to 10000000"
        );
        assert!(e("1:2:10000001").ends_with("from 1 to 10000000"));
        assert!(e("-1:2:3").contains("START and STOP > 0"));
    }

    /// A sweep read and checked with `?` throughout: the axis and grid errors convert into
    /// [`crate::ThresholdsError`], and a grid's value out of range is found by `out_of_range`.
    #[test]
    fn sweep_errors_convert_for_the_question_mark() {
        use crate::sweep::{Grid, NamedMaterial, Partner, TVisAxis};
        use crate::{Material, ThresholdsError};
        let grid = |radius: &str, k: &str| -> Result<Grid, ThresholdsError> {
            let grid = Grid {
                materials: vec![NamedMaterial {
                    name: "co2".into(),
                    material: Material::co2(),
                }],
                gamma_sv: None,
                radius: parse_axis("radius", radius)?,
                partner: Partner::Same,
                t_vis: TVisAxis::Values(vec![1e-9]),
                k: parse_axis("k", k)?,
            };
            grid.validate()?;
            Ok(grid)
        };
        assert_eq!(grid("1e-6:1e-4:3", "0.01").unwrap().len(), 3);
        let axis = grid("1e-6:x:3", "0.01").unwrap_err();
        assert!(matches!(axis, ThresholdsError::Axis(_)), "{axis}");
        let k = grid("1e-6", "0.01,0.95").unwrap_err();
        assert_eq!(k.out_of_range().map(|o| o.field), Some("k"), "{k}");
        let large = grid("1e-6:1e-4:100000", "0.005:0.05:100000").unwrap_err();
        assert!(
            large
                .to_string()
                .contains("make a grid of 10000000000 points"),
            "{large}"
        );
    }
}
