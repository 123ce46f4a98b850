//! The reader of the master tables' text form ([`super::format`] gives the layout), with
//! nothing but `std`: the build script (`crates/thresholds/build.rs`) includes this file too.

use super::format::{
    CellData, EndsData, PieceData, RowData, TableData, CELL_LIMITS, F_TOP, VOUCHED_LIMITS,
};

/// A file that cannot be read: its line (1-based; 0 for the whole file) and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FormatError {
    /// 1-based line number (0: the file as a whole).
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

fn bad(line: usize, problem: impl Into<String>) -> FormatError {
    FormatError {
        line,
        problem: problem.into(),
    }
}

/// The fields of a record line after its name, as numbers (`inf`, `nan` accepted).
fn numbers(line: usize, fields: &[&str], n: usize) -> Result<Vec<f64>, FormatError> {
    if fields.len() != n {
        return Err(bad(
            line,
            format!("expected {n} numbers, found {}", fields.len()),
        ));
    }
    fields
        .iter()
        .map(|f| {
            f.trim()
                .parse::<f64>()
                .map_err(|_| bad(line, format!("'{f}' is not a number")))
        })
        .collect()
}

/// Lower-bound limits `lb` (none, or one for each of the vouched limits `lo`), each a
/// distance above 0 and at most its vouched one: a NaN or a larger one would loosen the
/// tables' answers unnoticed.
fn bounds_within(line: usize, lo: &[f64], lb: &[f64]) -> Result<(), FormatError> {
    if lb.iter().zip(lo).all(|(&b, &l)| b > 0.0 && b <= l) {
        Ok(())
    } else {
        Err(bad(
            line,
            "a lower-bound limit (d_lb) must be above 0 and at most its d_lo",
        ))
    }
}

/// A cell's (or a k check's) limits from the fields of its record: the vouched ones, then the
/// lower-bound ones where given.
fn cell_record(line: usize, fields: &[&str]) -> Result<CellData, FormatError> {
    let n = if fields.len() == CELL_LIMITS {
        CELL_LIMITS
    } else {
        VOUCHED_LIMITS
    };
    let v = numbers(line, fields, n)?;
    bounds_within(line, &v[2..VOUCHED_LIMITS], &v[VOUCHED_LIMITS..])?;
    Ok(CellData::from_numbers(&v))
}

