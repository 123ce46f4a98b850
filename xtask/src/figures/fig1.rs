//! Figure 1: Greenwood's crack speed v(k, beta) for several k, over the full range and near
//! beta = 1 (Appendix A).

use super::chart::*;
use super::{geomspace, linspace, par_map, KS};
use super::{Error, Progress, Resolution};
use crate::table::Table;
use greenwood::CrackLaw;
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;

/// One curve of Figure 1: v(k, beta) over the full range and near beta = 1.
#[derive(Debug, Clone)]
pub struct CrackLawCurve {
    /// The modulus ratio k.
    pub k: f64,
    /// `(beta, v)` log-spaced over 1e-3 < beta < 1e3 within k < beta < 1/k.
    pub full: Vec<(f64, f64)>,
    /// `(beta, v)` in 0.95 <= beta <= 1.05.
    pub zoom: Vec<(f64, f64)>,
}

/// Figure 1: Greenwood's crack speed v(k, beta) for several k.
#[derive(Debug, Clone)]
pub struct Figure1 {
    /// One curve per k of [`KS`].
    pub curves: Vec<CrackLawCurve>,
}

impl Figure1 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let (n, nz) = (res.pick(300, 12), res.pick(101, 5));
        let curves = par_map("fig1", &KS, progress, |&k| -> Result<_, Error> {
            let law = CrackLaw::new(k)?;
            let lo = (k * (1.0 + 1e-9)).max(1e-3);
            let hi = (1.0 / k * (1.0 - 1e-9)).min(1e3);
            let eval = |betas: Vec<f64>| -> Result<Vec<(f64, f64)>, Error> {
                betas.into_iter().map(|b| Ok((b, law.v(b)?))).collect()
            };
            Ok(CrackLawCurve {
                k,
                full: eval(geomspace(lo, hi, n))?,
                zoom: eval(linspace(0.95, 1.05, nz))?,
            })
        })?;
        Ok(Self { curves })
    }

    /// `fig1.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "fig1.csv",
            vec![
                "Figure 1: Greenwood's normalized crack speed v(k, beta) (Arakawa & Krijt 2021, Appendix A)".into(),
                "panel = full: 1e-3 < beta < 1e3 within k < beta < 1/k; panel = zoom: 0.95 <= beta <= 1.05".into(),
                "units: k, beta, v dimensionless (v = sigma0^2 T_vis a_dot / (E* gamma))".into(),
            ],
            &["panel", "k", "beta", "v"],
        );
        for c in &self.curves {
            for (panel, pts) in [("full", &c.full), ("zoom", &c.zoom)] {
                for &(beta, v) in pts {
                    t.push(vec![panel.into(), c.k.into(), beta.into(), v.into()]);
                }
            }
        }
        vec![t]
    }
}

impl Figure1 {
    /// `fig1.svg`: |v| against beta for each k, and v near beta = 1.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = picture(path, SIZE_TWO)?;
        let (left, right) = two_panels(&root);
        let mut chart = log_log(
            &left,
            "Figure 1: crack speed |v| (solid v > 0, thin v < 0)",
            (1e-3, 1e3),
            (1e-6, 1e8),
            "beta = G_eff / gamma (dimensionless)",
            "|v| (dimensionless)",
        )?;
        for (j, c) in self.curves.iter().enumerate() {
            let col = COLOURS[j % COLOURS.len()];
            let closing: Vec<_> = c.full.iter().filter(|p| p.1 > 0.0).copied().collect();
            let opening: Vec<_> = c
                .full
                .iter()
                .filter(|p| p.1 < 0.0)
                .map(|p| (p.0, -p.1))
                .collect();
            chart
                .draw_series(LineSeries::new(closing, col.stroke_width(2)))?
                .label(format!("k = {}", number(c.k)))
                .legend(legend_line(col));
            chart.draw_series(LineSeries::new(opening, col.stroke_width(1)))?;
        }
        legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
        let (lo, hi) = span(self.curves.iter().flat_map(|c| c.zoom.iter().map(|p| p.1)));
        let mut zoom = linear(
            &right,
            "v near beta = 1",
            0.95..1.05,
            lo..hi,
            "beta (dimensionless)",
            "v (dimensionless)",
        )?;
        for (j, c) in self.curves.iter().enumerate() {
            let col = COLOURS[j % COLOURS.len()];
            zoom.draw_series(LineSeries::new(c.zoom.clone(), col.stroke_width(2)))?
                .label(format!("k = {}", number(c.k)))
                .legend(legend_line(col));
        }
        legend(&mut zoom, SeriesLabelPosition::MiddleRight)?;
        root.present()?;
        Ok(())
    }
}
