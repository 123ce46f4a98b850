//! What the tables say of one ratio against the search limit f_max = v_max / V_stick,JKR: a
//! value clearly below it (an answer), clearly above it ("nothing below v_max"), or too close
//! to tell; and the answer both ratios make together.

/// A table answer is given only where a ratio is clearly on one side of the search limit
/// f_max: within this relative distance of it the exact search decides.
pub const V_MAX_MARGIN: f64 = 1e-4;

/// A lower bound read closer to the end than the tables vouch for values
/// ([`super::format::PieceData::d_lb`]) says "above the search limit" only where it exceeds
/// f_max by this (relative). There the interpolation is within the build's 2e-6 of the exact
/// nodes, but the default search strays from them by up to 1.4e-4 (near the cliff of CO2-like
/// rows, where V_out is nearly flat in V_in; the build's `--part bounds` stops where it strays
/// by more than 1e-3 at a node): ten times what the build accepts, seventy times the scatter
/// measured, so that the verdict is the default search's.
pub const BOUND_MARGIN: f64 = 1e-2;

/// What the tables say of one ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Side {
    /// The ratio, below the search limit.
    Below(f64),
    /// Above the search limit: nothing (bouncing or double collision) below v_max.
    Above,
    /// Not vouched for, or too close to the limit.
    Unknown,
}

/// `g = ln(ratio - 1)` vouched for, or a lower bound of it with the margin its verdict needs
/// ([`V_MAX_MARGIN`], or [`BOUND_MARGIN`] for the bounds checked against the exact nodes only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Eval {
    Value(f64),
    AtLeast { g: f64, margin: f64 },
    Unknown,
}

impl Eval {
    /// Of two lower bounds, the one that says the most (the larger ratio over its margin).
    pub(super) fn stronger(self, other: Eval) -> Eval {
        let reach = |e: Eval| match e {
            Eval::AtLeast { g, margin } => (1.0 + g.exp()) / (1.0 + margin),
            _ => f64::NEG_INFINITY,
        };
        if reach(other) > reach(self) {
            other
        } else {
            self
        }
    }
}

/// Which side of the search limit `f_max` (a ratio to V_stick,JKR) `e` puts its ratio on, with
/// [`V_MAX_MARGIN`] for a value and the bound's own margin for a lower bound.
pub(super) fn side(e: Eval, f_max: f64) -> Side {
    match e {
        Eval::Value(g) => {
            let r = 1.0 + g.exp();
            if r < f_max * (1.0 - V_MAX_MARGIN) {
                Side::Below(r)
            } else if r > f_max * (1.0 + V_MAX_MARGIN) {
                Side::Above
            } else {
                Side::Unknown
            }
        }
        Eval::AtLeast { g, margin } if 1.0 + g.exp() > f_max * (1.0 + margin) => Side::Above,
        _ => Side::Unknown,
    }
}

/// The answer from what the tables say of each ratio: both below the search limit, F above it
/// (no bouncing below v_max) with F_on below or above; nothing otherwise.
pub(super) fn both(stick: Side, onset: Side) -> Option<(Option<f64>, Option<f64>)> {
    match (stick, onset) {
        (Side::Below(s), Side::Below(o)) => Some((Some(s), Some(o.min(s)))),
        (Side::Above, Side::Below(o)) => Some((None, Some(o))),
        (Side::Above, Side::Above) => Some((None, None)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn g(ratio: f64) -> f64 {
        (ratio - 1.0).ln()
    }

    /// A value is an answer below f_max (1 - V_MAX_MARGIN), "above" beyond f_max (1 +
    /// V_MAX_MARGIN), nothing between; a lower bound is "above" only beyond f_max (1 + its
    /// margin), and nothing otherwise: 1.005 f_max from a bound checked against the exact nodes
    /// only ([`BOUND_MARGIN`]) tells nothing, 1.02 f_max tells "above".
    #[test]
    fn each_side_of_the_limit_with_its_margin() {
        let f_max = 1000.0;
        assert!(
            matches!(side(Eval::Value(g(999.0)), f_max), Side::Below(r) if (r - 999.0).abs() < 1e-9)
        );
        assert_eq!(side(Eval::Value(g(1000.05)), f_max), Side::Unknown);
        assert_eq!(side(Eval::Value(g(1000.2)), f_max), Side::Above);
        let bound = |r: f64, margin: f64| Eval::AtLeast { g: g(r), margin };
        assert_eq!(side(bound(1000.2, V_MAX_MARGIN), f_max), Side::Above);
        assert_eq!(side(bound(999.0, V_MAX_MARGIN), f_max), Side::Unknown);
        assert_eq!(side(bound(1005.0, BOUND_MARGIN), f_max), Side::Unknown);
        assert_eq!(side(bound(1020.0, BOUND_MARGIN), f_max), Side::Above);
    }

    /// Of two lower bounds the stronger is the one that tells "above" for the larger f_max:
    /// 1020 with a margin of 1e-2 (up to f_max = 1009.9) beats 1005 with 1e-4 (1004.9), and
    /// loses to 1015 with 1e-4 (1014.9); a value or nothing never replaces a bound.
    #[test]
    fn the_stronger_of_two_bounds() {
        let bound = |r: f64, margin: f64| Eval::AtLeast { g: g(r), margin };
        let deep = bound(1020.0, BOUND_MARGIN);
        assert_eq!(bound(1005.0, V_MAX_MARGIN).stronger(deep), deep);
        assert_eq!(
            deep.stronger(bound(1015.0, V_MAX_MARGIN)),
            bound(1015.0, V_MAX_MARGIN)
        );
        assert_eq!(deep.stronger(Eval::Unknown), deep);
        assert_eq!(deep.stronger(Eval::Value(g(5000.0))), deep);
    }
}
