//! Every method on logs: the result dicts carry the CLI's `--json` keys; the `run_*`
//! variants add the per-sample series as float64 arrays for plotting.

use crate::log::{read_path, PyLog};
use crate::{array, columns, from_py, result_dict, settings, to_py, value_err};
use gyrodrift as g;
use gyrodrift::hdr::HdrOptions;
use gyrodrift::pipeline::PipelineParams;
use gyrodrift::DriveLog;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

/// `{result, error, ...}` of a run: the Result keys, or None and why there are none.
fn run_dict<'py, T: serde::Serialize>(py: Python<'py>, r: &gyrodrift::Result<T>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    match r {
        Ok(v) => {
            d.set_item("result", result_dict(py, v)?)?;
            d.set_item("error", py.None())?;
        }
        Err(e) => {
            d.set_item("result", py.None())?;
            d.set_item("error", e.to_string())?;
        }
    }
    Ok(d)
}

/// Heuristic Drift Reduction (methods.md, Table III defaults): the Result keys. Raises
/// ValueError when the log has no usable reference heading.
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn hdr<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let opts: HdrOptions = crate::settings("hdr", settings)?;
    let r = py.detach(|| g::hdr::run(&log.log, &opts).and_then(|r| r.result)).map_err(value_err)?;
    result_dict(py, &r)
}

/// HDR with its per-sample series: `{result, error, eps0_dps, summary, trace}` (summary:
/// the estimator's end figures, which need no reference); the trace's arrays are float64
/// (turn_switch as 1.0/0.0).
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn run_hdr<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let opts: HdrOptions = crate::settings("hdr", settings)?;
    let run = py.detach(|| g::hdr::run(&log.log, &opts)).map_err(value_err)?;
    let d = run_dict(py, &run.result)?;
    d.set_item("eps0_dps", run.eps0_dps)?;
    d.set_item("summary", crate::to_py(py, &serde_json::to_value(run.summary(log.log.duration_min())).map_err(value_err)?)?)?;
    let trace = columns(py, &run.trace.columns())?;
    d.set_item("trace", trace)?;
    Ok(d)
}

/// The recommended drift-reduction pipeline (beyond the paper) with raw, Table-III HDR and
/// two peers: the pipeline Result keys.
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn pipeline<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let p: PipelineParams = crate::settings("pipeline", settings)?;
    let r = py.detach(|| gyrodrift::pipeline::run(&log.log, &p).and_then(|r| r.result)).map_err(value_err)?;
    result_dict(py, &r)
}

/// The pipeline with its per-block series: `{result, error, still_source, summary, trace}`
/// (summary: the estimator's end figures, which need no reference: a drive with no GPS
/// course still gets its bias and heading).
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn run_pipeline<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let p: PipelineParams = crate::settings("pipeline", settings)?;
    let run = py.detach(|| gyrodrift::pipeline::run(&log.log, &p)).map_err(value_err)?;
    let d = run_dict(py, &run.result)?;
    d.set_item("still_source", crate::to_py(py, &serde_json::to_value(run.still_source).map_err(value_err)?)?)?;
    d.set_item("summary", crate::to_py(py, &serde_json::to_value(run.summary(log.log.duration_min())).map_err(value_err)?)?)?;
    let trace = columns(py, &run.trace.columns())?;
    d.set_item("trace", trace)?;
    Ok(d)
}

/// Every method's dead-reckoned path (m east and north) at the rows with a speed:
/// `{time_s, raw_x_m, raw_y_m, hdr_x_m, ..., reference_y_m}` as the CLI's `pipeline --track`
/// writes them (the reference's only where the log has one).
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn pipeline_track<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let p: PipelineParams = crate::settings("pipeline", settings)?;
    let t = py.detach(|| gyrodrift::track::Tracks::of(&log.log, &p)).map_err(value_err)?;
    let d = PyDict::new(py);
    d.set_item("time_s", crate::array(py, t.time_s))?;
    for (name, path) in t.paths {
        d.set_item(format!("{name}_x_m"), crate::array(py, path.x_m))?;
        d.set_item(format!("{name}_y_m"), crate::array(py, path.y_m))?;
    }
    Ok(d)
}

