#!/usr/bin/env node
// Speed of a core-module build (the browser's main module, or a scratch build of it) in Node:
// Log.fromBytes of the 100 MB log (best of 3; `node tests/bench/parse-node.mjs` writes it)
// and runPipeline on Highway 1 (best of 5). Usage: node tests/bench/core-module-node.mjs DIR
// (DIR holds gyrodrift.js and gyrodrift_bg.wasm; default web/pkg, the core module).
import { readFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const root = join(fileURLToPath(import.meta.url), "..", "..", "..");
const dir = resolve(process.argv[2] ?? join(root, "web", "pkg"));
const mod = await import(join(dir, "gyrodrift.js"));
mod.initSync({ module: readFileSync(join(dir, "gyrodrift_bg.wasm")) });
const big = readFileSync("/tmp/gyrodrift-100mb.csv");
let parse = Infinity;
for (let k = 0; k < 3; k++) {
  const t0 = performance.now();
  const log = mod.Log.fromBytes(big);
  parse = Math.min(parse, performance.now() - t0);
  log.free();
}
const log = mod.Log.fromBytes(readFileSync(join(root, "sample-logs", "train", "highway-1.csv")));
let pipe = Infinity;
for (let k = 0; k < 5; k++) {
  const t0 = performance.now();
  mod.runPipeline(log, {});
  pipe = Math.min(pipe, performance.now() - t0);
}
log.free();
console.log(`${dir}: 100 MB Log.fromBytes ${parse.toFixed(0)} ms (best of 3); runPipeline Highway 1 ${pipe.toFixed(0)} ms (best of 5)`);
