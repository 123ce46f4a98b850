//! The data of Figures 1-7 of Arakawa & Krijt (2021), and the sphere-on-wall figure, as typed
//! structs. Only parameter grids live here: every number comes from `greenwood`, `contact`,
//! `dynamics` and `thresholds`. Each figure writes its CSV tables ([`Figures::tables`]) and draws
//! itself from its own fields (`crate::plot`).

use crate::table::Table;
use contact::{Contact, Geometry, Material};
use dynamics::{Collider, Outcome, SolverOptions, TrajectoryPoint};
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use thresholds::sweep::geomspace;
use thresholds::{
    fit_t_vis, sticking_thresholds, sweep_t_vis, v_frag, SearchOptions, StickingThresholds,
    TVisFit, TVisLaw,
};

/// Any failure while computing a figure.
pub type Error = Box<dyn std::error::Error + Send + Sync>;

/// Grid density: `Full` for `data/`, `Reduced` for the snapshot tests.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resolution {
    /// The committed figures.
    Full,
    /// A few points per curve.
    Reduced,
}

impl Resolution {
    fn pick(&self, full: usize, reduced: usize) -> usize {
        match self {
            Resolution::Full => full,
            Resolution::Reduced => reduced,
        }
    }
}

/// Reports progress: `(figure, done, total)`.
pub type Progress<'a> = &'a (dyn Fn(&str, usize, usize) + Sync);

/// A measured threshold velocity for sticking, with its grain radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// Measured V_stick (m/s).
    pub v_stick: f64,
    /// Its uncertainty (m/s).
    pub err: f64,
    /// Typical grain radius R1 (m).
    pub r1: f64,
}

/// Musiolik et al. (2016a): CO2 grains of R1 ~ 60 um stick below 0.04 ± 0.02 m/s (Section 5.1).
pub const CO2_EXPERIMENT: Measurement = Measurement {
    v_stick: 0.04,
    err: 0.02,
    r1: 60e-6,
};
/// Musiolik et al. (2016b): H2O grains of R1 ~ 90 um stick below ~0.73 m/s (Section 5.2).
pub const H2O_EXPERIMENT: Measurement = Measurement {
    v_stick: 0.73,
    err: 0.0,
    r1: 90e-6,
};
/// Gundlach et al. (2015): T_vis = 1e-10 s for H2O grains of R1 = 1.5 um, `(R1 (m), T_vis (s))`.
pub const GUNDLACH_2015: (f64, f64) = (1.5e-6, 1e-10);
/// Maximum collision velocities of aggregates in weakly turbulent discs, 25-50 m/s (Section 6).
pub const V_COL_MAX: (f64, f64) = (25.0, 50.0);
/// The fiducial k of the paper (Section 2.3).
pub const K: f64 = 0.01;
/// The k values of Figures 1 and 4.
pub const KS: [f64; 4] = [0.005, 0.01, 0.02, 0.05];
/// Surface energies of Figure 5 (J/m^2): from Gundlach et al. (2018) to Gundlach et al. (2011).
pub const GAMMAS_H2O: [f64; 4] = [0.02, 0.05, 0.1, 0.19];
/// The V_in of the three trajectories of Figure 2 (m/s).
pub const FIG2_V_IN: [f64; 3] = [0.035, 0.0405, 0.045];
/// T_vis of Figures 2 and 3 (s).
pub const FIG2_T_VIS: f64 = 1e-9;

/// `n` points from `a` to `b`, evenly spaced.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}

/// Runs `f` over `items` on all cores, reporting progress, keeping the order.
fn par_map<T: Sync, R: Send>(
    name: &str,
    items: &[T],
    progress: Progress,
    f: impl Fn(&T) -> Result<R, Error> + Sync,
) -> Result<Vec<R>, Error> {
    let done = AtomicUsize::new(0);
    let total = items.len();
    progress(name, 0, total);
    items
        .par_iter()
        .map(|x| {
            let r = f(x);
            progress(name, done.fetch_add(1, Ordering::Relaxed) + 1, total);
            r
        })
        .collect()
}

