//! The master tables as data: their text form (the committed CSV files) and their binary form
//! (what the library embeds), with nothing but `std`, so that the build script
//! (`crates/thresholds/build.rs`, which includes this file) and the library read them with the
//! same code.
//!
//! A table of one k, as text (`#` lines first, one record a line):
//! ```text
//! k,<k>
//! row,<y>,<x_s>,<x_on>,<monotone 0|1>                       a row of constant y = log10(c_D c_a)
//! body,<d_lo F>,<d_lo F_on>                                 the row's body (d = x_s - x)
//! node,<x>,<F>,<F_on>                                        x = log10 c_D, F = V_stick/V_stick,JKR
//! strip,<d_lo F_on>                                         the row's strip (d = x_on - x)
//! snode,<x>,<F_on>
//! cell,<x_hi F>,<x_hi F_on>,<d_lo F>,<d_lo F_on>,<d_lo strip F_on>   between this row and the next
//! ```
//! x_s is where F reaches [`F_TOP`], x_on where F_on does. A piece is vouched for where its
//! distance to its end is at least its `d_lo` (`inf`: nowhere). A cell is vouched for in plain
//! x (rows interpolated at the same x) up to `x_hi`, and at a fixed distance to the end (the
//! end interpolated in y) down to `d_lo`.
//!
//! The end curves x_s(y, k) and x_on(y, k) on a uniform grid in y and ln k:
//! ```text
//! grid,<y0>,<dy>,<ny>,<k0>,<steps per octave of k>,<nk>
//! k,<k>                                                      then ny lines:
//! <x_s>,<x_on>,<valid 0|1>
//! kgrid,<y0>,<dy>,<ny>                                       the y bins of the k checks
//! kcheck,<x_hi F>,<x_hi F_on>,<d_lo F>,<d_lo F_on>,<d_lo strip F_on>   per k interval, y bin
//! ```
//!
//! The binary form holds every table and the end curves as little-endian `f64` arrays, with the
//! node coordinates already turned into the interpolation coordinate `u = ln(end - x)` and the
//! ratios into `g = ln(ratio - 1)`, so that reading it is copying numbers.

/// The largest ratio the tables hold: each row ends where F = V_stick/V_stick,JKR (and where
/// F_on) reaches it. Beyond, nothing bounces (double-collides) below this many V_stick,JKR.
/// 1e4: ten times the default search limit (1000 V_stick,JKR), so that any `v_max` up to it is
/// answered; above it a search can meet the hyper-speed bouncing of large soft grains (from about
/// 5e5 V_stick,JKR at y = -4).
pub const F_TOP: f64 = 1e4;

/// One piece of a row: nodes in x with their ratios, vouched for down to a distance to the
/// piece's end.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PieceData {
    /// log10 c_D of the nodes, increasing.
    pub x: Vec<f64>,
    /// F = V_stick / V_stick,JKR at the nodes (NaN in a strip, which has none).
    pub f_stick: Vec<f64>,
    /// F_on = V_double_onset / V_stick,JKR at the nodes.
    pub f_onset: Vec<f64>,
    /// `[F, F_on]`: the interpolation is vouched for where the distance to the piece's end is at
    /// least this (infinite: nowhere).
    pub d_lo: [f64; 2],
}

/// One row of constant y.
#[derive(Debug, Clone, PartialEq)]
pub struct RowData {
    /// log10 (c_D c_a).
    pub y: f64,
    /// log10 c_D where F = [`F_TOP`]: the end of the body.
    pub x_s: f64,
    /// log10 c_D where F_on = [`F_TOP`]: the end of the strip (at least `x_s`).
    pub x_on: f64,
    /// Both ratios increase with x over the row's nodes, so a point closer to the end than the
    /// vouched nodes has a ratio at least that of the last vouched one.
    pub monotone: bool,
    /// Nodes with x < x_s, both ratios, interpolated in u = ln(x_s - x).
    pub body: PieceData,
    /// Nodes between x_s and x_on (the strip where double collisions but no bouncing remain
    /// up to F_TOP), F_on only, interpolated in w = ln(x_on - x); empty where the strip is too
    /// narrow to tabulate.
    pub strip: PieceData,
}

