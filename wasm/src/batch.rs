//! Batch methods over a parsed log: HDR, Gyrodometry, calibration, Allan, report, tune,
//! simulate, the pipeline and the comparison.

use crate::convert::*;
use crate::log::Log;
use crate::view::{reduced, View};
use crate::JsResult;
use gyrodrift::hdr::{self, HdrOptions, HdrParams};
use gyrodrift::{allan, calibration, gyrodometry, report, sim, tune, DriveLog};
use js_sys::Object;
use serde::Serialize;
use std::rc::Rc;
use wasm_bindgen::prelude::*;

/// `{ result, error }` of a batch run: the Result keys, or why there are none.
fn result_object<T: Serialize>(result: &gyrodrift::Result<T>) -> JsResult<Object> {
    let out = Object::new();
    let (r, e) = match result {
        Ok(r) => (to_js(r)?, JsValue::NULL),
        Err(e) => (JsValue::NULL, JsValue::from_str(&e.to_string())),
    };
    set(&out, "result", &r)?;
    set(&out, "error", &e)?;
    Ok(out)
}

/// `{ result, error, eps0_dps }` of a batch run with a static bias.
fn run_object<T: Serialize>(result: &gyrodrift::Result<T>, eps0_dps: f64) -> JsResult<Object> {
    let out = result_object(result)?;
    set(&out, "eps0_dps", &JsValue::from_f64(eps0_dps))?;
    Ok(out)
}

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
    let drift = t.drift_estimate_dps();
    let switch: Vec<f64> = t.turn_switch.iter().map(|&b| b as u8 as f64).collect();
    // With a view, every series keeps only the samples that draw the same (metrics are
    // computed on all of them first).
    let idx =
        view.as_ref().map(|v| v.indices(&t.time_s, &[&t.heading_raw_deg, &t.heading_hdr_deg, &t.rate_corrected_dps, &drift, &switch]));
    let r = |v: &[f64]| reduced(idx.as_deref(), v);
    let trace = object_of(&[
        ("time_s", r(&t.time_s)),
        ("heading_raw_deg", r(&t.heading_raw_deg)),
        ("heading_hdr_deg", r(&t.heading_hdr_deg)),
        ("rate_raw_dps", r(&t.rate_raw_dps)),
        ("rate_corrected_dps", r(&t.rate_corrected_dps)),
        ("i_dps", r(&t.i_dps)),
        ("drift_estimate_dps", r(&drift)),
        (
            "turn_switch",
            match &idx {
                Some(i) => bools(&i.iter().map(|&k| t.turn_switch[k]).collect::<Vec<_>>()),
                None => bools(&t.turn_switch),
            },
        ),
        ("attenuation", r(&t.attenuation)),
    ])?;
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
    let path = |p: gyrodrift::track::Path| -> JsResult<JsValue> {
        let p = p.for_drawing(TRACK_COLUMNS, TRACK_MAX_POINTS);
        let o = Object::new();
        set(&o, "x_m", &f64s(&p.x_m))?;
        set(&o, "y_m", &f64s(&p.y_m))?;
        Ok(o.into())
    };
    let out = Object::new();
    set(&out, "raw", &path(gyrodrift::track::dead_reckon(&log.log, &t.time_s, &t.heading_raw_deg).map_err(err)?)?)?;
    set(&out, "hdr", &path(gyrodrift::track::dead_reckon(&log.log, &t.time_s, &t.heading_hdr_deg).map_err(err)?)?)?;
    let reference = match gyrodrift::track::reference_path(&log.log) {
        Ok(p) => path(p)?,
        Err(_) => JsValue::NULL,
    };
    set(&out, "reference", &reference)?;
    Ok(out.into())
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

/// Gyrodometry on a robot log: the Result keys of methods.md.
#[wasm_bindgen(unchecked_return_type = "GyrodometryResult")]
pub fn gyrodometry(log: &Log, #[wasm_bindgen(unchecked_param_type = "GyrodometryOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: gyrodometry::GyrodometryOptions = self::options("gyrodometry", options)?;
    let run = gyrodometry::run(&log.log, &opts).map_err(err)?;
    to_js(&run.result.map_err(err)?)
}

