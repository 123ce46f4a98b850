//! The master figure: V_stick / V_stick,JKR over the two dimensionless numbers c_D (drag) and
//! c_D c_a (independent of T_vis), from the master tables at k = 0.01, with the cliff beyond
//! which nothing bounces (x_s, where F reaches 1e4, a hair short of it) and the paper's CO2
//! (60 um) and H2O (90 um) grains, which move along lines of constant c_D c_a as T_vis changes.

use super::chart::*;
use super::{co2_contact, h2o_with, linspace, par_map, Error, Progress, Resolution, K};
use crate::table::Table;
use contact::{Contact, Geometry};
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;
use thresholds::paper::{MUSIOLIK_2016A, MUSIOLIK_2016B};
use thresholds::{MasterTables, TVisLaw, DEFAULT_V_MAX_OVER_JKR};

/// The levels of F = V_stick / V_stick,JKR that separate the colour bands.
pub const LEVELS: [f64; 11] = [
    1.0003, 1.001, 1.01, 1.1, 1.5, 2.0, 5.0, 10.0, 30.0, 100.0, 300.0,
];

/// A paper's grain on the figure: a line of constant y, with marked relaxation times.
#[derive(Debug, Clone)]
pub struct Grain {
    /// What it is.
    pub label: String,
    /// y = log10(c_D c_a).
    pub y: f64,
    /// `(T_vis (s), x = log10 c_D, what)` of the marked relaxation times.
    pub marks: Vec<(f64, f64, String)>,
}

/// The master figure's data.
#[derive(Debug, Clone)]
pub struct FigureMaster {
    /// x = log10 c_D of the grid.
    pub x: Vec<f64>,
    /// y = log10(c_D c_a) of the grid.
    pub y: Vec<f64>,
    /// F at each (x, y), row by row in y (up to the default search limit, 1000); NaN where the
    /// tables do not vouch or nothing bounces below that limit.
    pub f: Vec<Vec<f64>>,
    /// `(y, x_s)` of the cliff: F reaches 1e4 at x_s, and nothing bounces below 1e4
    /// V_stick,JKR beyond it.
    pub cliff: Vec<(f64, f64)>,
    /// The paper's grains.
    pub grains: Vec<Grain>,
}

fn grain(label: &str, c: &Contact, marks: &[(f64, &str)]) -> Grain {
    let d = c.dimensionless(1.0);
    Grain {
        label: label.into(),
        y: (d.c_d * d.c_a).log10(),
        marks: marks
            .iter()
            .map(|&(t, what)| (t, (d.c_d * t).log10(), what.to_string()))
            .collect(),
    }
}

