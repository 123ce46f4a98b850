//! SVG pictures of the figures (plotters), drawn from the typed figure structs. Axes carry units;
//! log axes where the paper uses them, with ticks at 1, 2 and 5 of each decade when an axis spans
//! fewer than two decades, and ranges that fit the data.

use crate::figures::{
    Error, Figure1, Figure2, Figure3, Figure4, Figure5, Figure6, Figure7, FigureWall, Figures,
    ThresholdCurve, CO2_EXPERIMENT, H2O_EXPERIMENT, V_COL_MAX, WALL_GEOMETRIES,
};
use dynamics::Outcome;
use numerics::format::number;
use plotters::coord::combinators::WithKeyPoints;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

const SIZE_ONE: (u32, u32) = (720, 540);
const SIZE_TWO: (u32, u32) = (1300, 540);
const COLOURS: [RGBColor; 5] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(0, 0, 0),
];
const GREY: RGBColor = RGBColor(128, 128, 128);
const BAND: RGBColor = RGBColor(255, 221, 87);
const FONT: (&str, u32) = ("sans-serif", 18);
/// Axes spanning fewer decades than this get ticks at 2 and 5 of each decade too (with three
/// or more decades the decade labels alone are dense enough).
const FEW_DECADES: f64 = 2.999;

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type LogAxis = WithKeyPoints<LogCoord<f64>>;
type LogLog<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogAxis, LogAxis>>;

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

fn log_axis(lo: f64, hi: f64) -> LogAxis {
    (lo..hi).log_scale().with_key_points(log_ticks(lo, hi))
}

/// A chart with log axes, labelled in the workspace's number format.
fn log_log<'a, 'b>(
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
fn linear<'a, 'b>(
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
fn legend<'a, 'b: 'a, CT: CoordTranslate>(
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

/// Tick labels: the workspace's number format, with `1e-11` instead of `1e-11` spelt out.
fn label(v: &f64) -> String {
    let e = v.abs().log10();
    if (-3.0..=4.0).contains(&e) {
        let s = number(*v);
        s.strip_suffix(".0").map_or(s.clone(), str::to_string)
    } else {
        format!("{v:.0e}")
    }
}

/// `(min, max)` of values, padded by 5 % of the span.
fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    let pad = 0.05 * (hi - lo).max(1e-30);
    (lo - pad, hi + pad)
}

fn legend_line(c: RGBColor) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
}

/// A triangle marker at `(x, y)` of colour `c`, as a one-element series.
macro_rules! star {
    ($x:expr, $y:expr, $c:expr) => {
        std::iter::once(EmptyElement::at(($x, $y)) + TriangleMarker::new((0, 0), 8, $c.filled()))
    };
}

/// Draws every figure into `dir` as `fig1.svg` ... `fig7.svg` and `fig_wall.svg`.
pub fn draw_all(figs: &Figures, dir: &Path) -> Result<(), Error> {
    std::fs::create_dir_all(dir)?;
    figs.fig1.draw(&dir.join("fig1.svg"))?;
    figs.fig2.draw(&dir.join("fig2.svg"))?;
    figs.fig3.draw(&dir.join("fig3.svg"))?;
    figs.fig4.draw(&dir.join("fig4.svg"))?;
    figs.fig5.draw(&dir.join("fig5.svg"))?;
    figs.fig6.draw(&dir.join("fig6.svg"))?;
    figs.fig7.draw(&dir.join("fig7.svg"))?;
    figs.wall.draw(&dir.join("fig_wall.svg"))?;
    Ok(())
}

fn two_panels<'a>(root: &Area<'a>) -> (Area<'a>, Area<'a>) {
    root.split_horizontally(SIZE_TWO.0 / 2)
}

