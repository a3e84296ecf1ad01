#!/usr/bin/env python3
"""Every training population a pipeline change is chosen on, one line each: the battery's
training cases, the format probe's draws 1-5, the warm-up probe's draws 0-2, the independent
generator's draw 0, the noise probe and the 16 realisations of the shipped sets. None of
them is a scoring set (docs/battery.md says which sets are looked at only).

    python3 docs/experiments/training-probes.py [target/release/gyrodrift] [OUT_DIR]

BASELINE=DIR (an earlier run's OUT_DIR) also lists what moved against it: the battery's
training cases and the format and warm-up probes' logs whose pipeline NE_psi moved by more
than 5 % + 0.005 deg/min, marking those that crossed a count's line (within 1.25x + 0.05,
worse than 2x + 0.05, worse than raw by any amount). With ONLY= (empty) nothing runs and
OUT_DIR is compared as it is.

Each line is what the session rows of docs/pipeline.md's tried table quote: within 1.25x +
0.05 / worse than 2x + 0.05 / worse than raw, the mean pipeline NE_psi (deg/min) and the
worst ratio to the best other method. Environment variables reach the CLI unchanged, so a
measuring build's switches (`GD_...`) apply to every population. ONLY="battery format"
runs a subset (names: battery format warm generator noise realisations). The battery's JSON
is kept as OUT_DIR/battery-training.json for a case-by-case diff. About a minute and a half on two
cores.
"""
import csv
import json
import os
import re
import subprocess
import sys
from pathlib import Path

from goals import lines
from realisations import rows as realisation_rows

CLI = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "target/release/gyrodrift")
OUT = Path(sys.argv[2] if len(sys.argv) > 2 else "target/training-probes").resolve()
HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def run(args, **env):
    """Runs a command from the repository's root; its stdout."""
    e = dict(os.environ, **{k: str(v) for k, v in env.items()})
    return subprocess.run(args, cwd=ROOT, env=e, check=True, capture_output=True, text=True).stdout


def script(name, out, **env):
    """One of the experiment scripts beside this one, on the CLI; its stdout."""
    return run([sys.executable, str(HERE / name), CLI, str(OUT / out)], **env)


def table_rows(text):
    """The rows of a probe's table: first cell, then the numbers (a trailing x dropped)."""
    rows = {}
    for line in text.splitlines():
        cells = line.split()
        if len(cells) > 4 and cells[1].isdigit():
            rows[cells[0]] = [float(c.rstrip("x")) for c in cells[1:]]
    return rows


def battery():
    data = run([CLI, "battery", "--recipes", "sample-logs/recipes", "--data", "../shared/real-logs", "--split", "training", "--json"])
    (OUT / "battery-training.json").write_text(data)
    t = json.loads(data)["training"]
    pipeline = json.loads(data)["methods"].index("pipeline")
    return (f"{t['n_within']} / {t['n_over_2x']} / {t['n_worse_than_raw']} of {t['n_cases']}, mean {t['mean'][pipeline]:.3f}, "
            f"worst {t['worst_ratio']:.2f}x ({t['worst']})")


def format_probe():
    within = over = raw = 0
    worst = 0.0
    for draw in range(1, 6):
        for w, o, r, x, _ in (v[1:6] for v in table_rows(script("probe-formats.py", f"formats-{draw}", PROBE_DRAW=draw)).values()):
            within, over, raw, worst = within + int(w), over + int(o), raw + int(r), max(worst, x)
    return f"draws 1-5 {within} / {over} / {raw}, worst {worst:.2f}x"


def warm_probe():
    parts = []
    for draw in range(3):
        rows = table_rows(script("probe-warmups.py", f"warm-{draw}", WARM_DRAW=draw))
        a, c = rows["all"], rows["warm-cut"]
        parts.append(f"{a[1]:.0f} / {a[2]:.0f} / {a[3]:.0f} {a[4]:.2f}x (cut warm-ups {c[1]:.0f} / {c[2]:.0f} / {c[3]:.0f} {c[4]:.2f}x)")
    return "draws 0-2 " + "; ".join(parts)


