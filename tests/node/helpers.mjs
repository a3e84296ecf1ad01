// Shared helpers of the Node tests: paths, the CLI, and the package as users import it.
import { execFileSync } from "node:child_process";
import { readdirSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { dirname, join } from "node:path";

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
export const SAMPLES = join(ROOT, "sample-logs");
export const CLI = join(ROOT, "target", "release", "gyrodrift");
/** The shipped sample drives, training then test, each folder's sorted. */
export const drives = ["train", "test"].flatMap((d) =>
  readdirSync(join(SAMPLES, d)).filter((f) => f.endsWith(".csv")).sort().map((f) => join(SAMPLES, d, f)),
);

/** Runs the CLI; returns stdout. */
export function cli(...args) {
  return execFileSync(CLI, args, { encoding: "utf8", maxBuffer: 1 << 26 });
}

/** Typed arrays to plain arrays, so results compare with JSON from the CLI. */
export function plain(value) {
  return JSON.parse(JSON.stringify(value, (_k, v) => (ArrayBuffer.isView(v) ? Array.from(v) : v)));
}
