//! The CLI contract of the geometry and usability issue: `--radius2`/`--wall`, `--t-vis-law`
//! everywhere, `material`, the `"input"` object, warnings, file errors, one number format.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{json, json_of, run, run_line, TempDir};
use serde_json::Value;

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

/// `--radius2` defaults to `--radius`; V_stick,JKR on a wall is 2^(1/6) times that of identical
/// spheres (R = R1 and m* = m1 instead of R1/2 and m1/2; Section 5.1 formula); the text names
/// the geometry.
#[test]
fn geometry_flags() {
    let id = json_of("jkr --json");
    let same = json_of("jkr --radius2 0.00006 --json");
    assert_eq!(id, same);
    let wall = json_of("jkr --wall --json");
    let ratio = f(&wall["v_stick_jkr"]) / f(&id["v_stick_jkr"]);
    assert!((ratio - 2f64.powf(1.0 / 6.0)).abs() < 1e-12);
    assert_eq!(wall["input"]["radius2"], Value::Null);
    assert_eq!(wall["input"]["wall"], Value::Bool(true));
    assert_eq!(id["input"]["radius2"].as_f64(), Some(60e-6));
    let (_, text, _) = run_line("jkr --radius 60e-6 --radius2 30e-6");
    assert!(text.contains("two spheres of 60 um and 30 um"), "{text}");
    let (_, text, _) = run_line("v-stick --wall --t-vis 1e-12");
    assert!(text.contains("a 60 um sphere on a wall"), "{text}");
    let (code, _, err) = run_line("v-stick --wall --radius2 1e-5 --t-vis 1e-9");
    assert_eq!(code, 2);
    assert!(err.contains("--wall") && err.contains("--radius2"), "{err}");
    let (code, _, err) = run_line("jkr --radius2 -3");
    assert_eq!(code, 2);
    assert!(err.contains("--radius2 = -3.0: must be > 0"), "{err}");
}

/// `--t-vis-law` (any case) on collide and v-stick gives T_vis,H2O(90 um) = 9.4e-9 s (Section 5.3).
#[test]
fn t_vis_law_everywhere() {
    for cmd in [
        vec![
            "v-stick",
            "--material",
            "H2O",
            "--radius",
            "90e-6",
            "--t-vis-law",
            "H2O",
        ],
        vec![
            "collide",
            "--material",
            "h2o",
            "--radius",
            "90e-6",
            "--t-vis-law",
            "h2o",
            "--v-in",
            "1",
        ],
        vec![
            "v-frag",
            "--material",
            "h2o",
            "--radius",
            "90e-6",
            "--t-vis-law",
            "H2o",
        ],
    ] {
        let mut args = cmd.clone();
        args.push("--json");
        let j = json(&args);
        let t = f(&j["input"]["t_vis"]);
        assert!((t / 9.4e-9 - 1.0).abs() < 0.005, "{cmd:?}: {t}");
        assert_eq!(j["input"]["t_vis_law"], "h2o");
    }
    let (code, _, err) = run(&["v-stick"]);
    assert_eq!(code, 2);
    assert!(err.contains("--t-vis"), "{err}");
    let (code, _, _) = run_line("v-stick --t-vis 1e-9 --t-vis-law co2");
    assert_eq!(code, 2);
}

/// `material` prints the four constants after overrides; CO2's come from the sound speeds of
/// Section 3.2 (v_lg = 2900 m/s, v_ts = 1650 m/s, rho = 1560 kg/m^3: E = 10.7 GPa, nu = 0.26 as
/// printed), through the isotropic relations v_ts^2 = E / (2 rho (1 + nu)) and
/// v_lg^2 / v_ts^2 = 2 (1 - nu) / (1 - 2 nu), solved here.
#[test]
fn material_command() {
    let j = json_of("material CO2 --json");
    let (v_lg, v_ts, rho) = (2900.0f64, 1650.0f64, 1560.0);
    let nu = (v_lg * v_lg - 2.0 * v_ts * v_ts) / (2.0 * (v_lg * v_lg - v_ts * v_ts));
    let young = 2.0 * rho * v_ts * v_ts * (1.0 + nu);
    assert!((young / 1e9 - 10.7).abs() < 0.05 && (nu - 0.26).abs() < 0.005);
    assert!((f(&j["young"]) / young - 1.0).abs() < 1e-12, "{j}");
    assert!((f(&j["poisson"]) / nu - 1.0).abs() < 1e-12, "{j}");
    assert_eq!(f(&j["gamma_sv"]), 0.08);
    let j = json_of("material h2o --density 917 --json");
    assert_eq!(f(&j["density"]), 917.0);
    // a title does not call other constants by the preset's name alone
    let (_, text, _) = run_line("material h2o --density 917 --young 5e9");
    assert!(text.contains("h2o (young, density overridden)"), "{text}");
    let (_, text, _) = run_line("v-stick --t-vis 1e-9 --gamma-sv 0.1");
    assert!(
        text.contains("of 60 um of co2 (gamma_sv overridden)"),
        "{text}"
    );
    for key in ["gamma_sv", "young", "poisson", "density"] {
        assert!(j[key].is_number(), "{key}");
    }
}

