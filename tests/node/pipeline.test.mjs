// The recommended pipeline in the npm package under Node: runPipeline, the streaming
// PipelineEstimator, drives without a reference, the dead-reckoned track; each equal to the
// native CLI.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, readdirSync, mkdtempSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import * as gd from "gyrodrift";
import { ROOT, SAMPLES, cli, plain, drives } from "./helpers.mjs";

test("runPipeline's trace equals the CLI's `pipeline --trace`, the heading's sigma included", () => {
  const file = join(SAMPLES, "train", "city-1.csv");
  const out = join(mkdtempSync(join(tmpdir(), "gd-")), "trace.csv");
  cli("pipeline", file, "--trace", out);
  const [head, ...rows] = readFileSync(out, "utf8").trim().split("\n");
  const cols = head.split(",");
  const log = gd.Log.parse(readFileSync(file, "utf8"));
  const run = gd.runPipeline(log, {});
  assert.equal(run.trace.heading_sigma_deg.length, rows.length);
  for (const name of ["time_s", "heading_deg", "heading_sigma_deg", "heading_smoothed_deg", "bias_dps"]) {
    const j = cols.indexOf(name);
    assert.deepEqual(Array.from(run.trace[name]), rows.map((r) => Number(r.split(",")[j])), name);
  }
  assert.ok(run.trace.heading_sigma_deg.every((s) => Number.isFinite(s) && s >= 0));
  // The end figures are core's summary; the final bias is the bank's (the blended series
  // moves by the experts' per block): the last block's bias with the blend off.
  const bank = gd.runPipeline(log, { blend_sigmas: 0 }).trace;
  const last = bank.bias_dps.length - 1;
  assert.equal(run.summary.final_bias_dps, bank.bias_dps[last]);
  assert.equal(run.summary.final_bias_sigma_dps, bank.bias_sigma_dps[last]);
  assert.equal(run.result.final_bias_dps, run.summary.final_bias_dps);
  assert.ok(run.trace.bias_dps.some((b, i) => b !== bank.bias_dps[i]), "the blend moves some block's bias");
  log.free();
});

/** Feeds `log`'s rows (NaN speeds when it has none) to a PipelineEstimator and checks every
 *  closed block's state against runPipeline's trace; returns how many blocks were stops. */
function streamEqualsBatch(log, t, w, v) {
  const tr = gd.runPipeline(log, {}).trace;
  const est = new gd.PipelineEstimator({});
  const blocks = [];
  const block = (i) => Math.floor(t[i] - t[0]); // the batch path's 1 s blocks
  for (let i = 0; i < t.length; i++) {
    est.update(t[i], w[i], v ? v[i] : NaN);
    // The first row of a block closes the one before: its output is the state now.
    if (i > 0 && block(i) !== block(i - 1)) blocks.push(est.state());
  }
  assert.equal(blocks.length, tr.time_s.length - 1);
  assert.ok(blocks.length > 100);
  const shift = tr.heading_deg[0]; // the stream starts at 0; the trace is aligned to the reference
  blocks.forEach((s, j) => {
    assert.equal(s.heading_deg + shift, tr.heading_deg[j], `block ${j}`);
    assert.equal(s.bias_dps, tr.bias_dps[j]);
    assert.equal(s.heading_sigma_deg, tr.heading_sigma_deg[j]);
    assert.equal(s.stop, tr.stop[j] === 1, `block ${j}`);
  });
  assert.throws(() => est.update(t[0], 0, 0), /time must be finite and increase/);
  assert.throws(() => est.updateMany([1e9], [0, 1], [0]), /differ in length/);
  est.free();
  return blocks.filter((s) => s.stop).length;
}

