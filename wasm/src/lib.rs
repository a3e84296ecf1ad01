//! WebAssembly bindings of gyrodrift. Thin: they translate types (option objects in,
//! plain result objects and Float64Array series out) and errors (every core error becomes a
//! thrown JS `Error` with the same message the CLI prints). No science here, and no panic:
//! every fallible call returns `Result`.

use gyrodrift::hdr::{self, Hdr, HdrOptions, HdrParams};
use gyrodrift::{allan, calibration, gyrodometry, report, sim, tune, DriveLog};
use js_sys::{Array, Float64Array, Object, Reflect, Uint8Array};
use serde::Serialize;
use std::cell::{Cell, RefCell};
use std::rc::Rc;
use wasm_bindgen::prelude::*;

mod plot;
mod types;

type JsResult<T> = Result<T, JsValue>;

/// A JS `Error` with the message.
fn err(msg: impl std::fmt::Display) -> JsValue {
    js_sys::Error::new(&msg.to_string()).into()
}

/// Options from JS: undefined/null = all defaults; otherwise read by core's one schema
/// (`options::from_json`: the structs' serde with their aliases, then their `validate`),
/// which names an unknown or mistyped field. JSON has no NaN, so a non-finite number is
/// refused here, by name, before the conversion could turn it into "absent".
fn options<T: gyrodrift::options::Settings>(what: &str, value: JsValue) -> JsResult<T> {
    if value.is_undefined() || value.is_null() {
        return Ok(T::default());
    }
    let obj: &Object = value.dyn_ref().filter(|_| value.is_object()).ok_or_else(|| err(format!("{what} options: expected an object")))?;
    reject_non_finite(what, obj, "")?;
    let json: serde_json::Value =
        serde_wasm_bindgen::from_value(value.clone()).map_err(|e| err(format!("{what} options: {}", js_message(e))))?;
    gyrodrift::options::from_json(json).map_err(|e| err(format!("{what} options: {e}")))
}

/// An error naming the first non-finite number of an options object (one level of nesting).
fn reject_non_finite(what: &str, obj: &Object, prefix: &str) -> JsResult<()> {
    for key in Object::keys(obj).iter() {
        let name = format!("{prefix}{}", key.as_string().unwrap_or_default());
        let v = Reflect::get(obj, &key).unwrap_or(JsValue::UNDEFINED);
        if let Some(x) = v.as_f64() {
            if !x.is_finite() {
                return Err(err(format!("{what} options: {name}: {x} is not a finite number")));
            }
        } else if let (Some(inner), true) = (v.dyn_ref::<Object>(), prefix.is_empty() && v.is_object()) {
            reject_non_finite(what, inner, &format!("{name}."))?;
        }
    }
    Ok(())
}

/// The message of a serde-wasm-bindgen error (a JS Error underneath).
fn js_message(e: serde_wasm_bindgen::Error) -> String {
    let v: JsValue = e.into();
    v.dyn_ref::<js_sys::Error>().map(|e| String::from(e.message())).unwrap_or_else(|| format!("{v:?}"))
}

/// A plain JS object (structs as objects, not Maps).
fn to_js<T: Serialize>(value: &T) -> JsResult<JsValue> {
    let ser = serde_wasm_bindgen::Serializer::new().serialize_maps_as_objects(true);
    value.serialize(&ser).map_err(err)
}

/// A plain JS object, or null for None.
fn to_js_or_null<T: Serialize>(value: &Option<T>) -> JsResult<JsValue> {
    value.as_ref().map_or(Ok(JsValue::NULL), to_js)
}

fn set(obj: &Object, key: &str, value: &JsValue) -> JsResult<()> {
    Reflect::set(obj, &JsValue::from_str(key), value).map(|_| ())
}

fn f64s(v: &[f64]) -> JsValue {
    Float64Array::from(v).into()
}

fn bools(v: &[bool]) -> JsValue {
    let bytes: Vec<u8> = v.iter().map(|&b| b as u8).collect();
    Uint8Array::from(&bytes[..]).into()
}

