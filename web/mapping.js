// The mapping panel: raw files no preset fits. The user says which column is the time, the
// gyro (one axis, or three projected on gravity), the reference heading (a column or
// positions) and the speed; a live preview imports with that recipe in the worker and
// plots the integrated gyro against the reference. The recipe can be saved and re-used.
import * as gd from "./pkg/gyrodrift.js";
import * as plot from "./pkg/plot/gyrodrift_plot.js";
import { $, COLORS } from "./state.js";
import { saveRecipe } from "./loading.js";
import { sizeCanvas } from "./charts.js";

const TIME_UNITS = ["s", "ms", "us", "ns", "iso8601", "time_of_day"];
const TIME_LABELS = { iso8601: "ISO 8601", time_of_day: "time of day (hh:mm:ss)" };
const RATE_UNITS = ["deg/s", "rad/s", "mrad/s", "deg/h"];
const SPEED_UNITS = ["m/s", "km/h", "mph", "kn"];

/**
 * Core's guesses (`columnGuesses`: its `files` in name order) put in the panel's terms: a
 * guessed column as the panel's value ("file index:column", "" for none), and the reading
 * of the column a panel value names.
 */
function inPanel(g, sniffed) {
  const panelIndex = (c) => sniffed.findIndex((s) => s.name === g?.files[c.file]?.name);
  const value = (c) => (c && panelIndex(c) >= 0 ? `${panelIndex(c)}:${c.column}` : "");
  const reading = (v) => {
    const k = v.indexOf(":");
    const file = k < 0 ? undefined : g?.files.find((f) => f.name === sniffed[Number(v.slice(0, k))]?.name);
    return file?.columns.find((c) => c.name === v.slice(k + 1));
  };
  return { value, reading, file: (i) => g?.files.find((f) => f.name === sniffed[i].name) };
}

/** `unit` follows the column chosen in `col`: core's reading of it as `kind`, else `fallback`. */
function follow(reading, col, unit, kind, fallback, prefix = "") {
  const set = () => (unit.value = reading(prefix + col.value)?.[kind] ?? fallback);
  set();
  col.addEventListener("change", set);
}

/**
 * The GPS log core's draft takes the reference from, when it is one the panel's columns
 * cannot say (a GPX track, an NMEA log): its file, its table (as "track") and the draft's
 * heading, positions and speed on it; else null.
 */
function draftTrack(draft) {
  const id = draft?.heading?.table ?? draft?.positions?.table;
  const table = draft?.table?.find((t) => t.id === id && (t.format === "gpx" || t.format === "nmea"));
  if (!table) return null;
  const onTrack = (sec) => (sec?.source === "positions" ? sec : sec?.table === id ? { ...sec, table: "track" } : null);
  return {
    file: table.file,
    table: { ...table, id: "track" },
    heading: onTrack(draft.heading),
    positions: draft.positions ? { ...draft.positions, table: "track" } : null,
    speed: onTrack(draft.speed),
  };
}

function select(id, options, value, label) {
  const s = document.createElement("select");
  s.id = id;
  s.setAttribute("aria-label", label);
  for (const [v, text] of options) s.add(new Option(text, v, false, v === value));
  return s;
}

function row(label, ...controls) {
  const div = document.createElement("div");
  div.className = "map-row";
  const l = document.createElement("span");
  l.textContent = label;
  div.append(l, ...controls);
  return div;
}

/**
 * The form's fields for the sniffed files, appended to `body`, first chosen as core's
 * reading of the columns (`g`, `columnGuesses`; null leaves them to the first columns): the
 * time of each file, the yaw rate (one axis, or three on gravity), the reference heading, the
 * speed and the lead-in. A unit follows its column when another is chosen.
 */
