// The Track view: dead-reckoned paths on equal axes.
import * as gd from "../pkg/gyrodrift.js";
import { $, state, hdrOptions, pipelineOptions, COLORS } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart } from "../charts.js";
import { showError, render } from "../render.js";
import { background, perLog } from "../background.js";

/** The recommended pipeline's paths: they depend on the log, bias_s and the pipeline
 * settings only, so HDR's sliders reuse them; a large log's come from the worker. */
function pipelineTrackOf(e) {
  const options = pipelineOptions();
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
  // Equal axes (the plot module fits them to the plot area): the whole track, or where the
  // user zoomed and panned on this log (its centre and metres per canvas pixel).
  if (state.trackView && state.trackView.name === null) state.trackView.name = e.name; // from a link
  const v = state.trackView?.name === e.name ? state.trackView : null;
  chart("c-track", {
    title: `${e.name}: dead-reckoned track`, x_label: "east (m)", y_label: "north (m)",
    equal_axes: true, view: v ? [v.xc, v.yc, v.mpp] : null,
    series: series.map((s) => ({ ...s, points: false, path: true })),
  });
}
