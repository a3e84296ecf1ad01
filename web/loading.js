// Loading: files and samples into the log list, large files parsed in a Web Worker.
import * as gd from "./pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, SAMPLES } from "./state.js";
import { renderList, selectEntry } from "./controls.js";
import { openMapping } from "./mapping.js";
import { download } from "./charts.js";

export function addLog(name, bytes) {
  // a bad file shows its error and changes nothing else
  return addParsed(name, () => gd.Log.fromBytes(bytes));
}

export function headline(entry) {
  try {
    if (entry.kind === "drive" && !entry.scored) return "no reference: not scored";
    if (entry.kind === "drive") return `HDR ${fmt(gd.hdr(entry.log, hdrOptions()).improvement, 1)}x`;
    if (entry.kind === "robot") return `Gyrodometry ${fmt(gd.gyrodometry(entry.log, state.gyro).E_psi_gyrodometry_deg, 2)} deg`;
    if (entry.kind === "turntable") return `360° err ${fmt(gd.calibrate(entry.log, {}).turn360_err_compensated_max_deg, 2)} deg`;
    if (entry.kind === "static") return `ARW ${fmt(gd.allan(entry.log).arw_deg_per_sqrt_h, 2)} deg/√h`;
  } catch (e) {
    return e.message.slice(0, 60);
  }
  return "";
}

/** Yields to the page (input, drawing) before the next step. */
const nextTask = () => new Promise((r) => setTimeout(r, 0));

/** Rows copied into the page's module per task when a worker hands a big log over. */
const CHUNK_ROWS = 250_000;

/** A worker's parsed columns as a Log, copied in a chunk per task (core checks each chunk). */
async function buildInTasks(data) {
  const names = Object.keys(data.columns);
  const n = data.columns.time_s ? data.columns.time_s.length : 0;
  const chunk = (i) => {
    const cut = (a) => a.subarray(i, Math.min(n, i + CHUNK_ROWS));
    return { meta: data.meta, line: data.line.length === n ? cut(data.line) : undefined, columns: Object.fromEntries(names.map((k) => [k, cut(data.columns[k])])) };
  };
  const b = new gd.LogBuilder(chunk(0), n);
  try {
    for (let i = CHUNK_ROWS; i < n; i += CHUNK_ROWS) {
      await nextTask();
      b.append(chunk(i));
    }
    return b.finish();
  } finally {
    b.free();
  }
}

// Files above this size are parsed in a Web Worker with a progress bar; the page stays live.
const WORKER_BYTES = 4 << 20;
let worker = null;
let jobs = 0;

/** Entries' logs as named columns for the worker, with the buffers to transfer (copies: the page keeps its logs). */
export function driveColumns(entries) {
  const cols = entries.map((e) => ({ ...e.log.toColumns(), name: e.name }));
  return { cols, transfer: cols.flatMap((c) => [c.line.buffer, ...Object.values(c.columns).map((a) => a.buffer)]) };
}

/** Runs a job in the worker; `onProgress(fraction)` as it goes; resolves with {data | error}. */
export function inWorker(message, transfer, onProgress) {
  worker ||= new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
  const id = ++jobs;
  return new Promise((resolve) => {
    const onMessage = (ev) => {
      if (ev.data.id !== id) return;
      if (ev.data.progress != null) return onProgress(ev.data.progress);
      worker.removeEventListener("message", onMessage);
      resolve(ev.data);
    };
    worker.addEventListener("message", onMessage);
    worker.postMessage({ ...message, id }, transfer);
  });
}

export async function parseInWorker(file, buffer, options = {}) {
  const bar = $("progress");
  bar.hidden = false;
  bar.value = 0;
  const res = await inWorker({ type: "parse", buffer, ...options }, [buffer], (f) => {
    bar.value = f;
    $("status").textContent = `parsing ${file.name}: ${Math.round(f * 100)} %`;
  });
  bar.hidden = true;
  return res;
}

/** A log the worker parsed (`parseInWorker`'s answer) added to the list as `addParsed` adds
 * one, copied in a chunk per task so none holds the page for long; the check comes from the
 * worker, which keeps its copy for the slow work (Track, pipeline) unless the log was split
 * at a gap (its parts are not the worker's log) or failed. */
async function addWorkerParsed(f, res) {
  let built;
  try {
    built = res.error ? { error: Object.assign(new Error(res.error), { code: res.code }) } : { log: await buildInTasks(res.data) };
  } catch (err) {
    built = { error: err };
  }
  const e = addParsed(f.name, () => {
    if (built.error) throw built.error;
    return built.log;
  }, res.check);
  if (res.key != null && !e.error && !e.note) e.workerKey = res.key;
  else if (res.key != null) inWorker({ type: "forget", key: res.key }, [], () => {});
  return e;
}

