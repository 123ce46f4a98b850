//! The contact of two bodies of one material ([`Geometry`]): JKR equilibrium, forces, energies
//! (Section 2) and the JKR sticking and breaking energies (Sections 5.1 and 6).

use crate::{ContactError, Geometry, Material, Warning};
use numerics::format::number;
use numerics::{positive, OutOfRange};
use std::f64::consts::PI;

/// The JKR quantities of a contact as `(name, SI unit)` (an empty unit: dimensionless, the Tabor
/// parameter), in the order the CLI's `jkr` and Python's `jkr` report them;
/// [`Contact::jkr_values`] gives their values.
pub const JKR_QUANTITIES: [(&str, &str); 8] = [
    ("a_eq", "m"),
    ("delta_eq", "m"),
    ("tabor", ""),
    ("f_crit", "N"),
    ("delta_crit", "m"),
    ("e_stick", "J"),
    ("e_break", "J"),
    ("v_stick_jkr", "m/s"),
];
/// Range of action of the surface forces, epsilon = 0.3 nm (Section 2.2, after Krijt et al. 2013), in m.
pub const SURFACE_FORCE_RANGE: f64 = 0.3e-9;

/// Coefficient of `V_stick,JKR = (14.18 / m*)^(1/2) (gamma^5 R^4 / E*^2)^(1/6)` (Thornton & Ning 1998;
/// Section 5.1), dimensionless.
pub const THORNTON_NING_14_18: f64 = 14.18;

/// `E_break,JKR = 1.54 F_crit delta_crit` (Section 6, Wada et al. 2007), dimensionless.
pub const E_BREAK_COEFF: f64 = 1.54;

/// Tabor parameter below which JKR theory is outside its validity (Section 2.2: it needs mu >> 1).
pub const TABOR_MIN: f64 = 1.0;

/// Grains of this radius (m) tell whether a contact's infinite units come from the material
/// constants or from its radius (`Contact::new`): a micron, well inside [`PLAUSIBLE_RADIUS`].
const UNITS_REFERENCE_RADIUS: f64 = 1e-6;

/// Head-on contact of two bodies ([`Geometry`]) made of one [`Material`].
///
/// Reduced quantities (Section 2.1): `R` and `m*` from the [`Geometry`] (`R1/2` and `m1/2` for
/// the paper's identical spheres), `E* = E / (2 (1 - nu^2))`, and the work of adhesion
/// `gamma = 2 gamma_SV` (Section 3.1), which is the gamma of every formula below. All inputs and
/// outputs are SI.
///
/// # Example
/// ```
/// use contact::{Contact, Geometry, Material};
/// let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
/// // Section 5.1: V_stick,JKR = 1.66e-2 m/s for CO2 grains of R1 = 60 um; Section 2.2: mu ~ 9.5
/// assert!((c.v_stick_jkr() - 1.66e-2).abs() < 5e-5);
/// assert!((c.tabor() - 9.5).abs() < 0.05);
/// // the JKR equilibrium is where the apparent surface energy equals gamma: beta = 1
/// assert!((c.beta(c.a_eq(), c.delta_eq()) - 1.0).abs() < 1e-12);
/// // on a wall, V_stick,JKR is 2^(1/6) times larger (R = R1, m* = m1)
/// let w = Contact::new(Material::co2(), Geometry::wall(60e-6))?;
/// assert!((w.v_stick_jkr() / c.v_stick_jkr() - 2f64.powf(1.0 / 6.0)).abs() < 1e-12);
/// # Ok::<(), contact::ContactError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    material: Material,
    geometry: Geometry,
    epsilon: f64,
    /// The JKR units and the quantities they are made of, computed once: every answer from
    /// the master tables asks for them (two cube roots, a power and some fifteen divisions each
    /// time they were recomputed).
    units: Units,
}

/// The JKR units of a contact (SI): a_eq (m), t0 (s), V_stick,JKR (m/s), with R (m), m* (kg)
/// and E* (Pa).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Units {
    reduced_radius: f64,
    m_star: f64,
    e_star: f64,
    a_eq: f64,
    t0: f64,
    v_stick_jkr: f64,
}

impl Contact {
    /// Contact of the bodies `geometry` (radii in m, > 0) made of `material` (validated), with
    /// the surface-force range epsilon = [`SURFACE_FORCE_RANGE`].
    pub fn new(material: Material, geometry: Geometry) -> Result<Self, ContactError> {
        material.validate()?;
        geometry.validate()?;
        let contact = Self::with_units(material, geometry);
        // valid constants can still be too far out for f64 (a radius of 1e300 m has an
        // infinite mass): refuse them here rather than let a search run on infinities
        if !contact.units_finite() {
            return Err(Self::units_out_of_range(material, geometry).into());
        }
        Ok(contact)
    }

