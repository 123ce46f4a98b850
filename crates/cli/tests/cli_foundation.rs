//! The `stickiness` command as a user runs it: JSON contract, defaults, bad input.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{assert_bad_input, json, json_of, run, run_line, TempDir};

/// Defaults are the paper's CO2 case (R1 = 60 um): V_stick,JKR = 1.66e-2 m/s (Section 5.1).
#[test]
fn jkr_defaults_and_keys() {
    let v = json_of("jkr --json");
    for key in [
        "a_eq",
        "delta_eq",
        "tabor",
        "f_crit",
        "delta_crit",
        "e_stick",
        "e_break",
        "v_stick_jkr",
    ] {
        assert!(v[key].as_f64().is_some(), "missing {key}");
    }
    assert!((v["v_stick_jkr"].as_f64().unwrap() - 1.66e-2).abs() < 5e-5);
    let (code, text, _) = run(&["jkr"]);
    assert_eq!(code, 0);
    assert!(text.contains("v_stick_jkr") && text.contains("m/s"));
}

/// Sections 2.5 and 5.4 give two CO2 densities: --density 1650 scales V_stick,JKR by sqrt(1560/1650).
#[test]
fn density_override_scales_v_stick_jkr() {
    let a = json_of("jkr --json")["v_stick_jkr"].as_f64().unwrap();
    let b = json_of("jkr --density 1650 --json")["v_stick_jkr"]
        .as_f64()
        .unwrap();
    assert!((b / a - (1560.0f64 / 1650.0).sqrt()).abs() < 1e-12);
}

/// Appendix A / Figure 1: v(k, 1) = 0 and sign(v) = sign(1 - beta).
#[test]
fn crack_law_keys_and_signs() {
    let v = json_of("crack-law --k 0.01 --beta 2 --json");
    for key in ["k", "beta", "alpha", "v"] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert!(v["v"].as_f64().unwrap() < 0.0);
    let v = json_of("crack-law --beta 0.5 --json");
    assert!(v["v"].as_f64().unwrap() > 0.0);
    let v = json_of("crack-law --beta 1 --json");
    assert_eq!(v["v"].as_f64().unwrap(), 0.0);
}

#[test]
fn bad_input_names_the_flag_and_range() {
    assert_bad_input(&[
        ("jkr --radius -1", "--radius"),
        ("jkr --radius 0", "--radius"),
        ("jkr --poisson 0.5", "--poisson"),
        ("jkr --poisson -1", "--poisson"),
        ("jkr --young nan", "--young"),
        ("crack-law --k 1 --beta 0.5", "--k"),
        ("crack-law --k 0.01 --beta 200", "--beta"),
    ]);
    let (code, _, err) = run_line("jkr --material co3");
    assert_eq!(code, 2);
    assert!(err.contains("co2, h2o") && err.contains("JSON"), "{err}");
}