function buildForm(sniffed, g, gpsLog, body) {
  const { value: guessed, reading, file } = inPanel(g, sniffed);
  // A GPS log's "columns" (a GPX track's first line, NMEA's first sentence) are no columns.
  const isGpsLog = (i) => !!(file(i)?.gpx || file(i)?.nmea);
  const cols = [["", "—"]];
  sniffed.forEach((s, i) => isGpsLog(i) || s.header.forEach((c) => cols.push([`${i}:${c}`, sniffed.length > 1 ? `${s.name} › ${c}` : c])));
  // Time of each file.
  const times = sniffed.map((s, i) => {
    const col = select(`map-time-${i}`, s.header.map((h) => [h, h]), file(i)?.time_column ?? s.header[0], `time column of ${s.name}`);
    const unit = select(`map-time-unit-${i}`, TIME_UNITS.map((u) => [u, TIME_LABELS[u] ?? u]), "s", `time unit of ${s.name}`);
    follow(reading, col, unit, "time", "s", `${i}:`);
    // A GPS log's time is its own (a GPX track's points, NMEA's hhmmss): read as the draft does.
    const line = row(`time of ${s.name}`, col, unit);
    line.hidden = isGpsLog(i);
    body.append(line);
    return { col, unit };
  });

  // Yaw rate: one axis or three on gravity.
  const mode = select("map-rate-mode", [["one", "one axis"], ["three", "three axes, projected on gravity"]], g?.yaw_from_axes ? "three" : "one", "yaw rate from");
  const rate = select("map-rate", cols, guessed(g?.yaw_rate), "yaw rate column");
  const axes = ["x", "y", "z"].map((a, k) => select(`map-axis-${a}`, cols, guessed(g?.gyro_axes?.[k]), `gyro ${a} column`));
  const acc = ["x", "y", "z"].map((a, k) => select(`map-acc-${a}`, cols, guessed(g?.accel_axes?.[k]), `accelerometer ${a} column`));
  const rateUnit = select("map-rate-unit", RATE_UNITS.map((u) => [u, u]), "rad/s", "yaw rate unit");
  follow(reading, rate, rateUnit, "rate_unit", "rad/s");
  const sense = select("map-rate-sense", [["ccw", "left turn positive (ccw)"], ["cw", "right turn positive (cw)"]], "ccw", "yaw rate sign");
  const oneRow = row("gyro column", rate);
  const threeRow = row("gyro x, y, z / accel x, y, z", ...axes, ...acc);
  body.append(row("yaw rate", mode, rateUnit, sense), oneRow, threeRow);

  // Reference heading.
  const p = g?.lat_lon;
  const modes = [["none", "none"], ["column", "a heading column"], ["positions", "positions (lat, lon)"]];
  if (gpsLog) modes.push(["track", `the GPS log ${gpsLog.file}`]);
  const refMode = select("map-ref-mode", modes, g?.course ? "column" : gpsLog ? "track" : p ? "positions" : "none", "reference from");
  const ref = select("map-ref", cols, guessed(g?.course), "reference heading column");
  const refUnit = select("map-ref-unit", [["deg", "deg"], ["rad", "rad"]], "deg", "reference unit");
  follow(reading, ref, refUnit, "angle_unit", "deg");
  const refSense = select("map-ref-sense", [["cw", "clockwise from north (GPS course)"], ["ccw", "counter-clockwise"]], "cw", "reference sign");
  const latSel = select("map-lat", cols, p ? guessed({ file: p.file, column: p.lat }) : "", "latitude column");
  const lonSel = select("map-lon", cols, p ? guessed({ file: p.file, column: p.lon }) : "", "longitude column");
  // A GPS course means nothing at a standstill: with a speed, headings below this are dropped.
  const minSpeed = document.createElement("input");
  Object.assign(minSpeed, { id: "map-ref-min-speed", type: "number", min: 0, max: 50, step: 0.5, value: 5 });
  minSpeed.setAttribute("aria-label", "reference heading only above this speed, m/s (with a speed column)");
  minSpeed.title = "reference heading only above this speed, m/s (with a speed column): a GPS course means nothing at a standstill";
  const above = Object.assign(document.createElement("span"), { textContent: "above (m/s)", className: "map-note" });
  const refRow = row("heading column", ref, refUnit, refSense, above, minSpeed);
  const posRow = row("latitude, longitude", latSel, lonSel);
  body.append(row("reference", refMode), refRow, posRow);

  // Speed and the lead-in.
  const sp = select("map-speed", cols, guessed(g?.speed), "speed column");
  const spUnit = select("map-speed-unit", SPEED_UNITS.map((u) => [u, u]), "m/s", "speed unit");
  follow(reading, sp, spUnit, "speed_unit", "m/s");
  const lead = document.createElement("input");
  Object.assign(lead, { id: "map-lead", type: "number", min: 0, max: 600, step: 1, value: 0 });
  lead.setAttribute("aria-label", "stationary lead-in, s");
  body.append(row("speed (optional)", sp, spUnit), row("stationary lead-in, s", lead));

  return { times, mode, rate, axes, acc, rateUnit, sense, oneRow, threeRow, refMode, ref, refUnit, refSense, minSpeed, latSel, lonSel, refRow, posRow, sp, spUnit, lead, track: gpsLog };
}

