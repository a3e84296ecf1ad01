// The dashboard's charts and parameters: opens with a sample drive plotted, sliders change
// metrics and plot, bad values are refused in place, zoom, pan, tooltips, ticks, legends,
// and the URL round-trips the parameters, the view and the zoom.
import { test } from "node:test";
import assert from "node:assert/strict";
import { join } from "node:path";
import { SAMPLES, cli } from "../node/helpers.mjs";
import { openDashboard, ARTIFACTS, URL0, page, ready, inked, canvasHash } from "./harness.mjs";

openDashboard();

test("opens with a sample drive plotted", async () => {
  await page.goto(URL0);
  await ready();
  assert.equal(await page.locator("#logs li").count(), 5);
  assert.match(await page.locator("#logs li.selected").innerText(), /City 1/);
  assert.ok((await inked("c-heading")) > 5000, "heading chart drawn");
  assert.ok((await inked("c-error")) > 3000);
  assert.ok((await inked("c-rate")) > 3000);
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "city-1.csv"), "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  // The recommended pipeline is shown beside HDR, with the CLI's numbers.
  const pipe = JSON.parse(cli("pipeline", join(SAMPLES, "train", "city-1.csv"), "--json"));
  assert.equal(await page.locator("#m-e-pipeline").innerText(), pipe.E_psi_pipeline_deg.toFixed(2));
  assert.equal(await page.locator("#m-improvement-pipeline").innerText(), pipe.improvement_pipeline.toFixed(2));
  await page.screenshot({ path: join(ARTIFACTS, "hdr.png"), fullPage: true });
});

test("moving a slider changes the metrics and the plot", async () => {
  const before = await page.locator("#m-e-hdr").innerText();
  const plot = await canvasHash("c-heading");
  await page.locator("#p-i_c_dps").fill("0.01");
  await page.waitForFunction((b) => document.getElementById("m-e-hdr").innerText !== b, before);
  assert.notEqual(await canvasHash("c-heading"), plot);
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "city-1.csv"), "--json", "--set", "i_c=0.01"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  // slider-to-redraw time on the 52 min 10 Hz drive (Highway 1): re-run HDR and redraw 3 charts
  await page.locator("#logs li", { hasText: "Highway 1" }).locator("button.pick").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Highway 1"));
  const ms = await page.evaluate(async () => {
    const s = [];
    for (let k = 0; k < 20; k++) {
      const el = document.getElementById("p-tau_s");
      el.value = String(0.5 + k * 0.05);
      const t0 = performance.now();
      el.dispatchEvent(new Event("input"));
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      s.push(Number(document.body.dataset.renderMs));
    }
    s.sort((a, b) => a - b);
    return s[Math.floor(s.length / 2)];
  });
  console.log(`# slider -> re-run + redraw of the HDR view (Highway 1, 52.1 min at 10 Hz): median ${ms} ms`);
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
});

test("a bad, empty or out-of-range value is refused in place; results, slider and URL keep the last valid one", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  const box = page.locator("#p-i_c_dps-value");
  await box.fill("0.03");
  await box.dispatchEvent("change");
  await page.waitForFunction(() => location.hash.includes("i_c_dps=0.03"));
  const good = await page.locator("#m-e-hdr").innerText();
  for (const bad of ["", "1e9", "-1"]) {
    await box.fill(bad);
    await box.dispatchEvent("change");
    const why = page.locator("#p-i_c_dps-error");
    await page.waitForFunction(() => document.getElementById("p-i_c_dps-error").textContent !== "");
    assert.match(await why.innerText(), bad === "" ? /enter a number/ : /i_c.*\[0, 10\]/, bad);
    assert.match(await why.innerText(), /kept 0\.03/);
    assert.equal(await box.getAttribute("aria-invalid"), "true");
    assert.equal(await page.locator("#p-i_c_dps").inputValue(), "0.03", "slider untouched");
    assert.equal(await page.locator("#m-e-hdr").innerText(), good, "results untouched");
    assert.ok(page.url().includes("i_c_dps=0.03"), "URL untouched");
  }
  await page.screenshot({ path: join(ARTIFACTS, "refused-input.png") });
  await box.fill("0.01");
  await box.dispatchEvent("change");
  await page.waitForFunction(() => document.getElementById("p-i_c_dps-error").textContent === "");
  assert.equal(await box.getAttribute("aria-invalid"), null);
});

