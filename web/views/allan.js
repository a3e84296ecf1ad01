// The Allan view: the deviation with its 68 % band, the minimum with its band, and the
// flat bottom where the minimum could as well lie (core's AllanConfidence).
import * as gd from "../pkg/gyrodrift.js";
import { $, esc, fmt, COLORS } from "../state.js";
import { logFor } from "../controls.js";
import { chart } from "../charts.js";
import { showError } from "../render.js";

export function renderAllan() {
  const e = logFor("allan");
  if (!e) return showError("Load a log with gyro_dps for the Allan view.");
  const r = gd.allan(e.log);
  const c = r.confidence;
  const [a, b] = c.tau_min_range_s;
  $("allan-metrics").innerHTML = `<span>${esc(e.name)}</span><span>ARW <b id="m-arw">${fmt(r.arw_deg_per_sqrt_s, 5)}</b> deg/√s = <b>${fmt(r.arw_deg_per_sqrt_h, 3)}</b> deg/√h</span>
    <span title="methods.md: the plain minimum of the grid / 0.664; the band is one sigma, 1/√(2(N/m − 1)) (IEEE 952 Annex C)">bias instability <b id="m-bi">${fmt(r.bias_instability_dps, 5)}</b> deg/s = <b>${fmt(r.bias_instability_dph, 2)}</b> deg/h at τ = ${fmt(r.tau_at_min_s, 1)} s,
      68 % band <b id="m-bi-band">${fmt(c.bias_instability_low_dps, 5)}–${fmt(c.bias_instability_high_dps, 5)}</b> deg/s</span>
    <span title="the cluster times whose band reaches the minimum's: the minimum could as well lie anywhere here">flat bottom τ <b id="m-bottom">${fmt(a, 1)}–${fmt(b, 1)}</b> s · tightest bound at τ = <b id="m-tight">${fmt(c.tau_tightest_s, 1)}</b> s (${fmt(c.adev_tightest_dps / 0.664, 5)} deg/s)</span>`;
  const imin = r.tau_s.indexOf(r.tau_at_min_s);
  chart("c-allan", {
    title: "overlapping Allan deviation (band: 68 %; shaded: where the minimum could lie)", x_label: "τ (s)", y_label: "σ(τ) (deg/s)", log_x: true, log_y: true,
    // A little room past both ends, so the last point (often the minimum) is not on the frame.
    x_range: [r.tau_s[0] / 1.4, r.tau_s[r.tau_s.length - 1] * 1.4],
    shade: { x: [a, b, b], mask: [1, 1, 0], color: "#e08e0b", label: "flat bottom" },
    series: [
      { name: "68 % band", color: "#9fb8e0", x: r.tau_s, y: c.adev_low_dps },
      { name: "68 % band", color: "#9fb8e0", x: r.tau_s, y: c.adev_high_dps },
      { name: "Allan deviation", color: COLORS.hdr, x: r.tau_s, y: r.adev_dps, width: 2 },
      { name: "−1/2 slope (ARW)", color: COLORS.zero, x: r.tau_s, y: r.arw_line_dps },
      { name: "minimum ± 68 %", color: COLORS.raw, x: [r.tau_s[imin], r.tau_s[imin]], y: [c.min_low_dps, c.min_high_dps], width: 3 },
      { name: "minimum", color: COLORS.raw, x: [r.tau_s[imin]], y: [r.adev_dps[imin]], points: true },
      { name: "tightest bound", color: COLORS.odo, x: [c.tau_tightest_s], y: [c.adev_tightest_dps], points: true },
    ],
  });
}
