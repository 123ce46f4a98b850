//! The restitution tables as data: text (the committed `data/restitution_k<k>.csv`) and binary
//! (what the library embeds, [`crate::bytes`]), with nothing but `std`, so that the build script
//! includes this file and reads them with the library's own code.
//!
//! One table a k, as text (`#` lines first):
//! ```text
//! k,<k>
//! sigma,<sigma_0>,...          the bouncing channels: V_in = V_stick e^sigma
//! nu,<nu_0>,...                the double-collision channels: V_in = V_stick (F_on/F)^nu
//! row,<y>,<x_s>                a row of constant y = log10(c_D c_a), its end x_s
//! rnode,<x>,<F>,<F_on>,<h...>  a node: x = log10 c_D, the ratios, h at every channel (nan: none)
//! cells,<0|1 ...>              per interval of this row's nodes: its cell to the next row vouched
//! bcells,<0|1 ...>             the same cells vouched for bouncing alone (absent: as cells)
//! kcells,<0|1 ...>             the same cells, for the cubic in ln k up to the next table
//! kbcells,<0|1 ...>            the k cells vouched for bouncing alone (absent: as kcells)
//! ```
//! h is `ln(|V_out| / V_stick)` at every channel: V_out < 0 (bouncing) above V_stick, > 0
//! (double collision) below it. |V_out| grows from 0 at V_stick, linearly in the distance to it
//! where the contact dissipates and as its square root in the JKR limit, saturates far above
//! it (e falls as 1/V_in near the cliff), and rises steeply, about as ln(1/(1 - nu)), towards
//! the onset of double collisions: in h against ln sigma + sigma and against logit nu =
//! ln(nu/(1 - nu)) each of these is a straight stretch, and the change between them smooth, so
//! the channels are spaced evenly in those coordinates ([`channel_coordinate`]) and the tables
//! interpolate in them ([`Table`] holds them so).

use crate::bytes::{self, Writer};
use std::borrow::Cow;

/// An array of numbers: borrowed from the embedded binary form (no copy: a table's first answer
/// reads only the pages it touches), or owned (made from the text form).
pub type Floats = Cow<'static, [f64]>;

/// The interpolation coordinate of channel `q`: ln sigma + sigma on the bouncing side (ln sigma
/// next to V_stick, sigma far above it, where h rises as sigma while e stays near 1 in the JKR
/// limit: channels evenly in ln sigma alone missed e by 6e-4 at sigma = 6.5), logit nu =
/// ln(nu / (1 - nu)) on the double-collision side.
pub fn channel_coordinate(bouncing: bool, q: f64) -> f64 {
    if bouncing {
        q.ln() + q
    } else {
        (q / (1.0 - q)).ln()
    }
}

/// The channel of coordinate `z`: the inverse of [`channel_coordinate`] (Newton's method on the
/// bouncing side, to rounding).
pub fn channel_at(bouncing: bool, z: f64) -> f64 {
    if !bouncing {
        return 1.0 / (1.0 + (-z).exp());
    }
    // ln q + q = z: start from q = e^z (small q) or z - ln z (large)
    let mut q = if z < 1.0 {
        z.exp().min(0.5)
    } else {
        z - z.ln()
    };
    for _ in 0..50 {
        let step = (q.ln() + q - z) / (1.0 / q + 1.0);
        q = (q - step).max(0.5 * q);
        if step.abs() <= 1e-15 * q {
            break;
        }
    }
    q
}

/// One node: its position, the threshold ratios there and `h` at every channel.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeData {
    /// log10 c_D.
    pub x: f64,
    /// F = V_stick / V_stick,JKR.
    pub f: f64,
    /// F_on = V_double_onset / V_stick,JKR.
    pub f_on: f64,
    /// h at the sigma channels, then at the nu channels (NaN where not computed).
    pub h: Vec<f64>,
}