test("charts zoom with the keyboard and reset", async () => {
  const full = await page.evaluate(() => window.gyrodrift.state.layouts["c-heading"].x_max - window.gyrodrift.state.layouts["c-heading"].x_min);
  await page.locator("#c-heading").focus();
  await page.keyboard.press("+");
  await page.waitForFunction((f) => {
    const L = window.gyrodrift.state.layouts["c-heading"];
    return L.x_max - L.x_min < f * 0.9;
  }, full);
  await page.keyboard.press("0");
  await page.waitForFunction(() => window.gyrodrift.state.zoom === null);
});

test("the time axis reads in s, min or h by the span shown", async () => {
  const unit = () => page.evaluate(() => [window.gyrodrift.state.layouts["c-heading"].x_unit, document.getElementById("c-heading").getAttribute("aria-label")]);
  const zoom = async (z) => {
    await page.evaluate((z) => { window.gyrodrift.state.zoom = z; window.gyrodrift.render(); }, z);
  };
  try {
    await zoom(null);
    let [u, label] = await unit();
    assert.equal(u, "min", "City 1 (about 20 min) in minutes");
    assert.match(label, /time \(min\) 0\.\d+ to \d+\.\d/);
    await zoom([100, 220]);
    [u, label] = await unit();
    assert.equal(u, "s");
    assert.match(label, /time \(s\) 100 to 220/);
    await zoom([0, 60 * 3600]);
    [u, label] = await unit();
    assert.equal(u, "h");
    assert.match(label, /time \(h\) 0\.00 to 60\.0/);
  } finally {
    await zoom(null);
  }
});

test("a tooltip at the cursor lists every shown series with core's value there, in any time chart", async () => {
  await page.locator("#c-error").scrollIntoViewIfNeeded();
  const box = await page.locator("#c-error").boundingBox();
  await page.mouse.move(box.x + box.width * 0.6, box.y + box.height * 0.5);
  const tip = page.locator("#c-error").locator("xpath=..").locator(".tip");
  await tip.waitFor({ state: "visible" });
  const check = () => page.evaluate(() => {
    const { state, gd } = window.gyrodrift;
    const spec = state.specs["c-error"];
    const cells = [...document.querySelectorAll("#c-error ~ .tip td[data-series]")].map((td) => [td.dataset.series, td.textContent]);
    const want = spec.series.filter((s) => s.name !== "zero").map((s) => [s.name, gd.valueAt(s.x, s.y, state.cursor).toFixed(3)]);
    return { cells, want, head: document.querySelector("#c-error ~ .tip b").textContent };
  });
  let r = await check();
  assert.deepEqual(r.cells.map((c) => c[0]), ["raw", "HDR", "pipeline", "smoothed (offline)"]);
  assert.deepEqual(r.cells, r.want);
  assert.match(r.head, /^t = \d+\.\d\d min$/);
  await page.screenshot({ path: join(ARTIFACTS, "tooltip.png") });
  // The readout gives the pipeline's heading with its sigma from the bias model.
  const sigma = (await page.locator("#hdr-readout").innerText()).match(/pipeline -?[\d.]+ ± ([\d.]+) deg \(1σ, bias\)/);
  assert.ok(sigma && Number(sigma[1]) > 0, await page.locator("#hdr-readout").innerText());
  // A hidden series leaves the tooltip.
  await page.locator("#legend-c-error button.key", { hasText: /^raw$/ }).click();
  await page.locator("#c-error").scrollIntoViewIfNeeded();
  const box2 = await page.locator("#c-error").boundingBox();
  await page.mouse.move(box2.x + box2.width * 0.5, box2.y + box2.height * 0.5);
  await page.waitForFunction(() => !document.querySelector("#c-error ~ .tip td[data-series=raw]"));
  r = await check();
  assert.deepEqual(r.cells, r.want);
  await page.locator("#legend-c-error button.key", { hasText: /^raw$/ }).click();
  // The rate chart also says whether the turn switch is on.
  await page.locator("#c-rate").scrollIntoViewIfNeeded();
  const rb = await page.locator("#c-rate").boundingBox();
  await page.mouse.move(rb.x + rb.width * 0.5, rb.y + rb.height * 0.5);
  await page.locator("#c-rate ~ .tip").waitFor({ state: "visible" });
  assert.match(await page.locator("#c-rate ~ .tip").innerText(), /turn switch on: (yes|no)/);
  await page.mouse.move(0, 0);
  await page.waitForFunction(() => document.querySelector("#c-rate ~ .tip").hidden);
});

