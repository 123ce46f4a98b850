//! `stickiness sweep`: grid order, identity with single-point searches, the file contract, and
//! a kill -9 followed by --resume giving the same bytes as an uninterrupted run.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{json, run, TempDir};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

fn dir(name: &str) -> TempDir {
    TempDir::new(&format!("sweep-{name}"))
}

fn sweep(args: &[&str], out: &Path) -> (i32, String, String) {
    let mut a: Vec<String> = vec!["sweep".into()];
    a.extend(args.iter().map(|s| s.to_string()));
    a.push("--out".into());
    a.push(out.display().to_string());
    run(&a)
}

/// Data rows as maps column -> field.
fn rows(path: &Path) -> Vec<std::collections::BTreeMap<String, String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect()
}

const SMALL: [&str; 6] = [
    "--material",
    "co2,h2o",
    "--radius",
    "1e-6:1e-5:2",
    "--t-vis",
    "1e-12,1e-10,1e-9",
];

/// Rows come in grid order (material, gamma_sv, radius, radius2, t_vis, k; outermost first) and
/// each equals the single-point `v-stick` for its inputs: exactly for the first T_vis of a chunk
/// (no hint), within the bracket tolerance (1e-6) for the rest (seeded by their neighbour).
#[test]
fn rows_in_grid_order_equal_single_points() {
    let d = dir("order");
    let out = d.join("s.csv");
    let (code, _, err) = sweep(&[&SMALL[..], &["--k", "0.01,0.02"]].concat(), &out);
    assert_eq!(code, 0, "{err}");
    let rows = rows(&out);
    assert_eq!(rows.len(), 2 * 2 * 3 * 2);
    let mut i = 0;
    for material in ["co2", "h2o"] {
        for radius in ["1e-6", "0.00001"] {
            for (ti, t_vis) in ["1e-12", "1e-10", "1e-9"].iter().enumerate() {
                for k in ["0.01", "0.02"] {
                    let r = &rows[i];
                    assert_eq!(
                        (
                            r["material"].as_str(),
                            r["radius"].as_str(),
                            r["t_vis"].as_str(),
                            r["k"].as_str()
                        ),
                        (material, radius, *t_vis, k),
                        "row {i}"
                    );
                    let single = json(&[
                        "v-stick",
                        "--material",
                        material,
                        "--radius",
                        radius,
                        "--t-vis",
                        t_vis,
                        "--k",
                        k,
                        "--json",
                    ]);
                    for key in [
                        "v_stick",
                        "v_double_onset",
                        "v_stick_jkr",
                        "no_bouncing_below",
                    ] {
                        // an empty field is JSON's null
                        let a: Option<f64> = r[key].parse().ok();
                        let b = single[key].as_f64();
                        match (a, b) {
                            (Some(a), Some(b)) if ti > 0 && key != "v_stick_jkr" => {
                                assert!((a / b - 1.0).abs() < 2e-6, "row {i} {key}: {a} vs {b}")
                            }
                            _ => assert_eq!(a, b, "row {i} {key}"),
                        }
                    }
                    let vs: Option<f64> = r["v_stick"].parse().ok();
                    assert_eq!(r["v_frag"].parse::<f64>().ok(), vs.map(|v| 10.0 * v));
                    i += 1;
                }
            }
        }
    }
}

