//! The data of Figures 1-7 of Arakawa & Krijt (2021). Only parameter grids live here: every
//! number comes from `greenwood`, `contact`, `dynamics` and `thresholds`.

use crate::table::{Cell, Table};
use contact::{Contact, Material};
use dynamics::{Collider, Outcome, SolverOptions};
use greenwood::CrackLaw;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use thresholds::{fit_t_vis, sticking_thresholds, sweep_t_vis, v_frag, SearchOptions, TVisLaw};

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

/// `n` points from `a` to `b`, evenly spaced in log.
pub fn logspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![a];
    }
    (0..n)
        .map(|i| a * (b / a).powf(i as f64 / (n - 1) as f64))
        .collect()
}

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
        m.gamma_sv, m.young, m.poisson, m.density
    )
}

/// The fiducial k of the paper (Section 2.3).
pub const K: f64 = 0.01;
/// The k values of Figures 1 and 4.
pub const KS: [f64; 4] = [0.005, 0.01, 0.02, 0.05];
/// CO2 grains of Section 4 and 5.1.
pub const R1_CO2: f64 = 60e-6;
/// H2O grains of Section 5.2.
pub const R1_H2O: f64 = 90e-6;
/// Surface energies of Figure 5 (J/m^2).
pub const GAMMAS_H2O: [f64; 4] = [0.02, 0.05, 0.1, 0.19];

/// Figure 1: v(k, beta) for several k, over 1e-3 < beta < 1e3 and near beta = 1.
pub fn figure1(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let laws = par_map("fig1", &KS, progress, |&k| Ok(CrackLaw::new(k)?))?;
    let mut t = Table::new(
        "fig1.csv",
        vec![
            "Figure 1: Greenwood's normalized crack speed v(k, beta) (Arakawa & Krijt 2021, Appendix A)".into(),
            "panel = full: 1e-3 < beta < 1e3 within k < beta < 1/k; panel = zoom: 0.95 <= beta <= 1.05".into(),
            "units: k, beta, v dimensionless (v = sigma0^2 T_vis a_dot / (E* gamma))".into(),
        ],
        &["panel", "k", "beta", "v"],
    );
    let n = res.pick(300, 12);
    for (k, law) in KS.iter().zip(&laws) {
        let lo = (k * (1.0 + 1e-9)).max(1e-3);
        let hi = (1.0 / k * (1.0 - 1e-9)).min(1e3);
        for beta in logspace(lo, hi, n) {
            t.push(vec![
                "full".into(),
                (*k).into(),
                beta.into(),
                law.v(beta)?.into(),
            ]);
        }
        for beta in linspace(0.95, 1.05, res.pick(101, 5)) {
            t.push(vec![
                "zoom".into(),
                (*k).into(),
                beta.into(),
                law.v(beta)?.into(),
            ]);
        }
    }
    Ok(vec![t])
}

/// The V_in of the three trajectories of Figure 2 (m/s).
pub const FIG2_V_IN: [f64; 3] = [0.035, 0.0405, 0.045];

/// Figure 2: trajectories for CO2, R1 = 60 um, T_vis = 1e-9 s at V_in = 3.5, 4.05, 4.5 cm/s.
pub fn figure2(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let law = CrackLaw::new(K)?;
    let m = Material::co2();
    let c = Contact::new(m, R1_CO2)?;
    let t_vis = 1e-9;
    let opts = SolverOptions {
        record_trajectory: true,
        // let the sticking trajectory spiral towards the JKR point before it is decided
        decide_after: 20e-6,
        ..Default::default()
    };
    let collider = Collider::new(c, &law, t_vis)?.with_options(opts)?;
    let runs = par_map("fig2", &FIG2_V_IN, progress, |&v| Ok(collider.collide(v)?))?;
    let mut t = Table::new(
        "fig2.csv",
        vec![
            "Figure 2: head-on collisions in the delta-a and delta-delta_dot planes (Section 4)"
                .into(),
            material_line("co2", &m),
            format!("radius = {R1_CO2} m, t_vis = {t_vis} s, k = {K}, eps = {}", dynamics::EPS),
            format!(
                "JKR equilibrium: a_eq = {:e} m, delta_eq = {:e} m, delta_dot = 0",
                c.a_eq(),
                c.delta_eq()
            ),
            "400 points a trajectory at equal steps of its path length in (a/a_eq, delta/delta_eq, delta_dot/V_stick,JKR)".into(),
            "units: v_in [m/s], t [s], a [m], delta [m], delta_dot [m/s]".into(),
        ],
        &["v_in", "outcome", "t", "a", "delta", "delta_dot"],
    );
    let n = res.pick(400, 8);
    for (v, run) in FIG2_V_IN.iter().zip(&runs) {
        for p in resample(&run.trajectory, &c, n) {
            t.push(vec![
                (*v).into(),
                run.outcome.as_str().into(),
                p.t.into(),
                p.a.into(),
                p.delta.into(),
                p.delta_dot.into(),
            ]);
        }
    }
    Ok(vec![t])
}

