//! Shared chart helpers of the figures (plotters, SVG): sizes, colours, log axes with ticks at
//! each decade (and at 2 and 5 of each decade when an axis spans fewer than three decades),
//! ranges that fit the data, legends, and the tick-label format.

use super::Error;
use dynamics::Outcome;
use numerics::format::number;
use plotters::coord::combinators::WithKeyPoints;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Size (pixels) of a one-panel picture.
pub const SIZE_ONE: (u32, u32) = (720, 540);
/// Size (pixels) of a two-panel picture.
pub const SIZE_TWO: (u32, u32) = (1300, 540);
/// The colours of successive curves.
pub const COLOURS: [RGBColor; 5] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(0, 0, 0),
];
/// Grey: sticking, JKR.
pub const GREY: RGBColor = RGBColor(128, 128, 128);
/// The experimental band.
pub const BAND: RGBColor = RGBColor(255, 221, 87);
/// Captions.
pub const FONT: (&str, u32) = ("sans-serif", 18);
/// Axes spanning fewer decades than this (fewer than three) get ticks at 2 and 5 of each decade
/// too; with three or more decades the decade labels alone are dense enough.
const FEW_DECADES: f64 = 2.999;

/// A drawing area of an SVG picture.
pub type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
/// A log axis with chosen ticks.
pub type LogAxis = WithKeyPoints<LogCoord<f64>>;
/// A chart with two log axes.
pub type LogLog<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogAxis, LogAxis>>;

/// Tick values of a log axis over `[lo, hi]`: each decade, and 2 and 5 of each decade when the
/// axis spans fewer than `FEW_DECADES` decades.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let mantissas: &[f64] = if (hi / lo).log10() < FEW_DECADES {
        &[1.0, 2.0, 5.0]
    } else {
        &[1.0]
    };
    let mut out = Vec::new();
    let mut decade = 10f64.powf(lo.log10().floor());
    while decade <= hi * 1.000_001 {
        for m in mantissas {
            let v = m * decade;
            if v >= lo * 0.999_999 && v <= hi * 1.000_001 {
                out.push(v);
            }
        }
        decade *= 10.0;
    }
    out
}

/// A log range that holds `values` snugly: from the 1-2-5 value at or below the smallest to the
/// one at or above the largest (so no empty decade is left on either side).
pub fn log_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (1.0, 10.0);
    }
    let nice = |v: f64, up: bool| {
        let d = 10f64.powf(v.log10().floor());
        let steps = [1.0, 2.0, 5.0, 10.0];
        if up {
            steps
                .iter()
                .map(|m| m * d)
                .find(|x| *x >= v * (1.0 - 1e-12))
                .unwrap_or(10.0 * d)
        } else {
            steps
                .iter()
                .rev()
                .map(|m| m * d)
                .find(|x| *x <= v * (1.0 + 1e-12))
                .unwrap_or(d)
        }
    };
    (nice(lo, false), nice(hi, true))
}

/// A log axis over `[lo, hi]` with the ticks of [`log_ticks`].
pub fn log_axis(lo: f64, hi: f64) -> LogAxis {
    (lo..hi).log_scale().with_key_points(log_ticks(lo, hi))
}

/// A chart with log axes, labelled in the workspace's number format.
pub fn log_log<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    x_desc: &str,
    y_desc: &str,
) -> Result<LogLog<'a, 'b>, Error> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(log_axis(x0, x1), log_axis(y0, y1))?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&label)
        .y_label_formatter(&label)
        .draw()?;
    Ok(chart)
}

/// A linear chart.
pub fn linear<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
    x: std::ops::Range<f64>,
    y: std::ops::Range<f64>,
    x_desc: &str,
    y_desc: &str,
) -> Result<ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>, Error> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .draw()?;
    Ok(chart)
}

/// Draws the legend of `chart` at `pos`.
pub fn legend<'a, 'b: 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, SVGBackend<'b>, CT>,
    pos: SeriesLabelPosition,
) -> Result<(), Error> {
    chart
        .configure_series_labels()
        .position(pos)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .draw()?;
    Ok(())
}

/// Tick labels: between 1e-3 and 1e4 the workspace's number format (without a trailing `.0`),
/// otherwise the power of ten alone (`1e-11`).
pub fn label(v: &f64) -> String {
    let e = v.abs().log10();
    if (-3.0..=4.0).contains(&e) {
        let s = number(*v);
        s.strip_suffix(".0").map_or(s.clone(), str::to_string)
    } else {
        format!("{v:.0e}")
    }
}

/// `(min, max)` of values, padded by 5 % of the span.
pub fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    let pad = 0.05 * (hi - lo).max(1e-30);
    (lo - pad, hi + pad)
}

/// A legend entry: a short line of colour `c`.
pub fn legend_line(c: RGBColor) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
}

/// A triangle marker at `(x, y)` of colour `c`, as a one-element series.
macro_rules! star {
    ($x:expr, $y:expr, $c:expr) => {
        std::iter::once(EmptyElement::at(($x, $y)) + TriangleMarker::new((0, 0), 8, $c.filled()))
    };
}
pub(crate) use star;

/// A white SVG picture of `size` pixels at `path`.
pub fn picture(path: &std::path::Path, size: (u32, u32)) -> Result<Area<'_>, Error> {
    let root = SVGBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE)?;
    Ok(root)
}

/// The two panels of a [`SIZE_TWO`] picture, side by side.
pub fn two_panels<'a>(root: &Area<'a>) -> (Area<'a>, Area<'a>) {
    root.split_horizontally(SIZE_TWO.0 / 2)
}

/// The colour of an outcome in Figures 2 and 3.
pub fn outcome_colour(o: Outcome) -> RGBColor {
    match o {
        Outcome::Sticking => GREY,
        Outcome::DoubleCollision => COLOURS[0],
        Outcome::Bouncing => COLOURS[1],
    }
}

/// `v` rounded to `digits` significant figures, for legends.
pub fn round_to(v: f64, digits: i32) -> f64 {
    let scale = 10f64.powi(digits - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An axis over fewer than three decades gets 1, 2 and 5 of each decade (Figure 4's y axis,
    /// 0.01 to 0.2 m/s); wider axes only the decades.
    #[test]
    fn ticks() {
        assert_eq!(log_ticks(0.01, 0.2), vec![0.01, 0.02, 0.05, 0.1, 0.2]);
        assert_eq!(log_ticks(1e-12, 1e-8).len(), 5);
        assert_eq!(log_ticks(0.01, 1.0).len(), 7);
    }

    /// Ranges hold the data with no empty decade: Figure 7's V_stick from 2e-3 to 30 m/s.
    #[test]
    fn ranges_fit_the_data() {
        let (lo, hi) = log_range([0.0023, 31.0].into_iter());
        assert_eq!((lo, hi), (0.002, 50.0));
        let (lo, hi) = log_range([0.0166, 0.06].into_iter());
        assert_eq!((lo, hi), (0.01, 0.1));
    }
}