/// Gyrodometry on a robot log with wheel travel: the Result keys.
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn gyrodometry<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let o: g::gyrodometry::GyrodometryOptions = crate::settings("gyrodometry", settings)?;
    let r = py.detach(|| g::gyrodometry::run(&log.log, &o).and_then(|r| r.result)).map_err(value_err)?;
    result_dict(py, &r)
}

/// Gyrodometry with its per-row series: `{result, error, eps0_dps, trace}`.
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn run_gyrodometry<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let o: g::gyrodometry::GyrodometryOptions = crate::settings("gyrodometry", settings)?;
    let run = py.detach(|| g::gyrodometry::run(&log.log, &o)).map_err(value_err)?;
    let d = run_dict(py, &run.result)?;
    d.set_item("eps0_dps", run.eps0_dps)?;
    let trace = columns(py, &run.trace.columns())?;
    d.set_item("trace", trace)?;
    Ok(d)
}

/// Fits the rate x temperature error model to a turntable session: the Result keys.
#[pyfunction]
#[pyo3(signature = (log, settings=None))]
fn calibrate<'py>(py: Python<'py>, log: &PyLog, settings: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
    let o: g::calibration::CalibrationOptions = crate::settings("calibration", settings)?;
    let run = py.detach(|| g::calibration::run(&log.log, &o)).map_err(value_err)?;
    result_dict(py, &run.result)
}

/// Overlapping Allan deviation of the gyro column: the Result keys, `tau_s` and `adev_dps`
/// as float64 arrays, and each point's 68 % band under `confidence` (beyond methods.md; the
/// wasm package's and the CLI's).
#[pyfunction]
fn allan<'py>(py: Python<'py>, log: &PyLog) -> PyResult<Bound<'py, PyDict>> {
    let (r, c) = py.detach(|| g::allan::run_with_confidence(&log.log)).map_err(value_err)?;
    let d = result_dict(py, &g::allan::AllanWithConfidence { result: &r, confidence: &c })?;
    d.set_item("tau_s", array(py, r.tau_s.clone()))?;
    d.set_item("adev_dps", array(py, r.adev_dps.clone()))?;
    let conf = d.get_item("confidence")?.ok_or_else(|| value_err("no confidence"))?.cast_into::<PyDict>()?;
    conf.set_item("adev_low_dps", array(py, c.adev_low_dps.clone()))?;
    conf.set_item("adev_high_dps", array(py, c.adev_high_dps.clone()))?;
    Ok(d)
}

/// allantools' convention: `(taus, adevs)` of the overlapping Allan deviation of the gyro
/// column (deg/s), as `allantools.oadev(rate, rate=fs, data_type="freq", taus=...)[:2]`.
#[pyfunction]
fn oadev<'py>(py: Python<'py>, log: &PyLog) -> PyResult<Bound<'py, PyTuple>> {
    let r = py.detach(|| g::allan::run(&log.log)).map_err(value_err)?;
    PyTuple::new(py, [array(py, r.tau_s), array(py, r.adev_dps)])
}

