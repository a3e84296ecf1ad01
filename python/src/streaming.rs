//! Streaming estimators for live use: one sample in, the heading out (numpy arrays for many).

use crate::{array, result_dict, value_err, values};
use gyrodrift::gyrodometry;
use gyrodrift::hdr::{self, Hdr, HdrParams};
use gyrodrift::pipeline::{PipelineParams, PipelineStream};
use gyrodrift::snapshot;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};

/// Streaming HDR: `update(time_s, rate_raw_dps)` per sample returns the heading (deg);
/// `state()` gives the last step's full output.
#[pyclass(module = "gyrodrift")]
pub struct HdrEstimator {
    inner: Hdr,
    last: Option<hdr::HdrOutput>,
}

#[pymethods]
impl HdrEstimator {
    /// Parameters as a dict (Table III where missing) and the static bias to remove, deg/s.
    #[new]
    #[pyo3(signature = (params=None, eps0_dps=0.0))]
    fn new(params: Option<&Bound<'_, PyAny>>, eps0_dps: f64) -> PyResult<Self> {
        let p: HdrParams = crate::settings("HdrEstimator", params)?;
        Ok(HdrEstimator { inner: Hdr::new(p, eps0_dps).map_err(value_err)?, last: None })
    }

    /// One raw sample; returns the heading. Raises ValueError on a non-finite value or a
    /// time that does not increase, leaving the state as it was.
    fn update(&mut self, time_s: f64, rate_raw_dps: f64) -> PyResult<f64> {
        let o = self.inner.update(time_s, rate_raw_dps).map_err(value_err)?;
        self.last = Some(o);
        Ok(o.heading_deg)
    }

    /// Many samples at once (float64 arrays); returns their headings.
    fn update_many(&mut self, py: Python<'_>, time_s: &Bound<'_, PyAny>, rate_raw_dps: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let (t, w) = (values(time_s, "time_s")?, values(rate_raw_dps, "rate_raw_dps")?);
        let mut out = Vec::new();
        self.inner.update_slice_headings(&t, &w, &mut out, &mut self.last).map_err(value_err)?;
        Ok(array(py, out))
    }

    /// The full output of the last step (None before the first).
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.last.as_ref().map(|o| result_dict(py, o)).transpose()
    }

    #[getter]
    fn heading_deg(&self) -> f64 {
        self.last.map_or(0.0, |o| o.heading_deg)
    }

    /// The estimator's whole state as bytes (to resume it later, elsewhere, or in the wasm
    /// package: `from_state`); pickling uses it too.
    fn save_state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        Ok(PyBytes::new(py, &snapshot::save(&(self.inner.clone(), self.last)).map_err(value_err)?))
    }

    /// The estimator `save_state` saved, to go on where it stopped (the same headings, bit
    /// for bit); ValueError for bytes that are not one, a build's whose estimators differ,
    /// or damaged.
    #[staticmethod]
    fn from_state(state: &[u8]) -> PyResult<Self> {
        let (inner, last) = snapshot::load(state).map_err(value_err)?;
        Ok(HdrEstimator { inner, last })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyBytes>,))> {
        Ok((py.get_type::<Self>().getattr("from_state")?, (self.save_state(py)?,)))
    }
}

/// Streaming Gyrodometry: `update(time_s, rate_raw_dps, odo_left_m, odo_right_m)` per row.
#[pyclass(module = "gyrodrift")]
pub struct GyrodometryEstimator {
    inner: gyrodometry::Gyrodometry,
    last: Option<gyrodometry::GyrodometryOutput>,
}

#[pymethods]
impl GyrodometryEstimator {
    #[new]
    #[pyo3(signature = (wheelbase_m, thres_rate_dps, eps0_dps=0.0))]
    fn new(wheelbase_m: f64, thres_rate_dps: f64, eps0_dps: f64) -> PyResult<Self> {
        let inner = gyrodometry::Gyrodometry::new(wheelbase_m, thres_rate_dps, eps0_dps).map_err(value_err)?;
        Ok(GyrodometryEstimator { inner, last: None })
    }

    /// One row; returns the Gyrodometry heading, deg.
    fn update(&mut self, time_s: f64, rate_raw_dps: f64, odo_left_m: f64, odo_right_m: f64) -> PyResult<f64> {
        let o = self.inner.update(time_s, rate_raw_dps, odo_left_m, odo_right_m).map_err(value_err)?;
        self.last = Some(o);
        Ok(o.heading_deg)
    }

