//! The grid of a sweep: its axes ([`Grid`]), its points in grid order ([`Point`]) and its unit of
//! work ([`Chunk`]), with the crack laws of its k values built once ([`Laws`]).

use super::Row;
use crate::laws::{v_frag, TVisLaw};
use crate::stick::{sticking_thresholds, Hint, HintChain, SearchOptions, StickingThresholds};
use crate::ThresholdsError;
use contact::{Contact, Geometry, Material};
use greenwood::CrackLaw;
use numerics::OutOfRange;
use std::collections::BTreeMap;

/// One material of a sweep: its name (as given: a preset or a file path) and its constants.
#[derive(Debug, Clone, PartialEq)]
pub struct NamedMaterial {
    /// The name as given (`co2`, `h2o`, a path).
    pub name: String,
    /// The constants (SI).
    pub material: Material,
}

/// The second body of every point of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub enum Partner {
    /// Identical spheres: R2 = R1.
    Same,
    /// Spheres of these radii R2 (m): an axis of the grid.
    Radii(Vec<f64>),
    /// A flat wall.
    Wall,
}

/// Where the relaxation times come from.
#[derive(Debug, Clone, PartialEq)]
pub enum TVisAxis {
    /// These T_vis (s): an axis of the grid.
    Values(Vec<f64>),
    /// T_vis from a size law of R1 (Section 5.3): one value per radius.
    Law(TVisLaw),
}

/// The axes of a sweep (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Materials (outermost axis).
    pub materials: Vec<NamedMaterial>,
    /// Surface free energies gamma_SV (J/m^2) replacing each material's; `None`: the material's.
    pub gamma_sv: Option<Vec<f64>>,
    /// Radii R1 (m).
    pub radius: Vec<f64>,
    /// The second body.
    pub partner: Partner,
    /// Relaxation times.
    pub t_vis: TVisAxis,
    /// Modulus ratios k (innermost axis).
    pub k: Vec<f64>,
}

/// One point of the grid: the inputs of one search (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Index of the point in grid order.
    pub index: usize,
    /// Index into [`Grid::materials`].
    pub material: usize,
    /// The material constants after the gamma_SV axis.
    pub constants: Material,
    /// The two bodies.
    pub geometry: Geometry,
    /// Relaxation time (s).
    pub t_vis: f64,
    /// Modulus ratio k.
    pub k: f64,
}

/// All T_vis of one combination of the other axes: the unit of work of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Chunk {
    /// The points, in increasing order of the T_vis axis.
    pub points: Vec<Point>,
    /// A warning for each of its rows beyond the contact's own: T_vis from the size law of the
    /// other ice ([`TVisLaw::mismatch`]).
    pub caution: Option<String>,
}

/// The most points a grid may have: 1e9 (a CSV row is about 150 bytes, so 150 GB of output,
/// and hours of work even where the master tables answer every point); a larger grid is
/// refused before any work ([`Grid::validate`]) rather than exhausting the memory.
pub const MAX_GRID_POINTS: usize = 1_000_000_000;

/// Why a grid is refused before any work ([`Grid::validate`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GridError {
    /// A value of an axis out of its range.
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// More points than [`MAX_GRID_POINTS`]; `axis` is the longest axis.
    #[error("{}", self.message_for(self.field()))]
    TooLarge {
        /// The longest axis (its input name: `radius`, `t_vis`, `k`, ...).
        axis: &'static str,
        /// Its number of values.
        length: usize,
        /// The grid's number of points (the product of the axes' lengths).
        points: f64,
    },
}

impl GridError {
    /// The input the refusal names: the axis out of range, or the longest axis.
    pub fn field(&self) -> &'static str {
        match self {
            GridError::OutOfRange(o) => o.field,
            GridError::TooLarge { axis, .. } => axis,
        }
    }

    /// The message with the input under another name (a command-line flag).
    pub fn message_for(&self, name: &str) -> String {
        match self {
            GridError::OutOfRange(o) => o.message_for(name),
            GridError::TooLarge { length, points, .. } => format!(
                "{name}: {length} values make a grid of {points:.0} points (the product of the \
                 axes' lengths); at most {MAX_GRID_POINTS}"
            ),
        }
    }
}

fn check_axis(
    field: &'static str,
    values: &[f64],
    ok: impl Fn(f64) -> bool,
    allowed: &'static str,
    unit: &'static str,
) -> Result<(), OutOfRange> {
    if values.is_empty() {
        return Err(OutOfRange::new(field, f64::NAN, "at least one value", unit));
    }
    match values.iter().find(|v| !ok(**v)) {
        Some(&v) => Err(OutOfRange::new(field, v, allowed, unit)),
        None => Ok(()),
    }
}

impl Grid {
    fn n_gamma(&self) -> usize {
        self.gamma_sv.as_ref().map_or(1, Vec::len)
    }

