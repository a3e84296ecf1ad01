"""pandas helpers: a Log to and from a DataFrame, fleet rows as a DataFrame.

Type translation only: the columns are CSV v1's (``time_s``, ``gyro_dps``, ...), copied
as float64; core checks them as it checks a file.
"""

from __future__ import annotations

from typing import Any, Iterable, Mapping, Optional

import numpy as np

from ._core import COLUMNS, Log, row_columns


def from_pandas(df: Any, meta: Optional[Mapping[str, Any]] = None) -> Log:
    """A Log from a DataFrame whose columns are named as in CSV v1 (others are ignored).

    The time is the ``time_s`` column, or, without one, a ``DatetimeIndex`` or
    ``TimedeltaIndex`` (a sensor frame's usual index); date-times are seconds since the
    first row, time spans their seconds. Missing values (NaN, None) are empty cells.
    ``meta`` holds ``name``, ``bias_s``, ``wheelbase_m``, ... as a log's ``# key: value``
    lines do.
    """
    import pandas as pd

    columns = {
        c: np.ascontiguousarray(df[c].to_numpy(dtype=np.float64, na_value=np.nan))
        for c in COLUMNS
        if c in df.columns and c != "time_s"
    }
    time = df["time_s"] if "time_s" in df.columns else None
    if time is None and isinstance(df.index, (pd.DatetimeIndex, pd.TimedeltaIndex)):
        time = pd.Series(df.index)
    if time is not None:
        columns["time_s"] = _seconds(pd.Series(time))
    return Log.from_columns(columns, dict(meta) if meta else None)


def read_parquet_frame(path: str) -> Any:
    """A Parquet file (local, or an fsspec URL) as a DataFrame, through pyarrow."""
    import pyarrow.parquet as pq

    from .remote import is_url

    if is_url(path):
        import fsspec

        fs, inner = fsspec.core.url_to_fs(path)
        return pq.read_table(inner, filesystem=fs).to_pandas()
    return pq.read_table(path).to_pandas()


def _seconds(time: Any) -> Any:
    """A time column as float64 seconds: date-times since the first row, time spans as they
    are, numbers as they are."""
    import pandas as pd

    if pd.api.types.is_datetime64_any_dtype(time):
        time = time - time.iloc[0]
    if pd.api.types.is_timedelta64_dtype(time):
        return np.ascontiguousarray(time.dt.total_seconds().to_numpy(dtype=np.float64, na_value=np.nan))
    return np.ascontiguousarray(time.to_numpy(dtype=np.float64, na_value=np.nan))


def to_pandas(log: Log) -> Any:
    """The log's columns as a DataFrame (float64; NaN = empty cell)."""
    import pandas as pd

    return pd.DataFrame(log.columns())


def rows_to_pandas(rows: Iterable[Mapping[str, Any]]) -> Any:
    """Fleet rows (``score_file``, ``score_files``, ``score_log``) as a DataFrame with the
    columns in the CLI's order."""
    import pandas as pd

    return pd.DataFrame(list(rows), columns=row_columns())