fn logs_of(logs: &[PyRef<'_, PyLog>]) -> Vec<(String, std::sync::Arc<DriveLog>)> {
    PyLog::named(logs)
}

fn borrowed(v: &[(String, std::sync::Arc<DriveLog>)]) -> Vec<(String, &DriveLog)> {
    v.iter().map(|(n, l)| (n.clone(), l.as_ref())).collect()
}

/// The logs as the CLI takes them: one that `check` finds an error in (time not in seconds,
/// heading in radians, gyro in another unit or clockwise; core's `refusal`) is a ValueError
/// naming it and the fix (its `code` "check", its `log` the name), since every figure from it
/// would be absurd, unless `ignore_check`.
fn checked(
    py: Python<'_>,
    named: Vec<(String, std::sync::Arc<DriveLog>)>,
    ignore_check: bool,
) -> PyResult<Vec<(String, std::sync::Arc<DriveLog>)>> {
    if !ignore_check {
        let refused = py.detach(|| named.iter().find_map(|(n, l)| g::log::accept::refusal(l).map(|r| (n.clone(), r))));
        if let Some((name, r)) = refused {
            let err = PyValueError::new_err(format!("{name}: {}", g::log::accept::check_refused(&r, "ignore_check=True")));
            // As the wasm tables' refusal: `code` "check" and the log's name.
            err.value(py).setattr("code", g::log::accept::Refusal::Check.code())?;
            err.value(py).setattr("log", name)?;
            return Err(err);
        }
    }
    Ok(named)
}

/// The drives a table can score, as the CLI's `report`, `compare` and `tune` take them: one
/// without a reference heading (core's `has_reference`) is left out with a UserWarning naming
/// it (the CLI's stderr line); none left to score is a ValueError.
fn scored(py: Python<'_>, logs: &[PyRef<'_, PyLog>], ignore_check: bool) -> PyResult<Vec<(String, std::sync::Arc<DriveLog>)>> {
    let (named, unscored): (Vec<_>, Vec<_>) =
        checked(py, logs_of(logs), ignore_check)?.into_iter().partition(|(_, log)| log.has_reference());
    let unscored: Vec<String> = unscored.into_iter().map(|(name, _)| name).collect();
    for name in &unscored {
        let msg = std::ffi::CString::new(format!("{name}: not scored: no reference heading (ref_heading_deg absent or empty)"))
            .map_err(value_err)?;
        PyErr::warn(py, &py.get_type::<pyo3::exceptions::PyUserWarning>(), &msg, 1)?;
    }
    if named.is_empty() && !unscored.is_empty() {
        return Err(PyValueError::new_err(format!("no drive has a reference heading to score against ({})", unscored.join(", "))));
    }
    Ok(named)
}

/// The HDR paper's Table II over logs (named by `# name:`): the CLI's `report --json`.
#[pyfunction]
#[pyo3(signature = (logs, settings=None, ignore_check=false))]
fn report<'py>(
    py: Python<'py>,
    logs: Vec<PyRef<'py, PyLog>>,
    settings: Option<&Bound<'py, PyAny>>,
    ignore_check: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let opts: HdrOptions = crate::settings("hdr", settings)?;
    let named = scored(py, &logs, ignore_check)?;
    let r = py.detach(|| gyrodrift::report::Report::build(&borrowed(&named), &opts)).map_err(value_err)?;
    result_dict(py, &r)
}

/// Every method side by side (NE_psi per drive): the CLI's `report --compare --json`.
#[pyfunction]
#[pyo3(signature = (logs, settings=None, ignore_check=false))]
fn compare<'py>(
    py: Python<'py>,
    logs: Vec<PyRef<'py, PyLog>>,
    settings: Option<&Bound<'py, PyAny>>,
    ignore_check: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let p: PipelineParams = crate::settings("pipeline", settings)?;
    let named = scored(py, &logs, ignore_check)?;
    let c = py.detach(|| gyrodrift::compare::compare(&borrowed(&named), &p, None)).map_err(value_err)?;
    result_dict(py, &c)
}

/// The robustness battery's error profiles on these drives (core's `battery::on_drives`):
/// `{methods, cases, scoring, added, skipped}`, each case's `ne_psi` in the order of
/// `methods`, as the CLI's `battery --logs --json` but without its tuned-HDR peer.
#[pyfunction]
#[pyo3(signature = (logs, settings=None, ignore_check=false))]
fn battery<'py>(
    py: Python<'py>,
    logs: Vec<PyRef<'py, PyLog>>,
    settings: Option<&Bound<'py, PyAny>>,
    ignore_check: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let p: PipelineParams = crate::settings("pipeline", settings)?;
    let named = checked(py, logs_of(&logs), ignore_check)?;
    let b = py.detach(|| gyrodrift::battery::on_drives(&borrowed(&named), &p)).map_err(value_err)?;
    result_dict(py, &b)
}

