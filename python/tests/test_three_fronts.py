"""The same numbers bit for bit from the three fronts on every sample log: the Python
package, the CLI's --json and the wasm package under Node (all three run core)."""

import json
import shutil
import subprocess

import pytest

import gyrodrift as g
from conftest import ROOT, SAMPLES

WASM = ROOT / "web" / "pkg" / "node" / "gyrodrift.js"

# Each sample's methods: (wasm/python function, CLI command).
CASES = [
    ("train/city-1.csv", ["hdr", "pipeline"]),
    ("train/highway-1.csv", ["hdr", "pipeline"]),
    ("test/rural-3.csv", ["hdr", "pipeline"]),
    ("robot/square.csv", ["gyrodometry", "hdr"]),
    ("turntable/session.csv", ["calibrate"]),
    ("static/static-2h.csv", ["allan"]),
]

NODE = """
const g = require(process.argv[1]);
const fs = require("fs");
const cases = JSON.parse(process.argv[2]);
const out = {};
const plain = (v) => JSON.parse(JSON.stringify(v, (_k, x) => (ArrayBuffer.isView(x) ? Array.from(x) : x)));
for (const [file, methods] of cases) {
  const log = g.Log.parse(fs.readFileSync(file, "utf8"));
  for (const m of methods) {
    const r = m === "allan" ? g.allan(log) : g[m](log, {});
    // Extras the wasm package adds for its plots (not Result keys).
    if (m === "allan") delete r.arw_line_dps;
    if (m === "calibrate") delete r.sets;
    out[file + ":" + m] = plain(r);
  }
}
process.stdout.write(JSON.stringify(out));
"""

PY = {"hdr": g.hdr, "pipeline": g.pipeline, "gyrodometry": g.gyrodometry, "calibrate": g.calibrate, "allan": g.allan}


def exact(a, b, where):
    """Equal bit for bit: the same keys, the same floats (NaN equal to NaN)."""
    if hasattr(a, "tolist"):
        a = a.tolist()
    if hasattr(b, "tolist"):
        b = b.tolist()
    if isinstance(a, dict):
        assert set(a) == set(b), (where, sorted(a), sorted(b))
        for k in a:
            exact(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            exact(x, y, f"{where}[{i}]")
    else:
        assert a == b or (a != a and b != b), (where, a, b)


@pytest.mark.skipif(shutil.which("node") is None or not WASM.exists(), reason="the wasm package (web/pkg) is built by scripts/test.sh")
def test_python_cli_and_wasm_agree_bit_for_bit(cli):
    cases = [(str(SAMPLES / f), ms) for f, ms in CASES]
    wasm = json.loads(subprocess.run(["node", "-e", NODE, str(WASM), json.dumps(cases)], capture_output=True, text=True, check=True).stdout)
    for path, methods in cases:
        log = g.read_log(path)
        for m in methods:
            py = PY[m](log)
            # the CLI's --json, Python and wasm: the Result keys (and allan's confidence band)
            exact(py, cli(m, path, "--json"), f"{path}:{m} python vs CLI")
            exact(py, wasm[f"{path}:{m}"], f"{path}:{m} python vs wasm")


def test_the_wheel_in_a_clean_virtual_environment(cli, tmp_path):
    """pip install of the built wheel alone (numpy comes as its one dependency), then
    `import gyrodrift`: the CLI's numbers, bit for bit."""
    import sys
    import venv

    wheels = sorted((ROOT / "target" / "wheels").glob("gyrodrift-*.whl"))
    assert wheels, "build the wheel first (scripts/test.sh)"
    env = tmp_path / "venv"
    venv.create(env, with_pip=True)
    py = env / "bin" / "python"
    subprocess.run([str(py), "-m", "pip", "install", "-q", "--disable-pip-version-check", str(wheels[-1])], check=True)
    city = str(SAMPLES / "train" / "city-1.csv")
    code = "import json, sys, gyrodrift as g; l = g.read_log(sys.argv[1]); print(json.dumps({'hdr': g.hdr(l), 'pipeline': g.pipeline(l)}))"
    out = json.loads(subprocess.run([str(py), "-c", code, city], capture_output=True, text=True, check=True).stdout)
    exact(out["hdr"], cli("hdr", city, "--json"), "clean venv hdr")
    exact(out["pipeline"], cli("pipeline", city, "--json"), "clean venv pipeline")
    assert sys.prefix != str(env)


RESUME = """
const g = require(process.argv[1]);
const fs = require("fs");
const [file, cut, statePath, outPath] = process.argv.slice(2);
const log = g.Log.parse(fs.readFileSync(file, "utf8"));
const [t, w, v] = ["time_s", "gyro_dps", "speed_mps"].map((c) => log.column(c));
const n = Number(cut);
// Resume Python's state for the rows after the cut; save, at the cut, a state of its own.
const resumed = g.PipelineEstimator.fromState(fs.readFileSync(statePath));
const tail = Array.from(resumed.updateMany(t.subarray(n), w.subarray(n), v.subarray(n)));
const own = new g.PipelineEstimator({ bias_s: 20 });
own.updateMany(t.subarray(0, n), w.subarray(0, n), v.subarray(0, n));
fs.writeFileSync(outPath, own.saveState());
process.stdout.write(JSON.stringify(tail));
"""


@pytest.mark.skipif(shutil.which("node") is None or not WASM.exists(), reason="the wasm package (web/pkg) is built by scripts/test.sh")
def test_a_live_pipeline_saved_in_python_resumes_in_wasm_and_back(tmp_path):
    """The PipelineEstimator's saved state crosses fronts: Python's, resumed in the wasm
    package under Node, and the wasm package's, resumed in Python, each give the
    uninterrupted stream's headings bit for bit."""
    path = str(SAMPLES / "train" / "city-1.csv")
    log = g.read_log(path)
    t, w, v = (log.column(c) for c in ("time_s", "gyro_dps", "speed_mps"))
    whole = g.PipelineEstimator({"bias_s": 20}).update_many(t, w, v).tolist()
    cut = len(t) // 2
    first = g.PipelineEstimator({"bias_s": 20})
    first.update_many(t[:cut], w[:cut], v[:cut])
    (tmp_path / "py.state").write_bytes(first.save_state())
    out = subprocess.run(["node", "-e", RESUME, str(WASM), path, str(cut), str(tmp_path / "py.state"), str(tmp_path / "wasm.state")], capture_output=True, text=True, check=True)
    assert json.loads(out.stdout) == whole[cut:]
    resumed = g.PipelineEstimator.from_state((tmp_path / "wasm.state").read_bytes())
    assert resumed.update_many(t[cut:], w[cut:], v[cut:]).tolist() == whole[cut:]
