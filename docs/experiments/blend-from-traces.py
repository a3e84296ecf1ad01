#!/usr/bin/env python3
"""The blend of the bank's heading with Table-III HDR's, computed from the two methods'
traces (how the twenty-fifth session measured it before building it: docs/pipeline.md).
For every training case of the battery (or the format probe's logs), the bank's trace
(`pipeline --trace --set blend_sigmas=0`) and HDR's (`hdr --trace`, HDR from the log's
start, as the battery's peer) are blended per 1 s block: the heading moves by the mean of
the two moves where the biases they imply differ by less than K of the bank's bias sigma,
by the bank's alone elsewhere. Prints the goal's counts against the best other method.

    python3 docs/experiments/blend-from-traces.py [K=2] [battery|probe]

probe: the format probe's "as written" logs of PROBE_DRAWS (default "1 2 3 4 5") under
target/probeK (run docs/experiments/probe-formats.py first), against its four peers.
"""
import bisect, csv, glob, json, os, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

from goals import counts

CLI = os.path.abspath("target/release/gyrodrift")
K = float(sys.argv[1]) if len(sys.argv) > 1 else 2.0
WHAT = sys.argv[2] if len(sys.argv) > 2 else "battery"
OUT = "target/blend-traces"


def run(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True).stdout


def rows(path):
    r = [x for x in csv.reader(l for l in open(path) if not l.startswith("#"))]
    return r[0], r[1:]


def reference(path):
    h, body = rows(path)
    ti, ri = h.index("time_s"), h.index("ref_heading_deg")
    ref = [(float(r[ti]), float(r[ri])) for r in body if len(r) > ri and r[ri] != ""]
    rh = [ref[0][1]]
    for _, x in ref[1:]:
        rh.append(rh[-1] + ((x - rh[-1] + 180) % 360 - 180))
    return [t for t, _ in ref], rh


def e_psi(t, psi, rt, rh):
    """methods.md: aligned at the first scored sample, interpolated, mean |error|."""
    k0, errs = None, []
    for tr, r in zip(rt, rh):
        if tr < t[0] or tr > t[-1]:
            continue
        j = bisect.bisect_right(t, tr) - 1
        p = psi[j] if t[j] == tr or j + 1 == len(t) else psi[j] + (psi[j + 1] - psi[j]) * (tr - t[j]) / (t[j + 1] - t[j])
        k0 = r - p if k0 is None else k0
        errs.append(abs(p + k0 - r))
    return sum(errs) / len(errs)


def blended(log):
    """The bank's and the blend's NE_psi numerators (E_psi, deg) for one log."""
    bank, hdr = log + ".bank.csv", log + ".hdr.csv"
    if not os.path.exists(hdr):
        run("pipeline", log, "--set", "blend_sigmas=0", "--trace", bank, "--json")
        run("hdr", log, "--trace", hdr, "--json")
    P, H = list(csv.DictReader(open(bank))), list(csv.DictReader(open(hdr)))
    t = [float(r["time_s"]) for r in P]
    hp = [float(r["heading_deg"]) for r in P]
    sp = [float(r["bias_sigma_dps"]) for r in P]
    th, hh = [float(r["time_s"]) for r in H], [float(r["heading_hdr_deg"]) for r in H]
    hh = [hh[min(max(bisect.bisect_right(th, x) - 1, 0), len(th) - 1)] for x in t]  # the same blocks
    psi, offset = [hp[0]], 0.0
    for n in range(1, len(t)):
        apart = (hh[n] - hh[n - 1]) - (hp[n] - hp[n - 1])
        if abs(apart / (t[n] - t[n - 1])) < K * sp[n - 1]:
            offset += 0.5 * apart
        psi.append(hp[n] + offset)
    rt, rh = reference(log)
    return e_psi(t, hp, rt, rh), e_psi(t, psi, rt, rh)


def cases():
    """(log, duration_min, best other's NE_psi, raw's NE_psi) per case."""
    if WHAT == "probe":
        for d in os.environ.get("PROBE_DRAWS", "1 2 3 4 5").split():
            for log in sorted(glob.glob(f"target/probe{d}/p*_orig.csv")):
                j = json.loads(run("pipeline", log, "--json") or "{}")
                if "duration_min" in j and "NE_psi_raw_deg_per_min" in j:
                    peers = [j[f"NE_psi_{m}_deg_per_min"] for m in ("raw", "hdr", "fusion_offset", "zaru")]
                    yield log, j["duration_min"], min(peers), peers[0]
        return
    os.makedirs(OUT, exist_ok=True)
    b = json.loads(run("battery", "--recipes", "sample-logs/recipes", "--data", "../shared/real-logs", "--split", "training", "--json"))
    m = b["methods"]
    others = [m.index(x) for x in m if x not in ("pipeline", "smoothed")]
    for i, c in enumerate(x for x in b["cases"] if x["training"]):
        log = f"{OUT}/{i}.csv"
        if not os.path.exists(log):
            run("battery", "--recipes", "sample-logs/recipes", "--data", "../shared/real-logs",
                "--write-case", f"{c['base']} / {c['profile']}", "--out", log)
        yield log, c["duration_min"], min(c["ne_psi"][j] for j in others), c["ne_psi"][m.index("raw")]


if __name__ == "__main__":
    cs = list(cases())
    with ThreadPoolExecutor(8) as ex:
        es = list(ex.map(lambda c: blended(c[0]), cs))
    for name, k in (("bank alone", 0), (f"blend at {K} sigma", 1)):
        ne = [e[k] / c[1] for e, c in zip(es, cs)]
        within, over, raw, worst = counts([(x, c[2], c[3]) for x, c in zip(ne, cs)])
        print(f"{WHAT} {name}: {len(cs)} cases, within 1.25x + 0.05 {within}, worse than 2x + 0.05 {over}, worse than raw {raw}, worst {worst:.2f}x, mean {sum(ne) / len(ne):.3f}")
