//! The master tables' text form, written in the workspace's one number format (shortest round
//! trip): the committed files `crates/thresholds/data/master_k<k>.csv` and `master_ends.csv`.
//! The layout and the reader are in [`super::format`].

use super::format::{EndsData, PieceData, TableData};
use numerics::format::number;
use std::fmt::Write as _;

/// Significant figures of the ratios written: 12, far below the nodes' own error (about 1e-7).
const DIGITS: usize = 12;

/// `v` rounded to [`DIGITS`] significant figures.
fn rounded(v: f64) -> f64 {
    format!("{:.*e}", DIGITS - 1, v).parse().unwrap_or(v)
}

fn header(out: &mut String, lines: &[String]) {
    for h in lines {
        let _ = writeln!(out, "# {h}");
    }
}

fn piece(out: &mut String, p: &PieceData, strip: bool) {
    for i in 0..p.x.len() {
        if strip {
            let _ = writeln!(
                out,
                "snode,{},{}",
                number(p.x[i]),
                number(rounded(p.f_onset[i]))
            );
        } else {
            let _ = writeln!(
                out,
                "node,{},{},{}",
                number(p.x[i]),
                number(rounded(p.f_stick[i])),
                number(rounded(p.f_onset[i]))
            );
        }
    }
}

/// The text of one k's table (see [`super::format`]).
pub fn table_to_text(t: &TableData) -> String {
    let mut out = String::new();
    header(&mut out, &t.header);
    let _ = writeln!(out, "k,{}", number(t.k));
    for (j, r) in t.rows.iter().enumerate() {
        let _ = write!(
            out,
            "row,{},{},{},{}",
            number(r.y),
            number(r.x_s),
            number(r.x_on),
            u8::from(r.monotone)
        );
        if !r.monotone && r.none_beyond > 0.0 {
            let _ = write!(out, ",{}", number(r.none_beyond));
        }
        out.push('\n');
        let _ = write!(
            out,
            "body,{},{}",
            number(r.body.d_lo[0]),
            number(r.body.d_lo[1])
        );
        if let Some(d) = r.body.d_lb {
            let _ = write!(out, ",{},{}", number(d[0]), number(d[1]));
        }
        out.push('\n');
        piece(&mut out, &r.body, false);
        if !r.strip.x.is_empty() {
            let _ = write!(out, "strip,{}", number(r.strip.d_lo[1]));
            if let Some(d) = r.strip.d_lb {
                let _ = write!(out, ",{}", number(d[1]));
            }
            out.push('\n');
            piece(&mut out, &r.strip, true);
        }
        if let Some(c) = t.cells.get(j) {
            let v: Vec<String> = c.numbers().iter().map(|&x| number(x)).collect();
            let _ = writeln!(out, "cell,{}", v.join(","));
        }
    }
    out
}

