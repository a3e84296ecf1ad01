// Input to the npm package under Node: bad logs and arguments throw Errors naming line and
// column (never a trap) and the module keeps working; check, gaps, settings, logger
// presets, logs handed over in chunks, columns reduced for plotting.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, readdirSync, mkdtempSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { execFileSync } from "node:child_process";
import { join } from "node:path";
import * as gd from "gyrodrift";
import { ROOT, SAMPLES, cli, plain, drives } from "./helpers.mjs";

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

test("a log saved with ';' and decimal commas (a spreadsheet's CSV in many locales) reads as the comma log", () => {
  const text = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const saved = "\ufeff" + text.split("\n").map((l) => (l.startsWith("#") ? l : l.replaceAll(",", ";").replaceAll(".", ","))).join("\r\n");
  const want = gd.Log.parse(text);
  const bytes = new TextEncoder().encode(saved);
  assert.equal(gd.isDriveLog("city-1.csv", bytes), true);
  for (const got of [gd.Log.parse(saved), gd.Log.fromBytes(bytes), gd.Log.fromBytesWithProgress(bytes, () => {}), gd.logInTimeOrder(bytes).log]) {
    for (const c of ["time_s", "gyro_dps", "temp_c", "ref_heading_deg", "speed_mps"]) assert.deepEqual(Array.from(got.column(c)), Array.from(want.column(c)), c);
    assert.deepEqual(got.meta(), want.meta());
  }
  assert.throws(() => gd.Log.parse("time_s;gyro_dps\r\n0;1,5\r\n0,1;1,5x\r\n"), { message: 'line 3, column gyro_dps: "1.5x" is not a number' });
});

test("a last line cut short: Log.fromBytes refuses it naming the line, logInTimeOrder drops it and says so", () => {
  const text = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const cutAt = text.trimEnd().lastIndexOf("\n");
  const bytes = new TextEncoder().encode(text.slice(0, cutAt + 6));
  assert.throws(() => gd.Log.fromBytes(bytes), /row has 2 fields, the header has 5 \(truncated row\?\)$/);
  const { log, fixed } = gd.logInTimeOrder(bytes);
  assert.equal(fixed, "its last line, cut short (2 of 5 cells, no line end), dropped");
  const want = gd.Log.parse(text.slice(0, cutAt + 1));
  assert.deepEqual(Array.from(log.column("gyro_dps")), Array.from(want.column("gyro_dps")));
});

test("a UTF-16 or binary file: Log.fromBytes says what it is, not a header of garbage", () => {
  const utf16 = Uint8Array.from([0xff, 0xfe, ...Array.from(new TextEncoder().encode("time_s,gyro_dps\n0,1\n")).flatMap((b) => [b, 0])]);
  assert.throws(() => gd.Log.fromBytes(utf16), /line 1: UTF-16 text/);
  const parquet = Uint8Array.from([0x50, 0x41, 0x52, 0x31, 0x15, 0x04, 0x00, 0x00, 0x81, 0x0a]);
  assert.throws(() => gd.Log.fromBytes(parquet), /line 1: a binary file \(NUL bytes\), not a text table$/);
});

test("two logs joined into one file: every parse names the second log's first line; logsJoined reads each", () => {
  const a = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const b = readFileSync(join(SAMPLES, "train", "city-2.csv"), "utf8");
  const bytes = new TextEncoder().encode(a + b);
  const line = a.split("\n").length;
  const said = `line ${line}: a '#' line after the rows ("# name: City 2"): a second log joined on? A log's '#' lines come before its header; split the file before this line`;
  for (const parse of [() => gd.Log.parse(a + b), () => gd.Log.fromBytes(bytes), () => gd.Log.fromBytesWithProgress(bytes, () => {}), () => gd.logInTimeOrder(bytes)]) {
    assert.throws(parse, { message: said });
  }
  // logsJoined: each log as parsed alone, with the line it starts on (the CLI's `split`).
  const logs = gd.logsJoined(bytes);
  assert.deepEqual(logs.map((l) => [l.log.name, l.line, l.fixed]), [["City 1", 1, ""], ["City 2", line, ""]]);
  for (const [got, text] of [[logs[0].log, a], [logs[1].log, b]]) {
    const want = gd.Log.parse(text);
    assert.deepEqual(got.meta(), want.meta());
    assert.deepEqual(Array.from(got.column("gyro_dps")), Array.from(want.column("gyro_dps")));
  }
  assert.throws(() => gd.logsJoined(new TextEncoder().encode(a + "# name: x\ntime_s,gyro_dps\n0,1\n1,x\n")), {
    message: `line ${line + 3}, column gyro_dps: "x" is not a number`,
  });
});

