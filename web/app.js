// The gyrodrift dashboard: loads logs, keeps the view's settings (and the URL) in sync, and
// asks the wasm package for every number and every chart. No science here.
import init, * as gd from "./pkg/gyrodrift.js";

const PARAMS = [
  { key: "i_c_dps", label: "i_c", unit: "deg/s", min: 0, max: 0.2, step: 0.0001 },
  { key: "tau_s", label: "tau", unit: "s", min: 0, max: 5, step: 0.01 },
  { key: "theta_w_dps", label: "theta_w", unit: "deg/s", min: 0, max: 3, step: 0.001 },
  { key: "c1", label: "c1", unit: "", min: 0.005, max: 3, step: 0.005 },
  { key: "c2", label: "c2", unit: "", min: 0, max: 4, step: 0.01 },
  { key: "bias_s", label: "bias_s", unit: "s", min: 0, max: 120, step: 1 },
];
const GYRO_PARAMS = [{ key: "thres_rate_dps", label: "threshold", unit: "deg/s", min: 0, max: 10, step: 0.05 }];
const SAMPLES = [
  "sample-logs/train/city-1.csv",
  "sample-logs/train/highway-1.csv",
  "sample-logs/robot/straight.csv",
  "sample-logs/turntable/session.csv",
  "sample-logs/static/static-2h.csv",
];
const VIEW_KIND = { hdr: "drive", track: "drive", gyrodometry: "robot", calibration: "turntable", allan: null, report: null };
const COLORS = { ref: "#111111", raw: "#d1495b", hdr: "#1f5fbf", pipe: "#2e9d5b", smooth: "#7fc99b", odo: "#e08e0b", gyro: "#8e44ad", fused: "#1f5fbf", zero: "#999999" };

const state = {
  entries: [], // { name, log: gd.Log | null, error: string | null, kind, headline }
  selected: -1,
  view: "hdr",
  params: {},
  resample: true,
  gyro: { thres_rate_dps: 1.25 },
  zoom: null,
  cursor: null,
  layouts: {},
};

const $ = (id) => document.getElementById(id);
const fmt = (v, d = 3) => (Number.isFinite(v) ? v.toFixed(d) : "–");

function defaults() {
  const t3 = gd.tableIII();
  return { ...t3, bias_s: null };
}

// ---------- URL state ----------
function readUrl() {
  const h = new URLSearchParams(location.hash.slice(1));
  if (h.has("view") && h.get("view") in VIEW_KIND) state.view = h.get("view");
  for (const p of PARAMS) {
    if (h.has(p.key)) {
      const v = Number(h.get(p.key));
      if (Number.isFinite(v)) state.params[p.key] = v;
    }
  }
  if (h.has("resample")) state.resample = h.get("resample") !== "0";
  if (h.has("thres_rate_dps")) state.gyro.thres_rate_dps = Number(h.get("thres_rate_dps")) || 1.25;
  return h.get("log");
}

let urlTimer = 0;
function writeUrl() {
  // Debounced: browsers throttle history updates, and a slider fires many per second.
  clearTimeout(urlTimer);
  urlTimer = setTimeout(writeUrlNow, 150);
}

function writeUrlNow() {
  const h = new URLSearchParams();
  h.set("view", state.view);
  const e = state.entries[state.selected];
  if (e) h.set("log", e.name);
  for (const p of PARAMS) if (state.params[p.key] != null) h.set(p.key, String(state.params[p.key]));
  h.set("resample", state.resample ? "1" : "0");
  h.set("thres_rate_dps", String(state.gyro.thres_rate_dps));
  history.replaceState(null, "", "#" + h.toString());
}

// ---------- loading ----------
function addLog(name, bytes) {
  // a bad file shows its error and changes nothing else
  return addParsed(name, () => gd.Log.fromBytes(bytes));
}

function headline(entry) {
  try {
    if (entry.kind === "drive") return `HDR ${fmt(gd.hdr(entry.log, hdrOptions()).improvement, 1)}x`;
    if (entry.kind === "robot") return `Gyrodometry ${fmt(gd.gyrodometry(entry.log, state.gyro).E_psi_gyrodometry_deg, 2)} deg`;
    if (entry.kind === "turntable") return `360° err ${fmt(gd.calibrate(entry.log, {}).turn360_err_compensated_max_deg, 2)} deg`;
    if (entry.kind === "static") return `ARW ${fmt(gd.allan(entry.log).arw_deg_per_sqrt_h, 2)} deg/√h`;
  } catch (e) {
    return e.message.slice(0, 60);
  }
  return "";
}

// Files above this size are parsed in a Web Worker with a progress bar; the page stays live.
const WORKER_BYTES = 4 << 20;
let worker = null;
let jobs = 0;

