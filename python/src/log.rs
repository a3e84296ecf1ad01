//! `Log`: a parsed drive log (CSV v1), read from a file or text, or made from numpy columns.

use crate::{array, from_py, result_dict, value_err, values};
use gyrodrift::log::accept::{Refusal, TimeOrder};
use gyrodrift::{Column, DriveLog};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::{PyKeyError, PyOSError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::sync::Arc;

/// A parsed drive log. Pass it to every method as often as needed; it is never changed.
#[pyclass(name = "Log", module = "gyrodrift", frozen)]
pub struct PyLog {
    pub(crate) log: Arc<DriveLog>,
}

impl PyLog {
    pub(crate) fn new(log: DriveLog) -> PyLog {
        PyLog { log: Arc::new(log) }
    }

    /// The logs of a Python list with their names (`# name:` or "log i").
    pub(crate) fn named(logs: &[PyRef<'_, PyLog>]) -> Vec<(String, Arc<DriveLog>)> {
        logs.iter()
            .enumerate()
            .map(|(i, l)| (l.log.meta.name.clone().filter(|n| !n.is_empty()).unwrap_or_else(|| format!("log {}", i + 1)), l.log.clone()))
            .collect()
    }
}

/// Metadata from a dict: `name`, `bias_s`, `wheelbase_m`, `description`; any other key is
/// kept as text, as an unknown `# key: value` line is.
fn meta_of(v: serde_json::Value) -> PyResult<gyrodrift::LogMeta> {
    let serde_json::Value::Object(mut o) = v else {
        return Err(value_err("meta: expected a dict"));
    };
    let mut other = serde_json::Map::new();
    for k in o.keys().cloned().collect::<Vec<_>>() {
        if !matches!(k.as_str(), "name" | "bias_s" | "wheelbase_m" | "description") {
            let x = o.remove(&k).unwrap_or_default();
            other.insert(k, serde_json::Value::String(x.as_str().map_or_else(|| x.to_string(), str::to_string)));
        }
    }
    o.insert("other".into(), serde_json::Value::Object(other));
    let meta: gyrodrift::LogMeta = serde_json::from_value(serde_json::Value::Object(o)).map_err(|e| value_err(format!("meta: {e}")))?;
    for (k, v) in meta.name.iter().map(|n| ("name", n)).chain(meta.other.iter().map(|(k, v)| (k.as_str(), v))) {
        gyrodrift::log::check_meta_text(k, v).map_err(value_err)?;
    }
    Ok(meta)
}

/// A pickled log's state: its metadata, each row's line, its columns by name.
type LogState<'py> = (Bound<'py, PyDict>, Py<PyAny>, Bound<'py, PyDict>);

/// Named float64 columns (CSV v1 names) from a dict of numpy arrays.
fn columns_of(columns: &Bound<'_, PyDict>) -> PyResult<Vec<(Column, Vec<f64>)>> {
    let mut cols = Vec::new();
    for (k, v) in columns.iter() {
        let name: String = k.extract()?;
        let c = Column::from_name(&name).ok_or_else(|| PyKeyError::new_err(format!("unknown column {name}")))?;
        cols.push((c, values(&v, &name)?));
    }
    Ok(cols)
}

/// Reads a log file; an unreadable file is an OSError, a bad cell a ValueError naming the
/// file, line and column (and, for a logger's raw export a preset reads, the `import_files`
/// call that makes a v1 log of it).
pub(crate) fn read_path(path: &str, order: TimeOrder) -> Result<(DriveLog, Option<String>), Refused> {
    let dir = std::path::Path::new(path);
    if dir.is_dir() {
        let what = match gyrodrift::import::folder_hint(dir) {
            Some(h) => hint_text(&h, "a recording"),
            None => format!("to score every log in it: python -m gyrodrift.fleet {path} --out rows.parquet"),
        };
        return Err(value_err(format!("{path}: a folder, not a log file; {what}")).into());
    }
    if path.contains("://") && !dir.exists() {
        return Err(PyOSError::new_err(format!(
            "{path}: cannot open: Log.read reads local files; gyrodrift.read_log fetches a URL (fsspec)"
        ))
        .into());
    }
    // A gzip-compressed log (drive.csv.gz) reads as the plain file.
    let f = gyrodrift::log::file::open_log(dir).map_err(|e| PyOSError::new_err(format!("{path}: cannot open: {e}")))?;
    gyrodrift::log::accept::parse_by(f, order).map_err(|e| {
        let hint = match gyrodrift::import::import_hint(dir) {
            Some(h) => format!("; {}", hint_text(&h, "a file")),
            None if gyrodrift::import::draft_reads_refused(dir, &e) => {
                format!("; if it is a logger's table, gyrodrift.draft_recipe([{path:?}]) drafts a recipe from its column names")
            }
            None => String::new(),
        };
        let joined = if Refusal::of(&e) == Some(Refusal::Joined) {
            "; gyrodrift.Log.read_joined reads each log in it"
        } else if Refusal::of(&e) == Some(Refusal::ClockReset) {
            "; gyrodrift.Log.read_joined reads each part (a logger restarted?) as a log of its own"
        } else {
            ""
        };
        Refused::of(&e, format!("{path}: {e}{order_hint}{joined}{hint}", order_hint = time_order_hint(&e)))
    })
}

/// `time_order` as given ("error" or "fix").
pub(crate) fn time_order(s: &str) -> PyResult<TimeOrder> {
    match s {
        "error" => Ok(TimeOrder::Error),
        "fix" => Ok(TimeOrder::Fix),
        _ => Err(value_err(format!("time_order \"{s}\": \"error\" or \"fix\""))),
    }
}

/// A failure made without the GIL (inside `detach`): the error, and for a parser's refusal
/// its kind ("time_order", "clock_reset", "joined", "cut_row", "foreign"; core's `accept::Refusal`),
/// which [`Refused::raise`] sets as the ValueError's `code` with the GIL held, so a fleet
/// job tells which reading mends a log without matching the words.
pub(crate) struct Refused {
    err: PyErr,
    code: Option<&'static str>,
}

impl From<PyErr> for Refused {
    fn from(err: PyErr) -> Self {
        Refused { err, code: None }
    }
}

impl Refused {
    /// A parser's refusal `e` as a ValueError with `message`.
    pub(crate) fn of(e: &gyrodrift::Error, message: String) -> Self {
        Refused { err: value_err(message), code: Refusal::of(e).map(Refusal::code) }
    }

    /// The Python error, its `code` set (None for other errors).
    pub(crate) fn raise(self, py: Python<'_>) -> PyErr {
        match self.err.value(py).setattr("code", self.code) {
            Ok(()) => self.err,
            Err(set) => set,
        }
    }
}

/// For a log refused for its time order: the argument that fixes it.
fn time_order_hint(e: &gyrodrift::Error) -> &'static str {
    match Refusal::of(e) == Some(Refusal::TimeOrder) {
        true => "; time_order=\"fix\" merges repeated times and sorts rows up to 1 s late in",
        false => "",
    }
}

/// The log, and what fixing its time order did as a Python UserWarning (`name`: the file).
pub(crate) fn warned(py: Python<'_>, name: &str, (log, fixed): (DriveLog, Option<String>)) -> PyResult<PyLog> {
    if let Some(f) = fixed {
        let message = std::ffi::CString::new(format!("{name}: {f}")).map_err(value_err)?;
        PyErr::warn(py, &py.get_type::<pyo3::exceptions::PyUserWarning>(), &message, 1)?;
    }
    Ok(PyLog::new(log))
}

/// An import hint in Python's words (`what`: a file, a recording): the `import_files` call
/// that makes a v1 log of it.
fn hint_text(h: &gyrodrift::import::ImportHint, what: &str) -> String {
    let files: Vec<String> = h.files.iter().map(|p| format!("{:?}", p.display().to_string())).collect();
    format!(
        "it looks like {what} of {} (import preset {}): gyrodrift.import_files([{}]) makes a v1 drive log of it",
        h.title,
        h.preset,
        files.join(", ")
    )
}

/// For files that failed to read as v1 logs (a fleet's error rows): one hint per folder of
/// a logger's raw exports, as "FOLDER: it looks like a recording of ...", at most
/// `max_folders` folders looked at (core's `folder_hints`).
#[pyfunction]
#[pyo3(signature = (paths, max_folders = 20))]
fn folder_hints(paths: Vec<std::path::PathBuf>, max_folders: usize) -> Vec<String> {
    gyrodrift::import::folder_hints(&paths, max_folders)
        .iter()
        .map(|h| format!("{}: {}", h.folder.display(), hint_text(h, "a recording")))
        .collect()
}

#[pymethods]
impl PyLog {
    /// Reads a CSV v1 log file on this machine (`gyrodrift.read_log` also fetches fsspec URLs).
    /// `time_order="fix"`: a time that repeats or steps back by at most 1 s is put in order
    /// (rows of one time merged by their mean, late rows sorted in; a UserWarning says so).
    #[staticmethod]
    #[pyo3(signature = (path, time_order="error"))]
    fn read(py: Python<'_>, path: std::path::PathBuf, time_order: &str) -> PyResult<PyLog> {
        let (p, order) = (path.display().to_string(), self::time_order(time_order)?);
        let read = py.detach(|| read_path(&p, order)).map_err(|e| e.raise(py))?;
        warned(py, &p, read)
    }

    /// Reads each log of a file that holds several joined on (`cat a.csv b.csv`, a logger
    /// appending each session), which `read` refuses naming the second's first line: a Log
    /// each; what reading one did is a UserWarning naming the line it starts on.
    #[staticmethod]
    #[pyo3(signature = (path, time_order="error"))]
    fn read_joined(py: Python<'_>, path: std::path::PathBuf, time_order: &str) -> PyResult<Vec<PyLog>> {
        let (p, order) = (path.display().to_string(), self::time_order(time_order)?);
        let logs = py
            .detach(|| {
                let f = gyrodrift::log::file::open_log(&path)
                    .map_err(|e| Refused::from(PyOSError::new_err(format!("{p}: cannot open: {e}"))))?;
                gyrodrift::log::accept::parse_joined(f, order).map_err(|e| Refused::of(&e, format!("{p}: {e}{}", time_order_hint(&e))))
            })
            .map_err(|e| e.raise(py))?;
        logs.into_iter().map(|(log, said, line)| warned(py, &format!("{p} (from line {line})"), (log, said))).collect()
    }

    /// Parses CSV v1 text (or as a spreadsheet saves it with `;` and decimal commas; a last
    /// line cut short is dropped with a UserWarning).
    #[staticmethod]
    fn parse(py: Python<'_>, text: &str) -> PyResult<PyLog> {
        let read = py.detach(|| gyrodrift::log::accept::parse_by(text.as_bytes(), TimeOrder::Error));
        let read = read.map_err(|e| Refused::of(&e, e.to_string()).raise(py))?;
        warned(py, "log", read)
    }

    /// Parses a CSV v1 log's bytes, gzip-compressed or not (an object store's file, as the
    /// wasm package's `Log.fromBytes` takes a file's).
    /// `time_order` as for `read`.
    #[staticmethod]
    #[pyo3(signature = (data, time_order="error"))]
    fn from_bytes(py: Python<'_>, data: Vec<u8>, time_order: &str) -> PyResult<PyLog> {
        let order = self::time_order(time_order)?;
        let parse = |r| gyrodrift::log::accept::parse_by(r, order);
        let parsed = py.detach(|| gyrodrift::log::file::decompressed(&data[..]).map_err(gyrodrift::Error::from).and_then(parse));
        let read = parsed.map_err(|e| Refused::of(&e, format!("{e}{}", time_order_hint(&e))).raise(py))?;
        warned(py, "log", read)
    }

    /// A log from float64 columns named as in CSV v1 (`time_s`, `gyro_dps`, ...; NaN = empty
    /// cell) and optional metadata (`name`, `bias_s`, `wheelbase_m`, ...), checked as the
    /// parser checks a file.
    #[staticmethod]
    #[pyo3(signature = (columns, meta=None))]
    fn from_columns(columns: &Bound<'_, PyDict>, meta: Option<&Bound<'_, PyAny>>) -> PyResult<PyLog> {
        let meta = match meta {
            Some(m) => meta_of(from_py("meta", m)?)?,
            None => Default::default(),
        };
        let cols = columns_of(columns)?;
        let n = cols.first().map_or(0, |(_, v)| v.len());
        let lines = (2..n as u64 + 2).collect();
        DriveLog::from_columns(meta, lines, cols).map(PyLog::new).map_err(value_err)
    }

    /// Pickling (multiprocessing, Dask, joblib, `copy.deepcopy`): the metadata, each row's
    /// line in its file and the columns, made a log again by `_from_state` with the
    /// parser's checks. Every value, the line numbers its errors name and the metadata
    /// come back as they were.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, LogState<'py>)> {
        let line = PyArray1::from_vec(py, self.log.line.clone()).into_any().unbind();
        Ok((py.get_type::<PyLog>().getattr("_from_state")?, (self.meta(py)?, line, self.columns(py)?)))
    }

    /// The log `__reduce__` took apart (its metadata as `meta()` gives it: Python floats,
    /// exact, where JSON text would not bring every one back).
    #[staticmethod]
    fn _from_state(meta: &Bound<'_, PyDict>, line: PyReadonlyArray1<'_, u64>, columns: &Bound<'_, PyDict>) -> PyResult<PyLog> {
        let meta: gyrodrift::LogMeta = serde_json::from_value(from_py("meta", meta)?).map_err(|e| value_err(format!("meta: {e}")))?;
        let line = line.as_slice().map_err(value_err)?.to_vec();
        DriveLog::from_columns(meta, line, columns_of(columns)?).map(PyLog::new).map_err(value_err)
    }

    /// `# name:` (None when the file has none).
    #[getter]
    fn name(&self) -> Option<String> {
        self.log.meta.name.clone()
    }

    /// "drive", "robot", "turntable" or "static", from the columns.
    #[getter]
    fn kind(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        crate::to_py(py, &serde_json::to_value(self.log.kind()).map_err(value_err)?)
    }

    /// Whether a reference heading has a value to score against (`report`, `compare` and
    /// `tune` raise on a drive without one; `run_pipeline` and `run_hdr` give its summary).
    #[getter]
    fn has_reference(&self) -> bool {
        self.log.has_reference()
    }

    /// Last minus first time, minutes.
    #[getter]
    fn duration_min(&self) -> f64 {
        self.log.duration_min()
    }

    fn __len__(&self) -> usize {
        self.log.len()
    }

    fn __repr__(&self) -> String {
        let name = self.log.meta.name.as_deref().unwrap_or("unnamed");
        format!("<gyrodrift.Log {name:?}: {} rows, {:.1} min>", self.log.len(), self.log.duration_min())
    }

    /// The `# key: value` metadata as a dict.
    fn meta<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        result_dict(py, &self.log.meta)
    }

    /// The names of the known columns present, in CSV v1 order.
    fn column_names(&self) -> Vec<&'static str> {
        self.log.present_columns().iter().map(|c| c.name()).collect()
    }

    /// One column as a float64 array (NaN = empty cell).
    fn column(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        let c = Column::from_name(name).ok_or_else(|| PyKeyError::new_err(format!("unknown column {name}")))?;
        let v = self.log.column(c).ok_or_else(|| PyKeyError::new_err(format!("{name}: not in this log")))?;
        Ok(array(py, v.to_vec()))
    }

    /// Every present column as a dict of float64 arrays.
    fn columns<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (c, v) in self.log.columns() {
            d.set_item(c.name(), array(py, v.to_vec()))?;
        }
        Ok(d)
    }

    /// The log as CSV v1 text.
    fn to_csv(&self) -> PyResult<String> {
        let mut buf = Vec::new();
        self.log.write_csv(&mut buf).map_err(value_err)?;
        String::from_utf8(buf).map_err(value_err)
    }

    /// The log split at its gaps in time (as the CLI's `--gaps split`): a list of logs, the
    /// parts scored as drives of their own (this log alone when it has no gap).
    #[pyo3(signature = (bias_s=None))]
    fn split_at_gaps<'py>(&self, py: Python<'py>, bias_s: Option<f64>) -> PyResult<Bound<'py, PyList>> {
        let s = gyrodrift::log::gaps::split_at_gaps((*self.log).clone(), Default::default(), self.log.bias_s(bias_s)).map_err(value_err)?;
        PyList::new(py, s.parts.into_iter().map(PyLog::new))
    }
}

/// What a log looks like before any method runs (the CLI's `check`): findings with fixes.
#[pyfunction]
fn check<'py>(py: Python<'py>, log: &PyLog) -> PyResult<Bound<'py, PyDict>> {
    result_dict(py, &gyrodrift::check::check(&log.log))
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(folder_hints, m)?)
}
