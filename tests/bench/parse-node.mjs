#!/usr/bin/env node
// Parse speed of a ~100 MB drive log in the wasm package (Node; the page uses the same
// code): the 52 min Highway 1 sample repeated with shifted time. Also writes the file to
// /tmp/gyrodrift-100mb.csv for the native comparison:
//   node tests/bench/parse-node.mjs && time target/release/gyrodrift hdr /tmp/gyrodrift-100mb.csv
import { readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { Log } from "gyrodrift";

const root = join(fileURLToPath(import.meta.url), "..", "..", "..");
const src = readFileSync(join(root, "sample-logs", "train", "highway-1.csv"), "utf8").split("\n");
const header = src.findIndex((l) => l.startsWith("time_s"));
const rows = src.slice(header + 1).filter((l) => l.length > 0).map((l) => l.split(","));
const span = Number(rows[rows.length - 1][0]) + 0.1;
const parts = [src.slice(0, header + 1).join("\n") + "\n"];
let size = parts[0].length;
for (let k = 0; size < 100e6; k++) {
  const chunk = rows.map((r) => [(Number(r[0]) + k * span).toFixed(1), ...r.slice(1)].join(",")).join("\n") + "\n";
  parts.push(chunk);
  size += chunk.length;
}
const text = parts.join("");
writeFileSync("/tmp/gyrodrift-100mb.csv", text);
const bytes = new TextEncoder().encode(text);
for (const [label, fn] of [["Log.fromBytes", () => Log.fromBytes(bytes)], ["Log.parse (string)", () => Log.parse(text)]]) {
  let best = Infinity, n = 0;
  for (let k = 0; k < 3; k++) {
    const t0 = performance.now();
    const log = fn();
    best = Math.min(best, performance.now() - t0);
    n = log.rowCount;
    log.free();
  }
  console.log(`${label.padEnd(20)} ${(bytes.length / 1e6).toFixed(1)} MB, ${n} rows: ${(best / 1000).toFixed(2)} s (${(bytes.length / 1e6 / (best / 1000)).toFixed(0)} MB/s)`);
}
