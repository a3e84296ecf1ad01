// The npm package as shipped: the Node fleet example prints the CLI's report; the browser's
// core module keeps its size and loads apart from plot and full. Run: node --test tests/node/
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync, readdirSync } from "node:fs";
import { join } from "node:path";
import { execFileSync } from "node:child_process";
import * as gd from "gyrodrift";
import { ROOT, SAMPLES, cli, plain } from "./helpers.mjs";

test("the Node fleet example prints the same report as the CLI", () => {
  const dir = join(SAMPLES, "train");
  const out = execFileSync("node", [join(ROOT, "examples", "node", "report.mjs"), dir], { encoding: "utf8" });
  const files = readdirSync(dir).filter((f) => f.endsWith(".csv")).sort().map((f) => join(dir, f));
  assert.equal(out, cli("report", "--markdown", ...files));
  assert.match(out, /\| City 1 \|/);
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