impl Figure1 {
    /// `fig1.svg`: |v| against beta for each k, and v near beta = 1.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = SVGBackend::new(path, SIZE_TWO).into_drawing_area();
        root.fill(&WHITE)?;
        let (left, right) = two_panels(&root);
        let mut chart = log_log(
            &left,
            "Figure 1: crack speed |v| (solid v > 0, thin v < 0)",
            (1e-3, 1e3),
            (1e-6, 1e8),
            "beta = G_eff / gamma (dimensionless)",
            "|v| (dimensionless)",
        )?;
        for (j, c) in self.curves.iter().enumerate() {
            let col = COLOURS[j % COLOURS.len()];
            let closing: Vec<_> = c.full.iter().filter(|p| p.1 > 0.0).copied().collect();
            let opening: Vec<_> = c
                .full
                .iter()
                .filter(|p| p.1 < 0.0)
                .map(|p| (p.0, -p.1))
                .collect();
            chart
                .draw_series(LineSeries::new(closing, col.stroke_width(2)))?
                .label(format!("k = {}", number(c.k)))
                .legend(legend_line(col));
            chart.draw_series(LineSeries::new(opening, col.stroke_width(1)))?;
        }
        legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
        let (lo, hi) = span(self.curves.iter().flat_map(|c| c.zoom.iter().map(|p| p.1)));
        let mut zoom = linear(
            &right,
            "v near beta = 1",
            0.95..1.05,
            lo..hi,
            "beta (dimensionless)",
            "v (dimensionless)",
        )?;
        for (j, c) in self.curves.iter().enumerate() {
            let col = COLOURS[j % COLOURS.len()];
            zoom.draw_series(LineSeries::new(c.zoom.clone(), col.stroke_width(2)))?
                .label(format!("k = {}", number(c.k)))
                .legend(legend_line(col));
        }
        legend(&mut zoom, SeriesLabelPosition::MiddleRight)?;
        root.present()?;
        Ok(())
    }
}

fn outcome_colour(o: Outcome) -> RGBColor {
    match o {
        Outcome::Sticking => GREY,
        Outcome::DoubleCollision => COLOURS[0],
        Outcome::Bouncing => COLOURS[1],
    }
}

impl Figure2 {
    /// `fig2.svg`: the trajectories in the delta-a and delta-delta_dot planes.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = SVGBackend::new(path, SIZE_TWO).into_drawing_area();
        root.fill(&WHITE)?;
        let (left, right) = two_panels(&root);
        let points = || self.runs.iter().flat_map(|r| r.points.iter());
        // plotted in nm, um and cm/s
        let (d0, d1) = span(points().map(|p| p.delta * 1e9));
        let (_, a1) = span(points().map(|p| p.a * 1e6));
        let (v0, v1) = span(points().map(|p| p.delta_dot * 100.0));
        let mut da = linear(
            &left,
            "Figure 2: delta-a plane (star: JKR equilibrium)",
            d0..d1,
            0.0..a1,
            "mutual approach delta (nm)",
            "contact radius a (um)",
        )?;
        let mut dv = linear(
            &right,
            "delta-delta_dot plane",
            d0..d1,
            v0..v1,
            "mutual approach delta (nm)",
            "approach speed delta_dot (cm/s)",
        )?;
        for run in &self.runs {
            let c = outcome_colour(run.outcome);
            let label = format!(
                "V_in = {} cm/s ({})",
                number(run.v_in * 100.0),
                run.outcome.as_str()
            );
            let xy = |f: &dyn Fn(&dynamics::TrajectoryPoint) -> f64| -> Vec<(f64, f64)> {
                run.points.iter().map(|p| (p.delta * 1e9, f(p))).collect()
            };
            da.draw_series(LineSeries::new(xy(&|p| p.a * 1e6), c.stroke_width(2)))?
                .label(label.clone())
                .legend(legend_line(c));
            dv.draw_series(LineSeries::new(
                xy(&|p| p.delta_dot * 100.0),
                c.stroke_width(2),
            ))?
            .label(label)
            .legend(legend_line(c));
        }
        let (a_eq, d_eq) = (self.contact.a_eq(), self.contact.delta_eq());
        da.draw_series(star!(d_eq * 1e9, a_eq * 1e6, COLOURS[2]))?;
        dv.draw_series(star!(d_eq * 1e9, 0.0, COLOURS[2]))?;
        legend(&mut da, SeriesLabelPosition::LowerRight)?;
        legend(&mut dv, SeriesLabelPosition::LowerRight)?;
        root.present()?;
        Ok(())
    }
}