fn material_line(name: &str, m: &Material) -> String {
    format!(
        "material = {name}: gamma_sv = {} J/m^2, young = {} Pa, poisson = {}, density = {} kg/m^3",
        number(m.gamma_sv),
        number(m.young),
        number(m.poisson),
        number(m.density)
    )
}

fn co2_contact(r1: f64) -> Result<Contact, Error> {
    Ok(Contact::new(Material::co2(), Geometry::identical(r1))?)
}

fn h2o_with(gamma_sv: f64) -> Material {
    Material {
        gamma_sv,
        ..Material::h2o()
    }
}

/// One curve of Figure 1: v(k, beta) over the full range and near beta = 1.
#[derive(Debug, Clone)]
pub struct CrackLawCurve {
    /// The modulus ratio k.
    pub k: f64,
    /// `(beta, v)` log-spaced over 1e-3 < beta < 1e3 within k < beta < 1/k.
    pub full: Vec<(f64, f64)>,
    /// `(beta, v)` in 0.95 <= beta <= 1.05.
    pub zoom: Vec<(f64, f64)>,
}

/// Figure 1: Greenwood's crack speed v(k, beta) for several k.
#[derive(Debug, Clone)]
pub struct Figure1 {
    /// One curve per k of [`KS`].
    pub curves: Vec<CrackLawCurve>,
}

impl Figure1 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let (n, nz) = (res.pick(300, 12), res.pick(101, 5));
        let curves = par_map("fig1", &KS, progress, |&k| -> Result<_, Error> {
            let law = CrackLaw::new(k)?;
            let lo = (k * (1.0 + 1e-9)).max(1e-3);
            let hi = (1.0 / k * (1.0 - 1e-9)).min(1e3);
            let eval = |betas: Vec<f64>| -> Result<Vec<(f64, f64)>, Error> {
                betas.into_iter().map(|b| Ok((b, law.v(b)?))).collect()
            };
            Ok(CrackLawCurve {
                k,
                full: eval(geomspace(lo, hi, n))?,
                zoom: eval(linspace(0.95, 1.05, nz))?,
            })
        })?;
        Ok(Self { curves })
    }

    /// `fig1.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "fig1.csv",
            vec![
                "Figure 1: Greenwood's normalized crack speed v(k, beta) (Arakawa & Krijt 2021, Appendix A)".into(),
                "panel = full: 1e-3 < beta < 1e3 within k < beta < 1/k; panel = zoom: 0.95 <= beta <= 1.05".into(),
                "units: k, beta, v dimensionless (v = sigma0^2 T_vis a_dot / (E* gamma))".into(),
            ],
            &["panel", "k", "beta", "v"],
        );
        for c in &self.curves {
            for (panel, pts) in [("full", &c.full), ("zoom", &c.zoom)] {
                for &(beta, v) in pts {
                    t.push(vec![panel.into(), c.k.into(), beta.into(), v.into()]);
                }
            }
        }
        vec![t]
    }
}

/// One trajectory of Figure 2.
#[derive(Debug, Clone)]
pub struct Trajectory {
    /// Impact speed (m/s).
    pub v_in: f64,
    /// Its outcome.
    pub outcome: Outcome,
    /// Resampled states (SI).
    pub points: Vec<TrajectoryPoint>,
}

/// Figure 2: trajectories for CO2, R1 = 60 um, T_vis = 1e-9 s at V_in = 3.5, 4.05, 4.5 cm/s.
#[derive(Debug, Clone)]
pub struct Figure2 {
    /// The contact (CO2, 60 um, identical spheres).
    pub contact: Contact,
    /// One run per V_in of [`FIG2_V_IN`].
    pub runs: Vec<Trajectory>,
}

