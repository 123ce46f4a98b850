//! The checks of the restitution tables against the ODE: each cell between two rows at its
//! centre, at speeds between the channels ([`BuildConfig::check_sigma`], [`BuildConfig::check_nu`]),
//! and at its quarters at those and denser speeds ([`QUARTERS`]),
//! e within [`BuildConfig::tol_e`], both sides and the bouncing side apart; each interval
//! between tables of neighbouring k at its middle k ([`k_cells`]).

use super::build::{collide, e_of, ratios, BuildConfig};
use super::format::{CellFlags, RowData, Table, TableData};
use super::{RestitutionTables, MIN_WINDOW};
use crate::master::{MasterTables, F_TOP};
use crate::{Outcome, ThresholdsError};
use greenwood::CrackLaw;
use rayon::prelude::*;

/// Whether the tables' e at `(x, y, k)` is within `tol_e` of the ODE at every check speed, and
/// at every bouncing one: `(all, bouncing)` (the bouncing speeds are checked first).
pub(super) fn check_point(
    cfg: &BuildConfig,
    law: &CrackLaw,
    tables: &RestitutionTables,
    masters: &MasterTables,
    x: f64,
    y: f64,
) -> (bool, bool) {
    let speeds = (&cfg.check_sigma[..], &cfg.check_nu[..]);
    check_point_at(cfg, law, tables, masters, (x, y), speeds)
}

/// [`check_point`] at the bouncing and double-collision speeds `(sigma, nu)`.
fn check_point_at(
    cfg: &BuildConfig,
    law: &CrackLaw,
    tables: &RestitutionTables,
    masters: &MasterTables,
    (x, y): (f64, f64),
    (sigma, nu): (&[f64], &[f64]),
) -> (bool, bool) {
    let Some((f, f_on)) = ratios(masters, x, y, law.k()) else {
        return (false, false);
    };
    let window = (f / f_on).ln();
    let speeds = sigma.iter().map(|&q| (true, q)).chain(
        nu.iter()
            .map(|&q| (false, q))
            .filter(|_| window >= MIN_WINDOW),
    );
    for (bouncing, q) in speeds {
        let s = if bouncing {
            f * q.exp()
        } else {
            f * (-q * window).exp()
        };
        // speeds the tables leave to the ODE (next to V_stick or the onset) are not checked
        if s > F_TOP || super::channel_of(s, f, f_on).is_none() {
            continue;
        }
        // where the tables decline (a channel without value in the stencil) they claim nothing
        let Some(h) = tables.h_unchecked(x, y, law.k(), bouncing, q) else {
            continue;
        };
        // a miss on the double-collision side leaves the bouncing side checked
        let Some((outcome, v_out)) = collide(cfg, law, x, y, s) else {
            return (false, !bouncing);
        };
        let exact = if outcome == Outcome::Sticking {
            0.0
        } else {
            -v_out / s
        };
        if (e_of(h, f, s, bouncing) - exact).abs() > cfg.tol_e {
            return (false, !bouncing);
        }
    }
    (true, true)
}

/// The centre of the cell of row `j`'s interval `i` (its nodes in increasing x).
pub(super) fn centre(rows: &[RowData], j: usize, i: usize) -> (f64, f64) {
    across(rows, j, i, 0.5)
}

/// The point of the cell of row `j`'s interval `i` at mid-y and the fraction `t` of the
/// interval in u = ln(x_s - x) (from its node of smaller x).
pub(super) fn across(rows: &[RowData], j: usize, i: usize, t: f64) -> (f64, f64) {
    let r = &rows[j];
    let (a, b) = (r.nodes[i].x, r.nodes[i + 1].x);
    let u = (1.0 - t) * (r.x_s - a).ln() + t * (r.x_s - b).ln();
    (r.x_s - u.exp(), 0.5 * (r.y + rows[j + 1].y))
}

/// Where in its interval (in u, at mid-y) a cell is checked besides its centre, at both speed
/// sets ([`BuildConfig::check_sigma`] and [`BuildConfig::check_nu`], and
/// [`BuildConfig::quarter_speeds`]).
pub const QUARTERS: [f64; 3] = [0.25, 0.5, 0.75];

