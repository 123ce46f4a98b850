//! SVG pictures of the figure tables (plotters). Axes carry units; log axes where the paper uses them.

use crate::figures::Error;
use crate::table::Table;
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

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type LogLog<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// A chart with log axes, labelled in scientific notation.
fn log_log<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
    x: std::ops::Range<f64>,
    y: std::ops::Range<f64>,
    x_desc: &str,
    y_desc: &str,
) -> Result<LogLog<'a, 'b>, Error> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x.log_scale(), y.log_scale())?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&sci)
        .y_label_formatter(&sci)
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

/// Pairs `(x, y)` of two columns where both are numbers, optionally filtered by row.
fn xy(t: &Table, x: &str, y: &str, keep: impl Fn(usize) -> bool) -> Vec<(f64, f64)> {
    t.numbers(x)
        .into_iter()
        .zip(t.numbers(y))
        .enumerate()
        .filter_map(|(i, (a, b))| if keep(i) { Some((a?, b?)) } else { None })
        .collect()
}

/// Tick labels of log axes: `1e-11`, `0.1`, `10`.
fn sci(v: &f64) -> String {
    let e = v.abs().log10();
    if (-2.0..=3.0).contains(&e) {
        format!("{v}")
    } else {
        format!("{v:.0e}")
    }
}

/// `(min, max)` of the points' coordinates, padded by 5 % of the span.
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

fn number_in(t: &Table, key: &str) -> Option<f64> {
    t.comments.iter().find_map(|c| {
        let i = c.find(key)?;
        let rest = &c[i + key.len()..];
        let rest = rest.trim_start_matches([' ', '=']);
        rest.split([' ', ',']).next()?.parse().ok()
    })
}

/// Draws every figure into `dir` as `fig<N>.svg`.
pub fn draw_all(figures: &[(usize, Vec<Table>)], dir: &Path) -> Result<(), Error> {
    std::fs::create_dir_all(dir)?;
    for (n, tables) in figures {
        let path = dir.join(format!("fig{n}.svg"));
        match n {
            1 => fig1(&tables[0], &path)?,
            2 => fig2(&tables[0], &path)?,
            3 => fig3(&tables[0], &path)?,
            4 => fig4(&tables[0], &path)?,
            5 => fig5(&tables[0], &path)?,
            6 => fig6(&tables[0], &tables[1], &path)?,
            7 => fig7(&tables[0], &path)?,
            _ => {}
        }
    }
    Ok(())
}

fn two_panels<'a>(root: &Area<'a>) -> (Area<'a>, Area<'a>) {
    root.split_horizontally(SIZE_TWO.0 / 2)
}