/// `n` points at equal steps of the path length of a trajectory in the plane of
/// `(a/a_eq, delta/delta_eq, delta_dot/V_stick,JKR)`, linearly interpolated between solver steps:
/// the output does not depend on where the solver put its steps.
fn resample(
    traj: &[dynamics::TrajectoryPoint],
    c: &Contact,
    n: usize,
) -> Vec<dynamics::TrajectoryPoint> {
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
        out.push(dynamics::TrajectoryPoint {
            t: mix(p.t, q.t),
            a: mix(p.a, q.a),
            delta: mix(p.delta, q.delta),
            delta_dot: mix(p.delta_dot, q.delta_dot),
            energy: mix(p.energy, q.energy),
        });
    }
    out
}

/// Figure 3: coefficient of restitution against V_in for CO2, R1 = 60 um, T_vis = 1e-9 s.
pub fn figure3(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let law = CrackLaw::new(K)?;
    let m = Material::co2();
    let c = Contact::new(m, R1_CO2)?;
    let t_vis = 1e-9;
    let th = sticking_thresholds(&c, &law, t_vis, &SearchOptions::default())?;
    let (vd, vs) = (
        th.v_double_onset.ok_or("no double collisions")?,
        th.v_stick.ok_or("no bouncing")?,
    );
    let mut v_in = linspace(0.02, 0.1, res.pick(161, 6));
    // resolve the narrow double-collision window
    v_in.extend(linspace(vd, vs, res.pick(42, 4)).into_iter().skip(1));
    v_in.retain(|v| (v - vd).abs() > 1e-9 * vd);
    v_in.sort_by(f64::total_cmp);
    let collider = Collider::new(c, &law, t_vis)?;
    let runs = par_map("fig3", &v_in, progress, |&v| Ok(collider.collide(v)?))?;
    let mut t = Table::new(
        "fig3.csv",
        vec![
            "Figure 3: coefficient of restitution e against the impact speed V_in (Section 4.4)".into(),
            material_line("co2", &m),
            format!("radius = {R1_CO2} m, t_vis = {t_vis} s, k = {K}"),
            format!("v_double_onset = {vd:e} m/s, v_stick = {vs:e} m/s"),
            "e: observed value (0 for sticking and double collisions); e_computed: -V_out/V_in of the first contact".into(),
            "units: v_in [m/s], e and e_computed dimensionless".into(),
        ],
        &["v_in", "outcome", "e", "e_computed"],
    );
    for (v, r) in v_in.iter().zip(&runs) {
        let observed = if r.outcome == Outcome::Bouncing {
            r.e
        } else {
            0.0
        };
        t.push(vec![
            (*v).into(),
            r.outcome.as_str().into(),
            observed.into(),
            r.e.into(),
        ]);
    }
    Ok(vec![t])
}

/// Figure 4: V_stick against T_vis for several k, CO2, R1 = 60 um.
pub fn figure4(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let m = Material::co2();
    let c = Contact::new(m, R1_CO2)?;
    let laws = KS
        .iter()
        .map(|&k| CrackLaw::new(k))
        .collect::<Result<Vec<_>, _>>()?;
    let t_vis = logspace(1e-12, 1e-8, res.pick(33, 3));
    // one sweep over T_vis per k (each search seeded by its neighbour), the k in parallel
    let sweeps = par_map("fig4", &laws, progress, |law| {
        Ok(sweep_t_vis(&c, law, &t_vis, &SearchOptions::default())?)
    })?;
    let jobs: Vec<(usize, f64)> = (0..KS.len())
        .flat_map(|i| t_vis.iter().map(move |&t| (i, t)))
        .collect();
    let ths: Vec<_> = sweeps.into_iter().flatten().collect();
    let mut t = Table::new(
        "fig4.csv",
        vec![
            "Figure 4: threshold velocity for sticking V_stick against T_vis for several k (Section 5.1)".into(),
            material_line("co2", &m),
            format!("radius = {R1_CO2} m; experiment (Musiolik et al. 2016a): V_stick = 0.04 +- 0.02 m/s"),
            "units: k dimensionless, t_vis [s], v_stick, v_double_onset, v_stick_jkr [m/s]".into(),
        ],
        &["k", "t_vis", "v_stick", "v_double_onset", "v_stick_jkr"],
    );
    for ((i, tv), th) in jobs.iter().zip(&ths) {
        t.push(vec![
            KS[*i].into(),
            (*tv).into(),
            th.v_stick.into(),
            th.v_double_onset.into(),
            th.v_stick_jkr.into(),
        ]);
    }
    Ok(vec![t])
}

