//! `roads --plot`: the recorded and simulated distributions of each road statistic, per road
//! class, as distribution functions, and the yaw-rate spectra, in one SVG (the figure of
//! docs/simulator.md).

use gyrodrift::sim::roads::spectrum::BAND_NAMES;
use gyrodrift::sim::roads::{cdf_points, statistic, RoadComparison, RoadSamples, STATISTICS};
use plotters::prelude::*;
use std::path::Path;

const RECORDED: RGBColor = RGBColor(0, 90, 181);
const SIMULATED: RGBColor = RGBColor(220, 50, 32);

/// Draws one panel per statistic (rows) and road class (columns).
pub fn draw(c: &RoadComparison, path: &Path) -> Result<(), String> {
    let root = SVGBackend::new(path, (1200, 1700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let (title, body) = root.split_vertically(40);
    title
        .titled(
            "Road statistics: recorded (blue) against simulated (red dashed), fraction of samples at or below; last row: yaw-rate spectra",
            ("sans-serif", 18),
        )
        .map_err(|e| e.to_string())?;
    // one row per statistic, and a last row of yaw-rate spectra
    let panels = body.split_evenly((STATISTICS.len() + 1, c.classes.len()));
    for (k, panel) in panels.iter().enumerate() {
        let (row, col) = (k / c.classes.len(), k % c.classes.len());
        let class = &c.classes[col];
        let (rec, sim) = (&c.pools.0.class[col], &c.pools.1.class[col]);
        if row == STATISTICS.len() {
            let worst = class.distance.spectrum.iter().copied().fold(0.0, f64::max);
            let caption = format!("{}: yaw-rate RMS per period band (deg/s), KS up to {worst:.2}", class.class.name());
            spectrum_chart(panel, &caption, &class.recorded.band_rms_dps, &class.simulated.band_rms_dps).map_err(|e| e.to_string())?;
            continue;
        }
        let d = class.distance.values()[row];
        let (name, unit) = STATISTICS[row];
        let caption = format!("{}: {name} ({unit}), KS {d:.2}", class.class.name());
        panel_chart(panel, &caption, rec, sim, row).map_err(|e| e.to_string())?;
    }
    root.present().map_err(|e| format!("{}: {e}", path.display()))
}

/// The RMS of each period band (longest period first), recorded and simulated.
fn spectrum_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    rec: &[f64; 5],
    sim: &[f64; 5],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let y_max = rec.iter().chain(sim).copied().filter(|v| v.is_finite()).fold(1e-3, f64::max) * 1.1;
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 13))
        .margin(6)
        .x_label_area_size(22)
        .y_label_area_size(32)
        .build_cartesian_2d(-0.2..4.2, 0.0..y_max)?;
    chart
        .configure_mesh()
        .x_labels(5)
        .x_label_formatter(&|x: &f64| BAND_NAMES.get(x.round() as usize).map_or(String::new(), |s| s.to_string()))
        .y_labels(3)
        .label_style(("sans-serif", 11))
        .draw()?;
    let line =
        |v: &[f64; 5]| -> Vec<(f64, f64)> { v.iter().enumerate().filter(|p| p.1.is_finite()).map(|(k, &y)| (k as f64, y)).collect() };
    chart.draw_series(LineSeries::new(line(rec), RECORDED.stroke_width(2)))?;
    chart.draw_series(DashedLineSeries::new(line(sim), 6, 4, SIMULATED.stroke_width(2)))?;
    Ok(())
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
