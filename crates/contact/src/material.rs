//! Bulk material properties of a grain (Arakawa & Krijt 2021, Section 3).

use crate::ContactError;
use numerics::{positive, OutOfRange};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Names of the built-in materials, for messages.
pub const PRESETS: &str = "co2, h2o";

/// Longitudinal sound speed in CO2 ice at 80 K (m/s), Yamashita et al. (1997), Section 3.2.
pub const CO2_V_LONGITUDINAL: f64 = 2900.0;
/// Transverse sound speed in CO2 ice at 80 K (m/s), Yamashita et al. (1997), Section 3.2.
pub const CO2_V_TRANSVERSE: f64 = 1650.0;

/// The four material constants of the model, in SI units.
///
/// `gamma_sv` is the surface free energy; the contact uses the work of adhesion
/// `gamma = 2 gamma_sv` (Section 3.1). The same four names are the fields of a material JSON file.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Surface free energy gamma_SV (J/m^2).
    pub gamma_sv: f64,
    /// (Relaxed) Young's modulus E (Pa).
    pub young: f64,
    /// Poisson ratio nu (dimensionless, -1 < nu < 0.5; a collision needs nu != 0, its drag being
    /// A = T_vis/nu^2, Section 2.5).
    pub poisson: f64,
    /// Material density rho (kg/m^3).
    pub density: f64,
}

/// Young's modulus (Pa) and Poisson ratio from the longitudinal and transverse sound speeds
/// `v_lg`, `v_ts` (m/s) and the density `rho` (kg/m^3) (Section 3.2):
/// `G = rho v_ts^2`, `K = rho v_lg^2 - 4G/3`, `E = 9KG/(3K + G)`, `nu = (3K - 2G)/(2(3K + G))`.
pub fn elastic_from_sound_speeds(v_lg: f64, v_ts: f64, rho: f64) -> (f64, f64) {
    let g = rho * v_ts * v_ts;
    let k = rho * v_lg * v_lg - 4.0 * g / 3.0;
    let young = 9.0 * k * g / (3.0 * k + g);
    let poisson = (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g));
    (young, poisson)
}

impl Material {
    /// CO2 ice (Section 3): gamma_SV = 0.08 J/m^2 (Wood 1999); E and nu from the sound speeds
    /// 2900 and 1650 m/s (Yamashita et al. 1997) at rho = 1560 kg/m^3 (Section 2.5), which gives
    /// E = 10.7 GPa and nu = 0.26. (Section 5.4 uses rho = 1650 kg/m^3; set `density` to change it.)
    pub fn co2() -> Self {
        let density = 1560.0;
        let (young, poisson) =
            elastic_from_sound_speeds(CO2_V_LONGITUDINAL, CO2_V_TRANSVERSE, density);
        Self {
            gamma_sv: 0.08,
            young,
            poisson,
            density,
        }
    }

    /// H2O ice (Sections 3 and 5.2): gamma_SV = 0.1 J/m^2, E = 7 GPa, nu = 0.25, rho = 930 kg/m^3.
    pub fn h2o() -> Self {
        Self {
            gamma_sv: 0.1,
            young: 7e9,
            poisson: 0.25,
            density: 930.0,
        }
    }

    /// A built-in material by name (`co2`, `h2o`; case-insensitive).
    pub fn preset(name: &str) -> Option<Self> {
        match name.to_ascii_lowercase().as_str() {
            "co2" => Some(Self::co2()),
            "h2o" => Some(Self::h2o()),
            _ => None,
        }
    }

    /// A preset name, or else a path to a JSON material file (validated; see
    /// [`Material::from_json_file`]). A name that looks like a path (it holds a `/` or ends in
    /// `.json`) but names no file is [`ContactError::MaterialFileNotFound`].
    pub fn from_name_or_path(name: &str) -> Result<Self, ContactError> {
        match Self::preset(name) {
            Some(m) => Ok(m),
            None => Self::from_json_file(Path::new(name)).map_err(|e| match e {
                ContactError::MaterialFileNotFound { .. } if !looks_like_path(name) => {
                    ContactError::UnknownMaterial {
                        name: name.to_string(),
                        presets: PRESETS,
                    }
                }
                other => other,
            }),
        }
    }