thread_local! {
    /// Live logs by id (a short list: a Vec beats a HashMap here in code size and speed).
    static LOGS: RefCell<Vec<(u32, Rc<DriveLog>)>> = const { RefCell::new(Vec::new()) };
    static NEXT_ID: Cell<u32> = const { Cell::new(1) };
}

/// A parsed drive log. Pass it to the functions below as often as needed; `free()` it (or
/// let the garbage collector do so) when done.
#[wasm_bindgen]
pub struct Log {
    id: u32,
    log: Rc<DriveLog>,
    name: String,
}

impl Drop for Log {
    fn drop(&mut self) {
        let id = self.id;
        LOGS.with(|m| m.borrow_mut().retain(|(k, _)| *k != id));
    }
}

impl Log {
    fn new(log: DriveLog) -> Log {
        let id = NEXT_ID.with(|n| {
            let id = n.get();
            n.set(id.wrapping_add(1).max(1));
            id
        });
        let log = Rc::new(log);
        LOGS.with(|m| m.borrow_mut().push((id, log.clone())));
        let name = log.meta.name.clone().unwrap_or_default();
        Log { id, log, name }
    }

    /// The logs of a JS array of `Log` objects, with their names, without taking them.
    fn from_array(value: &JsValue, what: &str) -> JsResult<Vec<(String, Rc<DriveLog>)>> {
        if value.is_undefined() || value.is_null() {
            return Ok(Vec::new());
        }
        let arr: &Array = value.dyn_ref().ok_or_else(|| err(format!("{what}: expected an array of Log")))?;
        let mut out = Vec::with_capacity(arr.length() as usize);
        for (i, item) in arr.iter().enumerate() {
            let id = Reflect::get(&item, &JsValue::from_str("id"))
                .ok()
                .and_then(|v| v.as_f64())
                .ok_or_else(|| err(format!("{what}[{i}]: not a Log")))?;
            let name = Reflect::get(&item, &JsValue::from_str("name")).ok().and_then(|v| v.as_string());
            let log = LOGS
                .with(|m| m.borrow().iter().find(|(k, _)| *k == id as u32).map(|(_, l)| l.clone()))
                .ok_or_else(|| err(format!("{what}[{i}]: this Log was freed")))?;
            let name = name.filter(|n| !n.is_empty()).unwrap_or_else(|| format!("log {}", i + 1));
            out.push((name, log));
        }
        Ok(out)
    }
}

#[wasm_bindgen]
impl Log {
    /// Parses CSV v1 text; a bad file throws an Error naming line and column.
    pub fn parse(text: &str) -> JsResult<Log> {
        gyrodrift::parse_log_str(text).map(Log::new).map_err(err)
    }

    /// Parses CSV v1 bytes (e.g. from a File's arrayBuffer()).
    #[wasm_bindgen(js_name = fromBytes)]
    pub fn from_bytes(bytes: &[u8]) -> JsResult<Log> {
        gyrodrift::parse_log(bytes).map(Log::new).map_err(err)
    }

    /// Parses CSV v1 bytes, calling `progress(fraction)` now and then (for a Web Worker
    /// parsing a large file).
    #[wasm_bindgen(js_name = fromBytesWithProgress)]
    pub fn from_bytes_with_progress(bytes: &[u8], progress: &js_sys::Function) -> JsResult<Log> {
        let total = bytes.len().max(1) as f64;
        let mut cb = |b: u64| {
            let _ = progress.call1(&JsValue::NULL, &JsValue::from_f64(b as f64 / total));
        };
        gyrodrift::log::parse_log_progress(bytes, Default::default(), &mut cb).map(Log::new).map_err(err)
    }

    /// The parsed log as plain data `{ meta, line, columns: { name: Float64Array } }`,
    /// whose buffers can be transferred from a worker; `Log.fromColumns` takes it back.
    #[wasm_bindgen(js_name = toColumns, unchecked_return_type = "LogColumns")]
    pub fn to_columns(&self) -> JsResult<JsValue> {
        let out = Object::new();
        set(&out, "meta", &to_js(&self.log.meta)?)?;
        let lines: Vec<f64> = self.log.line.iter().map(|&l| l as f64).collect();
        set(&out, "line", &f64s(&lines))?;
        let cols = Object::new();
        for (c, v) in self.log.columns() {
            set(&cols, c.name(), &f64s(v))?;
        }
        set(&out, "columns", &cols)?;
        Ok(out.into())
    }

