//! Charts drawn from Rust with plotters-canvas. A chart spec (title, axis labels, ranges,
//! series as Float64Array, optional shaded intervals and cursor) comes from the page;
//! series are reduced by core's min/max decimation to the canvas width before drawing.
//! Returns the plot area in canvas pixels and its ranges, so the page maps mouse to data.

use gyrodrift::export::{self, Series as Plotted};
use gyrodrift::{axis, decimate};
use js_sys::{Float64Array, Object, Reflect};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_canvas::CanvasBackend;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

mod spec;
use spec::{Series, Shade, Spec};

/// Where the plot area is, for mouse mapping.
struct Layout {
    left: i32,
    top: i32,
    right: i32,
    bottom: i32,
    x_min: f64,
    x_max: f64,
    y_min: f64,
    y_max: f64,
    /// The time axis's unit ("" when x is not time) and the seconds it holds (1 when not time).
    x_unit: &'static str,
    x_unit_s: f64,
    /// Where a time axis counts from, s: a time t is labelled (t - x_origin) / x_unit_s.
    x_origin: f64,
    /// Where the ticks are, as labelled (in the time unit; log axes as values, not exponents).
    x_ticks: Vec<f64>,
    y_ticks: Vec<f64>,
}

fn parse_color(s: &str) -> RGBColor {
    let h = s.trim_start_matches('#');
    let v = u32::from_str_radix(h, 16).unwrap_or(0x444444);
    RGBColor((v >> 16) as u8, (v >> 8) as u8, v as u8)
}

/// A linear f64 axis whose ticks are given (core's round values), not chosen by plotters.
struct Ticked {
    range: std::ops::Range<f64>,
    ticks: Vec<f64>,
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;
    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let (a, b) = (self.range.start, self.range.end);
        let f = if b > a { (value - a) / (b - a) } else { 0.0 };
        limit.0 + (f * (limit.1 - limit.0) as f64).round() as i32
    }
    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        // Bold lines and labels at the ticks; no light lines between them.
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }
    fn range(&self) -> std::ops::Range<f64> {
        self.range.clone()
    }
}

/// A tick label: at most six decimals, no trailing zeros (0.30000000000000004 -> 0.3).
fn plain(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

fn js_err(e: impl std::fmt::Display) -> JsValue {
    js_sys::Error::new(&e.to_string()).into()
}

/// Draws a chart on the canvas (sized to its CSS box times the device pixel ratio).
#[wasm_bindgen(js_name = drawChart, unchecked_return_type = "ChartLayout")]
pub fn draw_chart(
    canvas: HtmlCanvasElement,
    #[wasm_bindgen(unchecked_param_type = "ChartSpec")] spec: JsValue,
) -> Result<JsValue, JsValue> {
    let spec = Spec::read(&spec)?;
    let backend = CanvasBackend::with_canvas_object(canvas).ok_or_else(|| js_err("no 2D canvas context"))?;
    let root = backend.into_drawing_area();
    let layout = draw(&root, &spec).map_err(js_err)?;
    root.present().map_err(js_err)?;
    let o = Object::new();
    for (k, v) in [
        ("left", layout.left as f64),
        ("top", layout.top as f64),
        ("right", layout.right as f64),
        ("bottom", layout.bottom as f64),
        ("x_min", layout.x_min),
        ("x_max", layout.x_max),
        ("y_min", layout.y_min),
        ("y_max", layout.y_max),
        ("x_unit_s", layout.x_unit_s),
        ("x_origin", layout.x_origin),
    ] {
        Reflect::set(&o, &JsValue::from_str(k), &JsValue::from_f64(v))?;
    }
    Reflect::set(&o, &JsValue::from_str("x_unit"), &JsValue::from_str(layout.x_unit))?;
    Reflect::set(&o, &JsValue::from_str("x_ticks"), &Float64Array::from(&layout.x_ticks[..]))?;
    Reflect::set(&o, &JsValue::from_str("y_ticks"), &Float64Array::from(&layout.y_ticks[..]))?;
    Ok(o.into())
}

/// The unit of an axis label "<quantity> (<unit>)", "" when it has none (core's
/// `export::label_unit`): the one reading for CSV columns and the dashboard's tooltips.
#[wasm_bindgen(js_name = labelUnit)]
pub fn label_unit(label: &str) -> String {
    export::label_unit(label).to_string()
}

/// Every series of a chart spec as CSV, as plotted (core's `export`): over a shared x
/// (time in seconds, tau) one row per x; a chart of paths (a track) two columns per path.
/// Columns are named "<series> (<y unit>)"; a shaded mask becomes a 0/1 column.
#[wasm_bindgen(js_name = chartCsv)]
pub fn chart_csv(#[wasm_bindgen(unchecked_param_type = "ChartSpec")] spec: JsValue) -> Result<String, JsValue> {
    let spec = Spec::read(&spec)?;
    let mut names: Vec<String> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    let mut kept = Vec::new();
    for s in spec.series.iter().filter(|s| s.name != "zero") {
        // Two series of one name (a band's edges) get numbered columns.
        let name = if seen.insert(s.name.clone()) { s.name.clone() } else { format!("{} {}", s.name, names.len() + 1) };
        names.push(name);
        kept.push(s);
    }
    if kept.iter().any(|s| s.path) {
        let series: Vec<Plotted> = kept.iter().zip(&names).map(|(s, n)| Plotted { name: n, x: &s.x, y: &s.y }).collect();
        return Ok(export::paths_csv(&spec.x_label, &spec.y_label, &series));
    }
    let y_unit = export::label_unit(&spec.y_label);
    let columns: Vec<String> = names.iter().map(|n| if y_unit.is_empty() { n.clone() } else { format!("{n} ({y_unit})") }).collect();
    let mut series: Vec<Plotted> = kept.iter().zip(&columns).map(|(s, n)| Plotted { name: n, x: &s.x, y: &s.y }).collect();
    let shade_name = spec.shade.as_ref().map(|sh| format!("{} (0/1)", if sh.label.is_empty() { "shaded" } else { &sh.label }));
    if let (Some(sh), Some(n)) = (&spec.shade, &shade_name) {
        series.push(Plotted { name: n, x: &sh.x, y: &sh.mask });
    }
    let x_name = if spec.time_x { format!("{} (s)", spec.x_label) } else { spec.x_label.clone() };
    Ok(export::series_csv(&x_name, &series))
}

/// A series decimated to the pixel columns (or whole, for points and paths).
type Decimated<'a> = Vec<(&'a Series, Vec<f64>, Vec<f64>)>;

