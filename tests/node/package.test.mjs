// The npm package under Node: same numbers as the native CLI bit for bit, errors, the
// fleet example. Run: node --test tests/node/
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, readdirSync, mkdtempSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { execFileSync } from "node:child_process";
import * as gd from "gyrodrift";
import { ROOT, SAMPLES, cli, plain } from "./helpers.mjs";

const drives = ["train", "test"].flatMap((d) =>
  readdirSync(join(SAMPLES, d)).filter((f) => f.endsWith(".csv")).sort().map((f) => join(SAMPLES, d, f)),
);

test("hdr on every sample drive equals the native CLI bit for bit", () => {
  for (const file of drives) {
    const log = gd.Log.parse(readFileSync(file, "utf8"));
    for (const [opts, args] of [[{}, []], [{ resample: false, i_c_dps: 0.01 }, ["--no-resample", "--set", "i_c=0.01"]]]) {
      const native = JSON.parse(cli("hdr", file, "--json", ...args));
      assert.deepEqual(plain(gd.hdr(log, opts)), native, file);
    }
    log.free();
  }
});

test("gyrodometry, calibrate and allan equal the native CLI", () => {
  for (const f of readdirSync(join(SAMPLES, "robot"))) {
    const file = join(SAMPLES, "robot", f);
    const log = gd.Log.parse(readFileSync(file, "utf8"));
    assert.deepEqual(plain(gd.gyrodometry(log, {})), JSON.parse(cli("gyrodometry", file, "--json")), file);
  }
  const tt = join(SAMPLES, "turntable", "session.csv");
  const cal = plain(gd.calibrate(gd.Log.parse(readFileSync(tt, "utf8")), {}));
  delete cal.sets;
  const nativeCal = JSON.parse(cli("calibrate", tt, "--json"));
  assert.deepEqual(cal, nativeCal);
  const st = join(SAMPLES, "static", "static-2h.csv");
  const al = plain(gd.allan(gd.Log.parse(readFileSync(st, "utf8"))));
  assert.ok(al.arw_line_dps.length === al.tau_s.length);
  delete al.arw_line_dps; // the plotting helper; the rest are the Result keys
  // The whole result, confidence band (beyond methods.md) included, equals the CLI's JSON,
  // and the band matches the CLI's text table.
  assert.deepEqual(al, JSON.parse(cli("allan", st, "--json")));
  const conf = al.confidence;
  const text = cli("allan", st);
  const band = text.match(/68 % band +([\d.]+) to ([\d.]+) deg\/s; the minimum could lie anywhere in tau ([\d.]+) to ([\d.]+) s/);
  assert.equal(conf.bias_instability_low_dps.toFixed(6), band[1]);
  assert.equal(conf.bias_instability_high_dps.toFixed(6), band[2]);
  assert.deepEqual(conf.tau_min_range_s, [Number(band[3]), Number(band[4])]);
  assert.equal(conf.adev_low_dps.length, al.tau_s.length);
});

test("bad input throws an Error with line and column, and the module keeps working", () => {
  assert.throws(() => gd.Log.parse("time_s,gyro_dps\n0,1\n0.1,1.2.3\n"), {
    name: "Error",
    message: 'line 3, column gyro_dps: "1.2.3" is not a number',
  });
  assert.throws(() => gd.Log.parse("gyro_dps\n1\n"), /missing required column time_s/);
  assert.throws(() => gd.hdr(gd.Log.parse("time_s,gyro_dps\n0,1\n1,2\n"), {}), /missing column ref_heading_deg/);
  assert.throws(() => gd.hdr(gd.Log.parse(readFileSync(drives[0], "utf8")), { tau_s: "x" }), /hdr options: parameter tau_s: invalid type/);
  const est = new gd.HdrEstimator({}, 0);
  est.update(0, 0.1);
  assert.throws(() => est.update(0, 0.1), /not after/);
  assert.equal(typeof est.update(1, 0.1), "number");
  const ok = gd.hdr(gd.Log.parse(readFileSync(drives[0], "utf8")), {});
  assert.ok(ok.E_psi_hdr_deg > 0);
});

test("simulate in wasm writes the same sample log as the native CLI", () => {
  const log = gd.simulate({ kind: "turntable", seed: 401, name: "Turntable session" });
  assert.equal(log.toCsv(), readFileSync(join(SAMPLES, "turntable", "session.csv"), "utf8"));
});