/// Table II ("report") or the comparison ("compare") as "markdown", "csv" or "text".
#[pyfunction]
#[pyo3(signature = (logs, table="report", format="markdown", settings=None, ignore_check=false))]
fn table<'py>(
    py: Python<'py>,
    logs: Vec<PyRef<'py, PyLog>>,
    table: &str,
    format: &str,
    settings: Option<&Bound<'py, PyAny>>,
    ignore_check: bool,
) -> PyResult<String> {
    let named = scored(py, &logs, ignore_check)?;
    let drives = borrowed(&named);
    match table {
        "report" => {
            let opts: HdrOptions = crate::settings("hdr", settings)?;
            let r = py.detach(|| gyrodrift::report::Report::build(&drives, &opts)).map_err(value_err)?;
            match format {
                "markdown" => Ok(r.to_markdown()),
                "csv" => Ok(r.to_csv()),
                "text" => Ok(r.to_text()),
                f => Err(PyValueError::new_err(format!("format {f:?}: expected markdown, csv or text"))),
            }
        }
        "compare" => {
            let p: PipelineParams = crate::settings("pipeline", settings)?;
            let c = py.detach(|| gyrodrift::compare::compare(&drives, &p, None)).map_err(value_err)?;
            match format {
                "markdown" => Ok(c.to_markdown()),
                "csv" => Ok(c.to_csv()),
                f => Err(PyValueError::new_err(format!("format {f:?}: expected markdown or csv for the comparison"))),
            }
        }
        t => Err(PyValueError::new_err(format!("table {t:?}: expected report or compare"))),
    }
}

/// Tunes HDR's five parameters on `train` (leave-one-drive-out cross-validated, refusing
/// parameters that do not generalise) and scores Table III against them on both sets.
#[pyfunction]
#[pyo3(signature = (train, test=Vec::new(), settings=None, ignore_check=false))]
fn tune<'py>(
    py: Python<'py>,
    train: Vec<PyRef<'py, PyLog>>,
    test: Vec<PyRef<'py, PyLog>>,
    settings: Option<&Bound<'py, PyAny>>,
    ignore_check: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let opts: g::tune::TuneOptions = crate::settings("tune", settings)?;
    let train = scored(py, &train, ignore_check)?;
    let test = scored(py, &test, ignore_check)?;
    let rep = py
        .detach(|| {
            let hdr_opts = HdrOptions::default();
            let tr = g::tune::prepare_all(&borrowed(&train), &hdr_opts)?;
            let te = g::tune::prepare_all(&borrowed(&test), &hdr_opts)?;
            g::tune::tune_and_report(&tr, &te, &opts)
        })
        .map_err(value_err)?;
    result_dict(py, &rep)
}

/// Simulates a log with known truth, as `gyrodrift simulate` (same seed, same log):
/// `simulate({"kind": "drive", "scenario": "city", "minutes": 20, "seed": 1})`.
#[pyfunction]
#[pyo3(signature = (request=None))]
fn simulate(py: Python<'_>, request: Option<&Bound<'_, PyAny>>) -> PyResult<PyLog> {
    let req: g::sim::SimRequest = settings("simulate", request)?;
    py.detach(|| g::sim::simulate(&req)).map(PyLog::new).map_err(value_err)
}

/// The log with these gyro errors added to its yaw rate, as `gyrodrift inject` (the
/// battery's classes; `battery_profiles()` for its own): `add_gyro_errors(log, {"bias_dps": 1})`.
#[pyfunction]
#[pyo3(signature = (log, errors=None))]
fn add_gyro_errors(py: Python<'_>, log: &PyLog, errors: Option<&Bound<'_, PyAny>>) -> PyResult<PyLog> {
    let e: g::sim::GyroErrors = settings("add_gyro_errors", errors)?;
    let log = log.log.clone();
    py.detach(|| g::sim::inject(&log, &e)).map(PyLog::new).map_err(value_err)
}

