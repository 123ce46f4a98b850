//! The sphere-on-wall figure: V_stick against T_vis for CO2 grains of 60 um, two identical
//! spheres against a sphere on a CO2 wall (the laboratory geometry of Musiolik et al. 2016a).

use super::curves::{curves_table, v_stick_chart, ThresholdCurve};
use super::{figure_comments, geomspace, par_map, Error, Progress, Resolution, K};
use crate::table::{Cell, Table};
use contact::{Contact, Geometry, Material};
use greenwood::CrackLaw;
use numerics::format::number;
use std::path::Path;
use thresholds::paper::MUSIOLIK_2016A;
use thresholds::{fit_t_vis, sweep_t_vis, SearchOptions, TVisFit};

/// The sphere-on-wall figure: V_stick against T_vis for CO2 grains of 60 um, two identical
/// spheres against a sphere on a CO2 wall (the laboratory geometry of Musiolik et al. 2016a),
/// with the relaxation times each geometry needs for 0.04 ± 0.02 m/s.
#[derive(Debug, Clone)]
pub struct FigureWall {
    /// Identical spheres (parameter 0) and the wall (parameter 1).
    pub curves: Vec<ThresholdCurve>,
    /// The T_vis fit to the experiment in each geometry, in the order of `curves`.
    pub fits: Vec<TVisFit>,
}

/// The geometry names of [`FigureWall`], in the order of its curves.
pub const WALL_GEOMETRIES: [&str; 2] = ["identical", "wall"];

impl FigureWall {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let e = MUSIOLIK_2016A;
        let t_vis = geomspace(1e-12, 1e-8, res.pick(33, 3));
        let geometries = [Geometry::identical(e.radius), Geometry::wall(e.radius)];
        let out = par_map("fig_wall", &[0usize, 1], progress, |&i| {
            let c = Contact::new(Material::co2(), geometries[i])?;
            let opts = SearchOptions::exact();
            let curve = ThresholdCurve {
                parameter: i as f64,
                v_stick_jkr: c.v_stick_jkr(),
                points: sweep_t_vis(&c, &law, &t_vis, &opts)?,
            };
            Ok((curve, fit_t_vis(&c, &law, e.v_stick, e.v_stick_err, &opts)?))
        })?;
        let (curves, fits) = out.into_iter().unzip();
        Ok(Self { curves, fits })
    }

    /// `fig_wall.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let e = MUSIOLIK_2016A;
        let mut notes = vec![format!(
            "radius = {} m, k = {}; identical: R = R1/2, m* = m1/2; wall: R = R1, m* = m1",
            number(e.radius),
            number(K)
        )];
        for (name, f) in WALL_GEOMETRIES.iter().zip(&self.fits) {
            notes.push(format!(
                "{name}: T_vis for V_stick = {} +- {} m/s (Musiolik et al. 2016a): {} s ({} .. {} s)",
                number(e.v_stick),
                number(e.v_stick_err),
                number(f.t_vis),
                number(f.t_vis_min),
                number(f.t_vis_max)
            ));
        }
        let comments = figure_comments(
            "Sphere on a wall: V_stick against T_vis, two identical spheres against a sphere on a flat wall of the same material",
            ("co2", &Material::co2()),
            &notes,
        );
        let curves = WALL_GEOMETRIES
            .iter()
            .map(|n| Cell::from(*n))
            .zip(&self.curves);
        let parameter = ("geometry", None);
        vec![curves_table(
            "fig_wall.csv",
            comments,
            parameter,
            curves,
            false,
        )]
    }
}

impl FigureWall {
    /// `fig_wall.svg`: V_stick against T_vis for identical spheres and a sphere on a wall.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let e = MUSIOLIK_2016A;
        let curves: Vec<_> = WALL_GEOMETRIES
            .iter()
            .zip(&self.curves)
            .map(|(name, c)| {
                let label = if *name == "wall" {
                    "a 60 um sphere on a wall"
                } else {
                    "two identical spheres of 60 um"
                };
                (label.to_string(), c)
            })
            .collect();
        let caption = "Sphere on a wall: CO2, R1 = 60 um, k = 0.01";
        v_stick_chart(path, caption, &curves, &e)
    }
}