/// The x and y ranges (given, or from the data in the x window) and the decimated series.
fn ranges(spec: &Spec, columns: usize, equal: Option<[f64; 4]>) -> (f64, f64, f64, f64, Decimated<'_>) {
    let (x_range, y_range) = match equal {
        Some([a, b, c, d]) => (Some([a, b]), Some([c, d])),
        None => (spec.x_range, spec.y_range),
    };
    let (x0, x1) = match x_range {
        Some([a, b]) if b > a => (a, b),
        _ => axis::finite_range(spec.series.iter().flat_map(|s| s.x.iter().copied())).unwrap_or((0.0, 1.0)),
    };
    let mut decimated = Vec::with_capacity(spec.series.len());
    for s in &spec.series {
        let (dx, dy) = if s.points || s.path { (s.x.clone(), s.y.clone()) } else { decimate::min_max(&s.x, &s.y, x0, x1, columns) };
        decimated.push((s, dx, dy));
    }
    let (y0, y1) = match y_range {
        Some([a, b]) if b > a => (a, b),
        _ => axis::value_range(
            decimated.iter().flat_map(|(_, dx, dy)| dx.iter().zip(dy.iter()).filter(|(x, _)| **x >= x0 && **x <= x1).map(|(_, y)| *y)),
            spec.log_y,
        ),
    };
    (x0, x1, y0, y1, decimated)
}

/// The chart's title and its font size: `full` px, smaller down to `least` when the title is
/// wider than `avail` px (a phone), and cut at a word with an ellipsis below that, so a title
/// never runs off the canvas.
fn fit_caption(root: &DrawingArea<CanvasBackend, Shift>, title: &str, avail: u32, full: i32, least: i32) -> (String, i32) {
    let width = |t: &str, size: i32| root.estimate_text_size(t, &("sans-serif", size).into_font().into()).map_or(0, |(w, _)| w);
    let w_full = width(title, full);
    if w_full <= avail {
        return (title.to_string(), full);
    }
    let size = ((full as f64 * avail as f64 / w_full as f64).floor() as i32).clamp(least, full);
    if width(title, size) <= avail {
        return (title.to_string(), size);
    }
    let words: Vec<&str> = title.split(' ').collect();
    for n in (1..words.len()).rev() {
        let cut = format!("{}…", words[..n].join(" "));
        if width(&cut, size) <= avail {
            return (cut, size);
        }
    }
    (title.to_string(), size)
}

/// The plotted coordinates: a time axis in its unit, a log axis in log10.
#[derive(Clone, Copy)]
struct Scale {
    log_x: bool,
    log_y: bool,
    /// Seconds per unit of a time axis (1 otherwise).
    per: f64,
    /// Where a time axis counts from, s (0 otherwise).
    origin: f64,
}

impl Scale {
    fn tx(self, v: f64) -> f64 {
        if self.log_x {
            v.log10()
        } else {
            (v - self.origin) / self.per
        }
    }
    fn ty(self, v: f64) -> f64 {
        if self.log_y {
            v.log10()
        } else {
            v
        }
    }
}

