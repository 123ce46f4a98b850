//! Arguments shared by the subcommands: the material, the geometry, k, T_vis and the search.
//!
//! Defaults are written as the workspace's number format prints them (`0.00006`, `1e-6`), so
//! `--help` shows every number as the JSON output does (checked by a test).

use crate::error::CliError;
use clap::{Args, ValueEnum};
use contact::{Contact, Geometry, Material};
use serde_json::{json, Map, Value};
use std::path::Path;
use thresholds::TVisLaw;

/// The material: a preset or a JSON file, with optional overrides of each constant.
#[derive(Debug, Clone, Args)]
pub struct MaterialArgs {
    /// Material: a preset (co2, h2o; any case) or a path to a JSON file with gamma_sv, young,
    /// poisson, density (SI).
    #[arg(long, default_value = "co2")]
    pub material: String,
    #[command(flatten)]
    pub overrides: Overrides,
}

/// Overrides of the four material constants (SI).
#[derive(Debug, Clone, Args)]
pub struct Overrides {
    /// Override the surface free energy gamma_SV (J/m^2, > 0); the work of adhesion is 2 gamma_SV.
    #[arg(long, allow_hyphen_values = true)]
    pub gamma_sv: Option<f64>,
    #[command(flatten)]
    pub bulk: BulkOverrides,
}

/// Overrides of the three bulk constants (SI); `sweep` takes gamma_SV as an axis instead.
#[derive(Debug, Clone, Args)]
pub struct BulkOverrides {
    /// Override Young's modulus E (Pa, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub young: Option<f64>,
    /// Override the Poisson ratio nu (dimensionless, -1 < nu < 0.5; nonzero for a collision,
    /// whose drag is A = T_vis/nu^2).
    #[arg(long, allow_hyphen_values = true)]
    pub poisson: Option<f64>,
    /// Override the density rho (kg/m^3, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub density: Option<f64>,
}

impl BulkOverrides {
    /// `(flag, value)` of each override given, as the command line spells it.
    pub fn given(&self) -> Vec<(&'static str, f64)> {
        [
            ("--young", self.young),
            ("--poisson", self.poisson),
            ("--density", self.density),
        ]
        .into_iter()
        .filter_map(|(flag, v)| Some((flag, v?)))
        .collect()
    }
}

/// A material after overrides, with the name it goes by in titles and in `"input"`.
#[derive(Debug, Clone)]
pub struct NamedMaterial {
    /// A preset's name (lower case, however it was typed) or the path of the file, as given.
    pub given: String,
    /// For titles: the preset name, or the file's stem, with the overridden constants named
    /// (`co2 (young, density overridden)`): a title must not call a material of other
    /// constants by a preset's name alone.
    pub short: String,
    /// The constants (SI), validated.
    pub material: Material,
}