/// Figure 5: V_stick against T_vis for H2O, R1 = 90 um, several gamma_SV.
pub fn figure5(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let law = CrackLaw::new(K)?;
    let t_vis = logspace(1e-12, 1e-7, res.pick(41, 3));
    // one sweep over T_vis per gamma_SV (each search seeded by its neighbour), in parallel
    let sweeps = par_map("fig5", &GAMMAS_H2O, progress, |&g| {
        let c = Contact::new(
            Material {
                gamma_sv: g,
                ..Material::h2o()
            },
            R1_H2O,
        )?;
        Ok(sweep_t_vis(&c, &law, &t_vis, &SearchOptions::default())?)
    })?;
    let jobs: Vec<(f64, f64)> = GAMMAS_H2O
        .iter()
        .flat_map(|&g| t_vis.iter().map(move |&t| (g, t)))
        .collect();
    let ths: Vec<_> = sweeps.into_iter().flatten().collect();
    let mut t = Table::new(
        "fig5.csv",
        vec![
            "Figure 5: V_stick against T_vis for H2O grains and several gamma_sv (Section 5.2)".into(),
            material_line("h2o (gamma_sv varied)", &Material::h2o()),
            format!("radius = {R1_H2O} m, k = {K}; experiment (Musiolik et al. 2016b): V_stick ~ 0.73 m/s"),
            "v_stick is empty where no collision bounces up to no_bouncing_below (the curve ends)".into(),
            "units: gamma_sv [J/m^2], t_vis [s], v_stick, v_double_onset, v_stick_jkr, no_bouncing_below [m/s]".into(),
        ],
        &["gamma_sv", "t_vis", "v_stick", "v_double_onset", "v_stick_jkr", "no_bouncing_below"],
    );
    for ((g, tv), th) in jobs.iter().zip(&ths) {
        let nb = if th.v_stick.is_none() {
            Cell::Num(th.v_max)
        } else {
            Cell::Missing
        };
        t.push(vec![
            (*g).into(),
            (*tv).into(),
            th.v_stick.into(),
            th.v_double_onset.into(),
            th.v_stick_jkr.into(),
            nb,
        ]);
    }
    Ok(vec![t])
}