impl Figure2 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let contact = co2_contact(CO2_EXPERIMENT.r1)?;
        let opts = SolverOptions {
            record_trajectory: true,
            // let the sticking trajectory spiral towards the JKR point before it is decided
            decide_after: 20e-6,
            ..Default::default()
        };
        let collider = Collider::new(contact, CrackLaw::new(K)?, FIG2_T_VIS)?.with_options(opts)?;
        let n = res.pick(400, 8);
        let runs = par_map("fig2", &FIG2_V_IN, progress, |&v_in| {
            let run = collider.collide(v_in)?;
            Ok(Trajectory {
                v_in,
                outcome: run.outcome,
                points: resample(&run.trajectory, &contact, n),
            })
        })?;
        Ok(Self { contact, runs })
    }

    /// `fig2.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let c = &self.contact;
        let mut t = Table::new(
            "fig2.csv",
            vec![
                "Figure 2: head-on collisions in the delta-a and delta-delta_dot planes (Section 4)"
                    .into(),
                material_line("co2", c.material()),
                format!(
                    "radius = {} m, t_vis = {} s, k = {}, eps = {}",
                    number(c.r1()),
                    number(FIG2_T_VIS),
                    number(K),
                    number(dynamics::EPS)
                ),
                format!(
                    "JKR equilibrium: a_eq = {} m, delta_eq = {} m, delta_dot = 0",
                    number(c.a_eq()),
                    number(c.delta_eq())
                ),
                "400 points a trajectory at equal steps of its path length in (a/a_eq, delta/delta_eq, delta_dot/V_stick,JKR)".into(),
                "units: v_in [m/s], t [s], a [m], delta [m], delta_dot [m/s]".into(),
            ],
            &["v_in", "outcome", "t", "a", "delta", "delta_dot"],
        );
        for run in &self.runs {
            for p in &run.points {
                t.push(vec![
                    run.v_in.into(),
                    run.outcome.as_str().into(),
                    p.t.into(),
                    p.a.into(),
                    p.delta.into(),
                    p.delta_dot.into(),
                ]);
            }
        }
        vec![t]
    }
}

