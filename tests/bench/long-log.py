#!/usr/bin/env python3
"""Writes a long log for the memory and speed figures of BENCHMARKS.md: City 1 (10 Hz)
repeated with shifted times until ROWS rows, with one unknown padding column that the
parser skips (PAD characters a row).

    python3 tests/bench/long-log.py OUT.csv [ROWS=15000000] [PAD=49]

15 M rows with PAD 49 make a 1.15 GB file of 1.5 M s (17 days); 4.5 M rows 125 hours.
"""
import sys
from pathlib import Path

out = sys.argv[1]
rows_wanted = int(sys.argv[2]) if len(sys.argv) > 2 else 15_000_000
pad = "x" * (int(sys.argv[3]) if len(sys.argv) > 3 else 49)
src = Path(__file__).resolve().parents[2] / "sample-logs" / "train" / "city-1.csv"
lines = src.read_text().splitlines()
meta = [l for l in lines if l.startswith("#")]
header, *rows = [l for l in lines if not l.startswith("#")]
period_s = float(rows[-1].split(",", 1)[0]) + 0.1
with open(out, "w") as f:
    f.write("\n".join(meta) + "\n" + header + ",pad\n")
    written, k = 0, 0
    while written < rows_wanted:
        take = rows[: rows_wanted - written]
        f.write("".join(f"{float(t) + k * period_s:.1f},{rest},{pad}\n" for t, rest in (r.split(",", 1) for r in take)))
        written, k = written + len(take), k + 1
