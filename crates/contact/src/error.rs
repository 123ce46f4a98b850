//! Typed errors of the contact model.

/// Everything that can go wrong when building a material or a contact.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// A parameter is non-finite or outside its physical range.
    #[error("{field} = {value:?} is outside the allowed range {allowed} ({unit})")]
    OutOfRange {
        /// Name of the parameter, as in the material file and the CLI (`young`, `radius`, ...).
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range, human readable (`> 0`, `-1 < nu < 0.5`).
        allowed: &'static str,
        /// SI unit of the parameter.
        unit: &'static str,
    },
    /// A material name that is neither a preset nor a readable file.
    #[error("unknown material '{name}': the presets are {presets}; a path to a JSON file with the fields gamma_sv, young, poisson, density (SI units) also works")]
    UnknownMaterial {
        /// The name given.
        name: String,
        /// The preset names, comma separated.
        presets: &'static str,
    },
    /// A material file that cannot be read or parsed (the message names the field).
    #[error("material file '{path}': {message}")]
    MaterialFile {
        /// Path of the file.
        path: String,
        /// What is wrong with it.
        message: String,
    },
}