/// `n` points at equal steps of the path length of a trajectory in the plane of
/// `(a/a_eq, delta/delta_eq, delta_dot/V_stick,JKR)`, linearly interpolated between solver steps:
/// the output does not depend on where the solver put its steps.
fn resample(traj: &[TrajectoryPoint], c: &Contact, n: usize) -> Vec<TrajectoryPoint> {
    let (sa, sd, sv) = (c.a_eq(), c.delta_eq(), c.v_stick_jkr());
    let mut length = vec![0.0];
    for w in traj.windows(2) {
        let d = ((w[1].a - w[0].a) / sa)
            .hypot((w[1].delta - w[0].delta) / sd)
            .hypot((w[1].delta_dot - w[0].delta_dot) / sv);
        length.push(length.last().copied().unwrap_or(0.0) + d);
    }
    let total = length.last().copied().unwrap_or(0.0);
    let mut out = Vec::with_capacity(n);
    let mut j = 0;
    for i in 0..n {
        let s = total * i as f64 / (n - 1).max(1) as f64;
        while j + 2 < length.len() && length[j + 1] < s {
            j += 1;
        }
        let (p, q) = (traj[j], traj[(j + 1).min(traj.len() - 1)]);
        let span = length[(j + 1).min(length.len() - 1)] - length[j];
        let f = if span > 0.0 {
            ((s - length[j]) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let mix = |x: f64, y: f64| x + f * (y - x);
        out.push(TrajectoryPoint {
            t: mix(p.t, q.t),
            a: mix(p.a, q.a),
            delta: mix(p.delta, q.delta),
            delta_dot: mix(p.delta_dot, q.delta_dot),
            energy: mix(p.energy, q.energy),
            beta: mix(p.beta, q.beta),
        });
    }
    out
}

/// One collision of Figure 3.
#[derive(Debug, Clone, Copy)]
pub struct Restitution {
    /// Impact speed (m/s).
    pub v_in: f64,
    /// Its outcome.
    pub outcome: Outcome,
    /// `-V_out/V_in` of the first contact (negative for double collisions, 0 for sticking).
    pub e_computed: f64,
}

impl Restitution {
    /// The e an experiment observes: `e_computed` for bouncing, 0 for sticking and double
    /// collisions (the second contact sticks, Section 4.4).
    pub fn e_observed(&self) -> f64 {
        if self.outcome == Outcome::Bouncing {
            self.e_computed
        } else {
            0.0
        }
    }
}

/// Figure 3: coefficient of restitution against V_in for CO2, R1 = 60 um, T_vis = 1e-9 s.
#[derive(Debug, Clone)]
pub struct Figure3 {
    /// The thresholds at T_vis = 1e-9 s (m/s).
    pub thresholds: StickingThresholds,
    /// Collisions in order of V_in.
    pub points: Vec<Restitution>,
}

impl Figure3 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let c = co2_contact(CO2_EXPERIMENT.r1)?;
        let th = sticking_thresholds(&c, &law, FIG2_T_VIS, &SearchOptions::default())?;
        let (vd, vs) = (
            th.v_double_onset.ok_or("no double collisions")?,
            th.v_stick.ok_or("no bouncing")?,
        );
        let mut v_in = linspace(0.02, 0.1, res.pick(161, 6));
        // resolve the narrow double-collision window
        v_in.extend(linspace(vd, vs, res.pick(42, 4)).into_iter().skip(1));
        v_in.retain(|v| (v - vd).abs() > 1e-9 * vd);
        v_in.sort_by(f64::total_cmp);
        let collider = Collider::new(c, law, FIG2_T_VIS)?;
        let points = par_map("fig3", &v_in, progress, |&v| {
            let r = collider.collide(v)?;
            Ok(Restitution {
                v_in: v,
                outcome: r.outcome,
                e_computed: r.e,
            })
        })?;
        Ok(Self {
            thresholds: th,
            points,
        })
    }

    /// The double-collision onset and V_stick (m/s).
    pub fn transitions(&self) -> (f64, f64) {
        let th = &self.thresholds;
        (
            th.v_double_onset.unwrap_or(f64::NAN),
            th.v_stick.unwrap_or(f64::NAN),
        )
    }

    /// `fig3.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let (vd, vs) = self.transitions();
        let mut t = Table::new(
            "fig3.csv",
            vec![
                "Figure 3: coefficient of restitution e against the impact speed V_in (Section 4.4)".into(),
                material_line("co2", &Material::co2()),
                format!(
                    "radius = {} m, t_vis = {} s, k = {}",
                    number(CO2_EXPERIMENT.r1),
                    number(FIG2_T_VIS),
                    number(K)
                ),
                format!("v_double_onset = {} m/s, v_stick = {} m/s", number(vd), number(vs)),
                "e: observed value (0 for sticking and double collisions); e_computed: -V_out/V_in of the first contact".into(),
                "units: v_in [m/s], e and e_computed dimensionless".into(),
            ],
            &["v_in", "outcome", "e", "e_computed"],
        );
        for p in &self.points {
            t.push(vec![
                p.v_in.into(),
                p.outcome.as_str().into(),
                p.e_observed().into(),
                p.e_computed.into(),
            ]);
        }
        vec![t]
    }
}

/// V_stick against T_vis for one value of a parameter (k, gamma_SV or the geometry).
#[derive(Debug, Clone)]
pub struct ThresholdCurve {
    /// The parameter of the curve (k, gamma_SV in J/m^2; 0 and 1 for identical spheres and a
    /// wall in the wall figure).
    pub parameter: f64,
    /// V_stick,JKR of the curve's contact (m/s).
    pub v_stick_jkr: f64,
    /// One search per T_vis, in increasing T_vis.
    pub points: Vec<StickingThresholds>,
}

impl ThresholdCurve {
    /// `(T_vis, V_stick)` where V_stick exists.
    pub fn v_stick(&self) -> Vec<(f64, f64)> {
        self.points
            .iter()
            .filter_map(|p| Some((p.t_vis, p.v_stick?)))
            .collect()
    }
}

/// Figure 4: V_stick against T_vis for several k, CO2, R1 = 60 um.
#[derive(Debug, Clone)]
pub struct Figure4 {
    /// One curve per k of [`KS`].
    pub curves: Vec<ThresholdCurve>,
}

