// The dashboard's state: settings, the loaded logs, the view, and the URL that mirrors them.
// Defaults come from the wasm package (core's own), never typed in here.
import * as gd from "./pkg/gyrodrift.js";

export const PARAMS = [
  { key: "i_c_dps", label: "i_c", unit: "deg/s", min: 0, max: 0.2, step: 0.0001, help: "HDR's correction step: how fast the drift estimate I moves per second while the road looks straight (Eq. 11). 0 turns HDR off." },
  { key: "tau_s", label: "tau", unit: "s", min: 0, max: 5, step: 0.01, help: "Time constant of the rate low-pass (Eq. 7), undone on the heading by the de-lag step (Eq. 13)." },
  { key: "theta_w_dps", label: "theta_w", unit: "deg/s", min: 0, max: 3, step: 0.001, help: "Turn threshold: below this corrected rate the road is taken as straight and HDR corrects (Eq. 8)." },
  { key: "c1", label: "c1", unit: "", min: 0.005, max: 3, step: 0.005, help: "Shape of the step's decay with the number r of same-sign steps: R = (1 + c1) / (1 + c1 r^c2) (Eq. 10)." },
  { key: "c2", label: "c2", unit: "", min: 0, max: 4, step: 0.01, help: "Exponent of that decay (Eq. 10): larger = the step shrinks faster while the sign stays the same." },
  { key: "bias_s", label: "bias_s", unit: "s", min: 0, max: 120, step: 1, help: "Stationary lead-in whose mean gyro rate is the static bias eps0, removed before everything (Eq. 2). 0 = the log starts moving." },
];
/** What the metrics mean (methods.md, HDR Eqs. 15-16). */
export const METRIC_HELP = {
  E_psi: "E_psi: mean absolute heading error against the reference at its samples, deg (Eq. 15; drift past 180 deg counts in full).",
  NE_psi: "NE_psi: E_psi divided by the log's duration, deg/min (Eq. 16): comparable across drives of different lengths.",
  improvement: "Improvement: E_psi without correction divided by E_psi with it.",
  eps0: "eps0: static bias, the mean gyro rate over the first bias_s seconds, deg/s.",
};
/** The recommended pipeline's settings the page offers (core's defaults until set; the CLI's
 * `--set`, Python's and the npm package's options take every one): what a user's GPS and gyro
 * may ask of it. `group`: the nested settings object the key belongs to. */
export const PIPE_PARAMS = [
  { key: "still_speed_mps", group: "still", label: "still below", unit: "m/s", min: 0.05, max: 3, step: 0.05, help: "A 1 s block stands when every speed in it is below this. Raise it when the GPS speed at a standstill reads noise (0.3-1 m/s) and the pipeline finds few stops." },
  { key: "min_still_s", label: "stop trim", unit: "s", min: 0, max: 5, step: 0.5, help: "A stop's blocks count only this far from both of its ends (braking, GPS speed lag, pulling away into a turn); delays the stop evidence as much." },
  { key: "max_bias_dps", label: "max bias", unit: "deg/s", min: 0.5, max: 20, step: 0.5, help: "The widest bias accepted: a standing whose rate is further than this from the lead-in's bias (0 without a lead-in) is taken as a slow turn; without a lead-in, a steady standing of 10 s is taken whatever its rate." },
  { key: "road_gate_dps", label: "straight gate", unit: "deg/s", min: 0.05, max: 2, step: 0.01, help: "A moving block within this of the last 60 s's dominant rate counts as straight road, HDR's heuristic: wider finds more straights on a noisy gyro, and takes gentle curves for straight." },
  { key: "blend_sigmas", label: "blend guard", unit: "sigma", min: 0, max: 5, step: 0.1, help: "The heading moves with Table-III HDR's and Fusion's offset where the bias they imply is within this many sigmas of the bank's; 0 = the bank's heading alone." },
  { key: "blend_move_dps", label: "bend fallback", unit: "deg/s", min: 0, max: 2, step: 0.05, help: "While the bank's settled bias is further than this from where the last stop left it (long bends taken for straight road), the heading moves with Table-III HDR's; without a lead-in, a move longer than the road window is taken as the gyro's unless it is coming back; 0 = never." },
  { key: "blend_move_quiet_dps", label: "bend fallback, quiet gyro", unit: "deg/s", min: 0, max: 2, step: 0.05, help: "The bend fallback's threshold after a stationary lead-in on a quiet gyro (its standstill noise within the stop's 0.05 deg/s), where the lead-in has shown a steady bias; 0 = the bend fallback's own." },
];
export const GYRO_PARAMS = [{ key: "thres_rate_dps", label: "threshold", unit: "deg/s", min: 0, max: 10, step: 0.05, help: "Gyrodometry's threshold: where gyro and odometry disagree by more than this rate, the gyro's increment is used (Borenstein & Feng)." }];
export const SAMPLES = [
  "sample-logs/train/city-1.csv",
  "sample-logs/train/highway-1.csv",
  "sample-logs/robot/straight.csv",
  "sample-logs/turntable/session.csv",
  "sample-logs/static/static-2h.csv",
];
export const VIEW_KIND = { hdr: "drive", track: "drive", gyrodometry: "robot", calibration: "turntable", allan: null, report: null };
export const COLORS = { ref: "#111111", raw: "#d1495b", hdr: "#1f5fbf", pipe: "#2e9d5b", smooth: "#7fc99b", odo: "#e08e0b", gyro: "#8e44ad", fused: "#1f5fbf", zero: "#999999" };
export const PALETTE = ["#1f5fbf", "#2e9d5b", "#e08e0b", "#d1495b", "#8e44ad", "#00838f", "#6d4c41"];

