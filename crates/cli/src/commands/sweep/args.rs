//! The flags of `stickiness sweep` and what they determine: the grid, the search options and
//! the header that identifies the sweep in its file.

use crate::args::{BulkOverrides, Overrides, SearchArgs};
use crate::error::CliError;
use clap::{Args, ValueEnum};
use numerics::format::number;
use std::path::PathBuf;
use thresholds::sweep::{
    canonical, header_lines, header_text, parse_axis, Grid, NamedMaterial, Partner, TVisAxis,
};
use thresholds::{SearchOptions, TVisLaw};

/// File format of the rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Comma-separated values after `#` header lines (pandas: `read_csv(path, comment="#")`).
    Csv,
    /// One JSON object a line, after a first line `{"sweep": {header}}`.
    Jsonl,
}

impl From<Format> for thresholds::sweep::Format {
    fn from(f: Format) -> Self {
        match f {
            Format::Csv => Self::Csv,
            Format::Jsonl => Self::Jsonl,
        }
    }
}

/// Arguments of `stickiness sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Materials: a comma list of presets (co2, h2o) and JSON file paths.
    #[arg(long, default_value = "co2")]
    pub material: String,
    /// Surface free energies gamma_SV (J/m^2, each > 0) replacing each material's: a comma list
    /// or START:STOP:N (N log-spaced values, both ends included).
    #[arg(long, allow_hyphen_values = true)]
    pub gamma_sv: Option<String>,
    /// Radii R1 (m, each > 0): a comma list or START:STOP:N.
    #[arg(long, default_value = "0.00006", allow_hyphen_values = true)]
    pub radius: String,
    /// Radii R2 of the second sphere (m, each > 0): a comma list or START:STOP:N; default: R2 =
    /// R1.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "wall")]
    pub radius2: Option<String>,
    /// A sphere on a flat wall of the same material at every point.
    #[arg(long)]
    pub wall: bool,
    /// Relaxation times T_vis (s, each >= 0; 0 is the JKR limit): a comma list or START:STOP:N.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "t_vis_law")]
    pub t_vis: Option<String>,
    /// T_vis from the size law of Section 5.3 at each radius instead of a T_vis axis.
    #[arg(long, value_enum, ignore_case = true)]
    pub t_vis_law: Option<crate::args::LawName>,
    /// Modulus ratios k (dimensionless, each 0 < k <= 0.9; tables for 0.005-0.05): a comma list
    /// or START:STOP:N.
    #[arg(long, default_value = "0.01", allow_hyphen_values = true)]
    pub k: String,
    #[command(flatten)]
    pub search: SearchArgs,
    /// The output file.
    #[arg(long, value_name = "FILE.csv")]
    pub out: PathBuf,
    /// Continue an existing file of the same sweep: keep its complete rows, compute the rest.
    /// Every kept row must stand for its grid point (inputs as written, results that read as
    /// numbers); the first that does not is refused (exit 2, the file untouched).
    #[arg(long, conflicts_with = "force")]
    pub resume: bool,
    /// With --resume: also recompute N kept rows chosen at random, and the last one, and refuse
    /// if one differs beyond its method's tolerance (an edited result).
    #[arg(long, value_name = "N", requires = "resume")]
    pub verify: Option<usize>,
    /// Overwrite an existing file.
    #[arg(long)]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Format of the output file.
    #[arg(long, value_enum, ignore_case = true, default_value = "csv")]
    pub format: Format,
    /// Overrides of every material's bulk constants.
    #[command(flatten)]
    pub bulk: BulkOverrides,
}

impl SweepArgs {
    /// The grid (validated), the search options and the header text that identifies this sweep.
    pub(super) fn grid(&self) -> Result<(Grid, SearchOptions, String), CliError> {
        // gamma_SV is an axis of the sweep; the other constants are overrides
        let overrides = Overrides {
            gamma_sv: None,
            bulk: self.bulk.clone(),
        };
        let materials = self
            .material
            .split(',')
            .map(|name| {
                let named = overrides.resolve(name.trim(), crate::args::MATERIAL_PREFIX)?;
                Ok(NamedMaterial {
                    name: named.given,
                    material: named.material,
                })
            })
            .collect::<Result<Vec<_>, CliError>>()?;
        let axis = |flag: &str, spec: &str| parse_axis(flag, spec).map_err(CliError::from);
        let grid = Grid {
            materials,
            gamma_sv: self
                .gamma_sv
                .as_deref()
                .map(|s| axis("--gamma-sv", s))
                .transpose()?,
            radius: axis("--radius", &self.radius)?,
            partner: match (&self.radius2, self.wall) {
                (Some(s), _) => Partner::Radii(axis("--radius2", s)?),
                (None, true) => Partner::Wall,
                (None, false) => Partner::Same,
            },
            t_vis: match (&self.t_vis, self.t_vis_law) {
                (Some(s), _) => TVisAxis::Values(axis("--t-vis", s)?),
                (None, Some(law)) => TVisAxis::Law(TVisLaw::from(law)),
                (None, None) => {
                    return Err(CliError::Usage(
                        "one of --t-vis or --t-vis-law is required".into(),
                    ))
                }
            },
            k: axis("--k", &self.k)?,
        };
        grid.validate()?;
        let options = self.search.search_options();
        options.validate()?;
        let header = header_text(self.format.into(), &header_lines(&self.command(), &grid));
        Ok((grid, options, header))
    }

    /// The command line as it determines the rows (not --out, --resume, --force, --jobs), each
    /// axis in canonical form.
    fn command(&self) -> String {
        let mut command = vec![format!("stickiness sweep --material {}", self.material)];
        for (flag, v) in self.bulk.given() {
            command.push(format!("{flag} {}", number(v)));
        }
        if let Some(s) = &self.gamma_sv {
            command.push(format!("--gamma-sv {}", canonical(s)));
        }
        command.push(format!("--radius {}", canonical(&self.radius)));
        match (&self.radius2, self.wall) {
            (Some(s), _) => command.push(format!("--radius2 {}", canonical(s))),
            (None, true) => command.push("--wall".into()),
            (None, false) => {}
        }
        match (&self.t_vis, self.t_vis_law) {
            (Some(s), _) => command.push(format!("--t-vis {}", canonical(s))),
            (None, Some(l)) => command.push(format!("--t-vis-law {}", TVisLaw::from(l).name())),
            (None, None) => {}
        }
        command.push(format!("--k {}", canonical(&self.k)));
        command.push(format!("--rel-tol {}", number(self.search.rel_tol)));
        if let Some(v) = self.search.v_max {
            command.push(format!("--v-max {}", number(v)));
        }
        // always written: the default changed from search to table, and a resume must not mix
        // the two
        let method: thresholds::ThresholdMethod = self.search.method.method.into();
        command.push(format!("--method {}", method.name()));
        let format: thresholds::sweep::Format = self.format.into();
        command.push(format!("--format {}", format.name()));
        command.join(" ")
    }
}