/** Runs a job in the worker; `onProgress(fraction)` as it goes; resolves with {data | error}. */
function inWorker(message, transfer, onProgress) {
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

async function parseInWorker(file, buffer) {
  const bar = $("progress");
  bar.hidden = false;
  bar.value = 0;
  const res = await inWorker({ type: "parse", buffer }, [buffer], (f) => {
    bar.value = f;
    $("status").textContent = `parsing ${file.name}: ${Math.round(f * 100)} %`;
  });
  bar.hidden = true;
  return res;
}

function addParsed(name, make) {
  try {
    const log = make();
    if (!log.name) log.name = name.replace(/\.csv$/, "");
    const entry = { name: log.name, file: name, log, error: null, kind: log.kind, headline: "" };
    entry.headline = headline(entry);
    state.entries.push(entry);
    return entry;
  } catch (e) {
    const entry = { name, file: name, log: null, error: `${name}: ${e.message}`, kind: null, headline: "" };
    state.entries.push(entry);
    return entry;
  }
}

async function loadFiles(files) {
  let last = null;
  for (const f of files) {
    $("status").textContent = `reading ${f.name}…`;
    const buffer = await f.arrayBuffer();
    let e;
    if (buffer.byteLength > WORKER_BYTES && window.Worker) {
      const res = await parseInWorker(f, buffer);
      e = addParsed(f.name, () => {
        if (res.error) throw new Error(res.error);
        return gd.Log.fromColumns(res.data);
      });
    } else {
      e = addLog(f.name, new Uint8Array(buffer));
    }
    if (!e.error) last = e;
  }
  $("status").textContent = "";
  if (last) selectEntry(state.entries.indexOf(last));
  else renderList();
}

// ---------- list and selection ----------
function renderList() {
  const ul = $("logs");
  ul.replaceChildren();
  state.entries.forEach((e, i) => {
    const li = document.createElement("li");
    if (e.error) {
      li.className = "bad";
      li.textContent = e.error;
      li.dataset.error = "1";
    } else {
      if (i === state.selected) li.className = "selected";
      const b = document.createElement("button");
      b.className = "pick";
      b.innerHTML = `<div><b></b></div><div class="meta"></div>`;
      b.querySelector("b").textContent = e.name;
      b.querySelector(".meta").textContent = `${e.kind} · ${fmt(e.log.durationMin, 1)} min · ${e.headline}`;
      b.addEventListener("click", () => selectEntry(i));
      li.append(b);
    }
    ul.append(li);
  });
}

function selectEntry(i) {
  state.selected = i;
  state.zoom = null;
  state.cursor = null;
  const want = VIEW_KIND[state.view];
  const kind = state.entries[i]?.kind;
  if (want && kind && kind !== want) {
    const v = Object.keys(VIEW_KIND).find((k) => VIEW_KIND[k] === kind) || (kind === "static" ? "allan" : state.view);
    state.view = v;
  }
  render();
}

/** The selected log if it suits the view, else the first loaded one that does. */
function logFor(view) {
  const want = VIEW_KIND[view];
  const sel = state.entries[state.selected];
  if (view === "allan") {
    // any gyro log will do, a static one is what the method is for
    if (sel && !sel.error && sel.kind === "static") return sel;
    return state.entries.find((e) => !e.error && e.kind === "static") || (sel && !sel.error ? sel : null);
  }
  if (sel && !sel.error && (!want || sel.kind === want)) return sel;
  return state.entries.find((e) => !e.error && (!want || e.kind === want)) || null;
}

// ---------- parameters ----------
function hdrOptions() {
  const o = { resample: state.resample };
  for (const p of PARAMS) if (state.params[p.key] != null) o[p.key] = state.params[p.key];
  return o;
}

function buildParams(form, list, get, set, extra) {
  form.replaceChildren();
  for (const p of list) {
    const row = document.createElement("div");
    row.className = "param";
    const id = `p-${p.key}`;
    row.innerHTML = `<label for="${id}"></label><input type="range" id="${id}"><input type="number" aria-label=""><span class="unit"></span>`;
    row.querySelector("label").textContent = p.label;
    row.querySelector(".unit").textContent = p.unit;
    const [range, num] = row.querySelectorAll("input");
    num.setAttribute("aria-label", `${p.label} (${p.unit || "no unit"})`);
    for (const el of [range, num]) Object.assign(el, { min: p.min, max: p.max, step: p.step });
    const sync = () => {
      const v = get(p.key);
      range.value = v;
      num.value = v;
    };
    const onInput = (el) => () => {
      const v = Number(el.value);
      if (!Number.isFinite(v)) return;
      set(p.key, v);
      (el === range ? num : range).value = v;
      scheduleRender();
    };
    range.addEventListener("input", onInput(range));
    num.addEventListener("change", onInput(num));
    row.sync = sync;
    sync();
    form.append(row);
  }
  if (extra) extra(form);
}

function syncParams() {
  for (const row of document.querySelectorAll(".param")) row.sync?.();
  const rs = $("p-resample");
  if (rs) rs.checked = state.resample;
}

// ---------- charts ----------
function sizeCanvas(c) {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(100, Math.round(c.clientWidth * dpr));
  const h = Math.max(80, Math.round(c.clientHeight * dpr));
  if (c.width !== w || c.height !== h) Object.assign(c, { width: w, height: h });
  return dpr;
}

function chart(id, spec) {
  const c = $(id);
  const dpr = sizeCanvas(c);
  state.layouts[id] = gd.drawChart(c, { ...spec, dpr });
  c.dataset.drawn = String(Number(c.dataset.drawn || 0) + 1);
}

let pending = false;
let lastListKey = "";
function scheduleRender() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    render();
  });
}

