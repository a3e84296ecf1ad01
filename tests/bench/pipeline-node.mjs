#!/usr/bin/env node
// The recommended pipeline in Node through the wasm package (what the dashboard's HDR view
// calls): runPipeline on the shipped 52 min Highway 1 drive, beside runHdr. Run after the
// package is built:
//   node tests/bench/pipeline-node.mjs
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { dirname, join } from "node:path";
import { Log, runPipeline, runHdr, PipelineEstimator } from "gyrodrift";

const root = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
const log = Log.parse(readFileSync(join(root, "sample-logs", "train", "highway-1.csv"), "utf8"));

function time(name, f, n) {
  f(); // warm up
  const t0 = performance.now();
  for (let i = 0; i < n; i++) f();
  const ms = (performance.now() - t0) / n;
  console.log(`${name.padEnd(28)} ${ms.toFixed(2)} ms`);
}
time("runPipeline (Highway 1)", () => runPipeline(log, {}), 10);
time("runHdr (Highway 1)", () => runHdr(log, {}), 20);
// The same drive streamed row by row through the live estimator (all its rows at once).
const [t, w, v] = ["time_s", "gyro_dps", "speed_mps"].map((c) => log.column(c));
time(`PipelineEstimator (${t.length} rows)`, () => {
  const est = new PipelineEstimator({});
  est.updateMany(t, w, v);
  est.free();
}, 10);