/// The robustness battery's gyro error profiles: dicts of name, training and errors.
#[pyfunction]
fn battery_profiles(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let v = serde_json::to_value(g::battery::profiles()).map_err(value_err)?;
    to_py(py, &v)?.into_bound(py).cast_into::<PyList>().map_err(|_| value_err("profiles that are not a list"))
}

/// A recipe given as the path of a TOML or JSON file (read by core, JSON by its extension)
/// or as a dict (the same object as JSON), and the folder of its file.
pub(crate) fn recipe_arg(recipe: &Bound<'_, PyAny>) -> PyResult<(gyrodrift::import::Recipe, Option<std::path::PathBuf>)> {
    if let Ok(path) = recipe.extract::<std::path::PathBuf>() {
        if !path.is_file() {
            return Err(pyo3::exceptions::PyOSError::new_err(format!("{}: cannot read: no such file", path.display())));
        }
        let r = gyrodrift::import::read_recipe(&path).map_err(value_err)?;
        Ok((r, Some(path.parent().map(|p| p.to_path_buf()).unwrap_or_default())))
    } else {
        let r = serde_json::from_value(from_py("recipe", recipe)?).map_err(|e| value_err(format!("recipe: {e}")))?;
        Ok((r, None))
    }
}

/// Imports recorded files by a recipe (a dict, or the path of a TOML or JSON recipe);
/// files are read from `data_dir` (default: the recipe's folder, or the working folder for
/// a dict), which may be a logger's zipped export. Returns `(log, summary)`.
#[pyfunction]
#[pyo3(signature = (recipe, data_dir=None))]
fn import_log<'py>(
    py: Python<'py>,
    recipe: &Bound<'py, PyAny>,
    data_dir: Option<std::path::PathBuf>,
) -> PyResult<(PyLog, Bound<'py, PyDict>)> {
    // The files are confined to the data folder, links followed, as the CLI confines them.
    let (parsed, folder) = recipe_arg(recipe)?;
    let root = data_dir.or(folder).unwrap_or_default();
    let (log, summary) = py.detach(|| gyrodrift::import::import_from_folder(&parsed, &root, false)).map_err(value_err)?;
    Ok((PyLog::new(log), result_dict(py, &summary)?))
}

/// A logger's raw files (paths, their folder, or the .zip it shared) imported by the preset detected from
/// their names and headers: (log, summary, detection) with detection = {preset, title, recipe, used, ignored}.
#[pyfunction]
fn import_files<'py>(py: Python<'py>, paths: Vec<std::path::PathBuf>) -> PyResult<(PyLog, Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let (d, log, summary) = py.detach(|| gyrodrift::import::import_paths(&paths)).map_err(value_err)?;
    let used: Vec<(String, String)> = d.used.iter().map(|(r, f)| (r.to_string(), f.clone())).collect();
    let detection =
        serde_json::json!({ "preset": d.preset, "title": d.title, "recipe": d.recipe_json, "used": used, "ignored": d.ignored });
    Ok((PyLog::new(log), result_dict(py, &summary)?, result_dict(py, &detection)?))
}

/// For raw files no preset reads (paths, or their folder): a draft recipe from their column
/// names, {recipe, guesses}, each guess a line to check before `import_log(recipe, folder)`.
#[pyfunction]
fn draft_recipe<'py>(py: Python<'py>, paths: Vec<std::path::PathBuf>) -> PyResult<Bound<'py, PyDict>> {
    let heads = gyrodrift::import::read_heads(&paths).map_err(value_err)?;
    let d = gyrodrift::import::draft_recipe(&heads).map_err(value_err)?;
    result_dict(py, &serde_json::json!({ "recipe": d.recipe_json, "guesses": d.guesses }))
}

