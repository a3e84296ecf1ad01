// The dashboard's other views: Track, exports (JSON, CSV), log columns and overlays, the
// Report's tables, the robustness battery and one worse gyro, Allan deviation; each with
// the CLI's numbers.
import { test } from "node:test";
import assert from "node:assert/strict";
import { mkdtempSync, readFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { SAMPLES, cli } from "../node/helpers.mjs";
import { openDashboard, context, ARTIFACTS, page, inked } from "./harness.mjs";

openDashboard();

test("the Track view has equal metres per pixel across and up, and the recommended pipeline's paths; its zoom and pan are in the link", async () => {
  await page.locator("#tabs button[data-view=track]").click();
  await page.waitForFunction(() => window.gyrodrift.state.layouts["c-track"]);
  const names = await page.evaluate(() => window.gyrodrift.state.specs["c-track"].series.map((s) => s.name));
  assert.deepEqual(names, ["reference heading", "raw", "HDR", "pipeline (recommended)", "smoothed (offline)"]);
  for (const width of [1400, 390]) {
    await page.setViewportSize({ width, height: 1000 });
    await page.waitForTimeout(200);
    const L = await page.evaluate(() => window.gyrodrift.state.layouts["c-track"]);
    const across = (L.x_max - L.x_min) / (L.right - L.left);
    const up = (L.y_max - L.y_min) / (L.bottom - L.top);
    assert.ok(Math.abs(across / up - 1) < 0.01, `width ${width}: ${across} m/px across, ${up} m/px up`);
    // The whole track is shown, with 5 % to spare on the axis that limits it.
    const ext = await page.evaluate(() => {
      const e = (k) => { let l = Infinity, h = -Infinity; for (const s of window.gyrodrift.state.specs["c-track"].series) for (const v of s[k]) if (Number.isFinite(v)) { l = Math.min(l, v); h = Math.max(h, v); } return [l, h]; };
      return [e("x"), e("y")];
    });
    const [[x0, x1], [y0, y1]] = ext;
    assert.ok(L.x_min <= x0 && L.x_max >= x1 && L.y_min <= y0 && L.y_max >= y1, `${JSON.stringify(ext)} in ${JSON.stringify(L)}`);
    const spare = Math.min((L.x_max - L.x_min) / (x1 - x0), (L.y_max - L.y_min) / (y1 - y0));
    assert.ok(Math.abs(spare - 1.05) < 0.02, `spare ${spare}`);
  }
  await page.setViewportSize({ width: 1400, height: 1000 });
  await page.waitForTimeout(200);
  // The wheel zooms about the cursor (the metres under it stay under it), a drag pans, a
  // double click resets; the axes stay equal.
  const layout = () => page.evaluate(() => window.gyrodrift.state.layouts["c-track"]);
  const canvas = page.locator("#c-track");
  const box = await canvas.boundingBox();
  const L0 = await layout();
  const kc = (await canvas.evaluate((c) => c.width)) / box.width; // canvas pixels per CSS pixel
  // The metres under CSS pixel (px, py) of the canvas in layout L.
  const under = (L, px, py) => [
    L.x_min + (px * kc - L.left) * ((L.x_max - L.x_min) / (L.right - L.left)),
    L.y_max - (py * kc - L.top) * ((L.y_max - L.y_min) / (L.bottom - L.top)),
  ];
  const [px, py] = [box.width * 0.3, box.height * 0.4];
  const before = under(L0, px, py);
  await page.mouse.move(box.x + px, box.y + py);
  await page.mouse.wheel(0, -100);
  await page.waitForFunction((w) => window.gyrodrift.state.layouts["c-track"].x_max - window.gyrodrift.state.layouts["c-track"].x_min < w, L0.x_max - L0.x_min);
  const L1 = await layout();
  assert.ok(Math.abs((L1.x_max - L1.x_min) / (L0.x_max - L0.x_min) - 0.8) < 1e-6, "one wheel step zooms in by 0.8");
  const after = under(L1, px, py);
  assert.ok(Math.hypot(after[0] - before[0], after[1] - before[1]) < 2 * (L0.x_max - L0.x_min) / (L0.right - L0.left), `${before} -> ${after}`);
  const across = (L1.x_max - L1.x_min) / (L1.right - L1.left), up = (L1.y_max - L1.y_min) / (L1.bottom - L1.top);
  assert.ok(Math.abs(across / up - 1) < 0.01);
  await page.mouse.down();
  await page.mouse.move(box.x + px + 100, box.y + py, { steps: 4 });
  await page.mouse.up();
  await page.waitForTimeout(100);
  const L2 = await layout();
  assert.ok(L2.x_min < L1.x_min && Math.abs(L2.x_max - L2.x_min - (L1.x_max - L1.x_min)) < 1e-6, "a drag to the right pans west");
  // The view is in the link, and a link's view is applied.
  await page.waitForFunction(() => /[#&]track=[-0-9.e]+(%2C|,)[-0-9.e]+(%2C|,)[0-9.e]+/.test(location.hash));
  const linked = page.url().split("#")[0] + "#view=track&log=City+1&track=1000,1500,2";
  await page.evaluate((u) => { location.href = u; }, linked);
  await page.waitForFunction(() => {
    const L = window.gyrodrift.state.layouts["c-track"];
    return L && Math.abs((L.x_min + L.x_max) / 2 - 1000) < 1e-6 && Math.abs((L.y_min + L.y_max) / 2 - 1500) < 1e-6 && Math.abs((L.x_max - L.x_min) / (L.right - L.left) - 2) < 1e-9;
  });
  await canvas.dblclick();
  await page.waitForFunction(() => window.gyrodrift.state.trackView === null && !location.hash.includes("track="));
  await page.waitForTimeout(100);
  assert.ok(Math.abs((await layout()).x_max - L0.x_max) < 1e-6, "a double click shows the whole track again");
  await page.locator("#tabs button[data-view=hdr]").click();
});

test("exports reproduce: the JSON names the log, settings and version; files are named by log and chart", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  const [json] = await Promise.all([page.waitForEvent("download"), page.locator("#export-json").click()]);
  assert.equal(json.suggestedFilename(), "City 1-hdr.json");
  const out = JSON.parse(readFileSync(await json.path(), "utf8"));
  assert.equal(out.log, "City 1");
  assert.equal(out.method, "hdr");
  assert.match(out.gyrodrift, /^\d+\.\d+\.\d+/);
  assert.equal(out.options.i_c_dps, Number(await page.locator("#p-i_c_dps").inputValue()));
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "city-1.csv"), "--json", "--set", `i_c=${out.options.i_c_dps}`, "--set", `tau=${out.options.tau_s}`));
  assert.equal(out.result.E_psi_hdr_deg, native.E_psi_hdr_deg, "the JSON's settings give its numbers");
  const [png] = await Promise.all([page.waitForEvent("download"), page.locator("button.png[data-canvas=c-heading]").click()]);
  assert.equal(png.suggestedFilename(), "City 1-heading.png");
});

