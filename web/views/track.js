// The Track view: dead-reckoned paths on equal axes.
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, timeRange } from "../charts.js";
import { showError, render, scheduleRender } from "../render.js";
import { background, perLog } from "../background.js";

/** The recommended pipeline's paths: they depend on the log and bias_s only, so HDR's
 * sliders reuse them; a large log's come from the worker. */
function pipelineTrackOf(e) {
  const options = { bias_s: hdrOptions().bias_s ?? null };
  return perLog(e, "pipelineTrack", options, () => gd.pipelineTrack(e.log, options));
}

export function renderTrack() {
  const e = logFor("track");
  if (!e) return showError("Load a drive log with speed_mps for the Track view.");
  // A large log's paths come from the worker (the page never pauses); small ones are quick here.
  const bg = background(e, "track", hdrOptions());
  const pt = pipelineTrackOf(e);
  $("track-busy").textContent = bg?.pending ? (bg.stale ? "Updating the track in the background…" : "Computing the track of this large log in the background…")
    : pt.pending ? "Computing the pipeline's track in the background…" : pt.error ? `pipeline: ${pt.error}` : "";
  if (bg?.error) return showError(bg.error);
  const tr = bg ? bg.data : gd.track(e.log, hdrOptions());
  if (!tr) return;
  const series = [];
  if (tr.reference) series.push({ name: "reference heading", color: COLORS.ref, x: tr.reference.x_m, y: tr.reference.y_m, points: false, width: 2 });
  series.push({ name: "raw", color: COLORS.raw, x: tr.raw.x_m, y: tr.raw.y_m, points: false });
  series.push({ name: "HDR", color: COLORS.hdr, x: tr.hdr.x_m, y: tr.hdr.y_m, points: false, width: 2 });
  const p = pt.data;
  if (p) {
    series.push({ name: "pipeline (recommended)", color: COLORS.pipe, x: p.pipeline.x_m, y: p.pipeline.y_m, points: false, width: 2 });
    series.push({ name: "smoothed (offline)", color: COLORS.smooth, x: p.smoothed.x_m, y: p.smoothed.y_m, points: false });
  }
  // Equal axes: the same metres per pixel across and up. The plot area inside the canvas
  // (margins for labels) is not square, so its size is read from the last drawing.
  const ext = (key) => {
    let l = Infinity, h = -Infinity;
    for (const s of series) for (const v of s[key]) if (Number.isFinite(v)) { l = Math.min(l, v); h = Math.max(h, v); }
    return Number.isFinite(l) ? [l, h] : [0, 1];
  };
  const [x0, x1] = ext("x"), [y0, y1] = ext("y");
  // The whole track, or where the user zoomed and panned on this log (one scale across and
  // up: metres per canvas pixel, and the centre).
  const zoomed = state.trackView?.name === e.name ? state.trackView : null;
  const ranges = (w, h) => {
    const mpp = zoomed ? zoomed.mpp : Math.max((x1 - x0) / w, (y1 - y0) / h, 1e-9) * 1.05;
    const xc = zoomed ? zoomed.xc : (x0 + x1) / 2, yc = zoomed ? zoomed.yc : (y0 + y1) / 2;
    return { x_range: [xc - (mpp * w) / 2, xc + (mpp * w) / 2], y_range: [yc - (mpp * h) / 2, yc + (mpp * h) / 2] };
  };
  const spec = (w, h) => ({
    title: `${e.name}: dead-reckoned track`, x_label: "east (m)", y_label: "north (m)",
    ...ranges(w, h),
    series: series.map((s) => ({ ...s, points: false, path: true })),
  });
  const area = () => {
    const L = state.layouts["c-track"];
    return L ? [L.right - L.left, L.bottom - L.top] : [1, 1];
  };
  const [w, h] = area();
  chart("c-track", spec(w, h));
  const [w2, h2] = area();
  if (w2 !== w || h2 !== h) chart("c-track", spec(w2, h2)); // first drawing, or the canvas was resized
}

