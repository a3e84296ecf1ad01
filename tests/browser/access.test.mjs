// Accessibility and small screens: keyboard and names, first-use explanations, axe-core in
// every view, and on a phone's touch screen taps, pans, pinches and the stacked layout.
import { test } from "node:test";
import assert from "node:assert/strict";
import { join } from "node:path";
import { ROOT } from "../node/helpers.mjs";
import { openDashboard, ARTIFACTS, URL0, page, ready, onPhone } from "./harness.mjs";

openDashboard();

test("accessibility: tabs move with arrow keys, buttons have unique names, charts have a text alternative", async () => {
  await page.locator("#tabs button[data-view=hdr]").focus();
  await page.keyboard.press("ArrowRight");
  await page.waitForFunction(() => window.gyrodrift.state.view === "track");
  assert.equal(await page.evaluate(() => document.activeElement.dataset.view), "track");
  assert.equal(await page.locator("#tabs button[tabindex='0']").count(), 1);
  await page.keyboard.press("ArrowLeft");
  await page.waitForFunction(() => window.gyrodrift.state.view === "hdr");
  const names = await page.locator("button.png").evaluateAll((bs) => bs.map((b) => b.getAttribute("aria-label")));
  assert.equal(new Set(names).size, names.length, names.join(" | "));
  const label = await page.locator("#c-heading").getAttribute("aria-label");
  assert.equal(await page.locator("#c-heading").getAttribute("role"), "img");
  assert.match(label, /heading: reference \(GPS\), raw, HDR.*time \(min\) [\d.]+ to \d+/);
  assert.equal(await page.locator("#view-error").getAttribute("role"), "alert");
});

test("first use: a panel says what the tool is for, every parameter and metric explains itself", async () => {
  const intro = page.locator("#first-use");
  assert.match(await intro.locator("summary").innerText(), /What is this/);
  for (const p of ["i_c_dps", "tau_s", "theta_w_dps", "c1", "c2", "bias_s"]) {
    const help = await page.locator(`label[for=p-${p}]`).getAttribute("title");
    assert.ok(help && help.length > 30, `${p}: ${help}`);
  }
  assert.match(await page.locator("label[for=p-i_c_dps]").getAttribute("title"), /Eq\. 11/);
  assert.match(await page.locator("#m-e-hdr").locator("xpath=..").getAttribute("title"), /mean absolute heading error/);
  const example = await intro.locator("a[download]").getAttribute("href");
  const res = await page.request.get(new URL(example, page.url()).href);
  assert.ok(res.ok() && (await res.text()).includes("time_s"), "the example CSV downloads");
});

