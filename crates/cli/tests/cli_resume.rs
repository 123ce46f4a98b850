//! `stickiness sweep --resume` on damaged files (the issue "Resume keeps only rows it can vouch
//! for"): a row deleted, duplicated or swapped, an input edited, a result edited (found with
//! `--verify`), a result that is not a number, garbage appended: each is refused with exit 2
//! and one line naming the file, the line and the column, and the file is left untouched; a
//! torn last line is still dropped and recomputed, byte for byte.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{run, TempDir};
use std::path::Path;

/// The sweep: 6 radii x 4 T_vis = 24 rows.
const ARGS: [&str; 4] = ["--radius", "1e-6:1e-4:6", "--t-vis", "1e-12:1e-9:4"];

/// The CSV header: five `#` lines and the column names, so the first row is line 7.
const FIRST_ROW_LINE: usize = 7;

fn sweep(out: &Path, extra: &[&str]) -> (i32, String, String) {
    let mut a: Vec<String> = vec!["sweep".into()];
    a.extend(ARGS.iter().chain(extra).map(|s| s.to_string()));
    a.extend(["--out".to_string(), out.display().to_string()]);
    run(&a)
}

/// A whole sweep file, and the same with `damage` done to its lines (header lines first).
fn damaged(d: &TempDir, name: &str, damage: impl Fn(&mut Vec<String>)) -> (String, String) {
    let out = d.join(name);
    let (code, _, err) = sweep(&out, &[]);
    assert_eq!(code, 0, "{err}");
    let whole = std::fs::read_to_string(&out).unwrap();
    let mut lines: Vec<String> = whole.lines().map(String::from).collect();
    damage(&mut lines);
    let text = lines.join("\n") + "\n";
    std::fs::write(&out, &text).unwrap();
    (whole, text)
}

/// `--resume` (with `extra`) on `name` is refused: exit 2, one line naming the file, the line
/// and the column, and the file as it was.
fn assert_refused(d: &TempDir, name: &str, text: &str, extra: &[&str], line: usize, column: &str) {
    let out = d.join(name);
    let (code, stdout, err) = sweep(&out, &[&["--resume"], extra].concat());
    assert_eq!(code, 2, "{name}: {err}");
    assert!(stdout.is_empty(), "{name}: {stdout}");
    assert_eq!(err.trim().lines().count(), 1, "{name}: {err}");
    let said = format!("line {line}, column {column}");
    assert!(
        err.contains(&out.display().to_string()) && err.contains(&said),
        "{name}: expected '{said}' in: {err}"
    );
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        text,
        "{name}: a refused resume changed the file"
    );
}

/// The two silent failures: the 6th data row deleted (rows shift: line 12 holds grid
/// point 7, whose t_vis differs) and the 9th row's v_stick set to 0.123 by hand (kept by a plain
/// --resume, found by --verify, which recomputes every kept row here).
#[test]
fn a_deleted_row_and_an_edited_result_are_refused() {
    let d = TempDir::new("resume-deleted");
    let sixth = FIRST_ROW_LINE - 1 + 5;
    let (_, text) = damaged(&d, "deleted.csv", |l| {
        l.remove(sixth);
    });
    assert_refused(&d, "deleted.csv", &text, &[], FIRST_ROW_LINE + 5, "t_vis");

    let ninth = FIRST_ROW_LINE - 1 + 8;
    let (_, text) = damaged(&d, "edited.csv", |l| {
        let mut f: Vec<String> = l[ninth].split(',').map(String::from).collect();
        f[10] = "0.123".into(); // v_stick
        l[ninth] = f.join(",");
    });
    // the edit reads as a number: a plain resume cannot tell, --verify recomputes and can
    assert_refused(
        &d,
        "edited.csv",
        &text,
        &["--verify", "30"],
        ninth + 1,
        "v_stick",
    );
}

/// A row repeated, two rows swapped, an input edited, a result that is not a number, garbage
/// appended: each refused at its line and column.
#[test]
fn repeated_swapped_and_edited_rows_are_refused() {
    let d = TempDir::new("resume-damage");
    let row = |i: usize| FIRST_ROW_LINE - 1 + i; // index in the lines of data row i (0-based)
    let (_, text) = damaged(&d, "repeated.csv", |l| {
        let r = l[row(3)].clone();
        l.insert(row(3), r);
    });
    assert_refused(&d, "repeated.csv", &text, &[], row(4) + 1, "radius");
    let (_, text) = damaged(&d, "swapped.csv", |l| l.swap(row(4), row(9)));
    assert_refused(&d, "swapped.csv", &text, &[], row(4) + 1, "radius");
    let (_, text) = damaged(&d, "input.csv", |l| {
        l[row(2)] = l[row(2)].replacen("co2,", "h2o,", 1);
    });
    assert_refused(&d, "input.csv", &text, &[], row(2) + 1, "material");
    let (_, text) = damaged(&d, "result.csv", |l| {
        let mut f: Vec<String> = l[row(7)].split(',').map(String::from).collect();
        f[12] = "fast".into(); // v_stick_jkr
        l[row(7)] = f.join(",");
    });
    assert_refused(&d, "result.csv", &text, &[], row(7) + 1, "v_stick_jkr");
    let (_, text) = damaged(&d, "garbage.csv", |l| {
        l.truncate(row(10));
        l.push("some,garbage".into());
    });
    assert_refused(&d, "garbage.csv", &text, &[], row(10) + 1, "row");
}

/// A torn last line (a kill mid-write) is dropped and recomputed: the file ends byte-identical
/// to the whole sweep; `--verify` passes on an intact file; JSON Lines are checked the same way.
#[test]
fn a_torn_line_is_completed_and_jsonl_is_checked() {
    let d = TempDir::new("resume-torn");
    let out = d.join("torn.csv");
    let (whole, _) = damaged(&d, "torn.csv", |l| {
        l.truncate(FIRST_ROW_LINE - 1 + 15);
        let last = l.len() - 1;
        l[last].truncate(17);
    });
    let torn = std::fs::read_to_string(&out).unwrap();
    std::fs::write(&out, torn.trim_end_matches('\n')).unwrap();
    let (code, _, err) = sweep(&out, &["--resume", "--verify", "5"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), whole);

    let jl = d.join("s.jsonl");
    let (code, _, err) = sweep(&jl, &["--format", "jsonl"]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&jl).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    lines.remove(4); // the header line, then data rows 0..: row 3 (R1 = 1e-6 m) gone
    let damaged_text = lines.join("\n") + "\n";
    std::fs::write(&jl, &damaged_text).unwrap();
    let (code, _, err) = sweep(&jl, &["--format", "jsonl", "--resume"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("line 5, column radius"), "{err}");
    assert_eq!(std::fs::read_to_string(&jl).unwrap(), damaged_text);
}