/// Figure 6: fitted T_vis ranges against R1, the point of Gundlach et al. (2015) and both size laws.
pub fn figure6(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let law = CrackLaw::new(K)?;
    let opts = SearchOptions::default();
    let jobs = ["co2", "h2o"];
    let fits = par_map(
        "fig6",
        &jobs,
        progress,
        |&name| -> Result<(f64, f64, f64), Error> {
            if name == "co2" {
                let c = Contact::new(Material::co2(), R1_CO2)?;
                let f = fit_t_vis(&c, &law, 0.04, 0.02, &opts)?;
                Ok((f.t_vis, f.t_vis_min, f.t_vis_max))
            } else {
                // 0.73 m/s with 0.02 <= gamma_sv <= 0.19 J/m^2; central value at 0.1 J/m^2
                let fit = |g: f64| -> Result<f64, Error> {
                    let c = Contact::new(
                        Material {
                            gamma_sv: g,
                            ..Material::h2o()
                        },
                        R1_H2O,
                    )?;
                    Ok(fit_t_vis(&c, &law, 0.73, 0.0, &opts)?.t_vis)
                };
                Ok((fit(0.1)?, fit(0.19)?, fit(0.02)?))
            }
        },
    )?;
    let mut points = Table::new(
        "fig6_points.csv",
        vec![
            "Figure 6: relaxation times fitted to measured V_stick (Sections 5.1-5.3)".into(),
            "co2: R1 = 60 um, V_stick = 0.04 +- 0.02 m/s (Musiolik et al. 2016a)".into(),
            "h2o: R1 = 90 um, V_stick = 0.73 m/s, gamma_sv from 0.19 (t_vis_min) to 0.02 J/m^2 (t_vis_max), 0.1 J/m^2 (t_vis)".into(),
            "gundlach2015: R1 = 1.5 um, T_vis = 1e-10 s (Gundlach et al. 2015)".into(),
            "units: r1 [m], t_vis, t_vis_min, t_vis_max [s]".into(),
        ],
        &["source", "r1", "t_vis", "t_vis_min", "t_vis_max"],
    );
    points.push(vec![
        "co2".into(),
        R1_CO2.into(),
        fits[0].0.into(),
        fits[0].1.into(),
        fits[0].2.into(),
    ]);
    points.push(vec![
        "h2o".into(),
        R1_H2O.into(),
        fits[1].0.into(),
        fits[1].1.into(),
        fits[1].2.into(),
    ]);
    points.push(vec![
        "gundlach2015".into(),
        1.5e-6.into(),
        1e-10.into(),
        1e-10.into(),
        1e-10.into(),
    ]);
    let mut laws = Table::new(
        "fig6_laws.csv",
        vec![
            "Figure 6: size laws T_vis,CO2 = 1e-11 s (R1/1 um)^1.11 and T_vis,H2O = 1e-10 s (R1/1.5 um)^1.11 (Section 5.3)".into(),
            "units: r1 [m], t_vis_co2, t_vis_h2o [s]".into(),
        ],
        &["r1", "t_vis_co2", "t_vis_h2o"],
    );
    for r1 in logspace(1e-7, 1e-3, res.pick(41, 3)) {
        laws.push(vec![
            r1.into(),
            TVisLaw::Co2.t_vis(r1).into(),
            TVisLaw::H2o.t_vis(r1).into(),
        ]);
    }
    Ok(vec![points, laws])
}

/// Figure 7: V_stick and V_frag against R1 for T_vis,CO2(R1), T_vis,H2O(R1) and JKR; CO2 ice with
/// rho = 1650 kg/m^3 as in Section 5.4.
pub fn figure7(res: Resolution, progress: Progress) -> Result<Vec<Table>, Error> {
    let law = CrackLaw::new(K)?;
    let m = Material {
        density: 1650.0,
        ..Material::co2()
    };
    let r1s = logspace(1e-7, 1e-4, res.pick(25, 3));
    let jobs: Vec<(usize, TVisLaw)> = (0..r1s.len())
        .flat_map(|i| [TVisLaw::Co2, TVisLaw::H2o].map(|l| (i, l)))
        .collect();
    let ths = par_map("fig7", &jobs, progress, |&(i, l)| {
        let c = Contact::new(m, r1s[i])?;
        Ok(sticking_thresholds(
            &c,
            &law,
            l.t_vis(r1s[i]),
            &SearchOptions::default(),
        )?)
    })?;
    let mut t = Table::new(
        "fig7.csv",
        vec![
            "Figure 7: V_stick of monomers and V_frag = 10 V_stick of aggregates against the monomer radius (Sections 5.4, 6)".into(),
            material_line("co2 (Section 5.4 density)", &m),
            format!("k = {K}; t_vis_co2 = 1e-11 s (R1/1 um)^1.11, t_vis_h2o = 1e-10 s (R1/1.5 um)^1.11"),
            "maximum collision velocities in weakly turbulent disks: 25-50 m/s".into(),
            "units: r1 [m], t_vis_* [s], v_* [m/s]".into(),
        ],
        &[
            "r1", "t_vis_co2", "v_stick_co2", "v_frag_co2", "t_vis_h2o", "v_stick_h2o", "v_frag_h2o",
            "v_stick_jkr", "v_frag_jkr",
        ],
    );
    for (i, r1) in r1s.iter().enumerate() {
        let (co2, h2o) = (&ths[2 * i], &ths[2 * i + 1]);
        t.push(vec![
            (*r1).into(),
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
    Ok(vec![t])
}

/// Every figure, in order, as `(number, tables)`.
pub fn all(res: Resolution, progress: Progress) -> Result<Vec<(usize, Vec<Table>)>, Error> {
    type Fig = fn(Resolution, Progress) -> Result<Vec<Table>, Error>;
    let figs: [Fig; 7] = [
        figure1, figure2, figure3, figure4, figure5, figure6, figure7,
    ];
    figs.iter()
        .enumerate()
        .map(|(i, f)| Ok((i + 1, f(res, progress)?)))
        .collect()
}