/// The vouched limits of the cell between two rows, or of a k interval in a bin of y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellData {
    /// `[F, F_on]` interpolated at the same x on every row: vouched for up to this x
    /// (`-inf`: nowhere).
    pub x_hi: [f64; 2],
    /// `[body F, body F_on, strip F_on]` at a fixed distance to the end: vouched for where the
    /// distance is at least this (`inf`: nowhere).
    pub d_lo: [f64; 3],
}

impl CellData {
    /// Nothing vouched for.
    pub const NONE: CellData = CellData {
        x_hi: [f64::NEG_INFINITY; 2],
        d_lo: [f64::INFINITY; 3],
    };

    /// As five numbers: `x_hi` then `d_lo`.
    pub fn numbers(&self) -> [f64; 5] {
        [
            self.x_hi[0],
            self.x_hi[1],
            self.d_lo[0],
            self.d_lo[1],
            self.d_lo[2],
        ]
    }

    /// From five numbers ([`CellData::numbers`]).
    pub fn from_numbers(v: &[f64]) -> CellData {
        CellData {
            x_hi: [v[0], v[1]],
            d_lo: [v[2], v[3], v[4]],
        }
    }

    /// The interpolation form: `[x_hi F, x_hi F_on, u_lo F, u_lo F_on, u_lo strip]` (u = ln d).
    pub fn limits(&self) -> [f64; 5] {
        [
            self.x_hi[0],
            self.x_hi[1],
            self.d_lo[0].ln(),
            self.d_lo[1].ln(),
            self.d_lo[2].ln(),
        ]
    }
}

/// The table of one k.
#[derive(Debug, Clone, PartialEq)]
pub struct TableData {
    /// The modulus ratio k.
    pub k: f64,
    /// The `#` lines: the command, the commit, the settings.
    pub header: Vec<String>,
    /// Rows in increasing y.
    pub rows: Vec<RowData>,
    /// `rows.len() - 1` cells.
    pub cells: Vec<CellData>,
}

