//! The recommended drift reducer and the comparison of every method.

use super::*;

/// The recommended drift-reduction pipeline with raw, Table-III HDR and the two peers:
/// the pipeline Result keys. Throws when the log has no usable reference.
#[wasm_bindgen(unchecked_return_type = "PipelineResult")]
pub fn pipeline(log: &Log, #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue) -> JsResult<JsValue> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let run = gyrodrift::pipeline::run(&log.log, &p).map_err(err)?;
    to_js(&run.result.map_err(err)?)
}

/// The pipeline with its per-block series: `{ result, error, still_source, summary, trace,
/// errors }` (summary: the estimator's end figures, which need no reference).
#[wasm_bindgen(js_name = runPipeline, unchecked_return_type = "PipelineRun")]
pub fn run_pipeline(log: &Log, #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue) -> JsResult<JsValue> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let run = gyrodrift::pipeline::run(&log.log, &p).map_err(err)?;
    let out = result_object(&run.result)?;
    set(&out, "still_source", &to_js(&run.still_source)?)?;
    set(&out, "summary", &to_js(&run.summary(log.log.duration_min()))?)?;
    let t = &run.trace;
    let trace = columns_object(&t.columns(), None)?;
    set(&out, "trace", &trace)?;
    let errors = match run.errors(&log.log) {
        Some(e) => series(&[("time_s", &e.time_s), ("pipeline_deg", &e.errors_deg[0]), ("smoothed_deg", &e.errors_deg[1])])?.into(),
        None => JsValue::NULL,
    };
    set(&out, "errors", &errors)?;
    Ok(out.into())
}

/// Dead-reckoned paths (m) along the pipeline's causal and smoothed headings, reduced as
/// `track`'s: `{ pipeline, smoothed }`. Apart from `track` because it depends on the log and
/// `bias_s` only, not on HDR's sliders: a page computes it once per log.
#[wasm_bindgen(js_name = pipelineTrack, unchecked_return_type = "PipelineTracks")]
pub fn pipeline_track(log: &Log, #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue) -> JsResult<JsValue> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let t = gyrodrift::pipeline::run(&log.log, &p).map_err(err)?.trace;
    let out = Object::new();
    set(&out, "pipeline", &drawn_path(&log.log, &t.time_s, &t.heading_deg)?)?;
    set(&out, "smoothed", &drawn_path(&log.log, &t.time_s, &t.heading_smoothed_deg)?)?;
    Ok(out.into())
}

/// Every method side by side (NE_psi per drive): raw, Table-III HDR, the pipeline, peers.
#[wasm_bindgen(unchecked_return_type = "Compare")]
pub fn compare(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<JsValue> {
    to_js(&build_compare(&logs, options, ignore_check)?)
}

fn build_compare(logs: &JsValue, options: JsValue, ignore_check: Option<bool>) -> JsResult<gyrodrift::compare::Compare> {
    let p: gyrodrift::pipeline::PipelineParams = self::options("pipeline", options)?;
    let logs = Log::from_array(logs, "logs", ignore_check)?;
    let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), l.as_ref())).collect();
    gyrodrift::compare::compare(&named, &p, None).map_err(err)
}

/// The comparison as a table: "markdown" (the CLI's `report --compare`) or "csv".
#[wasm_bindgen(js_name = compareTable)]
pub fn compare_table(
    #[wasm_bindgen(unchecked_param_type = "Log[]")] logs: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue,
    #[wasm_bindgen(unchecked_param_type = "\"markdown\" | \"csv\"")] format: JsValue,
    ignore_check: Option<bool>,
) -> JsResult<String> {
    let format = js_string(&format, "compareTable(format)")?;
    let c = build_compare(&logs, options, ignore_check)?;
    match format.as_str() {
        "markdown" => Ok(c.to_markdown()),
        "csv" => Ok(c.to_csv()),
        other => Err(err(format!("compareTable: format \"{other}\" is not markdown or csv"))),
    }
}