impl Figure4 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let c = co2_contact(CO2_EXPERIMENT.r1)?;
        let t_vis = geomspace(1e-12, 1e-8, res.pick(33, 3));
        // one sweep over T_vis per k (each search seeded by its neighbour), the k in parallel
        let curves = par_map("fig4", &KS, progress, |&k| {
            Ok(ThresholdCurve {
                parameter: k,
                v_stick_jkr: c.v_stick_jkr(),
                points: sweep_t_vis(&c, &CrackLaw::new(k)?, &t_vis, &SearchOptions::default())?,
            })
        })?;
        Ok(Self { curves })
    }

    /// `fig4.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let e = CO2_EXPERIMENT;
        let mut t = Table::new(
            "fig4.csv",
            vec![
                "Figure 4: threshold velocity for sticking V_stick against T_vis for several k (Section 5.1)".into(),
                material_line("co2", &Material::co2()),
                format!(
                    "radius = {} m; experiment (Musiolik et al. 2016a): V_stick = {} +- {} m/s",
                    number(e.r1),
                    number(e.v_stick),
                    number(e.err)
                ),
                "units: k dimensionless, t_vis [s], v_stick, v_double_onset, v_stick_jkr [m/s]".into(),
            ],
            &["k", "t_vis", "v_stick", "v_double_onset", "v_stick_jkr"],
        );
        for c in &self.curves {
            for th in &c.points {
                t.push(vec![
                    c.parameter.into(),
                    th.t_vis.into(),
                    th.v_stick.into(),
                    th.v_double_onset.into(),
                    th.v_stick_jkr.into(),
                ]);
            }
        }
        vec![t]
    }
}

/// Figure 5: V_stick against T_vis for H2O, R1 = 90 um, several gamma_SV.
#[derive(Debug, Clone)]
pub struct Figure5 {
    /// One curve per gamma_SV of [`GAMMAS_H2O`].
    pub curves: Vec<ThresholdCurve>,
}

impl Figure5 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let t_vis = geomspace(1e-12, 1e-7, res.pick(41, 3));
        // one sweep over T_vis per gamma_SV (each search seeded by its neighbour), in parallel
        let curves = par_map("fig5", &GAMMAS_H2O, progress, |&g| {
            let c = Contact::new(h2o_with(g), Geometry::identical(H2O_EXPERIMENT.r1))?;
            Ok(ThresholdCurve {
                parameter: g,
                v_stick_jkr: c.v_stick_jkr(),
                points: sweep_t_vis(&c, &law, &t_vis, &SearchOptions::default())?,
            })
        })?;
        Ok(Self { curves })
    }

    /// `fig5.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "fig5.csv",
            vec![
                "Figure 5: V_stick against T_vis for H2O grains and several gamma_sv (Section 5.2)".into(),
                material_line("h2o (gamma_sv varied)", &Material::h2o()),
                format!(
                    "radius = {} m, k = {}; experiment (Musiolik et al. 2016b): V_stick ~ {} m/s",
                    number(H2O_EXPERIMENT.r1),
                    number(K),
                    number(H2O_EXPERIMENT.v_stick)
                ),
                "v_stick is empty where no collision bounces up to no_bouncing_below (the curve ends)".into(),
                "units: gamma_sv [J/m^2], t_vis [s], v_stick, v_double_onset, v_stick_jkr, no_bouncing_below [m/s]".into(),
            ],
            &["gamma_sv", "t_vis", "v_stick", "v_double_onset", "v_stick_jkr", "no_bouncing_below"],
        );
        for c in &self.curves {
            for th in &c.points {
                t.push(vec![
                    c.parameter.into(),
                    th.t_vis.into(),
                    th.v_stick.into(),
                    th.v_double_onset.into(),
                    th.v_stick_jkr.into(),
                    th.no_bouncing_below().into(),
                ]);
            }
        }
        vec![t]
    }
}

/// A relaxation time fitted to a measured V_stick, with its range.
#[derive(Debug, Clone, Copy)]
pub struct FittedTVis {
    /// `co2`, `h2o` or `gundlach2015`.
    pub source: &'static str,
    /// Grain radius R1 (m).
    pub r1: f64,
    /// Central T_vis (s).
    pub t_vis: f64,
    /// Lower end of the range (s).
    pub t_vis_min: f64,
    /// Upper end of the range (s).
    pub t_vis_max: f64,
}