test("axe-core finds no serious or critical accessibility violation in any view", async () => {
  await page.addScriptTag({ path: join(ROOT, "tests", "node_modules", "axe-core", "axe.min.js") });
  // The check can fail: a nameless button put in the page is found (then removed).
  const probe = await page.evaluate(async () => {
    const b = document.createElement("button");
    b.id = "axe-probe";
    document.body.append(b);
    const v = (await window.axe.run("#axe-probe", { resultTypes: ["violations"] })).violations.map((v) => `${v.id}:${v.impact}`);
    b.remove();
    return v;
  });
  assert.ok(probe.includes("button-name:critical"), probe.join(" "));
  // With a drive overlaid, so its list button and metrics row are checked too.
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "Highway 1" }).locator("button.overlay").click();
  await page.waitForSelector("#overlay-metrics .overlay-row");
  const found = [];
  for (const view of ["hdr", "track", "gyrodometry", "calibration", "allan", "report"]) {
    await page.locator(`#tabs button[data-view="${view}"]`).click();
    await page.waitForFunction((v) => !document.getElementById(`view-${v}`).hidden, view);
    const res = await page.evaluate(async () => (await window.axe.run(document, { resultTypes: ["violations"] })).violations
      .filter((v) => v.impact === "serious" || v.impact === "critical")
      .map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(" ")).join(", ")}`));
    found.push(...res.map((r) => `${view}: ${r}`));
  }
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "Highway 1" }).locator("button.overlay").click();
  assert.deepEqual(found, []);
});

test("on a touch screen a tap on a metric, a parameter's name or a note shows what its tooltip says", async () => {
  await onPhone(async (phone) => {
    const tip = phone.locator("#touch-tip");
    assert.equal(await tip.isVisible(), false);
    await phone.locator("#m-e-hdr").tap();
    assert.equal(await tip.isVisible(), true);
    assert.match(await tip.innerText(), /mean absolute heading error/);
    const t = await tip.boundingBox();
    assert.ok(t.x >= 0 && t.x + t.width <= 391, `the tip inside 390 px: ${JSON.stringify(t)}`);
    await phone.screenshot({ path: join(ARTIFACTS, "phone-touch-tip.png") });
    await phone.locator("label[for=p-i_c_dps]").tap();
    assert.match(await tip.innerText(), /Eq\. 11/);
    // A tap elsewhere closes it; a control's tap does its own work, no tip.
    await phone.locator("h1").tap();
    assert.equal(await tip.isVisible(), false);
    await phone.locator("#tabs button[data-view=track]").tap();
    assert.equal(await tip.isVisible(), false);
  });
});

test("on a touch screen a time chart pans with one finger, pinches with two and resets at a double tap", async () => {
  await onPhone(async (phone) => {
    const chart = phone.locator("#c-heading");
    await chart.scrollIntoViewIfNeeded();
    const b = await chart.boundingBox();
    const y = b.y + b.height / 2;
    const cdp = await phone.context().newCDPSession(phone);
    const touch = (type, xs) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: xs.map((x, id) => ({ x, y, id })) });
    const zoom = () => phone.evaluate(() => window.gyrodrift.state.zoom);
    const range = await phone.evaluate(() => { const L = window.gyrodrift.state.layouts["c-heading"]; return [L.x_min, L.x_max]; });
    // One finger from 60 % to 30 % of the chart: later times come into view, the span kept.
    await touch("touchStart", [b.x + 0.6 * b.width]);
    for (const f of [0.5, 0.4, 0.3]) await touch("touchMove", [b.x + f * b.width]);
    await touch("touchEnd", []);
    const panned = await zoom();
    assert.ok(panned && panned[0] > range[0] && Math.abs(panned[1] - panned[0] - (range[1] - range[0])) < 1e-6 * (range[1] - range[0]), JSON.stringify({ range, panned }));
    // Two fingers spread from 40-60 % to 20-80 %: a third of the span.
    await touch("touchStart", [b.x + 0.4 * b.width, b.x + 0.6 * b.width]);
    for (const d of [0.15, 0.2, 0.25, 0.3]) await touch("touchMove", [b.x + (0.5 - d) * b.width, b.x + (0.5 + d) * b.width]);
    await touch("touchEnd", []);
    const pinched = await zoom();
    const ratio = (pinched[1] - pinched[0]) / (panned[1] - panned[0]);
    assert.ok(Math.abs(ratio - 1 / 3) < 0.05, `pinched to ${ratio} of the span`);
    await phone.waitForTimeout(300);
    await phone.screenshot({ path: join(ARTIFACTS, "phone-pinched.png") });
    // The page still scrolls up and down over a chart.
    assert.equal(await chart.evaluate((c) => getComputedStyle(c).touchAction), "pan-y");
    // A double tap resets (the browser's dblclick: no double-tap zoom under pan-y).
    for (let i = 0; i < 2; i++) {
      await touch("touchStart", [b.x + 0.5 * b.width]);
      await touch("touchEnd", []);
      await phone.waitForTimeout(60);
    }
    await phone.waitForFunction(() => window.gyrodrift.state.zoom === null);
    // The Track view: two fingers spread to three times their distance zoom in threefold.
    await phone.locator("#tabs button[data-view=track]").tap();
    await phone.waitForFunction(() => window.gyrodrift.state.layouts["c-track"]);
    const track = phone.locator("#c-track");
    await track.scrollIntoViewIfNeeded();
    const tb = await track.boundingBox();
    const ty = tb.y + tb.height / 2;
    const mpp = () => phone.evaluate(() => { const L = window.gyrodrift.state.layouts["c-track"]; return (L.x_max - L.x_min) / (L.right - L.left); });
    const m0 = await mpp();
    const two = (type, d) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: type === "touchEnd" ? [] : [{ x: tb.x + tb.width / 2 - d, y: ty, id: 0 }, { x: tb.x + tb.width / 2 + d, y: ty, id: 1 }] });
    await two("touchStart", 30);
    for (const d of [45, 60, 75, 90]) await two("touchMove", d);
    await two("touchEnd", 0);
    await phone.waitForTimeout(200);
    assert.ok(Math.abs((await mpp()) / m0 - 1 / 3) < 0.05, `pinched the track to ${(await mpp()) / m0} of its scale`);
    await phone.screenshot({ path: join(ARTIFACTS, "phone-track-pinched.png") });
  });
});

test("at phone width the log list stacks above the views and the charts take the width", async () => {
  await page.setViewportSize({ width: 390, height: 900 });
  try {
    await page.goto(URL0);
    await ready();
    const box = async (sel) => page.locator(sel).boundingBox();
    const aside = await box("#logs-panel");
    const chart = await box("#c-heading");
    assert.ok(chart.width > 330, `heading chart ${chart.width} px wide at 390 px`);
    assert.ok(chart.y > aside.y + aside.height - 1, "charts below the log list");
    // The smoothed mode is shown, labelled non-causal.
    assert.match(await page.locator("#m-e-smoothed").innerText(), /^\d+\.\d\d$/);
    // every control is on the screen
    for (const sel of ["#p-i_c_dps", "#p-i_c_dps-value", "#p-bias_s-value", "#reset", "#export-trace", "#export-json", "#tabs button[data-view=report]"]) {
      const b = await box(sel);
      assert.ok(b && b.x >= 0 && b.x + b.width <= 391, `${sel} inside 390 px: ${JSON.stringify(b)}`);
    }
    // A chart's legend wraps beside its CSV and PNG buttons, never under them.
    const clashes = await page.evaluate(() => {
      const meet = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
      const out = [];
      for (const c of document.querySelectorAll("section:not([hidden]) .chart")) {
        const keys = [...c.querySelectorAll(".legend .key")].map((k) => k.getBoundingClientRect());
        for (const b of c.querySelectorAll("button.csv, button.png")) {
          const r = b.getBoundingClientRect();
          if (r.width > 0 && keys.some((k) => meet(k, r))) out.push(c.querySelector("canvas")?.id);
        }
      }
      return out;
    });
    assert.deepEqual(clashes, []);
    await page.screenshot({ path: join(ARTIFACTS, "phone.png"), fullPage: true });
    // The Report's wide tables scroll in their own boxes: the page never scrolls sideways.
    await page.locator("#tabs button[data-view=report]").click();
    await page.locator("#compare-table table").waitFor();
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= 391), "the report view scrolls the page sideways at 390 px");
    await page.screenshot({ path: join(ARTIFACTS, "phone-report.png"), fullPage: true });
    await page.locator("#tabs button[data-view=hdr]").click();
    // a tablet (820 px) stacks too
    await page.setViewportSize({ width: 820, height: 1000 });
    await page.waitForTimeout(200);
    const a2 = await box("#logs-panel");
    const c2 = await box("#c-heading");
    assert.ok(c2.y > a2.y + a2.height - 1 && c2.width > 760, `stacked at 820 px: chart ${JSON.stringify(c2)}`);
  } finally {
    await page.setViewportSize({ width: 1400, height: 1000 });
  }
});