    fn n_radius2(&self) -> usize {
        match &self.partner {
            Partner::Radii(r) => r.len(),
            _ => 1,
        }
    }

    fn n_t_vis(&self) -> usize {
        match &self.t_vis {
            TVisAxis::Values(t) => t.len(),
            TVisAxis::Law(_) => 1,
        }
    }

    /// Each axis by its input's name with its length, outermost first: the grid is their
    /// product.
    fn axis_lengths(&self) -> [(&'static str, usize); 6] {
        [
            ("material", self.materials.len()),
            ("gamma_sv", self.n_gamma()),
            ("radius", self.radius.len()),
            ("radius2", self.n_radius2()),
            ("t_vis", self.n_t_vis()),
            ("k", self.k.len()),
        ]
    }

    /// Number of points (`usize::MAX` where the product overflows: [`Grid::validate`] refuses
    /// such a grid).
    pub fn len(&self) -> usize {
        self.axis_lengths()
            .iter()
            .fold(1usize, |p, l| p.saturating_mul(l.1))
    }

    /// Number of chunks: one per combination of every axis but T_vis ([`Grid::chunks`]).
    pub fn n_chunks(&self) -> usize {
        self.materials.len() * self.n_gamma() * self.radius.len() * self.n_radius2() * self.k.len()
    }

    /// Whether the grid has no point.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Checks every axis before any work: each non-empty, radii and T_vis finite and > 0
    /// (T_vis >= 0), 0 < k <= 0.9 ([`dynamics::collision_k`]), gamma_SV > 0, every material
    /// with its gamma_SV valid, and its Poisson ratio nonzero where a T_vis > 0 asks for
    /// collisions ([`dynamics::collision_poisson`]).
    pub fn validate(&self) -> Result<(), GridError> {
        if self.materials.is_empty() {
            return Err(
                OutOfRange::new("material", f64::NAN, "at least one material", "name").into(),
            );
        }
        // the axes' product before anything is made from it (their chunks, the points)
        if self.len() > MAX_GRID_POINTS {
            let lengths = self.axis_lengths();
            let (axis, length) = lengths
                .into_iter()
                .max_by_key(|l| l.1)
                .unwrap_or(("radius", 0));
            // in floating point: the product may overflow usize
            let points = lengths.iter().map(|l| l.1 as f64).product();
            return Err(GridError::TooLarge {
                axis,
                length,
                points,
            });
        }
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if let Some(g) = &self.gamma_sv {
            check_axis("gamma_sv", g, positive, "> 0 and finite", "J/m^2")?;
        }
        check_axis("radius", &self.radius, positive, "> 0 and finite", "m")?;
        if let Partner::Radii(r) = &self.partner {
            check_axis("radius2", r, positive, "> 0 and finite", "m")?;
        }
        if let TVisAxis::Values(t) = &self.t_vis {
            check_axis(
                "t_vis",
                t,
                |v| v.is_finite() && v >= 0.0,
                ">= 0 and finite",
                "s",
            )?;
        }
        check_axis(
            "k",
            &self.k,
            |v| dynamics::collision_k(v).is_ok(),
            dynamics::K_RANGE,
            "dimensionless",
        )?;
        for m in &self.materials {
            for g in self.gamma_values(m) {
                Material {
                    gamma_sv: g,
                    ..m.material
                }
                .validate()?;
            }
        }
        // T_vis = 0 alone (the JKR limit) integrates no collision
        let collisions = match &self.t_vis {
            TVisAxis::Values(t) => t.iter().any(|&t| t > 0.0),
            TVisAxis::Law(_) => true,
        };
        if collisions {
            for m in &self.materials {
                dynamics::collision_poisson(m.material.poisson)?;
            }
        }
        Ok(())
    }

    fn gamma_values(&self, m: &NamedMaterial) -> Vec<f64> {
        self.gamma_sv
            .clone()
            .unwrap_or_else(|| vec![m.material.gamma_sv])
    }

    /// The index of a point in grid order from its axis indices.
    pub fn index(&self, m: usize, g: usize, r: usize, r2: usize, t: usize, k: usize) -> usize {
        ((((m * self.n_gamma() + g) * self.radius.len() + r) * self.n_radius2() + r2)
            * self.n_t_vis()
            + t)
            * self.k.len()
            + k
    }

    /// The chunks of the grid, in grid order of their first points.
    pub fn chunks(&self) -> Vec<Chunk> {
        let mut out = Vec::new();
        for (mi, m) in self.materials.iter().enumerate() {
            for (gi, g) in self.gamma_values(m).into_iter().enumerate() {
                let constants = Material {
                    gamma_sv: g,
                    ..m.material
                };
                for (ri, &r1) in self.radius.iter().enumerate() {
                    for r2i in 0..self.n_radius2() {
                        let geometry = match &self.partner {
                            Partner::Same => Geometry::identical(r1),
                            Partner::Radii(r2) => Geometry::spheres(r1, r2[r2i]),
                            Partner::Wall => Geometry::wall(r1),
                        };
                        for (ki, &k) in self.k.iter().enumerate() {
                            let (t_values, caution) = match &self.t_vis {
                                TVisAxis::Values(t) => (t.clone(), None),
                                TVisAxis::Law(law) => {
                                    (vec![law.t_vis(r1)], law.mismatch(&constants))
                                }
                            };
                            let points = t_values
                                .into_iter()
                                .enumerate()
                                .map(|(ti, t_vis)| Point {
                                    index: self.index(mi, gi, ri, r2i, ti, ki),
                                    material: mi,
                                    constants,
                                    geometry,
                                    t_vis,
                                    k,
                                })
                                .collect();
                            out.push(Chunk { points, caution });
                        }
                    }
                }
            }
        }
        out
    }
}

/// The crack-law tables of a grid's k values, each built once and shared by every point and
/// thread (a clone shares the table).
///
/// # Example
/// ```
/// use thresholds::sweep::Laws;
/// let laws = Laws::new(&[0.01, 0.02, 0.01])?;
/// assert_eq!(laws.get(0.02)?.k(), 0.02);
/// assert!(laws.get(0.05).is_err()); // not among the grid's k
/// assert!(Laws::new(&[1.5]).is_err()); // the crack law's 0 < k < 1 (collisions: k <= 0.9)
/// # Ok::<(), thresholds::ThresholdsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Laws(BTreeMap<u64, CrackLaw>);

impl Laws {
    /// The tables of every distinct value in `k` (dimensionless, 0 < k < 1, the crack law's
    /// range; a grid's collisions need k <= 0.9, which [`Grid::validate`] checks).
    pub fn new(k: &[f64]) -> Result<Self, ThresholdsError> {
        let mut map = BTreeMap::new();
        for &x in k {
            if let std::collections::btree_map::Entry::Vacant(e) = map.entry(x.to_bits()) {
                e.insert(CrackLaw::new(x)?);
            }
        }
        Ok(Self(map))
    }

