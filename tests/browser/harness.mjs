// The dashboard under test, shared by the browser test files: scripts/serve.mjs on a random
// port and Debian's headless Chromium (playwright-core) with one page, opened on the
// dashboard before a file's first test; helpers that read what the page drew.
// Screenshots go to test-artifacts/.
import { before, after } from "node:test";
import { spawn } from "node:child_process";
import { mkdirSync, mkdtempSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { ROOT } from "../node/helpers.mjs";

export const ARTIFACTS = join(ROOT, "test-artifacts");
mkdirSync(ARTIFACTS, { recursive: true });
const PORT = 18000 + Math.floor(Math.random() * 2000);
export const URL0 = `http://127.0.0.1:${PORT}/`;
/** The page every test of a file drives, and its browser context (set by `openDashboard`'s before hook). */
export let page, context;
let server;

/** Registers the file's before and after hooks: the server, the browser, the dashboard loaded. */
export function openDashboard() {
  before(async () => {
    server = spawn("node", [join(ROOT, "scripts", "serve.mjs"), String(PORT)], { stdio: ["ignore", "pipe", "inherit"] });
    await new Promise((res) => server.stdout.once("data", res));
    context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), "gd-chrome-")), {
      executablePath: "/usr/bin/chromium",
      headless: true,
      viewport: { width: 1400, height: 1000 },
      deviceScaleFactor: 1,
      args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
    });
    page = context.pages()[0] || (await context.newPage());
    page.on("pageerror", (e) => console.error("page error:", e.message));
    await page.goto(URL0);
    await ready();
  });
  after(async () => {
    await context?.close();
    server?.kill();
  });
}

export async function ready() {
  await page.waitForFunction(() => document.body.dataset.ready === "1", null, { timeout: 30000 });
}

/** Non-white pixels of a canvas (it has been drawn on). */
export async function inked(id) {
  return page.evaluate((id) => {
    const c = document.getElementById(id);
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 240 || d[i + 1] < 240 || d[i + 2] < 240) n++;
    return n;
  }, id);
}

export async function canvasHash(id) {
  return page.evaluate((id) => document.getElementById(id).toDataURL().length + ":" + document.getElementById(id).toDataURL().slice(-200), id);
}

/** Runs `fn` on the page opened in a phone's touch context (390 px, touch events). */
export async function onPhone(fn) {
  const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args: ["--no-sandbox", "--disable-gpu"] });
  try {
    const phone = await (await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true })).newPage();
    await phone.goto(URL0);
    await phone.waitForFunction(() => document.body.dataset.ready === "1", null, { timeout: 30000 });
    await fn(phone);
  } finally {
    await browser.close();
  }
}
