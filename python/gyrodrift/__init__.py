"""gyrodrift: a usable heading from a cheap yaw-rate gyro.

The Rust core of the CLI and the wasm package, for Python: HDR, Gyrodometry, gyro
calibration, Allan deviation, the recommended drift-reduction pipeline, comparison and
tuning, the robustness battery on your drives, the recipe import and the simulator.
Results are dicts with the CLI's ``--json`` keys; series are float64 numpy arrays; bad input raises ValueError naming the file, line
and column. ``gyrodrift.fleet`` runs a folder of drives on Dask.
"""

import os
from pathlib import PurePosixPath

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
from .frames import from_pandas, read_parquet_frame, rows_to_pandas, to_pandas
from .remote import fetch, is_url


def read_log(path: "_core.StrPath", time_order: str = "error") -> Log:
    """Reads a CSV v1 log file (gzip-compressed too, ``drive.csv.gz``), or one drive's
    Parquet file (``drive.parquet``, CSV v1's columns, as the fleet job reads a dataset with a
    drive per file; needs pyarrow), from a path or an fsspec URL (``s3://bucket/drive.csv``:
    fetched, then parsed by core). Bad input raises ValueError naming the file, line and
    column (a Parquet file's row); a file that cannot be opened, OSError.
    ``time_order="fix"``: a time that repeats or steps back by at most 1 s is put in order
    (rows of one time merged by their mean, late rows sorted in; a UserWarning says so); a
    CSV's policy: a Parquet file's time must strictly increase."""
    spec = os.fspath(path)
    url = isinstance(spec, str) and is_url(spec)
    if _is_parquet(spec, url):
        return _read_parquet(spec)
    if url:
        data = fetch(spec)
        try:
            return Log.from_bytes(data, time_order)
        except ValueError as e:
            raise ValueError(f"{spec}: {e}") from None
    return _core.read_log(path, time_order)


def _is_parquet(spec: "str | bytes", url: bool) -> bool:
    """A Parquet file: by its name, or (a local file) by its first bytes, ``PAR1``."""
    if os.fsdecode(spec).lower().endswith((".parquet", ".pq")):
        return True
    if url:
        return False
    try:
        with open(spec, "rb") as f:
            return f.read(4) == b"PAR1"
    except OSError:
        return False


def _read_parquet(spec: "str | bytes") -> Log:
    """One drive's Parquet file as a Log named by its file (``drive.parquet`` -> "drive"):
    a table holding several drives (a ``drive`` column with more than one value) is refused,
    naming the fleet job that scores it."""
    name = os.fsdecode(spec)
    try:
        import pyarrow.parquet  # noqa: F401
    except ImportError:
        raise ValueError(f"{name}: a Parquet file; reading it needs pyarrow (pip install 'gyrodrift[fleet]')") from None
    try:
        df = read_parquet_frame(name)
    except OSError:
        raise
    except Exception as e:
        raise ValueError(f"{name}: {e}") from None
    if "drive" in df.columns and df["drive"].nunique() > 1:
        raise ValueError(
            f"{name}: a Parquet table of {df['drive'].nunique()} drives (column 'drive'): score them with "
            "python -m gyrodrift.fleet, or give one drive's rows to gyrodrift.from_pandas"
        )
    try:
        return from_pandas(df, {"name": PurePosixPath(name).stem})
    except ValueError as e:
        raise ValueError(f"{name}: {e}") from None


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