fn fig1(t: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_TWO).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = two_panels(&root);
    let panel = t.texts("panel");
    let ks = t.numbers("k");
    let mut kvals: Vec<f64> = ks.iter().flatten().copied().collect();
    kvals.dedup();
    let mut chart = ChartBuilder::on(&left)
        .caption("Figure 1: crack speed |v| (solid v > 0, thin v < 0)", FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((1e-3f64..1e3).log_scale(), (1e-6f64..1e8).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("beta = G_eff / gamma (dimensionless)")
        .y_desc("|v| (dimensionless)")
        .x_label_formatter(&sci)
        .y_label_formatter(&sci)
        .draw()?;
    for (j, k) in kvals.iter().enumerate() {
        let c = COLOURS[j % COLOURS.len()];
        let on = |i: usize| panel[i] == "full" && ks[i] == Some(*k);
        let pts = xy(t, "beta", "v", on);
        let closing: Vec<_> = pts.iter().filter(|p| p.1 > 0.0).copied().collect();
        let opening: Vec<_> = pts
            .iter()
            .filter(|p| p.1 < 0.0)
            .map(|p| (p.0, -p.1))
            .collect();
        chart
            .draw_series(LineSeries::new(closing, c.stroke_width(2)))?
            .label(format!("k = {k}"))
            .legend(legend_line(c));
        chart.draw_series(LineSeries::new(opening, c.stroke_width(1)))?;
    }
    legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    let mut zoom = ChartBuilder::on(&right)
        .caption("v near beta = 1", FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.95f64..1.05, {
            let (lo, hi) = span(
                xy(t, "beta", "v", |i| panel[i] == "zoom")
                    .into_iter()
                    .map(|p| p.1),
            );
            lo..hi
        })?;
    zoom.configure_mesh()
        .x_desc("beta (dimensionless)")
        .y_desc("v (dimensionless)")
        .draw()?;
    for (j, k) in kvals.iter().enumerate() {
        let c = COLOURS[j % COLOURS.len()];
        let pts = xy(t, "beta", "v", |i| panel[i] == "zoom" && ks[i] == Some(*k));
        zoom.draw_series(LineSeries::new(pts, c.stroke_width(2)))?
            .label(format!("k = {k}"))
            .legend(legend_line(c));
    }
    legend(&mut zoom, SeriesLabelPosition::MiddleRight)?;
    root.present()?;
    Ok(())
}

fn fig2(t: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_TWO).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = two_panels(&root);
    let v_in = t.numbers("v_in");
    let mut cases: Vec<f64> = v_in.iter().flatten().copied().collect();
    cases.dedup();
    let outcomes = t.texts("outcome");
    let a_eq = number_in(t, "a_eq").unwrap_or(f64::NAN);
    let d_eq = number_in(t, "delta_eq").unwrap_or(f64::NAN);
    let colour = |o: &str| match o {
        "sticking" => GREY,
        "double" => COLOURS[0],
        _ => COLOURS[1],
    };
    let scale = |p: Vec<(f64, f64)>, sx: f64, sy: f64| -> Vec<(f64, f64)> {
        p.into_iter().map(|(x, y)| (x * sx, y * sy)).collect()
    };
    let (d0, d1) = span(t.numbers("delta").into_iter().flatten().map(|d| d * 1e9));
    let (_, a1) = span(t.numbers("a").into_iter().flatten().map(|a| a * 1e6));
    let (v0, v1) = span(
        t.numbers("delta_dot")
            .into_iter()
            .flatten()
            .map(|v| v * 100.0),
    );
    let mut da = ChartBuilder::on(&left)
        .caption("Figure 2: delta-a plane (star: JKR equilibrium)", FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(d0..d1, 0f64..a1)?;
    da.configure_mesh()
        .x_desc("mutual approach delta (nm)")
        .y_desc("contact radius a (um)")
        .draw()?;
    let mut dv = ChartBuilder::on(&right)
        .caption("delta-delta_dot plane", FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(d0..d1, v0..v1)?;
    dv.configure_mesh()
        .x_desc("mutual approach delta (nm)")
        .y_desc("approach speed delta_dot (cm/s)")
        .draw()?;
    for v in &cases {
        let idx: Vec<usize> = (0..v_in.len()).filter(|&i| v_in[i] == Some(*v)).collect();
        let o = idx.first().map_or("", |&i| outcomes[i].as_str());
        let c = colour(o);
        let on = |i: usize| v_in[i] == Some(*v);
        let label = format!("V_in = {:.2} cm/s ({o})", v * 100.0);
        da.draw_series(LineSeries::new(
            scale(xy(t, "delta", "a", on), 1e9, 1e6),
            c.stroke_width(2),
        ))?
        .label(label.clone())
        .legend(legend_line(c));
        dv.draw_series(LineSeries::new(
            scale(xy(t, "delta", "delta_dot", on), 1e9, 100.0),
            c.stroke_width(2),
        ))?
        .label(label)
        .legend(legend_line(c));
    }
    let star = |x: f64, y: f64| {
        EmptyElement::at((x, y)) + TriangleMarker::new((0, 0), 8, COLOURS[2].filled())
    };
    da.draw_series(std::iter::once(star(d_eq * 1e9, a_eq * 1e6)))?;
    dv.draw_series(std::iter::once(star(d_eq * 1e9, 0.0)))?;
    legend(&mut da, SeriesLabelPosition::LowerRight)?;
    legend(&mut dv, SeriesLabelPosition::LowerRight)?;
    root.present()?;
    Ok(())
}

fn fig3(t: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
    root.fill(&WHITE)?;
    let outcome = t.texts("outcome");
    let vs = number_in(t, "v_stick").unwrap_or(f64::NAN);
    let mut chart = ChartBuilder::on(&root)
        .caption("Figure 3: CO2, R1 = 60 um, T_vis = 1e-9 s", FONT)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(2f64..10.0, -0.3f64..1.0)?;
    chart
        .configure_mesh()
        .x_desc("impact speed V_in (cm/s)")
        .y_desc("coefficient of restitution e")
        .draw()?;
    let cm = |p: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
        p.into_iter().map(|(x, y)| (100.0 * x, y)).collect()
    };
    for (name, c) in [
        ("sticking", GREY),
        ("double", COLOURS[0]),
        ("bouncing", COLOURS[1]),
    ] {
        let pts = cm(xy(t, "v_in", "e", |i| outcome[i] == name));
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(2)))?
            .label(format!("{name} (observed e)"))
            .legend(legend_line(c));
    }
    let computed = cm(xy(t, "v_in", "e_computed", |i| outcome[i] == "double"));
    chart
        .draw_series(
            computed
                .iter()
                .map(|&p| Circle::new(p, 2, COLOURS[0].filled())),
        )?
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