/// A value that is not a number is bad input like any other: exit code 2 and one line naming
/// the flag, the value and what the flag takes (its help line), not clap's three lines; a flag
/// taken for the value of the option before it is named as such first.
#[test]
fn a_value_that_is_not_a_number_is_named_in_one_line() {
    let dir = TempDir::new("not-a-number");
    let out_file = dir.join("never.csv");
    let sweep = |jobs: &str| {
        let mut args = vec!["sweep", "--jobs", jobs, "--t-vis", "1e-9", "--out"];
        args.push(out_file.to_str().unwrap());
        args.into_iter().map(String::from).collect::<Vec<_>>()
    };
    let words = |line: &str| {
        line.split_whitespace()
            .map(String::from)
            .collect::<Vec<_>>()
    };
    for (args, expected) in [
        (words("v-stick --radius abc --t-vis 1e-9"), "--radius = abc: not a number; radius R1"),
        (words("collide --t-vis x --v-in 0.01"), "--t-vis = x: not a number; viscoelastic"),
        (words("v-stick --k 0.0x --t-vis 1e-9"), "--k = 0.0x: not a number; ratio of relaxed"),
        (sweep("1.5"), "--jobs = 1.5: not a whole number"),
        (sweep("99999999999999999999999"), "too large"),
        (
            words("--json collide --t-vis --v-in=0.1"),
            "a value is required for '--t-vis <T_VIS>' but none was supplied (found the flag '--v-in=0.1')",
        ),
        (words("v-stick --radius --help"), "(found the flag '--help')"),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(err.contains(expected), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    }
    // refused while parsing: no file is made
    assert!(!out_file.exists());
}

/// Every other usage error is one line as well (exit 2): clap's message with the possible
/// values, the missing flags or its tip appended, without the usage synopsis, which after a
/// conflict showed a command line that had never been given.
#[test]
fn usage_errors_are_one_line() {
    for (line, expected) in [
        (
            "v-stick --t-vis-law foo",
            "'foo' for '--t-vis-law <T_VIS_LAW>' [possible values: co2, h2o]",
        ),
        (
            "v-stick --t-vis 1e-9 --t-vis-law co2",
            "'--t-vis <T_VIS>' cannot be used with",
        ),
        (
            "v-stick --t-vis 1e-9 --wall --radius2 1e-5",
            "'--wall' cannot be used with",
        ),
        (
            "collide --t-vis 1e-9 --v-in 0.04 --method search",
            "[possible values: ode, table]",
        ),
        (
            "fit-t-vis",
            "required arguments were not provided: --v-stick <V_STICK>",
        ),
        (
            "sweep --t-vis 1e-9 --out x.csv --format xml",
            "[possible values: csv, jsonl]",
        ),
        (
            "v-stik",
            "unrecognized subcommand 'v-stik'; tip: a similar subcommand exists",
        ),
        (
            "v-stick --tvis 1e-9",
            "unexpected argument '--tvis' found; tip:",
        ),
    ] {
        let args: Vec<&str> = line.split_whitespace().collect();
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{line}: {err}");
        assert!(out.is_empty(), "{line}: {out}");
        assert_eq!(err.trim().lines().count(), 1, "{line}: {err}");
        assert!(
            err.starts_with("error: ") && err.contains(expected),
            "{line}: {err}"
        );
    }
    // help and version are what was asked for: clap's own, on stdout
    let (code, out, _) = run(&["v-stick", "--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("Usage: stickiness v-stick"), "{out}");
}

/// Every collision command states the collisions' range of k (0 < k <= 0.9, `dynamics::K_MAX`)
/// whichever check refuses it; `crack-law` alone takes any k below 1.
#[test]
fn collision_commands_state_the_collisions_range_of_k() {
    for k in ["0", "-0.1", "0.95", "1", "2", "nan"] {
        for command in [
            &["v-stick", "--t-vis", "1e-9"][..],
            &["collide", "--t-vis", "1e-9", "--v-in", "0.01"],
        ] {
            let mut args = command.to_vec();
            args.extend(["--k", k]);
            let (code, _, err) = run(&args);
            assert_eq!(code, 2, "{args:?}: {err}");
            assert!(
                err.contains("must be 0 < k <= 0.9 for a collision"),
                "{args:?}: {err}"
            );
        }
    }
    let (code, _, err) = run(&["crack-law", "--k", "2", "--beta", "1"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--k = 2.0: must be 0 < k < 1"), "{err}");
}

/// A Poisson ratio of 0 is named as such by every collision command and by a sweep of any
/// T_vis > 0 (the drag A = T_vis/nu^2 of Section 2.5 is infinite there), not blamed on T_vis;
/// `jkr` takes it (no drag in JKR).
#[test]
fn collision_commands_name_a_poisson_ratio_of_zero() {
    for command in [
        &["v-stick", "--t-vis", "1e-9"][..],
        &["collide", "--t-vis", "1e-9", "--v-in", "0.01"],
        &["fit-t-vis", "--v-stick", "0.04"],
    ] {
        let mut args = command.to_vec();
        args.extend(["--poisson", "0"]);
        let (code, _, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(
            err.contains("--poisson = 0") && err.contains("nonzero for a collision"),
            "{args:?}: {err}"
        );
    }
    let (code, _, err) = run(&["jkr", "--poisson", "0"]);
    assert_eq!(code, 0, "{err}");
    // a sweep refuses it before any work (no file made); at T_vis = 0 alone (the JKR limit,
    // no collision) it runs
    let dir = TempDir::new("sweep-poisson");
    let out = dir.join("s.csv");
    let o = out.to_str().unwrap();
    let (code, _, err) = run(&[
        "sweep",
        "--t-vis",
        "1e-9,1e-8",
        "--poisson",
        "0",
        "--out",
        o,
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--poisson = 0") && err.contains("nonzero for a collision"),
        "{err}"
    );
    assert!(!out.exists());
    let (code, _, err) = run(&["sweep", "--t-vis", "0", "--poisson", "0", "--out", o]);
    assert_eq!(code, 0, "{err}");
}

/// The range of T_vis is each command's: `collide` needs T_vis > 0 (0 is no collision), the
/// thresholds take 0 (the JKR limit); NaN and infinities are refused by all, and `collide
/// --trajectory` leaves its file as it was when T_vis or V_in is bad input.
#[test]
fn each_command_names_its_own_range_of_t_vis() {
    for t in ["-1", "0", "nan", "inf", "-inf"] {
        let (code, _, err) = run(&["collide", "--t-vis", t, "--v-in", "0.01"]);
        assert_eq!(code, 2, "{t}: {err}");
        assert!(
            err.contains("--t-vis") && err.contains("must be > 0"),
            "{t}: {err}"
        );
    }
    for command in ["v-stick", "v-frag"] {
        for t in ["-1", "nan", "inf", "-inf"] {
            let (code, _, err) = run(&[command, "--t-vis", t]);
            assert_eq!(code, 2, "{command} {t}: {err}");
            assert!(
                err.contains("--t-vis") && err.contains("must be >= 0"),
                "{command} {t}: {err}"
            );
        }
    }
    let dir = TempDir::new("trajectory-bad-input");
    let kept = dir.join("kept.csv");
    std::fs::write(&kept, "kept\n").unwrap();
    let made = dir.join("made.csv");
    for (t, v) in [("nan", "0.01"), ("1e-9", "-1")] {
        for path in [&kept, &made] {
            let args = [
                "collide",
                "--t-vis",
                t,
                "--v-in",
                v,
                "--trajectory",
                path.to_str().unwrap(),
            ];
            let (code, _, err) = run(&args);
            assert_eq!(code, 2, "{args:?}: {err}");
        }
    }
    assert_eq!(std::fs::read_to_string(&kept).unwrap(), "kept\n");
    assert!(!made.exists());
}

/// A material file with the four SI constants works like a preset (H2O of Section 5.2 here);
/// a missing or unknown field is named.
#[test]
fn material_from_json_file() {
    let dir = TempDir::new("material");
    let good = dir.join("ice.json");
    std::fs::write(
        &good,
        r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": 930}"#,
    )
    .unwrap();
    let from_file = json(&[
        "jkr",
        "--material",
        good.to_str().unwrap(),
        "--radius",
        "90e-6",
        "--json",
    ]);
    let mut preset = json_of("jkr --material h2o --radius 90e-6 --json");
    // the same numbers; only the material's name differs in the inputs
    preset["input"]["material"] = from_file["input"]["material"].clone();
    assert_eq!(from_file, preset);
    let bad = dir.join("bad.json");
    std::fs::write(&bad, r#"{"gamma_sv": 0.1, "young": 7e9, "density": 930}"#).unwrap();
    let (code, _, err) = run(&["jkr", "--material", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("poisson"), "{err}");
    // and what a material file holds, with the units
    assert!(err.contains(r#""density": kg/m^3"#), "{err}");
    std::fs::write(
        &bad,
        r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": 930, "color": 1}"#,
    )
    .unwrap();
    let (code, _, err) = run(&["jkr", "--material", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("color"), "{err}");
}