/// `kept` (a cell's flags `(all, bouncing)`, after its centre's check) after its checks at
/// [`QUARTERS`] at both speed sets (the centre at the denser ones only): a miss drops the flag
/// of its side, as at the centre. Why: the centre at seven bouncing speeds let cells through
/// where e changes fast along x (k = 0.02, x = -1.05 to -0.85, y = -4.29 at 15 V_stick: the
/// centre's checks passed, e 2.8e-4 off three quarters along; k = 0.0504, x = -1.8, y = -4.5:
/// 5.6e-4) or between two check speeds.
fn check_quarters_of(
    on: (&BuildConfig, &CrackLaw, &RestitutionTables, &MasterTables),
    rows: &[RowData],
    (j, i): (usize, usize),
    mut kept: (bool, bool),
) -> (bool, bool) {
    let (cfg, law, tables, masters) = on;
    let speed_sets = [
        (&cfg.check_sigma[..], &cfg.check_nu[..]),
        (&cfg.quarter_speeds.0[..], &cfg.quarter_speeds.1[..]),
    ];
    for t in QUARTERS {
        for (n, speeds) in speed_sets.into_iter().enumerate() {
            // the centre at the centre's speeds: `kept` holds that check already
            if t == 0.5 && n == 0 {
                continue;
            }
            if !(kept.0 || kept.1) {
                return kept;
            }
            let at = across(rows, j, i, t);
            let (all, bouncing) = check_point_at(cfg, law, tables, masters, at, speeds);
            kept = (kept.0 && all, kept.1 && bouncing);
        }
    }
    kept
}

/// The flags `(all, bouncing)` of cell `i` (an empty `bouncing` record is `all`'s, as the files
/// write it).
fn flags_of(cells: &CellFlags, i: usize) -> (bool, bool) {
    let all = cells.all.get(i).copied().unwrap_or(false);
    (all, cells.bouncing.get(i).copied().unwrap_or(all))
}

/// The header line of a table whose cells [`check_quarters`] checked.
pub const QUARTERS_HEADER: &str = "quarters: every vouched cell checked again at a quarter, half and three quarters of its interval (mid-y) at the centre's speeds and between every fourth pair of channels; a cell that missed is vouched no longer (cargo xtask restitution-table --quarters)";

/// Each vouched cell of `table` (of `law`'s k) checked again at its quarters ([`QUARTERS`],
/// both speed sets; `cargo xtask restitution-table --quarters`, for tables whose cells were
/// checked at their centres only), and [`QUARTERS_HEADER`] in its header; how many flags were
/// dropped (each side of each cell counts).
pub fn check_quarters(
    (cfg, law): (&BuildConfig, &CrackLaw),
    table: &mut TableData,
    masters: &MasterTables,
    progress: &(dyn Fn(&str) + Sync),
) -> usize {
    let tables = RestitutionTables::from_parts(vec![Table::from_data(table)]);
    let on = (cfg, law, &tables, masters);
    let rows = &table.rows;
    let checks: Vec<(usize, Vec<(bool, bool)>)> = (0..rows.len().saturating_sub(1))
        .into_par_iter()
        .map(|j| {
            let flags = (0..rows[j].nodes.len().saturating_sub(1))
                .map(|i| check_quarters_of(on, rows, (j, i), flags_of(&rows[j].cells, i)))
                .collect();
            (j, flags)
        })
        .collect();
    table.header.retain(|h| !h.starts_with("quarters:"));
    table.header.push(QUARTERS_HEADER.into());
    let mut lost = 0;
    for (j, flags) in checks {
        let cells = &mut table.rows[j].cells;
        let count = |c: &CellFlags| {
            (0..flags.len())
                .map(|i| flags_of(c, i))
                .map(|(a, b)| usize::from(a) + usize::from(b))
                .sum::<usize>()
        };
        let before = count(cells);
        cells.all = flags.iter().map(|f| f.0).collect();
        cells.bouncing = flags.iter().map(|f| f.1).collect();
        let fewer = before - count(cells);
        if fewer > 0 {
            lost += fewer;
            progress(&format!(
                "restitution k = {}, cells of row y = {}: {fewer} flags fewer at the quarters",
                table.k, table.rows[j].y
            ));
        }
    }
    lost
}

