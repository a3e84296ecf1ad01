"""Fleet batches on Dask distributed: one task per drive (or per chunk of small drives),
every method's E_psi and NE_psi per drive written to Parquet, the fleet's Table II printed.

    python -m gyrodrift.fleet INPUT --out results.parquet [--scheduler tcp://host:8786]

INPUT is a folder of CSV v1 logs (recursive; ``*.csv`` and gzipped ``*.csv.gz``), a glob of
them, or a Parquet dataset with one drive per file or per hive partition
(``drive=KEY/part-0.parquet``) whose columns are named as in CSV v1. Each may be a URL of an
fsspec filesystem instead of a local path (``s3://bucket/drives/``, ``gs://...``; with its
package installed on the workers, e.g. s3fs): each task fetches its own files. Without ``--scheduler`` a LocalCluster starts on this machine; with one, the
same code runs on a real cluster (the workers need this package installed). A drive that
fails is a row with its ``error``; the job goes on. With ``--import`` a logger's raw exports
among the CSV files are imported by their detected preset and scored, a drive per recording
(a folder's files stay in one task), as ``gyrodrift report --dir --import``; with ``--recipe
FILE`` (a logger of your own) the files that are not v1 logs are read by that recipe, a drive
per recording (a folder holding the files it names; each file, for a recipe of one table),
as ``gyrodrift report --dir --recipe``.

The scoring is core's (``score_files``, ``score_log``): nothing is computed here but the
plumbing. ``score_frame`` is the per-drive function for engines that hand over a pandas
DataFrame per group (Spark's ``applyInPandas``, Dask's ``groupby().apply``).
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import posixpath
import sys
from typing import Any, Dict, List, Mapping, Optional, Sequence

from ._core import error_row, folder_hints, recipe_endings, score_bytes, score_files, score_log, summary_markdown
from ._core import refusal_hints as _refusal_hints
from .frames import from_pandas, read_parquet_frame, rows_to_pandas
from .remote import fetch, is_url

#: Small CSV drives are grouped so that a task reads about this many bytes (fewer when the
#: fleet is small: at least about 4 tasks per worker thread).
CHUNK_BYTES = 64 * 1024 * 1024


def score_frame(df: Any, key: Optional[str] = None, options: Optional[Mapping[str, Any]] = None, key_column: str = "drive") -> Any:
    """One drive's rows (a pandas DataFrame with CSV v1 columns) to its fleet rows
    (a DataFrame with ``gyrodrift.row_columns()``). ``key`` labels the rows (default: the
    frame's ``key_column`` value). A drive that fails is a row with its error."""
    return rows_to_pandas(_frame_rows(df, key, options, key_column))


def _frame_rows(df: Any, key: Optional[str], options: Optional[Mapping[str, Any]], key_column: str = "drive") -> List[dict]:
    if key is None:
        key = str(df[key_column].iloc[0]) if key_column in df.columns and len(df) else "drive"
    df = df.sort_values("time_s", kind="stable") if "time_s" in df.columns else df
    try:
        log = from_pandas(df, {"name": key})
    except Exception as e:  # a bad column is the drive's error row, as for a bad file
        return [error_row(key, str(e))]
    return score_log(log, key, options)


def _score_paths(paths: Sequence[str], options: Optional[Mapping[str, Any]], import_raw: bool = False, recipe: Any = None) -> List[dict]:
    return score_files(list(paths), 1, options, import_raw, recipe)


def score_urls(urls: Sequence[str], options: Optional[Mapping[str, Any]] = None) -> List[dict]:
    """Log files at fsspec URLs (``s3://bucket/drive.csv.gz``), each fetched here and scored
    by core from its bytes (``score_bytes``: gzip too, named by the file's stem); a file that
    cannot be fetched is one row with its error."""
    rows: List[dict] = []
    for url in urls:
        try:
            data = fetch(url)
        except Exception as e:  # a missing or unreadable object is its row's error
            rows.append(error_row(url, str(e).removeprefix(f"{url}: ")))
            continue
        rows.extend(score_bytes(url, data, options))
    return rows


def _score_parquet(path: str, key: str, options: Optional[Mapping[str, Any]]) -> List[dict]:
    try:
        df = read_parquet_frame(path)
    except Exception as e:
        return [error_row(key, f"{path}: {e}")]
    return _frame_rows(df, key, options)


class _Listing:
    """The three questions ``find_inputs`` asks of a filesystem, and the name a found file is
    given: a local one (paths as given) or an fsspec one (URLs)."""

    def __init__(self, spec: str) -> None:
        if is_url(spec):
            import fsspec

            self.fs, self.root = fsspec.core.url_to_fs(spec)
            self.root = self.root.rstrip("/") or self.root
        else:
            self.fs, self.root = None, spec

    def isdir(self, path: str) -> bool:
        return self.fs.isdir(path) if self.fs else os.path.isdir(path)

    def subdirs(self, base: str) -> List[str]:
        if self.fs:
            return [d.rstrip("/") for d in self.fs.ls(base, detail=False) if self.fs.isdir(d)]
        return [os.path.join(base, d) for d in os.listdir(base) if os.path.isdir(os.path.join(base, d))]

    def glob(self, pattern: str) -> List[str]:
        return list(self.fs.glob(pattern)) if self.fs else glob.glob(pattern, recursive=True)

    def below(self, base: str, *parts: str) -> str:
        return "/".join((base,) + parts) if self.fs else os.path.join(base, *parts)

    def relative(self, path: str, base: str) -> str:
        return posixpath.relpath(path, base) if self.fs else os.path.relpath(path, base)

    def name(self, path: str) -> str:
        return self.fs.unstrip_protocol(path) if self.fs else path


def find_inputs(spec: str, zips: bool = False, endings: Sequence[str] = ()) -> Dict[str, List[Any]]:
    """What INPUT names: ``{"csv": [paths]}`` or ``{"parquet": [(path, key)]}``; ``zips``: a
    folder's ``*.zip`` files too (a logger's zipped exports, for ``--import``); ``endings``:
    files ending so too (a recipe's tables, ``recipe_endings``, for ``--recipe``). An fsspec
    URL (``s3://bucket/drives/``) names that filesystem's files, as URLs, by the same rules."""
    if is_url(spec) and (zips or endings):
        raise ValueError(f"{spec}: --import and --recipe read local folders only (a recording's files are imported together)")
    ls = _Listing(spec)
    base = ls.root
    if ls.isdir(base):
        hive = sorted(d for d in ls.subdirs(base) if "=" in os.path.basename(d))
        if hive:
            return {"parquet": [(ls.name(d), os.path.basename(d).split("=", 1)[1]) for d in hive]}
        pq_files = sorted(ls.glob(ls.below(base, "**", "*.parquet")))
        if pq_files:
            return {"parquet": [(ls.name(p), os.path.splitext(ls.relative(p, base))[0]) for p in pq_files]}
        exts = ["*.csv", "*.csv.gz"] + (["*.zip"] if zips else []) + ["*" + e for e in endings]
        csv = sorted({p for e in exts for p in ls.glob(ls.below(base, "**", e))})
        if not csv:
            raise ValueError(f"{spec}: no *.csv logs or *.parquet drives in this folder or below")
        return {"csv": [ls.name(p) for p in csv]}
    matched = sorted(ls.glob(base))
    if not matched:
        raise ValueError(f"{spec}: no file matches")
    if all(m.endswith(".parquet") for m in matched):
        return {"parquet": [(ls.name(m), os.path.splitext(os.path.basename(m))[0]) for m in matched]}
    return {"csv": [ls.name(m) for m in matched]}


def _sizes(paths: Sequence[str]) -> Dict[str, int]:
    """Each file's size in bytes (0 when it cannot be found), local or at fsspec URLs."""
    if paths and is_url(paths[0]):
        import fsspec

        fs, _ = fsspec.core.url_to_fs(paths[0])
        out = {}
        for p in paths:
            try:
                out[p] = int(fs.size(p) or 0)
            except (OSError, ValueError):
                out[p] = 0
        return out
    return {p: os.path.getsize(p) if os.path.exists(p) else 0 for p in paths}


def chunks(paths: Sequence[str], chunk_bytes: int = CHUNK_BYTES, keep_folders: bool = False, sizes: Optional[Mapping[str, int]] = None) -> List[List[str]]:
    """Paths grouped so that each group reads about ``chunk_bytes`` (a big file alone);
    ``keep_folders``: a folder's files never split between groups (a recording of raw
    exports is a folder's files together). ``sizes``: the files' sizes (default: looked up)."""
    sizes = sizes if sizes is not None else _sizes(paths)
    units: Dict[str, List[str]] = {}
    for p in paths:
        units.setdefault(os.path.dirname(p) if keep_folders else p, []).append(p)
    out: List[List[str]] = []
    cur: List[str] = []
    size = 0
    for unit in units.values():
        n = sum(sizes.get(p, 0) for p in unit)
        if cur and size + n > chunk_bytes:
            out.append(cur)
            cur, size = [], 0
        cur.extend(unit)
        size += n
    if cur:
        out.append(cur)
    return out


def run(
    spec: str,
    out: Optional[str] = None,
    scheduler: Optional[str] = None,
    workers: int = 2,
    options: Optional[Mapping[str, Any]] = None,
    progress: bool = True,
    chunk_bytes: int = CHUNK_BYTES,
    processes: bool = False,
    import_raw: bool = False,
    recipe: Any = None,
) -> Any:
    """Scores every drive of ``spec`` on Dask; returns the rows as a DataFrame (and writes
    them to ``out`` as Parquet when given). The LocalCluster's workers are threads of this
    process unless ``processes``: core releases the GIL while it scores, so threads run in
    parallel without pickling rows between processes (measured faster: docs/fleet.md).
    ``recipe`` (a path or a dict): the files that are not v1 logs are read by it."""
    from dask.distributed import Client, LocalCluster, wait
    from dask.distributed import progress as dask_progress

    if recipe is not None and not isinstance(recipe, Mapping):
        recipe = os.path.abspath(recipe)  # the workers' working folder may differ
    inputs = find_inputs(spec, zips=import_raw, endings=recipe_endings(recipe) if recipe is not None else ())
    by_folder = import_raw or recipe is not None
    cluster = None
    if scheduler:
        client = Client(scheduler)
    else:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=processes, dashboard_address=None)
        client = Client(cluster)
    try:
        opts = dict(options) if options else None
        if "csv" in inputs:
            # At least about 4 tasks per worker thread, so that no worker idles at the end.
            threads = max(1, sum(client.nthreads().values()))
            sizes = _sizes(inputs["csv"])
            total = sum(sizes.values())
            groups = chunks(inputs["csv"], max(1, min(chunk_bytes, total // (4 * threads))), keep_folders=by_folder, sizes=sizes)
            if is_url(spec):
                futures = client.map(score_urls, groups, options=opts, pure=False)
            else:
                futures = client.map(_score_paths, groups, options=opts, import_raw=import_raw, recipe=recipe, pure=False)
        else:
            paths, keys = zip(*inputs["parquet"])
            futures = client.map(_score_parquet, list(paths), list(keys), options=opts, pure=False)
        if progress and sys.stderr.isatty():
            dask_progress(futures)
        wait(futures)
        results = client.gather(futures)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    rows = rows_to_pandas([r for task in results for r in task])
    if out:
        rows.to_parquet(out, index=False)
    return rows


def summary(rows: Any) -> str:
    """The fleet's Table II (core's) of a rows DataFrame, as Markdown."""
    records = json.loads(rows.to_json(orient="records"))
    return summary_markdown(records)


def refusal_hints(rows: Any, import_raw: bool = False, recipe: Optional[str] = None) -> List[str]:
    """For the error rows another reading mends (core's refusal kinds, ``error_code``, as the
    summary counts them): the fleet option that reads them, once for all. ``import_raw`` and
    ``recipe``: how the job read the files that are not v1 logs (the hint for those differs).
    Core says which kinds, how many and why; this names each remedy in this job's options."""
    own = " reads a logger of your own (sample-logs/recipes/README.md; gyrodrift.draft_recipe([path]) drafts one from its column names)"
    by = {
        "time_order_fix": """--options '{"input": {"time_order": "fix"}}' puts it in order""",
        "joined_split": """--options '{"input": {"joined": "split"}}' scores each log as a drive of its own""",
        "check_each": """gyrodrift.check(gyrodrift.read_log(path)) names each fix (--options '{"input": {"ignore_check": true}}' runs them anyway, with absurd figures)""",
        "import_or_recipe": "--import reads the exports of the loggers it knows (SensorLog, Sensor Logger, phyphox, comma2k19, PX4, ROS); --recipe R: a recipe" + own,
        "recipe": "--recipe R: a recipe" + own,
        "other_recipe": "another recipe" + own,
    }
    records = json.loads(rows.to_json(orient="records"))
    return [f"{h['said']}: {by.get(h['remedy'], h['remedy'])}" for h in _refusal_hints(records, import_raw, recipe is not None)]


def main(argv: Optional[Sequence[str]] = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m gyrodrift.fleet", description=__doc__.split("\n\n")[0])
    ap.add_argument("input", help="folder of CSV logs (*.csv, *.csv.gz), a glob, or a Parquet dataset (a drive per file or per drive=KEY partition); local, or an fsspec URL (s3://bucket/drives/)")
    ap.add_argument("--out", help="write the per-drive rows to this Parquet file")
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster here)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster workers (default 2)")
    ap.add_argument("--processes", action="store_true", help="LocalCluster workers as processes (default: threads; core releases the GIL)")
    ap.add_argument("--import", dest="import_raw", action="store_true", help="import a logger's raw exports among the files (SensorLog, Sensor Logger, phyphox, ...) and score them, a drive per recording")
    ap.add_argument("--recipe", help="read the files that are not v1 logs by this recipe (TOML or JSON; a logger of your own), a drive per recording: a folder holding the files it names, or each file for a recipe of one table")
    ap.add_argument("--options", help='fleet options as JSON, e.g. \'{"input": {"gaps": "error", "time_order": "fix", "joined": "split"}, "pipeline": {"min_still_s": 3}}\'')
    ap.add_argument("--fail-on-error", action="store_true", help="exit 1 when a file could not be scored, once every row is written (a CI job); without it a fleet job exits 0")
    args = ap.parse_args(argv)
    try:
        options = json.loads(args.options) if args.options else None
        if args.recipe and args.import_raw:
            raise ValueError("give --import (the presets) or --recipe (yours), not both")
        rows = run(args.input, args.out, args.scheduler, args.workers, options, processes=args.processes, import_raw=args.import_raw, recipe=args.recipe)
    except (ValueError, OSError) as e:
        print(f"gyrodrift.fleet: {e}", file=sys.stderr)
        return 2
    failed = rows[rows["error"].notna()]
    for _, r in failed.iterrows():
        print(f"{r['file']}: {r['error']}", file=sys.stderr)
    # Folders of a logger's raw exports: the import that makes v1 logs of them, once each.
    for hint in folder_hints(list(failed["file"])):
        print(hint, file=sys.stderr)
    for hint in refusal_hints(rows, args.import_raw, args.recipe):
        print(hint, file=sys.stderr)
    print(summary(rows))
    if args.fail_on_error and len(failed):
        print(f"{len(failed)} of {len(rows)} rows are errors (--fail-on-error)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
