//! Figure 5: V_stick against T_vis for H2O grains of 90 um and several gamma_SV, with the
//! experiment of Musiolik et al. (2016b) (Section 5.2).

use super::curves::{curves_table, labelled, v_stick_chart, ThresholdCurve};
use super::{
    figure_comments, geomspace, h2o_with, par_map, Error, Progress, Resolution, GAMMAS_H2O, K,
};
use crate::table::Table;
use contact::{Contact, Geometry, Material};
use greenwood::CrackLaw;
use numerics::format::number;
use std::path::Path;
use thresholds::paper::MUSIOLIK_2016B;
use thresholds::{sweep_t_vis, SearchOptions};

/// Figure 5: V_stick against T_vis for H2O, R1 = 90 um, several gamma_SV.
#[derive(Debug, Clone)]
pub struct Figure5 {
    /// One curve per gamma_SV of [`GAMMAS_H2O`].
    pub curves: Vec<ThresholdCurve>,
}

impl Figure5 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let t_vis = geomspace(1e-12, 1e-7, res.pick(41, 3));
        // one sweep over T_vis per gamma_SV (each search seeded by its neighbour), in parallel
        let curves = par_map("fig5", &GAMMAS_H2O, progress, |&g| {
            let c = Contact::new(h2o_with(g), Geometry::identical(MUSIOLIK_2016B.radius))?;
            Ok(ThresholdCurve {
                parameter: g,
                v_stick_jkr: c.v_stick_jkr(),
                points: sweep_t_vis(&c, &law, &t_vis, &SearchOptions::exact())?,
            })
        })?;
        Ok(Self { curves })
    }

    /// `fig5.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let e = MUSIOLIK_2016B;
        let (r, k, v) = (number(e.radius), number(K), number(e.v_stick));
        let comments = figure_comments(
            "Figure 5: V_stick against T_vis for H2O grains and several gamma_sv (Section 5.2)",
            ("h2o (gamma_sv varied)", &Material::h2o()),
            &[
                format!("radius = {r} m, k = {k}; experiment (Musiolik et al. 2016b): V_stick ~ {v} m/s"),
                "v_stick is empty where no collision bounces up to no_bouncing_below (the curve ends)".into(),
            ],
        );
        let curves = self.curves.iter().map(|c| (c.parameter.into(), c));
        let parameter = ("gamma_sv", Some("gamma_sv [J/m^2]"));
        vec![curves_table("fig5.csv", comments, parameter, curves, true)]
    }
}

impl Figure5 {
    /// `fig5.svg`: V_stick against T_vis for each gamma_SV, with the H2O experiment.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let caption = "Figure 5: H2O, R1 = 90 um (x: no bouncing beyond)";
        let curves = labelled(&self.curves, "gamma_SV", " J/m^2");
        v_stick_chart(path, caption, &curves, &MUSIOLIK_2016B)
    }
}
