//! The table's answer to a threshold search ([`crate::ThresholdMethod::Table`]).

use super::MasterTable;
use crate::{SearchOptions, StickingThresholds, ThresholdMethod};
use contact::Contact;
use greenwood::CrackLaw;

/// A table answer is given only where V_stick is clearly on one side of the search limit
/// `v_max`: within this relative distance of it the exact search decides.
const V_MAX_MARGIN: f64 = 1e-4;

/// The thresholds of `contact` at `t_vis` (s, > 0) from the master table of `law`'s k, or
/// `None` where there is no table for k or it does not vouch for the point (the caller then
/// searches). Where V_stick lies beyond the search limit `opts.v_max`, the answer is "no
/// bouncing below v_max", as the search would say.
pub(crate) fn from_table(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: f64,
    opts: &SearchOptions,
) -> Option<StickingThresholds> {
    let table = MasterTable::standard(law.k())?;
    let d = contact.dimensionless(t_vis);
    let r = table.ratios(d.c_d, d.c_a)?;
    let v_jkr = contact.v_stick_jkr();
    let v_max = opts.v_max_for(v_jkr);
    let (stick, onset) = (r.v_stick * v_jkr, r.v_double_onset * v_jkr);
    let beyond = |v: f64| v > v_max * (1.0 + V_MAX_MARGIN);
    let within = |v: f64| v < v_max * (1.0 - V_MAX_MARGIN);
    let (v_stick, v_double_onset) = match (within(stick), within(onset)) {
        (true, true) => (Some(stick), Some(onset)),
        (false, true) if beyond(stick) => (None, Some(onset)),
        (false, false) if beyond(onset) => (None, None),
        _ => return None,
    };
    Some(StickingThresholds {
        t_vis,
        v_stick,
        v_double_onset,
        v_stick_jkr: v_jkr,
        v_max,
        collisions: 0,
        steps: 0,
        method: ThresholdMethod::Table,
    })
}
