//! Figure 4: V_stick against T_vis for several k, CO2 grains of 60 um, with the experiment of
//! Musiolik et al. (2016a) (Section 5.1).

use super::curves::{curves_table, labelled, v_stick_chart, ThresholdCurve};
use super::{co2_contact, figure_comments, geomspace, par_map, Error, Progress, Resolution, KS};
use crate::table::Table;
use contact::Material;
use greenwood::CrackLaw;
use numerics::format::number;
use std::path::Path;
use thresholds::paper::MUSIOLIK_2016A;
use thresholds::{sweep_t_vis, SearchOptions};

/// Figure 4: V_stick against T_vis for several k, CO2, R1 = 60 um.
#[derive(Debug, Clone)]
pub struct Figure4 {
    /// One curve per k of [`KS`].
    pub curves: Vec<ThresholdCurve>,
}

impl Figure4 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let c = co2_contact(MUSIOLIK_2016A.radius)?;
        let t_vis = geomspace(1e-12, 1e-8, res.pick(33, 3));
        // one sweep over T_vis per k (each search seeded by its neighbour), the k in parallel
        let curves = par_map("fig4", &KS, progress, |&k| {
            Ok(ThresholdCurve {
                parameter: k,
                v_stick_jkr: c.v_stick_jkr(),
                points: sweep_t_vis(&c, &CrackLaw::new(k)?, &t_vis, &SearchOptions::exact())?,
            })
        })?;
        Ok(Self { curves })
    }

    /// `fig4.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let e = MUSIOLIK_2016A;
        let (r, v, dv) = (number(e.radius), number(e.v_stick), number(e.v_stick_err));
        let comments = figure_comments(
            "Figure 4: threshold velocity for sticking V_stick against T_vis for several k (Section 5.1)",
            ("co2", &Material::co2()),
            &[format!("radius = {r} m; experiment (Musiolik et al. 2016a): V_stick = {v} +- {dv} m/s")],
        );
        let curves = self.curves.iter().map(|c| (c.parameter.into(), c));
        let parameter = ("k", Some("k dimensionless"));
        vec![curves_table("fig4.csv", comments, parameter, curves, false)]
    }
}

impl Figure4 {
    /// `fig4.svg`: V_stick against T_vis for each k, with the CO2 experiment.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let e = MUSIOLIK_2016A;
        let caption = "Figure 4: CO2, R1 = 60 um";
        v_stick_chart(path, caption, &labelled(&self.curves, "k", ""), &e)
    }
}