    /// The constant at fault where a contact's units are not finite: a material constant when
    /// grains of [`UNITS_REFERENCE_RADIUS`] of that material have no finite units either (the
    /// first of gamma_sv, young and density that, set to CO2's, gives them finite units), else
    /// the radius (R2 if R1 alone, as identical spheres, is fine).
    fn units_out_of_range(material: Material, geometry: Geometry) -> OutOfRange {
        let finite = |m: Material, g: Geometry| Self::with_units(m, g).units_finite();
        let reference = Geometry::identical(UNITS_REFERENCE_RADIUS);
        let (g, e, rho) = (material.gamma_sv, material.young, material.density);
        let with = format!(
            "with gamma_sv = {} J/m^2, young = {} Pa, density = {} kg/m^3",
            number(g),
            number(e),
            number(rho)
        );
        let rule = format!("such that, {with}, the mass and the JKR units of a contact are finite");
        if !finite(material, reference) {
            let co2 = Material::co2();
            let mut fixed = [material; 3];
            fixed[0].gamma_sv = co2.gamma_sv;
            fixed[1].young = co2.young;
            fixed[2].density = co2.density;
            let constants = [
                ("gamma_sv", g, "J/m^2"),
                ("young", e, "Pa"),
                ("density", rho, "kg/m^3"),
            ];
            let at_fault = constants
                .into_iter()
                .zip(fixed)
                .find(|c| finite(c.1, reference));
            if let Some(((name, value, unit), _)) = at_fault {
                return OutOfRange::new(name, value, rule, unit);
            }
        }
        let alone = Self::with_units(material, Geometry::identical(geometry.r1()));
        let (name, value) = match geometry.r2() {
            Some(r2) if alone.units_finite() => ("radius2", r2),
            _ => ("radius", geometry.r1()),
        };
        OutOfRange::new(name, value, rule, "m")
    }

    /// The contact with its units computed (epsilon = [`SURFACE_FORCE_RANGE`]; not validated).
    fn with_units(material: Material, geometry: Geometry) -> Self {
        let nu = material.poisson;
        let mut c = Self {
            material,
            geometry,
            epsilon: SURFACE_FORCE_RANGE,
            units: Units {
                reduced_radius: geometry.reduced_radius(),
                m_star: geometry.reduced_mass(material.density),
                e_star: material.young / (2.0 * (1.0 - nu * nu)),
                a_eq: f64::NAN,
                t0: f64::NAN,
                v_stick_jkr: f64::NAN,
            },
        };
        // from R, m* and E* above
        c.units.a_eq = c.compute_a_eq();
        c.units.t0 = c.compute_t0();
        c.units.v_stick_jkr = c.compute_v_stick_jkr();
        c
    }

    /// Whether the reduced mass and the JKR units (a_eq, t0, V_stick,JKR) are finite and > 0.
    fn units_finite(&self) -> bool {
        [self.m_star(), self.a_eq(), self.t0(), self.v_stick_jkr()]
            .iter()
            .all(|u| u.is_finite() && *u > 0.0)
    }

    /// The same contact with another surface-force range epsilon (m, > 0).
    pub fn with_epsilon(mut self, epsilon: f64) -> Result<Self, ContactError> {
        positive("epsilon", epsilon, "m")?;
        self.epsilon = epsilon;
        Ok(self)
    }

    /// The material (SI).
    pub fn material(&self) -> &Material {
        &self.material
    }

    /// The two bodies (radii in m).
    pub fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// Particle radius R1 (m).
    pub fn r1(&self) -> f64 {
        self.geometry.r1()
    }

    /// Surface-force range epsilon (m).
    pub fn epsilon(&self) -> f64 {
        self.epsilon
    }

    /// Reduced radius R = R1 R2/(R1 + R2) (m): R1/2 for identical spheres, R1 on a wall.
    pub fn reduced_radius(&self) -> f64 {
        self.units.reduced_radius
    }

    /// Contact modulus E* = E / (2 (1 - nu^2)) (Pa).
    pub fn e_star(&self) -> f64 {
        self.units.e_star
    }

    /// Mass of the (first) particle m1 = 4 pi rho R1^3 / 3 (kg).
    pub fn m1(&self) -> f64 {
        self.geometry.m1(self.material.density)
    }

    /// Reduced mass m* = m1 m2/(m1 + m2) (kg): m1/2 for identical spheres, m1 on a wall.
    pub fn m_star(&self) -> f64 {
        self.units.m_star
    }