test("CSV exports hold every plotted series as drawn: all HDR charts on one time line, and each chart's own", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=hdr]").click();
  const [dl] = await Promise.all([page.waitForEvent("download"), page.locator("#export-trace").click()]);
  assert.equal(dl.suggestedFilename(), "City 1-hdr-series.csv");
  const lines = readFileSync(await dl.path(), "utf8").trim().split("\n");
  const head = lines[0].split(",");
  for (const col of ["time (s)", "heading: reference (GPS) (deg)", "heading: raw (deg)", "heading: HDR (deg)", "heading: pipeline (deg)", "heading: smoothed (offline) (deg)",
    "error: raw (deg)", "error: HDR (deg)", "error: pipeline (deg)", "rate: ω corrected (deg/s)", "rate: −I drift estimate (deg/s)", "rate: turn switch on (0/1)"]) {
    assert.ok(head.includes(col), `${col} in ${lines[0]}`);
  }
  // The HDR column is the package's trace, sample for sample.
  const trace = await page.evaluate(() => {
    const { gd, state } = window.gyrodrift;
    const e = state.entries.find((x) => x.name === "City 1");
    const run = gd.runHdr(e.log, { resample: state.resample, ...state.params });
    return { t: [...run.trace.time_s.slice(0, 50)], hdr: [...run.trace.heading_hdr_deg.slice(0, 50)] };
  });
  const ti = head.indexOf("time (s)"), hi = head.indexOf("heading: HDR (deg)");
  const rows = new Map(lines.slice(1).map((l) => l.split(",")).map((c) => [Number(c[ti]), c[hi]]));
  for (let k = 0; k < 50; k++) assert.equal(Number(rows.get(trace.t[k])), trace.hdr[k], `t = ${trace.t[k]}`);
  // Each chart's CSV button: the Allan chart's taus and its band's two edges.
  await page.locator("#logs li", { hasText: "Static 2 h" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=allan]").click();
  await page.waitForFunction(() => !document.getElementById("view-allan").hidden);
  const [a] = await Promise.all([page.waitForEvent("download"), page.locator("button.csv[data-canvas=c-allan]").click()]);
  assert.equal(a.suggestedFilename(), "Static 2 h-allan.csv");
  const allan = readFileSync(await a.path(), "utf8").trim().split("\n");
  assert.match(allan[0], /^τ \(s\),68 % band \(deg\/s\),68 % band 2 \(deg\/s\),Allan deviation \(deg\/s\)/);
  const taus = await page.evaluate(() => window.gyrodrift.gd.allan(window.gyrodrift.state.entries.find((x) => x.name.startsWith("Static")).log).tau_s.length);
  assert.equal(allan.length - 1, taus);
  const names = await page.locator("button.csv").evaluateAll((bs) => bs.map((b) => b.getAttribute("aria-label")));
  assert.equal(new Set(names).size, names.length);
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
});