/** Zoom and pan on the track, equal axes throughout: the wheel zooms about the cursor, a drag
 * pans, a double click or tap resets; on a touch screen two fingers pinch and pan (one
 * finger still scrolls the page). */
export function attachTrackInteraction() {
  const c = $("c-track");
  c.style.touchAction = "pan-x pan-y";
  const k = () => c.width / c.clientWidth;
  // The view of the last drawing: its centre and metres per canvas pixel.
  const view = () => {
    const L = state.layouts["c-track"];
    if (!L) return null;
    return { L, xc: (L.x_min + L.x_max) / 2, yc: (L.y_min + L.y_max) / 2, mpp: (L.x_max - L.x_min) / (L.right - L.left) };
  };
  // The metres under a CSS pixel of the canvas, in view v.
  const metres = (v, px, py) => [v.L.x_min + (px * k() - v.L.left) * v.mpp, v.L.y_max - (py * k() - v.L.top) * v.mpp];
  const set = (xc, yc, mpp) => {
    const e = logFor("track");
    if (!e || !(mpp > 0)) return;
    state.trackView = { name: e.name, xc, yc, mpp };
    scheduleRender();
  };
  /** Zoom by f about CSS pixel (px, py) of view v, which also moves by (dx, dy) CSS pixels. */
  const zoomAbout = (v, px, py, f, dx = 0, dy = 0) => {
    const [x, y] = metres(v, px, py);
    set(x + (v.xc - x) * f - dx * k() * v.mpp * f, y + (v.yc - y) * f + dy * k() * v.mpp * f, v.mpp * f);
  };
  c.addEventListener("wheel", (ev) => {
    const v = view();
    if (!v) return;
    ev.preventDefault();
    zoomAbout(v, ev.offsetX, ev.offsetY, ev.deltaY > 0 ? 1.25 : 0.8);
  }, { passive: false });
  let drag = null;
  c.addEventListener("mousedown", (ev) => { drag = { v: view(), px: ev.offsetX, py: ev.offsetY }; });
  c.addEventListener("mousemove", (ev) => {
    if (!drag?.v) return;
    const { v } = drag;
    set(v.xc - (ev.offsetX - drag.px) * k() * v.mpp, v.yc + (ev.offsetY - drag.py) * k() * v.mpp, v.mpp);
  });
  window.addEventListener("mouseup", () => { drag = null; });
  c.addEventListener("dblclick", () => { state.trackView = null; scheduleRender(); });
  // Two fingers: the metres under their midpoint stay under it, the scale follows their spread.
  const at = new Map();
  let pinch = null;
  const begin = () => {
    const [a, b] = [...at.values()];
    pinch = at.size === 2 ? { v: view(), mid: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], d: Math.hypot(a[0] - b[0], a[1] - b[1]) } : null;
  };
  c.addEventListener("pointerdown", (ev) => {
    if (ev.pointerType !== "touch") return;
    at.set(ev.pointerId, [ev.offsetX, ev.offsetY]);
    begin();
  });
  c.addEventListener("pointermove", (ev) => {
    if (ev.pointerType !== "touch" || !at.has(ev.pointerId)) return;
    at.set(ev.pointerId, [ev.offsetX, ev.offsetY]);
    if (!pinch?.v || at.size !== 2) return;
    const [a, b] = [...at.values()];
    const d = Math.hypot(a[0] - b[0], a[1] - b[1]);
    if (d < 10 || pinch.d < 10) return;
    const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
    zoomAbout(pinch.v, pinch.mid[0], pinch.mid[1], pinch.d / d, mid[0] - pinch.mid[0], mid[1] - pinch.mid[1]);
  });
  const lift = (ev) => {
    if (at.delete(ev.pointerId)) begin();
  };
  c.addEventListener("pointerup", lift);
  c.addEventListener("pointercancel", lift);
}
