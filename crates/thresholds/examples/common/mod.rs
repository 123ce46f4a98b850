//! The reference cases of the measurement examples: CO2 grains of 60 um (Section 5.1) and H2O
//! grains of 90 um (Section 5.2), two identical spheres each, at chosen relaxation times.

use thresholds::{Contact, Geometry, Material};

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
