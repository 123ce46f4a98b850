//! Refining a committed restitution table in y where its cells fail between rows
//! (`cargo xtask restitution-table --refine --only I`).
//!
//! The cells of the tables built with rows every 0.25 in y fail in a band of y = -4.25 to 0.25
//! (five to nine cells an interval of rows, at one or two decades of c_D from the cliff, in
//! every table): there e from the tables misses the ODE by 2.5e-5 to 6e-5 at the cells'
//! centres and by about 1e-6 on the rows themselves (k = 0.01, rows y = -1.75 to -0.75), so the
//! miss is the cubic across the rows. Those are the grains of the laboratory experiments (CO2
//! and H2O of 20-200 um, T_vis 1e-11 - 3e-9 s): a fifth of their collisions went to the ODE.
//! A row halfway between two rows whose cells fail divides that miss by about sixteen; the
//! cells whose four-row stencil the new row enters are checked again.
//!
//! [`refill_table`] rebuilds the rows whose nodes were built without thresholds (the master
//! tables did not vouch there then, and do now).

use super::build::{build_row, ratios, BuildConfig};
use super::check::check_cells;
use super::format::{RowData, TableData};
use super::CLIFF_MARGIN;
use crate::master::build::grid_k;
use crate::master::format::EndsData;
use crate::master::interp::stencil_start;
use crate::master::MasterTables;
use crate::ThresholdsError;
use greenwood::CrackLaw;

/// The band of y refined: above 0.5 the cells hold; below -4.5 (rows with values since
/// [`refill_table`]) rows halfway answered 0.1 % more random collisions for tables a third
/// larger (`docs/performance.md`, "Restitution tables").
pub const REFINE_Y: (f64, f64) = (-4.5, 0.5);

/// The closest two rows may come: the end curves' grid in y (1/64), on which a new row's end
/// x_s is read.
pub const MIN_Y_STEP: f64 = 1.0 / 64.0;

/// Whether the bouncing cells from row `r` to the next fail anywhere the tables would answer
/// (at least [`CLIFF_MARGIN`] in x from the row's end; the committed tables were refined with
/// the margin at 0.05, so a refinement now would add rows for cells 0.03-0.05 from the end).
/// The double-collision channels next to the onset (nu = 0.99-0.998) miss by 6e-5 to 2e-3 with
/// rows 1/16 apart as with rows 1/4 apart: a finer row spacing does not help them.
fn fails(r: &RowData) -> bool {
    r.cells
        .side(true)
        .0
        .iter()
        .zip(r.nodes.windows(2))
        .any(|(&ok, pair)| !ok && r.x_s - pair[1].x >= CLIFF_MARGIN)
}

/// Adds a row halfway between every two rows of `table` (the table of the `k_index`-th k of the
/// master tables, on their end curves `ends`) whose cells fail within [`REFINE_Y`], and checks
/// again the cells whose stencil changed; `passes` times at most, or until no row is added.
/// The k cells of the refined table are cleared (`cargo xtask restitution-table --k-cells`
/// computes them again). Returns the number of rows added.
pub fn refine_table(
    cfg: &BuildConfig,
    table: &mut TableData,
    k_index: usize,
    ends: &EndsData,
    masters: &MasterTables,
    passes: usize,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<usize, ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    // the column of the end curves' grid at the table's k (12 steps an octave, the tables 3)
    let column = (k_index * (ends.per_octave / 3)) * ends.ny;
    debug_assert!((grid_k(ends.k0, 3, k_index) / table.k - 1.0).abs() < 1e-9);
    let mut added = 0;
    for pass in 0..passes {
        let rows = &table.rows;
        let new: Vec<RowData> = (0..rows.len().saturating_sub(1))
            .filter(|&j| fails(&rows[j]))
            .map(|j| (rows[j].y, rows[j + 1].y))
            .filter(|&(a, b)| b - a >= 2.0 * MIN_Y_STEP - 1e-12)
            .map(|(a, b)| 0.5 * (a + b))
            .filter(|&y| y >= REFINE_Y.0 && y <= REFINE_Y.1)
            .filter_map(|y| {
                let at = column + ((y - ends.y0) / ends.dy).round() as usize;
                let x_s = *ends.x_s.get(at)?;
                x_s.is_finite().then(|| {
                    let r = build_row(cfg, &law, masters, y, x_s);
                    progress(&format!(
                        "restitution k = {}, pass {pass}, new row y = {y}: {} nodes",
                        table.k,
                        r.nodes.len()
                    ));
                    r
                })
            })
            .collect();
        if new.is_empty() {
            break;
        }
        added += new.len();
        let new_y: Vec<f64> = new.iter().map(|r| r.y).collect();
        table.rows.extend(new);
        table.rows.sort_by(|a, b| a.y.total_cmp(&b.y));
        let changed: Vec<usize> = (0..table.rows.len())
            .filter(|&m| new_y.contains(&table.rows[m].y))
            .collect();
        let stale = stencils_holding(table.rows.len(), &changed);
        check_cells(cfg, &law, table, masters, &stale, progress);
    }
    if added > 0 {
        for r in &mut table.rows {
            r.cells.k_all.clear();
            r.cells.k_bouncing.clear();
        }
        table.header.push(format!(
            "refined: {added} rows added halfway between rows whose cells failed, y within {} .. {} (the cubic across rows; restitution::refine)",
            REFINE_Y.0, REFINE_Y.1
        ));
    }
    Ok(added)
}

