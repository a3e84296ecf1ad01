// The Report view: Table II, every method side by side, and tuning in a worker.
import * as gd from "../pkg/gyrodrift.js";
import { $, fmt, state, hdrOptions, pipelineOptions, COLORS, PALETTE } from "../state.js";
import { logFor, syncParams } from "../controls.js";
import { chart, timeRange } from "../charts.js";
import { showError, render } from "../render.js";
import { inWorker, driveColumns } from "../loading.js";
import { fillWorse } from "./robustness.js";

/** A log `check` found an error in: the CLI refuses it, as its figures would be absurd. */
const refused = (e) => e.errors?.length > 0;

/** The loaded drives with a reference heading and no check error: the ones the Report view
 * scores, as the CLI's report would. */
export function scoredDrives() {
  return state.entries.filter((e) => !e.error && e.scored && !refused(e));
}

/** The loaded drives the Report view tabulates. Those `check` refuses are left out here
 * (entry.errors, decided once where a log is loaded), so the tables are called with
 * ignore_check = true: no second check of every log at every slider step. */
export function reportDrives() {
  return scoredDrives().map((e) => e.log);
}

/** The Report tables as files: Table II and the comparison, CSV or Markdown, from core. */
export function reportExports(download) {
  const pipe = () => pipelineOptions();
  const files = {
    "export-report-csv": ["gyrodrift-table-ii.csv", "text/csv", () => gd.reportCsv(reportDrives(), hdrOptions(), true)],
    "export-report-md": ["gyrodrift-table-ii.md", "text/markdown", () => gd.reportMarkdown(reportDrives(), hdrOptions(), true)],
    "export-compare-csv": ["gyrodrift-methods.csv", "text/csv", () => gd.compareTable(reportDrives(), pipe(), "csv", true)],
    "export-compare-md": ["gyrodrift-methods.md", "text/markdown", () => gd.compareTable(reportDrives(), pipe(), "markdown", true)],
  };
  for (const [id, [name, type, make]] of Object.entries(files)) {
    $(id).addEventListener("click", () => {
      try {
        download(name, make(), type);
      } catch (e) {
        showError(e.message);
      }
    });
  }
}

export function renderReport() {
  const loaded = state.entries.filter((e) => !e.error && e.kind === "drive");
  const unscored = loaded.filter((e) => !e.scored).map((e) => e.name);
  const left = loaded.filter((e) => e.scored && refused(e)).map((e) => e.name);
  $("report-unscored").hidden = !unscored.length && !left.length;
  $("report-unscored").textContent = [
    unscored.length ? `Not scored (no reference heading): ${unscored.join(", ")}.` : "",
    left.length ? `Left out (check found an error, whose fix its badge says; the CLI refuses such a log): ${left.join(", ")}.` : "",
  ].filter(Boolean).join(" ");
  const drives = reportDrives();
  if (!drives.length) return showError("Load drive logs for the report.");
  const rep = gd.report(drives, hdrOptions(), true);
  $("report-table").replaceChildren(reportTable(rep));
  const cmp = gd.compare(drives, pipelineOptions(), true);
  $("compare-table").replaceChildren(compareTable(cmp));
  fillWorse();
}

export function compareTable(cmp) {
  const t = document.createElement("table");
  const cols = [["raw", "raw"], ["hdr_table_iii", "HDR Table III"], ["fusion_offset", "Fusion offset"], ["zaru", "ZARU at stops"], ["pipeline", "pipeline"]];
  t.innerHTML = `<thead><tr><th>drive</th><th>duration (min)</th>${cols.map(([, h]) => `<th>${h}</th>`).join("")}<th title="offline, non-causal; not ranked">smoothed (offline)</th></tr></thead><tbody></tbody>`;
  const body = t.querySelector("tbody");
  for (const r of [...cmp.rows, cmp.mean]) {
    const tr = document.createElement("tr");
    tr.dataset.drive = r.name;
    const best = Math.min(...cols.map(([k]) => r[k]));
    const cells = [r.name, fmt(r.duration_min, 1), ...cols.map(([k]) => fmt(r[k], 3))];
    cells.forEach((c, i) => {
      const td = document.createElement("td");
      td.textContent = c;
      if (i >= 2 && r[cols[i - 2][0]] === best) td.className = "best";
      if (i === cells.length - 1) td.className += " pipeline";
      tr.append(td);
    });
    const sm = document.createElement("td");
    sm.textContent = fmt(r.pipeline_smoothed, 3);
    sm.className = "smoothed";
    tr.append(sm);
    body.append(tr);
  }
  return t;
}