test("PipelineEstimator, fed the rows one by one, gives runPipeline's block headings, bias and sigma", () => {
  const text = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const log = gd.Log.parse(text);
  const [t, w, v] = ["time_s", "gyro_dps", "speed_mps"].map((c) => log.column(c));
  const stops = streamEqualsBatch(log, t, w, v);
  assert.ok(stops > 30, `${stops} stop blocks by speed`);
  assert.throws(() => new gd.PipelineEstimator({ no_such_setting: 1 }), /no_such_setting/);
  assert.throws(() => new gd.PipelineEstimator({ blend_move_dps: -0.1 }), /blend_move_dps: -0.1 is not a number in \[0, 1e6\)/);
  log.free();
  // The same drive with its gyro alone: stops are judged by the gyro against the lead-in.
  const lines = text.split("\n");
  const header = lines.findIndex((l) => l.startsWith("time_s"));
  const keep = lines[header].split(",").map((c, j) => (["time_s", "gyro_dps"].includes(c) ? j : -1)).filter((j) => j >= 0);
  const gyroOnly = lines.map((l, i) => (i < header || !l ? l : keep.map((j) => l.split(",")[j]).join(","))).join("\n");
  const bare = gd.Log.parse(gyroOnly);
  assert.deepEqual(bare.columns(), ["time_s", "gyro_dps"]);
  assert.ok(streamEqualsBatch(bare, t, w, null) > 30, "stop blocks by the gyro");
  bare.free();
});