/// Figure 6: fitted T_vis ranges against R1, the point of Gundlach et al. (2015), both size laws.
#[derive(Debug, Clone)]
pub struct Figure6 {
    /// The fitted points.
    pub fits: Vec<FittedTVis>,
    /// `(R1 (m), T_vis,CO2 (s), T_vis,H2O (s))` along the size laws.
    pub laws: Vec<(f64, f64, f64)>,
}

impl Figure6 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let opts = SearchOptions::default();
        let fits = par_map("fig6", &["co2", "h2o"], progress, |&name| {
            if name == "co2" {
                let e = CO2_EXPERIMENT;
                let f = fit_t_vis(&co2_contact(e.r1)?, &law, e.v_stick, e.err, &opts)?;
                Ok(FittedTVis {
                    source: "co2",
                    r1: e.r1,
                    t_vis: f.t_vis,
                    t_vis_min: f.t_vis_min,
                    t_vis_max: f.t_vis_max,
                })
            } else {
                // 0.73 m/s with 0.02 <= gamma_sv <= 0.19 J/m^2; central value at 0.1 J/m^2
                let e = H2O_EXPERIMENT;
                let fit = |g: f64| -> Result<f64, Error> {
                    let c = Contact::new(h2o_with(g), Geometry::identical(e.r1))?;
                    Ok(fit_t_vis(&c, &law, e.v_stick, e.err, &opts)?.t_vis)
                };
                Ok(FittedTVis {
                    source: "h2o",
                    r1: e.r1,
                    t_vis: fit(0.1)?,
                    t_vis_min: fit(GAMMAS_H2O[3])?,
                    t_vis_max: fit(GAMMAS_H2O[0])?,
                })
            }
        })?;
        let (r_g, t_g) = GUNDLACH_2015;
        let mut fits = fits;
        fits.push(FittedTVis {
            source: "gundlach2015",
            r1: r_g,
            t_vis: t_g,
            t_vis_min: t_g,
            t_vis_max: t_g,
        });
        let laws = geomspace(1e-7, 1e-3, res.pick(41, 3))
            .into_iter()
            .map(|r1| (r1, TVisLaw::Co2.t_vis(r1), TVisLaw::H2o.t_vis(r1)))
            .collect();
        Ok(Self { fits, laws })
    }

    /// `fig6_points.csv` and `fig6_laws.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let (c, h) = (CO2_EXPERIMENT, H2O_EXPERIMENT);
        let mut points = Table::new(
            "fig6_points.csv",
            vec![
                "Figure 6: relaxation times fitted to measured V_stick (Sections 5.1-5.3)".into(),
                format!(
                    "co2: R1 = {} m, V_stick = {} +- {} m/s (Musiolik et al. 2016a)",
                    number(c.r1),
                    number(c.v_stick),
                    number(c.err)
                ),
                format!(
                    "h2o: R1 = {} m, V_stick = {} m/s, gamma_sv from {} (t_vis_min) to {} J/m^2 (t_vis_max), 0.1 J/m^2 (t_vis)",
                    number(h.r1),
                    number(h.v_stick),
                    number(GAMMAS_H2O[3]),
                    number(GAMMAS_H2O[0])
                ),
                format!(
                    "gundlach2015: R1 = {} m, T_vis = {} s (Gundlach et al. 2015)",
                    number(GUNDLACH_2015.0),
                    number(GUNDLACH_2015.1)
                ),
                "units: r1 [m], t_vis, t_vis_min, t_vis_max [s]".into(),
            ],
            &["source", "r1", "t_vis", "t_vis_min", "t_vis_max"],
        );
        for f in &self.fits {
            points.push(vec![
                f.source.into(),
                f.r1.into(),
                f.t_vis.into(),
                f.t_vis_min.into(),
                f.t_vis_max.into(),
            ]);
        }
        let mut laws = Table::new(
            "fig6_laws.csv",
            vec![
                "Figure 6: size laws T_vis,CO2 = 1e-11 s (R1/1 um)^1.11 and T_vis,H2O = 1e-10 s (R1/1.5 um)^1.11 (Section 5.3)".into(),
                "units: r1 [m], t_vis_co2, t_vis_h2o [s]".into(),
            ],
            &["r1", "t_vis_co2", "t_vis_h2o"],
        );
        for &(r1, co2, h2o) in &self.laws {
            laws.push(vec![r1.into(), co2.into(), h2o.into()]);
        }
        vec![points, laws]
    }
}

