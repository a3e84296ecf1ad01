//! Many logs at once: Table II, tuning, the robustness battery; and the simulator.

use super::*;

/// The HDR paper's Table II over many logs (named by their `name`). A log `checkLog` finds an
/// error in throws, as the CLI refuses it, unless `ignore_check` (so in every table).
#[wasm_bindgen(unchecked_return_type = "Report")]
pub fn report(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<JsValue> {
    to_js(&build_report(&logs, options, ignore_check)?)
}

/// Table II over a JS array of logs with HDR options (shared by `report` and `reportMarkdown`).
fn build_report(logs: &JsValue, options: JsValue, ignore_check: Option<bool>) -> JsResult<report::Report> {
    let opts: HdrOptions = self::options("report", options)?;
    let logs = Log::from_array(logs, "logs", ignore_check)?;
    let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), &**l)).collect();
    report::Report::build(&named, &opts).map_err(err)
}

/// The report as Markdown (the CLI's `report --markdown`).
#[wasm_bindgen(js_name = reportMarkdown)]
pub fn report_markdown(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<String> {
    Ok(build_report(&logs, options, ignore_check)?.to_markdown())
}

/// The report as CSV (one row per drive, then the average).
#[wasm_bindgen(js_name = reportCsv)]
pub fn report_csv(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "HdrOptions")] options: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<String> {
    Ok(build_report(&logs, options, ignore_check)?.to_csv())
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
    ignore_check: Option<bool>,
) -> JsResult<JsValue> {
    let opts: tune::TuneOptions = self::options("tune", options)?;
    let hdr_opts = HdrOptions::default();
    let prep = |v: Vec<(String, Rc<DriveLog>)>| -> JsResult<Vec<tune::PreparedDrive>> {
        let named: Vec<(String, &DriveLog)> = v.iter().map(|(n, l)| (n.clone(), &**l)).collect();
        tune::prepare_all(&named, &hdr_opts).map_err(err)
    };
    let train = prep(Log::from_array(&train, "train", ignore_check)?)?;
    let test = prep(Log::from_array(&test, "test", ignore_check)?)?;
    let expected = tune::expected_evaluations_for(&opts, train.len()).max(1) as f64;
    let report = |n: u64| {
        if let Some(f) = &progress {
            let _ = f.call1(&JsValue::NULL, &JsValue::from_f64((n as f64 / expected).min(1.0)));
        }
    };
    to_js(&tune::tune_and_report_with_progress(&train, &test, &opts, &report).map_err(err)?)
}

/// The robustness battery's error profiles on these drives (core's `battery::on_drives`):
/// every method's NE_psi per case, the summary (`added`) and the goals; no tuned-HDR
/// peer (`batteryMarkdown` gives the same as the CLI prints it).
#[cfg(feature = "sim")]
#[wasm_bindgen(unchecked_return_type = "Battery")]
pub fn battery(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<JsValue> {
    to_js(&build_battery(&logs, options, ignore_check)?)
}

/// The battery on these drives as Markdown, every case listed (the CLI's `battery --cases`).
#[cfg(feature = "sim")]
#[wasm_bindgen(js_name = batteryMarkdown)]
pub fn battery_markdown(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<String> {
    Ok(build_battery(&logs, options, ignore_check)?.to_markdown(true))
}

#[cfg(feature = "sim")]
fn build_battery(logs: &JsValue, options: JsValue, ignore_check: Option<bool>) -> JsResult<gyrodrift::battery::Battery> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("battery", options)?;
    let logs = Log::from_array(logs, "logs", ignore_check)?;
    let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), &**l)).collect();
    gyrodrift::battery::on_drives(&named, &p).map_err(err)
}

/// Simulates a log with known truth (the CLI's `simulate`); the same seed gives the same
/// log as the native CLI.
#[cfg(feature = "sim")]
#[wasm_bindgen]
pub fn simulate(#[wasm_bindgen(unchecked_param_type = "SimRequest")] request: JsValue) -> JsResult<Log> {
    let req: sim::SimRequest = self::options("simulate", request)?;
    sim::simulate(&req).map(Log::new).map_err(err)
}

/// The log with these gyro errors added to its yaw rate (the CLI's `inject`; the battery's
/// error classes, `batteryProfiles()` for its own), every other column kept.
#[cfg(feature = "sim")]
#[wasm_bindgen(js_name = addGyroErrors)]
pub fn add_gyro_errors(log: &Log, #[wasm_bindgen(unchecked_param_type = "GyroErrors")] errors: JsValue) -> JsResult<Log> {
    let e: sim::GyroErrors = self::options("addGyroErrors", errors)?;
    sim::inject(&log.log, &e).map(Log::new).map_err(err)
}

/// The robustness battery's gyro error profiles: name, split and errors.
#[cfg(feature = "sim")]
#[wasm_bindgen(js_name = batteryProfiles, unchecked_return_type = "BatteryProfile[]")]
pub fn battery_profiles() -> JsResult<JsValue> {
    to_js(&gyrodrift::battery::profiles())
}
