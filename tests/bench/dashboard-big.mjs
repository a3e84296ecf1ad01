#!/usr/bin/env node
// The dashboard on a big log (issue 16, item 9), in headless Chromium: a 60 MB, 2.19 M-row
// log (Highway 1 repeated with shifted time: 60 h at 10 Hz) opened from disk; then 20 HDR
// slider moves (median render time: re-run and redraw) and a switch to the Track view; the
// longest main-thread task of each phase by the Long Tasks API (opening includes parsing in
// the worker and the pipeline, also in the worker, arriving).
//   node tests/bench/dashboard-big.mjs        (after scripts/test.sh has built web/pkg)
import { spawn } from "node:child_process";
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { ROOT, SAMPLES } from "../node/helpers.mjs";

const ROWS = 2_190_000;
const src = readFileSync(join(SAMPLES, "train", "highway-1.csv"), "utf8").split("\n");
const header = src.findIndex((l) => l.startsWith("time_s"));
const rows = src.slice(header + 1).filter((l) => l.length > 0).map((l) => l.split(","));
const span = Number(rows[rows.length - 1][0]) + 0.1;
const parts = ["# name: Big 60 h\n" + src[header] + "\n"];
let n = 0;
for (let k = 0; n < ROWS; k++) {
  const take = rows.slice(0, Math.min(rows.length, ROWS - n));
  parts.push(take.map((r) => [(Number(r[0]) + k * span).toFixed(1), ...r.slice(1)].join(",")).join("\n") + "\n");
  n += take.length;
}
const file = join(mkdtempSync(join(tmpdir(), "gd-big-")), "big-60h.csv");
writeFileSync(file, parts.join(""));
const mb = readFileSync(file).length / 1e6;

const PORT = 19000 + Math.floor(Math.random() * 900);
const server = spawn("node", [join(ROOT, "scripts", "serve.mjs"), String(PORT)], { stdio: ["ignore", "pipe", "inherit"] });
await new Promise((res) => server.stdout.once("data", res));
const context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), "gd-chrome-")), {
  executablePath: "/usr/bin/chromium",
  headless: true,
  viewport: { width: 1400, height: 1000 },
  deviceScaleFactor: 1,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
try {
  const page = context.pages()[0] || (await context.newPage());
  page.on("pageerror", (e) => console.error("page error:", e.message));
  await page.goto(`http://127.0.0.1:${PORT}/`);
  await page.waitForFunction(() => document.body.dataset.ready === "1", null, { timeout: 30000 });
  // The longest main-thread task from here on, by phase (Long Tasks API).
  await page.evaluate(() => {
    window.__tasks = [];
    new PerformanceObserver((l) => l.getEntries().forEach((e) => window.__tasks.push(e.duration))).observe({ type: "longtask", buffered: false });
  });
  const longest = () => page.evaluate(() => { const m = Math.max(0, ...window.__tasks); window.__tasks = []; return m; });
  const t0 = Date.now();
  await page.locator("#file-input").setInputFiles([file]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Big 60 h"), null, { timeout: 120000 });
  const loadS = (Date.now() - t0) / 1000;
  await page.waitForFunction(() => document.getElementById("m-e-pipeline"), null, { timeout: 120000 });
  const pipeS = (Date.now() - t0) / 1000;
  const openLongest = await longest();
  const slider = await page.evaluate(async () => {
    const s = [];
    for (let k = 0; k < 20; k++) {
      const el = document.getElementById("p-tau_s");
      el.value = String(0.5 + k * 0.05);
      el.dispatchEvent(new Event("input"));
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      s.push(Number(document.body.dataset.renderMs));
    }
    s.sort((a, b) => a - b);
    return { median: s[10], max: s[19] };
  });
  const sliderLongest = await longest();
  const t1 = Date.now();
  await page.locator('#tabs button[data-view="track"]').click();
  // The track is drawn when the worker's raw and HDR paths arrived (or at once, computed on
  // the page); the pipeline's paths (its own run in the worker) are drawn when they arrive.
  await page.waitForFunction(() => !/the track/.test(document.getElementById("track-busy").textContent) && Number(document.getElementById("c-track").dataset.drawn || 0) > 0, null, { timeout: 120000 });
  const drawnS = (Date.now() - t1) / 1000;
  await page.waitForFunction(() => !document.getElementById("track-busy").textContent && window.gyrodrift.state.specs["c-track"].series.some((s) => s.name.startsWith("pipeline")), null, { timeout: 120000 });
  const track = { longest: await longest(), drawnS, s: (Date.now() - t1) / 1000 };
  console.log(`${mb.toFixed(1)} MB, ${ROWS} rows: opened and plotted in ${loadS.toFixed(1)} s, pipeline shown after ${pipeS.toFixed(1)} s; longest main-thread task while opening ${openLongest.toFixed(0)} ms`);
  console.log(`HDR slider: longest main-thread task ${sliderLongest.toFixed(0)} ms`);
  console.log(`HDR slider -> re-run + redraw: median ${slider.median.toFixed(1)} ms, max ${slider.max.toFixed(1)} ms (goal: median <= 50)`);
  console.log(`Track view: drawn after ${track.drawnS.toFixed(1)} s, with the pipeline's paths after ${track.s.toFixed(1)} s, longest main-thread task ${track.longest.toFixed(0)} ms (goal <= 100)`);
} finally {
  await context.close();
  server.kill();
}