/// Every JSON object carries the inputs as used, so a scripted sweep needs no bookkeeping.
#[test]
fn every_json_has_its_inputs() {
    let common = [
        "material", "gamma_sv", "young", "poisson", "density", "radius", "radius2", "wall",
    ];
    for (args, own) in [
        (vec!["jkr"], vec![]),
        (
            vec!["collide", "--t-vis", "1e-9", "--v-in", "0.045"],
            vec!["t_vis", "v_in", "k"],
        ),
        (
            vec!["v-stick", "--t-vis", "1e-10"],
            vec!["t_vis", "k", "rel_tol", "v_max"],
        ),
        (vec!["v-frag"], vec!["t_vis", "k", "rel_tol", "v_max"]),
        (
            vec!["fit-t-vis", "--v-stick", "0.03"],
            vec!["v_stick", "v_stick_err", "k"],
        ),
    ] {
        let mut a = args.clone();
        a.push("--json");
        let j = json(&a);
        for key in common.iter().chain(own.iter()) {
            assert!(
                j["input"].get(*key).is_some(),
                "{args:?}: no input.{key}: {j}"
            );
        }
        assert!(j["warnings"].is_array());
    }
}

/// Section 5.1: V_stick > V_stick,JKR for every T_vis > 0, so fitting a value at or below
/// V_stick,JKR (1.66e-2 m/s for CO2, 60 um) is bad input, refused with V_stick,JKR as `jkr`
/// gives it (the paper's value to its digits, then the same number in the message).
#[test]
fn fit_below_jkr_is_refused() {
    let jkr = f(&json_of("jkr --json")["v_stick_jkr"]);
    assert!((jkr / 1.66e-2 - 1.0).abs() < 0.005 / 1.66, "{jkr}");
    let (code, out, err) = run_line("fit-t-vis --v-stick 0.016");
    assert_eq!(code, 2, "{out}");
    assert!(
        err.contains("--v-stick = 0.016") && err.contains(&format!("V_stick,JKR = {jkr} ")),
        "{err}"
    );
    assert!(out.is_empty());
}

/// A target above v-stick's default limit (1000 V_stick,JKR = 16.6 m/s): fit-t-vis finds it,
/// says how far v-stick must search, and v-stick at the fitted T_vis gives the target back.
#[test]
fn fit_above_the_default_limit_round_trips() {
    let j = json_of("fit-t-vis --v-stick 20 --json");
    let t = f(&j["t_vis"]);
    let w = j["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("--v-max 40.0")),
        "{j}"
    );
    let t_arg = t.to_string();
    let back = json(&["v-stick", "--t-vis", &t_arg, "--v-max", "40", "--json"]);
    let v = f(&back["v_stick"]);
    assert!((v / 20.0 - 1.0).abs() < 1e-3, "{v}");
}

