#!/usr/bin/env node
// The robustness battery on the user's drives in Node through the wasm package (what the
// dashboard's Report view runs in its worker, single-threaded): battery() on the shipped
// City 1 (19 min) and Highway 1 (52 min) drives, 32 profiles each. Run after the package
// is built:
//   node tests/bench/battery-node.mjs
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { dirname, join } from "node:path";
import { Log, battery } from "gyrodrift";

const root = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
const logs = ["city-1", "highway-1"].map((f) => Log.parse(readFileSync(join(root, "sample-logs", "train", `${f}.csv`), "utf8")));
for (const set of [[logs[0]], logs]) {
  const t0 = performance.now();
  const b = battery(set, {});
  const s = (performance.now() - t0) / 1000;
  console.log(`battery on ${set.map((l) => l.name).join(" + ")}: ${b.cases.length} cases in ${s.toFixed(2)} s`);
}
