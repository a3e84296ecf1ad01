// The Calibration view: error against rate before and after compensation.
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, timeRange } from "../charts.js";
import { showError, render } from "../render.js";

export function renderCal() {
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