impl Overrides {
    fn flags(&self) -> [(&'static str, Option<f64>); 4] {
        [
            ("gamma_sv", self.gamma_sv),
            ("young", self.bulk.young),
            ("poisson", self.bulk.poisson),
            ("density", self.bulk.density),
        ]
    }

    /// Resolves `name` (a preset or a JSON file) and applies the overrides. A bad value names
    /// the flag when it was overridden and the file (and field) when it came from the file.
    /// `prefix` starts the message of an unknown name, an unreadable file or a file's bad value:
    /// `"--material: "` where
    /// the name came from that flag, `""` for `material NAME`, where the name alone is clear.
    pub fn resolve(&self, name: &str, prefix: &str) -> Result<NamedMaterial, CliError> {
        let (mut m, file) = match Material::preset(name) {
            Some(m) => (m, None),
            None => {
                let m = Material::read_json_file(Path::new(name))
                    .map_err(|e| match e {
                        contact::ContactError::MaterialFileNotFound { .. }
                            if !name.contains('/') && !name.ends_with(".json") =>
                        {
                            contact::ContactError::UnknownMaterial {
                                name: name.to_string(),
                                presets: contact::PRESETS,
                            }
                        }
                        other => other,
                    })
                    .map_err(|e| CliError::Usage(format!("{prefix}{e}")))?;
                (m, Some(name))
            }
        };
        for (field, value) in self.flags() {
            if let Some(v) = value {
                match field {
                    "gamma_sv" => m.gamma_sv = v,
                    "young" => m.young = v,
                    "poisson" => m.poisson = v,
                    _ => m.density = v,
                }
            }
        }
        if let Err(e) = m.validate() {
            let overridden = self
                .flags()
                .iter()
                .any(|(f, v)| *f == e.field && v.is_some());
            return Err(match file {
                Some(path) if !overridden => CliError::Usage(format!("{prefix}{path}: {e}")),
                _ => e.into(),
            });
        }
        let mut short = match file {
            Some(path) => Path::new(path)
                .file_stem()
                .map_or_else(|| path.to_string(), |s| s.to_string_lossy().into_owned()),
            None => name.to_ascii_lowercase(),
        };
        let overridden: Vec<&str> = self
            .flags()
            .iter()
            .filter_map(|(f, v)| v.map(|_| *f))
            .collect();
        if !overridden.is_empty() {
            short = format!("{short} ({} overridden)", overridden.join(", "));
        }
        Ok(NamedMaterial {
            // a preset under its one name (`CO2` is `co2`), so that scripts group by it; a
            // file's path as given
            given: match file {
                Some(path) => path.to_string(),
                None => name.to_ascii_lowercase(),
            },
            short,
            material: m,
        })
    }
}

impl MaterialArgs {
    /// The material after overrides, validated.
    pub fn resolve(&self) -> Result<NamedMaterial, CliError> {
        self.overrides.resolve(&self.material, MATERIAL_PREFIX)
    }
}

/// The two bodies: a sphere of `--radius` and one of `--radius2`, or a wall.
#[derive(Debug, Clone, Args)]
pub struct GeometryArgs {
    // v-frag words its own: V_FRAG_RADIUS_HELP (main.rs)
    /// Radius R1 of the (first) sphere (m, > 0).
    #[arg(long, default_value = "0.00006", allow_hyphen_values = true)]
    pub radius: f64,
    /// Radius R2 of the second sphere (m, > 0); default: equal to --radius (identical spheres).
    #[arg(long, allow_hyphen_values = true)]
    pub radius2: Option<f64>,
    /// The sphere hits a flat wall of the same material (R2 -> infinity).
    #[arg(long, conflicts_with = "radius2")]
    pub wall: bool,
}

impl GeometryArgs {
    /// The geometry described by these flags.
    pub fn geometry(&self) -> Geometry {
        match (self.wall, self.radius2) {
            (true, _) => Geometry::wall(self.radius),
            (false, Some(r2)) => Geometry::spheres(self.radius, r2),
            (false, None) => Geometry::identical(self.radius),
        }
    }
}

/// A validated contact with the inputs that made it, for titles and for `"input"`.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The material and its names.
    pub material: NamedMaterial,
    /// The contact (SI).
    pub contact: Contact,
    /// Inputs as used: material, constants, radius, radius2, wall, then the command's own.
    pub input: Map<String, Value>,
    /// Cautions about the inputs beyond the contact's own (a size law of the other ice).
    pub cautions: Vec<String>,
}

impl Setup {
    /// Resolves the material and the geometry into a contact.
    pub fn new(material: &MaterialArgs, geometry: &GeometryArgs) -> Result<Self, CliError> {
        let named = material.resolve()?;
        let g = geometry.geometry();
        let contact = Contact::new(named.material, g)?;
        let m = &named.material;
        let mut input = Map::new();
        for (k, v) in [
            ("material", json!(named.given)),
            ("gamma_sv", json!(m.gamma_sv)),
            ("young", json!(m.young)),
            ("poisson", json!(m.poisson)),
            ("density", json!(m.density)),
            ("radius", json!(g.r1())),
            ("radius2", json!(g.r2())),
            ("wall", json!(g.is_wall())),
        ] {
            input.insert(k.into(), v);
        }
        Ok(Self {
            material: named,
            contact,
            input,
            cautions: Vec::new(),
        })
    }

    /// Records one more input as used.
    pub fn with_input(&mut self, key: &str, value: impl Into<Value>) {
        self.input.insert(key.into(), value.into());
    }

