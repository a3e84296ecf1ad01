// web/ as a static site: the built folder served by a plain static server (python3 -m
// http.server, not scripts/serve.mjs) from a sub-path shows the first screen with a drive
// plotted, at desktop and phone widths.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { spawn } from "node:child_process";
import { mkdtempSync, symlinkSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { ROOT } from "../node/helpers.mjs";

const PORT = 20000 + Math.floor(Math.random() * 2000);
let server, context, page;

before(async () => {
  const host = mkdtempSync(join(tmpdir(), "gd-host-"));
  symlinkSync(join(ROOT, "web"), join(host, "tools-gyro")); // deployed under /tools-gyro/
  server = spawn("python3", ["-m", "http.server", String(PORT), "--bind", "127.0.0.1", "--directory", host], { stdio: ["ignore", "pipe", "pipe"] });
  await new Promise((res) => setTimeout(res, 800));
  context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), "gd-chrome-")), {
    executablePath: "/usr/bin/chromium",
    headless: true,
    viewport: { width: 1400, height: 1000 },
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  });
  page = context.pages()[0] || (await context.newPage());
});

after(async () => {
  await context?.close();
  server?.kill();
});

test("the built web/ on a plain static host, under a sub-path, opens with City 1 plotted", async () => {
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  // Nothing the page asks for is missing or refused.
  page.on("response", (r) => r.status() >= 400 && errors.push(`${r.status()} ${r.url()}`));
  await page.goto(`http://127.0.0.1:${PORT}/tools-gyro/`);
  await page.waitForFunction(() => document.body.dataset.ready === "1", null, { timeout: 30000 });
  await page.waitForFunction(() => document.querySelectorAll("#logs li").length === 5, null, { timeout: 30000 });
  assert.match(await page.locator("#logs li.selected").innerText(), /City 1/);
  assert.match(await page.locator("#m-e-hdr").innerText(), /^\d+\.\d\d$/);
  assert.deepEqual(errors, []);
  await page.setViewportSize({ width: 390, height: 844 });
  await page.waitForTimeout(300);
  for (const id of ["#p-i_c_dps", "#p-i_c_dps-value", "#reset", "#tabs button[data-view=report]", "#export-json"]) {
    const box = await page.locator(id).boundingBox();
    assert.ok(box && box.x >= 0 && box.x + box.width <= 390 + 1, `${id} is inside the 390 px screen: ${JSON.stringify(box)}`);
  }
});