    /// Work of adhesion gamma = 2 gamma_SV (J/m^2).
    pub fn gamma(&self) -> f64 {
        2.0 * self.material.gamma_sv
    }

    /// Equilibrium contact radius a_eq = (9 pi gamma R^2 / (2 E*))^(1/3) (m) (Section 2.2).
    pub fn a_eq(&self) -> f64 {
        self.units.a_eq
    }

    fn compute_a_eq(&self) -> f64 {
        let r = self.reduced_radius();
        (9.0 * PI * self.gamma() * r * r / (2.0 * self.e_star())).cbrt()
    }

    /// Equilibrium mutual approach delta_eq = (3 pi^2 R gamma^2 / (4 E*^2))^(1/3) = a_eq^2 / (3R) (m).
    pub fn delta_eq(&self) -> f64 {
        let (g, e) = (self.gamma(), self.e_star());
        (3.0 * PI * PI * self.reduced_radius() * g * g / (4.0 * e * e)).cbrt()
    }

    /// Tabor parameter mu = (R gamma^2 / E*^2)^(1/3) / epsilon (dimensionless) (Section 2.2);
    /// JKR theory needs mu >> 1.
    pub fn tabor(&self) -> f64 {
        let (g, e) = (self.gamma(), self.e_star());
        (self.reduced_radius() * g * g / (e * e)).cbrt() / self.epsilon
    }

    /// Conditions under which the results of this contact should be read with care: a radius
    /// R1 (`radius`) or a different R2 (`radius2`) outside [`PLAUSIBLE_RADIUS`](crate::PLAUSIBLE_RADIUS),
    /// a material constant outside its plausible range ([`Warning::for_material`]), a Tabor
    /// parameter below [`TABOR_MIN`].
    pub fn warnings(&self) -> Vec<Warning> {
        let r2 = self.geometry.r2().filter(|&r2| r2 != self.r1());
        let mut out: Vec<Warning> = Warning::for_radius("radius", self.r1())
            .into_iter()
            .chain(r2.and_then(|r2| Warning::for_radius("radius2", r2)))
            .chain(Warning::for_material(&self.material))
            .collect();
        if self.tabor_below_min() {
            out.push(Warning::JkrOutsideValidity {
                tabor: self.tabor(),
            });
        }
        out
    }

    /// Whether [`Contact::warnings`] has any, without building them: an array of a million
    /// contacts from Python asks it of each (45 instructions an element instead of 150,
    /// callgrind).
    pub fn has_warnings(&self) -> bool {
        let r2 = self.geometry.r2().filter(|&r2| r2 != self.r1());
        Warning::for_radius("radius", self.r1()).is_some()
            || r2.is_some_and(|r2| Warning::for_radius("radius2", r2).is_some())
            || Warning::any_for_material(&self.material)
            || self.tabor_below_min()
    }

    /// Whether the Tabor parameter is below [`TABOR_MIN`], tested as mu^3 eps^3 = R gamma^2 /
    /// E*^2 < (TABOR_MIN eps)^3: without the cube root of [`Contact::tabor`].
    fn tabor_below_min(&self) -> bool {
        let (g, e) = (self.gamma(), self.e_star());
        self.reduced_radius() * g * g / (e * e) < (TABOR_MIN * self.epsilon).powi(3)
    }

    /// Pull-off force F_crit = 3 pi gamma R / 2 (N) (Section 6).
    pub fn f_crit(&self) -> f64 {
        1.5 * PI * self.gamma() * self.reduced_radius()
    }

    /// Critical pulling length delta_crit = (9/16)^(1/3) delta_eq (m) (Section 6).
    pub fn delta_crit(&self) -> f64 {
        (9.0f64 / 16.0).cbrt() * self.delta_eq()
    }

    /// JKR sticking velocity V_stick,JKR = (14.18/m*)^(1/2) (gamma^5 R^4 / E*^2)^(1/6) (m/s)
    /// (Thornton & Ning 1998; Section 5.1).
    pub fn v_stick_jkr(&self) -> f64 {
        self.units.v_stick_jkr
    }

    fn compute_v_stick_jkr(&self) -> f64 {
        let (g, e, r) = (self.gamma(), self.e_star(), self.reduced_radius());
        (THORNTON_NING_14_18 / self.m_star()).sqrt()
            * (g.powi(5) * r.powi(4) / (e * e)).powf(1.0 / 6.0)
    }

