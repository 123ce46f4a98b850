//! [`OutOfRange`], the one "bad input" error of the workspace.
//!
//! Every crate wraps [`OutOfRange`] with `#[from]` instead of defining its own, so
//! a bad argument reads the same wherever it is caught: `radius = nan: must be > 0 and finite (m)`.

use crate::format::number;
use std::borrow::Cow;

/// An input outside its allowed range: which one, its value, the range and the SI unit.
///
/// The [`std::fmt::Display`] form is `field = value: must be allowed (unit)`, with the value in the
/// workspace's one number format ([`crate::format::number`]); [`OutOfRange::message_for`] gives the
/// same sentence under another name (a CLI flag, a Python argument with its index).
#[derive(Debug, Clone, PartialEq)]
pub struct OutOfRange {
    /// Name of the input, as in the library (`radius`, `t_vis`, `k`, ...).
    pub field: &'static str,
    /// The rejected value.
    pub value: f64,
    /// The allowed range, human readable (`> 0 and finite`, `0 < k < 1`).
    pub allowed: Cow<'static, str>,
    /// SI unit of the input (`m`, `s`, `m/s`, `dimensionless`).
    pub unit: &'static str,
}

impl OutOfRange {
    /// An [`OutOfRange`] for `field` = `value`, allowed range `allowed`, SI `unit`.
    pub fn new(
        field: &'static str,
        value: f64,
        allowed: impl Into<Cow<'static, str>>,
        unit: &'static str,
    ) -> Self {
        Self {
            field,
            value,
            allowed: allowed.into(),
            unit,
        }
    }

    /// The message under another name: `name = value: must be allowed (unit)`.
    ///
    /// ```
    /// use numerics::OutOfRange;
    /// let e = OutOfRange::new("radius", f64::NAN, "> 0 and finite", "m");
    /// assert_eq!(e.to_string(), "radius = nan: must be > 0 and finite (m)");
    /// assert_eq!(e.message_for("--radius"), "--radius = nan: must be > 0 and finite (m)");
    /// ```
    pub fn message_for(&self, name: &str) -> String {
        format!(
            "{name} = {}: must be {} ({})",
            number(self.value),
            self.allowed,
            self.unit
        )
    }
}

impl std::fmt::Display for OutOfRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message_for(self.field))
    }
}

impl std::error::Error for OutOfRange {}

/// `Ok` when `value` is finite and > 0, else an [`OutOfRange`] naming `field` (SI `unit`).
pub fn positive(field: &'static str, value: f64, unit: &'static str) -> Result<(), OutOfRange> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(OutOfRange::new(field, value, "> 0 and finite", unit))
    }
}
