//! Steps and accuracy of one collision per integrator (`docs/performance.md`, "Integrator"):
//!
//! ```sh
//! cargo run --release -p dynamics --example integrators
//! ```
//! For each case, collisions just below and just above V_stick (0.99 and 1.01 V_stick): the
//! steps of BDF at the search tolerance (rtol 1e-8) and of Tsit45 at rtol 1e-8 and 1e-9 (the
//! latter as `Method::Auto` runs it), and, for the bouncing collision at 1.01 V_stick, the error
//! of V_out against BDF at rtol 1e-12, relative to V_in. Tsit45 is skipped where lambda > 2000
//! (hundreds of thousands of steps).

use contact::{Contact, Geometry, Material};
use dynamics::{Collider, DynamicsError, Method, SolverOptions};
use greenwood::CrackLaw;

fn main() -> Result<(), DynamicsError> {
    let law = CrackLaw::new(0.01)?;
    let co2 = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    let h2o = Contact::new(Material::h2o(), Geometry::identical(90e-6))?;
    // (case, contact, T_vis (s), V_stick (m/s), from `data/fig4.csv` and the searches)
    let cases = [
        ("CO2 60 um, T_vis = 1e-9 s", co2, 1e-9, 0.0413762),
        ("H2O 90 um, T_vis = 1e-9 s", h2o, 1e-9, 0.0674208),
        ("CO2 60 um, T_vis = 1e-11 s", co2, 1e-11, 0.0171244),
        ("CO2 60 um, T_vis = 1e-12 s", co2, 1e-12, 0.0166627),
        ("CO2 60 um, T_vis = 1e-14 s", co2, 1e-14, 0.0165975),
    ];
    let run = |contact: Contact, t_vis: f64, method: Method, rtol: f64, v: f64| {
        let opts = SolverOptions::at_rtol(rtol).with_method(method);
        Collider::new(contact, &law, t_vis)?
            .with_options(opts)?
            .collide(v)
    };
    println!(
        "case | lambda | steps BDF 1e-8 | Tsit45 1e-8 | Tsit45 1e-9 | V_out error (1.01 V_stick): BDF 1e-8 | Tsit45 1e-8 | Tsit45 1e-9"
    );
    for (name, contact, t_vis, v_stick) in cases {
        let lambda = Collider::new(contact, &law, t_vis)?.params().lambda;
        let (lo, hi) = (0.99 * v_stick, 1.01 * v_stick);
        let reference = run(contact, t_vis, Method::Bdf, 1e-12, hi)?.v_out;
        let mut steps = Vec::new();
        let mut errors = Vec::new();
        for (method, rtol) in [
            (Method::Bdf, 1e-8),
            (Method::Tsit45, 1e-8),
            (Method::Tsit45, 1e-9),
        ] {
            if method == Method::Tsit45 && lambda > 2000.0 {
                steps.push("—".to_string());
                errors.push("—".to_string());
                continue;
            }
            let (a, b) = (
                run(contact, t_vis, method, rtol, lo)?,
                run(contact, t_vis, method, rtol, hi)?,
            );
            steps.push(format!("{} / {}", a.steps, b.steps));
            errors.push(format!("{:.1e}", (b.v_out - reference).abs() / hi));
        }
        println!(
            "{name} | {lambda:.2e} | {} | {}",
            steps.join(" | "),
            errors.join(" | ")
        );
    }
    Ok(())
}