test("addGyroErrors and simulate's errors equal the native CLI's inject; bad errors name the field", () => {
  const file = join(SAMPLES, "test", "city-3.csv");
  const log = gd.Log.parse(readFileSync(file, "utf8"));
  const before = log.toCsv();
  const profiles = gd.batteryProfiles();
  const mems = profiles.find((p) => p.name === "cheap MEMS A cut");
  assert.ok(mems && mems.training && mems.errors.cut_lead_in, JSON.stringify(mems));
  const worse = gd.addGyroErrors(log, { ...mems.errors, seed: 4 });
  assert.equal(worse.toCsv(), cli("inject", file, "--profile", "cheap MEMS A cut", "--error", "seed=4"));
  const sim = gd.simulate({ kind: "drive", scenario: "rural", minutes: 2, seed: 3, errors: { bias_dps: -1.5, gyro_only: true } });
  assert.equal(sim.toCsv(), cli("simulate", "drive", "--scenario", "rural", "--minutes", "2", "--seed", "3", "--error", "bias_dps=-1.5", "--error", "gyro_only=1"));
  assert.throws(() => gd.addGyroErrors(log, { scale: "x" }), /addGyroErrors options: parameter scale/);
  assert.throws(() => gd.addGyroErrors(log, { noise_dps: -1 }), /noise_dps/);
  assert.throws(() => gd.simulate({ errors: { bias: 1 } }), /bias/);
  // The log given is untouched.
  assert.equal(log.toCsv(), before);
});

test("the Node fleet example prints the same report as the CLI", () => {
  const dir = join(SAMPLES, "train");
  const out = execFileSync("node", [join(ROOT, "examples", "node", "report.mjs"), dir], { encoding: "utf8" });
  const files = readdirSync(dir).filter((f) => f.endsWith(".csv")).sort().map((f) => join(dir, f));
  assert.equal(out, cli("report", "--markdown", ...files));
  assert.match(out, /\| City 1 \|/);
});

test("typed arrays, not JS arrays, for sample series", () => {
  const run = gd.runHdr(gd.Log.parse(readFileSync(drives[0], "utf8")), {});
  assert.ok(run.trace.heading_hdr_deg instanceof Float64Array);
  assert.ok(run.trace.turn_switch instanceof Uint8Array);
  assert.equal(run.trace.time_s.length, run.result.n_processed);
});

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

test("wrong argument types throw TypeError (never a trap), misspelled recipe fields are refused, and the module keeps working", () => {
  const log = gd.Log.parse("time_s,gyro_dps\n0,1\n1,2\n");
  const typeErrors = [
    () => gd.Log.parse(123),
    () => gd.Log.parse({}),
    () => log.column(5),
    () => gd.Log.fromBytes({ length: 1e9 }),
    () => gd.Log.fromBytes("abc"),
    () => { log.name = 123; },
    () => gd.hdr(log, 5),
    () => gd.defaults(7),
    () => gd.importLog(5, {}),
  ];
  for (const f of typeErrors) assert.throws(f, TypeError, f.toString());
  assert.throws(() => gd.importLog({ ofset_s: 1 }, {}), /recipe: unknown field `ofset_s`/);
  assert.throws(() => gd.importLog({ bias_s: NaN }, {}), /recipe: bias_s: NaN is not a finite number/);
  assert.throws(() => gd.hdr(log, { i_c: Infinity }), /hdr options: i_c: inf is not a finite number/);
  assert.equal(gd.Log.parse("time_s,gyro_dps\n0,1\n1,2\n").rowCount, 2);
  assert.equal(gd.defaults("gyrodometry").thres_rate_dps, 1.25);
  assert.equal(gd.defaultBiasS(), 20);
});