impl Figure3 {
    /// `fig3.svg`: e against V_in, observed and computed.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
        root.fill(&WHITE)?;
        let (_, vs) = self.transitions();
        let mut chart = linear(
            &root,
            "Figure 3: CO2, R1 = 60 um, T_vis = 1e-9 s",
            2.0..10.0,
            -0.3..1.0,
            "impact speed V_in (cm/s)",
            "coefficient of restitution e",
        )?;
        for o in [
            Outcome::Sticking,
            Outcome::DoubleCollision,
            Outcome::Bouncing,
        ] {
            let c = outcome_colour(o);
            let pts: Vec<_> = self
                .points
                .iter()
                .filter(|p| p.outcome == o)
                .map(|p| (100.0 * p.v_in, p.e_observed()))
                .collect();
            chart
                .draw_series(LineSeries::new(pts, c.stroke_width(2)))?
                .label(format!("{} (observed e)", o.as_str()))
                .legend(legend_line(c));
        }
        let computed = self
            .points
            .iter()
            .filter(|p| p.outcome == Outcome::DoubleCollision)
            .map(|p| Circle::new((100.0 * p.v_in, p.e_computed), 2, COLOURS[0].filled()));
        chart
            .draw_series(computed)?
            .label("double: computed e = -V_out/V_in")
            .legend(|(x, y)| Circle::new((x + 10, y), 3, COLOURS[0].filled()));
        chart
            .draw_series(std::iter::once(Circle::new(
                (100.0 * vs, 0.0),
                6,
                GREY.filled(),
            )))?
            .label(format!("V_stick = {:.3} cm/s", 100.0 * vs))
            .legend(|(x, y)| Circle::new((x + 10, y), 5, GREY.filled()));
        legend(&mut chart, SeriesLabelPosition::LowerRight)?;
        root.present()?;
        Ok(())
    }
}

/// V_stick against T_vis: one line per curve, the experimental band and the JKR stars.
fn v_stick_chart(
    path: &Path,
    caption: &str,
    curves: &[(String, &ThresholdCurve)],
    (x0, x1): (f64, f64),
    band: Option<(f64, f64)>,
    line_at: f64,
    experiment: &str,
) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
    root.fill(&WHITE)?;
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
        .label(experiment.to_string())
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

/// `v` rounded to `digits` significant figures, for legends.
fn round_to(v: f64, digits: i32) -> f64 {
    let scale = 10f64.powi(digits - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

impl Figure4 {
    /// `fig4.svg`: V_stick against T_vis for each k, with the CO2 experiment.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let e = CO2_EXPERIMENT;
        let curves: Vec<_> = self
            .curves
            .iter()
            .map(|c| (format!("k = {}", number(c.parameter)), c))
            .collect();
        v_stick_chart(
            path,
            "Figure 4: CO2, R1 = 60 um",
            &curves,
            (1e-12, 1e-8),
            Some((e.v_stick - e.err, e.v_stick + e.err)),
            e.v_stick,
            &format!("experiment {} +- {} m/s", number(e.v_stick), number(e.err)),
        )
    }
}

impl Figure5 {
    /// `fig5.svg`: V_stick against T_vis for each gamma_SV, with the H2O experiment.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let curves: Vec<_> = self
            .curves
            .iter()
            .map(|c| (format!("gamma_SV = {} J/m^2", number(c.parameter)), c))
            .collect();
        v_stick_chart(
            path,
            "Figure 5: H2O, R1 = 90 um (x: no bouncing beyond)",
            &curves,
            (1e-12, 1e-7),
            None,
            H2O_EXPERIMENT.v_stick,
            &format!("experiment {} m/s", number(H2O_EXPERIMENT.v_stick)),
        )
    }
}

impl Figure6 {
    /// `fig6.svg`: fitted T_vis with their ranges, and the size laws.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
        root.fill(&WHITE)?;
        let y = log_range(
            self.laws
                .iter()
                .flat_map(|l| [l.1, l.2])
                .chain(self.fits.iter().flat_map(|f| [f.t_vis_min, f.t_vis_max])),
        );
        let mut chart = log_log(
            &root,
            "Figure 6: relaxation time against particle radius",
            (0.1, 1000.0),
            y,
            "particle radius R1 (um)",
            "relaxation time T_vis (s)",
        )?;
        for (name, c, pick) in [("CO2 law", COLOURS[0], 0usize), ("H2O law", COLOURS[1], 1)] {
            let pts: Vec<_> = self
                .laws
                .iter()
                .map(|l| (l.0 * 1e6, if pick == 0 { l.1 } else { l.2 }))
                .collect();
            chart
                .draw_series(LineSeries::new(pts, c.stroke_width(1)))?
                .label(format!("{name} (T_vis ∝ R1^1.11)"))
                .legend(legend_line(c));
        }
        for f in &self.fits {
            let x = f.r1 * 1e6;
            let (c, label) = match f.source {
                "co2" => (COLOURS[0], "CO2 fit (this work)"),
                "h2o" => (COLOURS[1], "H2O fit (this work)"),
                _ => (COLOURS[1], "Gundlach et al. 2015"),
            };
            if f.source == "gundlach2015" {
                chart
                    .draw_series(star!(x, f.t_vis, c))?
                    .label(label)
                    .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 6, c.filled()));
            } else {
                chart
                    .draw_series(std::iter::once(ErrorBar::new_vertical(
                        x,
                        f.t_vis_min.max(y.0),
                        f.t_vis,
                        f.t_vis_max,
                        c.filled(),
                        10,
                    )))?
                    .label(label)
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
            }
        }
        legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
        root.present()?;
        Ok(())
    }
}