/** A name no loaded log has: "City 1", then "City 1 (2)", ... (the list and the URL name logs). */
function uniqueName(name) {
  const taken = new Set(state.entries.map((e) => e.name));
  let out = name;
  for (let k = 2; taken.has(out); k++) out = `${name} (${k})`;
  return out;
}

/** Adds a parsed log (split at gaps as the CLI does); `checked` is its check when the
 * worker ran it already. */
export function addParsed(name, make, checked = null) {
  try {
    const whole = make();
    const base = uniqueName(whole.name || name.replace(/\.csv$/, ""));
    const check = checked ?? gd.checkLog(whole);
    let parts = [whole];
    let note = null;
    if (check.gaps_s.length) {
      // No method may integrate across a gap in time: the log becomes its parts, each a
      // drive of its own (as the CLI's --gaps split).
      const split = whole.splitAtGaps(undefined);
      whole.free();
      parts = split.parts;
      note = split.summary;
      if (!parts.length) throw new Error(`every part between its gaps is shorter than 30 s (${note})`);
      parts.forEach((log, k) => (log.name = `${base} (part ${k + 1} of ${parts.length})`));
    } else {
      whole.name = base;
    }
    const entries = parts.map((log) => {
      const entry = { name: log.name, file: name, log, error: null, kind: log.kind, headline: "", findings: [], note };
      // A drive with no GPS course (speed, no ref_heading_deg value) is shown in the HDR
      // view, but not scored, tuned or put in the battery: core's rule, which looks at the
      // column inside the module (no copy) and stops at its first value.
      entry.scored = entry.kind === "drive" && log.hasReference;
      entry.headline = headline(entry);
      // What `gyrodrift check` would say: unit, sign and gap mistakes, each with its fix.
      const findings = parts.length > 1 ? gd.checkLog(log).findings : check.findings;
      entry.findings = findings.filter((f) => f.severity !== "info");
      // Its errors (time not in seconds, heading in radians, gyro in another unit or
      // clockwise): the CLI refuses such a log; the page flags it, leaves it out of the
      // Report and offers the fix.
      entry.errors = findings.filter((f) => f.severity === "error");
      // Information (no stops to judge the bias at, a scale to check): a quiet note of its own.
      entry.info = findings.filter((f) => f.severity === "info");
      return entry;
    });
    state.entries.push(...entries);
    return entries[0];
  } catch (e) {
    // `code`: the kind of a parser's refusal that another reading mends (core's `Refusal`).
    const entry = { name, file: name, log: null, error: `${name}: ${e.message}`, code: e.code ?? null, kind: null, headline: "" };
    state.entries.push(entry);
    return entry;
  }
}

/** Raw logger exports: the preset detected from all of them (or a dropped recipe, .toml or .json),
 * imported in the worker and added as one log; an error entry otherwise. */
async function importRaw(files, recipe) {
  const label = files.map((f) => f.name).join(", ");
  $("status").textContent = `importing ${label}…`;
  const bytes = {};
  let total = 0;
  for (const f of files) {
    bytes[f.name] = new Uint8Array(await f.arrayBuffer());
    total += f.size;
  }
  // In the worker always: it holds the whole package (the page's module has no import).
  // The bytes are copied, not transferred: the mapping panel may import them again.
  const importer = async (r, title) => {
    if (!window.Worker) return { error: "this browser has no Web Workers: import with gyrodrift import" };
    const bar = $("progress");
    bar.hidden = total < WORKER_BYTES;
    bar.removeAttribute("value"); // no progress from inside an import: indeterminate
    const out = await inWorker({ type: "import", files: bytes, recipe: r, title }, [], () => {});
    bar.hidden = true;
    return out;
  };
  let res = await importer(recipe);
  if (res.stage === "detect") {
    // No preset fits: the user maps the columns (cancel keeps the error entry).
    const named = files.map((f) => ({ name: f.name, bytes: bytes[f.name] }));
    const mapped = await openMapping(named, res.error, (r) => importer(r, "your column mapping"), { guesses: res.guesses, draft: res.draft });
    if (mapped) res = { ...mapped.res, detection: { ...mapped.res.detection, recipe: mapped.recipe } };
  }
  const before = state.entries.length;
  const entry = addParsed(label, () => {
    if (res.error) throw new Error(res.error);
    const log = gd.Log.fromColumns(res.data);
    if (!log.name || log.name === "log") log.name = files[0].name;
    return log;
  });
  // This import's entries (a log split at gaps is several) carry how they were imported.
  if (!entry.error) for (const e of state.entries.slice(before)) e.imported = res.detection;
  return entry;
}