test("checkLog equals the CLI's check, and finds a clockwise gyro with its fix, which every table then refuses unless ignore_check", () => {
  const file = join(SAMPLES, "train", "city-1.csv");
  const text = readFileSync(file, "utf8");
  assert.deepEqual(plain(gd.checkLog(gd.Log.parse(text))), JSON.parse(cli("check", file, "--json")));
  const lines = text.split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  const g = lines[h].split(",").indexOf("gyro_dps");
  const cw = lines.map((l, i) => {
    if (i <= h || !l) return l;
    const c = l.split(",");
    c[g] = String(-Number(c[g]));
    return c.join(",");
  });
  const cwLog = gd.Log.parse(cw.join("\n"));
  const r = gd.checkLog(cwLog);
  const f = r.findings.find((x) => x.code === "gyro_sign");
  assert.ok(f && f.severity === "error" && /positive = "cw"/.test(f.fix), JSON.stringify(r.findings));
  // Every table refuses it, as the CLI does, naming it and the fix; ignore_check runs it,
  // giving the CLI's --ignore-check figures.
  const city = gd.Log.parse(text);
  const refused = /City 1: check: error \[gyro_sign\].*positive = "cw".*ignore_check = true runs it anyway/;
  for (const [name, table] of Object.entries({
    report: (x) => gd.report([city, cwLog], {}, x),
    reportCsv: (x) => gd.reportCsv([cwLog], {}, x),
    reportMarkdown: (x) => gd.reportMarkdown([cwLog], {}, x),
    compare: (x) => gd.compare([cwLog], {}, x),
    compareTable: (x) => gd.compareTable([cwLog], {}, "csv", x),
    battery: (x) => gd.batteryMarkdown([cwLog], {}, x),
    tune: (x) => gd.tune([city], [cwLog], {}, undefined, x),
  })) {
    assert.throws(() => table(undefined), refused, name);
    assert.throws(() => table(false), refused, name);
    if (name === "report" || name === "compare") assert.doesNotThrow(() => table(true), name);
  }
  const dir = mkdtempSync(join(tmpdir(), "gd-cw-"));
  const path = join(dir, "cw.csv");
  writeFileSync(path, cw.join("\n"));
  assert.deepEqual(plain(gd.report([cwLog], {}, true)), JSON.parse(cli("report", path, "--ignore-check", "--json")));
  const noNulls = (o) => JSON.parse(JSON.stringify(o, (_, v) => (v === null ? undefined : v)));
  assert.deepEqual(plain(gd.compare([cwLog], {}, true)), noNulls(JSON.parse(cli("report", "--compare", path, "--ignore-check", "--json"))));
});

test("splitAtGaps gives the CLI's parts: no method integrates across a 60 s gap", () => {
  const text = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const lines = text.split("\n").filter((l) => {
    const t = Number(l.split(",")[0]);
    return !(l && !l.startsWith("#") && t >= 300 && t < 360);
  });
  const dir = mkdtempSync(join(tmpdir(), "gd-gap-"));
  const file = join(dir, "city-gap.csv");
  writeFileSync(file, lines.join("\n"));
  const split = gd.Log.parse(lines.join("\n")).splitAtGaps(undefined);
  assert.equal(split.parts.length, 2);
  assert.equal(split.gaps.length, 1);
  assert.match(split.summary, /60\.1 s at line/);
  const native = JSON.parse(cli("hdr", file, "--json"));
  assert.equal(native.length, 2);
  split.parts.forEach((p, i) => assert.equal(gd.hdr(p, {}).E_psi_hdr_deg, native[i].E_psi_hdr_deg));
  // The part before the gap is scored exactly as a log of its rows alone: nothing after
  // the gap reaches it, and the part after starts afresh (eps0 0: no lead-in there).
  const before = lines.filter((l) => {
    const t = Number(l.split(",")[0]);
    return !l || l.startsWith("#") || Number.isNaN(t) || t < 300;
  });
  const alone = gd.hdr(gd.Log.parse(before.join("\n")), {});
  assert.equal(alone.E_psi_hdr_deg, native[0].E_psi_hdr_deg);
  assert.equal(native[1].eps0_dps, 0);
  const whole = gd.Log.parse(text).splitAtGaps(undefined);
  assert.deepEqual([whole.parts.length, whole.gaps.length, whole.summary], [1, 0, null]);
  assert.throws(() => gd.Log.parse(text).splitAtGaps(NaN), TypeError);
});

test("checkOptions gives core's reason for a bad setting, or nothing for a good one", () => {
  assert.equal(gd.checkOptions("hdr", { i_c_dps: 0.03 }), undefined);
  assert.match(gd.checkOptions("hdr", { i_c_dps: 1e9 }), /i_c.*\[0, 10\]/);
  assert.match(gd.checkOptions("gyrodometry", { thres_rate_dps: -1 }), /thres/);
  assert.match(gd.checkOptions("hdr", { ofset: 1 }), /unknown field/);
  assert.throws(() => gd.checkOptions("nope", {}), /unknown method/);
});

