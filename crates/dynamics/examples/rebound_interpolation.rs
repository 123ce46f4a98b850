//! How accurate an interpolated rebound is (`docs/performance.md`, "Rebound restarts"):
//!
//! ```sh
//! cargo run --release -p dynamics --example rebound_interpolation
//! ```
//! Near V_stick and the onset of double collisions of the three reference cases, at the
//! threshold search's tolerance (rtol 1e-8): for two collisions a relative width w apart, the
//! rebound state at three speeds between them (the middle and 30 % of w either side) is
//! interpolated and compared with the rebound of the full collision at that speed. Prints the
//! largest difference (max norm, relative to the state's max norm) and the steps of a full
//! collision and of one continued from its rebound.

use contact::{Contact, Geometry, Material};
use dynamics::{Collider, Rebound, SolverOptions};
use greenwood::CrackLaw;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let law = CrackLaw::new(0.01)?;
    let opts = SolverOptions {
        rtol: 1e-8,
        atol: 1e-11,
        ..SolverOptions::default()
    };
    let norm = |u: [f64; 4]| u.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    println!("case | transition | w | interpolation error | C interpolated / extrapolated | steps full / continued");
    // (case, material, R1 (m), T_vis (s), V_stick, V_double_onset (m/s, from the search))
    for (name, material, radius, t_vis, v_stick, v_onset) in [
        (
            "CO2 60 um, 1e-9 s",
            Material::co2(),
            60e-6,
            1e-9,
            0.041376233,
            0.040303328,
        ),
        (
            "CO2 60 um, 1e-14 s",
            Material::co2(),
            60e-6,
            1e-14,
            0.0165975,
            0.01659743,
        ),
        (
            "H2O 90 um, 1e-9 s",
            Material::h2o(),
            90e-6,
            1e-9,
            0.067420775,
            0.064915524,
        ),
    ] {
        let contact = Contact::new(material, Geometry::identical(radius))?;
        let c = Collider::new(contact, &law, t_vis)?.with_options(opts)?;
        for (transition, v) in [("V_stick", v_stick), ("onset", v_onset)] {
            for w in [1e-2, 1e-3, 3e-4, 1e-4, 1e-5] {
                let (lo, hi) = (
                    c.collide(v * (1.0 - 0.5 * w))?,
                    c.collide(v * (1.0 + 0.5 * w))?,
                );
                let (Some(ra), Some(rb)) = (lo.rebound, hi.rebound) else {
                    println!("{name} | {transition} | {w:.0e} | (no rebound) |");
                    continue;
                };
                // relative error of the line through the two rebounds at `mid`, and the
                // coefficient C of error = C |(v - v_lo)(v - v_hi)| / v^2
                let off = |own: &Rebound, r: &Rebound, mid: f64| {
                    let (a, b) = (own.state(), r.state());
                    let diff = [a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]];
                    let error = norm(diff) / norm(a);
                    let product = ((mid - ra.v_in()) * (mid - rb.v_in()) / (mid * mid)).abs();
                    (error, error / product)
                };
                let (mut worst, mut steps) = (0.0f64, (0, 0));
                // C interpolated (between the two) and extrapolated (beyond either end)
                let mut coef = (0.0f64, 0.0f64);
                for offset in [-0.3, 0.0, 0.3] {
                    let mid = v * (1.0 + offset * w);
                    let full = c.collide(mid)?;
                    let (Some(own), Some(r)) = (full.rebound, Rebound::between(&ra, &rb, mid))
                    else {
                        continue;
                    };
                    let (error, k) = off(&own, &r, mid);
                    worst = worst.max(error);
                    coef.0 = coef.0.max(k);
                    steps = (full.steps, c.collide_from(mid, &r)?.steps);
                }
                for offset in [0.75, 1.5, -0.75, -1.5] {
                    let mid = v * (1.0 + offset * w);
                    let (Some(own), Some(r)) =
                        (c.collide(mid)?.rebound, Rebound::through(&ra, &rb, mid))
                    else {
                        continue;
                    };
                    coef.1 = coef.1.max(off(&own, &r, mid).1);
                }
                println!(
                    "{name} | {transition} | {w:.0e} | {worst:.1e} | {:.2} / {:.2} | {} / {}",
                    coef.0, coef.1, steps.0, steps.1
                );
            }
        }
    }
    Ok(())
}