    /// The table of `k`; an error for a k it was not built with.
    pub fn get(&self, k: f64) -> Result<CrackLaw, ThresholdsError> {
        self.0.get(&k.to_bits()).cloned().ok_or_else(|| {
            OutOfRange::new("k", k, "one of the grid's k values", "dimensionless").into()
        })
    }
}

impl Chunk {
    /// Computes every point of the chunk.
    pub fn compute(
        &self,
        laws: &impl Fn(f64) -> Result<CrackLaw, ThresholdsError>,
        opts: &SearchOptions,
    ) -> Result<Vec<Row>, ThresholdsError> {
        self.compute_from(0, &[], laws, opts, &mut |_| {})
    }

    /// Computes the points from `start` on, calling `done` with each row as it is found.
    /// `previous` holds the thresholds of the points just before `start` (the last
    /// [`crate::HINT_NEIGHBOURS`] or fewer,
    /// as `(t_vis, hint)`, [`crate::sweep::hint_of`] of their rows; empty for a fresh chunk), which seed the first
    /// search as they would have in an uninterrupted run. `laws(k)` gives the crack law of a k
    /// (build each once and share it).
    pub fn compute_from(
        &self,
        start: usize,
        previous: &[(f64, Hint)],
        laws: &impl Fn(f64) -> Result<CrackLaw, ThresholdsError>,
        opts: &SearchOptions,
        done: &mut impl FnMut(&Row),
    ) -> Result<Vec<Row>, ThresholdsError> {
        let mut chain = HintChain::new(previous);
        let mut rows = Vec::with_capacity(self.points.len().saturating_sub(start));
        for p in self.points.iter().skip(start) {
            let contact = Contact::new(p.constants, p.geometry)?;
            let law = laws(p.k)?;
            let hint = chain.next(p.t_vis, contact.v_stick_jkr());
            let o = SearchOptions { hint, ..*opts };
            let th: StickingThresholds = sticking_thresholds(&contact, &law, p.t_vis, &o)?;
            let row = Row {
                point: p.clone(),
                v_stick: th.v_stick,
                v_double_onset: th.v_double_onset,
                v_stick_jkr: th.v_stick_jkr,
                v_frag: th.v_stick.map(v_frag),
                no_bouncing_below: th.no_bouncing_below(),
                warnings: contact
                    .warnings()
                    .iter()
                    .map(|w| w.to_string())
                    .chain(self.caution.clone())
                    .collect(),
                method: th.method,
            };
            chain.push(p.t_vis, th.as_hint());
            done(&row);
            rows.push(row);
        }
        Ok(rows)
    }
}