type Chart<'a> = ChartContext<'a, CanvasBackend, Cartesian2d<Ticked, Ticked>>;
type DrawResult<T> = Result<T, Box<dyn std::error::Error>>;

/// Shaded intervals where the mask is 1 (turn switch, gyro used, ...); gaps narrower than a
/// pixel column are merged, so a flickering mask costs a few rectangles, not thousands.
fn draw_shade(chart: &mut Chart, sh: &Shade, sc: Scale, x: (f64, f64), cy: (f64, f64), columns: usize) -> DrawResult<()> {
    let (x0, x1) = x;
    let c = parse_color(&sh.color).mix(0.18);
    let intervals = axis::mask_intervals(&sh.x, &sh.mask, (x1 - x0) / columns as f64);
    let visible: Vec<(f64, f64)> = intervals.into_iter().filter(|(s0, e)| *e >= x0 && *s0 <= x1).collect();
    if visible.is_empty() {
        return Ok(());
    }
    let drawn = chart
        .draw_series(visible.iter().map(|&(s0, e)| Rectangle::new([(sc.tx(s0.max(x0)), cy.0), (sc.tx(e.min(x1)), cy.1)], c.filled())))?;
    if !sh.label.is_empty() {
        drawn.label(sh.label.as_str()).legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 16, y + 5)], c.filled()));
    }
    Ok(())
}

/// One series, decimated, as a line or as square markers, with its legend entry; what falls
/// outside the plot (cx, cy: its ranges as drawn) is cut at its edge, not drawn along it.
fn draw_line(
    chart: &mut Chart,
    s: &Series,
    (dx, dy): (&[f64], &[f64]),
    sc: Scale,
    (cx, cy): ((f64, f64), (f64, f64)),
    px: impl Fn(f64) -> i32,
) -> DrawResult<()> {
    let color = parse_color(&s.color);
    let width = px(s.width.unwrap_or(1) as f64).max(1) as u32;
    let pts: Vec<(f64, f64)> = dx
        .iter()
        .zip(dy.iter())
        .filter(|(x, y)| x.is_finite() && y.is_finite() && (!sc.log_x || **x > 0.0) && (!sc.log_y || **y > 0.0))
        .map(|(x, y)| (sc.tx(*x), sc.ty(*y)))
        .collect();
    let style = ShapeStyle { color: color.to_rgba(), filled: true, stroke_width: width };
    let drawn = if s.points {
        // Square markers: a filled rect is far cheaper on a canvas than an arc.
        let r = px(1.5);
        let inside = |&&(x, y): &&(f64, f64)| x >= cx.0 && x <= cx.1 && y >= cy.0.min(cy.1) && y <= cy.0.max(cy.1);
        chart.draw_series(pts.iter().filter(inside).map(|&p| EmptyElement::at(p) + Rectangle::new([(-r, -r), (r, r)], style)))?
    } else {
        let runs = gyrodrift::decimate::clip_polyline(&pts, cx, (cy.0.min(cy.1), cy.0.max(cy.1)));
        chart.draw_series(runs.into_iter().map(|run| PathElement::new(run, style)))?
    };
    drawn.label(s.name.as_str()).legend(move |(x, y)| {
        PathElement::new(vec![(x, y), (x + 16, y)], ShapeStyle { color: color.to_rgba(), filled: true, stroke_width: 2 })
    });
    Ok(())
}

/// The chart's frame: title, margins and label areas; the plot area is what they leave.
fn frame<'a, 'b>(
    root: &'a DrawingArea<CanvasBackend, Shift>,
    title: &'b str,
    title_px: i32,
    dpr: f64,
) -> ChartBuilder<'a, 'b, CanvasBackend> {
    let px = |v: f64| (v * dpr).round() as i32;
    let mut b = ChartBuilder::on(root);
    b.caption(title, ("sans-serif", title_px).into_font())
        .margin(px(8.0))
        .margin_right(px(16.0))
        .x_label_area_size(px(34.0))
        .y_label_area_size(px(62.0));
    b
}

/// Equal axes (core's `axis::equal_ranges`) on the plot area this frame leaves, measured by
/// building it once and clearing what that drew.
fn equal_ranges(
    root: &DrawingArea<CanvasBackend, Shift>,
    spec: &Spec,
    title: &str,
    title_px: i32,
) -> Result<[f64; 4], Box<dyn std::error::Error>> {
    let measured = frame(root, title, title_px, spec.dpr.clamp(0.5, 4.0))
        .build_cartesian_2d(Ticked { range: 0.0..1.0, ticks: Vec::new() }, Ticked { range: 0.0..1.0, ticks: Vec::new() })?;
    let (xr, yr) = measured.plotting_area().get_pixel_range();
    root.fill(&WHITE)?;
    let ext = |f: fn(&Series) -> &Vec<f64>| axis::finite_range(spec.series.iter().flat_map(|s| f(s).iter().copied())).unwrap_or((0.0, 1.0));
    let ((x0, x1), (y0, y1)) = (ext(|s| &s.x), ext(|s| &s.y));
    Ok(axis::equal_ranges([x0, x1, y0, y1], (xr.end - xr.start) as f64, (yr.end - yr.start) as f64, spec.view))
}