/// A sweep killed with SIGKILL part-way, then run again with --resume, ends byte-identical to
/// an uninterrupted run. The exact search (`--method search`, about 1 s here) so that the kill
/// lands among the rows and the resumed chunks must start from the hints the written rows give
/// (the tables answer this grid in milliseconds, before a kill could land). The kill lands at
/// half the uninterrupted duration; a kill after the end is retried earlier, one before the
/// first row later.
#[test]
fn kill_and_resume_gives_the_same_bytes() {
    let d = dir("resume");
    let args = [
        "--material",
        "co2,h2o",
        "--radius",
        "1e-6:1e-4:41",
        "--t-vis",
        "1e-12:1e-8:9",
        "--method",
        "search",
    ];
    let whole = d.join("whole.csv");
    let start = Instant::now();
    let (code, _, err) = sweep(&args, &whole);
    assert_eq!(code, 0, "{err}");
    let duration = start.elapsed();
    let expected = std::fs::read(&whole).unwrap();
    // the '#' lines and the column names
    let text = String::from_utf8(expected.clone()).unwrap();
    let columns = text.lines().position(|l| !l.starts_with('#')).unwrap();
    let header_len: usize = text.lines().take(columns + 1).map(|l| l.len() + 1).sum();
    let mut delay = duration / 2;
    let part = d.join("part.csv");
    let mut interrupted = false;
    for _ in 0..8 {
        let _ = std::fs::remove_file(&part);
        let mut child = Command::new(env!("CARGO_BIN_EXE_stickiness"))
            .arg("sweep")
            .args(args)
            .arg("--out")
            .arg(&part)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(delay);
        child.kill().unwrap(); // SIGKILL
        let status = child.wait().unwrap();
        let written = std::fs::read(&part).unwrap_or_default();
        if status.success() || written.len() >= expected.len() {
            delay /= 2;
            continue;
        }
        // what was written up to its last complete line is the start of the whole file
        let complete = written
            .iter()
            .rposition(|b| *b == b'\n')
            .map_or(0, |i| i + 1);
        assert!(expected.starts_with(&written[..complete]));
        if complete <= header_len {
            delay = delay * 3 / 2;
            continue;
        }
        interrupted = true;
        break;
    }
    assert!(
        interrupted,
        "no kill landed among the rows ({duration:?} uninterrupted)"
    );
    let (code, _, err) = sweep(&[&args[..], &["--resume"]].concat(), &part);
    assert_eq!(code, 0, "{err}");
    assert!(
        std::fs::read(&part).unwrap() == expected,
        "the resumed file differs"
    );
}

/// --resume drops a torn last line and starts again a file whose header was cut short; an
/// existing file needs --resume or --force; a file of another sweep is refused (its header cut
/// short too); bad axes (too many values too) exit 2 naming the flag before any file is written.
#[test]
fn file_contract() {
    let d = dir("contract");
    let out = d.join("s.csv");
    let (code, _, err) = sweep(&SMALL, &out);
    assert_eq!(code, 0, "{err}");
    let whole = std::fs::read_to_string(&out).unwrap();
    // tear the file in the middle of its last line, and drop one more row
    let cut = whole.trim_end().rfind('\n').unwrap();
    let cut = whole[..cut].rfind('\n').unwrap() + 20;
    std::fs::write(&out, &whole[..cut]).unwrap();
    let (code, _, err) = sweep(&[&SMALL[..], &["--resume"]].concat(), &out);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), whole);
    // a kill before the header was complete (cut in its first line, in the command line, just
    // before its end, and empty) holds no rows: --resume starts it again, ending with the whole
    // file
    let header_len = whole.find("\nmaterial,").unwrap() + 1;
    // past "--material co2,h2o", where the other sweep of this test differs
    let command_line = whole.find("# command:").unwrap() + 60;
    for cut in [20, command_line, header_len - 1, 0] {
        std::fs::write(&out, &whole[..cut]).unwrap();
        let (code, _, err) = sweep(&[&SMALL[..], &["--resume"]].concat(), &out);
        assert_eq!(code, 0, "cut at {cut}: {err}");
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            whole,
            "cut at {cut}"
        );
    }
    let (code, _, err) = sweep(&SMALL, &out);
    assert_eq!(code, 2);
    assert!(err.contains("--resume") && err.contains("--force"), "{err}");
    let (code, _, err) = sweep(&["--material", "co2", "--t-vis", "1e-9", "--resume"], &out);
    assert_eq!(code, 2);
    assert!(err.contains("another sweep"), "{err}");
    // the header of this sweep cut short is not a beginning of the other's: refused too
    std::fs::write(&out, &whole[..command_line]).unwrap();
    let (code, _, err) = sweep(&["--material", "co2", "--t-vis", "1e-9", "--resume"], &out);
    assert_eq!(code, 2);
    assert!(err.contains("another sweep"), "{err}");
    std::fs::write(&out, &whole).unwrap();
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        whole,
        "a refused resume changes nothing"
    );
    let (code, _, err) = sweep(&["--material", "co2", "--t-vis", "1e-9", "--force"], &out);
    assert_eq!(code, 0, "{err}");
    for (args, flag) in [
        (
            vec!["--radius", "1e-4:1e-6:0", "--t-vis", "1e-9"],
            "--radius",
        ),
        (
            vec!["--radius", "-1e-6,1e-6", "--t-vis", "1e-9"],
            "--radius",
        ),
        (vec!["--material", "co2,co3", "--t-vis", "1e-9"], "co3"),
        (vec!["--t-vis", "1e-9:abc:3"], "--t-vis"),
        (vec!["--k", "0.01,1.5", "--t-vis", "1e-9"], "--k"),
        // a typo in N (a billion radii: 8 GB for the axis alone) and a grid of 1e14 points
        (
            vec!["--radius", "1e-6:1e-4:1000000000", "--t-vis", "1e-9"],
            "--radius",
        ),
        (
            vec![
                "--radius",
                "1e-6:1e-4:10000000",
                "--t-vis",
                "1e-12:1e-8:10000000",
            ],
            "--t-vis: 10000000 values make a grid of 100000000000000 points",
        ),
    ] {
        let fresh = d.join("never.csv");
        let (code, out_text, err) = sweep(&args, &fresh);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(out_text.is_empty());
        assert!(
            !fresh.exists(),
            "{args:?}: a file was written before the check"
        );
    }
}