fn fig4(t: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
    root.fill(&WHITE)?;
    let ks = t.numbers("k");
    let mut kvals: Vec<f64> = ks.iter().flatten().copied().collect();
    kvals.dedup();
    kvals.sort_by(f64::total_cmp);
    kvals.dedup();
    let (x0, x1) = (1e-12f64, 1e-8f64);
    let mut chart = log_log(
        &root,
        "Figure 4: CO2, R1 = 60 um",
        x0..x1,
        1e-2..0.3,
        "relaxation time T_vis (s)",
        "threshold velocity for sticking V_stick (m/s)",
    )?;
    chart
        .draw_series(std::iter::once(Rectangle::new(
            [(x0, 0.02), (x1, 0.06)],
            BAND.mix(0.5).filled(),
        )))?
        .label("experiment 0.04 +- 0.02 m/s")
        .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BAND.filled()));
    chart.draw_series(LineSeries::new(
        [(x0, 0.04), (x1, 0.04)],
        BLACK.stroke_width(1),
    ))?;
    for (j, k) in kvals.iter().enumerate() {
        let c = COLOURS[j % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(
                xy(t, "t_vis", "v_stick", |i| ks[i] == Some(*k)),
                c.stroke_width(2),
            ))?
            .label(format!("k = {k}"))
            .legend(legend_line(c));
    }
    if let Some(Some(vj)) = t.numbers("v_stick_jkr").first() {
        chart
            .draw_series(std::iter::once(
                EmptyElement::at((x0 * 1.15, *vj)) + TriangleMarker::new((0, 0), 9, BLACK.filled()),
            ))?
            .label(format!("V_stick,JKR = {:.3e} m/s", vj))
            .legend(|(x, y)| TriangleMarker::new((x + 10, y), 6, BLACK.filled()));
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    root.present()?;
    Ok(())
}

fn fig5(t: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
    root.fill(&WHITE)?;
    let gs = t.numbers("gamma_sv");
    let mut gvals: Vec<f64> = gs.iter().flatten().copied().collect();
    gvals.sort_by(f64::total_cmp);
    gvals.dedup();
    let (x0, x1) = (1e-12f64, 1e-7f64);
    let mut chart = log_log(
        &root,
        "Figure 5: H2O, R1 = 90 um (curves end where no collision bounces)",
        x0..x1,
        1e-3..10.0,
        "relaxation time T_vis (s)",
        "threshold velocity for sticking V_stick (m/s)",
    )?;
    chart
        .draw_series(LineSeries::new(
            [(x0, 0.73), (x1, 0.73)],
            BLACK.stroke_width(1),
        ))?
        .label("experiment 0.73 m/s")
        .legend(legend_line(BLACK));
    for (j, g) in gvals.iter().enumerate() {
        let c = COLOURS[j % COLOURS.len()];
        let pts = xy(t, "t_vis", "v_stick", |i| gs[i] == Some(*g));
        let end = pts.last().copied();
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(2)))?
            .label(format!("gamma_SV = {g} J/m^2"))
            .legend(legend_line(c));
        if let Some(p) = end {
            chart.draw_series(std::iter::once(Cross::new(p, 6, c.stroke_width(2))))?;
        }
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    root.present()?;
    Ok(())
}

