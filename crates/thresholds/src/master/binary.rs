//! The master tables as the library interpolates them ([`Table`]: node coordinates already
//! turned into `u = ln(end - x)` and the ratios into `g = ln(ratio - 1)`) and their binary form:
//! every table and the end curves as little-endian `f64` arrays ([`crate::bytes`]), which the
//! library borrows in place from the embedded form ([`Floats`]). Made by the build script
//! (`crates/thresholds/build.rs`, which includes this file, [`super::format`] and
//! [`crate::bytes`]) from the committed text, read by the library on first use; `std` and
//! `bytemuck` only.

use super::format::{CellData, EndsData, PieceData, TableData, CELL_LIMITS, VOUCHED_LIMITS};
use crate::bytes::{self, Reader, Writer};
use std::borrow::Cow;

/// An array of numbers: borrowed from the embedded binary form (no copy: a process's first
/// answer reads only the pages it touches), or owned (made from the text form).
pub type Floats = Cow<'static, [f64]>;

/// A piece ready to interpolate: `u = ln(end - x)` increasing and `g = ln(ratio - 1)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Piece {
    /// ln(end - x) of the nodes, increasing (the nodes in decreasing x).
    pub u: Floats,
    /// `[ln(F - 1), ln(F_on - 1)]` at the nodes (the first NaN in a strip).
    pub g: [Floats; 2],
    /// `[F, F_on]`: vouched for u >= this (ln of the piece's `d_lo`).
    pub u_lo: [f64; 2],
    /// `[F, F_on]`: vouched for x <= this (`end - d_lo`; kept to spare an `exp` per answer).
    pub x_hi: [f64; 2],
    /// `[F, F_on]`: a lower bound for u >= this (ln of the piece's `d_lb`, else `u_lo`).
    pub u_lb: [f64; 2],
}

impl Piece {
    fn from_data(p: &PieceData, end: f64) -> Piece {
        let n = p.x.len();
        let rev = |v: &[f64], f: &dyn Fn(f64) -> f64| -> Floats {
            (0..n).map(|i| f(v[n - 1 - i])).collect::<Vec<_>>().into()
        };
        Piece {
            u: rev(&p.x, &|x| (end - x).ln()),
            g: [
                rev(&p.f_stick, &|r| (r - 1.0).ln()),
                rev(&p.f_onset, &|r| (r - 1.0).ln()),
            ],
            u_lo: [p.d_lo[0].ln(), p.d_lo[1].ln()],
            x_hi: [end - p.d_lo[0], end - p.d_lo[1]],
            u_lb: [p.bound_limit(0).ln(), p.bound_limit(1).ln()],
        }
    }

    /// Whether the piece has nodes.
    pub fn is_empty(&self) -> bool {
        self.u.is_empty()
    }
}

/// A row ready to interpolate.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// log10 (c_D c_a).
    pub y: f64,
    /// Where F = F_TOP.
    pub x_s: f64,
    /// Where F_on = F_TOP.
    pub x_on: f64,
    /// Both ratios increase with x over the nodes, and nothing bounces beyond the ends up to
    /// [`super::F_TOP`] ([`super::format::RowData::monotone`]).
    pub monotone: bool,
    /// The ratios increase towards the ends up to this ratio: at every node each of them is at
    /// least the smaller of its value at any node farther from the end and this (infinite when
    /// they increase throughout; [`super::format::RowData::increasing_up_to`]).
    pub mono: f64,
    /// Nothing bounces (double-collides) beyond the ends below this ratio: [`super::F_TOP`] for
    /// a monotone row, else what the build checked ([`super::format::RowData::none_beyond`]; 0: unchecked).
    pub beyond: f64,
    /// In u = ln(x_s - x).
    pub body: Piece,
    /// In w = ln(x_on - x) (F_on only).
    pub strip: Piece,
}