/// One monomer radius of Figure 7.
#[derive(Debug, Clone, Copy)]
pub struct SizePoint {
    /// Monomer radius R1 (m).
    pub r1: f64,
    /// Thresholds with T_vis = T_vis,CO2(R1).
    pub co2: StickingThresholds,
    /// Thresholds with T_vis = T_vis,H2O(R1).
    pub h2o: StickingThresholds,
}

/// Figure 7: V_stick and V_frag against R1 for T_vis,CO2(R1), T_vis,H2O(R1) and JKR; CO2 ice with
/// rho = 1650 kg/m^3 as in Section 5.4.
#[derive(Debug, Clone)]
pub struct Figure7 {
    /// The material (CO2 with the density of Section 5.4).
    pub material: Material,
    /// One point per radius, in increasing R1.
    pub points: Vec<SizePoint>,
}

impl Figure7 {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let material = Material {
            density: 1650.0,
            ..Material::co2()
        };
        let r1s = geomspace(1e-7, 1e-4, res.pick(25, 3));
        let jobs: Vec<(f64, TVisLaw)> = r1s
            .iter()
            .flat_map(|&r| [TVisLaw::Co2, TVisLaw::H2o].map(|l| (r, l)))
            .collect();
        let ths = par_map("fig7", &jobs, progress, |&(r1, l)| {
            let c = Contact::new(material, Geometry::identical(r1))?;
            Ok(sticking_thresholds(
                &c,
                &law,
                l.t_vis(r1),
                &SearchOptions::default(),
            )?)
        })?;
        let points = r1s
            .iter()
            .zip(ths.chunks(2))
            .map(|(&r1, pair)| SizePoint {
                r1,
                co2: pair[0],
                h2o: pair[1],
            })
            .collect();
        Ok(Self { material, points })
    }

    /// `fig7.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "fig7.csv",
            vec![
                "Figure 7: V_stick of monomers and V_frag = 10 V_stick of aggregates against the monomer radius (Sections 5.4, 6)".into(),
                material_line("co2 (Section 5.4 density)", &self.material),
                format!("k = {}; t_vis_co2 = 1e-11 s (R1/1 um)^1.11, t_vis_h2o = 1e-10 s (R1/1.5 um)^1.11", number(K)),
                format!(
                    "maximum collision velocities in weakly turbulent disks: {} - {} m/s",
                    number(V_COL_MAX.0),
                    number(V_COL_MAX.1)
                ),
                "units: r1 [m], t_vis_* [s], v_* [m/s]".into(),
            ],
            &[
                "r1", "t_vis_co2", "v_stick_co2", "v_frag_co2", "t_vis_h2o", "v_stick_h2o", "v_frag_h2o",
                "v_stick_jkr", "v_frag_jkr",
            ],
        );
        for p in &self.points {
            let (co2, h2o) = (&p.co2, &p.h2o);
            t.push(vec![
                p.r1.into(),
                co2.t_vis.into(),
                co2.v_stick.into(),
                co2.v_stick.map(v_frag).into(),
                h2o.t_vis.into(),
                h2o.v_stick.into(),
                h2o.v_stick.map(v_frag).into(),
                co2.v_stick_jkr.into(),
                v_frag(co2.v_stick_jkr).into(),
            ]);
        }
        vec![t]
    }
}

/// The sphere-on-wall figure: V_stick against T_vis for CO2 grains of 60 um, two identical
/// spheres against a sphere on a CO2 wall (the laboratory geometry of Musiolik et al. 2016a),
/// with the relaxation times each geometry needs for 0.04 ± 0.02 m/s.
#[derive(Debug, Clone)]
pub struct FigureWall {
    /// Identical spheres (parameter 0) and the wall (parameter 1).
    pub curves: Vec<ThresholdCurve>,
    /// The T_vis fit to the experiment in each geometry, in the order of `curves`.
    pub fits: Vec<TVisFit>,
}

/// The geometry names of [`FigureWall`], in the order of its curves.
pub const WALL_GEOMETRIES: [&str; 2] = ["identical", "wall"];