fn fig6(points: &Table, laws: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_ONE).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = log_log(
        &root,
        "Figure 6: relaxation time against particle radius",
        0.1..1000.0,
        1e-13..1e-6,
        "particle radius R1 (um)",
        "relaxation time T_vis (s)",
    )?;
    for (name, col, c) in [
        ("CO2 law", "t_vis_co2", COLOURS[0]),
        ("H2O law", "t_vis_h2o", COLOURS[1]),
    ] {
        let pts: Vec<_> = xy(laws, "r1", col, |_| true)
            .into_iter()
            .map(|(r, t)| (r * 1e6, t))
            .collect();
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(1)))?
            .label(format!("{name} (T_vis ∝ R1^1.11)"))
            .legend(legend_line(c));
    }
    let src = points.texts("source");
    let (r1, t, lo, hi) = (
        points.numbers("r1"),
        points.numbers("t_vis"),
        points.numbers("t_vis_min"),
        points.numbers("t_vis_max"),
    );
    for i in 0..src.len() {
        let (Some(r), Some(tv), Some(l), Some(h)) = (r1[i], t[i], lo[i], hi[i]) else {
            continue;
        };
        let x = r * 1e6;
        let (c, label) = match src[i].as_str() {
            "co2" => (COLOURS[0], "CO2 fit (this work)"),
            "h2o" => (COLOURS[1], "H2O fit (this work)"),
            _ => (COLOURS[1], "Gundlach et al. 2015"),
        };
        if src[i] == "gundlach2015" {
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((x, tv)) + TriangleMarker::new((0, 0), 9, c.filled()),
                ))?
                .label(label)
                .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 6, c.filled()));
        } else {
            chart
                .draw_series(std::iter::once(ErrorBar::new_vertical(
                    x,
                    l.max(1e-13),
                    tv,
                    h,
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

fn fig7(t: &Table, path: &Path) -> Result<(), Error> {
    let root = SVGBackend::new(path, SIZE_TWO).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = two_panels(&root);
    let um = |p: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
        p.into_iter().map(|(x, y)| (x * 1e6, y)).collect()
    };
    let series = [
        ("T_vis = T_vis,CO2 (standard)", "co2", COLOURS[0]),
        ("T_vis = T_vis,H2O", "h2o", COLOURS[1]),
        ("JKR (T_vis = 0)", "jkr", GREY),
    ];
    for (area, what, ylab, yr) in [
        (
            &left,
            "v_stick",
            "threshold velocity for sticking V_stick (m/s)",
            1e-3f64..100.0,
        ),
        (
            &right,
            "v_frag",
            "fragmentation velocity V_frag = 10 V_stick (m/s)",
            1e-2f64..1000.0,
        ),
    ] {
        let mut chart = log_log(
            area,
            &format!("Figure 7: CO2 monomers, {what}"),
            0.1..100.0,
            yr,
            "monomer radius R1 (um)",
            ylab,
        )?;
        if what == "v_frag" {
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(0.1, 25.0), (100.0, 50.0)],
                    COLOURS[0].mix(0.15).filled(),
                )))?
                .label("maximum collision velocity 25-50 m/s")
                .legend(|(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 20, y + 5)], COLOURS[0].mix(0.3).filled())
                });
        }
        for (label, suffix, c) in series {
            let pts = um(xy(t, "r1", &format!("{what}_{suffix}"), |_| true));
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