    /// The contact's warnings, then the cautions about the other inputs: what a report warns of.
    pub fn warnings(&self) -> Vec<String> {
        let contact = self.contact.warnings().into_iter().map(|w| w.to_string());
        contact.chain(self.cautions.iter().cloned()).collect()
    }

    /// `result`, after printing this setup's warnings on stderr if it failed: a warning of
    /// implausible input (a Young's modulus of 1e30 Pa) often explains the failure, and the
    /// report that would have carried it is not made.
    pub fn or_warned<T, E: Into<CliError>>(&self, result: Result<T, E>) -> Result<T, CliError> {
        result.map_err(|e| {
            crate::output::print_warnings(&self.warnings());
            e.into()
        })
    }

    /// `two identical spheres of 60 um of co2`, for titles.
    pub fn describe(&self) -> String {
        format!("{} of {}", self.contact.geometry(), self.material.short)
    }
}

/// The crack-law parameter shared by every collision command.
#[derive(Debug, Clone, Args)]
pub struct KArgs {
    /// Ratio of relaxed to instantaneous modulus k (dimensionless, 0 < k <= 0.9; tables for
    /// 0.005-0.05).
    #[arg(long, default_value = "0.01", allow_hyphen_values = true)]
    pub k: f64,
}

impl KArgs {
    /// Greenwood's crack law tabulated for this k; a k outside the collisions' range is refused
    /// with that range ([`dynamics::collision_k`]), not the crack law's wider 0 < k < 1.
    pub fn crack_law(&self) -> Result<greenwood::CrackLaw, CliError> {
        Ok(greenwood::CrackLaw::new(dynamics::collision_k(self.k)?)?)
    }
}

/// The size laws of Section 5.3, as a case-insensitive flag value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LawName {
    /// T_vis,CO2 = 1e-11 s (R1 / 1 um)^1.11.
    Co2,
    /// T_vis,H2O = 1e-10 s (R1 / 1.5 um)^1.11.
    H2o,
}

impl From<LawName> for TVisLaw {
    fn from(l: LawName) -> Self {
        match l {
            LawName::Co2 => TVisLaw::Co2,
            LawName::H2o => TVisLaw::H2o,
        }
    }
}

/// The relaxation time, given or from a size law of R1.
#[derive(Debug, Clone, Args)]
pub struct TVisArgs {
    // collide words its own: COLLIDE_T_VIS_HELP (main.rs)
    /// Viscoelastic relaxation time T_vis (s, >= 0; 0 is the JKR limit).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "t_vis_law")]
    pub t_vis: Option<f64>,
    /// T_vis from the size law of Section 5.3 at R1 = --radius: co2 = 1e-11 s (R1/1 um)^1.11,
    /// h2o = 1e-10 s (R1/1.5 um)^1.11 (a law with the other ice's material is warned of).
    #[arg(long, value_enum, ignore_case = true)]
    pub t_vis_law: Option<LawName>,
}

impl TVisArgs {
    /// The T_vis to use (s), recorded in `setup`'s inputs (with the law when one was given);
    /// `default` when neither flag is given (`None`: one of them is required).
    pub fn resolve(&self, setup: &mut Setup, default: Option<f64>) -> Result<f64, CliError> {
        let t_vis = match (self.t_vis, self.t_vis_law) {
            (Some(t), _) => t,
            (None, Some(law)) => {
                let law = TVisLaw::from(law);
                setup.with_input("t_vis_law", law.name());
                setup
                    .cautions
                    .extend(law.mismatch(setup.contact.material()));
                law.t_vis(setup.contact.r1())
            }
            (None, None) => default.ok_or_else(|| {
                CliError::Usage("one of --t-vis or --t-vis-law is required".into())
            })?,
        };
        // the range is the library's to check: 0 (the JKR limit) is a threshold's answer but no
        // collision, and each says so in its own message
        setup.with_input("t_vis", t_vis);
        Ok(t_vis)
    }
}

/// The contact, its relaxation time and its crack law: the inputs of one collision or of one
/// threshold search (`collide`, `v-stick`, `v-frag`).
#[derive(Debug, Clone, Args)]
pub struct PointArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    #[command(flatten)]
    pub geometry: GeometryArgs,
    #[command(flatten)]
    pub t_vis: TVisArgs,
    #[command(flatten)]
    pub k: KArgs,
}