/// The text of the end curves (see [`super::format`]).
pub fn ends_to_text(e: &EndsData) -> String {
    let mut out = String::new();
    header(&mut out, &e.header);
    let _ = writeln!(
        out,
        "grid,{},{},{},{},{},{}",
        number(e.y0),
        number(e.dy),
        e.ny,
        number(e.k0),
        e.per_octave,
        e.nk
    );
    for j in 0..e.nk {
        let _ = writeln!(
            out,
            "k,{}",
            number(e.k0 * 2f64.powf(j as f64 / e.per_octave as f64))
        );
        for i in 0..e.ny {
            let at = j * e.ny + i;
            let _ = writeln!(
                out,
                "{},{},{}",
                number(e.x_s[at]),
                number(e.x_on[at]),
                u8::from(e.is_valid(at))
            );
        }
    }
    let (y0, dy, ny) = e.kcheck_y;
    let _ = writeln!(out, "kgrid,{},{},{}", number(y0), number(dy), ny);
    for c in &e.kcheck {
        let v: Vec<String> = c.numbers().iter().map(|&x| number(x)).collect();
        let _ = writeln!(out, "kcheck,{}", v.join(","));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::master::format::{increasing_up_to, parse_ends, parse_table, F_TOP};

    /// A ratio that falls from one node to the next by more than the nodes' noise ends the
    /// increase; the level is the least ratio from there on (the row is at least the smaller of
    /// an earlier value and it), and a NaN (no value) interrupts nothing.
    #[test]
    fn the_level_where_ratios_stop_increasing() {
        assert_eq!(increasing_up_to(&[1.0, 2.0, 3.0]), f64::INFINITY);
        assert_eq!(increasing_up_to(&[1.0, 1.0 - 1e-9, 3.0]), f64::INFINITY);
        assert_eq!(increasing_up_to(&[1.0, 5.0, 4.0, 4.5, 3.0, 9.0]), 3.0);
        assert_eq!(increasing_up_to(&[1.0, f64::NAN, 2.0]), f64::INFINITY);
        assert_eq!(increasing_up_to(&[]), f64::INFINITY);
    }

    /// A row that is not monotone keeps the level it was checked beyond its ends to (the sixth
    /// number); a monotone row needs none (F_TOP), an unchecked one reads as 0.
    #[test]
    fn the_checked_level_beyond_the_ends_round_trips() {
        let row = |y: &str, tail: &str| {
            format!("row,{y},0.4,0.41,{tail}\nbody,1,1\nnode,-17,1.00015,1.00015\n")
        };
        let cell = "cell,-1,-1,inf,inf,inf\n";
        let text = format!(
            "k,0.01\n{}{cell}{}{cell}{}",
            row("-4.5", "0,9989.5"),
            row("-4", "1"),
            row("-3.5", "0")
        );
        let t = parse_table(&text).unwrap();
        let levels: Vec<f64> = t.rows.iter().map(|r| r.none_beyond).collect();
        assert_eq!(levels, [9989.5, F_TOP, 0.0]);
        assert_eq!(parse_table(&table_to_text(&t)).unwrap(), t);
    }

    /// A k check's lower-bound limits likewise: read where given, written back the same, and
    /// refused above the vouched ones.
    #[test]
    fn k_check_lower_bounds_round_trip() {
        let grid: String = (0..4)
            .map(|j| format!("k,{}\n{}", 0.01 * 2f64.powi(j), "0,0,1\n".repeat(4)))
            .collect();
        let ends = |kcheck: &str| format!("grid,0,1,4,0.01,1,4\n{grid}kgrid,0,1,1\n{kcheck}");
        let good = "kcheck,-1,-1,1e-4,1e-4,inf,1e-5,2e-5,inf\nkcheck,-1,-1,1e-4,1e-4,1e-4\n";
        let e = parse_ends(&ends(good)).unwrap();
        assert_eq!(e.kcheck[0].d_lb, Some([1e-5, 2e-5, f64::INFINITY]));
        assert_eq!(e.kcheck[1].d_lb, None);
        assert_eq!(parse_ends(&ends_to_text(&e)).unwrap(), e);
        assert!(parse_ends(&ends("kcheck,-1,-1,1e-4,1e-4,1e-4,1e-3,1e-5,1e-5\n")).is_err());
    }

    /// The lower-bound limits (`d_lb`) are optional trailing numbers of the body, strip and cell
    /// records: read where given, written back the same, absent (the vouched limits serve)
    /// where not, so that tables without them keep their text.
    #[test]
    fn lower_bound_limits_round_trip() {
        let text = "k,0.01\nrow,0,0.4,0.41,1\nbody,1e-4,2e-4,1e-5,1.5e-5\nnode,0.3,5,4\n\
                    strip,3e-4,2e-5\nsnode,0.405,900\ncell,0.3,0.3,1e-4,2e-4,3e-4,1e-5,2e-5,3e-5\n\
                    row,0.5,0.5,0.51,1\nbody,1e-4,2e-4\nnode,0.4,5,4\n";
        let t = parse_table(text).unwrap();
        let (a, b) = (&t.rows[0], &t.rows[1]);
        assert_eq!(a.body.d_lb, Some([1e-5, 1.5e-5]));
        assert_eq!(a.strip.d_lb, Some([f64::INFINITY, 2e-5]));
        assert_eq!(t.cells[0].d_lb, Some([1e-5, 2e-5, 3e-5]));
        assert_eq!((b.body.d_lb, b.body.bound_limit(1)), (None, 2e-4));
        assert_eq!(t.cells[0].bound_limit(2), 3e-5);
        // compared as text: a strip's F is NaN, which equals nothing
        let again = table_to_text(&t);
        assert_eq!(table_to_text(&parse_table(&again).unwrap()), again);
        assert!(again.contains("\nbody,0.0001,0.0002\n"), "{again}");
        // a lower-bound limit above its vouched one, or not a distance, is refused
        for bad in [
            "body,1e-4,2e-4,1e-5,3e-4",
            "body,1e-4,2e-4,nan,1e-5",
            "strip,3e-4,0",
        ] {
            let text = format!("k,0.01\nrow,0,0.4,0.41,1\n{bad}\n");
            assert!(parse_table(&text).is_err(), "{bad}");
        }
    }
}
