//! Size-dependent relaxation times (Section 5.3) and the fragmentation velocity (Section 6).

use crate::stick::{sticking_thresholds, SearchOptions};
use crate::ThresholdsError;
use contact::{Contact, Material};
use greenwood::CrackLaw;

/// `V_frag = 10 V_stick` (Section 6, Eq. vfrag; from C ~ 15 and E_break ~ 1.54 F_crit delta_crit).
pub const V_FRAG_FACTOR: f64 = 10.0;

/// Fragmentation velocity of aggregates of monomers with sticking velocity `v_stick` (m/s):
/// `V_frag = 10 V_stick` (m/s). With `v_stick = V_stick,JKR` this is V_frag,JKR.
///
/// # Example
/// ```
/// use thresholds::{v_frag, Contact, Geometry, Material};
/// // Section 7.1: V_frag,JKR = 2.96e-1 m/s for aggregates of CO2 monomers of R1 = 30 um
/// let c = Contact::new(Material::co2(), Geometry::identical(30e-6))?;
/// assert!((v_frag(c.v_stick_jkr()) / 0.296 - 1.0).abs() < 0.002);
/// # Ok::<(), thresholds::ContactError>(())
/// ```
pub fn v_frag(v_stick: f64) -> f64 {
    V_FRAG_FACTOR * v_stick
}

/// V_frag of aggregates and V_stick of their monomers at one relaxation time (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fragmentation {
    /// V_frag = 10 V_stick (m/s); `None` without bouncing below `no_bouncing_below`.
    pub v_frag: Option<f64>,
    /// V_stick of the monomers (m/s); `None` as `v_frag`.
    pub v_stick: Option<f64>,
    /// The relaxation time used (s); 0 is the JKR limit.
    pub t_vis: f64,
    /// V_frag,JKR = 10 V_stick,JKR (m/s).
    pub v_frag_jkr: f64,
    /// V_stick,JKR (m/s).
    pub v_stick_jkr: f64,
    /// Highest speed searched when no collision bounced (m/s), else `None`.
    pub no_bouncing_below: Option<f64>,
    /// Which answered: the exact search or the master table.
    pub method: crate::ThresholdMethod,
}

/// V_frag = 10 V_stick of aggregates of the monomers of `contact` at relaxation time `t_vis`
/// (s, >= 0; 0 is the JKR limit), Section 6. (Python's `stickiness.v_frag` and the CLI's
/// `v-frag` are this; [`v_frag`] is the factor alone.)
///
/// # Example
/// ```
/// use thresholds::{fragmentation, Contact, CrackLaw, Geometry, Material, SearchOptions, TVisLaw};
/// // aggregates of CO2 monomers of 0.1 um, T_vis from the size law of Section 5.3
/// let r1 = 0.1e-6;
/// let c = Contact::new(Material::co2(), Geometry::identical(r1))?;
/// let law = CrackLaw::new(0.01)?;
/// let f = fragmentation(&c, &law, TVisLaw::Co2.t_vis(r1), &SearchOptions::default())?;
/// let v_frag = f.v_frag.unwrap(); // 50.885 m/s (at 1650 kg/m^3: 49.02)
/// // Section 5.4: above its JKR limit 10 V_stick,JKR, and within a factor of a few of it
/// assert!(v_frag > 10.0 * c.v_stick_jkr() && v_frag < 3.0 * f.v_frag_jkr);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[doc(alias = "V_frag")]
pub fn fragmentation(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: f64,
    opts: &SearchOptions,
) -> Result<Fragmentation, ThresholdsError> {
    let th = sticking_thresholds(contact, law, t_vis, opts)?;
    Ok(Fragmentation {
        v_frag: th.v_stick.map(v_frag),
        v_stick: th.v_stick,
        t_vis,
        v_frag_jkr: v_frag(th.v_stick_jkr),
        v_stick_jkr: th.v_stick_jkr,
        no_bouncing_below: th.no_bouncing_below(),
        method: th.method,
    })
}

