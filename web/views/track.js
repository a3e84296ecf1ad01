// The Track view: dead-reckoned paths on equal axes.
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, timeRange } from "../charts.js";
import { showError, render } from "../render.js";

export function renderTrack() {
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
