// Slow work on a large log, in the Web Worker that parsed and kept it: the Track view's
// paths and the pipeline (seconds on millions of rows), so the page never pauses. The last
// result per log and kind is kept and shown, marked stale, while a new one is computed.
import { inWorker } from "./loading.js";
import { scheduleRender } from "./render.js";

const jobs = new Map(); // `${key}|${kind}` -> { options, pending, data, error }

/** The worker's result for this log, kind ("track", "pipeline") and options: `null` when
 * the log lives on the page only (compute it there), else `{ data, error, pending, stale }`
 * (data may be an older result, or null before the first). */
export function background(entry, kind, options) {
  if (entry.workerKey == null) return null;
  const id = `${entry.workerKey}|${kind}`;
  const want = JSON.stringify(options);
  let job = jobs.get(id);
  if (!job || job.options !== want) {
    const next = { options: want, pending: true, data: job?.data ?? null, error: null };
    jobs.set(id, next);
    inWorker({ type: kind, key: entry.workerKey, options }, [], () => {}).then((res) => {
      if (jobs.get(id) !== next) return; // a newer request replaced it
      Object.assign(next, { pending: false, data: res.data ?? null, error: res.error ?? null });
      scheduleRender();
    });
    job = next;
  }
  return { data: job.data, error: job.error, pending: job.pending, stale: job.pending && job.data != null };
}

const pageRuns = new WeakMap(); // log -> Map(kind -> { key, data, error }): work done on the page

/** Work that depends on a log and `options` only (not on sliders): the worker's result for a
 * log it keeps (`background`), else `compute()` run on the page once per log, kind and
 * options. `{ data, error, pending, stale }` either way; a thrown error is kept as `error`. */
export function perLog(entry, kind, options, compute) {
  const bg = background(entry, kind, options);
  if (bg) return bg;
  const key = JSON.stringify(options);
  let runs = pageRuns.get(entry.log);
  if (!runs) pageRuns.set(entry.log, (runs = new Map()));
  let c = runs.get(kind);
  if (!c || c.key !== key) {
    c = { key, data: null, error: null, pending: false, stale: false };
    try {
      c.data = compute();
    } catch (err) {
      c.error = err.message;
    }
    runs.set(kind, c);
  }
  return c;
}

/** Forgets a removed log's work and the worker's copy of it. */
export function forget(entry) {
  if (entry.workerKey == null) return;
  for (const k of [...jobs.keys()]) if (k.startsWith(`${entry.workerKey}|`)) jobs.delete(k);
  inWorker({ type: "forget", key: entry.workerKey }, [], () => {});
}
