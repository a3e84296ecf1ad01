//! Fleet rows (core's `fleet`): one dict per drive or part, with every method's E_psi and
//! NE_psi or the error that stopped it, and the fleet's Table II. The GIL is released while
//! core works, so a Dask worker's threads score drives in parallel.

use crate::log::PyLog;
use crate::{from_py, result_dict, value_err};
use gyrodrift::fleet::{self, DriveRow, FleetOptions};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

fn options(obj: Option<&Bound<'_, PyAny>>) -> PyResult<FleetOptions> {
    crate::settings("options", obj)
}

fn rows_list<'py>(py: Python<'py>, rows: &[DriveRow]) -> PyResult<Bound<'py, PyList>> {
    PyList::new(py, rows.iter().map(|r| result_dict(py, r)).collect::<PyResult<Vec<_>>>()?)
}

fn score_path(path: &Path, opts: &FleetOptions) -> Vec<DriveRow> {
    fleet::score_opened(path, gyrodrift::log::file::open_log(path), opts)
}

/// Every part of one log file as row dicts; a file that cannot be read or scored is one row
/// with its `error` (never an exception).
#[pyfunction]
#[pyo3(signature = (path, options=None))]
fn score_file<'py>(py: Python<'py>, path: PathBuf, options: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyList>> {
    let opts = self::options(options)?;
    let rows = py.detach(|| score_path(&path, &opts));
    rows_list(py, &rows)
}

/// One log file's rows from its bytes, fetched by the caller (an object store's file, a
/// gzip-compressed one too): labelled `file` (its URL), a log without `# name:` named by the
/// file's stem, as `score_file` names it; never an exception.
#[pyfunction]
#[pyo3(signature = (file, data, options=None))]
fn score_bytes<'py>(py: Python<'py>, file: String, data: Vec<u8>, options: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyList>> {
    let opts = self::options(options)?;
    let rows = py.detach(|| fleet::score_bytes(&file, &data, &opts));
    rows_list(py, &rows)
}

/// How the file names a recipe (a path or a dict) reads end (".txt", ".csv"): what a fleet
/// folder's files are collected by.
#[pyfunction]
fn recipe_endings(recipe: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    Ok(crate::methods::recipe_arg(recipe)?.0.file_endings())
}

/// Many files on `jobs` threads (0 = one per core), rows in file order. `import_raw`: a
/// logger's raw exports among them are imported by their detected preset and scored, a
/// drive per recording (the CLI's `report --dir --import`), after the logs. `recipe` (a
/// path or a dict): the files that are not v1 logs are read by it instead, a drive per
/// recording (a folder holding the files it names; each file, for a recipe of one table:
/// the CLI's `report --dir --recipe`).
#[pyfunction]
#[pyo3(signature = (paths, jobs=0, options=None, import_raw=false, recipe=None))]
fn score_files<'py>(
    py: Python<'py>,
    paths: Vec<PathBuf>,
    jobs: usize,
    options: Option<&Bound<'py, PyAny>>,
    import_raw: bool,
    recipe: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    let opts = self::options(options)?;
    let recipe = recipe.map(|r| crate::methods::recipe_arg(r).map(|(r, _)| r)).transpose()?;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(jobs).build().map_err(value_err)?;
    let rows: Vec<DriveRow> = py.detach(|| {
        pool.install(|| {
            let mut rows: Vec<DriveRow> = paths.par_iter().flat_map_iter(|p| score_path(p, &opts)).collect();
            if import_raw || recipe.is_some() {
                let recs = fleet::take_recordings(&mut rows, recipe.as_ref());
                rows.extend(recs.par_iter().flat_map_iter(|r| fleet::score_recording(r, recipe.as_ref(), &opts)).collect::<Vec<_>>());
            }
            rows
        })
    });
    rows_list(py, &rows)
}

/// A parsed log's rows; `file` labels them (default: the log's name).
#[pyfunction]
#[pyo3(signature = (log, file=None, options=None))]
fn score_log<'py>(py: Python<'py>, log: &PyLog, file: Option<String>, options: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyList>> {
    let opts = self::options(options)?;
    let name = log.log.meta.name.clone().unwrap_or_else(|| "log".into());
    let file = file.unwrap_or_else(|| name.clone());
    let rows = py.detach(|| fleet::score_log(&file, &name, (*log.log).clone(), &opts));
    rows_list(py, &rows)
}

/// Rows (dicts as the scorers return them) back to core's rows.
fn rows_from(rows: &Bound<'_, PyAny>) -> PyResult<Vec<DriveRow>> {
    let v = from_py("rows", rows)?;
    serde_json::from_value(v).map_err(|e| value_err(format!("rows: {e}")))
}

/// The paper's Table II over fleet rows: per method the drives, mean E_psi and NE_psi,
/// median and p90 NE_psi, drives better than raw; with the files, errors and hours.
#[pyfunction]
fn summarize<'py>(py: Python<'py>, rows: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    result_dict(py, &fleet::summarize(&rows_from(rows)?))
}

/// The error rows another reading mends, a dict per kind (core's `fleet::refusal_hints`):
/// `files`, `why` (words after "1 file " or "N files "), `said` (the two together) and `remedy` (time_order_fix, joined_split,
/// check_each, import_or_recipe, recipe, other_recipe), for the fleet job to name in its
/// options. `import_raw`, `recipe`: how the job read the files that are not v1 logs.
#[pyfunction]
#[pyo3(signature = (rows, import_raw=false, recipe=false))]
fn refusal_hints<'py>(py: Python<'py>, rows: &Bound<'py, PyAny>, import_raw: bool, recipe: bool) -> PyResult<Bound<'py, PyList>> {
    let reading = fleet::ForeignReading::of(import_raw, recipe);
    let hints = fleet::refusal_hints(&fleet::summarize(&rows_from(rows)?).errors_by_code, reading);
    PyList::new(py, hints.iter().map(|h| result_dict(py, h)).collect::<PyResult<Vec<_>>>()?)
}

/// The summary as a Markdown table.
#[pyfunction]
fn summary_markdown(rows: &Bound<'_, PyAny>) -> PyResult<String> {
    Ok(fleet::summarize(&rows_from(rows)?).to_markdown())
}

/// The row of a drive that could not be scored: `file` and why (e.g. a Parquet partition
/// that cannot be read), so engines outside core report failures in the same shape.
#[pyfunction]
fn error_row<'py>(py: Python<'py>, file: &str, message: &str) -> PyResult<Bound<'py, PyDict>> {
    result_dict(py, &DriveRow::failed(file, message))
}

/// The column names of a fleet row, in order (the CLI's `report --dir --out` columns).
#[pyfunction]
fn row_columns() -> Vec<&'static str> {
    fleet::CSV_HEADER.split(',').collect()
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(score_file, m)?)?;
    m.add_function(wrap_pyfunction!(score_files, m)?)?;
    m.add_function(wrap_pyfunction!(recipe_endings, m)?)?;
    m.add_function(wrap_pyfunction!(score_bytes, m)?)?;
    m.add_function(wrap_pyfunction!(score_log, m)?)?;
    m.add_function(wrap_pyfunction!(summarize, m)?)?;
    m.add_function(wrap_pyfunction!(summary_markdown, m)?)?;
    m.add_function(wrap_pyfunction!(refusal_hints, m)?)?;
    m.add_function(wrap_pyfunction!(error_row, m)?)?;
    m.add_function(wrap_pyfunction!(row_columns, m)?)
}
