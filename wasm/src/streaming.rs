//! Streaming estimators for live use: one sample in, the heading out.

use crate::convert::*;
use crate::JsResult;
use gyrodrift::gyrodometry;
use gyrodrift::hdr::{self, Hdr, HdrParams};
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

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
        let mut out = Vec::new();
        self.inner.update_slice_headings(time_s, rate_raw_dps, &mut out, &mut self.last).map_err(err)?;
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

/// Saving and resuming (core's `snapshot`): in the Node build, not in the browser's modules.
#[cfg(feature = "snapshot")]
#[wasm_bindgen]
impl HdrEstimator {
    /// The estimator's whole state as bytes (to store and resume later, elsewhere, or in
    /// Python: `fromState`).
    #[wasm_bindgen(js_name = saveState)]
    pub fn save_state(&self) -> JsResult<Vec<u8>> {
        gyrodrift::snapshot::save(&(self.inner.clone(), self.last)).map_err(err)
    }

    /// The estimator `saveState` saved, to go on where it stopped (the same headings, bit
    /// for bit); throws for bytes that are not one, a build's whose estimators differ, or
    /// damaged.
    #[wasm_bindgen(js_name = fromState)]
    pub fn from_state(state: &[u8]) -> JsResult<HdrEstimator> {
        let (inner, last) = gyrodrift::snapshot::load(state).map_err(err)?;
        Ok(HdrEstimator { inner, last })
    }
}

#[cfg(feature = "snapshot")]
#[wasm_bindgen]
impl GyrodometryEstimator {
    /// The estimator's whole state as bytes (`fromState` resumes it).
    #[wasm_bindgen(js_name = saveState)]
    pub fn save_state(&self) -> JsResult<Vec<u8>> {
        gyrodrift::snapshot::save(&(self.inner.clone(), self.last)).map_err(err)
    }

    /// The estimator `saveState` saved, to go on where it stopped.
    #[wasm_bindgen(js_name = fromState)]
    pub fn from_state(state: &[u8]) -> JsResult<GyrodometryEstimator> {
        let (inner, last) = gyrodrift::snapshot::load(state).map_err(err)?;
        Ok(GyrodometryEstimator { inner, last })
    }
}