impl PointArgs {
    /// The contact (with its inputs), T_vis (s; `default_t_vis` when no flag gives it, `None`:
    /// one is required) and the crack law of k.
    pub fn resolve(
        &self,
        default_t_vis: Option<f64>,
    ) -> Result<(Setup, f64, greenwood::CrackLaw), CliError> {
        let mut setup = Setup::new(&self.material, &self.geometry)?;
        let t_vis = self.t_vis.resolve(&mut setup, default_t_vis)?;
        Ok((setup, t_vis, self.k.crack_law()?))
    }
}

/// `--t-vis` of `collide`: a collision has no JKR limit to answer at T_vis = 0.
pub const COLLIDE_T_VIS_HELP: &str = "Viscoelastic relaxation time T_vis (s, > 0)";

/// `--t-vis` of `v-frag`, whose default is the JKR limit.
pub const V_FRAG_T_VIS_HELP: &str =
    "Viscoelastic relaxation time T_vis (s, >= 0; default 0, the JKR limit: V_frag,JKR)";

/// `--radius` of `v-frag`: the aggregates' monomers (Section 6).
pub const V_FRAG_RADIUS_HELP: &str = "Radius of the aggregates' monomers (m, > 0): R1 of the two \
     identical spheres whose V_stick sets V_frag (with --radius2 or --wall, R1 of that pair)";

/// `--v-max` of `fit-t-vis`, whose searches have a limit of their own.
pub const FIT_V_MAX_HELP: &str = "Highest impact speed searched for bouncing (m/s; default twice \
     each target V_stick, raised to this where higher; at most 10000.0)";

/// The threshold-search settings shared by v-stick, fit-t-vis, v-frag and sweep.
#[derive(Debug, Clone, Args)]
pub struct SearchArgs {
    /// Relative tolerance of the threshold brackets (dimensionless, 1e-15 < rel_tol < 0.5).
    #[arg(long, default_value = "1e-6", allow_hyphen_values = true)]
    pub rel_tol: f64,
    // fit-t-vis words its own: FIT_V_MAX_HELP (main.rs)
    /// Highest impact speed searched for bouncing (m/s; default 1000 V_stick,JKR; at most
    /// 10000.0).
    #[arg(long, allow_hyphen_values = true)]
    pub v_max: Option<f64>,
    #[command(flatten)]
    pub method: MethodArg,
}

/// How thresholds are answered: the master tables where they vouch for their accuracy
/// (microseconds), or the exact search (milliseconds).
#[derive(Debug, Clone, Args)]
pub struct MethodArg {
    /// table (default): the master tables of V_stick / V_stick,JKR over the two dimensionless
    /// numbers and k, within 1e-5 of the search where they vouch for it, the search elsewhere;
    /// search: the exact search (20-100 collisions). "method" in the output says which answered.
    #[arg(long, value_enum, ignore_case = true, default_value = "table")]
    pub method: MethodName,
}

/// The values of `--method`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodName {
    /// The master tables, the search where they do not vouch.
    Table,
    /// The exact search.
    Search,
}

impl From<MethodName> for thresholds::ThresholdMethod {
    fn from(m: MethodName) -> Self {
        match m {
            MethodName::Search => Self::Search,
            MethodName::Table => Self::Table,
        }
    }
}

impl SearchArgs {
    /// The library's search options, recorded in `setup`'s inputs (the command records the
    /// `v_max` it searched up to).
    pub fn options(&self, setup: &mut Setup) -> thresholds::SearchOptions {
        let options = self.search_options();
        setup.with_input("rel_tol", self.rel_tol);
        setup.with_input("method", options.method.name());
        options
    }

    /// The library's search options.
    pub fn search_options(&self) -> thresholds::SearchOptions {
        thresholds::SearchOptions {
            rel_tol: self.rel_tol,
            v_max: self.v_max,
            method: self.method.method.into(),
            ..Default::default()
        }
    }
}

/// How a bad `--material` value starts its message: with the flag, as every other bad input.
pub const MATERIAL_PREFIX: &str = "--material: ";
