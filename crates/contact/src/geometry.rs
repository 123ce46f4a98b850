//! Which two bodies touch: two spheres (equal or not) or a sphere on a flat wall, all of one
//! material. The reduced radius and the reduced mass are derived here and nowhere else.
//!
//! ```text
//! R  = R1 R2 / (R1 + R2),   m* = m1 m2 / (m1 + m2),   m_i = 4 pi rho R_i^3 / 3
//! identical spheres (R2 = R1):  R = R1/2,  m* = m1/2         (Arakawa & Krijt 2021, Sec. 2.1, 2.5)
//! sphere on a wall (R2 -> inf): R = R1,    m* = m1
//! ```
//! `E* = E/(2(1 - nu^2))`, `gamma = 2 gamma_SV` and `T_vis` do not depend on the geometry: the
//! same material is on both sides.

use numerics::format::length;
use numerics::{positive, OutOfRange};
use std::f64::consts::PI;

/// The two bodies of a head-on contact, both of one material (SI: radii in m).
///
/// # Example
/// ```
/// use contact::Geometry;
/// let pair = Geometry::spheres(60e-6, 30e-6);
/// assert!((pair.reduced_radius() - 20e-6).abs() < 1e-18); // 60 * 30 / 90 um
/// assert_eq!(Geometry::identical(60e-6).reduced_radius(), 30e-6);
/// assert_eq!(Geometry::wall(60e-6).reduced_radius(), 60e-6);
/// assert_eq!(pair.to_string(), "two spheres of 60 um and 30 um");
/// assert_eq!(Geometry::wall(60e-6).to_string(), "a 60 um sphere on a wall");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Geometry {
    /// Two spheres of radii `r1` and `r2` (m); `r2 == r1` are the identical spheres of the paper.
    Spheres {
        /// Radius R1 of the first sphere (m).
        r1: f64,
        /// Radius R2 of the second sphere (m).
        r2: f64,
    },
    /// A sphere of radius `r1` (m) on a flat wall of the same material (R2 -> infinity, infinite
    /// mass), as in the laboratory experiments of Musiolik et al. (2016a,b).
    Wall {
        /// Radius R1 of the sphere (m).
        r1: f64,
    },
}

/// `a b / (a + b)` without overflow, and symmetric to the bit in its arguments: swapping two
/// spheres changes nothing. Equal arguments give `a / 2` exactly.
fn reduced(a: f64, b: f64) -> f64 {
    if a == b {
        return 0.5 * a;
    }
    let (small, large) = if a < b { (a, b) } else { (b, a) };
    small / (1.0 + small / large)
}

impl Geometry {
    /// Two identical spheres of radius `r1` (m): the geometry of the paper.
    pub fn identical(r1: f64) -> Self {
        Self::Spheres { r1, r2: r1 }
    }

    /// Two spheres of radii `r1` and `r2` (m).
    pub fn spheres(r1: f64, r2: f64) -> Self {
        Self::Spheres { r1, r2 }
    }

    /// A sphere of radius `r1` (m) on a flat wall.
    pub fn wall(r1: f64) -> Self {
        Self::Wall { r1 }
    }

    /// Checks the radii: finite and > 0 (`radius`, `radius2`).
    pub fn validate(&self) -> Result<(), OutOfRange> {
        positive("radius", self.r1(), "m")?;
        if let Some(r2) = self.r2() {
            positive("radius2", r2, "m")?;
        }
        Ok(())
    }

    /// Radius R1 of the (first) sphere (m).
    pub fn r1(&self) -> f64 {
        match *self {
            Self::Spheres { r1, .. } | Self::Wall { r1 } => r1,
        }
    }

    /// Radius R2 of the second sphere (m); `None` for a wall.
    pub fn r2(&self) -> Option<f64> {
        match *self {
            Self::Spheres { r2, .. } => Some(r2),
            Self::Wall { .. } => None,
        }
    }

    /// Whether the second body is a flat wall.
    pub fn is_wall(&self) -> bool {
        matches!(self, Self::Wall { .. })
    }

    /// Reduced radius `R = R1 R2/(R1 + R2)` (m): `R1/2` for identical spheres, `R1` on a wall.
    pub fn reduced_radius(&self) -> f64 {
        match *self {
            Self::Spheres { r1, r2 } => reduced(r1, r2),
            Self::Wall { r1 } => r1,
        }
    }

    /// Mass `4 pi rho R1^3 / 3` of the (first) sphere (kg) for density `density` (kg/m^3).
    pub fn m1(&self, density: f64) -> f64 {
        sphere_mass(self.r1(), density)
    }

    /// Reduced mass `m* = m1 m2/(m1 + m2)` (kg) for density `density` (kg/m^3): `m1/2` for
    /// identical spheres, `m1` on a wall.
    pub fn reduced_mass(&self, density: f64) -> f64 {
        match *self {
            Self::Spheres { r1, r2 } => reduced(sphere_mass(r1, density), sphere_mass(r2, density)),
            Self::Wall { r1 } => sphere_mass(r1, density),
        }
    }
}

/// Mass of a sphere of radius `r` (m) and density `density` (kg/m^3): `4 pi rho r^3 / 3` (kg).
fn sphere_mass(r: f64, density: f64) -> f64 {
    4.0 * PI * density * r.powi(3) / 3.0
}

impl Geometry {
    /// The geometry as the arguments that set it, for messages (SI): `radius = 6e-5 m`
    /// (identical spheres), `radius = 6e-5 m, radius2 = 3e-5 m`, `radius = 6e-5 m on a wall`;
    /// then the reduced radius R (m) the contact uses.
    ///
    /// ```
    /// use contact::Geometry;
    /// assert_eq!(Geometry::spheres(6e-5, 3e-5).as_arguments(),
    ///            "radius = 0.00006 m, radius2 = 0.00003 m: reduced radius R = 0.00002 m");
    /// ```
    pub fn as_arguments(&self) -> String {
        let n = numerics::format::number;
        let given = match *self {
            Self::Spheres { r1, r2 } if r1 == r2 => format!("radius = {} m", n(r1)),
            Self::Spheres { r1, r2 } => format!("radius = {} m, radius2 = {} m", n(r1), n(r2)),
            Self::Wall { r1 } => format!("radius = {} m on a wall", n(r1)),
        };
        format!("{given}: reduced radius R = {} m", n(self.reduced_radius()))
    }
}

impl std::fmt::Display for Geometry {
    /// `two identical spheres of 60 um`, `two spheres of 60 um and 30 um`, `a 60 um sphere on a wall`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::Spheres { r1, r2 } if r1 == r2 => {
                write!(f, "two identical spheres of {}", length(r1))
            }
            Self::Spheres { r1, r2 } => {
                write!(f, "two spheres of {} and {}", length(r1), length(r2))
            }
            Self::Wall { r1 } => write!(f, "a {} sphere on a wall", length(r1)),
        }
    }
}
