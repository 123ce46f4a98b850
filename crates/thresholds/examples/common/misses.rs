//! The tally of a probe that compares a reading of the tables with the reference search at
//! points (`kink_lattice`, `kind_stencil`): each point's line, then how many have a reading
//! and how many of those lie within 2e-6 and 1e-5.

/// Prints each point's line; returns how many have a miss (a reading at all) and how many of
/// them are within 2e-6 and within 1e-5 (relative).
pub fn tally(lines: &[(String, Option<f64>)]) -> (usize, usize, usize) {
    for (line, _) in lines {
        println!("{line}");
    }
    let within = |tol: f64| {
        lines
            .iter()
            .filter(|(_, m)| m.is_some_and(|m| m <= tol))
            .count()
    };
    let with = lines.iter().filter(|(_, m)| m.is_some()).count();
    (with, within(2e-6), within(1e-5))
}