impl FigureWall {
    /// Computes the figure.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        let law = CrackLaw::new(K)?;
        let e = CO2_EXPERIMENT;
        let t_vis = geomspace(1e-12, 1e-8, res.pick(33, 3));
        let geometries = [Geometry::identical(e.r1), Geometry::wall(e.r1)];
        let out = par_map("fig_wall", &[0usize, 1], progress, |&i| {
            let c = Contact::new(Material::co2(), geometries[i])?;
            let opts = SearchOptions::default();
            let curve = ThresholdCurve {
                parameter: i as f64,
                v_stick_jkr: c.v_stick_jkr(),
                points: sweep_t_vis(&c, &law, &t_vis, &opts)?,
            };
            Ok((curve, fit_t_vis(&c, &law, e.v_stick, e.err, &opts)?))
        })?;
        let (curves, fits) = out.into_iter().unzip();
        Ok(Self { curves, fits })
    }

    /// `fig_wall.csv`.
    pub fn to_tables(&self) -> Vec<Table> {
        let e = CO2_EXPERIMENT;
        let mut comments = vec![
            "Sphere on a wall: V_stick against T_vis, two identical spheres against a sphere on a flat wall of the same material".into(),
            material_line("co2", &Material::co2()),
            format!(
                "radius = {} m, k = {}; identical: R = R1/2, m* = m1/2; wall: R = R1, m* = m1",
                number(e.r1),
                number(K)
            ),
        ];
        for (name, f) in WALL_GEOMETRIES.iter().zip(&self.fits) {
            comments.push(format!(
                "{name}: T_vis for V_stick = {} +- {} m/s (Musiolik et al. 2016a): {} s ({} .. {} s)",
                number(e.v_stick),
                number(e.err),
                number(f.t_vis),
                number(f.t_vis_min),
                number(f.t_vis_max)
            ));
        }
        comments.push("units: t_vis [s], v_stick, v_double_onset, v_stick_jkr [m/s]".into());
        let mut t = Table::new(
            "fig_wall.csv",
            comments,
            &[
                "geometry",
                "t_vis",
                "v_stick",
                "v_double_onset",
                "v_stick_jkr",
            ],
        );
        for (name, c) in WALL_GEOMETRIES.iter().zip(&self.curves) {
            for th in &c.points {
                t.push(vec![
                    (*name).into(),
                    th.t_vis.into(),
                    th.v_stick.into(),
                    th.v_double_onset.into(),
                    th.v_stick_jkr.into(),
                ]);
            }
        }
        vec![t]
    }
}

/// Every figure.
#[derive(Debug, Clone)]
pub struct Figures {
    /// Figure 1.
    pub fig1: Figure1,
    /// Figure 2.
    pub fig2: Figure2,
    /// Figure 3.
    pub fig3: Figure3,
    /// Figure 4.
    pub fig4: Figure4,
    /// Figure 5.
    pub fig5: Figure5,
    /// Figure 6.
    pub fig6: Figure6,
    /// Figure 7.
    pub fig7: Figure7,
    /// The sphere-on-wall figure.
    pub wall: FigureWall,
}

impl Figures {
    /// Computes every figure, in order.
    pub fn compute(res: Resolution, progress: Progress) -> Result<Self, Error> {
        Ok(Self {
            fig1: Figure1::compute(res, progress)?,
            fig2: Figure2::compute(res, progress)?,
            fig3: Figure3::compute(res, progress)?,
            fig4: Figure4::compute(res, progress)?,
            fig5: Figure5::compute(res, progress)?,
            fig6: Figure6::compute(res, progress)?,
            fig7: Figure7::compute(res, progress)?,
            wall: FigureWall::compute(res, progress)?,
        })
    }

    /// Every CSV table, in order.
    pub fn tables(&self) -> Vec<Table> {
        [
            self.fig1.to_tables(),
            self.fig2.to_tables(),
            self.fig3.to_tables(),
            self.fig4.to_tables(),
            self.fig5.to_tables(),
            self.fig6.to_tables(),
            self.fig7.to_tables(),
            self.wall.to_tables(),
        ]
        .concat()
    }
}
