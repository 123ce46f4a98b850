//! Tests of the restitution tables' text and binary forms ([`super`]).

use super::*;

/// A table with three nodes a row and each cell record once, as the module doc defines
/// them: the first row has no `bcells` (bouncing falls back on `cells`), the second no
/// `kbcells` (falls back on `kcells`).
const TEXT: &str = "k,0.01\nsigma,0.5\nnu,0.3,0.6\n\
    row,-1,0.5\nrnode,0.1,2,1.5,0.1,0.2,0.3\nrnode,0.2,2,1.5,0.1,0.2,0.3\n\
    rnode,0.3,2,1.5,0.1,0.2,0.3\ncells,01\nkcells,10\nkbcells,11\n\
    row,-0.5,0.5\nrnode,0.1,2,1.5,0.1,0.2,0.3\nrnode,0.2,2,1.5,0.1,0.2,0.3\n\
    rnode,0.3,2,1.5,0.1,0.2,0.3\ncells,00\nbcells,01\nkcells,01\n";

/// Each side reads its own flags or falls back; the interpolation form holds them reversed
/// (nodes in decreasing x) and resolved; text and binary forms give the table back.
#[test]
fn cell_flags_fall_back_and_survive_both_forms() {
    let (t, f) = (parse(TEXT).expect("the table reads"), false);
    let (first, second) = (&t.rows[0].cells, &t.rows[1].cells);
    assert_eq!(first.side(true), (&[f, true][..], &[true, true][..]));
    assert_eq!(first.side(false), (&[f, true][..], &[true, f][..]));
    assert_eq!(second.side(true), (&[f, true][..], &[f, true][..]));
    assert_eq!(second.side(false), (&[f, f][..], &[f, true][..]));
    let table = Table::from_data(&t);
    assert_eq!(table.rows[0].cells.bouncing, [true, f]);
    assert_eq!(table.rows[1].cells.k_bouncing, [true, f]);
    // the text leaves out what falls back to an equal record, and reads back the same
    let text = crate::restitution::to_text(&t);
    assert_eq!(text.matches("kbcells").count(), 1);
    assert_eq!(parse(&text).expect("written text reads"), t);
    let bytes: &'static [u8] = Box::leak(to_bytes(&[t]).into_boxed_slice());
    assert_eq!(table_from_bytes(bytes, 0), Some(table));
}

/// As the checks write them (every record filled), a bouncing record equal to the one it falls
/// back on is left out of the text, one that differs is kept, and each side's flags read back
/// the same.
#[test]
fn records_equal_to_their_fallback_are_left_out() {
    let mut t = parse(TEXT).expect("the table reads");
    let full = CellFlags {
        all: vec![false, true],
        bouncing: vec![false, true],
        k_all: vec![true, false],
        k_bouncing: vec![true, false],
    };
    t.rows[0].cells = full.clone();
    t.rows[1].cells = CellFlags {
        bouncing: vec![true, true],
        ..full.clone()
    };
    let text = crate::restitution::to_text(&t);
    assert_eq!(text.matches("\nbcells,").count(), 1);
    assert_eq!(text.matches("kbcells").count(), 0);
    let back = parse(&text).expect("written text reads");
    for (r, w) in back.rows.iter().zip(&t.rows) {
        for bouncing in [true, false] {
            assert_eq!(r.cells.side(bouncing), w.cells.side(bouncing));
        }
    }
}

/// Bad cell records are named.
#[test]
fn bad_cell_records_are_refused() {
    let before = "k,0.01\nsigma,0.5\nnu,0.3,0.6\ncells,01\n";
    assert_eq!(parse(before).unwrap_err().problem, "cells before any row");
    let unknown = TEXT.replace("kbcells", "xcells");
    assert_eq!(
        parse(&unknown).unwrap_err().problem,
        "unknown record 'xcells'"
    );
    // a record of the wrong length (three flags for two intervals)
    let long = TEXT.replace("kbcells,11", "kbcells,110");
    assert!(parse(&long)
        .unwrap_err()
        .problem
        .contains("a cell flag per interval"));
}

/// `channel_at` inverts `channel_coordinate` on both sides, from next to V_stick to far
/// above it (ln q + q = z has one root for every z).
#[test]
fn the_channel_coordinate_is_inverted() {
    for q in [1e-4, 3e-3, 0.1, 0.5, 1.0, 2.7, 9.5] {
        let back = channel_at(true, channel_coordinate(true, q));
        assert!((back / q - 1.0).abs() < 1e-13, "{q}: {back}");
    }
    for q in [1e-4, 0.01, 0.5, 0.9, 0.999] {
        let back = channel_at(false, channel_coordinate(false, q));
        assert!((back / q - 1.0).abs() < 1e-12, "{q}: {back}");
    }
}
