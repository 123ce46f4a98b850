//! A few hundred random argument combinations: the command never panics, never prints NaN or
//! infinity, exits with 0, 1 (computation failed) or 2 (usage), and with --json prints exactly one
//! JSON object on success. Results are identical between reruns.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::run;

/// xorshift64*: a fixed, dependency-free sequence so the test is reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[(self.next() % xs.len() as u64) as usize]
    }
}

const ODD: [&str; 22] = [
    "0", "-1", "1e-300", "1e300", "nan", "NaN", "inf", "-inf", "abc", "", "1e-9", "0.5", "60e-6",
    "1e-2", "0.01", "0.99", "1", "2", "-0", "1e-16", "1e-6", "3.5e-2",
];

#[test]
fn random_arguments_never_panic_or_print_nan() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let commands: [(&str, &[&str]); 6] = [
        (
            "jkr",
            &[
                "--radius",
                "--radius2",
                "--gamma-sv",
                "--young",
                "--poisson",
                "--density",
                "--material",
            ],
        ),
        ("crack-law", &["--k", "--beta"]),
        (
            "collide",
            &[
                "--radius",
                "--radius2",
                "--t-vis",
                "--v-in",
                "--k",
                "--poisson",
                "--gamma-sv",
            ],
        ),
        (
            "v-stick",
            &[
                "--radius",
                "--t-vis",
                "--k",
                "--density",
                "--v-max",
                "--rel-tol",
            ],
        ),
        (
            "v-frag",
            &["--radius", "--t-vis", "--k", "--young", "--t-vis-law"],
        ),
        ("material", &["--gamma-sv", "--poisson"]),
    ];
    let materials = ["co2", "h2o", "CO2", "ice", "/nonexistent.json"];
    let mut ok = 0;
    for _ in 0..300 {
        let (cmd, flags) = commands[(rng.next() % commands.len() as u64) as usize];
        let mut args = vec![cmd.to_string()];
        // required arguments with sensible values most of the time, odd ones otherwise
        let required: &[(&str, &str)] = match cmd {
            "crack-law" => &[("--beta", "2")],
            "collide" => &[("--t-vis", "1e-9"), ("--v-in", "0.045")],
            "v-stick" => &[("--t-vis", "1e-9")],
            "material" => &[("--", "h2o")],
            _ => &[],
        };
        for (flag, good) in required {
            if *flag != "--" {
                args.push(flag.to_string());
            }
            args.push(
                if rng.next().is_multiple_of(3) {
                    rng.pick(&ODD)
                } else {
                    good
                }
                .to_string(),
            );
        }
        for _ in 0..(rng.next() % 3) {
            let flag = rng.pick(flags);
            args.push(flag.to_string());
            args.push(
                if flag == "--material" {
                    rng.pick(&materials)
                } else {
                    rng.pick(&ODD)
                }
                .to_string(),
            );
        }
        if rng.next().is_multiple_of(2) {
            args.push("--json".into());
        }
        let (code, out, err) = run(&args);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(matches!(code, 0..=2), "{args:?}: exit {code}: {err}");
        let bad = out
            .split(|c: char| !c.is_ascii_alphanumeric())
            .any(|t| ["nan", "inf", "infinity"].contains(&t.to_ascii_lowercase().as_str()));
        assert!(!bad, "{args:?}: {out}");
        if code == 0 {
            ok += 1;
            if args.iter().any(|a| a == "--json") {
                let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
                assert!(v.is_object());
            }
        } else {
            assert!(out.is_empty(), "{args:?}: failure printed to stdout: {out}");
            // the setup's warnings first (they may explain the failure), then the error
            let first = err.lines().find(|l| !l.starts_with("warning: "));
            assert!(
                first.is_some_and(|l| l.starts_with("error")) || err.contains("Usage"),
                "{args:?}: {err}"
            );
        }
    }
    assert!(
        ok > 50,
        "only {ok} successful runs: the generator is too hostile to test results"
    );
}

#[test]
fn reruns_are_bit_identical() {
    let args: Vec<String> = [
        "v-stick",
        "--material",
        "h2o",
        "--radius",
        "90e-6",
        "--t-vis",
        "1e-9",
        "--json",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let (a, b) = (run(&args), run(&args));
    assert_eq!(a.0, 0);
    assert_eq!(a.1, b.1);
}
