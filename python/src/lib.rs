//! `gyrodrift._core`: thin pyo3 bindings of the gyrodrift core. They translate types
//! (numpy float64 arrays, dicts with the CLI's `--json` keys) and errors (ValueError with
//! the file, line and column; OSError for files that cannot be opened), nothing else: every
//! number comes from core. The Python package `gyrodrift` re-exports this module and adds
//! the pandas helpers and the Dask fleet job.

use numpy::{AllowTypeChange, PyArray1, PyArrayLike1};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyList, PyString};
use serde_json::Value;

mod fleet;
mod log;
mod methods;
mod streaming;

pub use log::PyLog;

/// A core error as a Python ValueError (its message names file, line and column).
pub(crate) fn value_err(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// A serde value (the CLI's JSON) as Python objects: dicts, lists, floats, ints, str, None.
pub(crate) fn to_py(py: Python<'_>, v: &Value) -> PyResult<Py<PyAny>> {
    Ok(match v {
        Value::Null => py.None(),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any().unbind(),
        Value::Number(n) => match n.as_i64() {
            Some(i) if !n.is_f64() => i.into_pyobject(py)?.into_any().unbind(),
            _ => PyFloat::new(py, n.as_f64().unwrap_or(f64::NAN)).into_any().unbind(),
        },
        Value::String(s) => PyString::new(py, s).into_any().unbind(),
        Value::Array(a) => {
            let items = a.iter().map(|x| to_py(py, x)).collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any().unbind()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any().unbind()
        }
    })
}

/// Any serializable core result (a struct) as a Python dict (the CLI's `--json` keys).
pub(crate) fn result_dict<'py, T: serde::Serialize>(py: Python<'py>, r: &T) -> PyResult<Bound<'py, PyDict>> {
    let v = serde_json::to_value(r).map_err(value_err)?;
    to_py(py, &v)?.into_bound(py).cast_into::<PyDict>().map_err(|_| value_err("a result that is not an object"))
}

/// A Python object (dict of settings, a recipe) as a serde value; numbers must be finite, and
/// a dict key set to None is left out (its default).
pub(crate) fn from_py(what: &str, obj: &Bound<'_, PyAny>) -> PyResult<Value> {
    if obj.is_none() {
        return Ok(Value::Null);
    }
    // A bool, numpy's too (before the integers, which a numpy bool would also read as).
    if let Ok(b) = obj.extract::<bool>() {
        return Ok(Value::Bool(b));
    }
    if let Ok(i) = obj.extract::<i64>() {
        return Ok(Value::from(i));
    }
    if let Ok(x) = obj.extract::<f64>() {
        return serde_json::Number::from_f64(x)
            .map(Value::Number)
            .ok_or_else(|| PyValueError::new_err(format!("{what}: {x} is not a finite number")));
    }
    if let Ok(s) = obj.extract::<String>() {
        return Ok(Value::String(s));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        let mut m = serde_json::Map::new();
        for (k, v) in d.iter() {
            let key: String = k.extract().map_err(|_| PyTypeError::new_err(format!("{what}: keys must be str")))?;
            // A key set to None is a key not given: its default, as a keyword argument's.
            if v.is_none() {
                continue;
            }
            let inner = format!("{what}.{key}");
            m.insert(key, from_py(&inner, &v)?);
        }
        return Ok(Value::Object(m));
    }
    if let Ok(l) = obj.cast::<PyList>() {
        return Ok(Value::Array(l.iter().map(|x| from_py(what, &x)).collect::<PyResult<_>>()?));
    }
    Err(PyTypeError::new_err(format!("{what}: expected a dict, list, number, str, bool or None, got {}", obj.get_type().name()?)))
}

/// Settings of one method from an optional dict (defaults where missing; unknown keys and
/// out-of-range values refused by core's one schema).
pub(crate) fn settings<T: gyrodrift::options::Settings>(what: &str, obj: Option<&Bound<'_, PyAny>>) -> PyResult<T> {
    let v = match obj {
        Some(o) => from_py(what, o)?,
        None => Value::Null,
    };
    gyrodrift::options::from_json(v).map_err(|e| PyValueError::new_err(format!("{what}: {e}")))
}

/// A float64 numpy array from a Vec (moved, not copied).
pub(crate) fn array(py: Python<'_>, v: Vec<f64>) -> Py<PyAny> {
    PyArray1::from_vec(py, v).into_any().unbind()
}

/// The values of a 1-d array of numbers as numpy reads it (`numpy.asarray(x, float64)`): a
/// float64 array of any strides, another dtype, a list, a pandas Series.
pub(crate) fn values(a: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
    let a: PyArrayLike1<'_, f64, AllowTypeChange> = a
        .extract()
        .map_err(|_| PyValueError::new_err(format!("{what}: expected a 1-d array of numbers (numpy array, list, pandas Series)")))?;
    Ok(a.as_array().iter().copied().collect())
}

/// A core trace's `columns()` as a dict of float64 arrays, flags as 1.0 / 0.0 as the CLI's
/// trace CSV writes them.
pub(crate) fn columns<'py>(py: Python<'py>, cols: &[(&str, gyrodrift::series::Column<'_>)]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (k, c) in cols {
        d.set_item(k, array(py, c.to_f64s().into_owned()))?;
    }
    Ok(d)
}

/// The version of the core these bindings carry.
#[pyfunction]
fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add_class::<PyLog>()?;
    m.add("COLUMNS", gyrodrift::Column::ALL.iter().map(|c| c.name()).collect::<Vec<_>>())?;
    log::register(m)?;
    methods::register(m)?;
    streaming::register(m)?;
    fleet::register(m)?;
    Ok(())
}
