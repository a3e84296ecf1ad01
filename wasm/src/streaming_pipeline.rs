//! The recommended pipeline as a streaming estimator for live use (core's `PipelineStream`):
//! one row in, the heading out. In the full module (`gyrodrift/full`, Node), not in the
//! browser's size-budgeted core module.

use crate::convert::*;
use crate::JsResult;
use gyrodrift::pipeline::{PipelineOutput, PipelineParams, PipelineStream};
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

/// Streaming pipeline: `update(time_s, rate_raw_dps, speed_mps)` per row returns the heading
/// (deg, from 0); `speed_mps` NaN when the row has none (until a row brings a speed, stops
/// are judged by the gyro against the declared lead-in, as the batch path does for a log
/// without speed). The state is the last closed 1 s block's: bias, sigmas, stop. Call
/// `free()` when done.
#[wasm_bindgen]
pub struct PipelineEstimator {
    inner: PipelineStream,
}

#[wasm_bindgen]
impl PipelineEstimator {
    /// The pipeline's settings (`bias_s`: the stationary lead-in from the first row, 20 s
    /// when missing).
    #[wasm_bindgen(constructor)]
    pub fn new(#[wasm_bindgen(unchecked_param_type = "PipelineOptions")] options: JsValue) -> JsResult<PipelineEstimator> {
        let p: PipelineParams = self::options("PipelineEstimator", options)?;
        Ok(PipelineEstimator { inner: PipelineStream::new(p).map_err(err)? })
    }

    /// One row; returns the heading. Throws on a non-finite time or rate or a time that does
    /// not increase, leaving the state as it was.
    pub fn update(&mut self, time_s: f64, rate_raw_dps: f64, speed_mps: f64) -> JsResult<f64> {
        self.inner.update(time_s, rate_raw_dps, speed_mps).map_err(err)
    }

    /// Many rows at once (equal lengths; NaN speeds where unknown); returns their headings.
    #[wasm_bindgen(js_name = updateMany)]
    pub fn update_many(&mut self, time_s: &[f64], rate_raw_dps: &[f64], speed_mps: &[f64]) -> JsResult<Float64Array> {
        if rate_raw_dps.len() != time_s.len() || speed_mps.len() != time_s.len() {
            return Err(err("PipelineEstimator.updateMany: time_s, rate_raw_dps and speed_mps differ in length"));
        }
        let out = (0..time_s.len()).map(|i| self.inner.update(time_s[i], rate_raw_dps[i], speed_mps[i])).collect::<Result<Vec<f64>, _>>();
        Ok(Float64Array::from(&out.map_err(err)?[..]))
    }

    /// The last closed block's output (null before the first block closes).
    #[wasm_bindgen(unchecked_return_type = "PipelineState | null")]
    pub fn state(&self) -> JsResult<JsValue> {
        to_js_or_null(&self.inner.last_block())
    }

    #[wasm_bindgen(getter, js_name = headingDeg)]
    pub fn heading_deg(&self) -> f64 {
        self.inner.heading_deg()
    }
    /// The heading's sigma from the bias model at the last closed block, deg.
    #[wasm_bindgen(getter, js_name = headingSigmaDeg)]
    pub fn heading_sigma_deg(&self) -> f64 {
        self.inner.last_block().map_or(f64::NAN, |o: PipelineOutput| o.heading_sigma_deg)
    }
}

/// Saving and resuming (core's `snapshot`): in the Node build, not in the browser's modules.
#[cfg(feature = "snapshot")]
#[wasm_bindgen]
impl PipelineEstimator {
    /// The estimator's whole state as bytes (the bank, its evidence, the blend): `fromState`
    /// resumes it, here or in Python.
    #[wasm_bindgen(js_name = saveState)]
    pub fn save_state(&self) -> JsResult<Vec<u8>> {
        gyrodrift::snapshot::save(&self.inner).map_err(err)
    }

    /// The estimator `saveState` saved, to go on where it stopped (the same headings, bit
    /// for bit); throws for bytes that are not one, a build's whose estimators differ, or
    /// damaged.
    #[wasm_bindgen(js_name = fromState)]
    pub fn from_state(state: &[u8]) -> JsResult<PipelineEstimator> {
        Ok(PipelineEstimator { inner: gyrodrift::snapshot::load(state).map_err(err)? })
    }
}