export function reportTable(rep) {
  const t = document.createElement("table");
  t.innerHTML = `<thead><tr><th>drive</th><th>duration (min)</th><th>E<sub>ψ</sub> raw (deg)</th><th>NE<sub>ψ</sub> raw (deg/min)</th><th>E<sub>ψ</sub> HDR (deg)</th><th>NE<sub>ψ</sub> HDR (deg/min)</th><th>improvement</th></tr></thead><tbody></tbody>`;
  const body = t.querySelector("tbody");
  const row = (cells) => {
    const tr = document.createElement("tr");
    for (const c of cells) {
      const td = document.createElement("td");
      td.textContent = c;
      tr.append(td);
    }
    body.append(tr);
  };
  for (const r of rep.rows) row([r.name, fmt(r.duration_min, 1), fmt(r.E_psi_raw_deg, 1), fmt(r.NE_psi_raw_deg_per_min, 2), fmt(r.E_psi_hdr_deg, 1), fmt(r.NE_psi_hdr_deg_per_min, 2), fmt(r.improvement, 1) + "×"]);
  row([`average of ${rep.rows.length}`, fmt(rep.total_duration_min, 1), fmt(rep.mean_E_psi_raw_deg, 1), fmt(rep.mean_NE_psi_raw_deg_per_min, 2), fmt(rep.mean_E_psi_hdr_deg, 1), fmt(rep.mean_NE_psi_hdr_deg_per_min, 2), `${fmt(rep.mean_improvement, 1)}× (σ ${fmt(rep.std_improvement, 2)})`]);
  return t;
}

export async function runTune() {
  const drives = scoredDrives();
  if (!drives.length) return;
  const button = $("tune");
  const bar = $("tune-progress");
  button.disabled = true;
  bar.hidden = false;
  bar.value = 0;
  $("tune-status").textContent = "tuning in a worker…";
  const { cols: train, transfer } = driveColumns(drives);
  const t0 = performance.now();
  const res = await inWorker({ type: "tune", train, options: {} }, transfer, (f) => {
    bar.value = f;
  });
  bar.hidden = true;
  button.disabled = false;
  if (res.error) {
    $("tune-status").textContent = res.error;
    return;
  }
  const rep = res.data;
  const p = rep.result.params;
  const cv = rep.result.cv;
  const cvText = cv
    ? ` · leave-one-drive-out: held-out NE_ψ ${fmt(cv.cv_table_iii_deg_per_min, 4)} with Table III, ${fmt(cv.cv_tuned_deg_per_min, 4)} tuned`
    : " · no cross-validation (fewer than 3 drives)";
  const verdict = rep.result.recommended_is_tuned ? "recommended: the tuned parameters" : "recommended: Table III (the tuned parameters do worse on drives they were not tuned on)";
  $("tune-status").textContent = `done in ${((performance.now() - t0) / 1000).toFixed(1)} s: mean NE_ψ over the ${drives.length} drives ${fmt(rep.result.objective_start_deg_per_min, 4)} → ${fmt(rep.result.objective_tuned_deg_per_min, 4)} deg/min${cvText}; ${verdict}`;
  const div = $("tune-result");
  div.replaceChildren(reportTable(rep.train.tuned));
  const b = document.createElement("button");
  b.id = "apply-tuned";
  b.textContent = `${rep.result.recommended_is_tuned ? "Apply" : "Apply anyway (not recommended)"} tuned parameters (i_c ${fmt(p.i_c_dps, 4)}, tau ${fmt(p.tau_s, 3)}, theta_w ${fmt(p.theta_w_dps, 3)}, c1 ${fmt(p.c1, 3)}, c2 ${fmt(p.c2, 3)})`;
  b.addEventListener("click", () => {
    Object.assign(state.params, p);
    syncParams();
    state.view = "hdr";
    render();
  });
  div.append(b);
}
