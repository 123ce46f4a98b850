//! The two dimensionless numbers a collision depends on (Sections 2.3-2.5 in the JKR units of
//! `docs/model.md`), and the drag and crack-speed units they are made of:
//! ```text
//! A   = T_vis / nu^2                                   (drag coefficient, Sec. 2.5)
//! c_D = 2 A E* a_eq t0 / m*                            (drag number)
//! c_a = E* gamma t0 / (sigma0^2 T_vis a_eq),  sigma0 = gamma/epsilon   (crack-speed number, Sec. 2.3)
//! ```

use crate::Contact;

impl Contact {
    /// The drag coefficient A = T_vis / nu^2 (s) for relaxation time `t_vis` (s).
    pub fn drag_time(&self, t_vis: f64) -> f64 {
        let nu = self.material().poisson;
        t_vis / (nu * nu)
    }

    /// Attractive stress across the crack sigma0 = gamma / epsilon (Pa) (Section 2.3).
    pub fn sigma0(&self) -> f64 {
        self.gamma() / self.epsilon()
    }

    /// The crack-speed unit `E* gamma / (sigma0^2 T_vis)` (m/s): `a_dot = v(k, beta)` times this,
    /// for relaxation time `t_vis` (s, > 0) (Section 2.3).
    pub fn crack_speed_unit(&self, t_vis: f64) -> f64 {
        let s0 = self.sigma0();
        self.e_star() * self.gamma() / (s0 * s0 * t_vis)
    }

    /// The two dimensionless numbers of a collision at relaxation time `t_vis` (s, > 0): in JKR
    /// units the collision depends only on them, on k and on eps, so V_stick / V_stick,JKR is a
    /// function of `(c_D, c_a)` for every material, size and geometry (Sections 2.3-2.5):
    /// ```text
    /// c_D = 2 (T_vis/nu^2) E* a_eq t0 / m*          (drag)
    /// c_a = E* gamma t0 / (sigma0^2 T_vis a_eq)       (crack speed)
    /// ```
    /// `c_D` grows with T_vis and `c_a` falls as 1/T_vis; their product does not depend on
    /// T_vis or on the density.
    ///
    /// # Example
    /// ```
    /// use contact::{Contact, Geometry, Material};
    /// let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    /// let (a, b) = (c.dimensionless(1e-9), c.dimensionless(2e-9));
    /// assert!((b.c_d / a.c_d - 2.0).abs() < 1e-12 && (b.c_a / a.c_a - 0.5).abs() < 1e-12);
    /// // four times the density at twice T_vis: the same collision
    /// let dense = Contact::new(Material { density: 4.0 * 1560.0, ..Material::co2() }, Geometry::identical(60e-6))?;
    /// let d = dense.dimensionless(2e-9);
    /// assert!((d.c_d / a.c_d - 1.0).abs() < 1e-12 && (d.c_a / a.c_a - 1.0).abs() < 1e-12);
    /// # Ok::<(), contact::ContactError>(())
    /// ```
    pub fn dimensionless(&self, t_vis: f64) -> Dimensionless {
        Dimensionless {
            c_d: self.drag_number(t_vis),
            c_a: self.crack_speed_unit(t_vis) * self.t0() / self.a_eq(),
        }
    }

    /// The drag number c_D of [`Contact::dimensionless`] alone (dimensionless), for relaxation
    /// time `t_vis` (s): what the master tables need besides c_D c_a
    /// ([`Contact::drag_crack_product`]).
    pub fn drag_number(&self, t_vis: f64) -> f64 {
        2.0 * self.drag_time(t_vis) * self.e_star() * self.a_eq() * self.t0() / self.m_star()
    }

    /// The product c_D c_a of [`Contact::dimensionless`] (dimensionless), which does not depend
    /// on T_vis: `c_D c_a = 2 E*^2 gamma t0^2 / (nu^2 m* sigma0^2)`. The master tables' second
    /// axis y = log10(c_D c_a) taken from it is the same to the bit at every T_vis of a contact,
    /// so that an array at one radius finds its place along y once.
    ///
    /// # Example
    /// ```
    /// use contact::{Contact, Geometry, Material};
    /// let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    /// let d = c.dimensionless(1e-9);
    /// assert!((c.drag_crack_product() / (d.c_d * d.c_a) - 1.0).abs() < 1e-14);
    /// # Ok::<(), contact::ContactError>(())
    /// ```
    pub fn drag_crack_product(&self) -> f64 {
        let (e, nu, s0, t0) = (
            self.e_star(),
            self.material().poisson,
            self.sigma0(),
            self.t0(),
        );
        2.0 * e * e * self.gamma() * t0 * t0 / (nu * nu * self.m_star() * s0 * s0)
    }
}

/// The two dimensionless numbers of a collision ([`Contact::dimensionless`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimensionless {
    /// The drag number c_D = 2 (T_vis/nu^2) E* a_eq t0 / m* (dimensionless).
    pub c_d: f64,
    /// The crack-speed number c_a = E* gamma t0 / (sigma0^2 T_vis a_eq) (dimensionless), the
    /// `lambda` of the collision equations.
    pub c_a: f64,
}