/** Shows the rows the chosen modes use. */
function showRows(f) {
  f.oneRow.hidden = f.mode.value !== "one";
  f.threeRow.hidden = f.mode.value !== "three";
  f.refRow.hidden = f.refMode.value !== "column";
  f.posRow.hidden = f.refMode.value !== "positions";
}

/** The recipe the form `f` says for `files`, or an error text. */
function recipeOf(f, files, sniffed) {
  const { times, mode, rate, axes, acc, rateUnit, sense, refMode, ref, refUnit, refSense, minSpeed, latSel, lonSel, sp, spUnit, lead, track } = f;
  const used = new Set();
  const at = (v) => {
    const k = v.indexOf(":");
    used.add(Number(v.slice(0, k)));
    return { table: `t${v.slice(0, k)}`, column: v.slice(k + 1) };
  };
  const r = { name: `${files[0].name} (mapped)`, description: "imported by a column mapping", bias_s: Number(lead.value) || 0 };
  if (mode.value === "one") {
    if (!rate.value) return "choose the gyro column";
    const g = at(rate.value);
    r.yaw_rate = { ...g, unit: rateUnit.value, positive: sense.value };
  } else {
    if ([...axes, ...acc].some((s) => !s.value)) return "choose three gyro and three accelerometer columns";
    const g = axes.map((s) => at(s.value));
    const a = acc.map((s) => at(s.value));
    if (g.some((x) => x.table !== g[0].table)) return "the three gyro axes must be in one file";
    r.yaw_rate = { table: g[0].table, axes: g.map((x) => x.column), gravity: { axes: a.map((x) => x.column), table: a[0].table }, unit: rateUnit.value, positive: sense.value };
  }
  if (refMode.value === "column" && ref.value) {
    const h = at(ref.value);
    r.heading = { source: "column", ...h, unit: refUnit.value, positive: refSense.value };
    const min = Number(minSpeed.value);
    if (sp.value && at(sp.value).table === h.table) Object.assign(r.heading, { speed_column: at(sp.value).column, speed_unit: spUnit.value, min_speed_mps: Number.isFinite(min) && min >= 0 ? min : 5 });
  } else if (refMode.value === "positions" && latSel.value && lonSel.value) {
    const p = at(latSel.value);
    r.positions = { table: p.table, kind: "latlon", columns: [p.column, at(lonSel.value).column] };
    r.heading = { source: "positions" };
  }
  // The GPS log as core's draft reads it (its table, course or positions, and speed).
  const onTrack = refMode.value === "track" && track?.heading;
  if (onTrack) Object.assign(r, { heading: track.heading }, track.positions ? { positions: track.positions } : {});
  if (sp.value) r.speed = { source: "column", ...at(sp.value), unit: spUnit.value };
  else if (onTrack && track.speed) r.speed = track.speed;
  r.table = [...used].sort().map((i) => {
    const s = sniffed[i];
    const t = times[i];
    const time = t.unit.value in TIME_LABELS ? { column: t.col.value, format: t.unit.value } : { column: t.col.value, unit: t.unit.value };
    const spec = { id: `t${i}`, file: s.name, time };
    if (s.delimiter !== ",") spec.delimiter = s.delimiter;
    if (s.decimal_comma) spec.decimal_comma = true;
    if (s.skip_lines) spec.skip_lines = s.skip_lines;
    return spec;
  });
  if (onTrack) r.table.push(track.table);
  return r;
}

