#!/usr/bin/env python3
"""Do straight roads run in a few dominant directions (a street grid)? A measurement for
heading evidence the pipeline does not use (docs/pipeline.md, "Evidence it does not use:
dominant road directions"). Borenstein's Heuristic Drift Elimination snaps a walker's
heading to a building's dominant directions; on roads it would need straight stretches
whose headings lie within a degree or two of a grid.

    python3 docs/experiments/dominant-directions.py LOG.csv ...

For each v1 log with a reference heading: the straight stretches of its reference (the
unwrapped heading within 4 deg of the stretch's first sample for at least 15 s, above
5 m/s), their concentration about one direction mod 90 deg (the duration-weighted mean
resultant length R of 4 x heading; about 1 / sqrt(stretches) for headings at random, 1 for
an exact grid), the dominant direction, how far each stretch lies from it (counts in 5 deg
bins of |deviation|) and how many lie within 1 deg. Needs no package.
"""
import csv
import math
import sys

MIN_S, TOL_DEG, MIN_SPEED = 15.0, 4.0, 5.0


def samples(path):
    """(time, unwrapped reference heading, speed or nan) for every reference sample."""
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    head = rows[0]
    it, ir = head.index("time_s"), head.index("ref_heading_deg")
    isp = head.index("speed_mps") if "speed_mps" in head else None
    out, prev = [], None
    for r in rows[1:]:
        if r[ir] == "":
            continue
        v = float(r[ir])
        if prev is not None:
            v -= 360 * round((v - prev) / 360)
        prev = v
        speed = float(r[isp]) if isp is not None and r[isp] != "" else float("nan")
        out.append((float(r[it]), v, speed))
    return out


def stretches(x):
    """(start, end, mean heading) of each straight stretch."""
    found, i = [], 0
    while i < len(x):
        j = i
        while j + 1 < len(x) and abs(x[j + 1][1] - x[i][1]) < TOL_DEG and x[j + 1][0] - x[j][0] < 3 and not x[j + 1][2] < MIN_SPEED:
            j += 1
        if x[j][0] - x[i][0] >= MIN_S and not x[i][2] < MIN_SPEED:
            found.append((x[i][0], x[j][0], sum(v for _, v, _ in x[i : j + 1]) / (j - i + 1)))
            i = j + 1
        else:
            i += 1
    return found


def main():
    print(f"{'log':32} {'stretches':>9} {'R':>5} {'random':>6} {'dominant':>8}  |deviation| in 5 deg bins      within 1 deg")
    for path in sys.argv[1:]:
        s = stretches(samples(path))
        if len(s) < 3:
            print(f"{path.split('/')[-1][:32]:32} {len(s):9d}  (too few)")
            continue
        w = [b - a for a, b, _ in s]
        c = sum(wi * math.cos(math.radians(4 * v)) for wi, (_, _, v) in zip(w, s))
        n = sum(wi * math.sin(math.radians(4 * v)) for wi, (_, _, v) in zip(w, s))
        r = math.hypot(c, n) / sum(w)
        random_r = math.sqrt(sum(wi * wi for wi in w)) / sum(w)
        mu = math.degrees(math.atan2(n, c)) / 4
        dev = [abs((v - mu + 45) % 90 - 45) for _, _, v in s]
        bins = [0] * 9
        for d in dev:
            bins[min(int(d / 5), 8)] += 1
        near = sum(d < 1 for d in dev)
        print(f"{path.split('/')[-1][:32]:32} {len(s):9d} {r:5.2f} {random_r:6.2f} {mu % 90:8.1f}  {str(bins):30} {near:3d} of {len(s)}")


if __name__ == "__main__":
    main()
