//! Random points over the domain of the "Instant everywhere" issue, drawn alike by
//! `examples/table_accuracy.rs` (which measures the master tables there) and
//! `tests/master_table.rs` (which holds them to the search there; it includes this file), and
//! by the restitution tables' examples and tests (with their thresholds and impact speeds).

use thresholds::restitution::RestitutionTables;
use thresholds::{
    sticking_thresholds, Contact, CrackLaw, Geometry, MasterTables, Material, SearchOptions,
};

/// SplitMix64: a small deterministic generator, so that a run is repeatable.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [0, 1].
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }

    /// Log-uniform between `lo` and `hi`.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo * (hi / lo).powf(self.next())
    }

    /// One of `ks` at random (a table's own k).
    pub fn pick(&mut self, ks: &[f64]) -> f64 {
        ks[((self.next() * ks.len() as f64) as usize).min(ks.len() - 1)]
    }

    /// A k the restitution tables answer: log-uniform over their k range once their k cells
    /// are built ([`RestitutionTables::k_checked`]), else one of their own k.
    #[allow(dead_code)] // the restitution tables' example and test use it, the master tables' not
    pub fn restitution_k(&mut self) -> f64 {
        let tables = RestitutionTables::standard();
        let ks = tables.table_k();
        if tables.k_checked() {
            self.log_uniform(ks[0], ks[ks.len() - 1])
        } else {
            self.pick(ks)
        }
    }

    /// A k the tables answer: log-uniform over their k range where the k checks cover every
    /// interval between the tables, else one of the tables' own k (the tables are built one k at
    /// a time; `cargo xtask master-table --part kcheck` opens the intervals).
    pub fn answered_k(&mut self) -> f64 {
        let tables = MasterTables::standard();
        let (lo, hi) = tables.k_range();
        if tables.k_checked() {
            self.log_uniform(lo, hi)
        } else {
            let ks = tables.table_k();
            self.pick(ks)
        }
    }
}

/// One point of the domain.
pub struct Point {
    /// The material.
    pub material: Material,
    /// The bodies.
    pub geometry: Geometry,
    /// Their contact.
    pub contact: Contact,
    /// k.
    pub k: f64,
    /// T_vis (s).
    pub t_vis: f64,
}

impl Point {
    /// Where the master tables look the point up: x = log10 c_D, y = log10(c_D c_a) (from the
    /// product, as the library's answer takes it), and the default search limit as a ratio,
    /// f_max = v_max / V_stick,JKR.
    pub fn table_coordinates(&self) -> (f64, f64, f64) {
        let c_d = self.contact.drag_number(self.t_vis);
        let jkr = self.contact.v_stick_jkr();
        let f_max = SearchOptions::default().v_max_for(jkr) / jkr;
        (
            c_d.log10(),
            self.contact.drag_crack_product().log10(),
            f_max,
        )
    }

    /// The default search's V_stick and V_double_onset at `law`'s k and its search limit
    /// v_max (m/s); `None` where the search refuses the point (c_a above 3e10) or nothing
    /// bounces below the limit.
    #[allow(dead_code)] // the master tables' example and tests do not collide
    pub fn bouncing_thresholds(&self, law: &CrackLaw) -> Option<(f64, f64, f64)> {
        let opts = SearchOptions::default();
        let th = sticking_thresholds(&self.contact, law, self.t_vis, &opts).ok()?;
        let v_max = opts.v_max_for(self.contact.v_stick_jkr());
        Some((th.v_stick?, th.v_double_onset?, v_max))
    }

    /// How far below the cliff the point lies at `k`: x_s - x, with x_s the master tables' end
    /// curve at (y, k); `None` next to the kink of the end curves or outside their grid.
    #[allow(dead_code)] // only the restitution tables' example and test near the cliff ask
    pub fn below_cliff(&self, k: f64) -> Option<f64> {
        let (x, y, _) = self.table_coordinates();
        let end = MasterTables::standard().ends()?.at(y, k)?;
        Some(end.x_s - x)
    }
}

