// The HDR view: heading, error and rate charts for the paper's method beside the pipeline.
import * as gd from "../pkg/gyrodrift.js";
import { $, esc, fmt, state, hdrOptions, pipelineOptions, COLORS, PALETTE, METRIC_HELP } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, originOf } from "../charts.js";
import { showError, render } from "../render.js";
import { perLog } from "../background.js";

let lastHdr = null;
const NO_PIPE = { result: null, summary: null, trace: null, errors: null, pending: true };
/** The recommended pipeline beside the paper's method, with the same static-bias window.
 * It depends on the log, bias_s and the pipeline settings only, so HDR's sliders reuse it;
 * a large log's runs in the worker (seconds on millions of rows) and shows when it arrives. */
function pipelineOf(e) {
  const options = pipelineOptions();
  const r = perLog(e, "pipeline", options, () => gd.runPipeline(e.log, options));
  // On the page its error is the view's, as the HDR run's (the worker's shows as pending).
  if (r.error && e.workerKey == null) throw new Error(r.error);
  return r.data ? { ...r.data, pending: r.pending } : NO_PIPE;
}

export function renderHdr() {
  const e = logFor("hdr");
  if (!e) return showError("Load a drive log (with gyro_dps and ref_heading_deg) for the HDR view.");
  const v = drawView();
  const run = gd.runHdr(e.log, hdrOptions(), v);
  // The recommended pipeline beside the paper's method, with the same static-bias window.
  // It depends on the log, bias_s and the pipeline settings only, so HDR's sliders reuse it.
  const pipe = pipelineOf(e);
  lastHdr = { entry: e, run, pipe };
  const r = run.result;
  const pr = pipe.result;
  const busy = pipe.pending ? `<span class="recommended" id="pipe-busy">pipeline (recommended): computing in the background…</span>` : "";
  const m = $("hdr-metrics");
  if (r) {
    m.innerHTML = `<span title="${METRIC_HELP.E_psi}">E<sub>ψ</sub> raw <b id="m-e-raw">${fmt(r.E_psi_raw_deg, 2)}</b> deg</span>
      <span title="${METRIC_HELP.E_psi}">E<sub>ψ</sub> HDR <b id="m-e-hdr">${fmt(r.E_psi_hdr_deg, 2)}</b> deg</span>
      <span title="${METRIC_HELP.NE_psi}">NE<sub>ψ</sub> raw <b>${fmt(r.NE_psi_raw_deg_per_min, 3)}</b> deg/min</span>
      <span title="${METRIC_HELP.NE_psi}">NE<sub>ψ</sub> HDR <b id="m-ne-hdr">${fmt(r.NE_psi_hdr_deg_per_min, 3)}</b> deg/min</span>
      <span title="${METRIC_HELP.improvement}">improvement <b id="m-improvement">${fmt(r.improvement, 2)}</b>×</span>
      <span title="${METRIC_HELP.eps0}">ε<sub>0</sub> <b>${fmt(r.eps0_dps, 4)}</b> deg/s · ${r.n_processed} samples · ${fmt(r.duration_min, 1)} min</span>` +
      (pr ? `<span class="recommended" title="bank of bias Kalman filters: zero-rate updates at stops, HDR's straight-road heuristic around the drive's dominant rate; its heading averaged with Table-III HDR's and Fusion's offset where they agree with it on the bias (docs/pipeline.md)">pipeline (recommended): E<sub>ψ</sub> <b id="m-e-pipeline">${fmt(pr.E_psi_pipeline_deg, 2)}</b> deg · NE<sub>ψ</sub> <b>${fmt(pr.NE_psi_pipeline_deg_per_min, 3)}</b> deg/min · <b id="m-improvement-pipeline">${fmt(pr.improvement_pipeline, 2)}</b>× · stops ${fmt(pr.stop_s, 0)} s (${pr.still_source})</span>
      <span class="smoothed" title="forward-backward over the whole log: for recorded logs, not available live">smoothed (offline, non-causal): E<sub>ψ</sub> <b id="m-e-smoothed">${fmt(pr.E_psi_pipeline_smoothed_deg, 2)}</b> deg · NE<sub>ψ</sub> <b>${fmt(pr.NE_psi_pipeline_smoothed_deg_per_min, 3)}</b> deg/min</span>` : busy);
  } else if (!run.reference) {
    // A drive with no GPS course: the estimates run, nothing is scored.
    const ps = pipe.summary;
    m.innerHTML = `<span id="m-unscored">Not scored: ${esc(run.error)}. The headings below start at 0 deg.</span>` +
      (ps ? `<span class="recommended">pipeline (recommended): final bias <b id="m-bias-pipeline">${fmt(ps.final_bias_dps, 4)}</b> ± ${fmt(ps.final_bias_sigma_dps, 4)} deg/s (stops from ${ps.still_source})</span>` : busy);
  } else {
    m.textContent = run.error;
  }
  const t = run.trace.time_s;
  const overlaid = overlays(e, v);
  // Unzoomed, the time axis spans the plotted drive and every overlaid one.
  const ends = overlaid.map((o) => o.hdr.trace.time_s).filter((x) => x.length).map((x) => x[x.length - 1]);
  const xr = state.zoom || [t[0], Math.max(t[t.length - 1], ...ends)];
  const series = [];
  if (run.reference) series.push({ name: "reference (GPS)", color: COLORS.ref, x: run.reference.time_s, y: run.reference.heading_deg, width: 3 });
  series.push({ name: "raw", color: COLORS.raw, x: t, y: run.trace.heading_raw_deg, width: 1 });
  series.push({ name: "HDR", color: COLORS.hdr, x: t, y: run.trace.heading_hdr_deg, width: 2 });
  if (pipe.trace) {
    const pt = reduce(pipe.trace.time_s, [pipe.trace.heading_deg, pipe.trace.heading_smoothed_deg], v);
    series.push({ name: "pipeline", color: COLORS.pipe, x: pt.x, y: pt.ys[0], width: 2 });
    series.push({ name: "smoothed (offline)", color: COLORS.smooth, x: pt.x, y: pt.ys[1], width: 1 });
  }
  const pe = pipe.errors && reduce(pipe.errors.time_s, [pipe.errors.pipeline_deg, pipe.errors.smoothed_deg], v);
  const cursor = state.cursor;
  const x_origin = originOf(e);
  chart("c-heading", { title: `${e.name}: heading`, x_label: "time", time_x: true, x_origin, y_label: "heading (deg)", x_range: xr, series, cursor_x: cursor });
  // Without a reference there is no error to draw (not the last drive's chart left standing).
  $("c-error").parentElement.hidden = !run.errors;
  if (run.errors) {
    chart("c-error", {
      title: "heading error (estimate − reference)", x_label: "time", time_x: true, x_origin, y_label: "error (deg)", x_range: xr, cursor_x: cursor,
      series: [
        { name: "zero", color: COLORS.zero, x: [xr[0], xr[1]], y: [0, 0] },
        { name: "raw", color: COLORS.raw, x: run.errors.time_s, y: run.errors.raw_deg },
        { name: "HDR", color: COLORS.hdr, x: run.errors.time_s, y: run.errors.hdr_deg, width: 2 },
        ...(pe ? [{ name: "pipeline", color: COLORS.pipe, x: pe.x, y: pe.ys[0], width: 2 },
          { name: "smoothed (offline)", color: COLORS.smooth, x: pe.x, y: pe.ys[1], width: 1 }] : []),
        ...overlayErrorSeries(overlaid, v),
      ],
    });
  }
  chart("c-rate", {
    title: "corrected rate ω and drift estimate −I (shaded: turn switch on, HDR correcting)", x_label: "time", time_x: true, x_origin, y_label: "rate (deg/s)",
    // Around zero, where drift and the turn switch live (turns go off the chart, as in Figs. 3 and 5).
    x_range: xr, y_range: [-(3 * run_theta() + 0.3), 3 * run_theta() + 0.3], cursor_x: cursor,
    shade: { x: t, mask: run.trace.turn_switch, color: "#2e9d5b", label: "turn switch on" },
    series: [
      { name: "zero", color: COLORS.zero, x: [xr[0], xr[1]], y: [0, 0] },
      { name: "ω corrected", color: COLORS.hdr, x: t, y: run.trace.rate_corrected_dps },
      { name: "−I drift estimate", color: COLORS.raw, x: t, y: run.trace.drift_estimate_dps, width: 2 },
    ],
  });
  renderOverlays(overlaid);
  renderColumns(e, overlaid, xr, cursor, v);
  readout();
}