    /// Parses `{"gamma_sv": .., "young": .., "poisson": .., "density": ..}` (SI units) and
    /// validates it. Unknown or missing fields are errors that name the field.
    ///
    /// # Example
    /// ```
    /// use contact::Material;
    /// let ice = Material::from_json_str(r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": 930}"#)?;
    /// assert_eq!(ice, Material::h2o());
    /// let bad = Material::from_json_str(r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": -930}"#);
    /// assert_eq!(bad.unwrap_err().to_string(), "<string>: density = -930.0: must be > 0 and finite (kg/m^3)");
    /// # Ok::<(), contact::ContactError>(())
    /// ```
    pub fn from_json_str(json: &str) -> Result<Self, ContactError> {
        Self::parse_json(json, "<string>")
    }

    /// Reads and validates a JSON material file (see [`Material::from_json_str`]); every error
    /// names the file, and a bad value names its field: `ice.json: density = -930.0: must be > 0
    /// and finite (kg/m^3)`.
    pub fn from_json_file(path: &Path) -> Result<Self, ContactError> {
        let m = Self::read_json_file(path)?;
        m.validate().map_err(|e| ContactError::MaterialFile {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        Ok(m)
    }

    /// Reads a JSON material file without validating the values (for callers that override
    /// fields before validating); unreadable files, unknown and missing fields are errors.
    pub fn read_json_file(path: &Path) -> Result<Self, ContactError> {
        let shown = path.display().to_string();
        if !path.is_file() {
            return Err(ContactError::MaterialFileNotFound { path: shown });
        }
        let text = std::fs::read_to_string(path).map_err(|e| ContactError::MaterialFile {
            path: shown.clone(),
            message: e.to_string(),
        })?;
        serde_json::from_str(&text).map_err(|e| unparsed(&e, &shown))
    }

    fn parse_json(json: &str, shown: &str) -> Result<Self, ContactError> {
        let m: Self = serde_json::from_str(json).map_err(|e| unparsed(&e, shown))?;
        m.validate().map_err(|e| ContactError::MaterialFile {
            path: shown.into(),
            message: e.to_string(),
        })?;
        Ok(m)
    }

    /// Checks every field: finite, `gamma_sv`, `young`, `density` > 0 and -1 < `poisson` < 0.5.
    pub fn validate(&self) -> Result<(), OutOfRange> {
        positive("gamma_sv", self.gamma_sv, "J/m^2")?;
        positive("young", self.young, "Pa")?;
        if !(self.poisson.is_finite() && self.poisson > -1.0 && self.poisson < 0.5) {
            return Err(OutOfRange::new(
                "poisson",
                self.poisson,
                "-1 < poisson < 0.5",
                "dimensionless",
            ));
        }
        positive("density", self.density, "kg/m^3")?;
        Ok(())
    }
}

/// Whether a material name is meant as a file path rather than a preset name.
fn looks_like_path(name: &str) -> bool {
    name.contains(std::path::MAIN_SEPARATOR) || name.contains('/') || name.ends_with(".json")
}

/// What a material file holds, said after one that cannot be parsed.
const MATERIAL_FILE_FORM: &str = r#"a material file is {"gamma_sv": J/m^2, "young": Pa, "poisson": dimensionless, "density": kg/m^3}"#;

/// The error of a material file (or string) `shown` that JSON cannot parse into a material:
/// serde's message (which names a missing or unknown field), then what the file should hold.
fn unparsed(e: &serde_json::Error, shown: &str) -> ContactError {
    ContactError::MaterialFile {
        path: shown.into(),
        message: format!("{e} ({MATERIAL_FILE_FORM})"),
    }
}