def generator():
    rows = table_rows(script("independent-sim.py", "generator-0", INDEPENDENT_DRAW=0))
    return "draw 0 " + ", ".join(f"{k} {v[1]:.3f} (HDR {v[2]:.3f})" for k, v in rows.items())


def noise():
    means = []
    for line in script("noise-sweep.py", "noise").splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 3 and re.fullmatch(r"[0-9.]+", cells[0]):
            means.append(f"{cells[0]}: {cells[2]} ({cells[7]})")
    return "mean pipeline by noise level " + ", ".join(means)


def realisations():
    out = []
    for part in ["train", "test"]:
        drives = realisation_rows(CLI, OUT, part)
        n = len(drives)
        pipeline, hdr = sum(r["pipeline"] for r in drives), sum(r["hdr_table_iii"] for r in drives)
        out.append(f"{part} {pipeline / n:.3f} (HDR {hdr / n:.3f}, {n} drives)")
    return "; ".join(out)


def moved(before, after, raw, best):
    """A line for one case whose pipeline NE_psi moved, with the count lines it crossed."""
    within, over = lines(best)
    crossed = [name for name, line in [("1.25x", within), ("2x", over), ("raw", raw)] if (before > line) != (after > line)]
    mark = f"  crosses {', '.join(crossed)}" if crossed else ""
    return f"{before:8.3f} -> {after:8.3f}  (raw {raw:.3f}, best other {best:.3f}){mark}"


def changed(before, after):
    """Moved by more than 5 % + 0.005 deg/min."""
    return abs(after - before) > 0.05 * before + 0.005


def compare(base):
    """What moved against an earlier run's OUT_DIR (BASELINE), case by case."""
    lines = []
    old_json, new_json = base / "battery-training.json", OUT / "battery-training.json"
    if old_json.is_file() and new_json.is_file():
        old, new = json.loads(old_json.read_text()), json.loads(new_json.read_text())
        p = new["methods"].index("pipeline")
        before = {(c["base"], c["profile"]): c for c in old["cases"]}
        for c in new["cases"]:
            b = before.get((c["base"], c["profile"]))
            if b and changed(b["ne_psi"][p], c["ne_psi"][p]):
                best = min(v for i, v in enumerate(c["ne_psi"]) if i not in (p, new["methods"].index("smoothed")))
                lines.append(f"battery  {c['base']} / {c['profile']:<34} " + moved(b["ne_psi"][p], c["ne_psi"][p], c["ne_psi"][0], best))
    for kind in ["formats", "warm"]:
        for rows_csv in sorted(OUT.glob(f"{kind}-*/rows.csv")):
            old_csv = base / rows_csv.parent.name / "rows.csv"
            if not old_csv.is_file():
                continue
            key = lambda r: Path(r["file"]).name
            ne = lambda r, m: float(r[f"ne_psi_{m}_deg_per_min"] or "nan")
            before = {key(r): r for r in csv.DictReader(old_csv.open())}
            for r in csv.DictReader(rows_csv.open()):
                b = before.get(key(r))
                if b and changed(ne(b, "pipeline"), ne(r, "pipeline")):
                    best = min(ne(r, m) for m in ["raw", "hdr", "fusion_offset", "zaru"])
                    lines.append(f"{rows_csv.parent.name:<11}{key(r):<30} " + moved(ne(b, "pipeline"), ne(r, "pipeline"), ne(r, "raw"), best))
    return lines


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    probes = {"battery": battery, "format": format_probe, "warm": warm_probe, "generator": generator, "noise": noise,
              "realisations": realisations}
    only = os.environ.get("ONLY", " ".join(probes)).split()
    for name in only:
        print(f"{name:<12} {probes[name]()}", flush=True)
    if os.environ.get("BASELINE"):
        lines = compare(Path(os.environ["BASELINE"]).resolve())
        print(f"moved against {os.environ['BASELINE']}: {len(lines)}")
        print("\n".join(lines))


if __name__ == "__main__":
    main()