test("any log column plots on the shared time axis; another drive overlays the error and column charts; both in the URL", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=hdr]").click();
  const picker = page.locator("#col-picker");
  const cols = await picker.locator("input").evaluateAll((is) => is.map((i) => [i.value, i.checked]));
  assert.deepEqual(cols.map((c) => c[0]).sort(), (await page.evaluate(() => window.gyrodrift.state.entries.find((e) => e.name === "City 1").log.columns().filter((c) => c !== "time_s"))).sort());
  assert.deepEqual(cols.filter((c) => c[1]).map((c) => c[0]), ["speed_mps"], "speed by default");
  await picker.locator("input[value=temp_c]").check();
  await page.waitForFunction(() => /temp_c/.test(location.hash) && window.gyrodrift.state.specs["c-columns"].series.some((s) => s.name === "temp_c"));
  // The plotted temperature is the log's column, and the time axis is the HDR charts'.
  // Every drawn point is a sample of the column (core keeps, per pixel, the first, last and
  // extreme samples), the column's extremes are drawn, and the time axis is the HDR charts'.
  const same = await page.evaluate(() => {
    const { state } = window.gyrodrift;
    const s = state.specs["c-columns"].series.find((x) => x.name === "temp_c");
    const log = state.entries.find((e) => e.name === "City 1").log;
    const t = log.column("time_s"), col = log.column("temp_c");
    const at = new Map([...t].map((v, i) => [v, col[i]]));
    const finite = [...col].filter(Number.isFinite);
    return {
      samples: s.x.every((x, i) => Object.is(at.get(x), s.y[i])),
      extremes: Math.max(...s.y) === Math.max(...finite) && Math.min(...s.y) === Math.min(...finite),
      axis: state.layouts["c-columns"].x_max === state.layouts["c-heading"].x_max,
    };
  });
  assert.deepEqual(same, { samples: true, extremes: true, axis: true });
  // Overlay Highway 1: its HDR and pipeline errors join the error chart with the CLI's NE_psi.
  const hw = page.locator("#logs li", { hasText: "Highway 1" }).locator("button.overlay");
  assert.equal(await hw.getAttribute("aria-pressed"), "false");
  await hw.click();
  await page.waitForFunction(() => window.gyrodrift.state.specs["c-error"].series.some((s) => s.name === "Highway 1: HDR"));
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "highway-1.csv"), "--json"));
  assert.match(await page.locator('#overlay-metrics .overlay-row[data-log="Highway 1"]').innerText(), new RegExp(`HDR ${native.NE_psi_hdr_deg_per_min.toFixed(3)}`));
  assert.ok(await page.evaluate(() => window.gyrodrift.state.specs["c-columns"].series.some((s) => s.name === "Highway 1: temp_c")));
  // Unzoomed, the time axis now spans the longer overlaid drive.
  assert.ok(await page.evaluate(() => window.gyrodrift.state.layouts["c-error"].x_max >= window.gyrodrift.state.entries.find((e) => e.name === "Highway 1").log.durationMin * 60 - 1));
  await page.waitForFunction(() => new URLSearchParams(location.hash.slice(1)).getAll("overlay").includes("Highway 1"));
  assert.equal(await page.locator("#logs li", { hasText: "Highway 1" }).locator("button.overlay").getAttribute("aria-pressed"), "true");
  await page.screenshot({ path: join(ARTIFACTS, "overlay.png"), fullPage: true });
  // The link restores both in a new tab (this tab keeps the logs later tests use).
  const tab = await context.newPage();
  try {
    await tab.goto(page.url());
    await tab.waitForFunction(() => document.body.dataset.ready === "1" && window.gyrodrift.state.specs["c-error"]?.series.some((s) => s.name === "Highway 1: HDR"), null, { timeout: 30000 });
    assert.equal(await tab.locator("#col-picker input[value=temp_c]").isChecked(), true);
  } finally {
    await tab.close();
  }
  await page.locator("#logs li", { hasText: "Highway 1" }).locator("button.overlay").click();
  await picker.locator("input[value=temp_c]").uncheck();
  await page.waitForFunction(() => !/overlay=/.test(location.hash) && !window.gyrodrift.state.specs["c-error"].series.some((s) => s.name.startsWith("Highway 1")));
});