/// Gyrodometry with its series: `{ result, error, eps0_dps, trace }`.
#[wasm_bindgen(js_name = runGyrodometry, unchecked_return_type = "GyrodometryRun")]
pub fn run_gyrodometry(log: &Log, #[wasm_bindgen(unchecked_param_type = "GyrodometryOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: gyrodometry::GyrodometryOptions = self::options("gyrodometry", options)?;
    let run = gyrodometry::run(&log.log, &opts).map_err(err)?;
    let out = run_object(&run.result, run.eps0_dps)?;
    let t = &run.trace;
    let trace = object_of(&[
        ("time_s", f64s(&t.time_s)),
        ("heading_odo_deg", f64s(&t.heading_odo_deg)),
        ("heading_gyro_deg", f64s(&t.heading_gyro_deg)),
        ("heading_gyrodometry_deg", f64s(&t.heading_gyrodometry_deg)),
        ("used_gyro", bools(&t.used_gyro)),
    ])?;
    set(&out, "trace", &trace)?;
    Ok(out.into())
}

/// Calibration of a turntable session: the Result keys plus the per-set table `sets`.
#[wasm_bindgen(unchecked_return_type = "CalibrationRun")]
pub fn calibrate(log: &Log, #[wasm_bindgen(unchecked_param_type = "CalibrationOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: calibration::CalibrationOptions = self::options("calibrate", options)?;
    let run = calibration::run(&log.log, &opts).map_err(err)?;
    let out: JsValue = to_js(&run.result)?;
    let obj: &Object = out.unchecked_ref();
    set(obj, "sets", &to_js(&run.sets)?)?;
    Ok(out)
}

/// Overlapping Allan deviation of the log's gyro column (the Result keys; arrays as
/// Float64Array), with each point's 68 % band under `confidence` (beyond methods.md).
#[wasm_bindgen(unchecked_return_type = "AllanResult")]
pub fn allan(log: &Log) -> JsResult<JsValue> {
    let (r, c) = allan::run_with_confidence(&log.log).map_err(err)?;
    let out: JsValue = to_js(&r)?;
    let obj: &Object = out.unchecked_ref();
    set(obj, "tau_s", &f64s(&r.tau_s))?;
    set(obj, "adev_dps", &f64s(&r.adev_dps))?;
    let conf: JsValue = to_js(&c)?;
    let cobj: &Object = conf.unchecked_ref();
    set(cobj, "adev_low_dps", &f64s(&c.adev_low_dps))?;
    set(cobj, "adev_high_dps", &f64s(&c.adev_high_dps))?;
    set(obj, "confidence", &conf)?;
    set(obj, "arw_line_dps", &f64s(&allan::arw_line_dps(r.arw_deg_per_sqrt_s, &r.tau_s)))?;
    Ok(out)
}

/// The HDR paper's Table II over many logs (named by their `name`).
#[wasm_bindgen(unchecked_return_type = "Report")]
pub fn report(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
) -> JsResult<JsValue> {
    to_js(&build_report(&logs, options)?)
}

/// Table II over a JS array of logs with HDR options (shared by `report` and `reportMarkdown`).
fn build_report(logs: &JsValue, options: JsValue) -> JsResult<report::Report> {
    let opts: HdrOptions = self::options("report", options)?;
    let logs = Log::from_array(logs, "logs")?;
    let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), &**l)).collect();
    report::Report::build(&named, &opts).map_err(err)
}

/// The report as Markdown (the CLI's `report --markdown`).
#[wasm_bindgen(js_name = reportMarkdown)]
pub fn report_markdown(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
) -> JsResult<String> {
    Ok(build_report(&logs, options)?.to_markdown())
}

/// The report as CSV (one row per drive, then the average).
#[wasm_bindgen(js_name = reportCsv)]
pub fn report_csv(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
) -> JsResult<String> {
    Ok(build_report(&logs, options)?.to_csv())
}

/// Tunes the five HDR parameters on `train` and reports Table III vs tuned on both sets.
/// `progress(fraction)`, if given, is called as the search goes (e.g. from a Web Worker).
#[cfg(feature = "tune")]
#[wasm_bindgen(unchecked_return_type = "TuneReport")]
pub fn tune(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] train: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Log[] | undefined")] test: JsValue,
    #[wasm_bindgen(unchecked_param_type = "TuneOptions")] options: JsValue,
    progress: Option<js_sys::Function>,
) -> JsResult<JsValue> {
    let opts: tune::TuneOptions = self::options("tune", options)?;
    let hdr_opts = HdrOptions::default();
    let prep = |v: Vec<(String, Rc<DriveLog>)>| -> JsResult<Vec<tune::PreparedDrive>> {
        let named: Vec<(String, &DriveLog)> = v.iter().map(|(n, l)| (n.clone(), &**l)).collect();
        tune::prepare_all(&named, &hdr_opts).map_err(err)
    };
    let train = prep(Log::from_array(&train, "train")?)?;
    let test = prep(Log::from_array(&test, "test")?)?;
    let expected = tune::expected_evaluations_for(&opts, train.len()).max(1) as f64;
    let report = |n: u64| {
        if let Some(f) = &progress {
            let _ = f.call1(&JsValue::NULL, &JsValue::from_f64((n as f64 / expected).min(1.0)));
        }
    };
    to_js(&tune::tune_and_report_with_progress(&train, &test, &opts, &report).map_err(err)?)
}