test("a live estimator saved halfway (saveState) and resumed (fromState) gives the uninterrupted headings and state; foreign bytes throw", () => {
  const log = gd.Log.parse(readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8"));
  const [t, w, v] = ["time_s", "gyro_dps", "speed_mps"].map((c) => log.column(c));
  const robot = gd.Log.parse(readFileSync(join(SAMPLES, "robot", "square.csv"), "utf8"));
  const [rt, rw, l, r] = ["time_s", "gyro_dps", "odo_left_m", "odo_right_m"].map((c) => robot.column(c));
  const cases = [
    [() => new gd.PipelineEstimator({ bias_s: 20 }), (e, i) => e.update(t[i], w[i], v[i]), t.length],
    [() => new gd.HdrEstimator({}, 0.3), (e, i) => e.update(t[i], w[i]), t.length],
    [() => new gd.GyrodometryEstimator(0.34, 1.0, 0.0), (e, i) => e.update(rt[i], rw[i], l[i], r[i]), rt.length],
  ];
  for (const [make, step, n] of cases) {
    const whole = make();
    const full = Array.from({ length: n }, (_, i) => step(whole, i));
    const first = make();
    const cut = Math.floor(n / 2);
    for (let i = 0; i < cut; i++) step(first, i);
    const state = first.saveState();
    assert.ok(state instanceof Uint8Array && state.length > 16);
    const second = first.constructor.fromState(state);
    assert.deepEqual(second.state(), first.state());
    for (let i = cut; i < n; i++) assert.equal(step(second, i), full[i], `${first.constructor.name} row ${i}`);
    assert.deepEqual(second.state(), whole.state());
    for (const e of [whole, first, second]) e.free();
  }
  assert.throws(() => gd.PipelineEstimator.fromState(new TextEncoder().encode("time_s,gyro_dps")), /not a saved gyrodrift state/);
  assert.throws(() => gd.HdrEstimator.fromState(new gd.PipelineEstimator({}).saveState()), /the state is a PipelineEstimator's/);
  log.free();
  robot.free();
});

test("pipeline equals the native CLI; importLog reads a real-log recipe from Node Buffers", () => {
  for (const file of drives.slice(0, 4)) {
    const log = gd.Log.parse(readFileSync(file, "utf8"));
    assert.deepEqual(plain(gd.pipeline(log, {})), JSON.parse(cli("pipeline", file, "--json")), file);
    log.free();
  }
  // The recipe as JSON (the TOML of sample-logs/recipes), files from ../shared/real-logs.
  const real = join(ROOT, "..", "shared", "real-logs");
  let present = true;
  try {
    readdirSync(real);
  } catch {
    present = false;
  }
  if (!present) {
    if (process.env.GYRODRIFT_NO_REAL_LOGS === "1") return console.log("SKIPPED: ../shared/real-logs missing (GYRODRIFT_NO_REAL_LOGS=1)");
    assert.fail(`../shared/real-logs is missing at ${real}; set GYRODRIFT_NO_REAL_LOGS=1 to skip knowingly`);
  }
  const recipe = {
    name: "smartLoc Berlin",
    bias_s: 0,
    table: [
      { id: "odom", file: "Input.txt", format: "whitespace", record: "odom3", columns: ["type", "t", "vx", "vy", "vz", "wx", "wy", "wz"], time: { column: "t" } },
      { id: "gt", file: "GT.txt", format: "whitespace", record: "point3", columns: ["type", "t", "x", "y", "z"], time: { column: "t" } },
    ],
    yaw_rate: { table: "odom", column: "wz", unit: "rad/s", positive: "ccw" },
    positions: { table: "gt", kind: "ecef", columns: ["x", "y", "z"] },
    heading: { source: "positions", min_distance_m: 3, min_speed_mps: 1 },
    speed: { source: "column", table: "odom", column: "vx", unit: "m/s" },
  };
  const files = {
    "Input.txt": readFileSync(join(real, "smartloc-berlin", "Berlin_Potsdamer_Platz_Input.txt")),
    "GT.txt": readFileSync(join(real, "smartloc-berlin", "Berlin_Potsdamer_Platz_GT.txt")),
  };
  const { log, summary } = gd.importLog(recipe, files);
  assert.equal(summary.n_gyro, 1372);
  // The same log as the CLI's import with the shipped TOML recipe.
  const out = join(ROOT, "target", "node-smartloc.csv");
  cli("import", "--recipe", join(ROOT, "sample-logs", "recipes", "smartloc-berlin.toml"), "--data", real, "--out", out);
  const native = JSON.parse(cli("pipeline", out, "--json"));
  const r = plain(gd.pipeline(log, {}));
  assert.equal(r.E_psi_pipeline_deg, native.E_psi_pipeline_deg);
  assert.ok(r.E_psi_pipeline_deg < r.E_psi_hdr_deg && r.E_psi_pipeline_deg < r.E_psi_raw_deg);
  assert.throws(() => gd.importLog({ ...recipe, yaw_rate: { ...recipe.yaw_rate, column: "nope" } }, files), /missing column nope/);
});

test("a drive with speed and no reference heading is a drive: runPipeline gives its trace and says why it is not scored, as the CLI", () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-noref-"));
  const lines = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  const r = lines[h].split(",").indexOf("ref_heading_deg");
  const text = lines.map((l, i) => (i < h || !l ? l : l.split(",").filter((_, j) => j !== r).join(","))).join("\n");
  const file = join(dir, "no-gps.csv");
  writeFileSync(file, text);
  const log = gd.Log.parse(text);
  assert.equal(log.kind, "drive");
  // Core's rule, as Python's has_reference: a ref_heading_deg column with a value.
  assert.equal(log.hasReference, false);
  const blank = gd.Log.parse("time_s,gyro_dps,ref_heading_deg,speed_mps\n0,0.1,,5\n1,0.1,,5\n");
  const one = gd.Log.parse("time_s,gyro_dps,ref_heading_deg,speed_mps\n0,0.1,,5\n1,0.1,90,5\n");
  assert.deepEqual([blank.hasReference, one.hasReference, blank.kind], [false, true, "drive"]);
  blank.free();
  one.free();
  const run = gd.runPipeline(log, {});
  assert.equal(run.result, null);
  assert.match(run.error, /missing column ref_heading_deg/);
  assert.equal(run.errors, null);
  const native = JSON.parse(cli("pipeline", file, "--json"));
  assert.equal(native.not_scored, run.error);
  assert.equal(run.still_source, native.still_source);
  const t = run.trace;
  assert.equal(t.heading_deg[0], 0);
  // The final bias is core's summary's, the bank's (not the blended trace's last block).
  assert.equal(run.summary.final_bias_dps, native.final_bias_dps);
  assert.equal(run.summary.final_bias_sigma_dps, native.final_bias_sigma_dps);
  assert.equal(t.heading_deg[t.heading_deg.length - 1] - t.heading_deg[0], native.heading_change_deg);
  assert.equal(run.summary.heading_change_deg, native.heading_change_deg);
  // Without a speed either, a gyro alone stays a static session (Allan deviation).
  const still = gd.Log.parse("time_s,gyro_dps\n0,0.1\n1,0.1\n2,0.1\n");
  assert.equal(still.kind, "static");
  still.free();
  log.free();
});

test("pipelineTrack: the log's speed integrated along runPipeline's headings, with or without a reference; no speed is a clear Error", () => {
  const text = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const log = gd.Log.parse(text);
  const time = log.column("time_s"), speed = log.column("speed_mps");
  /** Dead reckoning written here, apart from core's: the speed at each row, the heading
   * interpolated at its time (held at the ends). Returns the end point. */
  const end = (tt, psi) => {
    let x = 0, y = 0, j = 0, last = null;
    for (let i = 0; i < time.length; i++) {
      const t = time[i];
      if (Number.isNaN(speed[i])) continue;
      if (last !== null) {
        while (j + 1 < tt.length && tt[j + 1] <= t) j++;
        const h = t <= tt[0] ? psi[0] : j + 1 < tt.length ? psi[j] + ((psi[j + 1] - psi[j]) * (t - tt[j])) / (tt[j + 1] - tt[j]) : psi[j];
        x += speed[i] * (t - last) * Math.cos((h * Math.PI) / 180);
        y += speed[i] * (t - last) * Math.sin((h * Math.PI) / 180);
      }
      last = t;
    }
    return [x, y];
  };
  const close = (p, e) => Math.hypot(p.x_m.at(-1) - e[0], p.y_m.at(-1) - e[1]) < 1e-6 * Math.hypot(...e) + 1e-6;
  const run = gd.runPipeline(log, {});
  const paths = gd.pipelineTrack(log, {});
  assert.ok(paths.pipeline.x_m instanceof Float64Array && paths.smoothed.y_m instanceof Float64Array);
  assert.ok(close(paths.pipeline, end(run.trace.time_s, run.trace.heading_deg)), "causal path's end");
  assert.ok(close(paths.smoothed, end(run.trace.time_s, run.trace.heading_smoothed_deg)), "smoothed path's end");
  // The CLI's `pipeline --track` ends where these paths end (drawing keeps the last point).
  const csv = join(mkdtempSync(join(tmpdir(), "gd-track-")), "track.csv");
  cli("pipeline", join(SAMPLES, "train", "city-1.csv"), "--track", csv);
  const rows = readFileSync(csv, "utf8").trim().split("\n");
  const head = rows[0].split(","), last = rows.at(-1).split(",").map(Number);
  for (const [k, p] of [["pipeline", paths.pipeline], ["smoothed", paths.smoothed]]) {
    assert.deepEqual([p.x_m.at(-1), p.y_m.at(-1)], [last[head.indexOf(`${k}_x_m`)], last[head.indexOf(`${k}_y_m`)]], k);
  }
  // On City 1 the pipeline's path ends nearer the reference path's end than raw integration's.
  const tr = gd.track(log, {});
  const miss = (p) => Math.hypot(p.x_m.at(-1) - tr.reference.x_m.at(-1), p.y_m.at(-1) - tr.reference.y_m.at(-1));
  assert.ok(miss(paths.pipeline) < miss(tr.raw) / 2, `${miss(paths.pipeline)} m against raw ${miss(tr.raw)} m`);
  // A drive without a reference heading still has its paths (headings from 0 deg).
  const lines = text.split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  const r = lines[h].split(",").indexOf("ref_heading_deg");
  const noRef = gd.Log.parse(lines.map((l, i) => (i < h || !l ? l : l.split(",").filter((_, k) => k !== r).join(","))).join("\n"));
  const unscored = gd.runPipeline(noRef, {});
  assert.equal(unscored.result, null);
  assert.ok(close(gd.pipelineTrack(noRef, {}).pipeline, end(unscored.trace.time_s, unscored.trace.heading_deg)), "no reference");
  noRef.free();
  const noSpeed = gd.Log.parse("time_s,gyro_dps,ref_heading_deg\n" + Array.from({ length: 60 }, (_, i) => `${i},0.1,0`).join("\n"));
  assert.throws(() => gd.pipelineTrack(noSpeed, {}), /speed_mps/);
  assert.throws(() => gd.pipelineTrack(log, { bias_s: -1 }), /bias_s/);
  noSpeed.free();
  log.free();
});
