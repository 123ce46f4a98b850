//! Figure 3: the coefficient of restitution against the impact speed, observed (0 for sticking
//! and double collisions) and computed, for CO2 grains of 60 um at T_vis = 1e-9 s (Section 4.4).

use super::chart::*;
use super::{co2_contact, figure_table, linspace, par_map, FIG2_T_VIS, K};
use super::{Error, Progress, Resolution};
use crate::table::Table;
use contact::Material;
use dynamics::{Collider, Outcome};
use greenwood::CrackLaw;
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;
use thresholds::paper::MUSIOLIK_2016A;
use thresholds::{sticking_thresholds, SearchOptions, StickingThresholds};

/// One collision of Figure 3.
#[derive(Debug, Clone, Copy)]
pub struct Restitution {
    /// Impact speed (m/s).
    pub v_in: f64,
    /// Its outcome.
    pub outcome: Outcome,
    /// `-V_out/V_in` of the first contact (negative for double collisions, 0 for sticking).
    pub e_computed: f64,
}

impl Restitution {
    /// The e an experiment observes ([`Outcome::observed_e`]): `e_computed` for bouncing, 0 for
    /// sticking and double collisions (the second contact sticks, Section 4.4).
    pub fn e_observed(&self) -> f64 {
        self.outcome.observed_e(self.e_computed)
    }
}

/// Figure 3: coefficient of restitution against V_in for CO2, R1 = 60 um, T_vis = 1e-9 s.
#[derive(Debug, Clone)]
pub struct Figure3 {
    /// The thresholds at T_vis = 1e-9 s (m/s).
    pub thresholds: StickingThresholds,
    /// Collisions in order of V_in.
    pub points: Vec<Restitution>,
}

impl Figure3 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let c = co2_contact(MUSIOLIK_2016A.radius)?;
        let th = sticking_thresholds(&c, &law, FIG2_T_VIS, &SearchOptions::exact())?;
        let (vd, vs) = (
            th.v_double_onset.ok_or("no double collisions")?,
            th.v_stick.ok_or("no bouncing")?,
        );
        let mut v_in = linspace(0.02, 0.1, res.pick(161, 6));
        // resolve the narrow double-collision window
        v_in.extend(linspace(vd, vs, res.pick(42, 4)).into_iter().skip(1));
        v_in.retain(|v| (v - vd).abs() > 1e-9 * vd);
        v_in.sort_by(f64::total_cmp);
        let collider = Collider::new(c, law, FIG2_T_VIS)?;
        let points = par_map("fig3", &v_in, progress, |&v| {
            let r = collider.collide(v)?;
            Ok(Restitution {
                v_in: v,
                outcome: r.outcome,
                e_computed: r.e,
            })
        })?;
        Ok(Self {
            thresholds: th,
            points,
        })
    }

    /// The double-collision onset and V_stick (m/s).
    pub fn transitions(&self) -> (f64, f64) {
        let th = &self.thresholds;
        (
            th.v_double_onset.unwrap_or(f64::NAN),
            th.v_stick.unwrap_or(f64::NAN),
        )
    }

    /// `fig3.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let (vd, vs) = self.transitions();
        let (r, t_vis, k) = (number(MUSIOLIK_2016A.radius), number(FIG2_T_VIS), number(K));
        let mut t = figure_table(
            "fig3.csv",
            "Figure 3: coefficient of restitution e against the impact speed V_in (Section 4.4)",
            ("co2", &Material::co2()),
            &[
                format!("radius = {r} m, t_vis = {t_vis} s, k = {k}"),
                format!("v_double_onset = {} m/s, v_stick = {} m/s", number(vd), number(vs)),
                "e: observed value (0 for sticking and double collisions); e_computed: -V_out/V_in of the first contact".into(),
                "units: v_in [m/s], e and e_computed dimensionless".into(),
            ],
            &["v_in", "outcome", "e", "e_computed"],
        );
        for p in &self.points {
            t.push(vec![
                p.v_in.into(),
                p.outcome.as_str().into(),
                p.e_observed().into(),
                p.e_computed.into(),
            ]);
        }
        vec![t]
    }
}

impl Figure3 {
    /// `fig3.svg`: e against V_in, observed and computed.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = picture(path, SIZE_ONE)?;
        let (_, vs) = self.transitions();
        let mut chart = linear(
            &root,
            "Figure 3: CO2, R1 = 60 um, T_vis = 1e-9 s",
            2.0..10.0,
            -0.3..1.0,
            "impact speed V_in (cm/s)",
            "coefficient of restitution e",
        )?;
        for o in [
            Outcome::Sticking,
            Outcome::DoubleCollision,
            Outcome::Bouncing,
        ] {
            let c = outcome_colour(o);
            let pts: Vec<_> = self
                .points
                .iter()
                .filter(|p| p.outcome == o)
                .map(|p| (100.0 * p.v_in, p.e_observed()))
                .collect();
            chart
                .draw_series(LineSeries::new(pts, c.stroke_width(2)))?
                .label(format!("{} (observed e)", o.as_str()))
                .legend(legend_line(c));
        }
        let computed = self
            .points
            .iter()
            .filter(|p| p.outcome == Outcome::DoubleCollision)
            .map(|p| Circle::new((100.0 * p.v_in, p.e_computed), 2, COLOURS[0].filled()));
        chart
            .draw_series(computed)?
            .label("double: computed e = -V_out/V_in")
            .legend(|(x, y)| Circle::new((x + 10, y), 3, COLOURS[0].filled()));
        chart
            .draw_series(std::iter::once(Circle::new(
                (100.0 * vs, 0.0),
                6,
                GREY.filled(),
            )))?
            .label(format!("V_stick = {:.3} cm/s", 100.0 * vs))
            .legend(|(x, y)| Circle::new((x + 10, y), 5, GREY.filled()));
        legend(&mut chart, SeriesLabelPosition::LowerRight)?;
        root.present()?;
        Ok(())
    }
}