/// Simulates a log with known truth (the CLI's `simulate`); the same seed gives the same
/// log as the native CLI.
#[cfg(feature = "sim")]
#[wasm_bindgen]
pub fn simulate(#[wasm_bindgen(unchecked_param_type = "SimRequest")] request: JsValue) -> JsResult<Log> {
    let req: sim::SimRequest = self::options("simulate", request)?;
    sim::simulate(&req).map(Log::new).map_err(err)
}

/// What a log looks like before any method runs (the CLI's `check`): rate, gaps, units and
/// sign against the reference, bias, outliers; each finding with its fix.
#[wasm_bindgen(js_name = checkLog, unchecked_return_type = "CheckReport")]
pub fn check_log(log: &Log) -> JsResult<JsValue> {
    to_js(&gyrodrift::check::check(&log.log))
}

/// Runs `$body` with `$T` the settings type of the method named `$method`, or gives the
/// unknown-method error: the one list of methods with settings.
macro_rules! with_settings {
    ($what:literal, $method:expr, |$T:ident| $body:expr) => {
        match $method {
            "hdr" => {
                type $T = HdrOptions;
                $body
            }
            "pipeline" => {
                type $T = gyrodrift::pipeline::PipelineParams;
                $body
            }
            "gyrodometry" => {
                type $T = gyrodometry::GyrodometryOptions;
                $body
            }
            "calibration" => {
                type $T = calibration::CalibrationOptions;
                $body
            }
            "tune" => {
                type $T = tune::TuneOptions;
                $body
            }
            other => Err(err(format!(concat!($what, ": unknown method \"{}\" (hdr, pipeline, gyrodometry, calibration, tune)"), other))),
        }
    };
}

/// The default settings of a method, as core has them: "hdr", "pipeline", "gyrodometry",
/// "calibration" or "tune"; `bias_s` (null) falls back to the log's or `defaultBiasS`.
#[wasm_bindgen(unchecked_return_type = "any")]
pub fn defaults(#[wasm_bindgen(unchecked_param_type = "string")] method: JsValue) -> JsResult<JsValue> {
    with_settings!("defaults", js_string(&method, "defaults(method)")?.as_str(), |T| to_js(&T::default()))
}

/// Checks settings for a method ("hdr", "pipeline", "gyrodometry", "calibration", "tune")
/// by core's schema and ranges without running anything: the message naming the field
/// and its range, or null when they are valid. For forms that refuse a bad value in place.
#[wasm_bindgen(js_name = checkOptions)]
pub fn check_options(
    #[wasm_bindgen(unchecked_param_type = "string")] method: JsValue,
    #[wasm_bindgen(unchecked_param_type = "object")] settings: JsValue,
) -> JsResult<Option<String>> {
    let method = js_string(&method, "checkOptions(method)")?;
    // An unknown method throws; a bad setting is the answer.
    let refused: Option<JsValue> = with_settings!("checkOptions", method.as_str(), |T| Ok(options::<T>(&method, settings).err()))?;
    Ok(refused.map(|e| e.dyn_into::<js_sys::Error>().map(|e| String::from(e.message())).unwrap_or_else(|v| format!("{v:?}"))))
}

/// The package's version (the core's), for exports that say what made them.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The static-bias window used when neither the options nor the log give one, s.
#[wasm_bindgen(js_name = defaultBiasS)]
pub fn default_bias_s() -> f64 {
    gyrodrift::log::DEFAULT_BIAS_S
}

/// Table III of the HDR paper (the defaults).
#[wasm_bindgen(js_name = tableIII, unchecked_return_type = "HdrParams")]
pub fn table_iii() -> JsResult<JsValue> {
    to_js(&HdrParams::table_iii())
}