    fn state<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.last.as_ref().map(|o| result_dict(py, o)).transpose()
    }

    #[getter]
    fn heading_deg(&self) -> f64 {
        self.last.map_or(0.0, |o| o.heading_deg)
    }

    #[getter]
    fn used_gyro(&self) -> bool {
        self.last.is_some_and(|o| o.used_gyro)
    }

    /// The estimator's whole state as bytes (`from_state` resumes it); pickling uses it too.
    fn save_state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        Ok(PyBytes::new(py, &snapshot::save(&(self.inner.clone(), self.last)).map_err(value_err)?))
    }

    /// The estimator `save_state` saved, to go on where it stopped.
    #[staticmethod]
    fn from_state(state: &[u8]) -> PyResult<Self> {
        let (inner, last) = snapshot::load(state).map_err(value_err)?;
        Ok(GyrodometryEstimator { inner, last })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyBytes>,))> {
        Ok((py.get_type::<Self>().getattr("from_state")?, (self.save_state(py)?,)))
    }
}

/// The recommended pipeline, streaming: `update(time_s, rate_raw_dps, speed_mps)` per row
/// returns the heading (deg, from 0); speed NaN when the row has none (until a row brings a
/// speed, stops are judged by the gyro against the declared lead-in, as the batch path does
/// for a log without speed). `state()` is the last closed 1 s block's output (bias, sigmas,
/// stop).
#[pyclass(module = "gyrodrift")]
pub struct PipelineEstimator {
    inner: PipelineStream,
}

#[pymethods]
impl PipelineEstimator {
    /// The pipeline's settings as a dict (`bias_s`: the stationary lead-in from the first
    /// row, 20 s when missing).
    #[new]
    #[pyo3(signature = (settings=None))]
    fn new(settings: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let p: PipelineParams = crate::settings("PipelineEstimator", settings)?;
        Ok(PipelineEstimator { inner: PipelineStream::new(p).map_err(value_err)? })
    }

    /// One row; returns the heading. Raises ValueError on a non-finite time or rate or a
    /// time that does not increase, leaving the state as it was.
    fn update(&mut self, time_s: f64, rate_raw_dps: f64, speed_mps: f64) -> PyResult<f64> {
        self.inner.update(time_s, rate_raw_dps, speed_mps).map_err(value_err)
    }

    /// Many rows at once (float64 arrays of one length; NaN speeds where unknown).
    fn update_many(
        &mut self,
        py: Python<'_>,
        time_s: &Bound<'_, PyAny>,
        rate_raw_dps: &Bound<'_, PyAny>,
        speed_mps: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let (t, w, v) = (values(time_s, "time_s")?, values(rate_raw_dps, "rate_raw_dps")?, values(speed_mps, "speed_mps")?);
        if w.len() != t.len() || v.len() != t.len() {
            return Err(value_err("update_many: time_s, rate_raw_dps and speed_mps differ in length"));
        }
        let out = (0..t.len()).map(|i| self.inner.update(t[i], w[i], v[i])).collect::<gyrodrift::Result<Vec<f64>>>();
        Ok(array(py, out.map_err(value_err)?))
    }

    /// The last closed block's output (None before the first block closes).
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.inner.last_block().as_ref().map(|o| result_dict(py, o)).transpose()
    }

    #[getter]
    fn heading_deg(&self) -> f64 {
        self.inner.heading_deg()
    }

    /// The estimator's whole state as bytes (the bank, its evidence, the blend: `from_state`
    /// resumes it, here or in the wasm package); pickling uses it too.
    fn save_state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        Ok(PyBytes::new(py, &snapshot::save(&self.inner).map_err(value_err)?))
    }

    /// The estimator `save_state` saved, to go on where it stopped (the same headings, bit
    /// for bit); ValueError for bytes that are not one, a build's whose estimators differ,
    /// or damaged.
    #[staticmethod]
    fn from_state(state: &[u8]) -> PyResult<Self> {
        Ok(PipelineEstimator { inner: snapshot::load(state).map_err(value_err)? })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyBytes>,))> {
        Ok((py.get_type::<Self>().getattr("from_state")?, (self.save_state(py)?,)))
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<HdrEstimator>()?;
    m.add_class::<GyrodometryEstimator>()?;
    m.add_class::<PipelineEstimator>()
}