/// One row of constant y.
#[derive(Debug, Clone, PartialEq)]
pub struct RowData {
    /// log10 (c_D c_a).
    pub y: f64,
    /// The end of the row (the master tables' x_s): the nodes' coordinate is ln(x_s - x).
    pub x_s: f64,
    /// Nodes in increasing x.
    pub nodes: Vec<NodeData>,
    /// Per interval of the nodes, which cells from this row to the next are vouched for.
    pub cells: CellFlags,
}

/// Which cells of a row (per interval of its nodes, from the row to the next) the checks
/// against the ODE vouched for; each is a record of the text form.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CellFlags {
    /// Every channel (`cells`).
    pub all: Vec<bool>,
    /// The bouncing channels alone (`bcells`; empty: as `all`): next to the onset of double
    /// collisions the double-collision channels miss where bouncing holds.
    pub bouncing: Vec<bool>,
    /// Every channel, for the cubic in ln k up to the next table (`kcells`; empty: not built).
    pub k_all: Vec<bool>,
    /// The bouncing channels alone, for the cubic in ln k (`kbcells`; empty: as `k_all`).
    pub k_bouncing: Vec<bool>,
}

impl CellFlags {
    /// The records' names, in the order of the text and binary forms.
    pub const RECORDS: [&'static str; 4] = ["cells", "bcells", "kcells", "kbcells"];

    /// No cell vouched for, among `cells` cells.
    pub fn none(cells: usize) -> Self {
        Self {
            all: vec![false; cells],
            ..Self::default()
        }
    }

    /// The records' names with their flags, in the order of the text and binary forms.
    pub fn records(&self) -> [(&'static str, &Vec<bool>); 4] {
        let [a, b, c, d] = Self::RECORDS;
        [
            (a, &self.all),
            (b, &self.bouncing),
            (c, &self.k_all),
            (d, &self.k_bouncing),
        ]
    }

    /// The flags of record `name`.
    fn record_mut(&mut self, name: &str) -> Option<&mut Vec<bool>> {
        let [a, b, c, d] = Self::RECORDS;
        [
            (a, &mut self.all),
            (b, &mut self.bouncing),
            (c, &mut self.k_all),
            (d, &mut self.k_bouncing),
        ]
        .into_iter()
        .find(|(n, _)| *n == name)
        .map(|(_, f)| f)
    }

    /// The cells of one side (bouncing, or a double collision, which needs every channel) and
    /// the k cells of it, the bouncing ones falling back on those of every channel.
    pub fn side(&self, bouncing: bool) -> (&[bool], &[bool]) {
        fn or<'a>(own: &'a [bool], all: &'a [bool]) -> &'a [bool] {
            if own.is_empty() {
                all
            } else {
                own
            }
        }
        if bouncing {
            (
                or(&self.bouncing, &self.all),
                or(&self.k_bouncing, &self.k_all),
            )
        } else {
            (&self.all, &self.k_all)
        }
    }

    /// Each side's flags resolved ([`Self::side`]) and in reverse order.
    fn reversed(&self) -> Self {
        let rev = |v: &[bool]| v.iter().rev().copied().collect::<Vec<bool>>();
        let ((bouncing, k_bouncing), (all, k_all)) = (self.side(true), self.side(false));
        Self {
            all: rev(all),
            bouncing: rev(bouncing),
            k_all: rev(k_all),
            k_bouncing: rev(k_bouncing),
        }
    }
}

/// The restitution table of one k.
#[derive(Debug, Clone, PartialEq)]
pub struct TableData {
    /// k.
    pub k: f64,
    /// The `#` lines.
    pub header: Vec<String>,
    /// The bouncing channels (sigma = ln(V_in / V_stick) > 0), increasing.
    pub sigma: Vec<f64>,
    /// The double-collision channels (nu = ln(V_stick/V_in) / ln(F/F_on), in (0, 1)),
    /// increasing.
    pub nu: Vec<f64>,
    /// Rows in increasing y.
    pub rows: Vec<RowData>,
}

/// A file that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FormatError {
    /// 1-based line (0: the file).
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

fn numbers(line: usize, fields: &[&str]) -> Result<Vec<f64>, FormatError> {
    fields
        .iter()
        .map(|f| {
            f.trim().parse::<f64>().map_err(|_| FormatError {
                line,
                problem: format!("'{f}' is not a number"),
            })
        })
        .collect()
}

fn bits(line: usize, field: Option<&&str>) -> Result<Vec<bool>, FormatError> {
    field
        .unwrap_or(&"")
        .chars()
        .map(|c| match c {
            '0' => Ok(false),
            '1' => Ok(true),
            _ => Err(FormatError {
                line,
                problem: "cells are 0 or 1".into(),
            }),
        })
        .collect()
}

/// Reads a table from its text.
pub fn parse(text: &str) -> Result<TableData, FormatError> {
    let mut t = TableData {
        k: f64::NAN,
        header: Vec::new(),
        sigma: Vec::new(),
        nu: Vec::new(),
        rows: Vec::new(),
    };
    let (header, records) = crate::text::split(text);
    t.header = header;
    for (n, line) in records {
        let fields: Vec<&str> = line.split(',').collect();
        let bad = |p: &str| FormatError {
            line: n,
            problem: p.into(),
        };
        match fields[0] {
            "" => {}
            "k" => {
                t.k = numbers(n, &fields[1..])?
                    .first()
                    .copied()
                    .unwrap_or(f64::NAN)
            }
            "sigma" => t.sigma = numbers(n, &fields[1..])?,
            "nu" => t.nu = numbers(n, &fields[1..])?,
            "row" => {
                let v = numbers(n, &fields[1..])?;
                if v.len() != 2 {
                    return Err(bad("a row has y and x_s"));
                }
                t.rows.push(RowData {
                    y: v[0],
                    x_s: v[1],
                    nodes: Vec::new(),
                    cells: CellFlags::default(),
                });
            }
            "rnode" => {
                let channels = t.sigma.len() + t.nu.len();
                let v = numbers(n, &fields[1..])?;
                let row = t
                    .rows
                    .last_mut()
                    .ok_or_else(|| bad("a node before any row"))?;
                if v.len() != 3 + channels {
                    return Err(bad("a node has x, F, F_on and a value at every channel"));
                }
                if row.nodes.last().is_some_and(|p| p.x >= v[0]) {
                    return Err(bad("nodes must increase in x"));
                }
                row.nodes.push(NodeData {
                    x: v[0],
                    f: v[1],
                    f_on: v[2],
                    h: v[3..].to_vec(),
                });
            }
            name if CellFlags::RECORDS.contains(&name) => {
                let b = bits(n, fields.get(1))?;
                let row = t
                    .rows
                    .last_mut()
                    .ok_or_else(|| bad("cells before any row"))?;
                if let Some(flags) = row.cells.record_mut(name) {
                    *flags = b;
                }
            }
            other => return Err(bad(&format!("unknown record '{other}'"))),
        }
    }
    let cells_fit = t.rows.iter().all(|r| {
        let m = r.nodes.len().saturating_sub(1);
        r.cells.all.len() == m
            && r.cells.records()[1..]
                .iter()
                .all(|(_, f)| f.is_empty() || f.len() == m)
    });
    if !(t.k > 0.0 && t.k < 1.0 && !t.sigma.is_empty() && t.nu.len() >= 2 && cells_fit) {
        return Err(FormatError {
            line: 0,
            problem: "a table needs k in (0, 1), channels, and a cell flag per interval of nodes"
                .into(),
        });
    }
    Ok(t)
}

/// A row ready to interpolate: the nodes in increasing u = ln(x_s - x).
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// y.
    pub y: f64,
    /// x_s.
    pub x_s: f64,
    /// ln(x_s - x) of the nodes, increasing (the nodes in decreasing x).
    pub u: Floats,
    /// h of node i at channel c: `h[i * channels + c]`.
    pub h: Floats,
    /// Cell flags in the same (decreasing x) order of intervals, each side's resolved (the
    /// bouncing ones filled from every channel's where the text had none).
    pub cells: CellFlags,
}

/// A table ready to interpolate.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// k.
    pub k: f64,
    /// The bouncing channels' coordinates, ln sigma + sigma (interpolation is in these).
    pub sigma: Vec<f64>,
    /// The double-collision channels' coordinates, logit nu = ln(nu / (1 - nu)).
    pub nu: Vec<f64>,
    /// The rows' y.
    pub ys: Vec<f64>,
    /// The rows.
    pub rows: Vec<Row>,
}