    /// Energy dissipated in a JKR bouncing collision E_stick,JKR = m* V_stick,JKR^2 / 2 (J)
    /// (Section 6; equals 0.9355 F_crit delta_crit to the rounding of 14.18).
    pub fn e_stick_jkr(&self) -> f64 {
        0.5 * self.m_star() * self.v_stick_jkr().powi(2)
    }

    /// Energy to break a contact at equilibrium E_break,JKR = 1.54 F_crit delta_crit (J) (Section 6).
    pub fn e_break_jkr(&self) -> f64 {
        E_BREAK_COEFF * self.f_crit() * self.delta_crit()
    }

    /// The values of [`JKR_QUANTITIES`] for this contact (SI), in its order.
    pub fn jkr_values(&self) -> [f64; 8] {
        [
            self.a_eq(),
            self.delta_eq(),
            self.tabor(),
            self.f_crit(),
            self.delta_crit(),
            self.e_stick_jkr(),
            self.e_break_jkr(),
            self.v_stick_jkr(),
        ]
    }

    /// Elastic force F_E = (2E*/(3R)) (3 a delta R - a^3) (N) at contact radius `a` (m) and mutual
    /// approach `delta` (m) (Section 2.5); positive is repulsive.
    pub fn f_e(&self, a: f64, delta: f64) -> f64 {
        let r = self.reduced_radius();
        2.0 * self.e_star() / (3.0 * r) * (3.0 * a * delta * r - a.powi(3))
    }

    /// Viscoelastic drag F_D = 2 A E* a delta_dot (N) with A = T_vis / nu^2 (s) (Section 2.5), at
    /// contact radius `a` (m), approach speed `delta_dot` (m/s) and relaxation time `t_vis` (s).
    pub fn f_d(&self, a: f64, delta_dot: f64, t_vis: f64) -> f64 {
        2.0 * self.drag_time(t_vis) * self.e_star() * a * delta_dot
    }

    /// Elastic strain energy U_E(a, delta) (J) (Section 2.1), written as
    /// `E* a [(delta - a^2/(3R))^2 + 4 a^4 / (45 R^2)]`, which is the paper's expression and shows U_E > 0.
    pub fn u_e(&self, a: f64, delta: f64) -> f64 {
        let r = self.reduced_radius();
        let d = delta - a * a / (3.0 * r);
        self.e_star() * a * (d * d + 4.0 * a.powi(4) / (45.0 * r * r))
    }

    /// Surface energy U_S = -pi a^2 gamma (J) at contact radius `a` (m) (Section 2.2).
    pub fn u_s(&self, a: f64) -> f64 {
        -PI * a * a * self.gamma()
    }

    /// Total mechanical energy of the collision `m* delta_dot^2 / 2 + U_E - pi a^2 gamma` (J).
    /// Under the model it never increases: F_D dissipates and the crack speed has the sign of
    /// `1 - beta`.
    pub fn total_energy(&self, a: f64, delta: f64, delta_dot: f64) -> f64 {
        0.5 * self.m_star() * delta_dot * delta_dot + self.u_e(a, delta) + self.u_s(a)
    }

    /// Apparent surface energy in equilibrium G_eff = E* (a^2 - delta R)^2 / (2 pi a R^2) (J/m^2)
    /// (Section 2.4).
    pub fn g_eff(&self, a: f64, delta: f64) -> f64 {
        let r = self.reduced_radius();
        let s = a * a - delta * r;
        self.e_star() * s * s / (2.0 * PI * a * r * r)
    }

    /// Normalized apparent surface energy beta = G_eff / gamma (dimensionless).
    pub fn beta(&self, a: f64, delta: f64) -> f64 {
        self.g_eff(a, delta) / self.gamma()
    }

    /// The JKR time unit `t0 = sqrt(m* delta_eq / F0)`, `F0 = 3 pi gamma R = 2 F_crit` (s): the
    /// time of the collision equations in JKR units (`docs/model.md`).
    pub fn t0(&self) -> f64 {
        self.units.t0
    }

    fn compute_t0(&self) -> f64 {
        let f0 = 2.0 * self.f_crit();
        (self.m_star() * self.delta_eq() / f0).sqrt()
    }

    /// Contact radius at first contact (delta = 0) where beta = (1 + eps) k:
    /// `a = [2 pi R^2 (1 + eps) k gamma / E*]^(1/3)` (m) (Section 4.1), for `k` and `eps` dimensionless.
    pub fn initial_contact_radius(&self, k: f64, eps: f64) -> f64 {
        let r = self.reduced_radius();
        (2.0 * PI * r * r * (1.0 + eps) * k * self.gamma() / self.e_star()).cbrt()
    }
}
