//! Typed errors of the contact model.

use numerics::OutOfRange;

/// Everything that can go wrong when building a material or a contact.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// A parameter is non-finite or outside its physical range (the field names it: `radius`,
    /// `radius2`, `young`, ...).
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// A material name that is neither a preset nor an existing file.
    #[error("unknown material '{name}': the presets are {presets}; a path to a JSON file with the fields gamma_sv, young, poisson, density (SI units) also works")]
    UnknownMaterial {
        /// The name given.
        name: String,
        /// The preset names, comma separated.
        presets: &'static str,
    },
    /// A path to a material file that does not exist.
    #[error("material file not found (or not a file): {path}")]
    MaterialFileNotFound {
        /// The path given.
        path: String,
    },
    /// A material file that cannot be read or parsed, or that holds a value out of range; the
    /// message names the field.
    #[error("{path}: {message}")]
    MaterialFile {
        /// Path of the file.
        path: String,
        /// What is wrong with it (`density = -930: must be > 0 and finite (kg/m^3)`).
        message: String,
    },
}
