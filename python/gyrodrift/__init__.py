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
    allan,
    battery,
    calibrate,
    check,
    compare,
    defaults,
    error_row,
    gyrodometry,
    hdr,
    import_files,
    import_log,
    oadev,
    pipeline,
    read_log,
    report,
    row_columns,
    run_gyrodometry,
    run_hdr,
    run_pipeline,
    score_file,
    score_files,
    score_log,
    simulate,
    static_bias,
    summarize,
    summary_markdown,
    table,
    tune,
    version,
)
from .frames import from_pandas, rows_to_pandas, to_pandas

__version__ = version()

__all__ = [
    "COLUMNS",
    "GyrodometryEstimator",
    "HdrEstimator",
    "Log",
    "PipelineEstimator",
    "allan",
    "battery",
    "calibrate",
    "check",
    "compare",
    "defaults",
    "error_row",
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
    "score_file",
    "score_files",
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