function showError(msg) {
  const p = $("view-error");
  p.hidden = !msg;
  p.textContent = msg || "";
}

function render() {
  for (const b of document.querySelectorAll("#tabs button")) b.setAttribute("aria-selected", String(b.dataset.view === state.view));
  for (const s of document.querySelectorAll(".view")) s.hidden = s.id !== `view-${state.view}`;
  const listKey = state.entries.length + ":" + state.selected;
  if (listKey !== lastListKey) {
    renderList();
    lastListKey = listKey;
  }
  writeUrl();
  showError("");
  const t0 = performance.now();
  try {
    ({ hdr: renderHdr, track: renderTrack, gyrodometry: renderGyro, calibration: renderCal, allan: renderAllan, report: renderReport })[state.view]();
  } catch (e) {
    showError(e.message);
  }
  document.body.dataset.renderMs = (performance.now() - t0).toFixed(2);
  document.body.dataset.ready = "1";
}

function timeRange(t) {
  return state.zoom || [t[0], t[t.length - 1]];
}

let lastHdr = null;
let pipeCache = null;
function renderHdr() {
  const e = logFor("hdr");
  if (!e) return showError("Load a drive log (with gyro_dps and ref_heading_deg) for the HDR view.");
  const run = gd.runHdr(e.log, hdrOptions());
  // The recommended pipeline beside the paper's method, with the same static-bias window.
  // It depends on the log and bias_s only, so HDR's sliders reuse it.
  const pipeKey = `${e.name}|${hdrOptions().bias_s ?? ""}`;
  if (!pipeCache || pipeCache.key !== pipeKey || pipeCache.log !== e.log) {
    pipeCache = { key: pipeKey, log: e.log, run: gd.runPipeline(e.log, { bias_s: hdrOptions().bias_s ?? null }) };
  }
  const pipe = pipeCache.run;
  lastHdr = { entry: e, run, pipe };
  const r = run.result;
  const pr = pipe.result;
  const m = $("hdr-metrics");
  if (r) {
    m.innerHTML = `<span>E<sub>ψ</sub> raw <b id="m-e-raw">${fmt(r.E_psi_raw_deg, 2)}</b> deg</span>
      <span>E<sub>ψ</sub> HDR <b id="m-e-hdr">${fmt(r.E_psi_hdr_deg, 2)}</b> deg</span>
      <span>NE<sub>ψ</sub> raw <b>${fmt(r.NE_psi_raw_deg_per_min, 3)}</b> deg/min</span>
      <span>NE<sub>ψ</sub> HDR <b id="m-ne-hdr">${fmt(r.NE_psi_hdr_deg_per_min, 3)}</b> deg/min</span>
      <span>improvement <b id="m-improvement">${fmt(r.improvement, 2)}</b>×</span>
      <span>ε<sub>0</sub> <b>${fmt(r.eps0_dps, 4)}</b> deg/s · ${r.n_processed} samples · ${fmt(r.duration_min, 1)} min</span>` +
      (pr ? `<span class="recommended" title="bank of bias Kalman filters: zero-rate updates at stops, HDR's straight-road heuristic around the drive's dominant rate (docs/pipeline.md)">pipeline (recommended): E<sub>ψ</sub> <b id="m-e-pipeline">${fmt(pr.E_psi_pipeline_deg, 2)}</b> deg · NE<sub>ψ</sub> <b>${fmt(pr.NE_psi_pipeline_deg_per_min, 3)}</b> deg/min · <b id="m-improvement-pipeline">${fmt(pr.improvement_pipeline, 2)}</b>× · stops ${fmt(pr.stop_s, 0)} s (${pr.still_source})</span>
      <span class="smoothed" title="forward-backward over the whole log: for recorded logs, not available live">smoothed (offline, non-causal): E<sub>ψ</sub> <b id="m-e-smoothed">${fmt(pr.E_psi_pipeline_smoothed_deg, 2)}</b> deg · NE<sub>ψ</sub> <b>${fmt(pr.NE_psi_pipeline_smoothed_deg_per_min, 3)}</b> deg/min</span>` : "");
  } else {
    m.textContent = run.error;
  }
  const t = run.trace.time_s;
  const xr = timeRange(t);
  const series = [];
  if (run.reference) series.push({ name: "reference (GPS)", color: COLORS.ref, x: run.reference.time_s, y: run.reference.heading_deg, width: 3 });
  series.push({ name: "raw", color: COLORS.raw, x: t, y: run.trace.heading_raw_deg, width: 1 });
  series.push({ name: "HDR", color: COLORS.hdr, x: t, y: run.trace.heading_hdr_deg, width: 2 });
  series.push({ name: "pipeline", color: COLORS.pipe, x: pipe.trace.time_s, y: pipe.trace.heading_deg, width: 2 });
  series.push({ name: "smoothed (offline)", color: COLORS.smooth, x: pipe.trace.time_s, y: pipe.trace.heading_smoothed_deg, width: 1 });
  const cursor = state.cursor;
  chart("c-heading", { title: `${e.name}: heading`, x_label: "time (s)", y_label: "heading (deg)", x_range: xr, series, cursor_x: cursor });
  if (run.errors) {
    chart("c-error", {
      title: "heading error (estimate − reference)", x_label: "time (s)", y_label: "error (deg)", x_range: xr, cursor_x: cursor,
      series: [
        { name: "zero", color: COLORS.zero, x: [xr[0], xr[1]], y: [0, 0] },
        { name: "raw", color: COLORS.raw, x: run.errors.time_s, y: run.errors.raw_deg },
        { name: "HDR", color: COLORS.hdr, x: run.errors.time_s, y: run.errors.hdr_deg, width: 2 },
        ...(pipe.errors ? [{ name: "pipeline", color: COLORS.pipe, x: pipe.errors.time_s, y: pipe.errors.pipeline_deg, width: 2 },
          { name: "smoothed (offline)", color: COLORS.smooth, x: pipe.errors.time_s, y: pipe.errors.smoothed_deg, width: 1 }] : []),
      ],
    });
  }
  chart("c-rate", {
    title: "corrected rate ω and drift estimate −I (shaded: turn switch on, HDR correcting)", x_label: "time (s)", y_label: "rate (deg/s)",
    // Around zero, where drift and the turn switch live (turns go off the chart, as in Figs. 3 and 5).
    x_range: xr, y_range: [-(3 * run_theta() + 0.3), 3 * run_theta() + 0.3], cursor_x: cursor,
    shade: { x: t, mask: run.trace.turn_switch, color: "#2e9d5b", label: "turn switch on" },
    series: [
      { name: "zero", color: COLORS.zero, x: [xr[0], xr[1]], y: [0, 0] },
      { name: "ω corrected", color: COLORS.hdr, x: t, y: run.trace.rate_corrected_dps },
      { name: "−I drift estimate", color: COLORS.raw, x: t, y: run.trace.drift_estimate_dps, width: 2 },
    ],
  });
  readout();
}

