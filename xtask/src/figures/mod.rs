//! The data and pictures of Figures 1-7 of Arakawa & Krijt (2021) and of the sphere-on-wall
//! figure, one file a figure (its typed data, its CSV tables and its SVG drawing); shared chart
//! helpers in [`chart`], the V_stick-against-T_vis curves of Figures 4, 5 and the wall figure in
//! [`curves`]. Only parameter grids live here: every number comes from `greenwood`, `contact`,
//! `dynamics` and `thresholds`, and the measurements compared with from `thresholds::paper`.

pub mod chart;
pub mod curves;
pub mod fig1;
pub mod fig2;
pub mod fig3;
pub mod fig4;
pub mod fig5;
pub mod fig6;
pub mod fig7;
pub mod master;
pub mod wall;

pub use curves::ThresholdCurve;
pub use fig1::{CrackLawCurve, Figure1};
pub use fig2::{Figure2, Trajectory};
pub use fig3::{Figure3, Restitution};
pub use fig4::Figure4;
pub use fig5::Figure5;
pub use fig6::{Figure6, FittedTVis};
pub use fig7::{Figure7, SizePoint};
pub use master::FigureMaster;
pub use wall::{FigureWall, WALL_GEOMETRIES};

use crate::table::Table;
use contact::{Contact, Geometry, Material};
use numerics::format::number;
use rayon::prelude::*;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use thresholds::paper::H2O_GAMMA_SV_RANGE;
pub use thresholds::sweep::geomspace;

/// Any failure while computing a figure.
pub type Error = Box<dyn std::error::Error + Send + Sync>;

/// Grid density: `Full` for `data/`, `Reduced` for the snapshot tests.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resolution {
    /// The committed figures.
    Full,
    /// A few points per curve.
    Reduced,
}

impl Resolution {
    pub(crate) fn pick(&self, full: usize, reduced: usize) -> usize {
        match self {
            Resolution::Full => full,
            Resolution::Reduced => reduced,
        }
    }
}

/// Reports progress: `(figure, done, total)`.
pub type Progress<'a> = &'a (dyn Fn(&str, usize, usize) + Sync);

/// The fiducial k of the paper (Section 2.3).
pub const K: f64 = thresholds::DEFAULT_K;
/// The k values of Figures 1 and 4.
pub const KS: [f64; 4] = [0.005, 0.01, 0.02, 0.05];
/// Surface energies of Figure 5 (J/m^2): from Gundlach et al. (2018) to Gundlach et al. (2011).
pub const GAMMAS_H2O: [f64; 4] = [H2O_GAMMA_SV_RANGE.0, 0.05, 0.1, H2O_GAMMA_SV_RANGE.1];
/// The V_in of the three trajectories of Figure 2 (m/s).
pub const FIG2_V_IN: [f64; 3] = [0.035, 0.0405, 0.045];
/// T_vis of Figures 2 and 3 (s).
pub const FIG2_T_VIS: f64 = 1e-9;

/// `n` points from `a` to `b`, evenly spaced.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}

/// Runs `f` over `items` on all cores, reporting progress, keeping the order.
pub(crate) fn par_map<T: Sync, R: Send>(
    name: &str,
    items: &[T],
    progress: Progress,
    f: impl Fn(&T) -> Result<R, Error> + Sync,
) -> Result<Vec<R>, Error> {
    let done = AtomicUsize::new(0);
    let total = items.len();
    progress(name, 0, total);
    items
        .par_iter()
        .map(|x| {
            let r = f(x);
            progress(name, done.fetch_add(1, Ordering::Relaxed) + 1, total);
            r
        })
        .collect()
}

/// The comment line naming a material and its constants.
pub(crate) fn material_line(name: &str, m: &Material) -> String {
    format!(
        "material = {name}: gamma_sv = {} J/m^2, young = {} Pa, poisson = {}, density = {} kg/m^3",
        number(m.gamma_sv),
        number(m.young),
        number(m.poisson),
        number(m.density)
    )
}

/// A figure's comment lines: `title`, the material's line, then `notes`.
pub(crate) fn figure_comments(
    title: &str,
    (name, material): (&str, &Material),
    notes: &[String],
) -> Vec<String> {
    let mut comments = vec![title.to_string(), material_line(name, material)];
    comments.extend_from_slice(notes);
    comments
}

/// A figure's table: its comment lines ([`figure_comments`]), then `columns`.
pub(crate) fn figure_table(
    file: &str,
    title: &str,
    material: (&str, &Material),
    notes: &[String],
    columns: &[&str],
) -> Table {
    Table::new(file, figure_comments(title, material, notes), columns)
}

/// Two identical CO2 spheres of radius `r1` (m).
pub(crate) fn co2_contact(r1: f64) -> Result<Contact, Error> {
    Ok(Contact::new(Material::co2(), Geometry::identical(r1))?)
}

/// H2O ice with surface energy `gamma_sv` (J/m^2).
pub(crate) fn h2o_with(gamma_sv: f64) -> Material {
    Material {
        gamma_sv,
        ..Material::h2o()
    }
}

/// Every figure.
#[derive(Debug, Clone)]
pub struct Figures {
    /// Figure 1.
    pub fig1: Figure1,
    /// Figure 2.
    pub fig2: Figure2,
    /// Figure 3.
    pub fig3: Figure3,
    /// Figure 4.
    pub fig4: Figure4,
    /// Figure 5.
    pub fig5: Figure5,
    /// Figure 6.
    pub fig6: Figure6,
    /// Figure 7.
    pub fig7: Figure7,
    /// The sphere-on-wall figure.
    pub wall: FigureWall,
    /// The master figure: V_stick / V_stick,JKR over the two dimensionless numbers.
    pub master: FigureMaster,
}

impl Figures {
    /// Computes every figure, in order.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        Ok(Self {
            fig1: Figure1::compute(res, progress)?,
            fig2: Figure2::compute(res, progress)?,
            fig3: Figure3::compute(res, progress)?,
            fig4: Figure4::compute(res, progress)?,
            fig5: Figure5::compute(res, progress)?,
            fig6: Figure6::compute(res, progress)?,
            fig7: Figure7::compute(res, progress)?,
            wall: FigureWall::compute(res, progress)?,
            master: FigureMaster::compute(res, progress)?,
        })
    }

    /// Every CSV table, in order.
    pub fn tables(&self) -> Vec<Table> {
        [
            self.fig1.to_tables(),
            self.fig2.to_tables(),
            self.fig3.to_tables(),
            self.fig4.to_tables(),
            self.fig5.to_tables(),
            self.fig6.to_tables(),
            self.fig7.to_tables(),
            self.wall.to_tables(),
            self.master.to_tables(),
        ]
        .concat()
    }

    /// Draws every figure into `dir` as `fig1.svg` ... `fig7.svg`, `fig_wall.svg` and
    /// `fig_master.svg`.
    pub fn draw_all(&self, dir: &Path) -> Result<(), Error> {
        std::fs::create_dir_all(dir)?;
        self.fig1.draw(&dir.join("fig1.svg"))?;
        self.fig2.draw(&dir.join("fig2.svg"))?;
        self.fig3.draw(&dir.join("fig3.svg"))?;
        self.fig4.draw(&dir.join("fig4.svg"))?;
        self.fig5.draw(&dir.join("fig5.svg"))?;
        self.fig6.draw(&dir.join("fig6.svg"))?;
        self.fig7.draw(&dir.join("fig7.svg"))?;
        self.wall.draw(&dir.join("fig_wall.svg"))?;
        self.master.draw(&dir.join("fig_master.svg"))?;
        Ok(())
    }
}