/**
 * Opens the panel for `files` ([{name, bytes}]) with `why` (the detection's error).
 * `importer(recipe)` imports in the worker: {data, detection} or {error}. `guesses` is core's
 * reading of the columns (`columnGuesses`, from the worker; null: none), the first choices;
 * `draft` core's draft recipe (`draftRecipe`; null: none), whose GPS log (a GPX track, an
 * NMEA log) the panel offers as the reference.
 * `preset` sets fields by id over them ({"map-rate-sense": "cw"}: a check error's fix),
 * `intro` says what the panel is for. Resolves with the last good import {res, recipe}, or
 * null when cancelled.
 */
export function openMapping(files, why, importer, { guesses, draft }, preset = {}, intro = "No preset fits these files. Say which column is what; the preview imports as you choose.") {
  const sniffed = files.map((f) => gd.sniffFile(f.name, f.bytes.subarray(0, 65536)));
  const dlg = $("mapping");
  $("mapping-why").textContent = why;
  $("mapping-intro").textContent = intro;
  const body = $("mapping-fields");
  body.replaceChildren();
  const form = buildForm(sniffed, guesses, draftTrack(draft), body);
  for (const [id, value] of Object.entries(preset)) {
    const el = body.querySelector(`#${id}`);
    if (el) el.value = value;
  }
  const recipe = () => recipeOf(form, files, sniffed);

  let last = null;
  let seq = 0;
  let timer = 0;
  async function preview() {
    showRows(form);
    const r = recipe();
    const out = $("mapping-preview");
    last = null;
    $("mapping-add").disabled = true;
    $("mapping-save").disabled = typeof r === "string";
    if (typeof r === "string") {
      out.textContent = r;
      out.className = "map-preview bad";
      return;
    }
    const n = ++seq;
    out.textContent = "importing…";
    const res = await importer(r);
    if (n !== seq) return; // a newer choice is on its way
    if (res.error) {
      out.textContent = res.error;
      out.className = "map-preview bad";
      return;
    }
    const s = res.detection.summary;
    out.className = "map-preview";
    out.textContent = `${s.n_rows} rows, ${s.n_gyro} gyro samples, ${s.n_reference} reference headings, ${s.duration_min.toFixed(1)} min`;
    last = { res, recipe: r };
    $("mapping-add").disabled = false;
    drawPreview(res.data);
  }
  // A change makes the shown preview stale at once, and one still importing too (it would
  // land after the change with the choices before it): Add waits for the new one.
  const schedule = () => {
    clearTimeout(timer);
    seq++;
    last = null;
    $("mapping-add").disabled = true;
    $("mapping-preview").textContent = "updating…";
    timer = setTimeout(preview, 250);
  };
  // Handlers replaced, not added: the panel is opened again and again, and a listener left
  // from an earlier opening would preview its own files and enable Add.
  body.onchange = schedule;
  body.oninput = schedule;
  $("mapping-save").onclick = () => {
    const r = recipe();
    if (typeof r !== "string") saveRecipe(files[0].name, r);
  };
  $("mapping-cancel").onclick = () => dlg.close();
  preview();
  dlg.showModal();
  return new Promise((resolve) => {
    $("mapping-add").onclick = () => {
      resolve(last);
      dlg.close();
    };
    dlg.onclose = () => resolve(null);
  });
}

/** Integrated gyro against the reference, from the imported columns. */
function drawPreview(data) {
  const c = $("mapping-plot");
  // Drawn at the size the panel shows it, in device pixels (a phone's 2-3x too).
  const dpr = sizeCanvas(c);
  const log = gd.Log.fromColumns(data);
  try {
    const run = gd.runHdr(log, {}); // the lead-in of the mapping (the log's bias_s)
    const series = [{ name: "gyro, integrated", color: COLORS.raw, x: run.trace.time_s, y: run.trace.heading_raw_deg }];
    if (run.reference) series.push({ name: "reference", color: COLORS.ref, x: run.reference.time_s, y: run.reference.heading_deg, points: true });
    plot.drawChart(c, { title: "gyro integrated from the lead-in bias", x_label: "time", time_x: true, y_label: "heading (deg)", series, legend: true, dpr });
  } catch (e) {
    c.getContext("2d").clearRect(0, 0, c.width, c.height);
  } finally {
    log.free();
  }
}