impl Table {
    /// The interpolation form of `t`.
    pub fn from_data(t: &TableData) -> Table {
        let rows = t
            .rows
            .iter()
            .map(|r| Row {
                y: r.y,
                x_s: r.x_s,
                u: r.nodes
                    .iter()
                    .rev()
                    .map(|p| (r.x_s - p.x).ln())
                    .collect::<Vec<_>>()
                    .into(),
                h: r.nodes
                    .iter()
                    .rev()
                    .flat_map(|p| p.h.iter().copied())
                    .collect::<Vec<_>>()
                    .into(),
                cells: r.cells.reversed(),
            })
            .collect::<Vec<_>>();
        Table {
            k: t.k,
            sigma: t
                .sigma
                .iter()
                .map(|&q| channel_coordinate(true, q))
                .collect(),
            nu: t.nu.iter().map(|&q| channel_coordinate(false, q)).collect(),
            ys: rows.iter().map(|r| r.y).collect(),
            rows,
        }
    }
}

/// The binary form's first bytes.
const MAGIC: &[u8; 8] = b"STKRT003";

/// The binary form of `tables` ([`crate::bytes`]; they share nothing).
pub fn to_bytes(tables: &[TableData]) -> Vec<u8> {
    let encoded: Vec<(f64, Vec<u8>)> = tables
        .iter()
        .map(|t| {
            let t = Table::from_data(t);
            let mut w = Writer::default();
            w.f(t.k);
            w.fs(&t.sigma);
            w.fs(&t.nu);
            w.list(&t.rows, |w, r| {
                w.f(r.y);
                w.f(r.x_s);
                w.fs(&r.u);
                w.fs(&r.h);
                for (_, flags) in r.cells.records() {
                    w.flags(flags);
                }
            });
            (t.k, w.0)
        })
        .collect();
    bytes::to_bytes(MAGIC, &[], &encoded)
}

/// `(k, offset, length)` of each table of the binary form.
pub fn index(bytes: &[u8]) -> Option<Vec<(f64, usize, usize)>> {
    bytes::index(bytes, MAGIC)
}

/// Table `i` of the binary form.
pub fn table_from_bytes(bytes: &'static [u8], i: usize) -> Option<Table> {
    let mut r = bytes::table(bytes, MAGIC, i)?;
    let (k, sigma, nu) = (r.f()?, r.fs()?, r.fs()?);
    let rows = r.list(|r| {
        let (y, x_s) = (r.f()?, r.f()?);
        let (u, h) = (r.fs_borrowed()?, r.fs_borrowed()?);
        let cells = CellFlags {
            all: r.flags()?,
            bouncing: r.flags()?,
            k_all: r.flags()?,
            k_bouncing: r.flags()?,
        };
        Some(Row {
            y,
            x_s,
            u,
            h,
            cells,
        })
    })?;
    // the binary form holds the channels' coordinates already (`to_bytes` writes a `Table`)
    Some(Table {
        k,
        sigma,
        nu,
        ys: rows.iter().map(|r| r.y).collect(),
        rows,
    })
}

#[cfg(test)]
#[path = "format_tests.rs"]
mod tests;
