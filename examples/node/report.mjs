#!/usr/bin/env node
// The fleet-tool use case: process a folder of drive logs with the gyrodrift package and
// print the HDR paper's Table II for them (Markdown).
//   node examples/node/report.mjs sample-logs/train
import { readdirSync, readFileSync } from "node:fs";
import { join, basename } from "node:path";
import { Log, reportMarkdown } from "gyrodrift";

const dir = process.argv[2];
if (!dir) {
  console.error("usage: report.mjs FOLDER");
  process.exit(2);
}
const files = readdirSync(dir).filter((f) => f.endsWith(".csv")).sort();
const logs = [];
for (const f of files) {
  try {
    const log = Log.parse(readFileSync(join(dir, f), "utf8"));
    if (!log.name) log.name = basename(f, ".csv");
    logs.push(log);
  } catch (e) {
    // one bad file does not stop the fleet report
    console.error(`${join(dir, f)}: ${e.message}`);
  }
}
process.stdout.write(reportMarkdown(logs, {}));
for (const log of logs) log.free();