/// --resume on a file of the other format names the format the file was written in.
#[test]
fn resuming_a_file_of_the_other_format_names_it() {
    let d = dir("other-format");
    let (csv, jsonl) = (d.join("s.csv"), d.join("s.jsonl"));
    assert_eq!(sweep(&SMALL, &csv).0, 0);
    assert_eq!(
        sweep(&[&SMALL[..], &["--format", "jsonl"]].concat(), &jsonl).0,
        0
    );
    let resume = [&SMALL[..], &["--resume"]].concat();
    let (code, _, err) = sweep(&[&resume[..], &["--format", "jsonl"]].concat(), &csv);
    assert_eq!(code, 2);
    assert!(err.contains("in the other format (--format csv)"), "{err}");
    let (code, _, err) = sweep(&resume, &jsonl);
    assert_eq!(code, 2);
    assert!(
        err.contains("in the other format (--format jsonl)"),
        "{err}"
    );
}

/// Geometry and law axes fill their columns; JSON Lines carry the same values.
#[test]
fn columns_and_jsonl() {
    let d = dir("columns");
    let csv = d.join("s.csv");
    let args = "--material co2 --radius 6e-5 --wall --t-vis-law co2 --gamma-sv 0.07,0.08";
    let args: Vec<&str> = args.split_whitespace().collect();
    let (code, _, err) = sweep(&args, &csv);
    assert_eq!(code, 0, "{err}");
    let r = rows(&csv);
    assert_eq!(r.len(), 2);
    assert_eq!(
        (r[0]["radius2"].as_str(), r[0]["wall"].as_str()),
        ("", "true")
    );
    assert_eq!(
        (r[0]["gamma_sv"].as_str(), r[1]["gamma_sv"].as_str()),
        ("0.07", "0.08")
    );
    let t: f64 = r[0]["t_vis"].parse().unwrap();
    assert!((t / (1e-11 * 60f64.powf(1.11)) - 1.0).abs() < 1e-12); // Section 5.3 CO2 law
    let jl = d.join("s.jsonl");
    let (code, _, err) = sweep(&[&args[..], &["--format", "jsonl"]].concat(), &jl);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&jl).unwrap();
    let lines: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert!(lines[0]["sweep"]["columns"].is_array());
    assert_eq!(
        lines[1]["v_stick"].as_f64().unwrap(),
        r[0]["v_stick"].parse::<f64>().unwrap()
    );
    assert_eq!(lines[1]["radius2"], serde_json::Value::Null);
}

/// Progress goes to stderr as plain lines when stderr is not a terminal.
#[test]
fn progress_lines_when_not_a_terminal() {
    let d = dir("progress");
    let (code, _, err) = sweep(&SMALL, &d.join("s.csv"));
    assert_eq!(code, 0);
    assert!(err.contains("sweep: 12/12 rows (100.0 %)"), "{err}");
}