test("a refusal another reading mends carries its kind as Error.code, in the full package and the page's core module", async () => {
  const pkg = join(ROOT, "web", "pkg");
  const page = await import(join(pkg, "gyrodrift.js"));
  page.initSync({ module: readFileSync(join(pkg, "gyrodrift_bg.wasm")) });
  const a = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const rows = "# name: x\ntime_s,gyro_dps,temp_c\n0,1,20\n1,1,20\n";
  const cases = [
    [rows + "1,1,20\n", "time_order"],
    [rows + "5,1,20\n0,1,20\n", "clock_reset"],
    [rows + "2,1\n3,1,20\n", "cut_row"],
    ["Time (s),Gyroscope z (rad/s)\n0,1\n1,1\n", "foreign"],
    [rows + "2,x,20\n", undefined],
    [rows + "2,1,20,4\n", undefined],
  ];
  const code = (parse) => {
    try {
      parse();
    } catch (e) {
      assert.ok(e instanceof Error && /^line \d+/.test(e.message), e.message);
      return e.code;
    }
    assert.fail("not refused");
  };
  for (const [text, want] of cases) {
    const bytes = new TextEncoder().encode(text);
    for (const m of [gd, page]) {
      for (const parse of [() => m.Log.parse(text), () => m.Log.fromBytes(bytes)]) assert.equal(code(parse), want, `${want}: ${text}`);
    }
    assert.equal(code(() => gd.Log.fromBytesWithProgress(bytes, () => {})), want, text);
  }
  // The full package names a second log joined on; the page's module reads it as a row cut
  // short (the page then asks the worker, which names it).
  const joined = new TextEncoder().encode(a + rows);
  assert.equal(code(() => gd.Log.fromBytes(joined)), "joined");
  assert.equal(code(() => gd.logInTimeOrder(joined)), "joined");
  assert.equal(code(() => page.Log.fromBytes(joined)), "cut_row");
  // Put in time order, a clock reset is still refused, and named so.
  assert.equal(code(() => gd.logInTimeOrder(new TextEncoder().encode(rows + "5,1,20\n0,1,20\n"))), "clock_reset");
});

