//! V_stick against T_vis along one parameter ([`ThresholdCurve`]) and its chart, shared by
//! Figures 4 and 5 and the sphere-on-wall figure.

use super::chart::*;
use super::Error;
use crate::table::{Cell, Table};
use numerics::format::number;
use plotters::prelude::*;
use std::path::Path;
use thresholds::paper::Measurement;
use thresholds::StickingThresholds;

/// V_stick against T_vis for one value of a parameter (k, gamma_SV or the geometry).
#[derive(Debug, Clone)]
pub struct ThresholdCurve {
    /// The parameter of the curve (k, gamma_SV in J/m^2; 0 and 1 for identical spheres and a
    /// wall in the wall figure).
    pub parameter: f64,
    /// V_stick,JKR of the curve's contact (m/s).
    pub v_stick_jkr: f64,
    /// One search per T_vis, in increasing T_vis.
    pub points: Vec<StickingThresholds>,
}

impl ThresholdCurve {
    /// The table rows of this curve: `label`, then T_vis, V_stick, V_double_onset and
    /// V_stick,JKR, and no_bouncing_below when `with_limit`, one row per T_vis.
    pub fn rows(&self, label: Cell, with_limit: bool) -> Vec<Vec<Cell>> {
        self.points
            .iter()
            .map(|th| {
                let mut row = vec![
                    label.clone(),
                    th.t_vis.into(),
                    th.v_stick.into(),
                    th.v_double_onset.into(),
                    th.v_stick_jkr.into(),
                ];
                if with_limit {
                    row.push(th.no_bouncing_below().into());
                }
                row
            })
            .collect()
    }

    /// `(T_vis, V_stick)` where V_stick exists.
    pub fn v_stick(&self) -> Vec<(f64, f64)> {
        self.points
            .iter()
            .filter_map(|p| Some((p.t_vis, p.v_stick?)))
            .collect()
    }
}

/// The CSV of a family of curves (Figures 4 and 5, the wall figure): the `comments`, then the
/// units line, and one row per curve and T_vis ([`ThresholdCurve::rows`]) under the columns
/// `parameter.0` (each curve's label), t_vis, v_stick, v_double_onset, v_stick_jkr and, when
/// `with_limit`, no_bouncing_below. `parameter.1` is the label's entry in the units line
/// (`None` for a label without one).
pub fn curves_table<'a>(
    file: &str,
    mut comments: Vec<String>,
    parameter: (&str, Option<&str>),
    curves: impl IntoIterator<Item = (Cell, &'a ThresholdCurve)>,
    with_limit: bool,
) -> Table {
    let limit = if with_limit {
        ", no_bouncing_below"
    } else {
        ""
    };
    let label = parameter.1.map_or(String::new(), |u| format!("{u}, "));
    comments.push(format!(
        "units: {label}t_vis [s], v_stick, v_double_onset, v_stick_jkr{limit} [m/s]"
    ));
    let mut columns = vec![
        parameter.0,
        "t_vis",
        "v_stick",
        "v_double_onset",
        "v_stick_jkr",
    ];
    if with_limit {
        columns.push("no_bouncing_below");
    }
    let mut t = Table::new(file, comments, &columns);
    for (label, c) in curves {
        t.rows.extend(c.rows(label, with_limit));
    }
    t
}

/// Each curve with its legend label, `name = parameter` followed by `unit` (e.g. `" J/m^2"`).
pub fn labelled<'a>(
    curves: &'a [ThresholdCurve],
    name: &str,
    unit: &str,
) -> Vec<(String, &'a ThresholdCurve)> {
    let label = |c: &ThresholdCurve| format!("{name} = {}{unit}", number(c.parameter));
    curves.iter().map(|c| (label(c), c)).collect()
}

/// V_stick against T_vis over the span of the curves' T_vis: one line per curve, the
/// experiment (a band for its uncertainty) and the JKR stars.
pub fn v_stick_chart(
    path: &Path,
    caption: &str,
    curves: &[(String, &ThresholdCurve)],
    experiment: &Measurement,
) -> Result<(), Error> {
    let t_vis = || {
        curves
            .iter()
            .flat_map(|(_, c)| c.points.iter().map(|p| p.t_vis))
    };
    let x0 = t_vis().fold(f64::INFINITY, f64::min);
    let x1 = t_vis().fold(f64::NEG_INFINITY, f64::max);
    let line_at = experiment.v_stick;
    let err = experiment.v_stick_err;
    let band = (err > 0.0).then_some((line_at - err, line_at + err));
    let what = if err > 0.0 {
        format!("experiment {} +- {} m/s", number(line_at), number(err))
    } else {
        format!("experiment {} m/s", number(line_at))
    };
    let root = picture(path, SIZE_ONE)?;
    let values = curves
        .iter()
        .flat_map(|(_, c)| c.v_stick().into_iter().map(|p| p.1).chain([c.v_stick_jkr]))
        .chain([line_at])
        .chain(band.map_or(vec![], |(a, b)| vec![a, b]));
    let y = log_range(values);
    let mut chart = log_log(
        &root,
        caption,
        (x0, x1),
        y,
        "relaxation time T_vis (s)",
        "threshold velocity for sticking V_stick (m/s)",
    )?;
    if let Some((lo, hi)) = band {
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(x0, lo), (x1, hi)],
                BAND.mix(0.5).filled(),
            )))?
            .label("experimental range")
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BAND.filled()));
    }
    chart
        .draw_series(LineSeries::new(
            [(x0, line_at), (x1, line_at)],
            BLACK.stroke_width(1),
        ))?
        .label(what)
        .legend(legend_line(BLACK));
    for (j, (name, c)) in curves.iter().enumerate() {
        let col = COLOURS[j % COLOURS.len()];
        let pts = c.v_stick();
        let end = pts.last().copied();
        chart
            .draw_series(LineSeries::new(pts, col.stroke_width(2)))?
            .label(name.clone())
            .legend(legend_line(col));
        // where no collision bounces any more the curve ends: mark its last point
        if c.points.last().is_some_and(|p| p.v_stick.is_none()) {
            if let Some(p) = end {
                chart.draw_series(std::iter::once(Cross::new(p, 6, col.stroke_width(2))))?;
            }
        }
    }
    // one star per distinct V_stick,JKR, named after its curve when they differ
    let mut jkr: Vec<(f64, &str)> = curves
        .iter()
        .map(|(n, c)| (c.v_stick_jkr, n.as_str()))
        .collect();
    jkr.dedup_by(|a, b| a.0 == b.0);
    for &(v, name) in &jkr {
        let whose = if jkr.len() > 1 {
            format!(" ({name})")
        } else {
            String::new()
        };
        chart
            .draw_series(star!(x0 * 1.15, v, BLACK))?
            .label(format!(
                "V_stick,JKR = {} m/s{whose}",
                number(round_to(v, 3))
            ))
            .legend(|(x, y)| TriangleMarker::new((x + 10, y), 6, BLACK.filled()));
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    root.present()?;
    Ok(())
}
