#!/usr/bin/env python3
"""A gyro noisier than the simulator's (0.02-0.12 deg/s per 10 Hz row): white noise of N deg/s
added to every row of simulated drives (scenarios city, suburbs, rural, highway, mixed; seeds
7 and 8, used for no other choice), and the pipeline scored against the best simple peer
(raw, Table-III HDR, Fusion offset, ZARU) as the battery scores it. A training probe.

    python3 docs/experiments/noise-sweep.py [target/release/gyrodrift] [OUT_DIR]

NOISE="0 0.2 0.3 0.5 1" sets the levels (deg/s per row); PROBE_SET="KEY=VALUE ..." runs the
pipeline with those settings; VERBOSE=1 prints every drive.
"""
import itertools
import json
import os
import subprocess
import sys
from pathlib import Path

from goals import counts

CLI = sys.argv[1] if len(sys.argv) > 1 else "target/release/gyrodrift"
OUT = Path(sys.argv[2] if len(sys.argv) > 2 else "target/noise-sweep")
PEERS = ["raw", "hdr", "fusion_offset", "zaru"]


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    sets = [a for kv in os.environ.get("PROBE_SET", "").split() for a in ("--set", kv)]
    print("noise (deg/s per row) | drives | mean pipeline | mean best peer | within 1.25x + 0.05 | worse than 2x + 0.05 | worse than raw | worst")
    for level in os.environ.get("NOISE", "0 0.2 0.3 0.5 1").split():
        rows = []
        for scenario, seed in itertools.product(["city", "suburbs", "rural", "highway", "mixed"], ["7", "8"]):
            # Written afresh every run: logs left by another build's simulator would be
            # scored as if they were this one's.
            log = OUT / f"{scenario}-{seed}-noise-{level}.csv"
            subprocess.run([CLI, "simulate", "drive", "--scenario", scenario, "--seed", seed,
                            "--error", f"noise_dps={level}", "--out", str(log)], check=True)
            out = subprocess.run([CLI, "pipeline", str(log), "--json", *sets], check=True, capture_output=True, text=True)
            r = json.loads(out.stdout)
            best = min(r[f"NE_psi_{p}_deg_per_min"] for p in PEERS)
            rows.append((r["NE_psi_pipeline_deg_per_min"], best, r["NE_psi_raw_deg_per_min"], f"{scenario} {seed}"))
        n = len(rows)
        within, over, raw, worst = counts([r[:3] for r in rows])
        print(f"{level} | {n} | {sum(r[0] for r in rows) / n:.3f} | {sum(r[1] for r in rows) / n:.3f} | {within} | {over} | {raw} | {worst:.2f}x")
        if os.environ.get("VERBOSE"):
            for p, b, _, name in rows:
                print(f"    {name}: pipeline {p:.3f}, best peer {b:.3f}")


main()