test("the Report tables export as CSV and Markdown, with the CLI's numbers", async () => {
  await page.locator("#tabs button[data-view=report]").click();
  await page.waitForSelector("#report-table table");
  const [csv] = await Promise.all([page.waitForEvent("download"), page.locator("#export-report-csv").click()]);
  assert.equal(csv.suggestedFilename(), "gyrodrift-table-ii.csv");
  const text = readFileSync(await csv.path(), "utf8");
  assert.match(text.split("\n")[0], /^name,duration_min,E_psi_raw_deg/);
  const city = text.split("\n").find((l) => l.startsWith("City 1,"));
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "city-1.csv"), "--json"));
  assert.ok(city && city.includes(String(native.E_psi_hdr_deg)), city);
  const [md] = await Promise.all([page.waitForEvent("download"), page.locator("#export-compare-md").click()]);
  assert.match(readFileSync(await md.path(), "utf8"), /\| Drive \| Duration \(min\) \| raw \| HDR Table III \|/);
  await page.locator("#tabs button[data-view=hdr]").click();
});

for (const [view, canvases] of [["track", ["c-track"]], ["gyrodometry", ["c-gyrodometry"]], ["calibration", ["c-cal-before", "c-cal-after"]], ["allan", ["c-allan"]], ["report", []]]) {
  test(`the ${view} view draws`, async () => {
    if (view === "report") {
      // Tune's leave-one-drive-out needs three drives: a third joins City 1 and Highway 1.
      await page.locator("#file-input").setInputFiles([join(SAMPLES, "test", "city-3.csv")]);
      await page.locator("#logs li", { hasText: "City 3" }).waitFor();
    }
    await page.locator(`#tabs button[data-view="${view}"]`).click();
    await page.waitForFunction((v) => !document.getElementById(`view-${v}`).hidden, view);
    assert.equal(await page.locator("#view-error").isVisible(), false, await page.locator("#view-error").innerText());
    for (const c of canvases) assert.ok((await inked(c)) > 3000, `${c} drawn`);
    if (view === "report") {
      assert.ok((await page.locator("#report-table tr").count()) >= 4);
      // Every method side by side, one row per drive plus the mean; City 1's pipeline as the CLI's.
      assert.equal(await page.locator("#compare-table tbody tr").count(), (await page.locator("#report-table tbody tr").count()));
      const pipe = JSON.parse(cli("pipeline", join(SAMPLES, "train", "city-1.csv"), "--json"));
      assert.equal(await page.locator('#compare-table tr[data-drive="City 1"] td.pipeline').innerText(), pipe.NE_psi_pipeline_deg_per_min.toFixed(3));
      // Tune runs in the worker; the page stays responsive meanwhile, then offers the result.
      await page.locator("#tune").click();
      await page.waitForSelector("#apply-tuned", { timeout: 120000 });
      assert.match(await page.locator("#tune-status").innerText(), /done in .* deg\/min/);
      assert.match(await page.locator("#tune-status").innerText(), /leave-one-drive-out: held-out NE_ψ .*; recommended: /);
      const before = await page.locator("#p-i_c_dps").inputValue();
      await page.locator("#apply-tuned").click();
      await page.waitForFunction(() => !document.getElementById("view-hdr").hidden);
      assert.notEqual(await page.locator("#p-i_c_dps").inputValue(), before);
    }
    await page.screenshot({ path: join(ARTIFACTS, `${view}.png`), fullPage: true });
  });
}

