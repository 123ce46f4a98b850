//! One module per subcommand; each turns parsed arguments into a [`crate::output::Report`].

pub mod collide;
pub mod crack_law;
pub mod fit_t_vis;
pub mod jkr;
pub mod material;
pub mod sweep;
pub mod v_frag;
pub mod v_stick;

use crate::args::Setup;
use crate::output::Report;
use numerics::format::number;

/// Adds `v_stick` and `no_bouncing_below` (JSON only) for a search up to `v_max` (m/s).
pub fn v_stick_rows(
    r: &mut Report,
    key: &str,
    value: Option<f64>,
    v_max: f64,
) -> Result<(), crate::error::CliError> {
    r.optional(
        key,
        value,
        "m/s",
        format!("no bouncing up to {} m/s", number(v_max)),
    )
}

/// Adds `no_bouncing_below` to the JSON form: the search limit where nothing bounced, else null.
pub fn no_bouncing_below(r: &mut Report, v_stick: Option<f64>, v_max: f64) {
    let value = match v_stick {
        Some(_) => serde_json::Value::Null,
        None => serde_json::Value::from(v_max),
    };
    r.json_only("no_bouncing_below", value);
}

/// A report titled `"{what}, T_vis = .. s, k = .."`, with the contact's warnings.
pub fn point_report(what: String, setup: &Setup, t_vis: f64, k: f64) -> Report {
    let mut r = Report::new(format!(
        "{what}, T_vis = {} s, k = {}",
        number(t_vis),
        number(k)
    ));
    r.warn(setup.warnings());
    r
}
