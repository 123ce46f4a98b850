//! Size-dependent relaxation times (Section 5.3) and the fragmentation velocity (Section 6).

/// `V_frag = 10 V_stick` (Section 6, Eq. vfrag; from C ~ 15 and E_break ~ 1.54 F_crit delta_crit).
pub const V_FRAG_FACTOR: f64 = 10.0;

/// Fragmentation velocity of aggregates of monomers with sticking velocity `v_stick` (m/s):
/// `V_frag = 10 V_stick` (m/s). With `v_stick = V_stick,JKR` this is V_frag,JKR.
pub fn v_frag(v_stick: f64) -> f64 {
    V_FRAG_FACTOR * v_stick
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

impl TVisLaw {
    /// The law by name: `co2` or `h2o` (case-insensitive).
    pub fn from_name(name: &str) -> Option<Self> {
        match name.to_ascii_lowercase().as_str() {
            "co2" => Some(Self::Co2),
            "h2o" => Some(Self::H2o),
            _ => None,
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
    pub fn t_vis(&self, r1: f64) -> f64 {
        let (t_ref, r_ref) = self.reference();
        t_ref * (r1 / r_ref).powf(T_VIS_EXPONENT)
    }
}
