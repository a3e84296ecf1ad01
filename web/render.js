// Rendering: one animation frame per burst of input, the active view, its errors.
import { $, state, writeUrl } from "./state.js";
import { renderList } from "./controls.js";
import { renderHdr } from "./views/hdr.js";
import { renderTrack } from "./views/track.js";
import { renderGyro } from "./views/gyrodometry.js";
import { renderCal } from "./views/calibration.js";
import { renderAllan } from "./views/allan.js";
import { renderReport } from "./views/report.js";

let pending = false;
let lastListKey = "";
export function scheduleRender() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    render();
  });
}

export function showError(msg) {
  const p = $("view-error");
  p.hidden = !msg;
  p.textContent = msg || "";
}

export function render() {
  for (const b of document.querySelectorAll("#tabs button")) {
    const on = b.dataset.view === state.view;
    b.setAttribute("aria-selected", String(on));
    b.tabIndex = on ? 0 : -1;
  }
  for (const s of document.querySelectorAll(".view")) s.hidden = s.id !== `view-${state.view}`;
  const listKey = [state.view, state.selected, ...state.entries.map((e) => e.name), ...state.overlay].join("|");
  if (listKey !== lastListKey) {
    renderList();
    lastListKey = listKey;
  }
  writeUrl();
  showError("");
  const t0 = performance.now();
  try {
    ({ hdr: renderHdr, track: renderTrack, gyrodometry: renderGyro, calibration: renderCal, allan: renderAllan, report: renderReport })[state.view]();
  } catch (e) {
    showError(e.message);
  }
  document.body.dataset.renderMs = (performance.now() - t0).toFixed(2);
  document.body.dataset.ready = "1";
}
