"""gyrodrift: a usable heading from a cheap yaw-rate gyro.

The Rust core of the CLI and the wasm package, for Python: HDR, Gyrodometry, gyro
calibration, Allan deviation, the recommended drift-reduction pipeline, comparison and
tuning, the robustness battery on your drives, the recipe import and the simulator.
Results are dicts with the CLI's ``--json`` keys; series are float64 numpy arrays; bad input raises ValueError naming the file, line
and column. ``gyrodrift.fleet`` runs a folder of drives on Dask.
"""

from ._core import (
    COLUMNS,
    GyrodometryEstimator,
    HdrEstimator,
    Log,
    PipelineEstimator,
    add_gyro_errors,
    allan,
    battery,
    battery_profiles,
    calibrate,
    check,
    compare,
    defaults,
    draft_recipe,
    column_guesses,
    error_row,
    folder_hints,
    gyrodometry,
    hdr,
    import_files,
    import_log,
    oadev,
    pipeline,
    report,
    row_columns,
    run_gyrodometry,
    run_hdr,
    run_pipeline,
    pipeline_track,
    score_bytes,
    score_file,
    score_files,
    recipe_endings,
    refusal_hints,
    score_log,
    simulate,
    static_bias,
    summarize,
    summary_markdown,
    table,
    tune,
    version,
)
from . import _core
from .frames import from_pandas, rows_to_pandas, to_pandas
from .remote import fetch, is_url


def read_log(path: "_core.StrPath", time_order: str = "error") -> Log:
    """Reads a CSV v1 log file (gzip-compressed too, ``drive.csv.gz``), from a path or an
    fsspec URL (``s3://bucket/drive.csv``: fetched, then parsed by core). Bad input raises
    ValueError naming the file, line and column; a file that cannot be opened, OSError.
    ``time_order="fix"``: a time that repeats or steps back by at most 1 s is put in order
    (rows of one time merged by their mean, late rows sorted in; a UserWarning says so)."""
    import os

    spec = os.fspath(path)
    if isinstance(spec, str) and is_url(spec):
        data = fetch(spec)
        try:
            return Log.from_bytes(data, time_order)
        except ValueError as e:
            raise ValueError(f"{spec}: {e}") from None
    return _core.read_log(path, time_order)


__version__ = version()

__all__ = [
    "COLUMNS",
    "GyrodometryEstimator",
    "HdrEstimator",
    "Log",
    "PipelineEstimator",
    "add_gyro_errors",
    "allan",
    "battery",
    "battery_profiles",
    "calibrate",
    "check",
    "compare",
    "defaults",
    "draft_recipe",
    "column_guesses",
    "error_row",
    "folder_hints",
    "from_pandas",
    "gyrodometry",
    "hdr",
    "import_files",
    "import_log",
    "oadev",
    "pipeline",
    "read_log",
    "report",
    "row_columns",
    "rows_to_pandas",
    "run_gyrodometry",
    "run_hdr",
    "run_pipeline",
    "pipeline_track",
    "score_bytes",
    "score_file",
    "score_files",
    "recipe_endings",
    "refusal_hints",
    "score_log",
    "simulate",
    "static_bias",
    "summarize",
    "summary_markdown",
    "table",
    "to_pandas",
    "tune",
    "version",
]