    /// A log from `toColumns()` data, checked as the parser checks.
    #[wasm_bindgen(js_name = fromColumns)]
    pub fn from_columns(#[wasm_bindgen(unchecked_param_type = "LogColumns")] data: JsValue) -> JsResult<Log> {
        let get = |o: &JsValue, k: &str| Reflect::get(o, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED);
        let meta: gyrodrift::LogMeta = serde_wasm_bindgen::from_value(get(&data, "meta")).unwrap_or_default();
        let line: Vec<u64> =
            get(&data, "line").dyn_into::<Float64Array>().map(|a| a.to_vec().into_iter().map(|v| v as u64).collect()).unwrap_or_default();
        let cols_obj = get(&data, "columns");
        let mut cols = Vec::new();
        for c in gyrodrift::Column::ALL {
            let v = get(&cols_obj, c.name());
            if let Some(a) = v.dyn_ref::<Float64Array>() {
                cols.push((c, a.to_vec()));
            }
        }
        DriveLog::from_columns(meta, line, cols).map(Log::new).map_err(err)
    }

    /// An identifier, used when a Log is passed inside an array.
    #[wasm_bindgen(getter)]
    pub fn id(&self) -> u32 {
        self.id
    }

    /// The log's `# name:` (settable; used in reports).
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.name.clone()
    }
    #[wasm_bindgen(setter)]
    pub fn set_name(&mut self, name: String) {
        self.name = name;
    }

    /// "drive", "robot", "turntable" or "static", from the columns.
    #[wasm_bindgen(getter, unchecked_return_type = "LogKind")]
    pub fn kind(&self) -> JsResult<JsValue> {
        to_js(&self.log.kind())
    }

    /// Last minus first time, minutes.
    #[wasm_bindgen(getter, js_name = durationMin)]
    pub fn duration_min(&self) -> f64 {
        self.log.duration_min()
    }

    /// Number of data rows.
    #[wasm_bindgen(getter, js_name = rowCount)]
    pub fn row_count(&self) -> usize {
        self.log.len()
    }

    /// The `# key: value` metadata.
    #[wasm_bindgen(unchecked_return_type = "LogMeta")]
    pub fn meta(&self) -> JsResult<JsValue> {
        to_js(&self.log.meta)
    }

    /// The known columns present in the file, in CSV v1 order.
    pub fn columns(&self) -> Vec<String> {
        self.log.present_columns().iter().map(|c| c.name().to_string()).collect()
    }

    /// One column's cells as a Float64Array (NaN = empty cell).
    pub fn column(&self, name: &str) -> JsResult<Float64Array> {
        let c = gyrodrift::Column::from_name(name).ok_or_else(|| err(format!("unknown column {name}")))?;
        let v = self.log.require(c, "not in this log").map_err(err)?;
        Ok(Float64Array::from(v))
    }

    /// The log as CSV v1 text.
    #[wasm_bindgen(js_name = toCsv)]
    pub fn to_csv(&self) -> JsResult<String> {
        let mut buf = Vec::new();
        self.log.write_csv(&mut buf).map_err(err)?;
        String::from_utf8(buf).map_err(err)
    }
}

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