function run_theta() {
  return state.params.theta_w_dps ?? 0.564;
}

function readout() {
  const el = $("hdr-readout");
  if (!lastHdr || state.cursor == null) {
    el.textContent = "";
    return;
  }
  const { run } = lastHdr;
  const t = state.cursor;
  const v = (x, y) => fmt(gd.valueAt(x, y, t), 3);
  const tr = run.trace;
  const ref = run.reference ? v(run.reference.time_s, run.reference.heading_deg) : "–";
  el.textContent = `t = ${fmt(t, 1)} s · reference ${ref} deg · raw ${v(tr.time_s, tr.heading_raw_deg)} deg · HDR ${v(tr.time_s, tr.heading_hdr_deg)} deg · ω ${v(tr.time_s, tr.rate_corrected_dps)} deg/s · −I ${v(tr.time_s, tr.drift_estimate_dps)} deg/s`;
}

function renderTrack() {
  const e = logFor("track");
  if (!e) return showError("Load a drive log with speed_mps for the Track view.");
  const tr = gd.track(e.log, hdrOptions());
  const series = [];
  if (tr.reference) series.push({ name: "reference heading", color: COLORS.ref, x: tr.reference.x_m, y: tr.reference.y_m, points: false, width: 2 });
  series.push({ name: "raw", color: COLORS.raw, x: tr.raw.x_m, y: tr.raw.y_m, points: false });
  series.push({ name: "HDR", color: COLORS.hdr, x: tr.hdr.x_m, y: tr.hdr.y_m, points: false, width: 2 });
  // Equal axes: a square range around all paths (the canvas is square).
  let lo = Infinity, hi = -Infinity;
  for (const s of series) for (const arr of [s.x, s.y]) for (const v of arr) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  const span = hi - lo || 1;
  const mid = (a) => { let l = Infinity, h = -Infinity; for (const v of a) { l = Math.min(l, v); h = Math.max(h, v); } return [l, h]; };
  const xs = series.map((s) => mid(s.x)), ys = series.map((s) => mid(s.y));
  const xc = (Math.min(...xs.map((r) => r[0])) + Math.max(...xs.map((r) => r[1]))) / 2;
  const yc = (Math.min(...ys.map((r) => r[0])) + Math.max(...ys.map((r) => r[1]))) / 2;
  const half = span / 2 * 1.05;
  chart("c-track", {
    title: `${e.name}: dead-reckoned track`, x_label: "east (m)", y_label: "north (m)",
    x_range: [xc - half, xc + half], y_range: [yc - half, yc + half],
    series: series.map((s) => ({ ...s, points: false, path: true })),
  });
}