/// Reads a table from its text.
pub fn parse_table(text: &str) -> Result<TableData, FormatError> {
    let mut t = TableData {
        k: f64::NAN,
        header: Vec::new(),
        rows: Vec::new(),
        cells: Vec::new(),
    };
    // which piece the nodes go to: false = body, true = strip
    let mut in_strip = false;
    let (header, records) = crate::text::split(text);
    t.header = header;
    for (n, line) in records {
        if line.trim().is_empty() {
            continue;
        }
        let mut fields = line.split(',');
        let name = fields.next().unwrap_or("");
        let rest: Vec<&str> = fields.collect();
        let row = |t: &mut TableData| -> Result<usize, FormatError> {
            t.rows
                .len()
                .checked_sub(1)
                .ok_or_else(|| bad(n, "a record before any row"))
        };
        match name {
            "k" => t.k = numbers(n, &rest, 1)?[0],
            "row" => {
                // the sixth number (none_beyond) only where a row that is not monotone was checked
                let v = numbers(n, &rest, if rest.len() == 5 { 5 } else { 4 })?;
                let monotone = v[3] == 1.0;
                t.rows.push(RowData {
                    y: v[0],
                    x_s: v[1],
                    x_on: v[2],
                    monotone,
                    none_beyond: match v.get(4) {
                        _ if monotone => F_TOP,
                        Some(&f) => f,
                        None => 0.0,
                    },
                    body: PieceData::default(),
                    strip: PieceData::default(),
                });
                in_strip = false;
            }
            "body" => {
                let j = row(&mut t)?;
                let v = numbers(n, &rest, if rest.len() == 4 { 4 } else { 2 })?;
                bounds_within(n, &v[..2], &v[2..])?;
                t.rows[j].body.d_lo = [v[0], v[1]];
                t.rows[j].body.d_lb = (v.len() == 4).then(|| [v[2], v[3]]);
                in_strip = false;
            }
            "strip" => {
                let j = row(&mut t)?;
                let v = numbers(n, &rest, if rest.len() == 2 { 2 } else { 1 })?;
                bounds_within(n, &v[..1], &v[1..])?;
                t.rows[j].strip.d_lo = [f64::INFINITY, v[0]];
                t.rows[j].strip.d_lb = v.get(1).map(|&d| [f64::INFINITY, d]);
                in_strip = true;
            }
            "node" | "snode" => {
                let j = row(&mut t)?;
                let (x, s, o) = if name == "node" {
                    let v = numbers(n, &rest, 3)?;
                    (v[0], v[1], v[2])
                } else {
                    let v = numbers(n, &rest, 2)?;
                    (v[0], f64::NAN, v[1])
                };
                if (name == "snode") != in_strip {
                    return Err(bad(n, format!("a {name} record outside its piece")));
                }
                let p = if in_strip {
                    &mut t.rows[j].strip
                } else {
                    &mut t.rows[j].body
                };
                if p.x.last().is_some_and(|&last| last >= x) {
                    return Err(bad(n, "nodes must increase in x"));
                }
                let ratio_ok = |r: f64| r > 1.0 && r.is_finite();
                if !(ratio_ok(o) && (in_strip || ratio_ok(s))) {
                    return Err(bad(n, "a ratio must be > 1 and finite"));
                }
                p.x.push(x);
                p.f_stick.push(s);
                p.f_onset.push(o);
            }
            "cell" => t.cells.push(cell_record(n, &rest)?),
            other => return Err(bad(n, format!("unknown record '{other}'"))),
        }
    }
    let ordered = t.rows.windows(2).all(|w| w[0].y < w[1].y);
    let sized = t.cells.len() + 1 == t.rows.len();
    let ends = t
        .rows
        .iter()
        .all(|r| r.x_s <= r.x_on && r.body.x.last().is_none_or(|&x| x < r.x_s));
    if !(t.k > 0.0 && t.k < 1.0 && ordered && sized && ends) {
        return Err(bad(
            0,
            "a table needs k in (0, 1), rows increasing in y, body nodes below x_s <= x_on, and a cell between each two rows",
        ));
    }
    Ok(t)
}

/// Reads the end curves from their text.
pub fn parse_ends(text: &str) -> Result<EndsData, FormatError> {
    let mut e = EndsData::empty();
    let (header, records) = crate::text::split(text);
    e.header = header;
    for (n, line) in records {
        let fields: Vec<&str> = line.split(',').collect();
        match fields[0] {
            "" => {}
            "grid" => {
                let v = numbers(n, &fields[1..], 6)?;
                (e.y0, e.dy, e.ny, e.k0, e.per_octave, e.nk) = (
                    v[0],
                    v[1],
                    v[2] as usize,
                    v[3],
                    v[4] as usize,
                    v[5] as usize,
                );
            }
            "k" => {
                let k = numbers(n, &fields[1..], 1)?[0];
                let expected = e.k0 * 2f64.powf(e.x_s.len() as f64 / (e.ny * e.per_octave) as f64);
                if e.ny == 0
                    || !e.x_s.len().is_multiple_of(e.ny)
                    || (k / expected - 1.0).abs() > 1e-9
                {
                    return Err(bad(n, format!("k = {k} is not the next k of the grid")));
                }
            }
            "kgrid" => {
                let v = numbers(n, &fields[1..], 3)?;
                e.kcheck_y = (v[0], v[1], v[2] as usize);
            }
            "kcheck" => e.kcheck.push(cell_record(n, &fields[1..])?),
            _ => {
                let v = numbers(n, &fields, 3)?;
                e.x_s.to_mut().push(v[0]);
                e.x_on.to_mut().push(v[1]);
                e.valid.to_mut().push(if v[2] == 1.0 { 1.0 } else { 0.0 });
            }
        }
    }
    if !(e.ny >= 4 && e.nk >= 4 && e.dy > 0.0 && e.k0 > 0.0 && e.per_octave > 0)
        || e.x_s.len() != e.ny * e.nk
        || (e.kcheck_y.2 > 0 && !e.kcheck.len().is_multiple_of(e.kcheck_y.2))
    {
        return Err(bad(
            0,
            "the end curves need a grid of at least 4 x 4 and every value of it",
        ));
    }
    Ok(e)
}