/// HDR with its per-sample series (Float64Array) for plotting: `{ result, error, eps0_dps, trace }`;
/// `result` is null and `error` says why when the log has no usable reference.
#[wasm_bindgen(js_name = runHdr, unchecked_return_type = "HdrRun")]
pub fn run_hdr(log: &Log, #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: HdrOptions = self::options("hdr", options)?;
    let run = hdr::run(&log.log, &opts).map_err(err)?;
    let out = run_object(&run.result, run.eps0_dps)?;
    let t = &run.trace;
    let trace = Object::new();
    set(&trace, "time_s", &f64s(&t.time_s))?;
    set(&trace, "heading_raw_deg", &f64s(&t.heading_raw_deg))?;
    set(&trace, "heading_hdr_deg", &f64s(&t.heading_hdr_deg))?;
    set(&trace, "rate_raw_dps", &f64s(&t.rate_raw_dps))?;
    set(&trace, "rate_corrected_dps", &f64s(&t.rate_corrected_dps))?;
    set(&trace, "i_dps", &f64s(&t.i_dps))?;
    set(&trace, "drift_estimate_dps", &f64s(&t.drift_estimate_dps()))?;
    set(&trace, "turn_switch", &bools(&t.turn_switch))?;
    set(&trace, "attenuation", &f64s(&t.attenuation))?;
    set(&out, "trace", &trace)?;
    // The unwrapped reference and the error of each heading at the scored samples.
    let (reference, errors) = match (&run.result, gyrodrift::metrics::Reference::from_log(&log.log)) {
        (Ok(_), Ok(r)) => {
            let refo = Object::new();
            set(&refo, "time_s", &f64s(&r.time_s))?;
            set(&refo, "heading_deg", &f64s(&r.heading_deg))?;
            let (te, e_raw) = gyrodrift::metrics::error_series(&t.time_s, &t.heading_raw_deg, &r);
            let (_, e_hdr) = gyrodrift::metrics::error_series(&t.time_s, &t.heading_hdr_deg, &r);
            let erro = Object::new();
            set(&erro, "time_s", &f64s(&te))?;
            set(&erro, "raw_deg", &f64s(&e_raw))?;
            set(&erro, "hdr_deg", &f64s(&e_hdr))?;
            (refo.into(), erro.into())
        }
        _ => (JsValue::NULL, JsValue::NULL),
    };
    set(&out, "reference", &reference)?;
    set(&out, "errors", &errors)?;
    Ok(out.into())
}

