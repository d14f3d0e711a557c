//! The report's two plots, drawn with plotters as SVG: cost against error per work scene
//! (`work_precision.svg`) and cost and error against the band's stiffness (`stiffness.svg`).
//! `run` draws them from the work-precision and stiffness sweeps; the side-by-side adds the
//! contenders' lines ([`ExtraLines`]). Each method has the core's colour
//! ([`Integrator::colour`]), the game's too; each panel's legend stands in a strip of its own
//! beside the axes, where no data is.

use std::error::Error;
use std::ops::Range;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::stiffness::StiffPoint;
use super::work_precision::WorkPoint;
use crate::measure::references::work_scenes;
use crate::physics::Integrator;

/// One line of a plot: an integrator's (dots), or a contender's whole `App` tick (triangles).
pub struct Line {
    pub label: String,
    pub colour: RGBAColor,
    pub triangles: bool,
    pub points: Vec<(f64, f64)>,
}

impl Line {
    fn of(integrator: Integrator, points: Vec<(f64, f64)>) -> Self {
        let [r, g, b] = integrator.colour();
        Self {
            label: integrator.name().to_owned(),
            colour: RGBColor(r, g, b).to_rgba(),
            triangles: false,
            points,
        }
    }
}

/// Lines from outside the core's integrators, to draw beside them.
///
/// They are the contenders' (in their `App`s): by scene in the work-precision plot, and in the
/// stiffness plot's cost and error panels.
#[derive(Default)]
pub struct ExtraLines {
    pub work: Vec<(&'static str, Line)>,
    pub stiffness: [Vec<Line>; 2],
}

/// The width of a panel's legend strip, at the right of its axes.
const LEGEND_WIDTH: u32 = 200;

/// One log-log panel: a line with dots per integrator, a legend beside it, and red crosses.
struct Panel<'a> {
    title: String,
    x: (&'a str, Range<f64>),
    y: (&'a str, Range<f64>),
    lines: Vec<Line>,
    crosses: Vec<(f64, f64)>,
}

fn draw_panel(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    panel: Panel,
) -> Result<(), Box<dyn Error>> {
    let width = area.dim_in_pixel().0;
    let (area, legend) = area.split_horizontally(width.saturating_sub(LEGEND_WIDTH));
    draw_legend(&legend, &panel.lines)?;
    let mut chart = ChartBuilder::on(&area)
        .caption(panel.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(90)
        .build_cartesian_2d(panel.x.1.log_scale(), panel.y.1.log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(RGBColor(240, 240, 240))
        .bold_line_style(RGBColor(200, 200, 200))
        .x_desc(panel.x.0)
        .y_desc(panel.y.0)
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()?;
    for line in panel.lines {
        let colour = line.colour;
        chart.draw_series(LineSeries::new(line.points.clone(), colour.stroke_width(2)))?;
        if line.triangles {
            chart.draw_series(
                line.points
                    .iter()
                    .map(|&p| TriangleMarker::new(p, 6, colour.filled())),
            )?;
        } else {
            chart.draw_series(
                line.points
                    .iter()
                    .map(|&p| Circle::new(p, 3, colour.filled())),
            )?;
        }
    }
    chart.draw_series(panel.crosses.iter().map(|&p| Cross::new(p, 5, RED)))?;
    Ok(())
}

/// Draws a panel's legend, in its strip.
///
/// It lists each line's mark (a dot or a triangle on a stroke) and name, top to bottom, level with
/// the axes' top.
fn draw_legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    lines: &[Line],
) -> Result<(), Box<dyn Error>> {
    let style = ("sans-serif", 13).into_font().color(&BLACK);
    for (index, line) in lines.iter().enumerate() {
        let y = 48 + 20 * index as i32;
        let colour = line.colour;
        area.draw(&PathElement::new(
            vec![(4, y), (28, y)],
            colour.stroke_width(2),
        ))?;
        if line.triangles {
            area.draw(&TriangleMarker::new((16, y), 6, colour.filled()))?;
        } else {
            area.draw(&Circle::new((16, y), 3, colour.filled()))?;
        }
        area.draw(&Text::new(line.label.clone(), (34, y - 8), style.clone()))?;
    }
    Ok(())
}

/// Returns the smallest and largest of some positive values.
fn extent(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, 0.0), |(low, high), v| {
        (low.min(v), high.max(v))
    })
}

/// Plots error (log x) against cost (log y), a panel per scene, a line per integrator.
///
/// There is also a line per contender (`extra`, by scene); diverged runs are red crosses at the
/// right edge.
pub(super) fn plot_work_precision(
    points: &[WorkPoint],
    mut extra: Vec<(&'static str, Line)>,
    path: &Path,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1400, 1000)).into_drawing_area();
    root.fill(&WHITE)?;
    let scenes: Vec<&str> = work_scenes().iter().map(|work| work.scene.name).collect();
    for (area, scene) in root.split_evenly((2, 2)).iter().zip(&scenes) {
        let here: Vec<&WorkPoint> = points.iter().filter(|p| p.scene == *scene).collect();
        let mut lines: Vec<Line> = Integrator::ALL
            .iter()
            .map(|&integrator| {
                let line = here
                    .iter()
                    .filter(|p| p.integrator == integrator)
                    .filter_map(|p| p.error.map(|e| (e.max(1e-16), p.ns_per_simulated_second)))
                    .collect();
                Line::of(integrator, line)
            })
            .collect();
        let (contenders, others) = extra.into_iter().partition(|(s, _)| s == scene);
        extra = others;
        lines.extend(contenders.into_iter().map(|(_, line)| line));
        let (x_min, x_max) = extent(lines.iter().flat_map(|l| l.points.iter().map(|p| p.0)));
        let x_max = x_max.max(1.0) * 30.0;
        let (y_min, y_max) = extent(
            here.iter()
                .map(|p| p.ns_per_simulated_second)
                .chain(lines.iter().flat_map(|l| l.points.iter().map(|p| p.1))),
        );
        let crosses = here
            .iter()
            .filter(|p| p.diverged_at.is_some())
            .map(|p| (x_max / 2.0, p.ns_per_simulated_second))
            .collect();
        draw_panel(
            area,
            Panel {
                title: format!("{scene}: cost against error (x: diverged)"),
                x: ("final pose error (px)", (x_min / 3.0).min(1e-12)..x_max),
                y: ("ns per simulated second", y_min / 2.0..y_max * 2.0),
                lines,
                crosses,
            },
        )?;
    }
    root.present()?;
    Ok(())
}

