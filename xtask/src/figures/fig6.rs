//! Figure 6: relaxation times fitted to the measured V_stick against the grain radius, the
//! value of Gundlach et al. (2015) and the size laws (Sections 5.1-5.3).

use super::chart::*;
use super::{co2_contact, geomspace, h2o_with, par_map, GAMMAS_H2O, K};
use super::{Error, Progress, Resolution};
use crate::table::Table;
use contact::{Contact, Geometry};
use greenwood::CrackLaw;
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;
use thresholds::paper::{GUNDLACH_2015_T_VIS, MUSIOLIK_2016A, MUSIOLIK_2016B};
use thresholds::{fit_t_vis, SearchOptions, TVisLaw};

/// A relaxation time fitted to a measured V_stick, with its range.
#[derive(Debug, Clone, Copy)]
pub struct FittedTVis {
    /// `co2`, `h2o` or `gundlach2015`.
    pub source: &'static str,
    /// Grain radius R1 (m).
    pub r1: f64,
    /// Central T_vis (s).
    pub t_vis: f64,
    /// Lower end of the range (s).
    pub t_vis_min: f64,
    /// Upper end of the range (s).
    pub t_vis_max: f64,
}

/// Figure 6: fitted T_vis ranges against R1, the point of Gundlach et al. (2015), both size laws.
#[derive(Debug, Clone)]
pub struct Figure6 {
    /// The fitted points.
    pub fits: Vec<FittedTVis>,
    /// `(R1 (m), T_vis,CO2 (s), T_vis,H2O (s))` along the size laws.
    pub laws: Vec<(f64, f64, f64)>,
}

impl Figure6 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let opts = SearchOptions::exact();
        let fits = par_map("fig6", &["co2", "h2o"], progress, |&name| {
            if name == "co2" {
                let e = MUSIOLIK_2016A;
                let f = fit_t_vis(
                    &co2_contact(e.radius)?,
                    &law,
                    e.v_stick,
                    e.v_stick_err,
                    &opts,
                )?;
                Ok(FittedTVis {
                    source: "co2",
                    r1: e.radius,
                    t_vis: f.t_vis,
                    t_vis_min: f.t_vis_min,
                    t_vis_max: f.t_vis_max,
                })
            } else {
                // 0.73 m/s with 0.02 <= gamma_sv <= 0.19 J/m^2; central value at 0.1 J/m^2
                let e = MUSIOLIK_2016B;
                let fit = |g: f64| -> Result<f64, Error> {
                    let c = Contact::new(h2o_with(g), Geometry::identical(e.radius))?;
                    Ok(fit_t_vis(&c, &law, e.v_stick, e.v_stick_err, &opts)?.t_vis)
                };
                Ok(FittedTVis {
                    source: "h2o",
                    r1: e.radius,
                    t_vis: fit(0.1)?,
                    t_vis_min: fit(GAMMAS_H2O[3])?,
                    t_vis_max: fit(GAMMAS_H2O[0])?,
                })
            }
        })?;
        let (r_g, t_g) = GUNDLACH_2015_T_VIS;
        let mut fits = fits;
        fits.push(FittedTVis {
            source: "gundlach2015",
            r1: r_g,
            t_vis: t_g,
            t_vis_min: t_g,
            t_vis_max: t_g,
        });
        let laws = geomspace(1e-7, 1e-3, res.pick(41, 3))
            .into_iter()
            .map(|r1| (r1, TVisLaw::Co2.t_vis(r1), TVisLaw::H2o.t_vis(r1)))
            .collect();
        Ok(Self { fits, laws })
    }

    /// `fig6_points.csv` and `fig6_laws.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let (c, h) = (MUSIOLIK_2016A, MUSIOLIK_2016B);
        let mut points = Table::new(
            "fig6_points.csv",
            vec![
                "Figure 6: relaxation times fitted to measured V_stick (Sections 5.1-5.3)".into(),
                format!(
                    "co2: R1 = {} m, V_stick = {} +- {} m/s (Musiolik et al. 2016a)",
                    number(c.radius),
                    number(c.v_stick),
                    number(c.v_stick_err)
                ),
                format!(
                    "h2o: R1 = {} m, V_stick = {} m/s, gamma_sv from {} (t_vis_min) to {} J/m^2 (t_vis_max), 0.1 J/m^2 (t_vis)",
                    number(h.radius),
                    number(h.v_stick),
                    number(GAMMAS_H2O[3]),
                    number(GAMMAS_H2O[0])
                ),
                format!(
                    "gundlach2015: R1 = {} m, T_vis = {} s (Gundlach et al. 2015)",
                    number(GUNDLACH_2015_T_VIS.0),
                    number(GUNDLACH_2015_T_VIS.1)
                ),
                "units: r1 [m], t_vis, t_vis_min, t_vis_max [s]".into(),
            ],
            &["source", "r1", "t_vis", "t_vis_min", "t_vis_max"],
        );
        for f in &self.fits {
            points.push(vec![
                f.source.into(),
                f.r1.into(),
                f.t_vis.into(),
                f.t_vis_min.into(),
                f.t_vis_max.into(),
            ]);
        }
        let mut laws = Table::new(
            "fig6_laws.csv",
            vec![
                "Figure 6: size laws T_vis,CO2 = 1e-11 s (R1/1 um)^1.11 and T_vis,H2O = 1e-10 s (R1/1.5 um)^1.11 (Section 5.3)".into(),
                "units: r1 [m], t_vis_co2, t_vis_h2o [s]".into(),
            ],
            &["r1", "t_vis_co2", "t_vis_h2o"],
        );
        for &(r1, co2, h2o) in &self.laws {
            laws.push(vec![r1.into(), co2.into(), h2o.into()]);
        }
        vec![points, laws]
    }
}