test("the robustness battery runs on the loaded drives in the worker, with the CLI's numbers", async () => {
  await page.locator("#tabs button[data-view=report]").click();
  await page.locator("#battery").click();
  await page.waitForSelector("#battery-summary", { timeout: 120000 });
  const status = await page.locator("#battery-status").innerText();
  assert.match(status, /^\d+ cases in [\d.]+ s: the pipeline within 1\.25× the best other \+ 0\.05 on \d+, .* worst [\d.]+× \(/);
  const n = Number(status.match(/^(\d+) cases/)[1]);
  assert.equal(await page.locator("#battery-cases tbody tr").count(), n);
  assert.equal(await page.locator("#battery-summary tbody tr").count(), 2);
  // City 1 with a +0.5 deg/s turn-on bias: each method's NE_psi as the CLI's `battery --logs` gives it.
  const native = JSON.parse(cli("battery", "--logs", join(SAMPLES, "train", "city-1.csv"), "--minutes", "2", "--split", "scoring", "--json"));
  const row = native.cases.find((c) => c.base === "City 1" && c.profile === "bias +0.5");
  await page.locator("#battery-result details summary").click();
  const cells = await page.evaluate(() =>
    [...document.querySelectorAll("#battery-cases tbody tr")].map((tr) => [...tr.cells].map((td) => td.textContent)).find((c) => c[0] === "City 1 / bias +0.5"),
  );
  assert.deepEqual(cells.slice(1, 7), row.ne_psi.slice(0, 6).map((v) => v.toFixed(3)), String(cells));
  // The cell marked best is the lowest causal one (not the smoothed mode's, column 6 here).
  const marked = await page.evaluate(() =>
    [...[...document.querySelectorAll("#battery-cases tbody tr")].find((tr) => tr.cells[0].textContent === "City 1 / bias +0.5").cells].map((td) => td.className === "best"),
  );
  const causal = cells.slice(1, 7).map(Number).filter((_, j) => j !== 5);
  assert.deepEqual(marked.slice(1, 7).map((m, j) => m && j !== 5), cells.slice(1, 7).map((v, j) => j !== 5 && Number(v) === Math.min(...causal)), String(cells));
  await page.screenshot({ path: join(ARTIFACTS, "battery.png"), fullPage: true });
  // A case opens as a log of its own, in the HDR view: the drive with the profile's errors
  // added, as the CLI's `battery --write-case` writes it (same raw integration: the HDR
  // parameters on the page are the tuned ones applied above).
  const nLogs = await page.locator("#logs li").count();
  await page.evaluate(() =>
    [...document.querySelectorAll("#battery-cases tbody tr")].find((tr) => tr.cells[0].textContent === "City 1 / bias +0.5").querySelector("button.open-case").click(),
  );
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City 1 / bias +0.5"));
  assert.equal(await page.locator("#logs li").count(), nLogs + 1);
  assert.equal(await page.evaluate(() => !document.getElementById("view-hdr").hidden), true);
  const caseFile = join(mkdtempSync(join(tmpdir(), "gd-case-")), "case.csv");
  cli("battery", "--logs", join(SAMPLES, "train", "city-1.csv"), "--minutes", "2", "--write-case", "City 1 / bias +0.5", "--out", caseFile);
  const caseHdr = JSON.parse(cli("hdr", caseFile, "--json"));
  assert.equal(await page.locator("#m-e-raw").innerText(), caseHdr.E_psi_raw_deg.toFixed(2));
  assert.equal(caseHdr.NE_psi_raw_deg_per_min.toFixed(3), cells[1]);
  await page.screenshot({ path: join(ARTIFACTS, "battery-case.png"), fullPage: true });
  await page.locator("#logs li", { hasText: "City 1 / bias +0.5" }).locator("button.remove").click();
  assert.equal(await page.locator("#logs li").count(), nLogs);
  await page.locator("#tabs button[data-view=hdr]").click();
});

test("one worse gyro: a drive and a profile picked in the Report view add a log equal to the CLI's inject", async () => {
  await page.locator("#tabs button[data-view=report]").click();
  await page.waitForFunction(() => document.querySelectorAll("#worse-profile option").length > 10);
  const nLogs = await page.locator("#logs li").count();
  await page.locator("#worse-drive").selectOption("Highway 1");
  await page.locator("#worse-profile").selectOption("bias -1.5 cut");
  await page.locator("#worse").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Highway 1 / bias -1.5 cut"));
  assert.equal(await page.locator("#logs li").count(), nLogs + 1);
  const file = join(mkdtempSync(join(tmpdir(), "gd-worse-")), "worse.csv");
  cli("inject", join(SAMPLES, "train", "highway-1.csv"), "--profile", "bias -1.5 cut", "--out", file);
  const native = JSON.parse(cli("hdr", file, "--json"));
  assert.equal(await page.locator("#m-e-raw").innerText(), native.E_psi_raw_deg.toFixed(2));
  await page.locator("#logs li", { hasText: "Highway 1 / bias -1.5 cut" }).locator("button.remove").click();
  assert.equal(await page.locator("#logs li").count(), nLogs);
});

test("the Allan view marks the minimum with its 68 % band and the flat bottom, with the CLI's numbers", async () => {
  await page.locator("#logs li", { hasText: "Static 2 h" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=allan]").click();
  await page.waitForFunction(() => !document.getElementById("view-allan").hidden && document.getElementById("m-bottom"));
  const text = cli("allan", join(SAMPLES, "static", "static-2h.csv"));
  const [, lo, hi, a, b] = text.match(/68 % band +([\d.]+) to ([\d.]+) deg\/s; the minimum could lie anywhere in tau ([\d.]+) to ([\d.]+) s/);
  const tight = text.match(/tightest bound +adev [\d.]+ deg\/s at tau = ([\d.]+) s/)[1];
  assert.equal(await page.locator("#m-bi-band").innerText(), `${Number(lo).toFixed(5)}–${Number(hi).toFixed(5)}`);
  assert.equal(await page.locator("#m-bottom").innerText(), `${Number(a).toFixed(1)}–${Number(b).toFixed(1)}`);
  assert.equal(await page.locator("#m-tight").innerText(), Number(tight).toFixed(1));
  // On the static sample the plain minimum is the last, noisiest point; the band says so.
  assert.ok(Number(b) > Number(a) && Number(tight) < Number(b), text);
  const keys = await page.locator("#legend-c-allan button.key").allInnerTexts();
  assert.deepEqual(keys.filter((k) => k === "68 % band"), ["68 % band"], keys.join(" | "));
  assert.ok(keys.includes("minimum ± 68 %") && keys.includes("flat bottom"), keys.join(" | "));
  assert.ok((await inked("c-allan")) > 3000);
  await page.screenshot({ path: join(ARTIFACTS, "allan-ci.png") });
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
});

test("the pipeline settings apply wherever the pipeline runs, with the CLI's --set numbers; a bad value is refused in place; the link keeps them; Reset clears them", async () => {
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  const city = join(SAMPLES, "train", "city-1.csv");
  const def = JSON.parse(cli("pipeline", city, "--json"));
  const set = JSON.parse(cli("pipeline", city, "--set", "still_speed_mps=3", "--json"));
  assert.notEqual(set.E_psi_pipeline_deg.toFixed(2), def.E_psi_pipeline_deg.toFixed(2));
  const shown = (v) => page.waitForFunction((t) => document.getElementById("m-e-pipeline")?.textContent === t, v.toFixed(2));
  await shown(def.E_psi_pipeline_deg);
  await page.evaluate(() => { document.getElementById("pipe-settings").open = true; });
  assert.equal(await page.locator("#p-still_speed_mps-value").inputValue(), "0.2"); // core's default
  await page.locator("#p-still_speed_mps-value").fill("3");
  await page.locator("#p-still_speed_mps-value").dispatchEvent("change");
  await shown(set.E_psi_pipeline_deg);
  await page.waitForFunction(() => location.hash.includes("pipe.still_speed_mps=3"));
  // A value core refuses is refused in place: the reason beside the box, the results kept.
  await page.locator("#p-still_speed_mps-value").fill("0");
  await page.locator("#p-still_speed_mps-value").dispatchEvent("change");
  assert.match(await page.locator("#p-still_speed_mps-error").innerText(), /still_speed_mps: 0 is not a number in \(0, 1e6\) \(kept 3\)/);
  assert.equal(await page.locator("#m-e-pipeline").innerText(), set.E_psi_pipeline_deg.toFixed(2));
  // The Report's comparison runs the pipeline with the same settings.
  await page.locator("#tabs button[data-view=report]").click();
  const cell = page.locator('#compare-table tr[data-drive="City 1"] td.pipeline');
  await cell.waitFor();
  assert.equal(await cell.innerText(), set.NE_psi_pipeline_deg_per_min.toFixed(3));
  await page.locator("#tabs button[data-view=hdr]").click();
  // The link opens with them (once the debounced link says the HDR view again).
  await page.waitForFunction(() => location.hash.includes("view=hdr") && location.hash.includes("pipe.still_speed_mps=3"));
  const link = page.url();
  await page.goto("about:blank");
  await page.goto(link);
  await page.waitForFunction(() => document.body.dataset.ready === "1", null, { timeout: 30000 });
  assert.equal(await page.locator("#p-still_speed_mps-value").inputValue(), "3");
  await shown(set.E_psi_pipeline_deg);
  await page.screenshot({ path: join(ARTIFACTS, "pipeline-settings.png") });
  // Reset: core's defaults, and the link without them.
  await page.evaluate(() => { document.getElementById("pipe-settings").open = true; });
  await page.locator("#reset-pipe").click();
  await shown(def.E_psi_pipeline_deg);
  assert.equal(await page.locator("#p-still_speed_mps-value").inputValue(), "0.2");
  await page.waitForFunction(() => !location.hash.includes("pipe."));
});
