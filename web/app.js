// The gyrodrift dashboard: loads logs, keeps the view's settings (and the URL) in sync, and
// asks the wasm package for every number and every chart. No science here. Modules:
// state.js (settings, URL), loading.js (files, worker), controls.js (list, forms),
// charts.js (canvases, legends, exports), chart-input.js (zoom, pan, cursor, the track too),
// render.js (the active view), views/*.js (one per view), touchtip.js (the tooltips, on a
// touch screen), remap.js (a check error's fix in the column mapper).
import init, * as gd from "./pkg/gyrodrift.js";
import initPlot from "./pkg/plot/gyrodrift_plot.js";
import { $, state, defaults, readUrl, urlHash, hdrOptions, pipelineOptions, pipeSetting, PARAMS, PIPE_PARAMS, GYRO_PARAMS, VIEW_KIND } from "./state.js";
import { filesOf, loadFiles, loadSamples } from "./loading.js";
import { buildParams, syncParams, logFor } from "./controls.js";
import { csvOf, download, pngOf, timeChartsCsv } from "./charts.js";
import { attachTimeInteraction, attachTrackInteraction } from "./chart-input.js";
import { render, scheduleRender, showError } from "./render.js";
import { runTune, reportExports } from "./views/report.js";
import { runBattery, addWorse } from "./views/robustness.js";
import { setupTouchTips } from "./touchtip.js";

// ---------- start ----------
async function main() {
  // The methods' module and the charts' module (the worker loads the whole package itself).
  await Promise.all([init(), initPlot()]);
  state.params = defaults();
  state.gyro = { thres_rate_dps: gd.defaults("gyrodometry").thres_rate_dps };
  const wantLog = readUrl();
  setupParams();
  setupTabs();
  setupExports();
  setupFiles();
  setupTouchTips();
  // The first-use panel is open until it has been closed once (remembered in this browser).
  const intro = $("first-use");
  intro.open = localStorage.getItem("gyrodrift.intro") !== "closed";
  intro.addEventListener("toggle", () => localStorage.setItem("gyrodrift.intro", intro.open ? "open" : "closed"));
  await loadSamples();
  applyLog(wantLog);
  render();
  setupRouting();
}

/** The HDR and Gyrodometry parameter forms; core checks every value typed. */
function setupParams() {
  buildParams($("hdr-params"), PARAMS, (k) => state.params[k] ?? (k === "bias_s" ? gd.defaultBiasS() : 0), (k, v) => { state.params[k] = v; }, (form) => {
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
  }, (k, v) => gd.checkOptions("hdr", { ...hdrOptions(), [k]: v }) ?? null);
  buildParams($("pipe-params"), PIPE_PARAMS, pipeSetting, (k, v) => { state.pipe[k] = v; }, (form) => {
    const reset = document.createElement("button");
    Object.assign(reset, { type: "button", id: "reset-pipe", textContent: "Reset the pipeline to its defaults" });
    reset.addEventListener("click", () => { state.pipe = {}; syncParams(); render(); });
    form.append(reset);
  }, (k, v) => gd.checkOptions("pipeline", pipelineOptions({ [k]: v })) ?? null);
  buildParams($("gyro-params"), GYRO_PARAMS, (k) => state.gyro[k], (k, v) => { state.gyro[k] = v; }, null, (k, v) => gd.checkOptions("gyrodometry", { ...state.gyro, [k]: v }) ?? null);
}

/** The view tabs (a tablist: arrow keys move between them; roving tabindex set in render)
 * and the time charts' zoom and cursor. */
function setupTabs() {
  const tabs = [...document.querySelectorAll("#tabs button")];
  for (const b of tabs) b.addEventListener("click", () => { state.view = b.dataset.view; state.zoom = null; render(); });
  $("tabs").addEventListener("keydown", (ev) => {
    const i = tabs.findIndex((b) => b.dataset.view === state.view);
    const j = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: tabs.length - 1 }[ev.key];
    if (j === undefined) return;
    ev.preventDefault();
    const b = tabs[(j + tabs.length) % tabs.length];
    b.click();
    b.focus();
  });
  for (const id of ["c-heading", "c-error", "c-rate", "c-columns", "c-gyrodometry"]) attachTimeInteraction(id);
  attachTrackInteraction();
  window.addEventListener("resize", scheduleRender);
}