// ---------- what is drawn: big logs reduced in core to the pixels ----------
/** The charts' window (null: all) and width in device pixels: series are reduced in core to
 * the samples that draw the same (first, last, extremes per pixel column). */
function drawView() {
  const c = $("c-heading");
  return { x_range: state.zoom, columns: Math.max(100, Math.round(c.clientWidth * (window.devicePixelRatio || 1))) };
}

const reduced = new WeakMap(); // first y array -> { key, out }
/** A cached series group (the pipeline's trace, a log column) reduced for the view, once
 * per zoom and width, not on every slider step. */
function reduce(x, ys, v) {
  const key = JSON.stringify(v);
  let c = reduced.get(ys[0]);
  if (!c || c.key !== key || c.x !== x) reduced.set(ys[0], (c = { key, x, out: gd.reduceSeries(x, ys, v) }));
  return c.out;
}

// ---------- other drives overlaid, log columns ----------
const overlayRuns = new WeakMap(); // log -> { key, hdr }
/** The overlaid drives (not the plotted one) with their HDR and pipeline runs, cached per
 * log and settings so a slider reruns only what it changes. */
function overlays(current, v) {
  const key = JSON.stringify([hdrOptions(), v]);
  return state.entries
    .filter((x) => x !== current && !x.error && x.kind === "drive" && state.overlay.has(x.name))
    .map((x, i) => {
      let c = overlayRuns.get(x.log);
      if (!c) overlayRuns.set(x.log, (c = {}));
      if (c.key !== key) Object.assign(c, { key, hdr: gd.runHdr(x.log, hdrOptions(), v) });
      return { entry: x, color: PALETTE[(i + 2) % PALETTE.length], hdr: c.hdr, pipe: pipelineOf(x) };
    });
}

