// The charts' input. The time charts: the tooltip at the cursor, zoom and pan by mouse
// (rubber band, Shift+drag, wheel), keys and touch (pan, pinch), every one sharing
// state.zoom. The Track view: zoom and pan on equal axes (state.trackView).
import * as plot from "./pkg/plot/gyrodrift_plot.js";
import * as gd from "./pkg/gyrodrift.js";
import { $, esc, state } from "./state.js";
import { scheduleRender } from "./render.js";
import { logFor } from "./controls.js";

/** The tooltip at the cursor: the time and every shown series' value there (core's
 * valueAt, linear between samples), the shaded state, in the chart's colours. */
function tooltip(id, c, ev) {
  const spec = state.specs[id], L = state.layouts[id];
  let tip = c.parentElement.querySelector(".tip");
  if (!tip) {
    tip = document.createElement("div");
    tip.className = "tip";
    tip.setAttribute("role", "tooltip");
    c.parentElement.append(tip);
  }
  if (!spec || !L || state.cursor == null) return (tip.hidden = true);
  const t = state.cursor;
  const per = L.x_unit_s;
  const unit = plot.labelUnit(spec.y_label || "");
  const rows = [];
  const seen = new Set();
  for (const s of spec.series) {
    if (!s.name || s.name === "zero" || seen.has(s.name)) continue;
    seen.add(s.name);
    const v = gd.valueAt(s.x, s.y, t);
    rows.push(`<tr><td><span class="swatch" style="background:${esc(s.color)}"></span>${esc(s.name)}</td><td data-series="${esc(s.name)}">${Number.isFinite(v) ? v.toFixed(Math.abs(v) >= 100 ? 1 : 3) : "–"}</td><td>${unit}</td></tr>`);
  }
  if (spec.shade?.label) {
    const on = gd.valueAt(spec.shade.x, spec.shade.mask, t) > 0.5;
    rows.push(`<tr><td colspan="3">${esc(spec.shade.label)}: <b>${on ? "yes" : "no"}</b></td></tr>`);
  }
  tip.innerHTML = `<b>t = ${((t - L.x_origin) / per).toFixed(per === 1 ? 1 : 2)} ${L.x_unit || "s"}</b><table>${rows.join("")}</table>`; // names escaped above
  tip.hidden = false;
  // Beside the cursor, flipped to its left past the middle so it stays inside the chart.
  const x = ev.offsetX, w = c.clientWidth;
  tip.style.top = `${c.offsetTop + Math.max(0, ev.offsetY - 10)}px`;
  tip.style.left = x < w / 2 ? `${c.offsetLeft + x + 16}px` : "";
  tip.style.right = x < w / 2 ? "" : `${w - x + 16}px`;
}

/** The rubber band while dragging: x only for a flat drag (x zoom, shared by the time
 * charts), a box when the drag is also tall (x and this chart's y). */
function band(c, box) {
  let el = c.parentElement.querySelector(".band");
  if (!el) {
    el = document.createElement("div");
    el.className = "band";
    c.parentElement.append(el);
  }
  el.hidden = !box;
  if (box) Object.assign(el.style, { left: `${c.offsetLeft + box.x0}px`, width: `${box.x1 - box.x0}px`, top: `${c.offsetTop + box.y0}px`, height: `${box.y1 - box.y0}px` });
}
const TALL_PX = 16;

/** Zoom and pan on time chart `id` (drag a band, Shift + drag to pan, wheel, keys); every time chart shares state.zoom. */
export function attachTimeInteraction(id) {
  const c = $(id);
  let drag = null;
  const scale = () => c.width / c.clientWidth;
  const toX = (ev) => {
    const L = state.layouts[id];
    if (!L) return null;
    const px = ev.offsetX * scale();
    return L.x_min + ((px - L.left) / (L.right - L.left)) * (L.x_max - L.x_min);
  };
  const toY = (offsetY) => {
    const L = state.layouts[id];
    return L.y_max - ((offsetY * scale() - L.top) / (L.bottom - L.top)) * (L.y_max - L.y_min);
  };
  /** The band in CSS pixels for a drag from d to the event. */
  const boxOf = (d, ev) => {
    const L = state.layouts[id], k = scale();
    const [x0, x1] = [Math.min(d.px, ev.offsetX), Math.max(d.px, ev.offsetX)];
    const tall = Math.abs(ev.offsetY - d.py) >= TALL_PX;
    const [y0, y1] = tall ? [Math.min(d.py, ev.offsetY), Math.max(d.py, ev.offsetY)] : [L.top / k, L.bottom / k];
    return { x0, x1, y0, y1, tall };
  };
  c.addEventListener("mousedown", (ev) => {
    drag = { x: toX(ev), px: ev.offsetX, py: ev.offsetY, shift: ev.shiftKey, range: state.layouts[id] && [state.layouts[id].x_min, state.layouts[id].x_max] };
  });
  c.addEventListener("mousemove", (ev) => {
    const x = toX(ev);
    if (x == null) return;
    if (drag && drag.shift && drag.range) {
      const d = drag.x - x;
      state.zoom = [drag.range[0] + d, drag.range[1] + d];
    } else if (drag && Math.abs(ev.offsetX - drag.px) > 2) band(c, boxOf(drag, ev));
    state.cursor = x;
    tooltip(id, c, ev);
    scheduleRender();
  });
  window.addEventListener("mouseup", (ev) => {
    if (!drag) return;
    const d = drag;
    drag = null;
    band(c, null);
    if (d.shift || ev.target !== c) return;
    const x = toX(ev);
    if (x != null && d.range && Math.abs(x - d.x) > (d.range[1] - d.range[0]) / 200) {
      const box = boxOf(d, ev);
      state.zoom = [Math.min(x, d.x), Math.max(x, d.x)];
      if (box.tall) state.yzoom[id] = [toY(box.y1), toY(box.y0)];
      scheduleRender();
    }
  });
  attachWheel(c, id, toX, toY);
  attachKeys(c, id);
  attachTouch(c, id, scale);
  c.addEventListener("mouseleave", () => {
    state.cursor = null;
    tooltip(id, c, null);
    scheduleRender();
  });
}