function renderGyro() {
  const e = logFor("gyrodometry");
  if (!e) return showError("Load a robot log (gyro_dps, odo_left_m, odo_right_m, # wheelbase_m) for the Gyrodometry view.");
  const run = gd.runGyrodometry(e.log, state.gyro);
  const r = run.result;
  $("gyro-metrics").innerHTML = r
    ? `<span>E<sub>ψ</sub> odometry <b>${fmt(r.E_psi_odo_deg, 3)}</b> deg</span><span>gyro <b>${fmt(r.E_psi_gyro_deg, 3)}</b> deg</span>
       <span>Gyrodometry <b id="m-gyrodometry">${fmt(r.E_psi_gyrodometry_deg, 3)}</b> deg</span>
       <span>final errors <b>${fmt(r.final_err_odo_deg, 2)}</b> / <b>${fmt(r.final_err_gyro_deg, 2)}</b> / <b>${fmt(r.final_err_gyrodometry_deg, 2)}</b> deg</span>
       <span>gyro used in <b>${r.n_gyro_intervals}</b> intervals</span>`
    : run.error;
  const t = run.trace.time_s;
  const xr = timeRange(t);
  const series = [];
  if (e.log.columns().includes("ref_heading_deg")) series.push({ name: "reference", color: COLORS.ref, x: e.log.column("time_s"), y: e.log.column("ref_heading_deg") });
  series.push({ name: "odometry", color: COLORS.odo, x: t, y: run.trace.heading_odo_deg });
  series.push({ name: "gyro", color: COLORS.gyro, x: t, y: run.trace.heading_gyro_deg });
  series.push({ name: "Gyrodometry", color: COLORS.fused, x: t, y: run.trace.heading_gyrodometry_deg, width: 2 });
  chart("c-gyrodometry", {
    title: `${e.name}: heading (shaded: gyro increment used)`, x_label: "time (s)", y_label: "heading (deg)", x_range: xr,
    cursor_x: state.cursor, series, shade: { x: t, mask: run.trace.used_gyro, color: "#8e44ad", label: "gyro used" },
  });
}

const PALETTE = ["#1f5fbf", "#2e9d5b", "#e08e0b", "#d1495b", "#8e44ad", "#00838f", "#6d4c41"];
function renderCal() {
  const e = logFor("calibration");
  if (!e) return showError("Load a turntable log (gyro_dps, temp_c, table_rate_dps) for the Calibration view.");
  const r = gd.calibrate(e.log, {});
  $("cal-metrics").innerHTML = `<span>360° error, static bias only: max <b>${fmt(r.turn360_err_static_only_max_deg, 2)}</b>, RMS <b>${fmt(r.turn360_err_static_only_rms_deg, 2)}</b> deg</span>
    <span>compensated: max <b id="m-cal-max">${fmt(r.turn360_err_compensated_max_deg, 3)}</b>, RMS <b>${fmt(r.turn360_err_compensated_rms_deg, 3)}</b> deg</span>
    <span>w<sub>s</sub> <b>${fmt(r.w_s_dps, 4)}</b>, w<sub>s</sub>* <b>${fmt(r.w_s_star_dps, 5)}</b> deg/s · ${r.n_sets} sets · fit RMS ${fmt(r.fit_residual_rms_dps, 5)} deg/s</span>
    <span>C (rows T<sup>0..${r.q}</sup>, columns w<sub>g</sub><sup>0..${r.p}</sup>): ${r.C.map((row) => "[" + row.map((c) => c.toExponential(3)).join(", ") + "]").join(" ")}</span>`;
  const groups = new Map();
  for (const s of r.sets) {
    const k = (Math.round(s.temp_c * 2) / 2).toFixed(1);
    if (!groups.has(k)) groups.set(k, []);
    groups.get(k).push(s);
  }
  const mk = (field) => [...groups.entries()].map(([k, sets], i) => ({
    name: `${k} °C`, color: PALETTE[i % PALETTE.length], points: true,
    x: sets.map((s) => s.table_rate_dps), y: sets.map((s) => s[field]),
  }));
  chart("c-cal-before", { title: "error vs rate, static bias removed only (paper Fig. 5)", x_label: "table rate (deg/s)", y_label: "error (deg/s)", series: mk("residual_static_only_dps") });
  chart("c-cal-after", { title: "error vs rate after compensation (paper Fig. 7)", x_label: "table rate (deg/s)", y_label: "error (deg/s)", series: mk("residual_compensated_dps") });
}