test("dragging shows a rubber band; a flat drag zooms time, a tall one this chart's y too; double-click resets", async () => {
  await page.locator("#c-error").scrollIntoViewIfNeeded();
  const box = await page.locator("#c-error").boundingBox();
  const y = box.y + box.height * 0.5;
  await page.mouse.move(box.x + box.width * 0.3, y);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.5, y + 3, { steps: 4 });
  const band = page.locator("#c-error ~ .band");
  await band.waitFor({ state: "visible" });
  const bb = await band.boundingBox();
  assert.ok(Math.abs(bb.width - box.width * 0.2) < 3, `band ${bb.width} px for a ${box.width * 0.2} px drag`);
  assert.ok(bb.height > box.height * 0.6, "a flat drag's band spans the plot's height");
  await page.mouse.up();
  await page.waitForFunction(() => window.gyrodrift.state.zoom !== null);
  assert.equal(await band.isHidden(), true);
  assert.equal(await page.evaluate(() => window.gyrodrift.state.yzoom["c-error"]), undefined);
  const before = await page.evaluate(() => ({ ...window.gyrodrift.state.layouts["c-error"] }));
  // A tall box: the y range follows the box on this chart only.
  await page.mouse.move(box.x + box.width * 0.4, box.y + box.height * 0.3);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.6, box.y + box.height * 0.6, { steps: 4 });
  await page.mouse.up();
  // (drawn on the next frame)
  await page.waitForFunction(() => {
    const { state } = window.gyrodrift;
    const yz = state.yzoom["c-error"];
    return yz && state.layouts["c-error"].y_min === yz[0] && state.layouts["c-error"].y_max === yz[1];
  });
  const after = await page.evaluate(() => ({ yz: window.gyrodrift.state.yzoom["c-error"], L: window.gyrodrift.state.layouts["c-error"], H: window.gyrodrift.state.layouts["c-heading"] }));
  assert.ok(after.yz[1] - after.yz[0] < (before.y_max - before.y_min) * 0.5, JSON.stringify(after.yz));
  assert.deepEqual([after.L.y_min, after.L.y_max], after.yz);
  assert.ok(after.H.x_max - after.H.x_min < before.x_max - before.x_min, "time zoom shared by the heading chart");
  await page.locator("#c-error").dblclick();
  await page.waitForFunction(() => window.gyrodrift.state.zoom === null && !window.gyrodrift.state.yzoom["c-error"]);
});

