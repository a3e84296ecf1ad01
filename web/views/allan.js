// The Allan view.
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, timeRange } from "../charts.js";
import { showError, render } from "../render.js";

export function renderAllan() {
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
