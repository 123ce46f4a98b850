//! Figure 7: V_stick of monomers and V_frag = 10 V_stick of their aggregates against the
//! monomer radius, for both size laws and JKR (Sections 5.4, 6).

use super::chart::*;
use super::{figure_table, geomspace, par_map, K};
use super::{Error, Progress, Resolution};
use crate::table::Table;
use contact::{Contact, Geometry, Material};
use greenwood::CrackLaw;
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;
use thresholds::paper::{CO2_DENSITY_SECTION_5_4, V_COL_MAX};
use thresholds::{sticking_thresholds, v_frag, SearchOptions, StickingThresholds, TVisLaw};

/// One monomer radius of Figure 7.
#[derive(Debug, Clone, Copy)]
pub struct SizePoint {
    /// Monomer radius R1 (m).
    pub r1: f64,
    /// Thresholds with T_vis = T_vis,CO2(R1).
    pub co2: StickingThresholds,
    /// Thresholds with T_vis = T_vis,H2O(R1).
    pub h2o: StickingThresholds,
}

/// Figure 7: V_stick and V_frag against R1 for T_vis,CO2(R1), T_vis,H2O(R1) and JKR; CO2 ice with
/// rho = 1650 kg/m^3 as in Section 5.4.
#[derive(Debug, Clone)]
pub struct Figure7 {
    /// The material (CO2 with the density of Section 5.4).
    pub material: Material,
    /// One point per radius, in increasing R1.
    pub points: Vec<SizePoint>,
}

impl Figure7 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let material = Material {
            density: CO2_DENSITY_SECTION_5_4,
            ..Material::co2()
        };
        let r1s = geomspace(1e-7, 1e-4, res.pick(25, 3));
        let jobs: Vec<(f64, TVisLaw)> = r1s
            .iter()
            .flat_map(|&r| [TVisLaw::Co2, TVisLaw::H2o].map(|l| (r, l)))
            .collect();
        let ths = par_map("fig7", &jobs, progress, |&(r1, l)| {
            let c = Contact::new(material, Geometry::identical(r1))?;
            Ok(sticking_thresholds(
                &c,
                &law,
                l.t_vis(r1),
                &SearchOptions::exact(),
            )?)
        })?;
        let points = r1s
            .iter()
            .zip(ths.chunks(2))
            .map(|(&r1, pair)| SizePoint {
                r1,
                co2: pair[0],
                h2o: pair[1],
            })
            .collect();
        Ok(Self { material, points })
    }

    /// `fig7.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let (v_lo, v_hi) = (number(V_COL_MAX.0), number(V_COL_MAX.1));
        let mut t = figure_table(
            "fig7.csv",
            "Figure 7: V_stick of monomers and V_frag = 10 V_stick of aggregates against the monomer radius (Sections 5.4, 6)",
            ("co2 (Section 5.4 density)", &self.material),
            &[
                format!("k = {}; t_vis_co2 = 1e-11 s (R1/1 um)^1.11, t_vis_h2o = 1e-10 s (R1/1.5 um)^1.11", number(K)),
                format!("maximum collision velocities in weakly turbulent disks: {v_lo} - {v_hi} m/s"),
                "units: r1 [m], t_vis_* [s], v_* [m/s]".into(),
            ],
            &[
                "r1", "t_vis_co2", "v_stick_co2", "v_frag_co2", "t_vis_h2o", "v_stick_h2o", "v_frag_h2o",
                "v_stick_jkr", "v_frag_jkr",
            ],
        );
        for p in &self.points {
            let (co2, h2o) = (&p.co2, &p.h2o);
            t.push(vec![
                p.r1.into(),
                co2.t_vis.into(),
                co2.v_stick.into(),
                co2.v_stick.map(v_frag).into(),
                h2o.t_vis.into(),
                h2o.v_stick.into(),
                h2o.v_stick.map(v_frag).into(),
                co2.v_stick_jkr.into(),
                v_frag(co2.v_stick_jkr).into(),
            ]);
        }
        vec![t]
    }
}

impl Figure7 {
    /// `fig7.svg`: V_stick and V_frag against the monomer radius.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = picture(path, SIZE_TWO)?;
        let (left, right) = two_panels(&root);
        type Pick = fn(&crate::figures::SizePoint) -> Option<f64>;
        let series: [(&str, RGBColor, Pick); 3] = [
            ("T_vis = T_vis,CO2 (standard)", COLOURS[0], |p| {
                p.co2.v_stick
            }),
            ("T_vis = T_vis,H2O", COLOURS[1], |p| p.h2o.v_stick),
            ("JKR (T_vis = 0)", GREY, |p| Some(p.co2.v_stick_jkr)),
        ];
        for (area, factor, what, ylab) in [
            (
                &left,
                1.0,
                "V_stick",
                "threshold velocity for sticking V_stick (m/s)",
            ),
            (
                &right,
                thresholds::V_FRAG_FACTOR,
                "V_frag",
                "fragmentation velocity V_frag = 10 V_stick (m/s)",
            ),
        ] {
            let mut values: Vec<f64> = self
                .points
                .iter()
                .flat_map(|p| series.iter().filter_map(|s| (s.2)(p)))
                .map(|v| v * factor)
                .collect();
            if what == "V_frag" {
                values.extend([V_COL_MAX.0, V_COL_MAX.1]);
            }
            let y = log_range(values.into_iter());
            let mut chart = log_log(
                area,
                &format!("Figure 7: CO2 monomers, {what}"),
                (0.1, 100.0),
                y,
                "monomer radius R1 (um)",
                ylab,
            )?;
            if what == "V_frag" {
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(0.1, V_COL_MAX.0), (100.0, V_COL_MAX.1)],
                        COLOURS[0].mix(0.15).filled(),
                    )))?
                    .label(format!(
                        "maximum collision velocity {} - {} m/s",
                        number(V_COL_MAX.0),
                        number(V_COL_MAX.1)
                    ))
                    .legend(|(x, y)| {
                        Rectangle::new([(x, y - 5), (x + 20, y + 5)], COLOURS[0].mix(0.3).filled())
                    });
            }
            for (label, c, pick) in series {
                let pts: Vec<_> = self
                    .points
                    .iter()
                    .filter_map(|p| Some((p.r1 * 1e6, pick(p)? * factor)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(pts, c.stroke_width(2)))?
                    .label(label)
                    .legend(legend_line(c));
            }
            legend(&mut chart, SeriesLabelPosition::UpperRight)?;
        }
        root.present()?;
        Ok(())
    }
}