/// Plots cost per step and error against k at 100 Hz, a line per integrator.
///
/// `extra` holds the contenders' lines for the two panels (cost, error).
pub(super) fn plot_stiffness(
    points: &[StiffPoint],
    extra: [Vec<Line>; 2],
    path: &Path,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1400, 550)).into_drawing_area();
    root.fill(&WHITE)?;
    let at_100: Vec<&StiffPoint> = points.iter().filter(|p| p.rate == 100.0).collect();
    type Value = fn(&StiffPoint) -> Option<f64>;
    let views: [(&str, &str, Value); 2] = [
        // A diverged run stops early and looks cheap: leave it out.
        ("cost per fixed step at 100 Hz", "ns per step", |p| {
            p.diverged_at.is_none().then_some(p.ns_per_tick)
        }),
        ("error at the horizon, 100 Hz", "pose error (px)", |p| {
            p.error.map(|e| e.max(1e-14))
        }),
    ];
    for ((area, (title, y_desc, value)), contenders) in
        root.split_evenly((1, 2)).iter().zip(views).zip(extra)
    {
        let mut lines: Vec<Line> = Integrator::ALL
            .iter()
            .map(|&integrator| {
                let line = at_100
                    .iter()
                    .filter(|p| p.integrator == integrator)
                    .filter_map(|p| value(p).map(|v| (p.k, v)))
                    .collect();
                Line::of(integrator, line)
            })
            .collect();
        lines.extend(contenders);
        let (y_min, y_max) = extent(lines.iter().flat_map(|l| l.points.iter().map(|p| p.1)));
        draw_panel(
            area,
            Panel {
                title: title.to_owned(),
                x: ("band stiffness k", 10.0..3e12),
                y: (y_desc, y_min / 3.0..y_max * 3.0),
                lines,
                crosses: Vec::new(),
            },
        )?;
    }
    root.present()?;
    Ok(())
}
