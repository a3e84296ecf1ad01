//! The chart spec the page hands over (title, axis labels, ranges, series as
//! Float64Array, an optional shaded interval and cursor), read from the JS object.

use super::js_err;
use js_sys::{Array, Float64Array, Reflect};
use wasm_bindgen::prelude::*;

pub(super) struct Series {
    pub(super) name: String,
    pub(super) color: String,
    pub(super) x: Vec<f64>,
    pub(super) y: Vec<f64>,
    pub(super) width: Option<u32>,
    /// Draw markers instead of a line (e.g. the 1 Hz GPS reference, Allan points).
    pub(super) points: bool,
    /// A path not ordered in x (a track): drawn as given, not decimated by x.
    pub(super) path: bool,
}

pub(super) struct Shade {
    pub(super) x: Vec<f64>,
    pub(super) mask: Vec<f64>,
    pub(super) color: String,
    pub(super) label: String,
}

pub(super) struct Spec {
    pub(super) title: String,
    pub(super) x_label: String,
    pub(super) y_label: String,
    pub(super) x_range: Option<[f64; 2]>,
    pub(super) y_range: Option<[f64; 2]>,
    pub(super) log_x: bool,
    pub(super) log_y: bool,
    /// The x axis is time in seconds: drawn in s, min or h by the span shown (core's
    /// `axis::time_unit`), labelled "<x_label> (<unit>)".
    pub(super) time_x: bool,
    /// A time axis counts from this time, s (the log's first row: an epoch-stamped log's
    /// axis reads minutes since its start, not since 1970). Default 0.
    pub(super) x_origin: f64,
    pub(super) series: Vec<Series>,
    pub(super) shade: Option<Shade>,
    pub(super) cursor_x: Option<f64>,
    /// Device pixel ratio (fonts and lines scale with it).
    pub(super) dpr: f64,
    /// Draw the legend inside the plot (default); a page with its own legend turns it off.
    pub(super) legend: bool,
    /// Equal axes (a track): one unit as long across as up, fitting the data or `view`.
    pub(super) equal_axes: bool,
    /// With equal axes: the centre and units per canvas pixel of a zoomed or panned view.
    pub(super) view: Option<[f64; 3]>,
}

// The spec is read with Reflect rather than serde: typed arrays copy straight into Vec<f64>
// and the package stays inside its size budget.
fn prop(obj: &JsValue, key: &str) -> JsValue {
    Reflect::get(obj, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
}
fn text(obj: &JsValue, key: &str) -> String {
    prop(obj, key).as_string().unwrap_or_default()
}
fn flag(obj: &JsValue, key: &str) -> bool {
    prop(obj, key).as_bool().unwrap_or(false)
}
fn number(obj: &JsValue, key: &str) -> Option<f64> {
    prop(obj, key).as_f64()
}
fn numbers(obj: &JsValue, key: &str) -> Result<Vec<f64>, JsValue> {
    let v = prop(obj, key);
    if let Some(a) = v.dyn_ref::<Float64Array>() {
        return Ok(a.to_vec());
    }
    if v.is_object() {
        // Arrays and other typed arrays: through Float64Array.from.
        return Ok(Float64Array::new(&v).to_vec());
    }
    Err(js_err(format!("chart spec: {key} must be an array of numbers")))
}
/// `len` numbers, or none when the key is absent, null or of another length.
fn range(obj: &JsValue, key: &str, len: usize) -> Result<Vec<f64>, JsValue> {
    let v = prop(obj, key);
    if v.is_undefined() || v.is_null() {
        return Ok(Vec::new());
    }
    let r = numbers(obj, key)?;
    Ok(if r.len() == len { r } else { Vec::new() })
}

fn pair(r: Vec<f64>) -> Option<[f64; 2]> {
    match r[..] {
        [a, b] => Some([a, b]),
        _ => None,
    }
}

impl Spec {
    pub(super) fn read(v: &JsValue) -> Result<Spec, JsValue> {
        if !v.is_object() {
            return Err(js_err("chart spec: expected an object"));
        }
        let arr: Array = prop(v, "series").dyn_into().map_err(|_| js_err("chart spec: series must be an array"))?;
        let mut series = Vec::with_capacity(arr.length() as usize);
        for s in arr.iter() {
            series.push(Series {
                name: text(&s, "name"),
                color: text(&s, "color"),
                x: numbers(&s, "x")?,
                y: numbers(&s, "y")?,
                width: number(&s, "width").map(|w| w.clamp(1.0, 20.0) as u32),
                points: flag(&s, "points"),
                path: flag(&s, "path"),
            });
        }
        let sh = prop(v, "shade");
        let shade = if sh.is_object() {
            Some(Shade { x: numbers(&sh, "x")?, mask: numbers(&sh, "mask")?, color: text(&sh, "color"), label: text(&sh, "label") })
        } else {
            None
        };
        Ok(Spec {
            title: text(v, "title"),
            x_label: text(v, "x_label"),
            y_label: text(v, "y_label"),
            x_range: pair(range(v, "x_range", 2)?),
            y_range: pair(range(v, "y_range", 2)?),
            log_x: flag(v, "log_x"),
            log_y: flag(v, "log_y"),
            time_x: flag(v, "time_x"),
            x_origin: number(v, "x_origin").filter(|o| o.is_finite()).unwrap_or(0.0),
            series,
            shade,
            cursor_x: number(v, "cursor_x"),
            dpr: number(v, "dpr").unwrap_or(1.0),
            legend: prop(v, "legend").as_bool().unwrap_or(true),
            equal_axes: flag(v, "equal_axes"),
            view: match range(v, "view", 3)?[..] {
                [xc, yc, per_px] => Some([xc, yc, per_px]),
                _ => None,
            },
        })
    }
}