test("a log a spreadsheet opened and saved (metadata padded with separators, one quoted) is a drive log this module reads", () => {
  const text = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const saved = text
    .split("\n")
    .map((l) => (l.startsWith("#") ? (l.includes(",") ? `"${l}",,,,` : `${l},,,,`) : l))
    .join("\r\n");
  const bytes = new TextEncoder().encode(saved);
  assert.equal(gd.isDriveLog("city-1.csv", bytes), true);
  const got = gd.Log.fromBytes(bytes);
  const want = gd.Log.parse(text);
  assert.deepEqual(got.meta(), want.meta());
  assert.deepEqual(Array.from(got.column("gyro_dps")), Array.from(want.column("gyro_dps")));
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
  // The package leaves out what the CLI's JSON has as null (the types mark it optional).
  const noNulls = (o) => JSON.parse(JSON.stringify(o, (_, v) => (v === null ? undefined : v)));
  const checked = plain(gd.checkLog(gd.Log.parse(text)));
  assert.deepEqual(checked, noNulls(JSON.parse(cli("check", file, "--json"))));
  // City 1's CRS03-like gyro warms 0.16 deg/s over its standings: information, no fix value.
  const drift = checked.findings.find((f) => f.code === "bias_drift");
  assert.ok(drift && drift.severity === "info" && drift.fix_value === undefined && checked.stop_bias_dps.length > 1, JSON.stringify(checked));
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
    assert.throws(() => table(false), (e) => refused.test(e.message) && e.code === "check" && e.log === "City 1", name);
    if (name === "report" || name === "compare") assert.doesNotThrow(() => table(true), name);
  }
  const dir = mkdtempSync(join(tmpdir(), "gd-cw-"));
  const path = join(dir, "cw.csv");
  writeFileSync(path, cw.join("\n"));
  assert.deepEqual(plain(gd.report([cwLog], {}, true)), JSON.parse(cli("report", path, "--ignore-check", "--json")));
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
  // The recording zipped, as Sensor Logger exports it (in a folder, deflated): the same
  // detection and log from the archive alone.
  const zip = join(mkdtempSync(join(tmpdir(), "gd-zip-")), "drive.zip");
  execFileSync("python3", ["-c", "import sys, os, zipfile\nz = zipfile.ZipFile(sys.argv[1], 'w', zipfile.ZIP_DEFLATED)\nfor f in sys.argv[3:]: z.write(os.path.join(sys.argv[2], f), 'Drive/' + f)", zip, dir, ...names]);
  const zipped = { "drive.zip": readFileSync(zip) };
  const dz = gd.detectImport(zipped);
  assert.equal(dz.preset, "sensor-logger");
  assert.deepEqual(dz.used, d.used);
  const fromZip = gd.importLog(dz.recipe, zipped).log;
  assert.deepEqual(Array.from(fromZip.column("gyro_dps")), Array.from(native.column("gyro_dps")));
  // Named by the archive, in the recipe too (saved and dropped again, it names the log alike).
  assert.equal(dz.recipe.name, "drive");
  assert.equal(fromZip.name, "drive");
  assert.throws(() => gd.detectImport({ "cut.zip": readFileSync(zip).subarray(0, 30) }), /cut\.zip: not a ZIP archive that can be read/);
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

test("logInTimeOrder (the full build) reads a log whose time repeats or is a little late, as the CLI's --time-order fix; Log.fromBytes refuses it", () => {
  const text = "# name: messy\ntime_s,gyro_dps\n0,1\n1,2\n1,4\n3,5\n2.5,7\n4,8\n";
  const bytes = new TextEncoder().encode(text);
  assert.throws(() => gd.Log.fromBytes(bytes), /line 5, column time_s: time 1 repeats 1 on line 4/);
  const { log, fixed } = gd.logInTimeOrder(bytes);
  assert.deepEqual([...log.column("time_s")], [0, 1, 2.5, 3, 4]);
  assert.deepEqual([...log.column("gyro_dps")], [1, 3, 7, 5, 8]);
  assert.equal(fixed, "1 rows of a repeated time merged, 1 late rows put in time order");
  assert.equal(log.name, "messy");
  log.free();
  assert.throws(() => gd.logInTimeOrder(new TextEncoder().encode("time_s,gyro_dps\n0,1\n5,2\n3,3\n")), /line 4, column time_s: time 3 goes back 2\.000 s from 5: a clock reset\?/);
});

test("draftRecipe drafts a recipe from raw files' column names as the CLI's --print-recipe does", () => {
  const csv = new TextEncoder().encode("stamp_ms,gyro_z_dps,course,speed_kmh\n0,1,,0\n1000,2,10,36\n2000,3,20,3.6\n");
  const files = { "my-logger.csv": csv };
  const d = gd.draftRecipe(files);
  assert.deepEqual(d.recipe.table[0].time, { column: "stamp_ms", unit: "ms" });
  assert.equal(d.recipe.yaw_rate.unit, "deg/s");
  assert.ok(d.guesses.some((g) => g.startsWith('yaw_rate: my-logger.csv column "gyro_z_dps", deg/s')), d.guesses.join("\n"));
  const { log, summary } = gd.importLog(d.recipe, files);
  assert.deepEqual(Array.from(log.column("gyro_dps")), [1, 2, 3]);
  assert.equal(summary.n_reference, 1); // 36 km/h passes the draft's 5 m/s, 3.6 does not
  // The same draft as the CLI prints (its TOML after the comment lines).
  const dir = mkdtempSync(join(tmpdir(), "gd-draft-"));
  writeFileSync(join(dir, "my-logger.csv"), csv);
  const printed = cli("import", join(dir, "my-logger.csv"), "--print-recipe");
  assert.deepEqual(gd.recipeFromToml(printed), d.recipe);
  assert.throws(() => gd.draftRecipe({ "c.csv": new TextEncoder().encode("t,a,b\n") }), /no column reads as a yaw rate/);
  assert.throws(() => gd.draftRecipe(5), TypeError);
});

test("columnGuesses reads every column as each kind it could be, the draft's reading", () => {
  const enc = (s) => new TextEncoder().encode(s);
  const files = {
    "imu.csv": enc("clock,gyro_x_rad,gyro_y_rad,gyro_z_rad,acc_x,acc_y,acc_z\n10:00:00.125,0,0,0,0,0,9.8\n"),
    "gps.csv": enc("t_ms,lat,lon,heading_rad,speed_kmh\n0,42,11,1,36\n"),
  };
  const g = gd.columnGuesses(files);
  // The files in name order; a column's `file` indexes them.
  assert.deepEqual(g.files.map((f) => [f.name, f.time_column]), [["gps.csv", "t_ms"], ["imu.csv", "clock"]]);
  const col = (i, name) => g.files[i].columns.find((c) => c.name === name);
  assert.equal(col(1, "clock").time, "time_of_day");
  assert.equal(col(0, "t_ms").time, "ms");
  assert.equal(col(1, "gyro_z_rad").rate_unit, "rad/s");
  assert.equal(col(0, "heading_rad").angle_unit, "rad");
  assert.equal(col(0, "speed_kmh").speed_unit, "km/h");
  assert.deepEqual(g.yaw_rate, { file: 1, column: "gyro_z_rad" });
  assert.deepEqual(g.gyro_axes.map((c) => c.column), ["gyro_x_rad", "gyro_y_rad", "gyro_z_rad"]);
  assert.deepEqual(g.accel_axes.map((c) => c.column), ["acc_x", "acc_y", "acc_z"]);
  assert.deepEqual(g.course, { file: 0, column: "heading_rad" });
  assert.deepEqual(g.lat_lon, { file: 0, lat: "lat", lon: "lon" });
  assert.equal(g.temperature, undefined);
  // The draft recipe reads the files the same way.
  assert.equal(g.yaw_from_axes, true);
  const d = gd.draftRecipe(files).recipe;
  assert.deepEqual([d.yaw_rate.axes, d.yaw_rate.gravity.axes, d.heading.column, d.speed.unit], [["gyro_x_rad", "gyro_y_rad", "gyro_z_rad"], ["acc_x", "acc_y", "acc_z"], "heading_rad", "km/h"]);
  // An NMEA log is no table of columns: its sentence to read, and none of its fields guessed.
  const nmea = gd.columnGuesses({ ...files, "gps.nmea": enc("$GPGGA,120000.00,4220.2340,N,07105.3704,W,1,09,1.2,16.6,M,-33.8,M,,0000*55\n$GPRMC,120000.00,A,4220.2340,N,07105.3704,W,10.0,80.0,241126,,,A*00\n") });
  assert.deepEqual(nmea.files.map((f) => f.nmea), [undefined, "$GPRMC", undefined]);
  assert.equal(nmea.yaw_rate.column, "gyro_z_rad");
  assert.throws(() => gd.columnGuesses({ "b.bin": new Uint8Array([0, 159, 146, 150, 0, 1]) }), /b\.bin/);
  assert.throws(() => gd.columnGuesses(5), TypeError);
});

test("importLog reads a GPX track (format gpx) as the CLI does: the heading from its positions", () => {
  const pts = [[42.0, 11.0], [42.0, 11.0001], [42.0, 11.0002], [42.0, 11.0003], [42.0001, 11.0003], [42.0002, 11.0003]];
  const trk = pts.map(([lat, lon], k) => `<trkpt lat="${lat}" lon="${lon}"><time>2026-11-27T10:00:0${k}Z</time></trkpt>`).join("");
  const gpx = `<?xml version="1.0"?><gpx version="1.1" creator="t" xmlns="http://www.topografix.com/GPX/1/1"><trk><trkseg>${trk}</trkseg></trk></gpx>`;
  let imu = "time,w\n";
  for (let i = 0; i <= 50; i++) imu += `2026-11-27 10:00:0${Math.floor(i / 10)}.${i % 10}Z,0\n`;
  const enc = (s) => new TextEncoder().encode(s);
  const files = { "imu.csv": enc(imu), "drive.gpx": enc(gpx) };
  const recipe = {
    table: [{ id: "imu", file: "imu.csv", time: { column: "time", format: "iso8601" } }, { id: "trk", file: "drive.gpx", format: "gpx" }],
    yaw_rate: { table: "imu", column: "w", unit: "deg/s", positive: "ccw" },
    positions: { table: "trk", kind: "latlon", columns: ["lat", "lon"] },
    heading: { source: "positions" },
    speed: { source: "positions" },
  };
  const { log, summary } = gd.importLog(recipe, files);
  assert.equal(summary.n_reference, 5);
  const ref = Array.from(log.column("ref_heading_deg")).filter(Number.isFinite);
  assert.deepEqual(ref.map((h) => Math.round(h) + 0), [-90, -90, -90, 0, 0]); // + 0: north as 0, not -0
  const dir = mkdtempSync(join(tmpdir(), "gd-gpx-"));
  writeFileSync(join(dir, "imu.csv"), files["imu.csv"]);
  writeFileSync(join(dir, "drive.gpx"), files["drive.gpx"]);
  writeFileSync(join(dir, "r.json"), JSON.stringify(recipe));
  const out = join(dir, "out.csv");
  cli("import", "--recipe", join(dir, "r.json"), "--out", out);
  assert.deepEqual(Array.from(gd.Log.parse(readFileSync(out, "utf8")).column("ref_heading_deg")), Array.from(log.column("ref_heading_deg")));
  assert.throws(() => gd.importLog(recipe, { ...files, "drive.gpx": enc("<gpx") }), /drive\.gpx: not a GPX file/);
});