impl Figure7 {
    /// `fig7.svg`: V_stick and V_frag against the monomer radius.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let root = SVGBackend::new(path, SIZE_TWO).into_drawing_area();
        root.fill(&WHITE)?;
        let (left, right) = two_panels(&root);
        type Pick = fn(&crate::figures::SizePoint) -> Option<f64>;
        let series: [(&str, RGBColor, Pick); 3] = [
            ("T_vis = T_vis,CO2 (standard)", COLOURS[0], |p| {
                p.co2.v_stick
            }),
            ("T_vis = T_vis,H2O", COLOURS[1], |p| p.h2o.v_stick),
            ("JKR (T_vis = 0)", GREY, |p| Some(p.co2.v_stick_jkr)),
        ];
        for (area, factor, what, ylab) in [
            (
                &left,
                1.0,
                "V_stick",
                "threshold velocity for sticking V_stick (m/s)",
            ),
            (
                &right,
                thresholds::V_FRAG_FACTOR,
                "V_frag",
                "fragmentation velocity V_frag = 10 V_stick (m/s)",
            ),
        ] {
            let mut values: Vec<f64> = self
                .points
                .iter()
                .flat_map(|p| series.iter().filter_map(|s| (s.2)(p)))
                .map(|v| v * factor)
                .collect();
            if what == "V_frag" {
                values.extend([V_COL_MAX.0, V_COL_MAX.1]);
            }
            let y = log_range(values.into_iter());
            let mut chart = log_log(
                area,
                &format!("Figure 7: CO2 monomers, {what}"),
                (0.1, 100.0),
                y,
                "monomer radius R1 (um)",
                ylab,
            )?;
            if what == "V_frag" {
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(0.1, V_COL_MAX.0), (100.0, V_COL_MAX.1)],
                        COLOURS[0].mix(0.15).filled(),
                    )))?
                    .label(format!(
                        "maximum collision velocity {} - {} m/s",
                        number(V_COL_MAX.0),
                        number(V_COL_MAX.1)
                    ))
                    .legend(|(x, y)| {
                        Rectangle::new([(x, y - 5), (x + 20, y + 5)], COLOURS[0].mix(0.3).filled())
                    });
            }
            for (label, c, pick) in series {
                let pts: Vec<_> = self
                    .points
                    .iter()
                    .filter_map(|p| Some((p.r1 * 1e6, pick(p)? * factor)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(pts, c.stroke_width(2)))?
                    .label(label)
                    .legend(legend_line(c));
            }
            legend(&mut chart, SeriesLabelPosition::UpperRight)?;
        }
        root.present()?;
        Ok(())
    }
}

impl FigureWall {
    /// `fig_wall.svg`: V_stick against T_vis for identical spheres and a sphere on a wall.
    pub fn draw(&self, path: &Path) -> Result<(), Error> {
        let e = CO2_EXPERIMENT;
        let curves: Vec<_> = WALL_GEOMETRIES
            .iter()
            .zip(&self.curves)
            .map(|(name, c)| {
                let label = if *name == "wall" {
                    "a 60 um sphere on a wall"
                } else {
                    "two identical spheres of 60 um"
                };
                (label.to_string(), c)
            })
            .collect();
        v_stick_chart(
            path,
            "Sphere on a wall: CO2, R1 = 60 um, k = 0.01",
            &curves,
            (1e-12, 1e-8),
            Some((e.v_stick - e.err, e.v_stick + e.err)),
            e.v_stick,
            &format!("experiment {} +- {} m/s", number(e.v_stick), number(e.err)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An axis over less than two decades gets 1, 2 and 5 of each decade (Figure 4's y axis,
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
