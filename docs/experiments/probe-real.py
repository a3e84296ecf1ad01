#!/usr/bin/env python3
"""The format probe on the recorded drives: each of `../shared/real-logs` imported by its
recipe, and written again with 10 % of its rows dropped and without its `# bias_s:` line
(the 20 s default lead-in). Prints, per drive and variant, the pipeline's NE_psi and the
best simple peer's (raw, Table-III HDR, Fusion offset, ZARU), deg/min.

    python3 docs/experiments/probe-real.py [target/release/gyrodrift] [OUT_DIR]
"""
import csv
import random
import subprocess
import sys
from pathlib import Path

CLI = sys.argv[1] if len(sys.argv) > 1 else "target/release/gyrodrift"
OUT = Path(sys.argv[2] if len(sys.argv) > 2 else "target/probe-real")
PEERS = ["raw", "hdr", "fusion_offset", "zaru"]


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for old in OUT.glob("*"):
        old.unlink()
    rng = random.Random(9)
    for recipe in sorted(Path("sample-logs/recipes").glob("*.toml")):
        src = OUT / f"{recipe.stem}.src"
        subprocess.run([CLI, "import", "--recipe", str(recipe), "--data", "../shared/real-logs", "--out", str(src)], check=True, capture_output=True)
        lines = [l for l in src.read_text().split("\n") if l]
        meta = [l for l in lines if l.startswith("#")]
        body = [l for l in lines if not l.startswith("#")]
        variants = {
            "orig": (meta, body[1:]),
            "dropped": (meta, [r for i, r in enumerate(body[1:]) if i == 0 or rng.random() > 0.1]),
            "no-header": ([l for l in meta if not l.startswith("# bias_s")], body[1:]),
        }
        for name, (m, rows) in variants.items():
            (OUT / f"{recipe.stem}__{name}.csv").write_text("\n".join(m + [body[0]] + rows) + "\n")
        src.unlink()
    rows_csv = OUT / "rows.csv"
    subprocess.run([CLI, "report", "--dir", str(OUT), "--compare", "--out", str(rows_csv)], check=True, capture_output=True)
    print(f"{'drive':<26} {'variant':<10} {'pipeline':>9} {'best peer':>10}")
    for r in sorted(csv.DictReader(rows_csv.open()), key=lambda r: r["file"]):
        drive, variant = Path(r["file"]).stem.split("__")
        if r["error"] or r["not_scored"]:
            print(f"{drive:<26} {variant:<10} {(r['error'] or r['not_scored'])[:60]}")
            continue
        ne = {k: float(r[f"ne_psi_{k}_deg_per_min"]) for k in PEERS + ["pipeline"]}
        print(f"{drive:<26} {variant:<10} {ne['pipeline']:>9.3f} {min(ne[k] for k in PEERS):>10.3f}")


if __name__ == "__main__":
    main()