/** Downloads: charts as PNG, the heading trace, a result JSON that reproduces, the Report's
 * tables; files named by log and chart (City 1-heading.png). */
function setupExports() {
  const fileName = (suffix) => `${(logFor(state.view)?.name || "gyrodrift").replace(/[^\w.() -]+/g, "_")}-${suffix}`;
  for (const b of document.querySelectorAll("button.png")) {
    const id = b.dataset.canvas, short = id.replace(/^c-/, "");
    b.addEventListener("click", () => download(fileName(`${short}.png`), pngOf(id)));
    // Beside each PNG: the chart's shown series as CSV.
    const csv = document.createElement("button");
    Object.assign(csv, { type: "button", className: "csv", textContent: "CSV" });
    csv.dataset.canvas = id;
    csv.setAttribute("aria-label", b.getAttribute("aria-label").replace(/ as PNG$/, "").replace(/^Download the /, "Download the series of the ") + " as CSV");
    csv.addEventListener("click", () => download(fileName(`${short}.csv`), csvOf(id), "text/csv"));
    b.after(csv);
  }
  $("export-trace").addEventListener("click", () => { if (logFor("hdr")) download(fileName("hdr-series.csv"), timeChartsCsv(["c-heading", "c-error", "c-rate", "c-columns"]), "text/csv"); });
  $("export-json").addEventListener("click", () => {
    const e = logFor("hdr");
    if (!e) return;
    const out = { log: e.name, file: e.file, gyrodrift: gd.version(), method: "hdr", options: hdrOptions(), result: gd.hdr(e.log, hdrOptions()) };
    download(fileName("hdr.json"), JSON.stringify(out, null, 2), "application/json");
  });
  $("tune").addEventListener("click", runTune);
  $("battery").addEventListener("click", runBattery);
  $("worse").addEventListener("click", addWorse);
  reportExports(download);
}

/** Opening and dropping files. */
function setupFiles() {
  $("file-input").addEventListener("change", (ev) => {
    const files = [...ev.target.files];
    ev.target.value = ""; // the same file can be opened again
    loadFiles(files);
  });
  document.addEventListener("dragover", (ev) => { ev.preventDefault(); document.body.classList.add("dragging"); });
  document.addEventListener("dragleave", () => document.body.classList.remove("dragging"));
  document.addEventListener("drop", (ev) => {
    ev.preventDefault();
    document.body.classList.remove("dragging");
    // The entries are the drop's only while its event runs: taken now, walked after.
    const entries = [...(ev.dataTransfer.items ?? [])].map((i) => i.webkitGetAsEntry?.()).filter(Boolean);
    if (entries.some((e) => e.isDirectory)) filesOf(entries).then(loadFiles);
    else loadFiles([...ev.dataTransfer.files]);
  });
}

/** A link pasted into this tab, or Back and Forward: apply the state it names. */
function setupRouting() {
  const follow = () => {
    if (location.hash === urlHash()) return;
    const log = readUrl();
    applyLog(log);
    syncParams();
    render();
  };
  window.addEventListener("hashchange", follow);
  window.addEventListener("popstate", follow);
}

/** Selects the log a link names; one opened from disk before a reload cannot come back, and
 * the page says so instead of showing another log silently. */
function applyLog(name) {
  let idx = name ? state.entries.findIndex((e) => e.name === name && !e.error) : -1;
  $("status").textContent = name && idx < 0 ? `The link names the log "${name}", which is not loaded (a log opened from disk is not kept across reloads): open it again.` : "";
  if (idx < 0) idx = state.entries.findIndex((e) => !e.error && e.kind === VIEW_KIND[state.view]);
  state.selected = Math.max(0, idx);
}

main().catch((e) => showError(`could not start: ${e.message}`));
window.gyrodrift = { state, gd, render };