/// The end curves on their grid.
#[derive(Debug, Clone, PartialEq)]
pub struct EndsData {
    /// The `#` lines.
    pub header: Vec<String>,
    /// The first y and the y step.
    pub y0: f64,
    /// The y step.
    pub dy: f64,
    /// The number of y values.
    pub ny: usize,
    /// The first k.
    pub k0: f64,
    /// k steps per octave (k_j = k0 2^(j / per_octave)).
    pub per_octave: usize,
    /// The number of k values.
    pub nk: usize,
    /// x_s at (k_j, y_i), index `j * ny + i` (NaN where it could not be computed).
    pub x_s: Vec<f64>,
    /// x_on likewise.
    pub x_on: Vec<f64>,
    /// Whether a cubic through the point and its neighbours is trusted there (false next to
    /// a kink of the curves, where the regime of the cliff changes).
    pub valid: Vec<bool>,
    /// The y bins of the checks between tables of neighbouring k: first y, step, count.
    pub kcheck_y: (f64, f64, usize),
    /// For the k interval between tables i and i + 1 and y bin b (index `i * count + b`): where
    /// the cubic in ln k is vouched for.
    pub kcheck: Vec<CellData>,
}

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
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        if let Some(h) = line.strip_prefix('#') {
            t.header.push(h.trim_start().to_string());
            continue;
        }
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
                let v = numbers(n, &rest, 4)?;
                t.rows.push(RowData {
                    y: v[0],
                    x_s: v[1],
                    x_on: v[2],
                    monotone: v[3] == 1.0,
                    body: PieceData::default(),
                    strip: PieceData::default(),
                });
                in_strip = false;
            }
            "body" => {
                let j = row(&mut t)?;
                let v = numbers(n, &rest, 2)?;
                t.rows[j].body.d_lo = [v[0], v[1]];
                in_strip = false;
            }
            "strip" => {
                let j = row(&mut t)?;
                let v = numbers(n, &rest, 1)?;
                t.rows[j].strip.d_lo = [f64::INFINITY, v[0]];
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
            "cell" => {
                let v = numbers(n, &rest, 5)?;
                t.cells.push(CellData::from_numbers(&v));
            }
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
    let mut e = EndsData {
        header: Vec::new(),
        y0: f64::NAN,
        dy: f64::NAN,
        ny: 0,
        k0: f64::NAN,
        per_octave: 0,
        nk: 0,
        x_s: Vec::new(),
        x_on: Vec::new(),
        valid: Vec::new(),
        kcheck_y: (f64::NAN, f64::NAN, 0),
        kcheck: Vec::new(),
    };
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        if let Some(h) = line.strip_prefix('#') {
            e.header.push(h.trim_start().to_string());
            continue;
        }
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
            "kcheck" => {
                let v = numbers(n, &fields[1..], 5)?;
                e.kcheck.push(CellData::from_numbers(&v));
            }
            _ => {
                let v = numbers(n, &fields, 3)?;
                e.x_s.push(v[0]);
                e.x_on.push(v[1]);
                e.valid.push(v[2] == 1.0);
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

/// A piece ready to interpolate: `u = ln(end - x)` increasing and `g = ln(ratio - 1)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Piece {
    /// ln(end - x) of the nodes, increasing (the nodes in decreasing x).
    pub u: Vec<f64>,
    /// `[ln(F - 1), ln(F_on - 1)]` at the nodes (the first NaN in a strip).
    pub g: [Vec<f64>; 2],
    /// `[F, F_on]`: vouched for u >= this (ln of the piece's `d_lo`).
    pub u_lo: [f64; 2],
    /// `[F, F_on]`: vouched for x <= this (`end - d_lo`; kept to spare an `exp` per answer).
    pub x_hi: [f64; 2],
}

impl Piece {
    fn from_data(p: &PieceData, end: f64) -> Piece {
        let n = p.x.len();
        let rev = |v: &[f64], f: &dyn Fn(f64) -> f64| (0..n).map(|i| f(v[n - 1 - i])).collect();
        Piece {
            u: rev(&p.x, &|x| (end - x).ln()),
            g: [
                rev(&p.f_stick, &|r| (r - 1.0).ln()),
                rev(&p.f_onset, &|r| (r - 1.0).ln()),
            ],
            u_lo: [p.d_lo[0].ln(), p.d_lo[1].ln()],
            x_hi: [end - p.d_lo[0], end - p.d_lo[1]],
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
    /// Both ratios increase with x over the nodes.
    pub monotone: bool,
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
    /// and `[body F, body F_on, strip F_on]` (at a fixed distance, vouched for u >= this).
    pub cells: Vec<[f64; 5]>,
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
const MAGIC: &[u8; 8] = b"STKMT004";

/// Appends numbers to the binary form.
#[derive(Default)]
struct Writer(Vec<u8>);

impl Writer {
    fn f(&mut self, v: f64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    fn n(&mut self, v: usize) {
        self.f(v as f64);
    }
    fn fs(&mut self, v: &[f64]) {
        self.n(v.len());
        for &x in v {
            self.f(x);
        }
    }
    fn piece(&mut self, p: &Piece) {
        self.fs(&p.u);
        self.fs(&p.g[0]);
        self.fs(&p.g[1]);
        self.f(p.u_lo[0]);
        self.f(p.u_lo[1]);
        self.f(p.x_hi[0]);
        self.f(p.x_hi[1]);
    }
}

/// Reads numbers from the binary form.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn f(&mut self) -> Option<f64> {
        let b = self.bytes.get(self.at..self.at + 8)?;
        self.at += 8;
        Some(f64::from_le_bytes(b.try_into().ok()?))
    }
    fn n(&mut self) -> Option<usize> {
        let v = self.f()?;
        (v >= 0.0 && v.fract() == 0.0 && v < 1e9).then_some(v as usize)
    }
    fn fs(&mut self) -> Option<Vec<f64>> {
        let n = self.n()?;
        let bytes = self.bytes.get(self.at..self.at + 8 * n)?;
        self.at += 8 * n;
        // in bulk: a process's first answer reads about 2 MB of these
        Some(
            bytes
                .chunks_exact(8)
                .map(|b| <[u8; 8]>::try_from(b).map_or(f64::NAN, f64::from_le_bytes))
                .collect(),
        )
    }
    fn piece(&mut self) -> Option<Piece> {
        Some(Piece {
            u: self.fs()?,
            g: [self.fs()?, self.fs()?],
            u_lo: [self.f()?, self.f()?],
            x_hi: [self.f()?, self.f()?],
        })
    }
}

/// The binary form of the tables and the end curves: the magic, the table count, each table's
/// k, byte offset and length, then the end curves, then the tables.
pub fn to_bytes(tables: &[TableData], ends: &EndsData) -> Vec<u8> {
    let encoded: Vec<Vec<u8>> = tables
        .iter()
        .map(|t| table_bytes(&Table::from_data(t)))
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
    let valid: Vec<f64> = ends.valid.iter().map(|&v| f64::from(u8::from(v))).collect();
    e.fs(&valid);
    e.f(ends.kcheck_y.0);
    e.f(ends.kcheck_y.1);
    e.n(ends.kcheck_y.2);
    let flat: Vec<f64> = ends.kcheck.iter().flat_map(CellData::numbers).collect();
    e.fs(&flat);
    let mut w = Writer::default();
    w.0.extend_from_slice(MAGIC);
    w.n(tables.len());
    let head = 8 + 8 + 24 * tables.len();
    let mut offset = head + e.0.len();
    for (t, b) in tables.iter().zip(&encoded) {
        w.f(t.k);
        w.n(offset);
        w.n(b.len());
        offset += b.len();
    }
    w.0.extend_from_slice(&e.0);
    for b in encoded {
        w.0.extend_from_slice(&b);
    }
    w.0
}

fn table_bytes(t: &Table) -> Vec<u8> {
    let mut w = Writer::default();
    w.f(t.k);
    w.n(t.rows.len());
    for r in &t.rows {
        w.f(r.y);
        w.f(r.x_s);
        w.f(r.x_on);
        w.f(f64::from(u8::from(r.monotone)));
        w.piece(&r.body);
        w.piece(&r.strip);
    }
    for c in &t.cells {
        for v in c {
            w.f(*v);
        }
    }
    w.0
}

/// The index of the binary form: `(k, offset, length)` of each table, and where the end curves
/// lie.
pub fn index(bytes: &[u8]) -> Option<Vec<(f64, usize, usize)>> {
    if bytes.get(..8)? != MAGIC {
        return None;
    }
    let mut r = Reader { bytes, at: 8 };
    let n = r.n()?;
    (0..n).map(|_| Some((r.f()?, r.n()?, r.n()?))).collect()
}

/// The end curves from the binary form.
pub fn ends_from_bytes(bytes: &[u8]) -> Option<EndsData> {
    let n = index(bytes)?.len();
    let mut r = Reader {
        bytes,
        at: 16 + 24 * n,
    };
    let (y0, dy, ny, k0, per_octave, nk) = (r.f()?, r.f()?, r.n()?, r.f()?, r.n()?, r.n()?);
    let x_s = r.fs()?;
    let x_on = r.fs()?;
    let valid = r.fs()?.into_iter().map(|v| v == 1.0).collect();
    let kcheck_y = (r.f()?, r.f()?, r.n()?);
    let flat = r.fs()?;
    let kcheck = flat.chunks_exact(5).map(CellData::from_numbers).collect();
    Some(EndsData {
        header: Vec::new(),
        y0,
        dy,
        ny,
        k0,
        per_octave,
        nk,
        x_s,
        x_on,
        valid,
        kcheck_y,
        kcheck,
    })
}

/// Table `i` of the binary form.
pub fn table_from_bytes(bytes: &[u8], i: usize) -> Option<Table> {
    let (_, offset, len) = *index(bytes)?.get(i)?;
    let mut r = Reader {
        bytes: bytes.get(offset..offset + len)?,
        at: 0,
    };
    let k = r.f()?;
    let n = r.n()?;
    let mut rows = Vec::with_capacity(n);
    for _ in 0..n {
        rows.push(Row {
            y: r.f()?,
            x_s: r.f()?,
            x_on: r.f()?,
            monotone: r.f()? == 1.0,
            body: r.piece()?,
            strip: r.piece()?,
        });
    }
    let cells = (0..n.saturating_sub(1))
        .map(|_| Some([r.f()?, r.f()?, r.f()?, r.f()?, r.f()?]))
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