function renderAllan() {
  const e = logFor("allan");
  if (!e) return showError("Load a log with gyro_dps for the Allan view.");
  const r = gd.allan(e.log);
  $("allan-metrics").innerHTML = `<span>${e.name}</span><span>ARW <b id="m-arw">${fmt(r.arw_deg_per_sqrt_s, 5)}</b> deg/√s = <b>${fmt(r.arw_deg_per_sqrt_h, 3)}</b> deg/√h</span>
    <span>bias instability <b>${fmt(r.bias_instability_dps, 5)}</b> deg/s = <b>${fmt(r.bias_instability_dph, 2)}</b> deg/h at τ = ${fmt(r.tau_at_min_s, 1)} s</span>`;
  const imin = r.tau_s.indexOf(r.tau_at_min_s);
  chart("c-allan", {
    title: "overlapping Allan deviation", x_label: "τ (s)", y_label: "σ(τ) (deg/s)", log_x: true, log_y: true,
    series: [
      { name: "Allan deviation", color: COLORS.hdr, x: r.tau_s, y: r.adev_dps, width: 2 },
      { name: "−1/2 slope (ARW)", color: COLORS.zero, x: r.tau_s, y: r.arw_line_dps },
      { name: "bias instability (min)", color: COLORS.raw, x: [r.tau_s[imin]], y: [r.adev_dps[imin]], points: true },
    ],
  });
}

function renderReport() {
  const drives = state.entries.filter((e) => !e.error && e.kind === "drive").map((e) => e.log);
  if (!drives.length) return showError("Load drive logs for the report.");
  const rep = gd.report(drives, hdrOptions());
  $("report-table").replaceChildren(reportTable(rep));
  const cmp = gd.compare(drives, { bias_s: hdrOptions().bias_s ?? null });
  $("compare-table").replaceChildren(compareTable(cmp));
}

function compareTable(cmp) {
  const t = document.createElement("table");
  const cols = [["raw", "raw"], ["hdr_table_iii", "HDR Table III"], ["fusion_offset", "Fusion offset"], ["zaru", "ZARU at stops"], ["pipeline", "pipeline"]];
  t.innerHTML = `<thead><tr><th>drive</th><th>duration (min)</th>${cols.map(([, h]) => `<th>${h}</th>`).join("")}<th title="offline, non-causal; not ranked">smoothed (offline)</th></tr></thead><tbody></tbody>`;
  const body = t.querySelector("tbody");
  for (const r of [...cmp.rows, cmp.mean]) {
    const tr = document.createElement("tr");
    tr.dataset.drive = r.name;
    const best = Math.min(...cols.map(([k]) => r[k]));
    const cells = [r.name, fmt(r.duration_min, 1), ...cols.map(([k]) => fmt(r[k], 3))];
    cells.forEach((c, i) => {
      const td = document.createElement("td");
      td.textContent = c;
      if (i >= 2 && r[cols[i - 2][0]] === best) td.className = "best";
      if (i === cells.length - 1) td.className += " pipeline";
      tr.append(td);
    });
    const sm = document.createElement("td");
    sm.textContent = fmt(r.pipeline_smoothed, 3);
    sm.className = "smoothed";
    tr.append(sm);
    body.append(tr);
  }
  return t;
}