/// The cells (and the bouncing cells) of the rows marked in `rows_to_check` checked at their
/// centres against the ODE, and those that pass at their quarters ([`QUARTERS`]).
pub(super) fn check_cells(
    cfg: &BuildConfig,
    law: &CrackLaw,
    table: &mut TableData,
    masters: &MasterTables,
    rows_to_check: &[bool],
    progress: &(dyn Fn(&str) + Sync),
) {
    let tables = RestitutionTables::from_parts(vec![Table::from_data(table)]);
    let on = (cfg, law, &tables, masters);
    let rows = &table.rows;
    let checks: Vec<(usize, Vec<(bool, bool)>)> = (0..rows.len().saturating_sub(1))
        .into_par_iter()
        .filter(|&j| rows_to_check[j])
        .map(|j| {
            let flags = (0..rows[j].nodes.len().saturating_sub(1))
                .map(|i| {
                    let (x, y) = centre(rows, j, i);
                    let kept = check_point(cfg, law, &tables, masters, x, y);
                    check_quarters_of(on, rows, (j, i), kept)
                })
                .collect();
            (j, flags)
        })
        .collect();
    for (j, flags) in checks {
        let (good, bouncing) = (
            flags.iter().filter(|f| f.0).count(),
            flags.iter().filter(|f| f.1).count(),
        );
        progress(&format!(
            "restitution k = {}, cells of row y = {}: {good} of {} vouched, {bouncing} for bouncing",
            table.k,
            table.rows[j].y,
            flags.len()
        ));
        let cells = &mut table.rows[j].cells;
        cells.all = flags.iter().map(|f| f.0).collect();
        cells.bouncing = flags.iter().map(|f| f.1).collect();
    }
}

/// Fills the k cells of `tables` (in increasing k): each cell of table i checked at the middle
/// k between it and table i + 1 with the cubic in ln k, for every channel (`kcells`) and for the
/// bouncing channels alone (`kbcells`).
pub fn k_cells(
    cfg: &BuildConfig,
    tables: &mut [TableData],
    masters: &MasterTables,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<(), ThresholdsError> {
    let all = RestitutionTables::from_parts(tables.iter().map(Table::from_data).collect());
    for i in 0..tables.len().saturating_sub(1) {
        let k_mid = (tables[i].k * tables[i + 1].k).sqrt();
        let law = CrackLaw::new(k_mid)?;
        let rows = &tables[i].rows;
        // per row, per cell: (every channel vouched, the bouncing channels vouched)
        let flags: Vec<Vec<(bool, bool)>> = (0..rows.len())
            .into_par_iter()
            .map(|j| {
                if j + 1 >= rows.len() {
                    return vec![(false, false); rows[j].nodes.len().saturating_sub(1)];
                }
                (0..rows[j].nodes.len().saturating_sub(1))
                    .map(|c| {
                        let (x, y) = centre(rows, j, c);
                        check_point(cfg, &law, &all, masters, x, y)
                    })
                    .collect()
            })
            .collect();
        let count = |side: fn(&(bool, bool)) -> bool| -> usize {
            flags
                .iter()
                .map(|f| f.iter().filter(|&b| side(b)).count())
                .sum()
        };
        let (good, bouncing) = (count(|b| b.0), count(|b| b.1));
        progress(&format!(
            "restitution k cells between k = {} and {}: {good} vouched, {bouncing} for bouncing",
            tables[i].k,
            tables[i + 1].k
        ));
        for (r, f) in tables[i].rows.iter_mut().zip(flags) {
            r.cells.k_all = f.iter().map(|b| b.0).collect();
            r.cells.k_bouncing = f.iter().map(|b| b.1).collect();
        }
    }
    Ok(())
}