export const state = {
  entries: [], // { name, log: gd.Log | null, error: string | null, kind, headline }
  selected: -1,
  view: "hdr",
  params: {},
  pipe: {}, // the pipeline settings set on the page (PIPE_PARAMS), by key; the rest are core's
  resample: true,
  gyro: {}, // filled from the package at start
  zoom: null,
  columns: null, // log columns plotted on the time axis (null: the view's default)
  overlay: new Set(), // names of drive logs overlaid on the HDR charts
  yzoom: {}, // per chart: a y range the user zoomed to (a tall drag box, Alt + wheel)
  trackView: null, // the Track view zoomed and panned: { name (of the log), xc, yc (m), mpp (m per canvas px) }
  cursor: null,
  layouts: {},
  hidden: {}, // per chart: the series names the user has hidden
  specs: {}, // per chart: what was last drawn (for the PNG export)
};

export const $ = (id) => document.getElementById(id);
/** Text for HTML: a log's name or an error message comes from a file and stays text. */
export const esc = (v) => String(v).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
export const fmt = (v, d = 3) => (Number.isFinite(v) ? v.toFixed(d) : "–");

export function defaults() {
  const t3 = gd.tableIII();
  return { ...t3, bias_s: null };
}

export function hdrOptions() {
  const o = { resample: state.resample };
  for (const p of PARAMS) if (state.params[p.key] != null) o[p.key] = state.params[p.key];
  return o;
}

/** The recommended pipeline's options everywhere it runs (HDR view, Track, Report, the
 * battery): HDR's static-bias window and the pipeline settings set on the page, plus `extra`. */
export function pipelineOptions(extra = {}) {
  const o = { bias_s: hdrOptions().bias_s ?? null };
  for (const [k, v] of Object.entries({ ...state.pipe, ...extra })) {
    const p = PIPE_PARAMS.find((q) => q.key === k);
    if (p?.group) o[p.group] = { ...o[p.group], [k]: v };
    else o[k] = v;
  }
  return o;
}

/** A pipeline setting's value as shown: the page's, else core's default. */
export function pipeSetting(key) {
  const p = PIPE_PARAMS.find((q) => q.key === key);
  const d = gd.defaults("pipeline");
  return state.pipe[key] ?? (p?.group ? d[p.group][key] : d[key]);
}

/** The selected log if it suits the view, else the first loaded one that does. */
export function logFor(view) {
  const want = VIEW_KIND[view];
  const sel = state.entries[state.selected];
  if (view === "allan") {
    // any gyro log will do, a static one is what the method is for
    if (sel && !sel.error && sel.kind === "static") return sel;
    return state.entries.find((e) => !e.error && e.kind === "static") || (sel && !sel.error ? sel : null);
  }
  if (sel && !sel.error && (!want || sel.kind === want)) return sel;
  return state.entries.find((e) => !e.error && (!want || e.kind === want)) || null;
}

