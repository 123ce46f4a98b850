//! `cargo xtask master-table --part beyond`: the rows of a committed table that are not monotone
//! checked for no bouncing beyond their ends, without new nodes: up to [`BELOW_THE_FALL`] of
//! [`F_TOP`] where nothing bounces there, else up to the ratio where they stop increasing.
//!
//! A row is monotone when its ratios increase towards its ends and nothing bounces beyond them
//! up to [`F_TOP`]; only then did the tables answer "no bouncing below v_max" beyond the end
//! and "at least" closer to it than vouched. Most rows that are not monotone fall only where
//! F is flat at F_TOP (9990-9999.9: the second kind of bouncing, whose threshold rises slowly
//! there, and the nodes' noise of a few 1e-6), and a row next to the kink of the cliff falls
//! where the second kind of bouncing takes over (F of 30-800): each increases up to a level
//! ([`RowData::increasing_up_to`]). Below that level the answers that need
//! monotone rows hold as well, once nothing is seen to bounce beyond the ends below it: this
//! pass runs that check ([`BEYOND`](super::row) distances, the exact search up to the level)
//! and records the level in the row (`none_beyond`; 0 where something bounces).
//!
//! "No bouncing beyond the end" rests on that check alone, not on how the row rises towards
//! its end (the same three distances vouch for it in a monotone row), so each row is first
//! checked up to [`BELOW_THE_FALL`] of [`F_TOP`]: next to the kink, where rows fall at F of
//! 30-800, nothing bounces beyond their ends up to there (the left branch of the cliff, where F
//! rises as a power of c_D), and "no bouncing below v_max" is answered there for the default
//! v_max (1000 V_stick,JKR) as well.

use super::row::none_beyond;
use super::BuildConfig;
use crate::master::format::{RowData, TableData, F_TOP};
use crate::ThresholdsError;
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;

/// The level checked is this fraction of the level where the ratios stop increasing: below it,
/// by more than the nodes' noise and the interpolation's error.
pub const BELOW_THE_FALL: f64 = 0.999;

/// `table` with each row that is not monotone checked beyond its ends up to
/// [`BELOW_THE_FALL`] of [`F_TOP`], or where something bounces there, up to [`BELOW_THE_FALL`]
/// of the level where its ratios stop increasing; `progress` is told each row's outcome.
pub fn check_beyond_table(
    cfg: &BuildConfig,
    table: &TableData,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<TableData, ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    let rows = table
        .rows
        .par_iter()
        .map(|row| {
            if row.monotone {
                return row.clone();
            }
            let clear_to = |level: f64| {
                none_beyond(cfg, &law, row.y, row.x_s, false, level)
                    && none_beyond(cfg, &law, row.y, row.x_on, true, level)
            };
            let top = BELOW_THE_FALL * F_TOP;
            let fall = F_TOP.min(BELOW_THE_FALL * row.increasing_up_to());
            let (level, clear) = if fall < top && clear_to(top) {
                (top, true)
            } else {
                (fall, clear_to(fall))
            };
            progress(&format!(
                "k = {}, row y = {}: {} beyond its ends below F = {}",
                table.k,
                row.y,
                if clear {
                    "nothing bounces"
                } else {
                    "something bounces"
                },
                number(level)
            ));
            RowData {
                none_beyond: if clear { level } else { 0.0 },
                ..row.clone()
            }
        })
        .collect();
    let built = super::built_at(table);
    let mut header = table.header.clone();
    header.push(format!(
        "beyond: each row that is not monotone checked for no bouncing beyond its ends below {} of {F_TOP}, else of the ratio where its ratios stop increasing (the row's sixth number; cargo xtask master-table --part beyond, on the table of commit {built})",
        number(BELOW_THE_FALL)
    ));
    Ok(TableData {
        k: table.k,
        header,
        rows,
        cells: table.cells.clone(),
    })
}

/// `--check` of the levels: every `every`-th row of `table` that is not monotone and carries a
/// level, from the middle of the first stride (and the middle one where there are fewer),
/// checked beyond its ends again below it; the y of the first row at which something now
/// bounces, if any, and how many rows were checked.
///
/// The sample starts mid-stride, not at the first row: the first rows (y = -6, where the
/// searches up to F_TOP run longest) took 91 of the 117 s of one thread that the 25 rows from
/// each table's first took (2026-11-27); from mid-stride, 21 rows take 63 s. A change of the
/// model moves every row's searches alike, and the nodes' check recomputes values of the
/// first rows too.
pub fn check_levels(
    cfg: &BuildConfig,
    table: &TableData,
    every: usize,
) -> Result<(Option<f64>, usize), ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    let candidates: Vec<&RowData> = table
        .rows
        .iter()
        .filter(|r| !r.monotone && r.none_beyond > 0.0)
        .collect();
    let rows: Vec<&RowData> = mid_stride(candidates.len(), every)
        .map(|i| candidates[i])
        .collect();
    let moved = rows
        .par_iter()
        .filter(|r| {
            !(none_beyond(cfg, &law, r.y, r.x_s, false, r.none_beyond)
                && none_beyond(cfg, &law, r.y, r.x_on, true, r.none_beyond))
        })
        .map(|r| r.y)
        .min_by(f64::total_cmp);
    Ok((moved, rows.len()))
}

/// The indices of `n` items that [`check_levels`] samples: every `every`-th from the middle of
/// the first stride, or the middle item where there are fewer.
fn mid_stride(n: usize, every: usize) -> impl Iterator<Item = usize> {
    let every = every.max(1);
    ((every / 2).min(n / 2)..n).step_by(every)
}

#[cfg(test)]
mod tests {
    use super::mid_stride;

    /// Every 16th of 40 from the 8th; of fewer than a stride, the middle one; of none, none.
    #[test]
    fn the_sample_starts_mid_stride() {
        let of = |n, every| mid_stride(n, every).collect::<Vec<_>>();
        assert_eq!(of(40, 16), [8, 24]);
        assert_eq!(of(41, 16), [8, 24, 40]);
        assert_eq!(of(5, 16), [2]);
        assert_eq!(of(1, 16), [0]);
        assert!(of(0, 16).is_empty());
        assert_eq!(of(3, 1), [0, 1, 2]);
    }
}