test("detectImport picks the logger's preset from raw files; importLog on its recipe gives the CLI's log", () => {
  const dir = join(ROOT, "sample-logs", "wild", "sensor-logger");
  const names = readdirSync(dir).sort();
  const files = Object.fromEntries(names.map((f) => [f, readFileSync(join(dir, f))]));
  const d = gd.detectImport(files);
  assert.equal(d.preset, "sensor-logger");
  assert.deepEqual(d.used, [["gyro", "Gyroscope.csv"], ["gravity", "Gravity.csv"], ["location", "Location.csv"]]);
  assert.deepEqual(d.ignored, ["Accelerometer.csv", "Metadata.csv"]);
  const { log } = gd.importLog(d.recipe, files);
  const out = join(mkdtempSync(join(tmpdir(), "gd-detect-")), "imported.csv");
  cli("import", ...names.map((f) => join(dir, f)), "--out", out);
  const native = gd.Log.parse(readFileSync(out, "utf8"));
  assert.deepEqual(Array.from(log.column("gyro_dps")), Array.from(native.column("gyro_dps")));
  assert.equal(gd.isDriveLog("city-1.csv", readFileSync(join(SAMPLES, "train", "city-1.csv"))), true);
  assert.equal(gd.isDriveLog("Gyroscope.csv", files["Gyroscope.csv"]), false);
  // Errors are Errors naming the file, never a trap.
  assert.throws(() => gd.detectImport(5), TypeError);
  assert.throws(() => gd.detectImport({ "x.bin": new Uint8Array([0, 1, 2]) }), /x\.bin: a binary file/);
  assert.throws(() => gd.detectImport({ "a.csv": new TextEncoder().encode("alpha;beta\n1;2\n") }), /no logger preset .* a\.csv \(header: alpha, beta\)/);
  assert.throws(() => gd.detectImport({}), /no files/);
});

test("the browser's core module is <= 200 KB gzipped and gives the whole package's numbers; plot and full load apart", async () => {
  const { gzipSync } = await import("node:zlib");
  const pkg = join(ROOT, "web", "pkg");
  const gz = (f) => gzipSync(readFileSync(join(pkg, f)), { level: 9 }).length;
  const core = gz("gyrodrift_bg.wasm") + gz("gyrodrift.js");
  assert.ok(core <= 200 * 1024, `core module ${core} bytes gzipped`);
  const mod = await import(join(pkg, "gyrodrift.js"));
  mod.initSync({ module: readFileSync(join(pkg, "gyrodrift_bg.wasm")) });
  const file = join(SAMPLES, "train", "city-1.csv");
  const a = mod.hdr(mod.Log.parse(readFileSync(file, "utf8")), {});
  const b = gd.hdr(gd.Log.parse(readFileSync(file, "utf8")), {});
  assert.deepEqual(plain(a), plain(b));
  assert.equal(typeof mod.pipeline, "function");
  assert.equal(typeof mod.isDriveLog, "function");
  // Import, tuning, simulation and charts are not in it: they are the full and plot modules.
  for (const f of ["importLog", "detectImport", "tune", "simulate", "addGyroErrors", "batteryProfiles", "drawChart"]) assert.equal(mod[f], undefined, f);
  const full = await import(join(pkg, "full", "gyrodrift.js"));
  assert.equal(typeof full.importLog, "function");
  const plot = await import(join(pkg, "plot", "gyrodrift_plot.js"));
  assert.equal(typeof plot.drawChart, "function");
  assert.equal(plot.hdr, undefined);
});

