//! What a log and a method's settings look like before anything runs: check, defaults,
//! option checks, version, the static-bias window.

use super::*;

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