/// A row's warning (a radius of 60 m, most often meant in um) is summed up on stderr and in
/// the JSON summary, not only left in the file's warnings column; a grid of plausible grains
/// gives none.
#[test]
fn rows_with_warnings_are_summed_up() {
    let d = dir("warned");
    let out = d.join("w.csv");
    let (code, stdout, err) = sweep(&["--t-vis", "1e-9", "--radius", "60e-6,60", "--json"], &out);
    assert_eq!(code, 0, "{err}");
    let w = serde_json::from_str::<serde_json::Value>(&stdout).unwrap()["warnings"]
        .as_array()
        .unwrap()
        .clone();
    assert_eq!(w.len(), 1, "{stdout}");
    let w = w[0].as_str().unwrap();
    assert!(
        w.starts_with("rows computed with warnings: 1 of 2")
            && w.contains("row 1: radius = 60.0 m"),
        "{w}"
    );
    assert!(
        err.contains("warning: rows computed with warnings"),
        "{err}"
    );
    // a size law of the other ice is a row's warning too (TVisLaw::mismatch)
    let (code, _, err) = sweep(
        &["--material", "co2,h2o", "--t-vis-law", "h2o", "--force"],
        &out,
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("1 of 2") && err.contains("row 0: t_vis_law = 'h2o'"),
        "{err}"
    );
    let (code, stdout, _) = sweep(&["--t-vis", "1e-9", "--json", "--force"], &out);
    assert_eq!(code, 0);
    assert_eq!(
        serde_json::from_str::<serde_json::Value>(&stdout).unwrap()["warnings"]
            .as_array()
            .map(Vec::len),
        Some(0)
    );
}

/// `sweep --method table` fills the method column with the path that answered each row.
#[test]
fn method_column() {
    let d = dir("method");
    let out = d.join("s.csv");
    // k = 0.06 lies outside the tables' 0.005-0.05: the search answers it; beyond the cliff
    // (1e-6 s) the tables say "no bouncing" themselves
    let (code, _, err) = sweep(
        &[
            "--t-vis",
            "1e-9,1e-6",
            "--k",
            "0.01,0.06",
            "--method",
            "table",
        ],
        &out,
    );
    assert_eq!(code, 0, "{err}");
    let methods: Vec<String> = rows(&out)
        .iter()
        .map(|r| format!("{} {} {}", r["k"], r["t_vis"], r["method"]))
        .collect();
    assert_eq!(
        methods,
        [
            "0.01 1e-9 table",
            "0.06 1e-9 search",
            "0.01 1e-6 table",
            "0.06 1e-6 search"
        ]
    );
}

/// A kill can cut a line inside a character (a material file's non-ASCII path, written in the
/// header and in every row): --resume cuts the torn line off and ends with the whole file.
#[test]
fn a_file_cut_inside_a_character_resumes() {
    let d = dir("utf8");
    let material = d.join("glacé.json");
    std::fs::write(
        &material,
        r#"{"gamma_sv": 0.08, "young": 1.07e10, "poisson": 0.26, "density": 1560}"#,
    )
    .unwrap();
    let out = d.join("s.csv");
    let material = material.display().to_string();
    let args = ["--material", &material, "--t-vis", "1e-12,1e-10,1e-9"];
    let (code, _, err) = sweep(&args, &out);
    assert_eq!(code, 0, "{err}");
    let whole = std::fs::read(&out).unwrap();
    // inside the two bytes of 'é': in the header's command line, and in the last row
    let e_acute = "é".as_bytes();
    let inside: Vec<usize> = whole
        .windows(2)
        .enumerate()
        .filter(|(_, w)| *w == e_acute)
        .map(|(i, _)| i + 1)
        .collect();
    for cut in [inside[0], inside[inside.len() - 1]] {
        std::fs::write(&out, &whole[..cut]).unwrap();
        let (code, _, err) = sweep(&[&args[..], &["--resume"]].concat(), &out);
        assert_eq!(code, 0, "cut at {cut}: {err}");
        assert!(std::fs::read(&out).unwrap() == whole, "cut at {cut}");
    }
}
