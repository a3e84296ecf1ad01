// The npm package in the bundlers web tools are built with. It is packed as npm publishes it
// (its "files" list), installed into a fresh app (tests/bundler/: the core module on the page,
// the full module in a Web Worker, the chart module drawing), bundled by Vite (its build, and
// its dev server, which pre-bundles dependencies) and by webpack 5, and opened in Chromium:
// each gives the Node package's numbers and draws its chart.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { build, createServer, preview } from "vite";
import webpack from "webpack";
import * as gd from "gyrodrift";
import { ROOT, SAMPLES } from "../node/helpers.mjs";

const LOG = join(SAMPLES, "train", "city-1.csv");
let dir, app, browser;

before(async () => {
  dir = mkdtempSync(join(tmpdir(), "gd-bundler-"));
  app = join(dir, "app");
  cpSync(join(ROOT, "tests", "bundler"), app, { recursive: true });
  mkdirSync(join(app, "public"));
  cpSync(LOG, join(app, "public", "city-1.csv"));
  // `npm pack` writes what `npm publish` would and prints the tarball's name.
  const tarball = execFileSync("npm", ["pack", "--silent", "--pack-destination", dir], { cwd: join(ROOT, "web", "pkg"), encoding: "utf8" }).trim();
  const installed = join(app, "node_modules", "gyrodrift");
  mkdirSync(installed, { recursive: true });
  execFileSync("tar", ["xzf", join(dir, tarball), "-C", installed, "--strip-components=1"]);
  browser = await chromium.launch({
    executablePath: "/usr/bin/chromium",
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  });
});

after(async () => {
  await browser?.close();
  if (dir) rmSync(dir, { recursive: true, force: true });
});

const port = () => 20000 + Math.floor(Math.random() * 2000);

/** Opens `url`, waits for the app's result; asserts the numbers and the chart; returns what failed to load. */
async function runsAsInNode(url) {
  const page = await browser.newPage();
  const missing = [];
  page.on("response", (r) => {
    if (r.status() >= 400 && !r.url().endsWith("/favicon.ico")) missing.push(`${r.status()} ${r.url()}`);
  });
  try {
    await page.goto(url);
    await page.waitForFunction(() => document.getElementById("out").textContent !== "loading", null, { timeout: 60000 });
    const text = await page.textContent("#out");
    assert.doesNotMatch(text, /^error/, `${text}\n${missing.join("\n")}`);
    const got = JSON.parse(text);
    const log = gd.Log.parse(readFileSync(LOG, "utf8"));
    assert.equal(got.hdr, gd.hdr(log, {}).NE_psi_hdr_deg_per_min);
    assert.equal(got.pipeline, gd.pipeline(log).NE_psi_pipeline_deg_per_min);
    assert.ok(got.plot_width > 300, text);
    const inked = await page.evaluate(() => {
      const c = document.getElementById("chart");
      const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] < 200) n++;
      return n;
    });
    assert.ok(inked > 1000, `the chart has ${inked} inked pixels`);
    assert.deepEqual(missing, []);
  } finally {
    await page.close();
  }
}

test("Vite: the built app runs the three modules and gives the Node package's numbers", async () => {
  await build({ root: app, configFile: false, logLevel: "silent" });
  const server = await preview({ root: app, configFile: false, logLevel: "silent", preview: { host: "127.0.0.1", port: port() } });
  try {
    await runsAsInNode(server.resolvedUrls.local[0]);
  } finally {
    await server.close();
  }
});

test("Vite: the dev server (dependencies pre-bundled) runs the same app", async () => {
  const server = await createServer({ root: app, configFile: false, logLevel: "silent", server: { host: "127.0.0.1", port: port() } });
  await server.listen();
  try {
    await runsAsInNode(server.resolvedUrls.local[0]);
  } finally {
    await server.close();
  }
});

test("webpack 5: the built app runs the three modules and gives the Node package's numbers", async () => {
  const out = join(app, "webpack-dist");
  const stats = await new Promise((resolve, reject) =>
    webpack(
      { mode: "production", context: app, entry: "./main.js", output: { path: out, publicPath: "auto" }, performance: { hints: false } },
      (err, s) => (err ? reject(err) : resolve(s)),
    ),
  );
  assert.ok(!stats.hasErrors(), stats.toString("errors-only"));
  cpSync(join(app, "index.html"), join(out, "index.html"));
  cpSync(LOG, join(out, "city-1.csv"));
  const server = await preview({ root: app, configFile: false, logLevel: "silent", build: { outDir: "webpack-dist" }, preview: { host: "127.0.0.1", port: port() } });
  try {
    await runsAsInNode(server.resolvedUrls.local[0]);
  } finally {
    await server.close();
  }
});
