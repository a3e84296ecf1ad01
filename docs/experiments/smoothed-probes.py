#!/usr/bin/env python3
"""The offline smoothed mode on the training populations, one line each: the battery's
training cases, the warm-up probe's draws 0-2, the independent generator's draw 0 and the
16 realisations of the shipped sets. training-probes.py quotes the causal pipeline only;
this says how the smoothed mode does on the same logs (made by it: pass its OUT_DIR).

    python3 docs/experiments/smoothed-probes.py [target/release/gyrodrift] PROBES_DIR [VARIANT ...]

A VARIANT is "base" or KEY=VALUE[,KEY=VALUE] set as GD_SMOOTH_KEY in the CLI's environment
(the measuring switches of smoothed-variants.patch, applied and the CLI rebuilt: CLAMP=k,
the smoothed bias held within k causal sigmas of the causal bias; NOFB=1, the smoothed blend
without the bend fallback, as before the sixty-first session; AVG=w, the smoothed heading
w smoothed + (1 - w) causal). Each line: the
cases, the smoothed mean NE_psi (deg/min) and the causal one, the smoothed mode within 1.25x
+ 0.05 and worse than 2x + 0.05 of the best causal method (the battery's rule), worse than
raw by more than 10 %, worse than the causal pipeline by more than 10 %.
"""

import glob
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
ARGS = sys.argv[1:]
CLI = str(Path(ARGS.pop(0)).resolve()) if ARGS and not Path(ARGS[0]).is_dir() else str(ROOT / "target/release/gyrodrift")
PROBES = Path(ARGS.pop(0))
VARIANTS = ARGS or ["base"]
CAUSAL = ["raw", "hdr_table_iii", "hdr_tuned", "fusion_offset", "zaru", "pipeline"]


def env_of(variant):
    env = dict(os.environ)
    if variant != "base":
        for kv in variant.split(","):
            k, v = kv.split("=")
            env["GD_SMOOTH_" + k] = v
    return env


def groups():
    """The probes' logs by population (a log the report refuses is left out, as the probes do)."""
    out = {}
    for d in ["warm-0", "warm-1", "warm-2", "generator-0"]:
        out[d] = sorted(f for f in glob.glob(str(PROBES / d / "*.csv")) if not f.endswith("rows.csv"))
    for part in ["train", "test"]:
        out["16 realisations " + part] = sorted(glob.glob(str(PROBES / "realisation-*" / part / "*.csv")))
    return out


def report_rows(files, env):
    rows = []
    for f in files:
        r = subprocess.run([CLI, "report", "--compare", "--json", f], env=env, capture_output=True, text=True, cwd=ROOT)
        if r.returncode == 0:
            rows += json.loads(r.stdout)["rows"]
    return rows


def battery_rows(env):
    args = [CLI, "battery", "--recipes", "sample-logs/recipes", "--data", "../shared/real-logs", "--split", "training", "--json"]
    d = json.loads(subprocess.run(args, env=env, capture_output=True, text=True, cwd=ROOT, check=True).stdout)
    keys = ["raw", "hdr_table_iii", "fusion_offset", "zaru", "pipeline", "pipeline_smoothed", "hdr_tuned"]
    return [dict(zip(keys, c["ne_psi"])) for c in d["cases"] if c["training"]]


def line(rows):
    n = len(rows)
    sm = [r["pipeline_smoothed"] for r in rows]
    best = [min(r[k] for k in CAUSAL if r.get(k) is not None) for r in rows]
    within = sum(s <= 1.25 * b + 0.05 for s, b in zip(sm, best))
    over = sum(s > 2 * b + 0.05 for s, b in zip(sm, best))
    raw = sum(s > 1.1 * r["raw"] for s, r in zip(sm, rows))
    causal = sum(s > 1.1 * r["pipeline"] for s, r in zip(sm, rows))
    mean_c = sum(r["pipeline"] for r in rows) / n
    return f"{n} cases, smoothed {sum(sm) / n:.3f} (causal {mean_c:.3f}), {within} / {over} / {raw}, worse than the causal {causal}"


def main():
    populations = groups()
    for variant in VARIANTS:
        env = env_of(variant)
        print(variant)
        print(f"  {'battery':22s} {line(battery_rows(env))}")
        for name, files in populations.items():
            print(f"  {name:22s} {line(report_rows(files, env))}")


if __name__ == "__main__":
    main()
