//! How far the solver tolerance moves V_stick and V_double_onset, per integrator: the
//! measurement behind `thresholds`' tolerance ladder and `SearchOptions::default_solver`
//! (`docs/performance.md`, "Tolerance ladder").
//!
//! ```sh
//! cargo run --release -p thresholds --example tolerance_ladder
//! ```
//! For CO2 (60 um) and H2O (90 um) at several T_vis, each threshold is searched to a relative
//! width of 1e-9 with the solver at each rtol (atol = 1e-3 rtol), and compared with
//! `SearchOptions::reference()` (BDF at rtol 1e-11, no rebound restarts). Prints the relative
//! shifts and the largest per integrator and rtol.
#![allow(clippy::unwrap_used, clippy::expect_used)]

#[path = "common/mod.rs"]
mod common;

use dynamics::Method;
use thresholds::{sticking_thresholds, Contact, CrackLaw, SearchOptions, SolverOptions};

fn main() {
    let law = CrackLaw::new(0.01).unwrap();
    let cases = common::cases(common::REFERENCE);
    let rtols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9];
    let methods = [Method::Bdf, Method::Auto];
    let search = |contact: &Contact, t_vis: f64, method: Method, rtol: f64| {
        let opts = SearchOptions {
            rel_tol: 1e-9,
            solver: SolverOptions::at_rtol(rtol).with_method(method),
            ..SearchOptions::exact()
        };
        let th = sticking_thresholds(contact, &law, t_vis, &opts).unwrap();
        (th.v_stick.unwrap(), th.v_double_onset.unwrap())
    };
    let mut worst = vec![[0.0f64; 2]; methods.len() * rtols.len()];
    for (name, contact, t_vis) in cases {
        let reference =
            sticking_thresholds(&contact, &law, t_vis, &SearchOptions::reference()).unwrap();
        let (s_ref, o_ref) = (
            reference.v_stick.unwrap(),
            reference.v_double_onset.unwrap(),
        );
        for (m, method) in methods.iter().enumerate() {
            let mut line = format!("{name}, {method:?}:");
            for (r, rtol) in rtols.iter().enumerate() {
                let (s, o) = search(&contact, t_vis, *method, *rtol);
                let (ds, d_o) = (s / s_ref - 1.0, o / o_ref - 1.0);
                line += &format!(" {rtol:e}: {ds:+.1e} {d_o:+.1e} |");
                let w = &mut worst[m * rtols.len() + r];
                w[0] = w[0].max(ds.abs());
                w[1] = w[1].max(d_o.abs());
            }
            println!("{line}");
        }
    }
    println!("largest |shift| (V_stick, onset):");
    for (m, method) in methods.iter().enumerate() {
        for (r, rtol) in rtols.iter().enumerate() {
            let w = worst[m * rtols.len() + r];
            println!("  {method:?} rtol {rtol:e}: {:.1e} {:.1e}", w[0], w[1]);
        }
    }
}
