//! Streaming estimators for live use: one sample in, the heading out (numpy arrays for many).

use crate::{array, result_dict, value_err, values};
use gyrodrift::gyrodometry;
use gyrodrift::hdr::{self, Hdr, HdrParams};
use numpy::PyReadonlyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

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
    fn update_many(
        &mut self,
        py: Python<'_>,
        time_s: PyReadonlyArray1<'_, f64>,
        rate_raw_dps: PyReadonlyArray1<'_, f64>,
    ) -> PyResult<Py<PyAny>> {
        let (t, w) = (values(&time_s, "time_s")?, values(&rate_raw_dps, "rate_raw_dps")?);
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
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<HdrEstimator>()?;
    m.add_class::<GyrodometryEstimator>()
}
