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

    Missing values (NaN, None) are empty cells. ``meta`` holds ``name``, ``bias_s``,
    ``wheelbase_m``, ... as a log's ``# key: value`` lines do.
    """
    columns = {
        c: np.ascontiguousarray(df[c].to_numpy(dtype=np.float64, na_value=np.nan))
        for c in COLUMNS
        if c in df.columns
    }
    return Log.from_columns(columns, dict(meta) if meta else None)


def to_pandas(log: Log) -> Any:
    """The log's columns as a DataFrame (float64; NaN = empty cell)."""
    import pandas as pd

    return pd.DataFrame(log.columns())


def rows_to_pandas(rows: Iterable[Mapping[str, Any]]) -> Any:
    """Fleet rows (``score_file``, ``score_files``, ``score_log``) as a DataFrame with the
    columns in the CLI's order."""
    import pandas as pd

    return pd.DataFrame(list(rows), columns=row_columns())