/** Saves a recipe as TOML (written by the worker's module), as `gyrodrift import --recipe` reads it. */
export async function saveRecipe(name, recipe) {
  const res = await inWorker({ type: "toml-out", recipe }, [], () => {});
  if (res.error) download(`${name}.recipe.json`, JSON.stringify(recipe, null, 2), "application/json");
  else download(`${name}.recipe.toml`, res.data, "application/toml");
}

/** A dropped file as the page reads it: a gzip-compressed one (`drive.csv.gz`, as fleets
 * store logs) as the file inside it, decompressed by the browser's own
 * DecompressionStream; any other as it is. Throws the entry's error for a file that cannot
 * be read (a dropped folder) or decompressed. */
async function readable(f) {
  let head;
  try {
    head = new Uint8Array(await f.slice(0, 2).arrayBuffer());
  } catch {
    throw new Error(`${f.name}: cannot be read (a folder? drop the files in it, or its .zip)`);
  }
  if (head[0] !== 0x1f || head[1] !== 0x8b) return f;
  try {
    const inner = await new Response(f.stream().pipeThrough(new DecompressionStream("gzip"))).blob();
    return new File([inner], f.name.replace(/\.gz$/i, ""), { type: "text/csv" });
  } catch {
    // The browser says only "Failed to fetch" for a stream that ends inside a block.
    throw new Error(`${f.name}: a damaged or cut gzip file: it cannot be decompressed`);
  }
}

/** The files of dropped entries, a dropped folder (an unzipped export, a folder of drives)
 * as the files in it at any depth, in the order the browser lists them; hidden files
 * (`.DS_Store`) and macOS resource forks left out, as the zip import leaves them. */
export async function filesOf(entries) {
  const out = [];
  const walk = async (entry) => {
    if (entry.name.startsWith(".") || entry.name === "__MACOSX") return;
    if (entry.isFile) out.push(await new Promise((ok, bad) => entry.file(ok, bad)));
    else if (entry.isDirectory) {
      const reader = entry.createReader();
      // readEntries gives a folder in batches until an empty one.
      for (let batch; (batch = await new Promise((ok, bad) => reader.readEntries(ok, bad))).length; ) {
        for (const e of batch) await walk(e);
      }
    }
  };
  for (const e of entries) await walk(e);
  return out;
}

export async function loadFiles(given) {
  // Drive logs v1 open as they are; other files are raw exports, imported together by the
  // preset they fit (a recipe .toml or .json dropped with them is used instead of detection).
  const logs = [];
  const raw = [];
  let recipe = null;
  const files = [];
  for (const f of given) {
    try {
      files.push(await readable(f));
    } catch (e) {
      state.entries.push({ name: f.name, file: f.name, log: null, error: e.message, kind: null, headline: "" });
    }
  }
  for (const f of files) {
    if (/\.(json|toml)$/i.test(f.name)) {
      try {
        if (/\.json$/i.test(f.name)) recipe = JSON.parse(await f.text());
        else {
          const res = await inWorker({ type: "toml-in", text: await f.text() }, [], () => {});
          if (res.error) throw new Error(res.error);
          recipe = res.data;
        }
      } catch (e) {
        state.entries.push({ name: f.name, file: f.name, log: null, error: `${f.name}: not a recipe: ${e.message}`, kind: null, headline: "" });
      }
      continue;
    }
    const head = new Uint8Array(await f.slice(0, 65536).arrayBuffer());
    (gd.isDriveLog(f.name, head) ? logs : raw).push(f);
  }
  let last = null;
  if (raw.length) {
    const e = await importRaw(raw, recipe);
    if (!e.error) last = e;
  }
  for (const f of logs) {
    $("status").textContent = `reading ${f.name}…`;
    const buffer = await f.arrayBuffer();
    let e;
    if (buffer.byteLength > WORKER_BYTES && window.Worker) {
      e = await addWorkerParsed(f, await parseInWorker(f, buffer));
      // Its first drawing in a task of its own, so none holds the page for long.
      await nextTask();
      // HDR's preparation (a pass over every row) in a task of its own before the first drawing.
      if (!e.error && !e.note && e.kind === "drive") {
        try {
          gd.prepareHdr(e.log, hdrOptions());
        } catch {
          /* the HDR view shows the error when it runs */
        }
        await nextTask();
      }
    } else {
      e = addLog(f.name, new Uint8Array(buffer));
      if (e.error && window.Worker && !ORDER_CODES.includes(e.code)) {
        // The page's module reads the format as written; the worker's also reads what a
        // spreadsheet writes (`;` and decimal commas, metadata lines padded or quoted).
        state.entries.splice(state.entries.indexOf(e), 1);
        e = await addWorkerParsed(f, await parseInWorker(f, buffer));
      }
    }
    if (!e.error) {
      last = e;
      // Its file, should check find an error the column mapper can fix (remap).
      for (const x of state.entries) if (x.file === f.name && !x.error && !x.source) x.source = f;
    } else if (e.code === "time_order" && window.Worker) {
      // A time that repeats or steps back: the list offers to put it in order (fixTimeOrder).
      Object.assign(e, { source: f, timeOrder: true });
    } else if (JOINED_CODES.includes(e.code) && window.Worker) {
      // Several logs joined in one file, or a logger's clock reset: the list offers to read
      // each (readJoined).
      Object.assign(e, { source: f, joined: true });
    } else if (e.code === "cut_row" && window.Worker) {
      // A logger stopped mid-line: the worker's module reads the log without its cut last
      // line and says so (a row cut anywhere else stays the error it is).
      Object.assign(e, { source: f });
      const read = await fixTimeOrder(e, "✂ last line cut short");
      if (!read.error) last = read;
    }
  }
  $("status").textContent = "";
  if (last) selectEntry(state.entries.indexOf(last));
  else renderList();
}