function overlayErrorSeries(overlaid, v) {
  return overlaid.flatMap((o) => {
    const pe = o.pipe.errors && reduce(o.pipe.errors.time_s, [o.pipe.errors.pipeline_deg], v);
    return [
      ...(o.hdr.errors ? [{ name: `${o.entry.name}: HDR`, color: o.color, x: o.hdr.errors.time_s, y: o.hdr.errors.hdr_deg }] : []),
      ...(pe ? [{ name: `${o.entry.name}: pipeline`, color: o.color, x: pe.x, y: pe.ys[0], width: 2 }] : []),
    ];
  });
}

function renderOverlays(overlaid) {
  $("overlay-metrics").innerHTML = overlaid
    .map((o) => `<span class="overlay-row" data-log="${esc(o.entry.name)}"><span class="swatch" style="background:${o.color}"></span><b>${esc(o.entry.name)}</b>: NE<sub>ψ</sub> raw ${fmt(o.hdr.result?.NE_psi_raw_deg_per_min, 3)} · HDR <b>${fmt(o.hdr.result?.NE_psi_hdr_deg_per_min, 3)}</b> · pipeline <b>${fmt(o.pipe.result?.NE_psi_pipeline_deg_per_min, 3)}</b> deg/min</span>`)
    .join("");
}

const columnCache = new WeakMap(); // log -> { key, byName: Map(column -> { x, ys }) }
/** A log column reduced for the view in core (the whole column never crosses), once per
 * zoom and width. */
function column(log, name, v) {
  const key = JSON.stringify(v);
  let c = columnCache.get(log);
  if (!c || c.key !== key) columnCache.set(log, (c = { key, byName: new Map() }));
  if (!c.byName.has(name)) c.byName.set(name, log.reduceColumns([name], v));
  return c.byName.get(name);
}

/** Any column of the log (speed, temperature, the raw gyro, ...) on the shared time axis,
 * chosen with checkboxes; overlaid drives add theirs. */
function renderColumns(e, overlaid, xr, cursor, v) {
  const cols = e.log.columns().filter((c) => c !== "time_s");
  const chosen = (state.columns || [cols.includes("speed_mps") ? "speed_mps" : "gyro_dps"]).filter((c) => cols.includes(c));
  const box = $("col-picker");
  const sig = cols.join(",") + "|" + chosen.join(",");
  if (box.dataset.sig !== sig) {
    box.dataset.sig = sig;
    box.replaceChildren(box.querySelector("legend"), ...cols.map((c) => {
      const label = document.createElement("label");
      const input = Object.assign(document.createElement("input"), { type: "checkbox", value: c, checked: chosen.includes(c) });
      input.addEventListener("change", () => {
        state.columns = [...box.querySelectorAll("input:checked")].map((i) => i.value);
        render();
      });
      label.append(input, c);
      return label;
    }));
  }
  const series = [];
  chosen.forEach((c, k) => {
    const own = column(e.log, c, v);
    series.push({ name: c, color: PALETTE[k % PALETTE.length], x: own.x, y: own.ys[0] });
    overlaid.forEach((o, i) => {
      if (!o.entry.log.columns().includes(c)) return;
      const r = column(o.entry.log, c, v);
      series.push({ name: `${o.entry.name}: ${c}`, color: PALETTE[(k + 3 + i) % PALETTE.length], width: 2, x: r.x, y: r.ys[0] });
    });
  });
  chart("c-columns", { title: `${e.name}: log columns`, x_label: "time", time_x: true, x_origin: originOf(e), y_label: "value (unit in the column's name)", x_range: xr, cursor_x: cursor, series });
}

export function run_theta() {
  return state.params.theta_w_dps ?? gd.tableIII().theta_w_dps;
}

export function readout() {
  const el = $("hdr-readout");
  if (!lastHdr || state.cursor == null) {
    el.textContent = "";
    return;
  }
  const { run, pipe } = lastHdr;
  const t = state.cursor;
  const v = (x, y) => fmt(gd.valueAt(x, y, t), 3);
  const tr = run.trace;
  const ref = run.reference ? v(run.reference.time_s, run.reference.heading_deg) : "–";
  const pt = pipe.trace;
  // The pipeline's heading with its sigma from the bias model (not the gyro's scale or noise).
  const p = pt ? ` · pipeline ${v(pt.time_s, pt.heading_deg)} ± ${v(pt.time_s, pt.heading_sigma_deg)} deg (1σ, bias)` : "";
  el.textContent = `t = ${fmt(t - originOf(lastHdr.entry), 1)} s · reference ${ref} deg · raw ${v(tr.time_s, tr.heading_raw_deg)} deg · HDR ${v(tr.time_s, tr.heading_hdr_deg)} deg${p} · ω ${v(tr.time_s, tr.rate_corrected_dps)} deg/s · −I ${v(tr.time_s, tr.drift_estimate_dps)} deg/s`;
}
