//! Conversion between SI and the nondimensional variables of [`crate::model`].

use crate::model::Params;
use contact::Contact;

/// The JKR-equilibrium units of one contact (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// Length unit of the contact radius, a_eq (m).
    pub a_eq: f64,
    /// Length unit of the mutual approach, delta_eq (m).
    pub delta_eq: f64,
    /// Time unit t0 = sqrt(m* delta_eq / F0), F0 = 3 pi gamma R (s).
    pub t0: f64,
    /// Speed unit V0 = delta_eq / t0 (m/s).
    pub v0: f64,
    /// Energy unit E0 = F0 delta_eq / 2 (J).
    pub e0: f64,
}

impl Scales {
    /// The units of `contact`.
    pub fn new(contact: &Contact) -> Self {
        let a_eq = contact.a_eq();
        let delta_eq = contact.delta_eq();
        let t0 = contact.t0();
        Self {
            a_eq,
            delta_eq,
            t0,
            v0: delta_eq / t0,
            e0: contact.f_crit() * delta_eq,
        }
    }

    /// Nondimensional parameters for relaxation time `t_vis` (s, > 0): lambda = c_a and c_D of
    /// [`Contact::dimensionless`].
    pub fn params(&self, contact: &Contact, t_vis: f64) -> Params {
        let d = contact.dimensionless(t_vis);
        Params {
            lambda: d.c_a,
            c_d: d.c_d,
            // F_c = lambda within [1, SPEED_CAP]: see crate::model, "Pseudo-time"
            speed_cap: d.c_a.clamp(1.0, crate::model::SPEED_CAP),
        }
    }
}
