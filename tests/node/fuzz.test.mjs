// A fuzz loop over the wasm package's entry points, as a web page or fleet tool would meet
// hostile input: mutated logs through every method, mutated recipes and tables through
// importLog, random options. Any thrown value must be an Error (a trap, RuntimeError, kills the
// module), and the module must still give the same result afterwards. Seeded: a failure
// prints its seed and iteration and replays.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import * as gd from "gyrodrift";
import { SAMPLES } from "./helpers.mjs";

const SEED = Number(process.env.GYRODRIFT_FUZZ_SEED || 20261123);
const N = Number(process.env.GYRODRIFT_FUZZ_N || 300);

/** xorshift32: the same sequence on every machine. */
function rng(seed) {
  let x = seed >>> 0 || 1;
  const next = () => {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    return (x >>> 0) / 4294967296;
  };
  return { next, int: (n) => Math.floor(next() * n), pick: (a) => a[Math.floor(next() * a.length)] };
}

const TOKENS = ["nan", "NaN", "inf", "-inf", "1e308", "-1e308", "1e-320", "0", "-0", "", ",", ",,", "\n", "\r\n", "\r", "\ufeff", "#", "# bias_s: nan", "# name: \u0000", "time_s", "gyro_dps", '"', '""', "\t", ";", "1,5", "99999999999", "-5", "é", "\u2028", "0x10", "1_000"];
const VALUES = [NaN, Infinity, -Infinity, -1, 0, 1e-300, 1e300, 0.5, 3, 1e9, "x", "", null, true, [], {}, [1, 2], { a: 1 }, "rad/s", "deg", "ms", "cw"];

const CELLS = ["", "0", "-0", "1", "-1", "359.9", "-720", "1e3", "-1e3", "9999", "0.0001", "150", "-60", "1e-9"];

/** A few random edits of `text`: most keep it a log (a cell changed or emptied, rows deleted,
 * a stretch of time shifted into a gap), some break it (a token inserted, a byte changed,
 * a line repeated, the file truncated). */
function mutate(r, text) {
  let s = text;
  for (let k = 1 + r.int(2); k > 0; k--) {
    const lines = s.split("\n");
    const data = lines.findIndex((l) => l.startsWith("time_s")) + 1 || 1;
    const i = data + r.int(Math.max(1, lines.length - data));
    const at = r.int(s.length + 1);
    switch (r.int(8)) {
      case 0:
      case 1:
      case 2: {
        const c = (lines[i] ?? "").split(",");
        c[r.int(c.length)] = r.pick(CELLS);
        lines[i] = c.join(",");
        s = lines.join("\n");
        break;
      }
      case 3: lines.splice(i, 1 + r.int(300)); s = lines.join("\n"); break;
      case 4: {
        const dt = r.pick([7, 60, 3600, 1e6]);
        s = lines.map((l, j) => (j >= i && l && !l.startsWith("#") && j >= data ? l.replace(/^[^,]*/, (t) => String(Number(t) + dt)) : l)).join("\n");
        break;
      }
      case 5: s = s.slice(0, at) + r.pick(TOKENS) + s.slice(at); break;
      case 6: s = r.int(2) ? s.slice(0, at) + String.fromCharCode(r.int(128)) + s.slice(at + 1) : lines.toSpliced(i, 0, lines[i] ?? "").join("\n"); break;
      default: s = s.slice(0, r.int(s.length + 1));
    }
  }
  return s;
}

const tally = { ok: 0, error: 0 };

/** Calls `f`; a throw must be an Error, never a wasm trap. */
function safely(what, f) {
  try {
    const v = f();
    tally.ok++;
    return v;
  } catch (e) {
    tally.error++;
    assert.ok(e instanceof Error, `${what}: threw a non-Error ${String(e)}`);
    assert.ok(!(e instanceof WebAssembly.RuntimeError), `${what}: wasm trap: ${e.message}`);
    return undefined;
  }
}

/** Random options: the method's defaults with a few keys set to hostile values. */
function options(r, method) {
  const o = { ...gd.defaults(method) };
  const keys = Object.keys(o);
  for (let k = r.int(3); k > 0; k--) o[r.pick(keys)] = r.pick(VALUES);
  if (r.int(5) === 0) o[r.pick(["ofset", "i_c", "x"])] = 1;
  return o;
}

/** A result given without an error has finite numbers (no NaN or inf passed off as a result). */
function finite(what, result) {
  for (const [k, v] of Object.entries(result ?? {})) {
    if (typeof v === "number") assert.ok(Number.isFinite(v), `${what}: ${k} = ${v}`);
  }
}

let batteryRuns = 0;
function everyMethod(r, log, tag) {
  // The battery runs every method on every profile of the log (42): on one log in ten.
  if (batteryRuns++ % 10 === 0) safely(`${tag} battery`, () => gd.battery([log], {}));
  finite(`${tag} hdr`, safely(`${tag} hdr`, () => gd.hdr(log, r.int(2) ? {} : options(r, "hdr"))));
  safely(`${tag} runHdr`, () => gd.runHdr(log, {}));
  finite(`${tag} pipeline`, safely(`${tag} pipeline`, () => gd.pipeline(log, r.int(2) ? {} : options(r, "pipeline"))));
  finite(`${tag} gyrodometry`, safely(`${tag} gyrodometry`, () => gd.gyrodometry(log, r.int(2) ? { wheelbase_m: 0.5 } : options(r, "gyrodometry"))));
  finite(`${tag} calibrate`, safely(`${tag} calibrate`, () => gd.calibrate(log, {})));
  safely(`${tag} allan`, () => gd.allan(log));
  safely(`${tag} checkLog`, () => gd.checkLog(log));
  safely(`${tag} compare`, () => gd.compare([log], {}));
  safely(`${tag} report`, () => gd.report([log], {}));
  safely(`${tag} splitAtGaps`, () => gd.Log.prototype.splitAtGaps.call(log, r.pick([undefined, 20, 0])).parts.forEach((p) => p.free()));
  safely(`${tag} toCsv`, () => gd.Log.parse(log.toCsv()).free());
}