test("axis ticks sit at round values: 1, 2 or 5 times a power of ten apart, whole decades on log axes", async () => {
  const round = (ticks) => {
    if (ticks.length < 2) return `only ${ticks.length} ticks`;
    const step = ticks[1] - ticks[0];
    const mag = 10 ** Math.floor(Math.log10(step) + 1e-9);
    const m = Math.round(step / mag);
    if (![1, 2, 5].includes(m) || Math.abs(step / mag - m) > 1e-6) return `step ${step}`;
    for (const t of ticks) if (Math.abs(t / step - Math.round(t / step)) > 1e-6) return `tick ${t} is not a multiple of ${step}`;
    for (let i = 1; i < ticks.length; i++) if (Math.abs(ticks[i] - ticks[i - 1] - step) > step * 1e-6) return "uneven";
    return "ok";
  };
  const L = await page.evaluate(() => Object.fromEntries(["c-heading", "c-error", "c-rate"].map((id) => [id, { x: [...window.gyrodrift.state.layouts[id].x_ticks], y: [...window.gyrodrift.state.layouts[id].y_ticks] }])));
  for (const [id, t] of Object.entries(L)) {
    assert.equal(round(t.x), "ok", `${id} x ${t.x}`);
    assert.equal(round(t.y), "ok", `${id} y ${t.y}`);
    assert.ok(t.x.length >= 3 && t.x.length <= 10 && t.y.length >= 3 && t.y.length <= 10, `${id}: ${t.x.length} x, ${t.y.length} y ticks`);
  }
  await page.locator("#tabs button[data-view=allan]").click();
  await page.waitForFunction(() => !document.getElementById("view-allan").hidden && window.gyrodrift.state.layouts["c-allan"]);
  const A = await page.evaluate(() => [...window.gyrodrift.state.layouts["c-allan"].x_ticks]);
  assert.ok(A.length >= 3 && A.every((v) => Math.abs(Math.log10(v) - Math.round(Math.log10(v))) < 1e-9), `Allan tau ticks ${A}`);
  await page.locator("#tabs button[data-view=hdr]").click();
});

test("the URL round-trips the parameters and the view", async () => {
  await page.waitForFunction(() => location.hash.includes("i_c_dps=0.01") && location.hash.includes("log=City"));
  const url = page.url();
  await page.goto("about:blank");
  await page.goto(url);
  await ready();
  assert.equal(await page.locator("#p-i_c_dps").inputValue(), "0.01");
  await page.locator("#reset").click();
  assert.equal(await page.locator("#p-i_c_dps").inputValue(), "0.0422");
});

test("a link pasted into the open tab is applied, zoom included, and Back steps back", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  await page.waitForFunction(() => location.hash.includes("view=hdr") && location.hash.includes("log=City"));
  const hdrUrl = page.url();
  const shared = hdrUrl.split("#")[0] + "#view=hdr&log=Highway+1&i_c_dps=0&tau_s=0.75&zoom=100,400";
  await page.evaluate((u) => { location.href = u; }, shared);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Highway 1"));
  assert.equal(await page.locator("#p-i_c_dps").inputValue(), "0", "a threshold of 0 round-trips");
  await page.waitForFunction(() => {
    const L = window.gyrodrift.state.layouts["c-heading"];
    return L && Math.abs(L.x_min - 100) < 1 && Math.abs(L.x_max - 400) < 1;
  });
  await page.locator("#tabs button[data-view=track]").click();
  await page.waitForFunction(() => location.hash.includes("view=track"));
  await page.goBack();
  await page.waitForFunction(() => window.gyrodrift.state.view === "hdr");
  assert.ok(page.url().includes("view=hdr"));
  await page.locator("#reset").click();
});

test("legends sit outside the data and hide a series on click; guide lines are not listed", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=hdr]").click();
  const keys = page.locator("#legend-c-error button.key");
  const names = await keys.allInnerTexts();
  assert.ok(names.includes("raw") && !names.includes("zero"), names.join(" | "));
  const before = await canvasHash("c-error");
  const raw = page.locator("#legend-c-error button.key", { hasText: /^raw$/ });
  await raw.click();
  await page.waitForFunction(() => document.querySelector("#legend-c-error button.key[aria-pressed=false]"));
  assert.notEqual(await canvasHash("c-error"), before);
  await raw.click();
  await page.waitForFunction(() => !document.querySelector("#legend-c-error button.key[aria-pressed=false]"));
});