function reportTable(rep) {
  const t = document.createElement("table");
  t.innerHTML = `<thead><tr><th>drive</th><th>duration (min)</th><th>E<sub>ψ</sub> raw (deg)</th><th>NE<sub>ψ</sub> raw (deg/min)</th><th>E<sub>ψ</sub> HDR (deg)</th><th>NE<sub>ψ</sub> HDR (deg/min)</th><th>improvement</th></tr></thead><tbody></tbody>`;
  const body = t.querySelector("tbody");
  const row = (cells) => {
    const tr = document.createElement("tr");
    for (const c of cells) {
      const td = document.createElement("td");
      td.textContent = c;
      tr.append(td);
    }
    body.append(tr);
  };
  for (const r of rep.rows) row([r.name, fmt(r.duration_min, 1), fmt(r.E_psi_raw_deg, 1), fmt(r.NE_psi_raw_deg_per_min, 2), fmt(r.E_psi_hdr_deg, 1), fmt(r.NE_psi_hdr_deg_per_min, 2), fmt(r.improvement, 1) + "×"]);
  row([`average of ${rep.rows.length}`, fmt(rep.total_duration_min, 1), fmt(rep.mean_E_psi_raw_deg, 1), fmt(rep.mean_NE_psi_raw_deg_per_min, 2), fmt(rep.mean_E_psi_hdr_deg, 1), fmt(rep.mean_NE_psi_hdr_deg_per_min, 2), `${fmt(rep.mean_improvement, 1)}× (σ ${fmt(rep.std_improvement, 2)})`]);
  return t;
}

async function runTune() {
  const drives = state.entries.filter((e) => !e.error && e.kind === "drive");
  if (!drives.length) return;
  const button = $("tune");
  const bar = $("tune-progress");
  button.disabled = true;
  bar.hidden = false;
  bar.value = 0;
  $("tune-status").textContent = "tuning in a worker…";
  const train = drives.map((e) => ({ ...e.log.toColumns(), name: e.name }));
  const transfer = train.flatMap((c) => [c.line.buffer, ...Object.values(c.columns).map((a) => a.buffer)]);
  const t0 = performance.now();
  const res = await inWorker({ type: "tune", train, options: {} }, transfer, (f) => {
    bar.value = f;
  });
  bar.hidden = true;
  button.disabled = false;
  if (res.error) {
    $("tune-status").textContent = res.error;
    return;
  }
  const rep = res.data;
  const p = rep.result.params;
  const cv = rep.result.cv;
  const cvText = cv
    ? ` · leave-one-drive-out: held-out NE_ψ ${fmt(cv.cv_table_iii_deg_per_min, 4)} with Table III, ${fmt(cv.cv_tuned_deg_per_min, 4)} tuned`
    : " · no cross-validation (fewer than 3 drives)";
  const verdict = rep.result.recommended_is_tuned ? "recommended: the tuned parameters" : "recommended: Table III (the tuned parameters do worse on drives they were not tuned on)";
  $("tune-status").textContent = `done in ${((performance.now() - t0) / 1000).toFixed(1)} s: mean NE_ψ over the ${drives.length} drives ${fmt(rep.result.objective_start_deg_per_min, 4)} → ${fmt(rep.result.objective_tuned_deg_per_min, 4)} deg/min${cvText}; ${verdict}`;
  const div = $("tune-result");
  div.replaceChildren(reportTable(rep.train.tuned));
  const b = document.createElement("button");
  b.id = "apply-tuned";
  b.textContent = `${rep.result.recommended_is_tuned ? "Apply" : "Apply anyway (not recommended)"} tuned parameters (i_c ${fmt(p.i_c_dps, 4)}, tau ${fmt(p.tau_s, 3)}, theta_w ${fmt(p.theta_w_dps, 3)}, c1 ${fmt(p.c1, 3)}, c2 ${fmt(p.c2, 3)})`;
  b.addEventListener("click", () => {
    Object.assign(state.params, p);
    syncParams();
    state.view = "hdr";
    render();
  });
  div.append(b);
}

