#!/usr/bin/env python3
"""Probe the pipeline on large warm-ups cut from their lead-in, a training population made
after the forty-fourth look (docs/battery.md): there a bend fallback that acted without a
lead-in held off +2 deg/s warm-ups on highways (worst 73x). The battery's training profiles
warm up by 1 deg/s at most and the format probe's by +-1, so neither shows that failure.
60 simulated drives (seeds 8000 + 100 K ..., used nowhere else), every scenario, each in
three groups of 20: a warm-up of 1-3 deg/s of either sign (tau 120-1200 s) cut from its
lead-in; a constant turn-on bias up to 3 deg/s cut from its lead-in (where bends read as
bias cost most); the same warm-ups with their lead-in. Prints, per group, how often the
pipeline is within 1.25x the best simple peer (raw, Table-III HDR, Fusion offset, ZARU)
+ 0.05 deg/min, worse than 2x, worse than raw by more than 10 % (the battery's counts),
the largest ratio and the mean of the ratios.

    python3 docs/experiments/probe-warmups.py [target/release/gyrodrift] [OUT_DIR]

WARM_DRAW=K (default 0) draws other drives; WARM_WORST=N also prints the N largest ratios;
WARM_SET="KEY=VALUE ..." runs the pipeline with those settings.
"""
import csv
import os
import random
import subprocess
import sys
from pathlib import Path

from goals import counts

CLI = sys.argv[1] if len(sys.argv) > 1 else "target/release/gyrodrift"
OUT = Path(sys.argv[2] if len(sys.argv) > 2 else "target/probe-warmups")
PEERS = ["raw", "hdr", "fusion_offset", "zaru"]
GROUPS = ["warm-cut", "bias-cut", "warm-lead"]


def drives():
    draw = int(os.environ.get("WARM_DRAW", "0"))
    rng = random.Random(8117 + draw)
    for i in range(60):
        group = GROUPS[i % 3]
        scenario = rng.choice(["city", "downtown", "suburbs", "rural", "highway", "mixed"])
        minutes = rng.choice([10, 20, 30, 45])
        sign = rng.choice([-1, 1])
        e = {"bias_dps": round(rng.uniform(-1, 1), 3)}
        if group == "bias-cut":
            e["bias_dps"] = round(sign * rng.uniform(0.5, 3), 3)
        else:
            e["warmup_dps"] = round(sign * rng.uniform(1, 3), 3)
            e["warmup_tau_s"] = rng.choice([120, 200, 300, 600, 1200])
        if group != "warm-lead":
            e["cut_lead_in"] = 1
        yield f"{group}_{i:02d}", scenario, minutes, 8000 + 100 * draw + i, e


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for old in OUT.glob("*"):
        old.unlink()
    for name, scenario, minutes, seed, errors in drives():
        args = [CLI, "simulate", "drive", "--scenario", scenario, "--minutes", str(minutes), "--seed", str(seed)]
        args += ["--out", str(OUT / f"{name}.csv")]
        for k, v in errors.items():
            args += ["--error", f"{k}={v}"]
        subprocess.run(args, check=True)
    rows_csv = OUT / "rows.csv"
    sets = [a for kv in os.environ.get("WARM_SET", "").split() for a in ("--set", kv)]
    subprocess.run([CLI, "report", "--dir", str(OUT), "--compare", "--out", str(rows_csv)] + sets, check=True, capture_output=True)
    by, ratios = {}, []
    for r in csv.DictReader(rows_csv.open()):
        stem = Path(r["file"]).stem
        group = stem.rsplit("_", 1)[0]
        if r["error"]:
            print(f"{stem}: {r['error']}")
            continue
        ne = {k: float(r[f"ne_psi_{k}_deg_per_min"]) for k in PEERS + ["pipeline"]}
        best = min(ne[k] for k in PEERS)
        by.setdefault(group, []).append((ne["pipeline"], best, ne["raw"]))
        ratios.append((ne["pipeline"] / best, stem, ne["pipeline"], best, ne["raw"]))
    print(f"{'group':<10} {'drives':>6} {'within 1.25x':>12} {'worse 2x':>9} {'worse raw':>10} {'worst':>7} {'mean ratio':>10}")
    for group in GROUPS + ["all"]:
        rows = [x for g in GROUPS for x in by.get(g, [])] if group == "all" else by.get(group, [])
        if not rows:
            continue
        within, over, raw, worst = counts(rows)
        mean = sum(p / b for p, b, _ in rows) / len(rows)
        print(f"{group:<10} {len(rows):>6} {within:>12} {over:>9} {raw:>10} {worst:>6.2f}x {mean:>10.3f}")
    for ratio, name, p, b, raw in sorted(ratios, reverse=True)[: int(os.environ.get("WARM_WORST", "0"))]:
        print(f"{name:<16} {ratio:6.2f}x  pipeline {p:.3f}  best peer {b:.3f}  raw {raw:.3f}")


if __name__ == "__main__":
    main()