/** Core's refusals (`Error.code`) that the worker's module reads another way, not by
 * reading the file again as a spreadsheet's: a time that repeats or steps back a little
 * (put in order), a clock reset (read in parts), a row cut short (dropped where it is the
 * last line; the page's module also reads a second log joined on as one). */
const ORDER_CODES = ["time_order", "clock_reset", "cut_row"];
/** Core's refusals of a file the worker reads as logs of their own: a second log joined
 * on, or a clock reset (a logger restarted), which no time-order fix mends. */
const JOINED_CODES = ["joined", "clock_reset"];

/** A log refused for its time order (or its last line cut short), read again in the worker
 * (whose module has the fixing parser) with its time put in order: rows of one time merged by
 * their mean, rows up to 1 s late sorted in, as the CLI's `--time-order fix`, and a last line
 * cut short dropped. It takes the error entry's place; what was fixed is its note, under
 * `label`. A clock reset stays an error entry, offered to be read in parts. Returns the new
 * entry. */
export async function fixTimeOrder(entry, label = "⇅ put in time order") {
  const f = entry.source;
  const res = await parseInWorker(f, await f.arrayBuffer(), { timeOrder: "fix" });
  state.entries.splice(state.entries.indexOf(entry), 1);
  const e = await addWorkerParsed(f, res);
  if (!e.error) Object.assign(e, { orderNote: res.fixed, orderLabel: label });
  // The page's module reads a second log joined on as a row cut short: the worker's names it.
  else if (JOINED_CODES.includes(e.code)) Object.assign(e, { source: f, joined: true });
  $("status").textContent = "";
  if (!e.error) selectEntry(state.entries.indexOf(e));
  else renderList();
  return e;
}

/** A file of several logs joined on (`cat a.csv b.csv`), read in the worker as the CLI's
 * `split` reads it: each log takes the error entry's place as a log of its own, its note the
 * line it starts on (and what putting its time in order did). Returns the first. */
export async function readJoined(entry) {
  const f = entry.source;
  const res = await parseInWorker(f, await f.arrayBuffer(), { joined: true });
  $("status").textContent = "";
  if (res.error) {
    entry.error = `${f.name}: ${res.error}`;
    renderList();
    return entry;
  }
  state.entries.splice(state.entries.indexOf(entry), 1);
  const added = [];
  for (const l of res.logs) {
    const e = await addWorkerParsed(f, { data: l.data, check: l.check });
    const note = `from line ${l.line} of ${f.name}${l.fixed ? `; ${l.fixed}` : ""}`;
    if (!e.error) Object.assign(e, { orderNote: note, orderLabel: "✂ one of the logs joined in its file" });
    added.push(e);
  }
  const first = added.find((e) => !e.error);
  if (first) selectEntry(state.entries.indexOf(first));
  else renderList();
  return first ?? added[0];
}

/** The shipped sample logs, fetched next to the page (absent on a bare static host). */
export async function loadSamples() {
  $("status").textContent = "loading sample logs…";
  for (const path of SAMPLES) {
    try {
      const res = await fetch(path);
      if (res.ok) addLog(path.split("/").pop(), new Uint8Array(await res.arrayBuffer()));
    } catch {
      /* served without sample-logs: the user opens files */
    }
  }
  $("status").textContent = "";
}
