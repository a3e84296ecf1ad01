// The Report view's robustness battery: the battery's error profiles on the loaded drives,
// run in the worker (core's battery::on_drives); the summary per method and every case,
// each of which opens as a log of its own (the drive with the profile's errors added).
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, pipelineOptions } from "../state.js";
import { inWorker, driveColumns, addParsed } from "../loading.js";
import { renderList, selectEntry } from "../controls.js";
import { scoredDrives } from "./report.js";

/** Runs the battery on every loaded drive and shows it. */
export async function runBattery() {
  const drives = scoredDrives();
  if (!drives.length) return;
  const button = $("battery");
  button.disabled = true;
  $("battery-status").textContent = "running in a worker…";
  const { cols, transfer } = driveColumns(drives);
  const t0 = performance.now();
  const res = await inWorker({ type: "battery", drives: cols, options: pipelineOptions() }, transfer);
  button.disabled = false;
  if (res.error) {
    $("battery-status").textContent = res.error;
    $("battery-result").replaceChildren();
    return;
  }
  const b = res.data;
  const s = b.added;
  const skipped = b.skipped.length ? ` · ${b.skipped.length} skipped (${b.skipped[0][1]})` : "";
  $("battery-status").textContent =
    `${s.n_cases} cases in ${((performance.now() - t0) / 1000).toFixed(1)} s: the pipeline within 1.25× the best other + 0.05 on ${s.n_within}, ` +
    `worse than 2× on ${s.n_over_2x}, worse than raw by > 10 % on ${s.n_worse_than_raw}; worst ${fmt(s.worst_ratio, 2)}× (${s.worst})${skipped}`;
  const details = document.createElement("details");
  details.innerHTML = `<summary>every case (${b.cases.length})</summary>`;
  details.append(casesTable(b));
  $("battery-result").replaceChildren(summaryTable(b), details);
}

/** Per method: mean NE_psi, and the cases within 1.25x / worse than 2x the best of its others. */
function summaryTable(b) {
  const s = b.added;
  const t = document.createElement("table");
  t.id = "battery-summary";
  t.innerHTML = `<thead><tr><th></th>${b.methods.map((m) => `<th>${m}</th>`).join("")}</tr></thead><tbody></tbody>`;
  const body = t.querySelector("tbody");
  const row = (label, cells) => {
    const tr = document.createElement("tr");
    for (const c of [label, ...cells]) {
      const td = document.createElement("td");
      td.textContent = c;
      tr.append(td);
    }
    body.append(tr);
  };
  row("mean NE_ψ (deg/min)", s.mean.map((v) => fmt(v, 3)));
  row("within 1.25× / worse than 2× the best of the others", s.each_within.map((w, i) => `${w} / ${s.each_over_2x[i]}`));
  return t;
}

/** Every case: its profile, each method's NE_psi (the best causal one marked), the ratio. */
function casesTable(b) {
  const t = document.createElement("table");
  t.id = "battery-cases";
  t.innerHTML = `<thead><tr><th>drive / profile</th>${b.methods.map((m) => `<th>${m}</th>`).join("")}<th>pipeline / best other</th><th></th></tr></thead><tbody></tbody>`;
  const body = t.querySelector("tbody");
  for (const c of b.cases) {
    const tr = document.createElement("tr");
    const cells = [`${c.base} / ${c.profile}`, ...c.ne_psi.map((v) => fmt(v, 3)), `${fmt(c.ratio, 2)}×${c.within ? "" : " !"}`];
    cells.forEach((v, i) => {
      const td = document.createElement("td");
      td.textContent = v;
      if (i >= 1 && i <= c.ne_psi.length && c.ne_psi[i - 1] === c.ne_psi[c.best]) td.className = "best";
      tr.append(td);
    });
    const open = document.createElement("button");
    open.type = "button";
    open.className = "open-case";
    open.textContent = "open";
    open.title = `add "${c.base} / ${c.profile}" to the logs: the drive with the profile's gyro errors (the CLI's battery --write-case)`;
    open.addEventListener("click", () => openCase(c, open));
    const td = document.createElement("td");
    td.append(open);
    tr.append(td);
    body.append(tr);
  }
  return t;
}

/** Adds one case as a log of its own (its "open" button). */
function openCase(c, button) {
  return addWithErrors(c.base, c.profile, button, $("battery-status"));
}

/** Adds drive `baseName` with profile `profile`'s errors (added in the worker by core's
 * inject) as a log of its own and shows it in the HDR view; an error is said in `status`
 * and leaves everything loaded. */
async function addWithErrors(baseName, profile, button, status) {
  const name = `${baseName} / ${profile}`;
  const base = scoredDrives().find((e) => e.name === baseName);
  if (!base) {
    status.textContent = `${name}: the drive ${baseName} is no longer loaded`;
    return;
  }
  button.disabled = true;
  const { cols, transfer } = driveColumns([base]);
  const res = await inWorker({ type: "case", drive: cols[0], profile }, transfer);
  button.disabled = false;
  if (res.error) {
    status.textContent = `${name}: ${res.error}`;
    return;
  }
  const entry = addParsed(name, () => {
    const log = gd.Log.fromColumns(res.data);
    log.name = name;
    return log;
  });
  renderList();
  if (entry.error) return;
  state.view = "hdr";
  selectEntry(state.entries.indexOf(entry));
  window.scrollTo({ top: 0 });
}

let profileNames = null;

/** Fills the worse-gyro pickers: the loaded drives, and the battery's profiles (asked of
 * the worker once; the page's own module has no simulator). Keeps what was picked. */
export async function fillWorse() {
  const pick = $("worse-drive");
  const was = pick.value;
  const drives = scoredDrives().map((e) => e.name);
  pick.replaceChildren(...drives.map((n) => new Option(n, n, false, n === was)));
  if (!profileNames && window.Worker) {
    profileNames = [];
    const res = await inWorker({ type: "profiles" }, []);
    if (res.error) return ($("worse-status").textContent = res.error);
    profileNames = res.data;
    $("worse-profile").replaceChildren(...profileNames.map((n) => new Option(n, n)));
  }
}

/** The worse-gyro button: the picked drive with the picked profile's errors. */
export function addWorse() {
  const drive = $("worse-drive").value;
  const profile = $("worse-profile").value;
  if (!drive || !profile) return ($("worse-status").textContent = "load a drive first");
  $("worse-status").textContent = "";
  return addWithErrors(drive, profile, $("worse"), $("worse-status"));
}
