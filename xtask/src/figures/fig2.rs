//! Figure 2: the trajectories of three collisions (sticking, double, bouncing) of CO2 grains of
//! 60 um at T_vis = 1e-9 s, in the delta-a and delta-delta_dot planes (Section 4).

use super::chart::*;
use super::{co2_contact, material_line, par_map, FIG2_T_VIS, FIG2_V_IN, K};
use super::{Error, Progress, Resolution};
use crate::table::Table;
use contact::Contact;
use dynamics::{Collider, Outcome, SolverOptions, TrajectoryPoint};
use greenwood::CrackLaw;
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;
use thresholds::paper::MUSIOLIK_2016A;

/// One trajectory of Figure 2.
#[derive(Debug, Clone)]
pub struct Trajectory {
    /// Impact speed (m/s).
    pub v_in: f64,
    /// Its outcome.
    pub outcome: Outcome,
    /// Resampled states (SI).
    pub points: Vec<TrajectoryPoint>,
}

/// Figure 2: trajectories for CO2, R1 = 60 um, T_vis = 1e-9 s at V_in = 3.5, 4.05, 4.5 cm/s.
#[derive(Debug, Clone)]
pub struct Figure2 {
    /// The contact (CO2, 60 um, identical spheres).
    pub contact: Contact,
    /// One run per V_in of [`FIG2_V_IN`].
    pub runs: Vec<Trajectory>,
}

impl Figure2 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let contact = co2_contact(MUSIOLIK_2016A.radius)?;
        let opts = SolverOptions {
            record_trajectory: true,
            // let the sticking trajectory spiral towards the JKR point before it is decided
            decide_after: 20e-6,
            ..Default::default()
        };
        let collider = Collider::new(contact, CrackLaw::new(K)?, FIG2_T_VIS)?.with_options(opts)?;
        let n = res.pick(400, 8);
        let runs = par_map("fig2", &FIG2_V_IN, progress, |&v_in| {
            let run = collider.collide(v_in)?;
            Ok(Trajectory {
                v_in,
                outcome: run.outcome,
                points: resample(&run.trajectory, &contact, n),
            })
        })?;
        Ok(Self { contact, runs })
    }

    /// `fig2.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let c = &self.contact;
        let mut t = Table::new(
            "fig2.csv",
            vec![
                "Figure 2: head-on collisions in the delta-a and delta-delta_dot planes (Section 4)"
                    .into(),
                material_line("co2", c.material()),
                format!(
                    "radius = {} m, t_vis = {} s, k = {}, eps = {}",
                    number(c.r1()),
                    number(FIG2_T_VIS),
                    number(K),
                    number(dynamics::EPS)
                ),
                format!(
                    "JKR equilibrium: a_eq = {} m, delta_eq = {} m, delta_dot = 0",
                    number(c.a_eq()),
                    number(c.delta_eq())
                ),
                format!(
                    "{} points a trajectory at equal steps of its path length in (a/a_eq, delta/delta_eq, delta_dot/V_stick,JKR)",
                    self.runs.first().map_or(0, |r| r.points.len())
                ),
                "units: v_in [m/s], t [s], a [m], delta [m], delta_dot [m/s]".into(),
            ],
            &["v_in", "outcome", "t", "a", "delta", "delta_dot"],
        );
        for run in &self.runs {
            for p in &run.points {
                t.push(vec![
                    run.v_in.into(),
                    run.outcome.as_str().into(),
                    p.t.into(),
                    p.a.into(),
                    p.delta.into(),
                    p.delta_dot.into(),
                ]);
            }
        }
        vec![t]
    }
}

/// `n` points at equal steps of the path length of a trajectory in the plane of
/// `(a/a_eq, delta/delta_eq, delta_dot/V_stick,JKR)`, linearly interpolated between solver steps:
/// the output does not depend on where the solver put its steps.
fn resample(traj: &[TrajectoryPoint], c: &Contact, n: usize) -> Vec<TrajectoryPoint> {
    let (sa, sd, sv) = (c.a_eq(), c.delta_eq(), c.v_stick_jkr());
    let mut length = vec![0.0];
    for w in traj.windows(2) {
        let d = ((w[1].a - w[0].a) / sa)
            .hypot((w[1].delta - w[0].delta) / sd)
            .hypot((w[1].delta_dot - w[0].delta_dot) / sv);
        length.push(length.last().copied().unwrap_or(0.0) + d);
    }
    let total = length.last().copied().unwrap_or(0.0);
    let mut out = Vec::with_capacity(n);
    let mut j = 0;
    for i in 0..n {
        let s = total * i as f64 / (n - 1).max(1) as f64;
        while j + 2 < length.len() && length[j + 1] < s {
            j += 1;
        }
        let (p, q) = (traj[j], traj[(j + 1).min(traj.len() - 1)]);
        let span = length[(j + 1).min(length.len() - 1)] - length[j];
        let f = if span > 0.0 {
            ((s - length[j]) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let mix = |x: f64, y: f64| x + f * (y - x);
        out.push(TrajectoryPoint {
            t: mix(p.t, q.t),
            a: mix(p.a, q.a),
            delta: mix(p.delta, q.delta),
            delta_dot: mix(p.delta_dot, q.delta_dot),
            energy: mix(p.energy, q.energy),
            beta: mix(p.beta, q.beta),
        });
    }
    out
}

impl Figure2 {
    /// `fig2.svg`: the trajectories in the delta-a and delta-delta_dot planes.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = picture(path, SIZE_TWO)?;
        let (left, right) = two_panels(&root);
        let points = || self.runs.iter().flat_map(|r| r.points.iter());
        // plotted in nm, um and cm/s
        let (d0, d1) = span(points().map(|p| p.delta * 1e9));
        let (_, a1) = span(points().map(|p| p.a * 1e6));
        let (v0, v1) = span(points().map(|p| p.delta_dot * 100.0));
        let mut da = linear(
            &left,
            "Figure 2: delta-a plane (star: JKR equilibrium)",
            d0..d1,
            0.0..a1,
            "mutual approach delta (nm)",
            "contact radius a (um)",
        )?;
        let mut dv = linear(
            &right,
            "delta-delta_dot plane",
            d0..d1,
            v0..v1,
            "mutual approach delta (nm)",
            "approach speed delta_dot (cm/s)",
        )?;
        for run in &self.runs {
            let c = outcome_colour(run.outcome);
            let label = format!(
                "V_in = {} cm/s ({})",
                number(run.v_in * 100.0),
                run.outcome.as_str()
            );
            let xy = |f: &dyn Fn(&dynamics::TrajectoryPoint) -> f64| -> Vec<(f64, f64)> {
                run.points.iter().map(|p| (p.delta * 1e9, f(p))).collect()
            };
            da.draw_series(LineSeries::new(xy(&|p| p.a * 1e6), c.stroke_width(2)))?
                .label(label.clone())
                .legend(legend_line(c));
            dv.draw_series(LineSeries::new(
                xy(&|p| p.delta_dot * 100.0),
                c.stroke_width(2),
            ))?
            .label(label)
            .legend(legend_line(c));
        }
        let (a_eq, d_eq) = (self.contact.a_eq(), self.contact.delta_eq());
        da.draw_series(star!(d_eq * 1e9, a_eq * 1e6, COLOURS[2]))?;
        dv.draw_series(star!(d_eq * 1e9, 0.0, COLOURS[2]))?;
        legend(&mut da, SeriesLabelPosition::LowerRight)?;
        legend(&mut dv, SeriesLabelPosition::LowerRight)?;
        root.present()?;
        Ok(())
    }
}
