"""A fleet of zipped Sensor Logger exports scored by `report --dir --import`: N copies of a
30-min recording (100 Hz gyro and gravity, 1 Hz location, deflated, 3.4 MB each), the
median wall time of three runs and the rows' check (every drive scored, none an error).

    python3 tests/bench/zip-fleet.py [--zips 12] [--jobs 1] [--dir target/zip-fleet-bench] [--cli PATH]

Run after building the CLI (cargo build --release -p gyrodrift-cli). Standard library only.
"""

import argparse
import io
import json
import math
import random
import statistics
import subprocess
import time
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CLI = ROOT / "target" / "release" / "gyrodrift"


def recording() -> bytes:
    """A 30-min Sensor Logger export, zipped: a slow weave at 10-13 m/s, seeded noise."""
    rnd = random.Random(1)
    t0 = 1763892000000000000
    gyro, grav, loc = [], [], []
    for i in range(180000):
        s = i / 100
        t = t0 + int(s * 1e9)
        gyro.append(f"{t},{s:.4f},0.0004,{0.05 * math.sin(s / 30) + rnd.gauss(0, 0.002):.6f},-0.0002")
        grav.append(f"{t},{s:.4f},0.0,9.80665,0.0")
        if i % 100 == 0:
            bearing = math.degrees(1.5 * math.cos(s / 30)) % 360
            loc.append(f"{t},{s:.4f},2.5,0.4,3.1,4.2,{10 + 3 * math.sin(s / 60):.2f},{bearing:.1f},520.3,11.575,48.137")
    xyz = "time,seconds_elapsed,z,y,x"
    files = {
        "Gyroscope.csv": "\n".join([xyz] + gyro) + "\n",
        "Gravity.csv": "\n".join([xyz] + grav) + "\n",
        "Accelerometer.csv": "\n".join([xyz] + grav) + "\n",
        "Location.csv": "\n".join(["time,seconds_elapsed,bearingAccuracy,speedAccuracy,verticalAccuracy,"
                                   "horizontalAccuracy,speed,bearing,altitude,longitude,latitude"] + loc) + "\n",
        "Metadata.csv": "version,device name,recording epoch time,platform\n3,Pixel 7,1763892000000,android\n",
    }
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, text in files.items():
            z.writestr("Drive/" + name, text)
    return buf.getvalue()


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--zips", type=int, default=12)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--dir", default=str(ROOT / "target" / "zip-fleet-bench"))
    ap.add_argument("--cli", default=str(CLI), help="the gyrodrift binary (another build to compare)")
    a = ap.parse_args()
    folder = Path(a.dir)
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.glob("*.zip"):
        old.unlink()
    z = recording()
    for k in range(a.zips):
        (folder / f"drive{k:02d}.zip").write_bytes(z)
    rows = folder.parent / (folder.name + "-rows.json")
    walls = []
    for _ in range(3):
        start = time.perf_counter()
        subprocess.run([a.cli, "report", "--dir", str(folder), "--import", "--jobs", str(a.jobs), "--out", str(rows)],
                       check=True, capture_output=True)
        walls.append(time.perf_counter() - start)
    scored = json.loads(rows.read_text())
    errors = [r for r in scored if r.get("error")]
    print(f"{a.zips} zips of {len(z) / 1e6:.1f} MB, --jobs {a.jobs}: median {statistics.median(walls):.2f} s "
          f"(runs {', '.join(f'{w:.2f}' for w in walls)}); {len(scored)} rows, {len(errors)} errors")


if __name__ == "__main__":
    main()