// 150 s of City 1 at 10 Hz: small enough for hundreds of runs of every method.
const CITY = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").split("\n").slice(0, 1510).join("\n");
const expected = gd.hdr(gd.Log.parse(CITY), {}).E_psi_hdr_deg;

test(`${N} mutated logs through every method: errors, never a trap; the module still works (seed ${SEED})`, () => {
  const r = rng(SEED);
  let parsed = 0;
  for (let i = 0; i < N; i++) {
    const text = mutate(r, CITY);
    const tag = `seed ${SEED} log ${i}`;
    const log = safely(`${tag} parse`, () => (r.int(2) ? gd.Log.parse(text) : gd.Log.fromBytes(new TextEncoder().encode(text))));
    if (log) {
      parsed++;
      try {
        everyMethod(r, log, tag);
      } catch (e) {
        if (process.env.GYRODRIFT_FUZZ_DUMP) writeFileSync(process.env.GYRODRIFT_FUZZ_DUMP, text);
        throw e;
      }
      log.free();
    }
  }
  // not vacuous: a good share of the inputs parse and reach the methods
  assert.ok(parsed > N / 5 && tally.ok > 3 * N, `${parsed} of ${N} parsed; ${JSON.stringify(tally)}`);
  console.log(`logs: ${parsed} of ${N} parsed; calls ${JSON.stringify(tally)}`);
  assert.equal(gd.hdr(gd.Log.parse(CITY), {}).E_psi_hdr_deg, expected);
});

/** A phone-like table: 3-axis gyro (rad/s), accelerometer, positions, 50 Hz for 120 s. */
function phoneTable() {
  const rows = ["t,gx,gy,gz,ax,ay,az,lat,lon"];
  for (let i = 0; i < 6000; i++) {
    const t = i / 50;
    const yaw = t > 10 && t % 30 > 25 ? 0.3 : 0;
    rows.push([t.toFixed(2), 0.001, -0.002, yaw + 0.01, 0.1, 0.2, 9.8, (52.5 + t * 1e-5).toFixed(7), (13.4 + (t > 60 ? (t - 60) * 1e-5 : 0)).toFixed(7)].join(","));
  }
  return rows.join("\n");
}

const RECIPE = {
  name: "phone",
  bias_s: 5,
  table: [{ id: "p", file: "phone.csv", time: { column: "t" } }],
  yaw_rate: { table: "p", axes: ["gx", "gy", "gz"], gravity: { axes: ["ax", "ay", "az"], first_s: 5 }, unit: "rad/s", positive: "ccw" },
  positions: { table: "p", kind: "latlon", columns: ["lat", "lon"] },
  heading: { source: "positions", min_distance_m: 2, min_speed_mps: 0.5 },
  speed: { source: "positions", window_s: 1 },
};

/** The recipe with a few fields replaced by hostile values or removed. */
function mutateRecipe(r) {
  const rec = structuredClone(RECIPE);
  for (let k = 1 + r.int(3); k > 0; k--) {
    // walk to a random object inside the recipe
    let obj = rec;
    for (let d = r.int(3); d > 0; d--) {
      const inner = Object.values(obj).filter((v) => v && typeof v === "object");
      if (!inner.length) break;
      obj = r.pick(inner);
    }
    const keys = Object.keys(obj);
    if (!keys.length) continue;
    const key = r.pick(keys);
    if (r.int(4) === 0) delete obj[key];
    else obj[key] = r.pick(VALUES);
  }
  return rec;
}

test(`${N} mutated recipes and tables through importLog: errors, never a trap (seed ${SEED})`, () => {
  const r = rng(SEED + 1);
  const table = phoneTable();
  const good = gd.importLog(RECIPE, { "phone.csv": new TextEncoder().encode(table) });
  const rows = good.log.rowCount;
  assert.ok(rows > 1000, `the base recipe imports (${rows} rows)`);
  let imported = 0;
  for (let i = 0; i < N; i++) {
    const tag = `seed ${SEED} recipe ${i}`;
    const recipe = r.int(2) ? mutateRecipe(r) : RECIPE;
    const bytes = new TextEncoder().encode(recipe === RECIPE || r.int(2) ? mutate(r, table) : table);
    const out = safely(`${tag} importLog`, () => gd.importLog(recipe, { "phone.csv": bytes }));
    if (out) {
      imported++;
      try {
        if (r.int(4) === 0) everyMethod(r, out.log, tag);
      } catch (e) {
        if (process.env.GYRODRIFT_FUZZ_DUMP) writeFileSync(process.env.GYRODRIFT_FUZZ_DUMP, out.log.toCsv());
        throw e;
      }
      out.log.free();
    }
  }
  assert.ok(imported > N / 10, `${imported} of ${N} imported`);
  console.log(`recipes: ${imported} of ${N} imported`);
  assert.equal(gd.importLog(RECIPE, { "phone.csv": new TextEncoder().encode(table) }).log.rowCount, rows);
});