// ---------- URL state ----------
/** Applies a link's state (view, parameters, zooms); returns the log name it asks for. Only
 * valid values are taken, 0 included. */
export function readUrl() {
  const h = new URLSearchParams(location.hash.slice(1));
  if (h.has("view") && h.get("view") in VIEW_KIND) state.view = h.get("view");
  const num = (k) => {
    const text = h.get(k);
    const v = text === null || text.trim() === "" ? NaN : Number(text);
    return Number.isFinite(v) ? v : null;
  };
  for (const p of PARAMS) {
    const v = num(p.key);
    if (v !== null && !gd.checkOptions("hdr", { [p.key]: v })) state.params[p.key] = v;
  }
  for (const p of PIPE_PARAMS) {
    const v = num(`pipe.${p.key}`);
    if (v !== null && !gd.checkOptions("pipeline", pipelineOptions({ [p.key]: v }))) state.pipe[p.key] = v;
  }
  if (h.has("resample")) state.resample = h.get("resample") !== "0";
  const thres = num("thres_rate_dps");
  if (thres !== null && !gd.checkOptions("gyrodometry", { thres_rate_dps: thres })) state.gyro.thres_rate_dps = thres;
  if (h.has("cols")) state.columns = h.get("cols").split(",").filter(Boolean);
  state.overlay = new Set(h.getAll("overlay"));
  const z = (h.get("zoom") || "").split(",").map(Number);
  state.zoom = z.length === 2 && z.every(Number.isFinite) && z[0] < z[1] ? z : null;
  // The Track view's zoom and pan: centre (m) and metres per canvas pixel, on the log that
  // view shows first (name null until then: web/views/track.js).
  const t = (h.get("track") || "").split(",").map(Number);
  state.trackView = t.length === 3 && t.every(Number.isFinite) && t[2] > 0 ? { name: null, xc: t[0], yc: t[1], mpp: t[2] } : null;
  return h.get("log");
}

let urlTimer = 0;
export function writeUrl() {
  // Debounced: browsers throttle history updates, and a slider fires many per second.
  clearTimeout(urlTimer);
  urlTimer = setTimeout(writeUrlNow, 150);
}

/** The hash the current state makes. */
export function urlHash() {
  const h = new URLSearchParams();
  h.set("view", state.view);
  const e = state.entries[state.selected];
  if (e && !e.error) h.set("log", e.name);
  for (const p of PARAMS) if (state.params[p.key] != null) h.set(p.key, String(state.params[p.key]));
  for (const p of PIPE_PARAMS) if (state.pipe[p.key] != null) h.set(`pipe.${p.key}`, String(state.pipe[p.key]));
  h.set("resample", state.resample ? "1" : "0");
  h.set("thres_rate_dps", String(state.gyro.thres_rate_dps));
  if (state.zoom) h.set("zoom", state.zoom.map((v) => +v.toFixed(3)).join(","));
  // The Track view's zoom, while it is on the log that view shows (the selected one, or the
  // first drive when the selected log is not one).
  const tv = state.trackView;
  if (tv && tv.name === logFor("track")?.name) h.set("track", [tv.xc, tv.yc, tv.mpp].map((v) => +v.toPrecision(6)).join(","));
  if (state.columns) h.set("cols", state.columns.join(","));
  for (const name of state.overlay) h.append("overlay", name);
  return "#" + h.toString();
}

/** Writes the URL: a new history entry when the view or the log changed (Back steps back),
 * else the current entry is replaced (sliders, zoom). */
export function writeUrlNow() {
  clearTimeout(urlTimer);
  const hash = urlHash();
  if (hash === location.hash) return;
  const was = new URLSearchParams(location.hash.slice(1));
  const now = new URLSearchParams(hash.slice(1));
  const step = was.get("view") !== now.get("view") || was.get("log") !== now.get("log");
  if (step && was.has("view")) history.pushState(null, "", hash);
  else history.replaceState(null, "", hash);
}