/// Static bias eps0 of a log over its first `bias_s` seconds (the log's own, or 20 s).
#[wasm_bindgen(js_name = staticBias)]
pub fn static_bias(log: &Log, bias_s: Option<f64>) -> JsResult<f64> {
    let gyro = log.log.require(gyrodrift::Column::GyroDps, "needed for the static bias").map_err(err)?;
    gyrodrift::preprocess::static_bias_dps(log.log.time_s(), gyro, log.log.bias_s(bias_s)).map_err(err)
}

/// The recommended drift-reduction pipeline with raw, Table-III HDR and the two peers:
/// the pipeline Result keys. Throws when the log has no usable reference.
#[wasm_bindgen(unchecked_return_type = "PipelineResult")]
pub fn pipeline(log: &Log, #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue) -> JsResult<JsValue> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let run = gyrodrift::pipeline::run(&log.log, &p).map_err(err)?;
    to_js(&run.result.map_err(err)?)
}

/// The pipeline with its per-block series: `{ result, error, still_source, trace }`.
#[wasm_bindgen(js_name = runPipeline, unchecked_return_type = "PipelineRun")]
pub fn run_pipeline(log: &Log, #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue) -> JsResult<JsValue> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let run = gyrodrift::pipeline::run(&log.log, &p).map_err(err)?;
    let out = result_object(&run.result)?;
    set(&out, "still_source", &to_js(&run.still_source)?)?;
    let t = &run.trace;
    let trace = object_of(&[
        ("time_s", f64s(&t.time_s)),
        ("heading_deg", f64s(&t.heading_deg)),
        ("heading_smoothed_deg", f64s(&t.heading_smoothed_deg)),
        ("bias_dps", f64s(&t.bias_dps)),
        ("bias_sigma_dps", f64s(&t.bias_sigma_dps)),
        ("bias_smoothed_dps", f64s(&t.bias_smoothed_dps)),
        ("stop", bools(&t.stop)),
    ])?;
    set(&out, "trace", &trace)?;
    let errors = match run.errors(&log.log) {
        Some(e) => series(&[("time_s", &e.time_s), ("pipeline_deg", &e.errors_deg[0]), ("smoothed_deg", &e.errors_deg[1])])?.into(),
        None => JsValue::NULL,
    };
    set(&out, "errors", &errors)?;
    Ok(out.into())
}

/// Every method side by side (NE_psi per drive): raw, Table-III HDR, the pipeline, peers.
#[wasm_bindgen(unchecked_return_type = "Compare")]
pub fn compare(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue,
) -> JsResult<JsValue> {
    to_js(&build_compare(&logs, options)?)
}

fn build_compare(logs: &JsValue, options: JsValue) -> JsResult<gyrodrift::compare::Compare> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let logs = Log::from_array(logs, "logs")?;
    let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), l.as_ref())).collect();
    gyrodrift::compare::compare(&named, &p, None).map_err(err)
}

/// The comparison as a table: "markdown" (the CLI's `report --compare`) or "csv".
#[wasm_bindgen(js_name = compareTable)]
pub fn compare_table(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue,
    #[wasm_bindgen(unchecked_param_type = "\"markdown\" | \"csv\"")] format: JsValue,
) -> JsResult<String> {
    let format = js_string(&format, "compareTable(format)")?;
    let c = build_compare(&logs, options)?;
    match format.as_str() {
        "markdown" => Ok(c.to_markdown()),
        "csv" => Ok(c.to_csv()),
        other => Err(err(format!("compareTable: format \"{other}\" is not markdown or csv"))),
    }
}

/// The value of a series at time t, linearly interpolated (core's rule), NaN outside.
#[wasm_bindgen(js_name = valueAt)]
pub fn value_at(x: &[f64], y: &[f64], t: f64) -> f64 {
    gyrodrift::metrics::value_at(x, y, t)
}

/// Whether a file (its first bytes suffice) is a drive log v1 already, not a raw export.
#[wasm_bindgen(js_name = isDriveLog)]
pub fn is_drive_log(name: &str, head: &[u8]) -> bool {
    gyrodrift::import::sniff(name, head).is_ok_and(|s| s.is_drive_log())
}

/// A raw file's dialect and header from its first bytes (`{ name, delimiter, decimal_comma,
/// skip_lines, header }`), for a page that maps columns by hand; throws for a binary file.
#[wasm_bindgen(js_name = sniffFile, unchecked_return_type = "Sniffed")]
pub fn sniff_file(name: &str, head: &[u8]) -> JsResult<JsValue> {
    to_js(&gyrodrift::import::sniff(name, head).map_err(err)?)
}
