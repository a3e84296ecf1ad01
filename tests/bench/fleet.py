"""Fleet throughput: N simulated drives scored by the native batch (1 and 2 jobs), by the
Python package in one process, and by the Dask job on a 2-worker LocalCluster; drives/s,
MB/s and peak memory (RSS of the process tree, sampled every 200 ms); and where one
process's time goes (read, parse, methods).

    tools/venv/bin/python tests/bench/fleet.py [--drives 1000] [--minutes 10] [--dir target/fleet-bench]

Run after scripts/test.sh (or build_cli and build_python) on a quiet machine. Prints a
Markdown table for BENCHMARKS.md.
"""

import argparse
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import psutil

ROOT = Path(__file__).resolve().parents[2]
CLI = ROOT / "target" / "release" / "gyrodrift"
PY = sys.executable
SCENARIOS = ["city", "downtown", "suburbs", "rural", "highway", "mixed"]


def make_drives(folder: Path, n: int, minutes: float) -> list:
    import gyrodrift as g

    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for i in range(n):
        p = folder / f"drive-{i:05}.csv"
        if not p.exists():
            log = g.simulate({"kind": "drive", "scenario": SCENARIOS[i % len(SCENARIOS)], "minutes": minutes, "seed": 1000 + i})
            p.write_text(log.to_csv())
        paths.append(p)
    broken = folder / "broken.csv"
    broken.write_text("time_s,gyro_dps,ref_heading_deg\n0,0.1,0\n1,abc,0\n")
    return paths + [broken]


def measured(cmd: list) -> tuple:
    """Wall time and peak RSS (MB) of a command and all its children."""
    t0 = time.perf_counter()
    proc = psutil.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    peak = 0
    while proc.poll() is None:
        try:
            procs = [proc] + proc.children(recursive=True)
            peak = max(peak, sum(p.memory_info().rss for p in procs if p.is_running()))
        except psutil.Error:
            pass
        time.sleep(0.2)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise SystemExit(f"{cmd}: exit {proc.returncode}: {proc.stderr.read().decode()[-2000:]}")
    return wall, peak / 1e6


SINGLE = """
import glob, sys, gyrodrift as g
rows = g.score_files(sorted(glob.glob(sys.argv[1] + "/*.csv")), jobs=1)
assert sum(1 for r in rows if r["error"]) == 1
"""

DASK = """
import sys
from gyrodrift import fleet
if __name__ == "__main__":
    rows = fleet.run(sys.argv[1], sys.argv[2], workers=2, progress=False, processes=sys.argv[3] == "processes")
    assert rows["error"].notna().sum() == 1
"""

STAGES = """
import glob, sys, time, gyrodrift as g
paths = sorted(glob.glob(sys.argv[1] + "/drive-*.csv"))[:200]
t0 = time.perf_counter(); texts = [open(p).read() for p in paths]; t1 = time.perf_counter()
logs = [g.Log.parse(t) for t in texts]; t2 = time.perf_counter()
rows = [g.score_log(l) for l in logs]; t3 = time.perf_counter()
print(f"{t1 - t0:.3f} {t2 - t1:.3f} {t3 - t2:.3f} {len(paths)}")
"""


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--drives", type=int, default=1000)
    ap.add_argument("--minutes", type=float, default=10.0)
    ap.add_argument("--dir", default=str(ROOT / "target" / "fleet-bench"))
    a = ap.parse_args()
    folder = Path(a.dir) / f"{a.drives}x{a.minutes:g}min"
    paths = make_drives(folder, a.drives, a.minutes)
    mb = sum(p.stat().st_size for p in paths) / 1e6
    hours = a.drives * a.minutes / 60
    out = Path(a.dir) / "rows.parquet"
    runs = [
        ("native `report --dir --jobs 1`", [str(CLI), "report", "--dir", str(folder), "--jobs", "1", "--out", str(out)]),
        ("native `report --dir --jobs 2`", [str(CLI), "report", "--dir", str(folder), "--jobs", "2", "--out", str(out)]),
        ("Python, one process (`score_files(jobs=1)`)", [PY, "-c", SINGLE, str(folder)]),
        ("Dask LocalCluster, 2 worker threads (`gyrodrift.fleet`, the default)", [PY, "-c", DASK, str(folder), str(out), "threads"]),
        ("Dask LocalCluster, 2 worker processes (`--processes`)", [PY, "-c", DASK, str(folder), str(out), "processes"]),
    ]
    print(f"{len(paths)} files ({a.drives} drives of {a.minutes:g} min, {hours:.0f} h of driving, one broken file), {mb:.0f} MB, {os.cpu_count()} cores\n")
    print("| run | wall (s) | drives/s | MB/s | peak RSS (MB) |")
    print("|---|---:|---:|---:|---:|")
    for name, cmd in runs:
        wall, peak = measured(cmd)
        print(f"| {name} | {wall:.2f} | {a.drives / wall:.0f} | {mb / wall:.0f} | {peak:.0f} |", flush=True)
    r, p, m, n = subprocess.run([PY, "-c", STAGES, str(folder)], capture_output=True, text=True, check=True).stdout.split()
    total = float(r) + float(p) + float(m)
    print(f"\nOne process, {n} drives: read {float(r):.2f} s ({100 * float(r) / total:.0f} %), parse {float(p):.2f} s ({100 * float(p) / total:.0f} %), methods {float(m):.2f} s ({100 * float(m) / total:.0f} %)")


if __name__ == "__main__":
    main()
