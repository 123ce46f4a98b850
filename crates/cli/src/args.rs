//! Arguments shared by the subcommands.

use crate::error::CliError;
use clap::Args;
use contact::{Contact, Material};

/// The material and the particle radius, with optional overrides of each material constant.
#[derive(Debug, Clone, Args)]
pub struct MaterialArgs {
    /// Material: a preset (co2, h2o) or a path to a JSON file with gamma_sv, young, poisson, density (SI).
    #[arg(long, default_value = "co2")]
    pub material: String,
    /// Particle radius R1 in metres (each of the two identical spheres).
    #[arg(long, default_value_t = 60e-6, allow_hyphen_values = true)]
    pub radius: f64,
    /// Override the surface free energy gamma_SV (J/m^2); the work of adhesion is 2 gamma_SV.
    #[arg(long, allow_hyphen_values = true)]
    pub gamma_sv: Option<f64>,
    /// Override Young's modulus E (Pa).
    #[arg(long, allow_hyphen_values = true)]
    pub young: Option<f64>,
    /// Override the Poisson ratio nu (dimensionless, -1 < nu < 0.5).
    #[arg(long, allow_hyphen_values = true)]
    pub poisson: Option<f64>,
    /// Override the density rho (kg/m^3).
    #[arg(long, allow_hyphen_values = true)]
    pub density: Option<f64>,
}

impl MaterialArgs {
    /// The material after overrides, validated.
    pub fn material(&self) -> Result<Material, CliError> {
        let mut m = Material::from_name_or_path(&self.material)?;
        if let Some(v) = self.gamma_sv {
            m.gamma_sv = v;
        }
        if let Some(v) = self.young {
            m.young = v;
        }
        if let Some(v) = self.poisson {
            m.poisson = v;
        }
        if let Some(v) = self.density {
            m.density = v;
        }
        m.validate()?;
        Ok(m)
    }

    /// The two-sphere contact described by these arguments.
    pub fn contact(&self) -> Result<Contact, CliError> {
        Ok(Contact::new(self.material()?, self.radius)?)
    }
}