/// An uncertainty reaching down to V_stick,JKR (1.66 cm/s for CO2 60 um): t_vis_min is the JKR
/// limit, 0, with a warning that says why; v_max is recorded as not given (null).
#[test]
fn fit_range_down_to_the_jkr_limit_warns() {
    let j = json_of("fit-t-vis --v-stick 0.04 --v-stick-err 0.03 --json");
    assert_eq!(f(&j["t_vis_min"]), 0.0);
    assert!(j["input"]["v_max"].is_null(), "{j}");
    let w = j["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("t_vis_min = 0 (the JKR limit")),
        "{j}"
    );
}

/// Valid but implausible input warns, on stderr and in the JSON; and before the error when the
/// computation refuses it (a Young's modulus of 1e30 Pa puts the crack-speed bound on T_vis at
/// 4 s), so that the slip is seen as the cause.
#[test]
fn implausible_input_warns() {
    for cmd in ["v-stick", "v-frag", "collide --v-in 0.1"] {
        let (code, _, err) = run_line(&format!("{cmd} --young 1e30 --t-vis 1e-9"));
        assert_eq!(code, 2, "{err}");
        let warned = err
            .find("warning: young = 1e+30 Pa is outside")
            .expect(&err);
        assert!(
            warned < err.find("error: --t-vis = 1e-9").expect(&err),
            "{err}"
        );
    }
    let (code, out, err) = run_line("jkr --radius 60 --json");
    assert_eq!(code, 0);
    assert!(err.contains("did you mean 60e-6 m?"), "{err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["warnings"].as_array().unwrap().len(), 1);
    let (code, out, err) = run_line("collide --t-vis 1e-9 --v-in 2000 --json");
    assert_eq!(code, 0, "{err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    assert!(
        j["warnings"][0]
            .as_str()
            .unwrap()
            .contains("v_in = 2000.0 m/s"),
        "{j}"
    );
}

/// Material files: errors name the file and the field, never a flag that was not given; an
/// override fixes a bad field and is then named itself; titles use the file's stem.
#[test]
fn material_file_errors_name_the_file() {
    let dir = TempDir::new("files");
    let path = dir.join("ice.json");
    let p = path.to_str().unwrap();
    std::fs::write(
        &path,
        r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": -930}"#,
    )
    .unwrap();
    let (code, _, err) = run(&["jkr", "--material", p]);
    assert_eq!(code, 2);
    assert!(
        err.contains(&format!("{p}: density = -930.0: must be > 0")),
        "{err}"
    );
    assert!(!err.contains("--density"), "{err}");
    let (code, text, _) = run(&["jkr", "--material", p, "--density", "930"]);
    assert_eq!(code, 0);
    assert!(
        text.starts_with(
            "JKR contact of two identical spheres of 60 um of ice (density overridden)\n"
        ),
        "{text}"
    );
    let (code, _, err) = run(&["jkr", "--material", p, "--density", "-1"]);
    assert_eq!(code, 2);
    assert!(err.contains("--density = -1.0"), "{err}");
    let missing = dir.join("nothing.json");
    let (code, _, err) = run(&["jkr", "--material", missing.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("not found") && err.contains("nothing.json"),
        "{err}"
    );
}

/// A trajectory path that cannot be written is bad input (exit 2) that names the path.
#[test]
fn unwritable_trajectory_is_bad_input() {
    let (code, _, err) =
        run_line("collide --t-vis 1e-9 --v-in 0.04 --trajectory /nonexistent/t.csv");
    assert_eq!(code, 2);
    assert!(err.contains("/nonexistent/t.csv"), "{err}");
}

/// Text and JSON print the same digits (shortest round-trip), with no trailing spaces, and
/// `no bouncing up to X m/s` where V_stick does not exist (`v_frag`: `above 10 X m/s`).
#[test]
fn one_number_format() {
    let args = ["v-stick", "--t-vis", "1e-6", "--v-max", "2"];
    let (_, text, _) = run(&args);
    assert!(
        text.contains("v_stick        = no bouncing up to 2.0 m/s"),
        "{text}"
    );
    assert!(text.lines().all(|l| !l.ends_with(' ')), "{text:?}");
    // V_frag = 10 V_stick (Section 6): without bouncing up to v_max, above 10 v_max
    let (_, text, _) = run(&["v-frag", "--t-vis", "1e-6", "--v-max", "2"]);
    assert!(
        text.contains("v_frag      = above 20.0 m/s (no bouncing up to 2.0 m/s)"),
        "{text}"
    );
    let (_, text, _) = run(&["jkr"]);
    let j = json_of("jkr --json");
    for key in ["a_eq", "tabor", "f_crit", "v_stick_jkr"] {
        let shown = j[key].to_string();
        assert!(
            text.contains(&format!("= {shown}")),
            "{key}: {shown} not in {text}"
        );
    }
    assert!(text.contains("of 60 um of co2"), "{text}");
}

/// `--help` shows defaults in the same format, and collide's help explains the sign of v_out.
#[test]
fn help_texts() {
    let (_, help, _) = run_line("v-stick --help");
    for default in [
        "[default: 0.00006]",
        "[default: 0.01]",
        "[default: 1e-6]",
        "[default: co2]",
    ] {
        assert!(help.contains(default), "{default} not in {help}");
    }
    let (_, help, _) = run_line("collide --help");
    assert!(
        help.contains("v_out < 0") && help.contains("v_out > 0"),
        "{help}"
    );
    assert!(help.contains("--t-end") && help.contains("--radius2") && help.contains("--wall"));
}

/// `--t-end` keeps a sticking collision going: Figure 2's spiral towards the JKR point.
#[test]
fn t_end_records_the_spiral() {
    let dir = TempDir::new("spiral");
    let path = dir.join("spiral.csv");
    let p = path.to_str().unwrap();
    let j = json(&[
        "collide",
        "--t-vis",
        "1e-9",
        "--v-in",
        "0.035",
        "--t-end",
        "2e-5",
        "--trajectory",
        p,
        "--json",
    ]);
    assert_eq!(j["outcome"], "sticking");
    let text = std::fs::read_to_string(&path).unwrap();
    let last: Vec<f64> = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert!(last[0] >= 2e-5, "integrated to {}", last[0]);
}

/// `fit-t-vis --v-stick` states in its help the cap it enforces (each trial T_vis is searched up
/// to twice the target, within the 1e4 m/s search limit: 5000 m/s).
#[test]
fn fit_t_vis_states_its_cap_on_v_stick() {
    let (code, _, err) = run_line("fit-t-vis --v-stick 5000.1");
    assert_eq!(code, 2);
    assert!(err.contains("<= 5000.0 (m/s)"), "{err}");
    // the highest target V_stick + dV too, named as the uncertainty the user gave
    let (code, _, err) = run_line("fit-t-vis --v-stick 4000 --v-stick-err 2000");
    assert_eq!(code, 2);
    assert!(
        err.contains("--v-stick-err = 2000.0: must be <= 1000.0 m/s here"),
        "{err}"
    );
    let (_, help, _) = run_line("fit-t-vis --help");
    let line = help
        .lines()
        .find(|l| l.contains("Measured threshold velocity"))
        .expect(&help);
    assert!(line.contains("at most 5000.0"), "{line}");
}
