"""Can lateral acceleration tell a steady curve from a gyro bias? A feasibility measurement.

A car's yaw rate is its lateral acceleration over its speed (a_lat / v), and a gyro bias
makes no lateral acceleration, so an accelerometer could in principle tell the pipeline's
worst confusion (a steady highway curve read as a bias) apart. This script measures how
well it does on the two Pixel 6a training drives (the battery's training bases with the
speed for it; the WID trials and the VN-100 circle are too short and slow), in 30 s blocks
above 8 m/s, against the GPS course:

    pip install numpy
    python3 docs/experiments/lateral-accel.py ../shared/real-logs/pixel6a-drives/20230806_144805
    python3 docs/experiments/lateral-accel.py ../shared/real-logs/pixel6a-drives/20230809_163741

Frames as in sample-logs/recipes/pixel6a-*.toml: up from the first 30 s of the accelerometer,
the phone's forward axis in the horizontal plane by least squares against d(GPS speed)/dt,
left = up x forward. Not a test: a measurement written up in docs/pipeline.md.
"""
import csv
import sys

import numpy as np

d = sys.argv[1]
gps = {row["time"]: row for row in csv.DictReader(open(d + "/gps.csv"))}
rows = [(r, gps[r["time"]]) for r in csv.DictReader(open(d + "/imu.csv")) if r["time"] in gps]
acc = np.array([[float(r["a_x"]), float(r["a_y"]), -float(r["a_z"])] for r, _ in rows])
gyro = np.array([[float(r["w_x"]), -float(r["w_y"]), float(r["w_z"])] for r, _ in rows])
v = np.array([float(g["speed"]) for _, g in rows])
bearing = np.array([float(g["bearing"]) for _, g in rows])
n = len(v)

up = acc[:30].mean(0)
up /= np.linalg.norm(up)
yaw_rate = gyro @ up  # rad/s, counter-clockwise
e1 = np.cross(up, [1.0, 0.0, 0.0])
e1 /= np.linalg.norm(e1)
e2 = np.cross(up, e1)
horizontal = np.stack([acc @ e1, acc @ e2], 1)
moving = v > 3
design = np.stack([np.gradient(v)[moving], np.ones(moving.sum())], 1)
coef, *_ = np.linalg.lstsq(design, horizontal[moving], rcond=None)
forward = coef[0] / np.linalg.norm(coef[0])
left = np.array([-forward[1], forward[0]])
lateral = horizontal @ left
fast = v > 8
if np.corrcoef(lateral[fast], (v * yaw_rate)[fast])[0, 1] < 0:
    lateral = -lateral  # the least-squares forward axis may point backward
acc_rate = lateral / np.maximum(v, 1.0)

BLOCK = 30
blocks = []
for s in range(0, n - BLOCK, BLOCK):
    if v[s : s + BLOCK].min() < 8:
        continue
    course = np.unwrap(np.radians(-bearing[s : s + BLOCK + 1]))
    blocks.append(
        ((course[-1] - course[0]) / BLOCK, yaw_rate[s : s + BLOCK].mean(),
         acc_rate[s : s + BLOCK].mean(), v[s : s + BLOCK].mean())
    )
blocks = np.array(blocks)
truth, gyro_b, acc_b = np.degrees(blocks[:, :3]).T
speed = blocks[:, 3]
straight = np.abs(truth) < 0.3
curve = np.abs(truth) > 1.0
print(f"{len(blocks)} blocks of {BLOCK} s above 8 m/s: {straight.sum()} straight (|rate| < 0.3 deg/s), "
      f"{curve.sum()} curves (> 1 deg/s)")
print(f"gyro - GPS course rate: mean {np.mean(gyro_b - truth):.3f}, sd {np.std(gyro_b - truth):.3f} deg/s")
print(f"a_lat/v - GPS course rate: mean {np.mean(acc_b - truth):.3f}, sd {np.std(acc_b - truth):.3f} deg/s")
err = acc_b[straight] - truth[straight]
fit = np.stack([np.ones(straight.sum()), 1 / speed[straight]], 1)
c, *_ = np.linalg.lstsq(fit, err, rcond=None)
print(f"straight blocks: a_lat/v offset {err.mean():.3f}, sd {err.std():.3f} deg/s; "
      f"sd {np.std(err - fit @ c):.3f} after fitting offset + c/v in hindsight")
print(f"curves: a_lat/v reads median {np.median(acc_b[curve] / truth[curve]):.2f} of the course rate "
      f"(10-90 %: {np.percentile(acc_b[curve] / truth[curve], 10):.2f} to "
      f"{np.percentile(acc_b[curve] / truth[curve], 90):.2f})")
looks_straight = curve & (np.abs(acc_b - err.mean()) < 0.5)
print(f"curves whose a_lat/v, less the straight offset, is within 0.5 deg/s of straight: "
      f"{looks_straight.sum()} of {curve.sum()}")
