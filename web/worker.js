// Work off the main thread with the whole wasm package (pkg/full: the page's own module has
// no import, tuning or simulation), so the page never freezes:
// - parse: a large log, with progress, and its check; the columns go back transferred, not
//   copied, and the page rebuilds the Log from them; or a log put in time order; or each
//   log of a file that holds several joined on (not kept: the page runs them);
// - import: raw logger files by their detected preset (or a given recipe; with none fitting,
//   core's reading of their columns and its draft recipe for the mapping panel); guess:
//   that reading alone;
//   recipes to and from TOML;
// - tune: the HDR parameters over the drives' columns, with progress;
// - battery: the robustness battery's error profiles on the drives' columns; case: one
//   drive with one profile's errors added (to open a case as a log); profiles: their names;
// - track, pipelineTrack, pipeline: the slow work on a large log this worker parsed and
//   kept (`key`), so the page's Track view and pipeline never pause it.
import init, { Log, tune, battery, batteryProfiles, addGyroErrors, detectImport, isDriveLog, columnGuesses, draftRecipe, importLog, recipeToToml, recipeFromToml, track, pipelineTrack, runPipeline, checkLog, logInTimeOrder, logsJoined } from "./pkg/full/gyrodrift.js";

const ready = init();
/** Large logs parsed here, kept for later work on them (freed on "forget"). */
const kept = new Map();

/** The files' heads: all that core's guesses and drafts read (copy no more into the module). */
function headsOf(files) {
  return Object.fromEntries(Object.entries(files).map(([name, b]) => [name, b.subarray(0, 65536)]));
}

/** Core's `f(heads)` (`columnGuesses`, `draftRecipe`), or null where it has none (a file
 * that is not a text table; no yaw-rate column for a draft): the panel then starts from the
 * first columns. */
function orNull(f, heads) {
  try {
    return f(heads);
  } catch {
    return null;
  }
}

/** The typed arrays' buffers inside a result, to transfer instead of copy. */
function buffers(v, out = []) {
  if (ArrayBuffer.isView(v)) out.push(v.buffer);
  else if (v && typeof v === "object") for (const x of Object.values(v)) buffers(x, out);
  return out;
}

/** Logs rebuilt from the page's columns, named as the page names them. */
function logsOf(columns) {
  return columns.map((c) => {
    const log = Log.fromColumns(c);
    log.name = c.name;
    return log;
  });
}

function progressReporter(id) {
  let last = -1;
  return (f) => {
    if (f - last >= 0.02) {
      last = f;
      self.postMessage({ id, progress: f });
    }
  };
}

self.onmessage = async (ev) => {
  await ready;
  const { id, type } = ev.data;
  try {
    if (type === "tune") {
      const logs = logsOf(ev.data.train);
      const report = tune(logs, undefined, ev.data.options || {}, progressReporter(id), true); // the page left out logs check refuses
      for (const l of logs) l.free();
      self.postMessage({ id, data: report });
      return;
    }
    if (type === "battery") {
      const logs = logsOf(ev.data.drives);
      try {
        self.postMessage({ id, data: battery(logs, ev.data.options || {}, true) }); // as for tune
      } finally {
        for (const l of logs) l.free();
      }
      return;
    }
    if (type === "profiles") return self.postMessage({ id, data: batteryProfiles().map((p) => p.name) });
    if (type === "case") {
      const profile = batteryProfiles().find((p) => p.name === ev.data.profile);
      if (!profile) return self.postMessage({ id, error: `no battery profile "${ev.data.profile}"` });
      const base = Log.fromColumns(ev.data.drive);
      let data;
      try {
        const log = addGyroErrors(base, profile.errors);
        data = log.toColumns();
        log.free();
      } finally {
        base.free();
      }
      return self.postMessage({ id, data }, buffers(data));
    }
    if (type === "track" || type === "pipelineTrack" || type === "pipeline") {
      const log = kept.get(ev.data.key);
      if (!log) return self.postMessage({ id, error: "this log is no longer kept in the worker" });
      const run = { track, pipelineTrack, pipeline: runPipeline }[type];
      const data = run(log, ev.data.options);
      return self.postMessage({ id, data }, buffers(data));
    }
    if (type === "forget") {
      kept.get(ev.data.key)?.free();
      kept.delete(ev.data.key);
      return self.postMessage({ id, data: true });
    }
    if (type === "toml-out") return self.postMessage({ id, data: recipeToToml(ev.data.recipe) });
    if (type === "toml-in") return self.postMessage({ id, data: recipeFromToml(ev.data.text) });
    if (type === "guess") return self.postMessage({ id, data: orNull(columnGuesses, headsOf(ev.data.files)) });
    if (type === "import") {
      const names = Object.keys(ev.data.files);
      if (!ev.data.recipe && names.length === 1 && isDriveLog(names[0], ev.data.files[names[0]])) {
        // A drive log as a spreadsheet saved it (metadata lines padded or quoted), which the
        // page's module does not read: this module reads it as the log it is.
        const log = Log.fromBytes(ev.data.files[names[0]]);
        const data = log.toColumns();
        log.free();
        return self.postMessage({ id, data }, buffers(data));
      }
      let d;
      try {
        d = ev.data.recipe
          ? { preset: "recipe", title: ev.data.title || "your recipe", recipe: ev.data.recipe, used: [], ignored: [] }
          : detectImport(ev.data.files);
      } catch (e) {
        // No preset fits: core's reading of the column names and first rows sets the
        // mapping panel's first choices.
        const heads = headsOf(ev.data.files);
        self.postMessage({ id, error: e.message, stage: "detect", guesses: orNull(columnGuesses, heads), draft: orNull(draftRecipe, heads)?.recipe ?? null });
        return;
      }
      const { log, summary } = importLog(d.recipe, ev.data.files);
      const data = log.toColumns();
      log.free();
      self.postMessage({ id, data, detection: { ...d, summary } }, buffers(data));
      return;
    }
    const bytes = new Uint8Array(ev.data.buffer);
    if (ev.data.joined) {
      const logs = logsJoined(bytes).map(({ log, fixed, line }) => {
        const data = log.toColumns();
        const check = checkLog(log);
        log.free();
        return { data, check, fixed, line };
      });
      self.postMessage({ id, logs }, buffers(logs.map((l) => l.data)));
      return;
    }
    // timeOrder "fix": a time that repeats or steps back a little is put in order (the
    // page's module refuses such a log), and `fixed` says what was done.
    const { log, fixed } = ev.data.timeOrder === "fix" ? logInTimeOrder(bytes) : { log: Log.fromBytesWithProgress(bytes, progressReporter(id)), fixed: "" };
    const data = log.toColumns();
    // `gyrodrift check` here too, so the page does not run it on millions of rows.
    const check = checkLog(log);
    kept.set(id, log);
    self.postMessage({ id, data, key: id, check, fixed }, buffers(data));
  } catch (e) {
    // `code`: the kind of a parser's refusal that another reading mends (core's `Refusal`).
    self.postMessage({ id, error: e.message, code: e.code });
  }
};