/// The empirical size laws `T_vis ∝ R1^1.11` of Section 5.3.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TVisLaw {
    /// `T_vis,CO2 = 1e-11 s (R1 / 1 um)^1.11` (Eq. T_vis_R1_CO2).
    Co2,
    /// `T_vis,H2O = 1e-10 s (R1 / 1.5 um)^1.11` (Eq. T_vis_R1_H2O, Gundlach et al. 2015).
    H2o,
}

/// Exponent of the size laws (Gundlach et al. 2015).
pub const T_VIS_EXPONENT: f64 = 1.11;

/// Names of the size laws, for messages.
pub const T_VIS_LAWS: &str = "co2, h2o";

impl TVisLaw {
    /// The law by name: `co2` or `h2o` (case-insensitive).
    pub fn from_name(name: &str) -> Option<Self> {
        match name.to_ascii_lowercase().as_str() {
            "co2" => Some(Self::Co2),
            "h2o" => Some(Self::H2o),
            _ => None,
        }
    }

    /// The law's name: `co2` or `h2o`.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Co2 => "co2",
            Self::H2o => "h2o",
        }
    }

    /// `(T_vis at the reference radius (s), reference radius (m))`.
    pub fn reference(&self) -> (f64, f64) {
        match self {
            Self::Co2 => (1e-11, 1e-6),
            Self::H2o => (1e-10, 1.5e-6),
        }
    }

    /// Relaxation time T_vis (s) of a grain of radius `r1` (m).
    ///
    /// The law is a power of `r1`, meant for `r1 > 0` and finite: a negative `r1` gives NaN,
    /// which a collision or search then refuses by name (`t_vis = NaN: must be > 0 ...`), `r1
    /// = 0` gives 0 (the JKR limit, which a threshold answers as such) and an infinite `r1`
    /// infinity. The CLI, Python and the sweeps check the radius first.
    ///
    /// # Example
    /// ```
    /// use thresholds::TVisLaw;
    /// // Section 5.3: T_vis,H2O = 9.4e-9 s at R1 = 90 um
    /// assert!((TVisLaw::H2o.t_vis(90e-6) / 9.4e-9 - 1.0).abs() < 0.005);
    /// ```
    pub fn t_vis(&self, r1: f64) -> f64 {
        let (t_ref, r_ref) = self.reference();
        t_ref * (r1 / r_ref).powf(T_VIS_EXPONENT)
    }

    /// The ice whose relaxation times the law was fitted to, with the constants of Section 3.
    pub fn ice(&self) -> Material {
        match self {
            Self::Co2 => Material::co2(),
            Self::H2o => Material::h2o(),
        }
    }

    /// A caution when `material` holds the constants of the other ice of Section 3: the size
    /// law of one ice applied to grains of the other, most often a slip (`co2` grains with
    /// `t_vis_law = h2o`). `None` for the law's own ice and for any other material, whose
    /// T_vis the user is free to take from either law. The CLI and Python show it as a warning.
    ///
    /// # Example
    /// ```
    /// use thresholds::{Material, TVisLaw};
    /// assert!(TVisLaw::H2o.mismatch(&Material::co2()).unwrap().contains("t_vis_law = 'h2o'"));
    /// assert_eq!(TVisLaw::Co2.mismatch(&Material::co2()), None);
    /// assert_eq!(TVisLaw::Co2.mismatch(&Material { density: 1000.0, ..Material::h2o() }), None);
    /// ```
    pub fn mismatch(&self, material: &Material) -> Option<String> {
        let other = match self {
            Self::Co2 => Self::H2o,
            Self::H2o => Self::Co2,
        };
        (*material == other.ice()).then(|| {
            format!(
                "t_vis_law = '{}' (the size law of {} ice, Section 5.3) is used with the constants \
                 of {} ice: t_vis_law = '{}' was probably meant",
                self.name(),
                self.name().to_uppercase(),
                other.name().to_uppercase(),
                other.name()
            )
        })
    }
}