impl Figure6 {
    /// `fig6.svg`: fitted T_vis with their ranges, and the size laws.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = picture(path, SIZE_ONE)?;
        let y = log_range(
            self.laws
                .iter()
                .flat_map(|l| [l.1, l.2])
                .chain(self.fits.iter().flat_map(|f| [f.t_vis_min, f.t_vis_max])),
        );
        let mut chart = log_log(
            &root,
            "Figure 6: relaxation time against particle radius",
            (0.1, 1000.0),
            y,
            "particle radius R1 (um)",
            "relaxation time T_vis (s)",
        )?;
        for (name, c, pick) in [("CO2 law", COLOURS[0], 0usize), ("H2O law", COLOURS[1], 1)] {
            let pts: Vec<_> = self
                .laws
                .iter()
                .map(|l| (l.0 * 1e6, if pick == 0 { l.1 } else { l.2 }))
                .collect();
            chart
                .draw_series(LineSeries::new(pts, c.stroke_width(1)))?
                .label(format!("{name} (T_vis ∝ R1^1.11)"))
                .legend(legend_line(c));
        }
        for f in &self.fits {
            let x = f.r1 * 1e6;
            let (c, label) = match f.source {
                "co2" => (COLOURS[0], "CO2 fit (this work)"),
                "h2o" => (COLOURS[1], "H2O fit (this work)"),
                _ => (COLOURS[1], "Gundlach et al. 2015"),
            };
            if f.source == "gundlach2015" {
                chart
                    .draw_series(star!(x, f.t_vis, c))?
                    .label(label)
                    .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 6, c.filled()));
            } else {
                chart
                    .draw_series(std::iter::once(ErrorBar::new_vertical(
                        x,
                        f.t_vis_min.max(y.0),
                        f.t_vis,
                        f.t_vis_max,
                        c.filled(),
                        10,
                    )))?
                    .label(label)
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
            }
        }
        legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
        root.present()?;
        Ok(())
    }
}