/** The touch pointers on canvas `c`, each at its [offsetX, offsetY]: `start(at)` when a finger
 * goes down or up (a gesture goes on from where the fingers are), `move(at)` as they move. */
function touches(c, start, move) {
  const at = new Map();
  c.addEventListener("pointerdown", (ev) => {
    if (ev.pointerType !== "touch") return;
    at.set(ev.pointerId, [ev.offsetX, ev.offsetY]);
    start(at);
  });
  c.addEventListener("pointermove", (ev) => {
    if (ev.pointerType !== "touch" || !at.has(ev.pointerId)) return;
    at.set(ev.pointerId, [ev.offsetX, ev.offsetY]);
    move(at);
  });
  const lift = (ev) => {
    if (at.delete(ev.pointerId)) start(at);
  };
  c.addEventListener("pointerup", lift);
  c.addEventListener("pointercancel", lift);
}

/** Touch: one finger dragged sideways pans time, two fingers pinch it (the page still scrolls
 * up and down: touch-action pan-y); a tap shows the values there, as the mouse's hover does
 * (the browser's compatibility mouse events). */
function attachTouch(c, id, scale) {
  c.style.touchAction = "pan-y";
  let start = null; // the time range, the layout and the fingers' offsetX when the gesture (re)started
  touches(c, (at) => {
    const L = state.layouts[id];
    start = L && at.size ? { range: state.zoom || [L.x_min, L.x_max], L, from: new Map([...at].map(([k, p]) => [k, p[0]])) } : null;
  }, (at) => {
    if (!start) return;
    const { range: [r0, r1], L, from } = start;
    // Fraction of the plot's width at a CSS x, and the time it showed when the gesture began.
    const u = (px) => (px * scale() - L.left) / (L.right - L.left);
    const t = (px) => r0 + u(px) * (r1 - r0);
    const x = (k) => at.get(k)[0];
    const ids = [...at.keys()].filter((k) => from.has(k)).slice(0, 2);
    if (ids.length === 1) {
      const [k] = ids;
      const n0 = t(from.get(k)) - u(x(k)) * (r1 - r0);
      state.zoom = [n0, n0 + (r1 - r0)];
    } else if (ids.length === 2) {
      // The two times under the fingers stay under them.
      const [a, b] = ids;
      const du = u(x(b)) - u(x(a));
      if (Math.abs(du) < 0.02) return;
      const span = (t(from.get(b)) - t(from.get(a))) / du;
      if (!(span > 0)) return;
      const n0 = t(from.get(a)) - u(x(a)) * span;
      state.zoom = [n0, n0 + span];
    } else return;
    scheduleRender();
  });
}

/** Wheel: zoom time around the cursor; Alt + wheel: this chart's y. */
function attachWheel(c, id, toX, toY) {
  c.addEventListener("wheel", (ev) => {
    const L = state.layouts[id];
    if (!L) return;
    ev.preventDefault();
    const k = ev.deltaY > 0 ? 1.25 : 0.8;
    if (ev.altKey) {
      // Alt + wheel: this chart's y around the cursor.
      const y = toY(ev.offsetY);
      state.yzoom[id] = [y - (y - L.y_min) * k, y + (L.y_max - y) * k];
    } else {
      const x = toX(ev);
      state.zoom = [x - (x - L.x_min) * k, x + (L.x_max - x) * k];
    }
    scheduleRender();
  }, { passive: false });
}

/** Double click or 0 resets; + / - zoom, arrow keys pan (the canvas is focusable). */
function attachKeys(c, id) {
  c.addEventListener("dblclick", () => { state.zoom = null; delete state.yzoom[id]; scheduleRender(); });
  c.tabIndex = 0;
  c.addEventListener("keydown", (ev) => {
    const L = state.layouts[id];
    if (!L) return;
    const [a, b] = [L.x_min, L.x_max];
    const w = b - a, mid = (a + b) / 2;
    const zoom = { "+": 0.8, "=": 0.8, "-": 1.25 }[ev.key];
    if (zoom) state.zoom = [mid - (w * zoom) / 2, mid + (w * zoom) / 2];
    else if (ev.key === "ArrowLeft") state.zoom = [a - w * 0.1, b - w * 0.1];
    else if (ev.key === "ArrowRight") state.zoom = [a + w * 0.1, b + w * 0.1];
    else if (ev.key === "0") { state.zoom = null; delete state.yzoom[id]; }
    else return;
    ev.preventDefault();
    scheduleRender();
  });
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
  const spread = (a, b) => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, Math.hypot(a[0] - b[0], a[1] - b[1])];
  let pinch = null;
  touches(c, (at) => {
    pinch = at.size === 2 ? { v: view(), s: spread(...at.values()) } : null;
  }, (at) => {
    if (!pinch?.v || at.size !== 2) return;
    const s = spread(...at.values());
    if (s[2] < 10 || pinch.s[2] < 10) return;
    zoomAbout(pinch.v, pinch.s[0], pinch.s[1], pinch.s[2] / s[2], s[0] - pinch.s[0], s[1] - pinch.s[1]);
  });
}
