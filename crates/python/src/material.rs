//! `stickiness.Material`: the four SI constants of a grain material.

use crate::error::{value_error, Error};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyString, PyType};
use std::path::PathBuf;

/// The four material constants of the model, in SI units.
///
/// Parameters
/// ----------
/// gamma_sv : float or Quantity
///     Surface free energy gamma_SV (J/m^2, > 0). The contact uses the work of adhesion
///     gamma = 2 gamma_SV.
/// young : float or Quantity
///     Young's modulus E (Pa, > 0).
/// poisson : float
///     Poisson ratio nu (dimensionless, -1 < nu < 0.5; nonzero for a collision, whose drag is
///     A = T_vis/nu^2, Section 2.5).
/// density : float or Quantity
///     Density rho (kg/m^3, > 0).
///
/// Raises
/// ------
/// ValueError
///     A constant out of its range, or a Quantity of the wrong dimension (the message names it).
///
/// Notes
/// -----
/// ``Material.co2()`` and ``Material.h2o()`` are the paper's ices (Arakawa & Krijt 2021,
/// Section 3; CO2's E and nu from its sound speeds), ``Material.named(name_or_path)`` either of
/// them or a JSON file, ``Material.from_json(path)`` reads ``{"gamma_sv", "young", "poisson",
/// "density"}``. Materials compare by value, hash, and pickle.
///
/// Examples
/// --------
/// >>> import stickiness as st
/// >>> co2 = st.Material.co2()
/// >>> co2.gamma_sv, round(co2.young / 1e9, 3), co2.density
/// (0.08, 10.708, 1560.0)
/// >>> co2.replace(gamma_sv=0.1) == st.Material(0.1, co2.young, co2.poisson, co2.density)
/// True
#[pyclass(frozen, module = "stickiness", name = "Material", from_py_object)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Surface free energy gamma_SV (J/m^2).
    #[pyo3(get)]
    gamma_sv: f64,
    /// Young's modulus E (Pa).
    #[pyo3(get)]
    young: f64,
    /// Poisson ratio nu (dimensionless).
    #[pyo3(get)]
    poisson: f64,
    /// Density rho (kg/m^3).
    #[pyo3(get)]
    density: f64,
}

impl From<thresholds::Material> for Material {
    fn from(m: thresholds::Material) -> Self {
        Self {
            gamma_sv: m.gamma_sv,
            young: m.young,
            poisson: m.poisson,
            density: m.density,
        }
    }
}

/// `value` in SI: a number, or an `astropy.units.Quantity` converted to `unit` (astropy's
/// spelling; `""` is dimensionless), a quantity of another dimension a `ValueError` naming the
/// constant and its unit.
fn si(value: &Bound<'_, PyAny>, name: &str, unit: &str) -> PyResult<f64> {
    if value.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected a number, got a bool"
        )));
    }
    if value.hasattr("unit")? && value.hasattr("to_value")? {
        let shown = if unit.is_empty() {
            "dimensionless"
        } else {
            unit
        };
        return match value.call_method1("to_value", (unit,)) {
            Ok(v) => v.extract::<f64>().map_err(|_| {
                PyTypeError::new_err(format!("{name}: expected one number, got an array"))
            }),
            Err(_) => Err(PyValueError::new_err(format!(
                "{name}: expected a quantity in {shown} (or convertible to it), got {}",
                value.getattr("unit")?
            ))),
        };
    }
    value.extract::<f64>().map_err(|_| {
        let kind = value
            .get_type()
            .name()
            .map_or("?".into(), |n| n.to_string());
        PyTypeError::new_err(format!("{name}: expected a number, got {kind}"))
    })
}

/// [`si`] for an optional constant.
fn si_option(value: Option<&Bound<'_, PyAny>>, name: &str, unit: &str) -> PyResult<Option<f64>> {
    value.map(|v| si(v, name, unit)).transpose()
}

impl Material {
    /// The library's material (SI).
    pub(crate) fn inner(&self) -> thresholds::Material {
        thresholds::Material {
            gamma_sv: self.gamma_sv,
            young: self.young,
            poisson: self.poisson,
            density: self.density,
        }
    }

    fn checked(inner: thresholds::Material) -> PyResult<Self> {
        inner.validate().map_err(|e| value_error(&e))?;
        Ok(inner.into())
    }
}

