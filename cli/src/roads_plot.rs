//! `roads --plot`: the recorded and simulated distributions of each road statistic, per road
//! class, as distribution functions in one SVG (the figure of docs/simulator.md).

use gyrodrift::sim::roads::{cdf_points, statistic, RoadComparison, RoadSamples, STATISTICS};
use plotters::prelude::*;
use std::path::Path;

const RECORDED: RGBColor = RGBColor(0, 90, 181);
const SIMULATED: RGBColor = RGBColor(220, 50, 32);

/// Draws one panel per statistic (rows) and road class (columns).
pub fn draw(c: &RoadComparison, path: &Path) -> Result<(), String> {
    let root = SVGBackend::new(path, (1200, 1500)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let (title, body) = root.split_vertically(40);
    title
        .titled("Road statistics: recorded (blue) against simulated (red dashed), fraction of samples at or below", ("sans-serif", 18))
        .map_err(|e| e.to_string())?;
    let panels = body.split_evenly((STATISTICS.len(), c.classes.len()));
    for (k, panel) in panels.iter().enumerate() {
        let (row, col) = (k / c.classes.len(), k % c.classes.len());
        let class = &c.classes[col];
        let (rec, sim) = (&c.pools.0.class[col], &c.pools.1.class[col]);
        let d = class.distance.values()[row];
        let (name, unit) = STATISTICS[row];
        let caption = format!("{}: {name} ({unit}), KS {d:.2}", class.class.name());
        panel_chart(panel, &caption, rec, sim, row).map_err(|e| e.to_string())?;
    }
    root.present().map_err(|e| format!("{}: {e}", path.display()))
}

fn panel_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    rec: &RoadSamples,
    sim: &RoadSamples,
    stat: usize,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (a, b) = (cdf_points(statistic(rec, stat), 200), cdf_points(statistic(sim, stat), 200));
    // the x range: up to the larger 95th percentile, so long tails do not squash the rest
    let p95 = |v: &[(f64, f64)]| v.iter().find(|p| p.1 >= 0.95).map_or(0.0, |p| p.0);
    let x_max = p95(&a).max(p95(&b)).max(1e-3) * 1.05;
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 13))
        .margin(6)
        .x_label_area_size(22)
        .y_label_area_size(32)
        .build_cartesian_2d(0.0..x_max, 0.0..1.0)?;
    chart.configure_mesh().x_labels(5).y_labels(3).label_style(("sans-serif", 11)).draw()?;
    let steps = |v: &[(f64, f64)]| -> Vec<(f64, f64)> { v.iter().map(|&(x, y)| (x.min(x_max), y)).collect() };
    chart.draw_series(LineSeries::new(steps(&a), RECORDED.stroke_width(2)))?;
    chart.draw_series(DashedLineSeries::new(steps(&b), 6, 4, SIMULATED.stroke_width(2)))?;
    Ok(())
}