fn draw(root: &DrawingArea<CanvasBackend, Shift>, spec: &Spec) -> Result<Layout, Box<dyn std::error::Error>> {
    root.fill(&WHITE)?;
    let dpr = spec.dpr.clamp(0.5, 4.0);
    let px = |v: f64| (v * dpr).round() as i32;
    let (w, _h) = root.dim_in_pixel();
    let columns = (w as usize).max(1);
    let (title, title_px) = fit_caption(root, &spec.title, w.saturating_sub(px(24.0).max(0) as u32), px(15.0), px(11.0));
    let equal = if spec.equal_axes { Some(equal_ranges(root, spec, &title, title_px)?) } else { None };
    let (x0, x1, y0, y1, decimated) = ranges(spec, columns, equal);
    // A time axis is drawn in its unit, so ticks fall on round minutes or hours.
    let unit = spec.time_x.then(|| axis::time_unit(x1 - x0));
    let per = unit.map_or(1.0, |u| u.seconds);
    let x_desc = match unit {
        Some(u) => format!("{} ({})", spec.x_label, u.name),
        None => spec.x_label.clone(),
    };
    let origin = if unit.is_some() { spec.x_origin } else { 0.0 };
    let sc = Scale { log_x: spec.log_x, log_y: spec.log_y, per, origin };
    let (cx0, cx1, cy0, cy1) = (sc.tx(x0), sc.tx(x1), sc.ty(y0), sc.ty(y1));
    let font = ("sans-serif", px(13.0)).into_font();
    // Ticks at round values (core's axis): 1-2-5 steps on a linear axis, whole decades on a
    // log one (drawn linear in log10).
    let tick = |log: bool, a: f64, b: f64| if log { axis::log_ticks(a, b, 12) } else { axis::ticks(a, b, 10) };
    let (x_ticks, y_ticks) = (tick(spec.log_x, cx0, cx1), tick(spec.log_y, cy0, cy1));
    let mut chart = frame(root, &title, title_px, dpr)
        .build_cartesian_2d(Ticked { range: cx0..cx1, ticks: x_ticks.clone() }, Ticked { range: cy0..cy1, ticks: y_ticks.clone() })?;
    let fmt_x = |v: &f64| if spec.log_x { plain(10f64.powf(*v)) } else { plain(*v) };
    let fmt_y = |v: &f64| if spec.log_y { format!("{:.1e}", 10f64.powf(*v)) } else { plain(*v) };
    chart
        .configure_mesh()
        .x_desc(&x_desc)
        .y_desc(&spec.y_label)
        .label_style(font.clone())
        .axis_desc_style(font.clone())
        .x_label_formatter(&fmt_x)
        .y_label_formatter(&fmt_y)
        .light_line_style(RGBColor(242, 242, 242))
        .draw()?;
    if let Some(sh) = &spec.shade {
        draw_shade(&mut chart, sh, sc, (x0, x1), (cy0, cy1), columns)?;
    }
    for (s, dx, dy) in &decimated {
        draw_line(&mut chart, s, (dx, dy), sc, ((cx0, cx1), (cy0, cy1)), px)?;
    }
    if let Some(c) = spec.cursor_x {
        if c >= x0 && c <= x1 {
            chart.draw_series(LineSeries::new(vec![(sc.tx(c), cy0), (sc.tx(c), cy1)], RGBColor(120, 120, 120)))?;
        }
    }
    if spec.legend {
        chart
            .configure_series_labels()
            .label_font(font)
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(200, 200, 200))
            .position(SeriesLabelPosition::UpperLeft)
            .draw()?;
    }
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    Ok(Layout {
        left: xr.start,
        right: xr.end,
        top: yr.start,
        bottom: yr.end,
        x_min: x0,
        x_max: x1,
        y_min: y0,
        y_max: y1,
        x_unit: unit.map_or("", |u| u.name),
        x_unit_s: per,
        x_origin: origin,
        x_ticks: x_ticks.iter().map(|&v| if spec.log_x { 10f64.powf(v) } else { v }).collect(),
        y_ticks: y_ticks.iter().map(|&v| if spec.log_y { 10f64.powf(v) } else { v }).collect(),
    })
}
