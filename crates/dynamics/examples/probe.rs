use contact::{Contact, Material};
use dynamics::*;
use greenwood::CrackLaw;
fn bisect(col: &Collider, mut lo: f64, mut hi: f64, is_hi: impl Fn(Outcome) -> bool) -> f64 {
    while (hi - lo) / hi > 1e-7 {
        let m = 0.5 * (lo + hi);
        let r = col.collide(m).unwrap();
        if is_hi(r.outcome) { hi = m } else { lo = m }
    }
    0.5 * (lo + hi)
}
fn main() {
    let law = CrackLaw::new(0.01).unwrap();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let t_vis: f64 = args[0].parse().unwrap();
    let mat = if args.len() > 1 && args[1] == "h2o" { Material::h2o() } else { Material::co2() };
    let r1: f64 = if args.len() > 2 { args[2].parse().unwrap() } else { 60e-6 };
    let mut m = mat; if args.len() > 3 { m.gamma_sv = args[3].parse().unwrap(); }
    let c = Contact::new(m, r1).unwrap();
    let col = Collider::new(c, &law, t_vis).unwrap();
    println!("vjkr {}", c.v_stick_jkr());
    let t = std::time::Instant::now();
    // scan
    let mut v = c.v_stick_jkr() * 0.5;
    let mut prev = Outcome::Sticking;
    let mut lo_s = v; let mut first_double = None; let mut first_bounce = None;
    while v < 100.0 {
        let r = col.collide(v).unwrap();
        if r.outcome != prev { println!("  {v}: {:?} (steps {}, crit {:?})", r.outcome, r.steps, r.sticking_criterion); }
        match r.outcome { Outcome::Sticking => lo_s = v, Outcome::DoubleCollision => { if first_double.is_none() { first_double = Some((lo_s, v)); } }, Outcome::Bouncing => { first_bounce = Some(v); break; } }
        prev = r.outcome;
        v *= 1.05;
    }
    let vb = first_bounce.unwrap();
    let vs = bisect(&col, vb / 1.05, vb, |o| o == Outcome::Bouncing);
    println!("V_stick = {vs}");
    if let Some((a, b)) = first_double { let vd = bisect(&col, a, b, |o| o != Outcome::Sticking); println!("V_double_onset = {vd}"); }
    println!("{:?}", t.elapsed());
}