/// Dead-reckoned paths (m) of a drive with speed: along the raw, HDR and reference headings.
/// `{ raw: {x_m, y_m}, hdr: {...}, reference: {...} | null }` as Float64Array.
#[wasm_bindgen(unchecked_return_type = "Tracks")]
pub fn track(log: &Log, #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue) -> JsResult<JsValue> {
    let opts: HdrOptions = self::options("track", options)?;
    let run = hdr::run(&log.log, &opts).map_err(err)?;
    let t = &run.trace;
    let path = |p: gyrodrift::track::Path| -> JsResult<JsValue> {
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
    let trace = Object::new();
    set(&trace, "time_s", &f64s(&t.time_s))?;
    set(&trace, "heading_odo_deg", &f64s(&t.heading_odo_deg))?;
    set(&trace, "heading_gyro_deg", &f64s(&t.heading_gyro_deg))?;
    set(&trace, "heading_gyrodometry_deg", &f64s(&t.heading_gyrodometry_deg))?;
    set(&trace, "used_gyro", &bools(&t.used_gyro))?;
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

/// Overlapping Allan deviation of the log's gyro column (the Result keys; arrays as Float64Array).
#[wasm_bindgen(unchecked_return_type = "AllanResult")]
pub fn allan(log: &Log) -> JsResult<JsValue> {
    let r = allan::run(&log.log).map_err(err)?;
    let out: JsValue = to_js(&r)?;
    let obj: &Object = out.unchecked_ref();
    set(obj, "tau_s", &f64s(&r.tau_s))?;
    set(obj, "adev_dps", &f64s(&r.adev_dps))?;
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

/// Tunes the five HDR parameters on `train` and reports Table III vs tuned on both sets.
/// `progress(fraction)`, if given, is called as the search goes (e.g. from a Web Worker).
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
#[wasm_bindgen]
pub fn simulate(#[wasm_bindgen(unchecked_param_type = "SimRequest")] request: JsValue) -> JsResult<Log> {
    let req: sim::SimRequest = self::options("simulate", request)?;
    sim::simulate(&req).map(Log::new).map_err(err)
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

/// Streaming HDR for online use: `update(time_s, rate_raw_dps)` per sample returns the
/// heading; the getters give the state after the last update. Call `free()` when done.
#[wasm_bindgen]
pub struct HdrEstimator {
    inner: Hdr,
    last: Option<hdr::HdrOutput>,
}

#[wasm_bindgen]
impl HdrEstimator {
    /// Parameters (Table III where missing) and the static bias to remove, deg/s.
    #[wasm_bindgen(constructor)]
    pub fn new(#[wasm_bindgen(unchecked_param_type = "HdrParams")] params: JsValue, eps0_dps: f64) -> JsResult<HdrEstimator> {
        let p: HdrParams = options("HdrEstimator", params)?;
        Ok(HdrEstimator { inner: Hdr::new(p, eps0_dps).map_err(err)?, last: None })
    }

    /// One raw sample; returns the heading (deg, starting at 0). Throws on a non-finite
    /// value or a time that does not increase, leaving the state as it was.
    pub fn update(&mut self, time_s: f64, rate_raw_dps: f64) -> JsResult<f64> {
        let o = self.inner.update(time_s, rate_raw_dps).map_err(err)?;
        self.last = Some(o);
        Ok(o.heading_deg)
    }

    /// Many samples at once; returns their headings.
    #[wasm_bindgen(js_name = updateMany)]
    pub fn update_many(&mut self, time_s: &[f64], rate_raw_dps: &[f64]) -> JsResult<Float64Array> {
        let mut out = Vec::with_capacity(time_s.len());
        let mut last = self.last;
        let r = self.inner.update_slice(time_s, rate_raw_dps, |o| {
            out.push(o.heading_deg);
            last = Some(*o);
        });
        self.last = last;
        r.map_err(err)?;
        Ok(Float64Array::from(&out[..]))
    }

    /// The full output of the last step (null before the first).
    #[wasm_bindgen(unchecked_return_type = "HdrState | null")]
    pub fn state(&self) -> JsResult<JsValue> {
        to_js_or_null(&self.last)
    }

    #[wasm_bindgen(getter, js_name = headingDeg)]
    pub fn heading_deg(&self) -> f64 {
        self.last.map_or(0.0, |o| o.heading_deg)
    }
    /// The drift estimate -I, deg/s.
    #[wasm_bindgen(getter, js_name = driftEstimateDps)]
    pub fn drift_estimate_dps(&self) -> f64 {
        self.last.map_or(0.0, |o| -o.i_dps)
    }
    #[wasm_bindgen(getter, js_name = rateCorrectedDps)]
    pub fn rate_corrected_dps(&self) -> f64 {
        self.last.map_or(0.0, |o| o.rate_corrected_dps)
    }
    #[wasm_bindgen(getter, js_name = turnSwitch)]
    pub fn turn_switch(&self) -> bool {
        self.last.is_some_and(|o| o.turn_switch)
    }
    #[wasm_bindgen(getter)]
    pub fn r(&self) -> f64 {
        self.last.map_or(1.0, |o| o.r as f64)
    }
    #[wasm_bindgen(getter)]
    pub fn attenuation(&self) -> f64 {
        self.last.map_or(1.0, |o| o.attenuation)
    }
}

/// Streaming Gyrodometry: `update(time_s, rate_raw_dps, odo_left_m, odo_right_m)` per row.
#[wasm_bindgen]
pub struct GyrodometryEstimator {
    inner: gyrodometry::Gyrodometry,
    last: Option<gyrodometry::GyrodometryOutput>,
}

#[wasm_bindgen]
impl GyrodometryEstimator {
    #[wasm_bindgen(constructor)]
    pub fn new(wheelbase_m: f64, thres_rate_dps: f64, eps0_dps: f64) -> JsResult<GyrodometryEstimator> {
        let inner = gyrodometry::Gyrodometry::new(wheelbase_m, thres_rate_dps, eps0_dps).map_err(err)?;
        Ok(GyrodometryEstimator { inner, last: None })
    }

    /// One row; returns the Gyrodometry heading, deg.
    pub fn update(&mut self, time_s: f64, rate_raw_dps: f64, odo_left_m: f64, odo_right_m: f64) -> JsResult<f64> {
        let o = self.inner.update(time_s, rate_raw_dps, odo_left_m, odo_right_m).map_err(err)?;
        self.last = Some(o);
        Ok(o.heading_deg)
    }

    #[wasm_bindgen(unchecked_return_type = "GyrodometryState | null")]
    pub fn state(&self) -> JsResult<JsValue> {
        to_js_or_null(&self.last)
    }

    #[wasm_bindgen(getter, js_name = headingDeg)]
    pub fn heading_deg(&self) -> f64 {
        self.last.map_or(0.0, |o| o.heading_deg)
    }
    #[wasm_bindgen(getter, js_name = usedGyro)]
    pub fn used_gyro(&self) -> bool {
        self.last.is_some_and(|o| o.used_gyro)
    }
}

/// Imports recorded files by a recipe (the same object as the CLI's TOML/JSON recipe):
/// `files` maps each recipe `file` name to its bytes. Returns `{ log, summary }`; a bad
/// recipe or file throws an Error naming the file, line and column.
#[wasm_bindgen(js_name = importLog, unchecked_return_type = "ImportResult")]
pub fn import_log(
    #[wasm_bindgen(unchecked_param_type = "Recipe")] recipe: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Record<string, Uint8Array>")] files: JsValue,
) -> JsResult<JsValue> {
    let recipe: gyrodrift::import::Recipe =
        serde_wasm_bindgen::from_value(recipe).map_err(|e| err(format!("recipe: {}", js_message(e))))?;
    let obj: &Object =
        files.dyn_ref().filter(|_| files.is_object()).ok_or_else(|| err("files: expected an object of name -> Uint8Array"))?;
    let mut map = std::collections::BTreeMap::new();
    for key in Object::keys(obj).iter() {
        let name = key.as_string().unwrap_or_default();
        let v = Reflect::get(obj, &key)?;
        let bytes: &Uint8Array = v.dyn_ref().ok_or_else(|| err(format!("files[\"{name}\"]: expected a Uint8Array")))?;
        map.insert(name, bytes.to_vec());
    }
    let (log, summary) = gyrodrift::import::import(&recipe, &mut map).map_err(err)?;
    let out = Object::new();
    set(&out, "log", &JsValue::from(Log::new(log)))?;
    set(&out, "summary", &to_js(&summary)?)?;
    Ok(out.into())
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
    let trace = Object::new();
    set(&trace, "time_s", &f64s(&t.time_s))?;
    set(&trace, "heading_deg", &f64s(&t.heading_deg))?;
    set(&trace, "heading_smoothed_deg", &f64s(&t.heading_smoothed_deg))?;
    set(&trace, "bias_dps", &f64s(&t.bias_dps))?;
    set(&trace, "bias_sigma_dps", &f64s(&t.bias_sigma_dps))?;
    set(&trace, "bias_smoothed_dps", &f64s(&t.bias_smoothed_dps))?;
    set(&trace, "stop", &bools(&t.stop))?;
    set(&out, "trace", &trace)?;
    // The error of the (aligned) heading at the scored reference samples.
    let errors = match (&run.result, gyrodrift::metrics::Reference::from_log(&log.log)) {
        (Ok(_), Ok(r)) => {
            let (te, e) = gyrodrift::metrics::error_series(&t.time_s, &t.heading_deg, &r);
            let (_, es) = gyrodrift::metrics::error_series(&t.time_s, &t.heading_smoothed_deg, &r);
            let erro = Object::new();
            set(&erro, "time_s", &f64s(&te))?;
            set(&erro, "pipeline_deg", &f64s(&e))?;
            set(&erro, "smoothed_deg", &f64s(&es))?;
            erro.into()
        }
        _ => JsValue::NULL,
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
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let logs = Log::from_array(&logs, "logs")?;
    let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), l.as_ref())).collect();
    to_js(&gyrodrift::compare::compare(&named, &p, None).map_err(err)?)
}