/// Which of the `n` rows' intervals (cells) have a four-row stencil holding one of the rows
/// `changed`: interval j is interpolated through rows `stencil_start(j, n) .. + 4` (clamped at
/// both ends), so those are the cells to check again.
fn stencils_holding(n: usize, changed: &[usize]) -> Vec<bool> {
    (0..n)
        .map(|j| {
            let s = stencil_start(j.min(n.saturating_sub(2)), n);
            changed.iter().any(|&m| (s..s + 4).contains(&m))
        })
        .collect()
}

/// Rebuilds the rows of `table` that hold a node without thresholds where the master tables now
/// vouch for them, and checks again the cells whose stencil holds a rebuilt row; returns the
/// number of rows rebuilt. A node stands on the master tables' F and F_on and has no value
/// without them: the tables built before the master tables had rows below y = -4.5 (most k)
/// had none at any node there, and the four-row stencils reaching down to them refused answers
/// up to y = -4.25 (81 rows of the committed tables: 51 below -4.5, 21 up to -3.75 for k =
/// 0.04 and 0.0504, the top rows y = 5 - 5.5 of those two, 3 of k = 0.01 with one node each).
/// The rows keep their y and end x_s; the k cells are cleared (`--k-cells` computes them
/// again).
pub fn refill_table(
    cfg: &BuildConfig,
    table: &mut TableData,
    masters: &MasterTables,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<usize, ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    let k = table.k;
    let stale_rows: Vec<usize> = (0..table.rows.len())
        .filter(|&j| {
            let r = &table.rows[j];
            r.nodes
                .iter()
                .any(|p| !p.f.is_finite() && ratios(masters, p.x, r.y, k).is_some())
        })
        .collect();
    for &j in &stale_rows {
        let (y, x_s) = (table.rows[j].y, table.rows[j].x_s);
        table.rows[j] = build_row(cfg, &law, masters, y, x_s);
        progress(&format!(
            "restitution k = {k}, row y = {y} rebuilt: {} nodes",
            table.rows[j].nodes.len()
        ));
    }
    if stale_rows.is_empty() {
        return Ok(0);
    }
    let stale = stencils_holding(table.rows.len(), &stale_rows);
    check_cells(cfg, &law, table, masters, &stale, progress);
    for r in &mut table.rows {
        r.cells.k_all.clear();
        r.cells.k_bouncing.clear();
    }
    table.header.push(format!(
        "refilled: {} rows rebuilt whose nodes had no thresholds where the master tables now vouch for them (restitution::refine)",
        stale_rows.len()
    ));
    Ok(stale_rows.len())
}

/// Checks every cell of `table` again, both sides and the bouncing side alone (a table built
/// before the bouncing cells were kept apart: its bouncing cells are then its cells).
pub fn recheck_table(
    cfg: &BuildConfig,
    table: &mut TableData,
    masters: &MasterTables,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<(), ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    let all = vec![true; table.rows.len()];
    check_cells(cfg, &law, table, masters, &all, progress);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::restitution::format::{CellFlags, NodeData};

    fn row(xs: &[f64], x_s: f64, cells: &[bool], bcells: &[bool]) -> RowData {
        RowData {
            y: 0.0,
            x_s,
            nodes: xs
                .iter()
                .map(|&x| NodeData {
                    x,
                    f: 2.0,
                    f_on: 1.5,
                    h: Vec::new(),
                })
                .collect(),
            cells: CellFlags {
                all: cells.to_vec(),
                bouncing: bcells.to_vec(),
                ..CellFlags::default()
            },
        }
    }

    /// The cells to check again after row m changed are those whose four-row stencil holds m,
    /// the clamped stencils at both ends included (interval 0 is interpolated through rows 0-3,
    /// the last of 9 intervals through rows 6-9).
    #[test]
    fn the_stencils_holding_a_row_include_the_clamped_ends() {
        let stale = |m| -> Vec<usize> {
            let s = stencils_holding(10, &[m]);
            (0..9).filter(|&j| s[j]).collect()
        };
        assert_eq!(stale(3), [0, 1, 2, 3, 4]);
        assert_eq!(stale(6), [4, 5, 6, 7, 8]);
        assert_eq!(stale(0), [0, 1]);
    }

    /// A failed cell counts where the tables would answer (at least CLIFF_MARGIN from the end,
    /// where the answer declines anyway), and the bouncing cells decide when kept apart (a miss
    /// next to the onset is not one a row in between mends).
    #[test]
    fn failing_cells_are_those_the_tables_would_answer() {
        let xs = [-2.0, -1.0, -0.5, -0.02];
        // the last cell ends 0.01 from x_s = -0.01: inside the margin
        assert!(!fails(&row(&xs, -0.01, &[true, true, false], &[])));
        assert!(fails(&row(&xs, -0.01, &[true, false, true], &[])));
        // the cells fail on the double-collision side only: the bouncing cells hold
        assert!(!fails(&row(
            &xs,
            -0.01,
            &[false, false, true],
            &[true, true, true]
        )));
        assert!(fails(&row(
            &xs,
            -0.01,
            &[true, true, true],
            &[false, true, true]
        )));
    }
}
