// The npm package's methods under Node, as users import it: HDR, Gyrodometry, calibration,
// Allan deviation, the simulator, injected errors and the battery equal the native CLI bit
// for bit.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, readdirSync } from "node:fs";
import { join } from "node:path";
import * as gd from "gyrodrift";
import { SAMPLES, cli, plain, drives } from "./helpers.mjs";

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

test("typed arrays, not JS arrays, for sample series", () => {
  const run = gd.runHdr(gd.Log.parse(readFileSync(drives[0], "utf8")), {});
  assert.ok(run.trace.heading_hdr_deg instanceof Float64Array);
  assert.ok(run.trace.turn_switch instanceof Uint8Array);
  assert.equal(run.trace.time_s.length, run.result.n_processed);
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
