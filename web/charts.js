// Charts: canvases drawn by the wasm package, their legends and exports (the time charts'
// zoom, pan and cursor: chart-input.js).
import * as plot from "./pkg/plot/gyrodrift_plot.js";
import { $, state } from "./state.js";
import { scheduleRender } from "./render.js";

export function sizeCanvas(c) {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(100, Math.round(c.clientWidth * dpr));
  const h = Math.max(80, Math.round(c.clientHeight * dpr));
  if (c.width !== w || c.height !== h) Object.assign(c, { width: w, height: h });
  return dpr;
}

/** The chart's legend as buttons above it, outside the data; a click hides or shows the
 * series (all of that name: a band's two edges are one key). Guide lines ("zero") are not listed. */
function legend(id, spec, hidden) {
  const c = $(id);
  let box = document.getElementById(`legend-${id}`);
  if (!box) {
    box = document.createElement("div");
    box.id = `legend-${id}`;
    box.className = "legend";
    box.setAttribute("role", "group");
    box.setAttribute("aria-label", "Series (click to hide or show)");
    c.before(box);
  }
  const keys = [...(spec.shade?.label ? [{ name: spec.shade.label, color: spec.shade.color, shade: true }] : []), ...(spec.series || [])].filter((s, i, all) => s.name && s.name !== "zero" && all.findIndex((o) => o.name === s.name) === i);
  const sig = keys.map((k) => `${k.name}:${hidden.has(k.name)}`).join("|");
  if (box.dataset.sig === sig) return;
  box.dataset.sig = sig;
  box.replaceChildren(
    ...keys.map((k) => {
      const b = document.createElement("button");
      b.type = "button";
      b.className = "key";
      b.setAttribute("aria-pressed", String(!hidden.has(k.name)));
      b.innerHTML = `<span class="swatch${k.shade ? " shade" : ""}"></span>`;
      b.querySelector(".swatch").style.background = k.color;
      b.append(k.name);
      b.addEventListener("click", () => {
        if (hidden.has(k.name)) hidden.delete(k.name);
        else hidden.add(k.name);
        scheduleRender();
      });
      return b;
    }),
  );
}

export function chart(id, spec) {
  const c = $(id);
  const dpr = sizeCanvas(c);
  const hidden = (state.hidden[id] ||= new Set());
  legend(id, spec, hidden);
  const shown = { ...spec, series: (spec.series || []).filter((s) => !hidden.has(s.name)), legend: false, dpr };
  if (state.yzoom[id]) shown.y_range = state.yzoom[id];
  if (spec.shade && hidden.has(spec.shade.label)) delete shown.shade;
  state.specs[id] = shown;
  const L = (state.layouts[id] = plot.drawChart(c, shown));
  c.dataset.drawn = String(Number(c.dataset.drawn || 0) + 1);
  // A text alternative for screen readers: what the chart shows and over which ranges.
  const r = (v) => (Math.abs(v) >= 100 ? v.toFixed(0) : v.toPrecision(3));
  const names = (spec.series || []).map((s) => s.name).filter((n) => n && n !== "zero");
  const per = L.x_unit_s;
  const xl = L.x_unit ? `${spec.x_label} (${L.x_unit})` : spec.x_label || "x";
  c.setAttribute("aria-label", `${spec.title}: ${names.join(", ")}; ${xl} ${r((L.x_min - L.x_origin) / per)} to ${r((L.x_max - L.x_origin) / per)}, ${spec.y_label || "y"} ${r(L.y_min)} to ${r(L.y_max)}`);
}

/** Where a log's time axis counts from: its first row's time, read once per log (0 for
 * most logs; an epoch-stamped log's charts read time since its start, not since 1970). */
export function originOf(e) {
  return (e.t0 ??= e.log?.column("time_s")[0] ?? 0);
}

export function timeRange(t) {
  return state.zoom || [t[0], t[t.length - 1]];
}

// ---------- exports ----------
/** Every shown series of a chart as CSV, as plotted (core's export through the plot module). */
export function csvOf(id) {
  return state.specs[id] ? plot.chartCsv(state.specs[id]) : "";
}

/** Every shown series of several time charts in one CSV on their shared time: columns named
 * "<chart>: <series> (<unit>)". */
export function timeChartsCsv(ids) {
  const series = [];
  let shade = null;
  for (const id of ids) {
    const spec = state.specs[id];
    if (!spec) continue;
    const unit = plot.labelUnit(spec.y_label || "");
    const chartName = id.replace(/^c-/, "");
    for (const s of spec.series) if (s.name && s.name !== "zero") series.push({ ...s, name: `${chartName}: ${s.name}${unit ? ` (${unit})` : ""}` });
    if (spec.shade && !shade) shade = { ...spec.shade, label: `${chartName}: ${spec.shade.label}` };
  }
  return plot.chartCsv({ x_label: "time", time_x: true, y_label: "", series, shade });
}

/** The chart as a PNG data URL, its legend drawn in (the page's legend is outside it). */
export function pngOf(id) {
  const c = $(id);
  if (state.specs[id]) plot.drawChart(c, { ...state.specs[id], legend: true });
  const url = c.toDataURL("image/png");
  if (state.specs[id]) plot.drawChart(c, state.specs[id]);
  return url;
}

export function download(name, data, type) {
  const a = document.createElement("a");
  a.href = typeof data === "string" && data.startsWith("data:") ? data : URL.createObjectURL(new Blob([data], { type }));
  a.download = name;
  a.click();
}