/// A point: gamma_SV (0.01-0.3 J/m^2), E (0.5-200 GPa), the density (500-5000 kg/m^3) and the
/// reduced radius R (5 nm - 1 cm) log-uniformly, nu (0.1-0.45) uniformly, two identical spheres
/// (R1 = 2R) or a sphere on a wall (R1 = R), k from what the tables answer
/// ([`Rng::answered_k`]) if `answered`, else log-uniformly from 0.005 to 0.05, and T_vis
/// log-uniformly from 1e-16 s to 1e-3 s.
pub fn draw(rng: &mut Rng, answered: bool) -> Point {
    let material = Material {
        gamma_sv: rng.log_uniform(0.01, 0.3),
        young: rng.log_uniform(0.5e9, 200e9),
        poisson: 0.1 + 0.35 * rng.next(),
        density: rng.log_uniform(500.0, 5000.0),
    };
    let r = rng.log_uniform(5e-9, 1e-2);
    let geometry = if rng.next() < 0.5 {
        Geometry::wall(r)
    } else {
        Geometry::identical(2.0 * r)
    };
    let k = if answered {
        rng.answered_k()
    } else {
        rng.log_uniform(0.005, 0.05)
    };
    Point {
        material,
        geometry,
        contact: Contact::new(material, geometry).expect("a valid contact"),
        k,
        t_vis: rng.log_uniform(1e-16, 1e-3),
    }
}

/// How far from the cliff (in x = log10 c_D) the restitution tables left every collision to
/// the ODE before their cells were checked at their quarters: the old
/// [`thresholds::restitution::CLIFF_MARGIN`].
#[allow(dead_code)] // only the restitution tables' example and test near the cliff use it
pub const OLD_CLIFF_MARGIN: f64 = 0.05;

/// An impact speed (m/s) just above `v_stick` (m/s): sigma = ln(V_in / V_stick) log-uniform
/// from 1e-4 to 1, where the rebound changes fast next to the cliff.
#[allow(dead_code)] // only the restitution tables' example and test near the cliff use it
pub fn just_above(rng: &mut Rng, v_stick: f64) -> f64 {
    v_stick * rng.log_uniform(1e-4, 1.0).exp()
}

/// An impact speed (m/s) around the thresholds `v_stick` and `v_on` (m/s) up to `v_max`: half
/// the time bouncing (ln(V_in/V_stick) log-uniform from 1e-4 to its largest), else a double
/// collision (V_in log-uniform between V_on and V_stick).
#[allow(dead_code)] // the restitution tables' example and test use it, the master tables' not
pub fn impact_speed(rng: &mut Rng, v_stick: f64, v_on: f64, v_max: f64) -> f64 {
    if rng.next() < 0.5 || v_on >= v_stick {
        let top = (v_max / v_stick).ln().max(2e-4);
        v_stick * rng.log_uniform(1e-4, top).exp()
    } else {
        rng.log_uniform(v_on, v_stick)
    }
}

/// The points `(x, y, k)` of `table_accuracy`'s draw of the whole domain that `tables` decline
/// at the default search limit: `TABLE_N` points (default 2e4) of the generator seeded with
/// `TABLE_SEED` (default 2026), as `table_accuracy` draws them.
#[allow(dead_code)] // the probes of the declined points use it, the tests not
pub fn declined_draw(tables: &MasterTables) -> Vec<[f64; 3]> {
    let var =
        |name: &str, default: u64| std::env::var(name).map_or(default, |s| s.parse().unwrap());
    let mut rng = Rng(var("TABLE_SEED", 2026));
    (0..var("TABLE_N", 20000))
        .map(|_| draw(&mut rng, false))
        .filter_map(|p| {
            let (x, y, f_max) = p.table_coordinates();
            tables
                .ratios_at(x, y, p.k, f_max)
                .is_none()
                .then_some([x, y, p.k])
        })
        .collect()
}
