// The Gyrodometry view.
import * as gd from "../pkg/gyrodrift.js";
import { $, esc, fmt, state, hdrOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, originOf, timeRange } from "../charts.js";
import { showError, render } from "../render.js";

export function renderGyro() {
  const e = logFor("gyrodometry");
  if (!e) return showError("Load a robot log (gyro_dps, odo_left_m, odo_right_m, # wheelbase_m) for the Gyrodometry view.");
  const run = gd.runGyrodometry(e.log, state.gyro);
  const r = run.result;
  $("gyro-metrics").innerHTML = r
    ? `<span>E<sub>ψ</sub> odometry <b>${fmt(r.E_psi_odo_deg, 3)}</b> deg</span><span>gyro <b>${fmt(r.E_psi_gyro_deg, 3)}</b> deg</span>
       <span>Gyrodometry <b id="m-gyrodometry">${fmt(r.E_psi_gyrodometry_deg, 3)}</b> deg</span>
       <span>final errors <b>${fmt(r.final_err_odo_deg, 2)}</b> / <b>${fmt(r.final_err_gyro_deg, 2)}</b> / <b>${fmt(r.final_err_gyrodometry_deg, 2)}</b> deg</span>
       <span>gyro used in <b>${r.n_gyro_intervals}</b> intervals</span>`
    : esc(run.error);
  const t = run.trace.time_s;
  const xr = timeRange(t);
  const series = [];
  if (e.log.columns().includes("ref_heading_deg")) series.push({ name: "reference", color: COLORS.ref, x: e.log.column("time_s"), y: e.log.column("ref_heading_deg") });
  series.push({ name: "odometry", color: COLORS.odo, x: t, y: run.trace.heading_odo_deg });
  series.push({ name: "gyro", color: COLORS.gyro, x: t, y: run.trace.heading_gyro_deg });
  series.push({ name: "Gyrodometry", color: COLORS.fused, x: t, y: run.trace.heading_gyrodometry_deg, width: 2 });
  chart("c-gyrodometry", {
    title: `${e.name}: heading (shaded: gyro increment used)`, x_label: "time", time_x: true, x_origin: originOf(e), y_label: "heading (deg)", x_range: xr,
    cursor_x: state.cursor, series, shade: { x: t, mask: run.trace.used_gyro, color: "#8e44ad", label: "gyro used" },
  });
}