#[pymethods]
impl Material {
    #[new]
    #[pyo3(signature = (gamma_sv, young=None, poisson=None, density=None))]
    fn new(
        gamma_sv: &Bound<'_, PyAny>,
        young: Option<&Bound<'_, PyAny>>,
        poisson: Option<&Bound<'_, PyAny>>,
        density: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        // a name or a file alone where the four numbers belong: say which call takes it
        let alone = young.is_none() && poisson.is_none() && density.is_none();
        let call = if gamma_sv.is_instance_of::<PyString>() {
            Some("named")
        } else if gamma_sv.hasattr("__fspath__")? {
            Some("from_json")
        } else {
            None
        };
        if let Some(call) = call.filter(|_| alone) {
            return Err(PyTypeError::new_err(format!(
                "Material({0}): Material takes the four constants gamma_sv (J/m^2), young (Pa), \
                 poisson and density (kg/m^3); for a preset ({1}) or a JSON file use \
                 Material.{call}({0})",
                gamma_sv.repr()?,
                thresholds::PRESETS
            )));
        }
        let missing: Vec<&str> = [("young", young), ("poisson", poisson), ("density", density)]
            .iter()
            .filter(|(_, v)| v.is_none())
            .map(|(name, _)| *name)
            .collect();
        let (Some(young), Some(poisson), Some(density)) = (young, poisson, density) else {
            return Err(PyTypeError::new_err(format!(
                "Material() missing {}: it takes the four constants gamma_sv (J/m^2), young (Pa), \
                 poisson and density (kg/m^3)",
                missing.join(", ")
            )));
        };
        Self::checked(thresholds::Material {
            gamma_sv: si(gamma_sv, "gamma_sv", "J/m2")?,
            young: si(young, "young", "Pa")?,
            poisson: si(poisson, "poisson", "")?,
            density: si(density, "density", "kg/m3")?,
        })
    }

    /// CO2 ice (Section 3): gamma_SV = 0.08 J/m^2; E = 10.708 GPa and nu = 0.26066 from the
    /// sound speeds 2900 and 1650 m/s at rho = 1560 kg/m^3.
    ///
    /// Returns
    /// -------
    /// Material
    #[staticmethod]
    fn co2() -> Self {
        thresholds::Material::co2().into()
    }

    /// H2O ice (Sections 3, 5.2): gamma_SV = 0.1 J/m^2, E = 7 GPa, nu = 0.25, rho = 930 kg/m^3.
    ///
    /// Returns
    /// -------
    /// Material
    #[staticmethod]
    fn h2o() -> Self {
        thresholds::Material::h2o().into()
    }

    /// A preset by name or a material file.
    ///
    /// Parameters
    /// ----------
    /// name : str
    ///     ``'co2'`` or ``'h2o'`` (any case), or the path of a JSON material file.
    ///
    /// Returns
    /// -------
    /// Material
    ///
    /// Raises
    /// ------
    /// OSError
    ///     No preset of that name and no such file.
    #[staticmethod]
    fn named(name: &str) -> PyResult<Self> {
        thresholds::Material::from_name_or_path(name)
            .map(Self::from)
            .map_err(|e| Error::from_contact(e, 0).into())
    }

    /// Reads a JSON material file.
    ///
    /// Parameters
    /// ----------
    /// path : str or os.PathLike
    ///     A file ``{"gamma_sv": .., "young": .., "poisson": .., "density": ..}`` (SI).
    ///
    /// Returns
    /// -------
    /// Material
    ///
    /// Raises
    /// ------
    /// FileNotFoundError
    ///     A missing file.
    /// ValueError
    ///     A bad or missing field (the message names the file and the field).
    #[staticmethod]
    fn from_json(path: PathBuf) -> PyResult<Self> {
        thresholds::Material::from_json_file(&path)
            .map(Self::from)
            .map_err(|e| Error::from_contact(e, 0).into())
    }

    /// A copy with some constants replaced, validated.
    ///
    /// Parameters
    /// ----------
    /// gamma_sv, young, poisson, density : float or Quantity, optional
    ///     The new values (SI: J/m^2, Pa, dimensionless, kg/m^3); the others are kept.
    ///
    /// Returns
    /// -------
    /// Material
    ///
    /// Examples
    /// --------
    /// >>> import stickiness as st
    /// >>> st.Material.h2o().replace(gamma_sv=0.19).gamma_sv
    /// 0.19
    #[pyo3(signature = (*, gamma_sv=None, young=None, poisson=None, density=None))]
    fn replace(
        &self,
        gamma_sv: Option<&Bound<'_, PyAny>>,
        young: Option<&Bound<'_, PyAny>>,
        poisson: Option<&Bound<'_, PyAny>>,
        density: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let m = self.inner();
        Self::checked(thresholds::Material {
            gamma_sv: si_option(gamma_sv, "gamma_sv", "J/m2")?.unwrap_or(m.gamma_sv),
            young: si_option(young, "young", "Pa")?.unwrap_or(m.young),
            poisson: si_option(poisson, "poisson", "")?.unwrap_or(m.poisson),
            density: si_option(density, "density", "kg/m3")?.unwrap_or(m.density),
        })
    }

    fn __repr__(&self) -> String {
        use numerics::format::number;
        format!(
            "Material(gamma_sv={}, young={}, poisson={}, density={})",
            number(self.gamma_sv),
            number(self.young),
            number(self.poisson),
            number(self.density)
        )
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<Material>().is_ok_and(|o| o.get() == self)
    }

    fn __hash__(&self) -> u64 {
        [self.gamma_sv, self.young, self.poisson, self.density]
            .iter()
            .fold(0xcbf2_9ce4_8422_2325u64, |h, x| {
                (h ^ x.to_bits()).wrapping_mul(0x0100_0000_01b3)
            })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> (Bound<'py, PyType>, (f64, f64, f64, f64)) {
        (
            py.get_type::<Material>(),
            (self.gamma_sv, self.young, self.poisson, self.density),
        )
    }
}