// ---------- interaction on time charts ----------
function attachTimeInteraction(id) {
  const c = $(id);
  let drag = null;
  const toX = (ev) => {
    const L = state.layouts[id];
    if (!L) return null;
    const px = ev.offsetX * (c.width / c.clientWidth);
    return L.x_min + ((px - L.left) / (L.right - L.left)) * (L.x_max - L.x_min);
  };
  c.addEventListener("mousedown", (ev) => { drag = { x: toX(ev), shift: ev.shiftKey, range: state.layouts[id] && [state.layouts[id].x_min, state.layouts[id].x_max] }; });
  c.addEventListener("mousemove", (ev) => {
    const x = toX(ev);
    if (x == null) return;
    if (drag && drag.shift && drag.range) {
      const d = drag.x - x;
      state.zoom = [drag.range[0] + d, drag.range[1] + d];
    }
    state.cursor = x;
    scheduleRender();
  });
  window.addEventListener("mouseup", (ev) => {
    if (!drag) return;
    const d = drag;
    drag = null;
    if (d.shift || ev.target !== c) return;
    const x = toX(ev);
    if (x != null && Math.abs(x - d.x) > 1e-9 && d.range && Math.abs(x - d.x) > (d.range[1] - d.range[0]) / 200) {
      state.zoom = [Math.min(x, d.x), Math.max(x, d.x)];
      scheduleRender();
    }
  });
  c.addEventListener("wheel", (ev) => {
    const L = state.layouts[id];
    if (!L) return;
    ev.preventDefault();
    const x = toX(ev);
    const k = ev.deltaY > 0 ? 1.25 : 0.8;
    state.zoom = [x - (x - L.x_min) * k, x + (L.x_max - x) * k];
    scheduleRender();
  }, { passive: false });
  c.addEventListener("dblclick", () => { state.zoom = null; scheduleRender(); });
  // Keyboard: + / - zoom, arrow keys pan, 0 resets (the canvas is focusable).
  c.tabIndex = 0;
  c.addEventListener("keydown", (ev) => {
    const L = state.layouts[id];
    if (!L) return;
    const [a, b] = [L.x_min, L.x_max];
    const w = b - a, mid = (a + b) / 2;
    const zoom = { "+": 0.8, "=": 0.8, "-": 1.25 }[ev.key];
    if (zoom) state.zoom = [mid - (w * zoom) / 2, mid + (w * zoom) / 2];
    else if (ev.key === "ArrowLeft") state.zoom = [a - w * 0.1, b - w * 0.1];
    else if (ev.key === "ArrowRight") state.zoom = [a + w * 0.1, b + w * 0.1];
    else if (ev.key === "0") state.zoom = null;
    else return;
    ev.preventDefault();
    scheduleRender();
  });
  c.addEventListener("mouseleave", () => { state.cursor = null; scheduleRender(); });
}

function download(name, data, type) {
  const a = document.createElement("a");
  a.href = typeof data === "string" && data.startsWith("data:") ? data : URL.createObjectURL(new Blob([data], { type }));
  a.download = name;
  a.click();
}

// ---------- start ----------
async function main() {
  await init();
  state.params = defaults();
  const wantLog = readUrl();
  buildParams($("hdr-params"), PARAMS, (k) => state.params[k] ?? (k === "bias_s" ? 20 : 0), (k, v) => { state.params[k] = v; }, (form) => {
    const row = document.createElement("div");
    row.className = "param";
    row.innerHTML = `<label for="p-resample">1 Hz blocks</label><input type="checkbox" id="p-resample"><span></span><span></span>`;
    const cb = row.querySelector("input");
    cb.checked = state.resample;
    cb.addEventListener("change", () => { state.resample = cb.checked; scheduleRender(); });
    const reset = document.createElement("button");
    reset.type = "button";
    reset.id = "reset";
    reset.textContent = "Reset to Table III";
    reset.addEventListener("click", () => { state.params = defaults(); state.resample = true; syncParams(); render(); });
    form.append(row, reset);
  });
  buildParams($("gyro-params"), GYRO_PARAMS, (k) => state.gyro[k], (k, v) => { state.gyro[k] = v; });
  for (const b of document.querySelectorAll("#tabs button")) b.addEventListener("click", () => { state.view = b.dataset.view; state.zoom = null; render(); });
  for (const id of ["c-heading", "c-error", "c-rate", "c-gyrodometry"]) attachTimeInteraction(id);
  for (const b of document.querySelectorAll("button.png")) b.addEventListener("click", () => download(`${b.dataset.canvas}.png`, $(b.dataset.canvas).toDataURL("image/png")));
  $("export-trace").addEventListener("click", () => { const e = logFor("hdr"); if (e) download(`${e.name}-heading.csv`, gd.hdrTraceCsv(e.log, hdrOptions()), "text/csv"); });
  $("export-json").addEventListener("click", () => { const e = logFor("hdr"); if (e) download(`${e.name}-hdr.json`, JSON.stringify(gd.hdr(e.log, hdrOptions()), null, 2), "application/json"); });
  $("tune").addEventListener("click", runTune);
  $("file-input").addEventListener("change", (ev) => loadFiles([...ev.target.files]));
  document.addEventListener("dragover", (ev) => { ev.preventDefault(); document.body.classList.add("dragging"); });
  document.addEventListener("dragleave", () => document.body.classList.remove("dragging"));
  document.addEventListener("drop", (ev) => { ev.preventDefault(); document.body.classList.remove("dragging"); loadFiles([...ev.dataTransfer.files]); });
  window.addEventListener("resize", scheduleRender);

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
  let idx = state.entries.findIndex((e) => e.name === wantLog);
  if (idx < 0) idx = state.entries.findIndex((e) => e.kind === VIEW_KIND[state.view]) ;
  state.selected = Math.max(0, idx);
  render();
}

main().catch((e) => showError(`could not start: ${e.message}`));
window.gyrodrift = { state, gd, render };
