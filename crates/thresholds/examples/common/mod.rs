//! The reference cases of the measurement examples: CO2 grains of 60 um (Section 5.1) and H2O
//! grains of 90 um (Section 5.2), two identical spheres each, at chosen relaxation times.

use thresholds::{Contact, Geometry, Material};

/// The cases of `tight_reference` and `tolerance_ladder`: CO2 from the JKR end (1e-14 s) to the
/// paper's fit (1e-9 s) and beyond, H2O at two T_vis.
pub const REFERENCE: &[(&str, f64)] = &[
    ("co2", 1e-14),
    ("co2", 1e-12),
    ("co2", 1e-11),
    ("co2", 1e-10),
    ("co2", 1e-9),
    ("co2", 1e-8),
    ("h2o", 1e-11),
    ("h2o", 1e-9),
];

/// `("CO2 60 um, T_vis = 1e-9 s", contact, t_vis)` for each `(material, t_vis)` of `list`
/// (`"co2"` or `"h2o"`, T_vis in s).
pub fn cases(list: &[(&str, f64)]) -> Vec<(String, Contact, f64)> {
    list.iter()
        .map(|&(name, t_vis)| {
            let (material, radius, label) = match name {
                "h2o" => (Material::h2o(), 90e-6, "H2O 90 um"),
                _ => (Material::co2(), 60e-6, "CO2 60 um"),
            };
            let contact =
                Contact::new(material, Geometry::identical(radius)).expect("a valid contact");
            (format!("{label}, T_vis = {t_vis:e} s"), contact, t_vis)
        })
        .collect()
}
