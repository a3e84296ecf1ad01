// The Track view: dead-reckoned paths on equal axes.
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, timeRange } from "../charts.js";
import { showError, render } from "../render.js";
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
