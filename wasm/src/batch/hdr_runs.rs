//! HDR over a parsed log: the Result keys, its per-sample series reduced for a chart, the
//! dead-reckoned tracks and the trace CSV.

use super::*;

/// HDR on a log: the Result keys of methods.md. Throws when the log has no usable reference.
#[wasm_bindgen(unchecked_return_type = "HdrResult")]
pub fn hdr(log: &Log, #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: HdrOptions = self::options("hdr", options)?;
    let run = hdr::run(&log.log, &opts).map_err(err)?;
    to_js(&run.result.map_err(err)?)
}

/// Prepares HDR's samples and reference for these options and caches them on the log, so a
/// page can spend that time (O(rows)) in a task of its own before the first `runHdr`.
#[wasm_bindgen(js_name = prepareHdr)]
pub fn prepare_hdr(log: &Log, #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue) -> JsResult<()> {
    let opts: HdrOptions = self::options("hdr", options)?;
    log.hdr_prepared(&opts).map(|_| ()).map_err(err)
}

/// The series the dashboard's HDR view draws: a view's reduction keeps their shapes.
const HDR_DRAWN: [&str; 5] = ["heading_raw_deg", "heading_hdr_deg", "rate_corrected_dps", "drift_estimate_dps", "turn_switch"];

/// HDR with its per-sample series (Float64Array) for plotting: `{ result, error, eps0_dps, trace }`;
/// `result` is null and `error` says why when the log has no usable reference.
#[wasm_bindgen(js_name = runHdr, unchecked_return_type = "HdrRun")]
pub fn run_hdr(
    log: &Log,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "ChartView")] view: Option<JsValue>,
) -> JsResult<JsValue> {
    let opts: HdrOptions = self::options("hdr", options)?;
    let view = View::read(&view.unwrap_or(JsValue::UNDEFINED))?;
    let prepared = log.hdr_prepared(&opts).map_err(err)?;
    let run = hdr::run_prepared(&log.log, &prepared, &opts).map_err(err)?;
    let out = run_object(&run.result, run.eps0_dps)?;
    let t = &run.trace;
    let cols = t.columns();
    // With a view, every series keeps only the samples that draw the same (metrics are
    // computed on all of them first): those of the series the HDR view draws.
    let idx = view.as_ref().map(|v| {
        let drawn: Vec<_> = cols.iter().filter(|(n, _)| HDR_DRAWN.contains(n)).map(|(_, c)| c.to_f64s()).collect();
        v.indices(&t.time_s, &drawn.iter().map(|c| &**c).collect::<Vec<_>>())
    });
    let trace = columns_object(&cols, idx.as_deref())?;
    set(&out, "trace", &trace)?;
    let against = prepared.reference.as_ref().ok().and_then(|rf| Some((rf, run.errors_against(rf)?)));
    let (reference, errors) = match against {
        Some((rf, e)) => {
            let ri = view.as_ref().map(|v| v.indices(&rf.time_s, &[&rf.heading_deg]));
            let ei = view.as_ref().map(|v| v.indices(&e.time_s, &[&e.errors_deg[0], &e.errors_deg[1]]));
            let reference =
                object_of(&[("time_s", reduced(ri.as_deref(), &rf.time_s)), ("heading_deg", reduced(ri.as_deref(), &rf.heading_deg))])?;
            let errors = object_of(&[
                ("time_s", reduced(ei.as_deref(), &e.time_s)),
                ("raw_deg", reduced(ei.as_deref(), &e.errors_deg[0])),
                ("hdr_deg", reduced(ei.as_deref(), &e.errors_deg[1])),
            ])?;
            (reference.into(), errors.into())
        }
        None => (JsValue::NULL, JsValue::NULL),
    };
    set(&out, "reference", &reference)?;
    set(&out, "errors", &errors)?;
    Ok(out.into())
}

/// Resolution the Track view's paths are reduced to (pixels across the larger extent), and
/// the most points a path keeps (a 60 h drive's path is coarser than half a pixel).
const TRACK_COLUMNS: usize = 4000;
const TRACK_MAX_POINTS: usize = 50_000;

/// Dead-reckoned paths (m) of a drive with speed: along the raw, HDR and reference headings.
/// `{ raw: {x_m, y_m}, hdr: {...}, reference: {...} | null }` as Float64Array, reduced for
/// drawing to points at least 1/8000 of the path's extent apart, at most 50 000 per path
/// (core's `Path::for_drawing`).
#[wasm_bindgen(unchecked_return_type = "Tracks")]
pub fn track(log: &Log, #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: HdrOptions = self::options("track", options)?;
    let run = hdr::run(&log.log, &opts).map_err(err)?;
    let t = &run.trace;
    let out = Object::new();
    set(&out, "raw", &drawn_path(&log.log, &t.time_s, &t.heading_raw_deg)?)?;
    set(&out, "hdr", &drawn_path(&log.log, &t.time_s, &t.heading_hdr_deg)?)?;
    let reference = match gyrodrift::track::reference_path(&log.log) {
        Ok(p) => path_object(p)?,
        Err(_) => JsValue::NULL,
    };
    set(&out, "reference", &reference)?;
    Ok(out.into())
}

/// The log's speed integrated along a heading trace, reduced for drawing.
pub(crate) fn drawn_path(log: &DriveLog, time_s: &[f64], heading_deg: &[f64]) -> JsResult<JsValue> {
    path_object(gyrodrift::track::dead_reckon(log, time_s, heading_deg).map_err(err)?)
}

fn path_object(p: gyrodrift::track::Path) -> JsResult<JsValue> {
    let p = p.for_drawing(TRACK_COLUMNS, TRACK_MAX_POINTS);
    Ok(object_of(&[("x_m", f64s(&p.x_m)), ("y_m", f64s(&p.y_m))])?.into())
}

/// The per-sample heading trace CSV of methods.md (time_s, heading_raw_deg, heading_hdr_deg).
#[wasm_bindgen(js_name = hdrTraceCsv)]
pub fn hdr_trace_csv(log: &Log, #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue) -> JsResult<String> {
    let opts: HdrOptions = self::options("hdr", options)?;
    let run = hdr::run(&log.log, &opts).map_err(err)?;
    let mut buf = Vec::new();
    run.trace.write_csv(&mut buf).map_err(err)?;
    String::from_utf8(buf).map_err(err)
}