test("LogBuilder: a log handed over in chunks equals the whole; a bad chunk is refused whole, naming its line and column", () => {
  const log = gd.Log.parse(readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8"));
  const data = log.toColumns();
  const names = Object.keys(data.columns);
  const n = data.columns.time_s.length;
  const chunk = (i, j) => ({ meta: data.meta, line: data.line.subarray(i, j), columns: Object.fromEntries(names.map((k) => [k, data.columns[k].subarray(i, j)])) });
  const b = new gd.LogBuilder(chunk(0, 1000), n);
  // time going back: the line of the offending row, nothing of the chunk kept
  assert.throws(() => b.append(chunk(500, 1500)), (e) => e instanceof Error && /time_s/.test(e.message) && e.message.includes(String(data.line[500])));
  // a gyro value out of range, named by line and column
  const bad = chunk(1000, 1100);
  bad.columns.gyro_dps = bad.columns.gyro_dps.slice();
  bad.columns.gyro_dps[7] = 1e9;
  assert.throws(() => b.append(bad), (e) => /gyro_dps/.test(e.message) && e.message.includes(String(data.line[1007])));
  assert.throws(() => b.append({ columns: { time_s: data.columns.time_s.subarray(1000, 1001) } }), /gyro_dps/);
  assert.throws(() => b.append({ columns: { time_s: "no" } }), /time_s/);
  for (let i = 1000; i < n; i += 3000) b.append(chunk(i, Math.min(n, i + 3000)));
  const built = b.finish();
  assert.throws(() => b.finish(), /already finished/);
  b.free();
  assert.deepEqual(plain(gd.hdr(built, {})), plain(gd.hdr(log, {})));
  assert.deepEqual(built.toColumns().line, data.line);
  assert.throws(() => new gd.LogBuilder({ meta: data.meta, columns: { gyro_dps: new Float64Array(1) } }, 0), /time_s/);
  assert.throws(() => new gd.LogBuilder({ columns: { time_s: new Float64Array([1, 0]) } }, 2), /line 3/);
  built.free();
  log.free();
});

test("Log.reduceColumns gives reduceSeries' points of the log's own columns, without copying them out", () => {
  const log = gd.Log.parse(readFileSync(join(SAMPLES, "train", "highway-1.csv"), "utf8"));
  for (const view of [{ columns: 300 }, { columns: 120, x_range: [100, 900] }]) {
    const got = log.reduceColumns(["speed_mps", "gyro_dps"], view);
    const want = gd.reduceSeries(log.column("time_s"), [log.column("speed_mps"), log.column("gyro_dps")], view);
    assert.ok(got.x.length > 0 && got.x.length < log.column("time_s").length, "reduced");
    assert.deepEqual(got.x, want.x);
    assert.deepEqual(got.ys, want.ys);
  }
  assert.throws(() => log.reduceColumns(["odo_left_m"], { columns: 100 }), /odo_left_m/);
  assert.throws(() => log.reduceColumns(["nope"], { columns: 100 }), /unknown column nope/);
  assert.throws(() => log.reduceColumns("speed_mps", { columns: 100 }), TypeError);
  assert.throws(() => log.reduceColumns(["speed_mps"], {}), /columns/);
  log.free();
});

test("battery on the user's drives gives the CLI's `battery --logs` cases, method for method", () => {
  const file = join(SAMPLES, "test", "city-3.csv");
  const log = gd.Log.parse(readFileSync(file, "utf8"));
  const b = gd.battery([log], {});
  const native = JSON.parse(cli("battery", "--logs", file, "--minutes", "2", "--split", "scoring", "--json"));
  const mine = native.cases.filter((c) => c.base === log.name);
  assert.ok(mine.length > 20);
  assert.deepEqual(b.methods, native.methods.slice(0, 6)); // the page has no tuned-HDR peer
  assert.equal(b.cases.length, mine.length);
  assert.equal(b.added.n_cases, mine.length);
  assert.equal(b.training, undefined);
  assert.deepEqual(b.scoring, b.added);
  b.cases.forEach((c, i) => {
    assert.equal(c.profile, mine[i].profile);
    assert.equal(c.training, false);
    assert.deepEqual(c.ne_psi, mine[i].ne_psi.slice(0, 6), c.profile);
    // The best causal column is core's: the smoothed mode (column 5) is never it.
    assert.notEqual(c.best, 5, c.profile);
    assert.equal(c.ne_psi[c.best], Math.min(...c.ne_psi.filter((_, j) => j !== 5)), c.profile);
  });
  assert.match(gd.batteryMarkdown([log], {}), /\| added \(\d+\) \|/);
  // A log without a reference heading is refused with core's reason; the module keeps working.
  const bare = gd.Log.parse("time_s,gyro_dps\n0,0.1\n1,0.1\n2,0.1\n");
  assert.throws(() => gd.battery([bare], {}), (e) => e instanceof Error && /ref_heading_deg/.test(e.message));
  assert.throws(() => gd.battery([log], { no_such_setting: 1 }), /no_such_setting/);
  assert.equal(gd.battery([log], {}).cases.length, mine.length);
  bare.free();
  log.free();
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