impl FigureMaster {
    /// Computes the figure from the committed table of k = 0.01.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let tables = MasterTables::standard();
        let ends = tables.ends().ok_or("the master tables are not embedded")?;
        let x = linspace(-17.0, 1.0, res.pick(361, 5));
        let y = linspace(-5.75, 5.0, res.pick(87, 4));
        let f = par_map("fig_master", &y, progress, |&y| {
            Ok(x.iter()
                .map(|&x| {
                    tables
                        .ratios_at(x, y, K, DEFAULT_V_MAX_OVER_JKR)
                        .and_then(|r| r.v_stick)
                        .unwrap_or(f64::NAN)
                })
                .collect())
        })?;
        let cliff = y
            .iter()
            .filter_map(|&y| ends.at(y, K).map(|e| (y, e.x_s)))
            .collect();
        let co2 = co2_contact(MUSIOLIK_2016A.radius)?;
        let h2o = Contact::new(h2o_with(0.1), Geometry::identical(MUSIOLIK_2016B.radius))?;
        let grains = vec![
            grain(
                "CO2, 60 um",
                &co2,
                &[
                    (8.5e-11, "the lower end of Section 5.1's fit"),
                    (1e-9, "Section 4"),
                    (1.97e-9, "the upper end of Section 5.1's fit"),
                ],
            ),
            grain(
                "H2O, 90 um, gamma_SV = 0.1 J/m^2",
                &h2o,
                // T_vis,H2O of Section 5.3, 9.4e-9 s, to three figures
                &[(
                    (TVisLaw::H2o.t_vis(MUSIOLIK_2016B.radius) * 1e11).round() / 1e11,
                    "T_vis,H2O of Section 5.3",
                )],
            ),
        ];
        Ok(Self {
            x,
            y,
            f,
            cliff,
            grains,
        })
    }

    /// `fig_master.csv` and `fig_master_cliff.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let mut grid = Table::new(
            "fig_master.csv",
            vec![
                "Master figure: F = V_stick/V_stick,JKR over x = log10 c_D and y = log10(c_D c_a), k = 0.01, from the master tables".into(),
                "c_D = 2 (T_vis/nu^2) E* a_eq t0/m*, c_a = E* gamma t0/(sigma0^2 T_vis a_eq): every material, size and geometry; empty where nothing bounces below 1000 V_stick,JKR (near and beyond the cliff) or the tables do not vouch".into(),
                "units: x, y, f dimensionless".into(),
            ],
            &["x", "y", "f"],
        );
        for (j, &y) in self.y.iter().enumerate() {
            for (i, &x) in self.x.iter().enumerate() {
                grid.push(vec![x.into(), y.into(), self.f[j][i].into()]);
            }
        }
        let mut cliff = Table::new(
            "fig_master_cliff.csv",
            vec![
                "Master figure: the cliff, x_s = log10 c_D where V_stick reaches 1e4 V_stick,JKR (nothing bounces below that beyond it), at each y of the figure (k = 0.01), from the tables' end curves".into(),
                "units: y, x dimensionless".into(),
            ],
            &["y", "x"],
        );
        for &(y, x) in &self.cliff {
            cliff.push(vec![y.into(), x.into()]);
        }
        vec![grid, cliff]
    }

    /// `fig_master.svg`: the bands of F, the cliff, the paper's grains.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = picture(path, SIZE_ONE)?;
        let (x0, x1) = (self.x[0], self.x[self.x.len() - 1]);
        let (y0, y1) = (self.y[0], self.y[self.y.len() - 1]);
        let mut chart = linear(
            &root,
            "V_stick / V_stick,JKR over the two dimensionless numbers (k = 0.01)",
            x0..x1,
            y0..y1,
            "log10 c_D (drag; grows with T_vis)",
            "log10 c_D c_a (independent of T_vis)",
        )?;
        let (dx, dy) = (self.x[1] - self.x[0], self.y[1] - self.y[0]);
        let band = |f: f64| LEVELS.iter().take_while(|&&l| f > l).count();
        let shade = |b: usize| {
            let t = b as f64 / LEVELS.len() as f64;
            RGBColor(
                (255.0 * (1.0 - 0.8 * t)) as u8,
                (245.0 * (1.0 - 0.55 * t)) as u8,
                (200.0 + 55.0 * t) as u8,
            )
        };
        let cells = self.y.iter().enumerate().flat_map(|(j, &y)| {
            self.x.iter().enumerate().filter_map(move |(i, &x)| {
                let f = self.f[j][i];
                f.is_finite().then_some((x, y, band(f)))
            })
        });
        chart.draw_series(cells.map(|(x, y, b)| {
            Rectangle::new(
                // a little wider than the cell, so that neighbours overlap without seams
                [(x - 0.6 * dx, y - 0.6 * dy), (x + 0.6 * dx, y + 0.6 * dy)],
                shade(b).filled(),
            )
        }))?;
        for (b, l) in LEVELS.iter().enumerate() {
            let c = shade(b + 1);
            chart
                .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
                .label(format!("F > {}", number(*l)))
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], c.filled()));
        }
        chart
            .draw_series(LineSeries::new(
                self.cliff.iter().map(|&(y, x)| (x, y)),
                BLACK.stroke_width(2),
            ))?
            .label("cliff x_s: V_stick = 1e4 V_stick,JKR, no bouncing beyond")
            .legend(legend_line(BLACK));
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
            .label("white: F > 1000 (the default limit), or the thin band at the cliff")
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], WHITE.filled()));
        for (g, col) in self.grains.iter().zip([COLOURS[0], COLOURS[1]]) {
            let times: Vec<String> = g.marks.iter().map(|m| number(m.0)).collect();
            chart
                .draw_series(LineSeries::new([(x0, g.y), (x1, g.y)], col.stroke_width(1)))?
                .label(format!(
                    "{} (dots: T_vis = {} s)",
                    g.label,
                    times.join(", ")
                ))
                .legend(legend_line(col));
            chart.draw_series(
                g.marks
                    .iter()
                    .map(|m| Circle::new((m.1, g.y), 4, col.filled())),
            )?;
        }
        legend(&mut chart, SeriesLabelPosition::LowerLeft)?;
        root.present()?;
        Ok(())
    }
}
