//! Gyrodometry, calibration and the Allan deviation over a parsed log.

use super::*;

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
    let trace = columns_object(&t.columns(), None)?;
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
