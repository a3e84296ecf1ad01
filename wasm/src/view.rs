//! What a page draws: a time window and its width in pixels. Series given a view keep only
//! the samples that draw the same (core's `decimate::shared_indices`), so a 2 M-row log
//! crosses into JavaScript and the plot module as a few thousand points.

use crate::convert::*;
use crate::log::Log;
use crate::JsResult;
use js_sys::Object;
use wasm_bindgen::prelude::*;

/// What a page draws: a time window (or all) and its width in pixel columns.
pub(crate) struct View {
    x_range: Option<[f64; 2]>,
    columns: usize,
}

impl View {
    pub(crate) fn read(v: &JsValue) -> JsResult<Option<View>> {
        if v.is_undefined() || v.is_null() {
            return Ok(None);
        }
        let columns = js_sys::Reflect::get(v, &"columns".into())?.as_f64().filter(|c| c.is_finite() && *c >= 1.0 && *c <= 100_000.0);
        let columns = columns.ok_or_else(|| err("view.columns must be a number of pixel columns, 1 to 100000"))? as usize;
        let r = js_sys::Reflect::get(v, &"x_range".into())?;
        let x_range = if r.is_undefined() || r.is_null() {
            None
        } else {
            let a = js_sys::Float64Array::new(&r).to_vec();
            match a[..] {
                [lo, hi] if lo.is_finite() && hi.is_finite() && hi > lo => Some([lo, hi]),
                _ => return Err(err("view.x_range must be [from, to] with from < to")),
            }
        };
        Ok(Some(View { x_range, columns }))
    }

    /// The samples to keep of series sharing `x` (core's `decimate::shared_indices`).
    pub(crate) fn indices(&self, x: &[f64], ys: &[&[f64]]) -> Vec<usize> {
        let [x0, x1] = self.x_range.unwrap_or_else(|| [x.first().copied().unwrap_or(0.0), x.last().copied().unwrap_or(0.0)]);
        if x1.partial_cmp(&x0) != Some(std::cmp::Ordering::Greater) {
            return (0..x.len()).collect();
        }
        gyrodrift::decimate::shared_indices(x, ys, x0, x1, self.columns)
    }
}

pub(crate) fn reduced(idx: Option<&[usize]>, v: &[f64]) -> JsValue {
    match idx {
        Some(i) => f64s(&gyrodrift::decimate::take(v, i)),
        None => f64s(v),
    }
}

/// A core trace's `columns()` as a JS object: Float64Array values, Uint8Array flags, each
/// reduced to the samples `idx` keeps when given (a chart's view).
pub(crate) fn columns_object(cols: &[(&str, gyrodrift::series::Column<'_>)], idx: Option<&[usize]>) -> JsResult<Object> {
    use gyrodrift::series::Column;
    let out = Object::new();
    for (name, c) in cols {
        let v = match (c, idx) {
            (Column::Values(v), _) => reduced(idx, v),
            (Column::Flags(f), Some(i)) => bools(&i.iter().map(|&k| f[k]).collect::<Vec<_>>()),
            (Column::Flags(f), None) => bools(f),
        };
        set(&out, name, &v)?;
    }
    Ok(out)
}

/// Series sharing one x reduced for drawing in a view: `{ x, ys }` holding, per pixel
/// column, the first and last sample and each series' extremes (core's
/// `decimate::shared_indices`), so a page re-draws a cached 2 M-sample trace cheaply.
#[wasm_bindgen(js_name = reduceSeries, unchecked_return_type = "{ x: Float64Array; ys: Float64Array[] }")]
pub fn reduce_series(
    x: &[f64],
    #[wasm_bindgen(unchecked_param_type = "ArrayLike<number>[]")] ys: JsValue,
    #[wasm_bindgen(unchecked_param_type = "ChartView")] view: JsValue,
) -> JsResult<JsValue> {
    let view = View::read(&view)?.ok_or_else(|| err("reduceSeries needs a view { x_range?, columns }"))?;
    let arr: js_sys::Array = ys.dyn_into().map_err(|_| err("ys must be an array of series"))?;
    let cols: Vec<Vec<f64>> = arr.iter().map(|y| js_sys::Float64Array::new(&y).to_vec()).collect();
    let refs: Vec<&[f64]> = cols.iter().map(|c| c.as_slice()).collect();
    reduced_group(&view, x, &refs)
}

/// `{ x, ys }`: the series kept for the view.
fn reduced_group(view: &View, x: &[f64], ys: &[&[f64]]) -> JsResult<JsValue> {
    let idx = view.indices(x, ys);
    let out = Object::new();
    set(&out, "x", &reduced(Some(&idx), x))?;
    let list = js_sys::Array::new();
    for c in ys {
        list.push(&reduced(Some(&idx), c));
    }
    set(&out, "ys", &list)?;
    Ok(out.into())
}

#[wasm_bindgen]
impl Log {
    /// Columns of this log on its time axis reduced for a view, as `reduceSeries(time_s,
    /// columns, view)` gives them, without copying whole columns out of the module.
    #[wasm_bindgen(js_name = reduceColumns, unchecked_return_type = "{ x: Float64Array; ys: Float64Array[] }")]
    pub fn reduce_columns(
        &self,
        #[wasm_bindgen(unchecked_param_type = "string[]")] names: JsValue,
        #[wasm_bindgen(unchecked_param_type = "ChartView")] view: JsValue,
    ) -> JsResult<JsValue> {
        let view = View::read(&view)?.ok_or_else(|| err("reduceColumns needs a view { x_range?, columns }"))?;
        let arr: js_sys::Array = names.dyn_into().map_err(|_| type_err("Log.reduceColumns(names): expected an array of column names"))?;
        let mut cols = Vec::new();
        for n in arr.iter() {
            let name = js_string(&n, "Log.reduceColumns(names)")?;
            let c = gyrodrift::Column::from_name(&name).ok_or_else(|| err(format!("unknown column {name}")))?;
            cols.push(self.log.require(c, "not in this log").map_err(err)?);
        }
        reduced_group(&view, self.log.time_s(), &cols)
    }
}