/// What raw files' columns are (paths, or their folder), read from their names and first
/// rows as the draft reads them: {files, yaw_rate, gyro_axes, ...}, each column by its file's
/// index in `files` (the paths' order).
#[pyfunction]
fn column_guesses<'py>(py: Python<'py>, paths: Vec<std::path::PathBuf>) -> PyResult<Bound<'py, PyDict>> {
    let heads = gyrodrift::import::read_heads(&paths).map_err(value_err)?;
    result_dict(py, &gyrodrift::import::column_guesses(&heads).map_err(value_err)?)
}

/// The default settings of a method: "hdr", "pipeline", "gyrodometry", "calibration", "tune".
#[pyfunction]
fn defaults<'py>(py: Python<'py>, method: &str) -> PyResult<Bound<'py, PyDict>> {
    match method {
        "hdr" => result_dict(py, &HdrOptions::default()),
        "pipeline" => result_dict(py, &PipelineParams::default()),
        "gyrodometry" => result_dict(py, &g::gyrodometry::GyrodometryOptions::default()),
        "calibration" => result_dict(py, &g::calibration::CalibrationOptions::default()),
        "tune" => result_dict(py, &g::tune::TuneOptions::default()),
        m => Err(PyValueError::new_err(format!("unknown method {m:?} (hdr, pipeline, gyrodometry, calibration, tune)"))),
    }
}

/// Static bias eps0 (Eq. 2) of a log over its first `bias_s` seconds (the log's, or 20 s).
#[pyfunction]
#[pyo3(signature = (log, bias_s=None))]
fn static_bias(log: &PyLog, bias_s: Option<f64>) -> PyResult<f64> {
    let gyro = log.log.require(gyrodrift::Column::GyroDps, "needed for the static bias").map_err(value_err)?;
    gyrodrift::preprocess::static_bias_dps(log.log.time_s(), gyro, log.log.bias_s(bias_s)).map_err(value_err)
}

/// Reads a log file (the same as `Log.read`).
#[pyfunction]
#[pyo3(signature = (path, time_order="error"))]
fn read_log(py: Python<'_>, path: std::path::PathBuf, time_order: &str) -> PyResult<PyLog> {
    let (p, order) = (path.display().to_string(), crate::log::time_order(time_order)?);
    let read = py.detach(|| read_path(&p, order)).map_err(|e| e.raise(py))?;
    crate::log::warned(py, &p, read)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(hdr, m)?)?;
    m.add_function(wrap_pyfunction!(run_hdr, m)?)?;
    m.add_function(wrap_pyfunction!(pipeline, m)?)?;
    m.add_function(wrap_pyfunction!(run_pipeline, m)?)?;
    m.add_function(wrap_pyfunction!(pipeline_track, m)?)?;
    m.add_function(wrap_pyfunction!(gyrodometry, m)?)?;
    m.add_function(wrap_pyfunction!(run_gyrodometry, m)?)?;
    m.add_function(wrap_pyfunction!(calibrate, m)?)?;
    m.add_function(wrap_pyfunction!(allan, m)?)?;
    m.add_function(wrap_pyfunction!(oadev, m)?)?;
    m.add_function(wrap_pyfunction!(report, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    m.add_function(wrap_pyfunction!(battery, m)?)?;
    m.add_function(wrap_pyfunction!(table, m)?)?;
    m.add_function(wrap_pyfunction!(tune, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(add_gyro_errors, m)?)?;
    m.add_function(wrap_pyfunction!(battery_profiles, m)?)?;
    m.add_function(wrap_pyfunction!(import_log, m)?)?;
    m.add_function(wrap_pyfunction!(import_files, m)?)?;
    m.add_function(wrap_pyfunction!(draft_recipe, m)?)?;
    m.add_function(wrap_pyfunction!(column_guesses, m)?)?;
    m.add_function(wrap_pyfunction!(defaults, m)?)?;
    m.add_function(wrap_pyfunction!(static_bias, m)?)?;
    m.add_function(wrap_pyfunction!(read_log, m)?)?;
    Ok(())
}
