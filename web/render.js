// Rendering: one animation frame per burst of input, the active view, its errors.
import { $, state, writeUrl } from "./state.js";
import { renderList, logFor, said } from "./controls.js";
import { canRemap, remap } from "./remap.js";
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

/** A check error in the plotted log, said above the view with its fix: the CLI refuses such
 * a log (its figures would be absurd, e.g. a clockwise gyro's), the page shows them
 * flagged. */
function showCheck(e) {
  const errors = e?.errors ?? [];
  const box = $("view-check");
  box.hidden = !errors.length;
  box.replaceChildren();
  if (!errors.length) return;
  const head = document.createElement("b");
  head.textContent = `⚠ ${e.name}: check found an error, so these figures are not to be trusted (the CLI refuses the log until it is fixed)`;
  box.append(head, ...said(errors).map((line) => Object.assign(document.createElement("p"), { textContent: line })));
  if (canRemap(e)) {
    const fix = Object.assign(document.createElement("button"), { type: "button", id: "check-remap", textContent: "Open it with the fix in the column mapper…" });
    fix.addEventListener("click", () => remap(e));
    box.append(fix);
  }
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
  showCheck(state.view === "report" ? null : logFor(state.view));
  const t0 = performance.now();
  try {
    ({ hdr: renderHdr, track: renderTrack, gyrodometry: renderGyro, calibration: renderCal, allan: renderAllan, report: renderReport })[state.view]();
  } catch (e) {
    showError(e.message);
  }
  document.body.dataset.renderMs = (performance.now() - t0).toFixed(2);
  document.body.dataset.ready = "1";
}