/// A table ready to interpolate.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// k.
    pub k: f64,
    /// The rows' y.
    pub ys: Vec<f64>,
    /// The rows.
    pub rows: Vec<Row>,
    /// Per cell ([`CellData::limits`]): `[x_hi F, x_hi F_on]` (plain x, vouched for x <= this)
    /// and `[body F, body F_on, strip F_on]` (at a fixed distance, vouched for u >= this), then
    /// the same three as lower bounds only.
    pub cells: Vec<[f64; CELL_LIMITS]>,
    /// The cell of each bin of y, 1/[`Y_BINS`] wide from the first row ([`y_bins`]): the cell of
    /// a y without a search.
    pub y_bins: Vec<u32>,
}

/// Bins of y per unit: the rows lie on this grid (0.5 halved down to 1/64 by the build).
pub const Y_BINS: f64 = 64.0;

/// The cell (`i`: between rows i and i + 1) of each bin of y of [`Y_BINS`] from `ys[0]`; empty
/// unless every row lies on that grid.
pub fn y_bins(ys: &[f64]) -> Vec<u32> {
    let Some((&y0, &y1)) = ys.first().zip(ys.last()) else {
        return Vec::new();
    };
    let on_grid = ys.iter().all(|y| {
        let p = (y - y0) * Y_BINS;
        (p - p.round()).abs() < 1e-9
    });
    if ys.len() < 2 || !on_grid {
        return Vec::new();
    }
    let bins = ((y1 - y0) * Y_BINS).round() as usize;
    (0..bins)
        .map(|m| {
            let mid = y0 + (m as f64 + 0.5) / Y_BINS;
            (ys.partition_point(|&v| v <= mid) - 1) as u32
        })
        .collect()
}

impl Table {
    /// The interpolation form of `t`.
    pub fn from_data(t: &TableData) -> Table {
        Table {
            k: t.k,
            ys: t.rows.iter().map(|r| r.y).collect(),
            rows: t
                .rows
                .iter()
                .map(|r| Row {
                    y: r.y,
                    x_s: r.x_s,
                    x_on: r.x_on,
                    monotone: r.monotone,
                    mono: if r.monotone {
                        f64::INFINITY
                    } else {
                        r.increasing_up_to()
                    },
                    // F_TOP for a monotone row already (`RowData::none_beyond`)
                    beyond: r.none_beyond,
                    body: Piece::from_data(&r.body, r.x_s),
                    strip: Piece::from_data(&r.strip, r.x_on),
                })
                .collect(),
            cells: t.cells.iter().map(CellData::limits).collect(),
            y_bins: y_bins(&t.rows.iter().map(|r| r.y).collect::<Vec<_>>()),
        }
    }
}

/// The binary form's first bytes.
const MAGIC: &[u8; 8] = b"STKMT007";

impl Piece {
    fn write(&self, w: &mut Writer) {
        w.fs(&self.u);
        w.fs(&self.g[0]);
        w.fs(&self.g[1]);
        w.f(self.u_lo[0]);
        w.f(self.u_lo[1]);
        w.f(self.x_hi[0]);
        w.f(self.x_hi[1]);
        w.f(self.u_lb[0]);
        w.f(self.u_lb[1]);
    }

    fn read(r: &mut Reader<'static>) -> Option<Piece> {
        Some(Piece {
            u: r.fs_borrowed()?,
            g: [r.fs_borrowed()?, r.fs_borrowed()?],
            u_lo: [r.f()?, r.f()?],
            x_hi: [r.f()?, r.f()?],
            u_lb: [r.f()?, r.f()?],
        })
    }
}

