//! The collision commands as a user runs them: JSON contract, files, bad input.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{assert_bad_input, json, json_of, run_line, TempDir};
use std::process::Command;

/// Section 4: 3.5, 4.05 and 4.5 cm/s stick, double-collide and bounce (CO2, 60 um, 1e-9 s).
#[test]
fn collide_outcomes_and_keys() {
    for (v, outcome) in [
        ("0.035", "sticking"),
        ("0.0405", "double"),
        ("0.045", "bouncing"),
    ] {
        let j = json(&[
            "collide",
            "--material",
            "co2",
            "--radius",
            "60e-6",
            "--t-vis",
            "1e-9",
            "--v-in",
            v,
            "--json",
        ]);
        assert_eq!(j["outcome"], outcome);
        for key in ["e", "e_observed", "v_out", "contact_time"] {
            assert!(j.get(key).is_some(), "missing {key}");
        }
        // e as an experiment observes it (Section 4.4): a rebound that sticks or comes back
        // for a second contact is seen as e = 0; a bouncing one as its e
        let (e, seen) = (j["e"].as_f64().unwrap(), j["e_observed"].as_f64().unwrap());
        assert_eq!(seen, if outcome == "bouncing" { e } else { 0.0 });
    }
}

#[test]
fn collide_writes_a_trajectory_csv() {
    let dir = TempDir::new("test");
    let path = dir.join("traj.csv");
    let p = path.to_str().unwrap();
    json(&[
        "collide",
        "--t-vis",
        "1e-9",
        "--v-in",
        "0.045",
        "--trajectory",
        p,
        "--json",
    ]);
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(lines.next(), Some("t,a,delta,delta_dot,energy,beta"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 10);
    assert_eq!(rows[0][2], 0.0); // delta = 0 at first contact (Section 2.5)
    assert_eq!(rows[0][3], 0.045); // delta_dot = V_in
    assert!((rows[0][5] / 0.0101 - 1.0).abs() < 1e-9); // beta = (1 + eps) k
}

/// Section 4.4: V_stick = 4.14 cm/s (first bouncing V_in on the paper's 0.01 cm/s grid).
#[test]
fn v_stick_keys() {
    let j = json_of("v-stick --material co2 --radius 60e-6 --t-vis 1e-9 --json");
    let vs = j["v_stick"].as_f64().unwrap();
    assert!(vs > 0.0413 && vs <= 0.0414);
    assert!(j["v_double_onset"].as_f64().unwrap() < vs);
    assert!(j["v_stick_jkr"].as_f64().unwrap() < vs);
}

#[test]
fn v_stick_without_bouncing_says_so() {
    let j = json_of("v-stick --t-vis 1e-6 --v-max 2 --json");
    assert!(j["v_stick"].is_null());
    assert_eq!(j["no_bouncing_below"].as_f64(), Some(2.0));
}

/// Section 5.1: 0.04 ± 0.02 m/s gives 8.5e-11 <= T_vis <= 1.97e-9 s.
#[test]
fn fit_t_vis_keys() {
    let j =
        json_of("fit-t-vis --material co2 --radius 60e-6 --v-stick 0.04 --v-stick-err 0.02 --json");
    let (lo, hi) = (
        j["t_vis_min"].as_f64().unwrap(),
        j["t_vis_max"].as_f64().unwrap(),
    );
    assert!(
        lo > 8.4e-11 && lo <= 8.5e-11 && (1.97e-9..1.98e-9).contains(&hi),
        "{j}"
    );
    let t = j["t_vis"].as_f64().unwrap();
    assert!(lo < t && t < hi);
}

/// Section 7.1: V_frag,JKR(30 um) = 0.296 m/s; Section 5.3 laws give T_vis.
#[test]
fn v_frag_keys() {
    let j = json_of("v-frag --material co2 --radius 30e-6 --json");
    assert!((j["v_frag"].as_f64().unwrap() / 0.296 - 1.0).abs() < 0.002);
    assert_eq!(j["t_vis"].as_f64(), Some(0.0));
    let j = json_of("v-frag --material h2o --radius 90e-6 --t-vis-law h2o --json");
    assert!((j["t_vis"].as_f64().unwrap() / 9.4e-9 - 1.0).abs() < 0.005);
    let (vf, vs) = (
        j["v_frag"].as_f64().unwrap(),
        j["v_stick"].as_f64().unwrap(),
    );
    assert!((vf - 10.0 * vs).abs() < 1e-12 * vf);
}

#[test]
fn bad_collision_input() {
    assert_bad_input(&[
        ("collide --t-vis 1e-9 --v-in -1", "--v-in"),
        ("collide --t-vis -1e-9 --v-in 1", "--t-vis"),
        ("collide --t-vis 1e-9 --v-in 1 --k 0", "--k"),
        ("v-stick --t-vis -1", "--t-vis"),
        ("fit-t-vis --v-stick 0", "--v-stick"),
        (
            "fit-t-vis --v-stick 0.04 --v-stick-err 0.05",
            "--v-stick-err",
        ),
    ]);
    let (code, _, err) = run_line("collide --t-vis 0 --v-in 1");
    assert_eq!(code, 2);
    assert!(err.contains("JKR"), "{err}");
}

/// Section 2.2: JKR theory needs a Tabor parameter mu >> 1; small grains get a warning on stderr
/// and in the JSON "warnings" list, large ones none.
#[test]
fn tabor_warning_for_small_grains() {
    let out = Command::new(env!("CARGO_BIN_EXE_stickiness"))
        .args(["jkr", "--radius", "1e-8", "--json"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(j["tabor"].as_f64().unwrap() < 1.0);
    let w = j["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1);
    assert!(w[0].as_str().unwrap().contains("Tabor"));
    assert!(String::from_utf8_lossy(&out.stderr).contains("warning: Tabor"));
    let j = json_of("jkr --json");
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(0));
}

/// V_stick >= V_stick,JKR at every T_vis (Section 5.1): a `--v-max` below V_stick,JKR finds no
/// bouncing whatever the grains, and says so in a warning (stderr and the JSON "warnings"); a
/// `--v-max` above it, none.
#[test]
fn a_search_limit_below_the_jkr_threshold_is_warned_of() {
    let j = json_of("v-stick --t-vis 1e-9 --v-max 0.01 --json");
    assert!(j["v_stick"].is_null() && j["v_stick_jkr"].as_f64().unwrap() > 0.01);
    let w = j["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1);
    assert!(w[0]
        .as_str()
        .unwrap()
        .starts_with("--v-max 0.01 m/s is below V_stick,JKR"));
    let j = json_of("v-frag --t-vis 1e-9 --v-max 0.01 --json");
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(1));
    let j = json_of("v-stick --t-vis 1e-9 --v-max 0.02 --json");
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(0));
}

/// The size laws of Section 5.3 belong to their ices: CO2's constants with H2O's law (or the
/// reverse) are warned of, naming the law that was probably meant; each ice with its own law,
/// and a T_vis given outright, are not.
#[test]
fn a_size_law_of_the_other_ice_is_warned_of() {
    let j = json_of("v-stick --material co2 --t-vis-law h2o --json");
    let w = j["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1);
    let w = w[0].as_str().unwrap();
    assert!(
        w.starts_with("t_vis_law = 'h2o'") && w.ends_with("t_vis_law = 'co2' was probably meant")
    );
    let j = json_of("v-frag --material h2o --radius 1e-7 --t-vis-law co2 --json");
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(1));
    for ok in [
        "v-stick --material co2 --t-vis-law co2 --json",
        "collide --material h2o --t-vis-law h2o --v-in 1 --json",
    ] {
        assert_eq!(
            json_of(ok)["warnings"].as_array().map(Vec::len),
            Some(0),
            "{ok}"
        );
    }
}

/// `--method` (default `table`): the master table answers within 1e-5 of the exact search
/// (Section 4.4's CO2 case), the JSON echoes the choice in "input" and says in "method" which
/// path answered; beyond the no-bouncing cliff (T_vis = 1e-6 s) the table says "no bouncing"
/// itself, as the search does.
#[test]
fn method_table_answers_and_says_so() {
    let s = json_of("v-stick --t-vis 1e-9 --method search --json");
    let t = json_of("v-stick --t-vis 1e-9 --json");
    assert_eq!(
        (s["method"].as_str(), t["method"].as_str()),
        (Some("search"), Some("table"))
    );
    assert_eq!(t["input"]["method"].as_str(), Some("table"));
    for key in ["v_stick", "v_double_onset"] {
        let (a, b) = (s[key].as_f64().unwrap(), t[key].as_f64().unwrap());
        assert!((a / b - 1.0).abs() < 1e-5, "{key}: {a} vs {b}");
    }
    let far = json_of("v-stick --t-vis 1e-6 --json");
    let far_search = json_of("v-stick --t-vis 1e-6 --method search --json");
    assert_eq!(far["method"].as_str(), Some("table"));
    assert!(far["v_stick"].is_null() && far_search["v_stick"].is_null());
    assert_eq!(far["no_bouncing_below"], far_search["no_bouncing_below"]);
    let fit = json_of("fit-t-vis --v-stick 0.04 --v-stick-err 0.02 --method table --json");
    assert_eq!(fit["method"].as_str(), Some("table"));
    let frag = json_of("v-frag --radius 1e-7 --t-vis-law co2 --method table --json");
    assert_eq!(frag["method"].as_str(), Some("table"));
}