/// The binary form of the tables and the end curves ([`crate::bytes`]): the end curves are
/// what the tables share.
pub fn to_bytes(tables: &[TableData], ends: &EndsData) -> Vec<u8> {
    let encoded: Vec<(f64, Vec<u8>)> = tables
        .iter()
        .map(|t| (t.k, table_bytes(&Table::from_data(t))))
        .collect();
    let mut e = Writer::default();
    e.f(ends.y0);
    e.f(ends.dy);
    e.n(ends.ny);
    e.f(ends.k0);
    e.n(ends.per_octave);
    e.n(ends.nk);
    e.fs(&ends.x_s);
    e.fs(&ends.x_on);
    e.fs(&ends.valid);
    e.f(ends.kcheck_y.0);
    e.f(ends.kcheck_y.1);
    e.n(ends.kcheck_y.2);
    // each k check's limits with its lower-bound ones (those of the vouched limits where it has
    // none)
    let flat: Vec<f64> = ends
        .kcheck
        .iter()
        .flat_map(|c| {
            let lb = [0, 1, 2].map(|i| c.bound_limit(i));
            c.vouched().into_iter().chain(lb)
        })
        .collect();
    e.fs(&flat);
    bytes::to_bytes(MAGIC, &e.0, &encoded)
}

fn table_bytes(t: &Table) -> Vec<u8> {
    let mut w = Writer::default();
    w.f(t.k);
    w.list(&t.rows, |w, r| {
        for v in [r.y, r.x_s, r.x_on] {
            w.f(v);
        }
        w.flag(r.monotone);
        for v in [r.mono, r.beyond] {
            w.f(v);
        }
        r.body.write(w);
        r.strip.write(w);
    });
    for c in &t.cells {
        for v in c {
            w.f(*v);
        }
    }
    w.0
}

/// The index of the binary form: `(k, offset, length)` of each table.
pub fn index(bytes: &[u8]) -> Option<Vec<(f64, usize, usize)>> {
    bytes::index(bytes, MAGIC)
}

/// The end curves from the binary form.
pub fn ends_from_bytes(bytes: &'static [u8]) -> Option<EndsData> {
    let mut r = bytes::shared(bytes, MAGIC)?;
    let mut e = EndsData::empty();
    (e.y0, e.dy, e.ny, e.k0, e.per_octave, e.nk) = (r.f()?, r.f()?, r.n()?, r.f()?, r.n()?, r.n()?);
    e.x_s = r.fs_borrowed()?;
    e.x_on = r.fs_borrowed()?;
    e.valid = r.fs_borrowed()?;
    e.kcheck_y = (r.f()?, r.f()?, r.n()?);
    e.kcheck = r
        .fs()?
        .chunks_exact(CELL_LIMITS)
        .map(|v| {
            // none given (every one the vouched limit's, to the bit) reads as none, as in the text
            let bits = |w: &[f64]| w.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            let given = bits(&v[VOUCHED_LIMITS..]) != bits(&v[2..VOUCHED_LIMITS]);
            CellData::from_numbers(if given { v } else { &v[..VOUCHED_LIMITS] })
        })
        .collect();
    Some(e)
}

/// Table `i` of the binary form.
pub fn table_from_bytes(bytes: &'static [u8], i: usize) -> Option<Table> {
    let mut r = bytes::table(bytes, MAGIC, i)?;
    let k = r.f()?;
    let rows = r.list(|r| {
        let (y, x_s, x_on, monotone) = (r.f()?, r.f()?, r.f()?, r.flag()?);
        let (mono, beyond) = (r.f()?, r.f()?);
        let (body, strip) = (Piece::read(r)?, Piece::read(r)?);
        Some(Row {
            y,
            x_s,
            x_on,
            monotone,
            mono,
            beyond,
            body,
            strip,
        })
    })?;
    let cells = (0..rows.len().saturating_sub(1))
        .map(|_| {
            let mut c = [0.0; CELL_LIMITS];
            for v in &mut c {
                *v = r.f()?;
            }
            Some(c)
        })
        .collect::<Option<Vec<_>>>()?;
    let ys: Vec<f64> = rows.iter().map(|r| r.y).collect();
    Some(Table {
        k,
        y_bins: y_bins(&ys),
        ys,
        rows,
        cells,
    })
}
