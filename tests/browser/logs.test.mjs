// Logs in the dashboard: a loaded file shows the CLI's numbers, a bad one its line and
// column while the rest is kept; check badges, gaps, drives without a reference, the log
// list's management, large logs parsed in a Web Worker, names shown as text.
import { test } from "node:test";
import assert from "node:assert/strict";
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { gzipSync } from "node:zlib";
import { join } from "node:path";
import { SAMPLES, cli } from "../node/helpers.mjs";
import { openDashboard, ARTIFACTS, page } from "./harness.mjs";

openDashboard();

test("a loaded log shows the CLI's numbers; a bad one shows line and column and keeps the rest", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-logs-"));
  const good = join(SAMPLES, "test", "rural-3.csv");
  const bad = join(dir, "broken.csv");
  writeFileSync(bad, "time_s,gyro_dps,ref_heading_deg\n0,1,0\n0.1,1.2.3,0\n");
  await page.locator("#file-input").setInputFiles([good]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Rural 3"));
  const native = JSON.parse(cli("hdr", good, "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  assert.equal(await page.locator("#m-improvement").innerText(), native.improvement.toFixed(2));
  const n = await page.locator("#logs li").count();
  await page.locator("#file-input").setInputFiles([bad]);
  await page.waitForSelector("#logs li.bad");
  assert.match(await page.locator("#logs li.bad").innerText(), /broken\.csv: line 3, column gyro_dps: "1\.2\.3" is not a number/);
  assert.equal(await page.locator("#logs li").count(), n + 1);
  assert.match(await page.locator("#logs li.selected").innerText(), /Rural 3/);
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  await page.screenshot({ path: join(ARTIFACTS, "bad-file.png"), fullPage: true });
});

test("an epoch-stamped log reads time since its start and gives the pipeline the log from 0 gives", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-epoch-"));
  const lines = readFileSync(join(SAMPLES, "test", "city-3.csv"), "utf8").split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  const name = lines.findIndex((l) => l.startsWith("# name:"));
  lines[name] = "# name: City Epoch";
  const epoch = join(dir, "city-epoch.csv");
  writeFileSync(epoch, lines.map((l, i) => (i <= h || !l ? l : l.replace(/^[^,]+/, (t) => (Number(t) + 1763892000).toFixed(3)))).join("\n"));
  await page.locator("#file-input").setInputFiles([epoch]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City Epoch"));
  await page.waitForSelector("#m-e-pipeline");
  const native = JSON.parse(cli("pipeline", join(SAMPLES, "test", "city-3.csv"), "--json"));
  assert.equal(await page.locator("#m-e-pipeline").innerText(), native.E_psi_pipeline_deg.toFixed(2));
  const L = await page.evaluate(() => { const l = window.gyrodrift.state.layouts["c-heading"]; return { ...l, x_ticks: Array.from(l.x_ticks) }; });
  assert.equal(L.x_origin, 1763892000);
  assert.ok(L.x_ticks.length > 2 && L.x_ticks.every((t) => t >= 0 && t < 100), `ticks ${L.x_ticks}`);
  assert.match(await page.locator("#c-heading").getAttribute("aria-label"), /time \(min\) 0\.\d+ to \d+\.\d/);
});

test("a log whose time repeats is refused, and put in time order on request, with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-order-"));
  const lines = readFileSync(join(SAMPLES, "test", "rural-3.csv"), "utf8").split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  lines[lines.findIndex((l) => l.startsWith("# name:"))] = "# name: Rural Repeat";
  lines.splice(h + 300, 0, lines[h + 299]);
  const repeat = join(dir, "rural-repeat.csv");
  writeFileSync(repeat, lines.join("\n"));
  await page.locator("#file-input").setInputFiles([repeat]);
  const bad = page.locator("#logs li.bad", { hasText: "rural-repeat.csv" });
  await bad.waitFor();
  assert.match(await bad.innerText(), /line \d+, column time_s: time [\d.]+ repeats/);
  await bad.locator("button.fix-order").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Rural Repeat"));
  assert.equal(await page.locator("#logs li.bad", { hasText: "rural-repeat.csv" }).count(), 0);
  assert.match(await page.locator("#logs li.selected").innerText(), /put in time order/);
  assert.equal(await page.locator("#logs li.selected details.check p").last().textContent(), "1 rows of a repeated time merged");
  const native = JSON.parse(cli("hdr", repeat, "--json", "--time-order", "fix"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  await page.screenshot({ path: join(ARTIFACTS, "time-order.png"), fullPage: false });
  // Taken off again: the later tests count the list's check notes.
  await page.locator("#logs li", { hasText: "Rural Repeat" }).locator("button.remove").click();
  await page.waitForFunction(() => ![...document.querySelectorAll("#logs li")].some((li) => li.innerText.includes("Rural Repeat")));
});

test("a gzip-compressed log (drive.csv.gz) opens as the plain file, with the CLI's numbers; a damaged one is a clear error", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-gz-"));
  const plain = join(SAMPLES, "test", "city-3.csv");
  const gz = join(dir, "city-3.csv.gz");
  writeFileSync(gz, gzipSync(readFileSync(plain)));
  await page.locator("#file-input").setInputFiles([gz]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City 3"));
  const native = JSON.parse(cli("hdr", gz, "--json"));
  assert.deepEqual(native, JSON.parse(cli("hdr", plain, "--json")));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  const cut = join(dir, "cut.csv.gz");
  writeFileSync(cut, gzipSync(readFileSync(plain)).subarray(0, 200));
  await page.locator("#file-input").setInputFiles([cut]);
  await page.waitForFunction(() => [...document.querySelectorAll("#logs li.bad")].some((li) => li.innerText.includes("cut.csv.gz: a damaged or cut gzip file")));
  assert.match(await page.locator("#logs li.selected").innerText(), /City 3/);
  // A dropped folder is a file the page cannot read (its reads fail): said so, not as gzip.
  await page.evaluate(async () => {
    const { loadFiles } = await import("/loading.js");
    const folder = { name: "Drive 2026-11-27", slice: () => ({ arrayBuffer: () => Promise.reject(new DOMException("unreadable", "NotReadableError")) }) };
    await loadFiles([folder]);
  });
  assert.match(await page.locator("#logs li.bad").last().innerText(), /Drive 2026-11-27: cannot be read \(a folder\? drop the files in it, or its \.zip\)/);
  assert.match(await page.locator("#logs li.selected").innerText(), /City 3/);
});

test("a log saved with ';' and decimal commas opens as the comma log, with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-dialect-"));
  const plain = join(SAMPLES, "test", "mixed-2.csv");
  const lines = readFileSync(plain, "utf8").split("\n");
  const file = join(dir, "mixed-2-eu.csv");
  writeFileSync(file, "\ufeff" + lines.map((l) => (l.startsWith("#") ? l : l.replaceAll(",", ";").replaceAll(".", ","))).join("\r\n"));
  await page.locator("#file-input").setInputFiles([file]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Mixed 2"));
  const native = JSON.parse(cli("hdr", file, "--json"));
  assert.deepEqual(native, JSON.parse(cli("hdr", plain, "--json")));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  assert.equal(await page.locator("#m-improvement").innerText(), native.improvement.toFixed(2));
});

test("a log whose last line a logger cut short opens without it, saying so, with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-cut-"));
  const text = readFileSync(join(SAMPLES, "test", "rural-3.csv"), "utf8").replace("# name: Rural 3", "# name: Rural 3 cut");
  const cutAt = text.trimEnd().lastIndexOf("\n");
  const file = join(dir, "rural-3-cut.csv");
  writeFileSync(file, text.slice(0, cutAt + 6));
  await page.locator("#file-input").setInputFiles([file]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Rural 3 cut"));
  const entry = page.locator("#logs li", { hasText: "Rural 3 cut" });
  assert.match(await entry.innerText(), /last line cut short/);
  assert.match(await entry.locator("details.check.split").getAttribute("title"), /its last line, cut short \(2 of 5 cells, no line end\), dropped/);
  const native = JSON.parse(cli("hdr", file, "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  await entry.locator("button.remove").click();
});

test("two logs joined into one file are an error naming the second log's first line, the rest stays; each log read on request", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-joined-"));
  const a = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const b = readFileSync(join(SAMPLES, "train", "city-2.csv"), "utf8");
  const file = join(dir, "joined.csv");
  writeFileSync(file, a + b);
  const before = await page.locator("#logs li:not(.bad)").count();
  await page.locator("#file-input").setInputFiles([file]);
  const bad = page.locator("#logs li.bad", { hasText: "joined.csv" });
  await bad.waitFor();
  const line = a.split("\n").length;
  assert.match(await bad.innerText(), new RegExp(`line ${line}: a '#' line after the rows \\("# name: City 2"\\): a second log joined on\\?`));
  assert.equal(await page.locator("#logs li:not(.bad)").count(), before);
  // Read each: two logs in the error's place, each noted with its first line, City 2 with
  // the CLI's numbers for city-2.csv alone.
  await bad.locator("button.fix-joined").click();
  await page.waitForFunction((n) => document.querySelectorAll("#logs li:not(.bad)").length === n + 2, before);
  assert.equal(await page.locator("#logs li.bad", { hasText: "joined.csv" }).count(), 0);
  const second = page.locator("#logs li", { hasText: `from line ${line} of joined.csv` });
  assert.equal(await second.count(), 1);
  await second.locator("button.pick").click();
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "city-2.csv"), "--json"));
  await page.waitForFunction((v) => document.querySelector("#m-e-hdr")?.innerText === v, native.E_psi_hdr_deg.toFixed(2));
  await page.screenshot({ path: join(ARTIFACTS, "joined.png"), fullPage: false });
  for (const l of [1, line]) await page.locator("#logs li", { hasText: `from line ${l} of joined.csv` }).locator("button.remove").click();
  await page.waitForFunction((n) => document.querySelectorAll("#logs li:not(.bad)").length === n, before);
});

test("a second log that starts with its header row alone, or a logger's clock reset, is named as such and read in parts on request (not put in time order)", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-parts-"));
  const a = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8");
  const b = readFileSync(join(SAMPLES, "train", "city-2.csv"), "utf8").split("\n");
  const line = a.split("\n").length;
  const cases = [
    // A logger that writes no metadata: City 2 with its header row alone.
    ["headers.csv", b.filter((l) => !l.startsWith("#")), `line ${line}: the header row again after the rows .*a second log joined on\\?`, /^headers$/m],
    // Restarted without a new header: City 2's rows go on from time 0, named after City 1.
    ["reset.csv", b.filter((l) => l && !l.startsWith("#") && !l.startsWith("time_s")), `line ${line}, column time_s: time 0 goes back .*a clock reset\\?`, /City 1 \(2\)/],
  ];
  const native = JSON.parse(cli("hdr", join(SAMPLES, "train", "city-2.csv"), "--json"));
  for (const [name, rows, error, named] of cases) {
    writeFileSync(join(dir, name), a + rows.join("\n") + "\n");
    const before = await page.locator("#logs li:not(.bad)").count();
    await page.locator("#file-input").setInputFiles([join(dir, name)]);
    const bad = page.locator("#logs li.bad", { hasText: name });
    await bad.waitFor();
    assert.match(await bad.innerText(), new RegExp(error));
    assert.equal(await bad.locator("button.fix-order").count(), 0, name);
    await bad.locator("button.fix-joined").click();
    await page.waitForFunction((n) => document.querySelectorAll("#logs li:not(.bad)").length === n + 2, before);
    const second = page.locator("#logs li", { hasText: `from line ${line} of ${name}` });
    assert.match(await second.innerText(), named);
    await second.locator("button.pick").click();
    await page.waitForFunction((v) => document.querySelector("#m-e-hdr")?.innerText === v, native.E_psi_hdr_deg.toFixed(2));
    for (const l of [1, line]) await page.locator("#logs li", { hasText: `from line ${l} of ${name}` }).locator("button.remove").click();
    await page.waitForFunction((n) => document.querySelectorAll("#logs li:not(.bad)").length === n, before);
  }
});

test("a log a spreadsheet opened and saved (padded, quoted, Windows-1252) opens as the log, with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-excel-"));
  const text = readFileSync(join(SAMPLES, "test", "highway-3.csv"), "utf8").replace("# name: Highway 3", "# name: Highway 3 from Excel");
  // Excel in a comma locale: metadata padded to the header's width, the one with a comma
  // quoted; and the same with padding alone (which the page's module refuses first).
  const padded = (quote) => text.split("\n").map((l) => (l.startsWith("#") ? (quote && l.includes(",") ? `"${l}",,,,` : `${l},,,,`) : l)).join("\r\n");
  // And saved on Windows: Windows-1252, with a "ü" in its name.
  const latin = (s) => Buffer.from(s.replace("from Excel", "from Excel für"), "latin1");
  for (const [name, bytes] of [["highway-3-excel.csv", padded(true)], ["highway-3-padded.csv", padded(false)], ["highway-3-1252.csv", latin(padded(false))]]) {
    const file = join(dir, name);
    writeFileSync(file, bytes);
    await page.locator("#file-input").setInputFiles([file]);
    await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Highway 3 from Excel"));
    const native = JSON.parse(cli("hdr", file, "--json"));
    assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2), name);
    if (name.includes("1252")) assert.match(await page.locator("#logs li.selected").innerText(), /Highway 3 from Excel für/);
    await page.locator("#logs li.selected button.remove").click();
  }
});

test("a log with a clockwise gyro gets a check badge naming the fix; the shipped ones none", async () => {
  assert.equal(await page.locator("#logs li .check.error, #logs li .check.warning").count(), 0);
  // Information is no badge: City 1's CRS03-like gyro warms between its standings, told muted.
  const drift = page.locator("#logs li", { hasText: "City 1" }).locator(".check.info");
  assert.match(await drift.innerText(), /bias drift/);
  assert.match(await drift.getAttribute("title"), /the gyro's bias moves while driving: it reads 1\.95 deg\/s standing at 2 s/);
  const dir = mkdtempSync(join(tmpdir(), "gd-cw-"));
  const cw = join(dir, "city-cw.csv");
  const lines = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  const g = lines[h].split(",").indexOf("gyro_dps");
  const name = lines.findIndex((l) => l.startsWith("# name:"));
  if (name >= 0) lines[name] = "# name: City CW";
  writeFileSync(cw, lines.map((l, i) => (i <= h || !l ? l : l.split(",").map((c, j) => (j === g ? String(-Number(c)) : c)).join(","))).join("\n"));
  await page.locator("#file-input").setInputFiles([cw]);
  await page.waitForSelector("#logs li .check.error");
  const badge = page.locator("#logs li .check.error");
  assert.match(await badge.innerText(), /gyro_sign/);
  assert.match(await badge.getAttribute("title"), /positive = "cw"/);
  // What it says and its fix open under it at a click or a tap (a tooltip shows nothing on a
  // phone), and close again.
  const said = badge.locator("p").first();
  assert.equal(await said.isVisible(), false);
  await badge.locator("summary").click();
  assert.equal(await said.isVisible(), true);
  assert.match(await said.innerText(), /turn opposite ways.*fix: .*positive = "cw"/);
  await page.screenshot({ path: join(ARTIFACTS, "check-badge.png") });
  await badge.locator("summary").click();
  assert.equal(await said.isVisible(), false);
  // Above the view too, while it plots that log: its figures are not to be trusted.
  const banner = page.locator("#view-check");
  assert.equal(await banner.isVisible(), true);
  assert.match(await banner.innerText(), /City CW: check found an error[\s\S]*opposite ways[\s\S]*fix: heading\.positive or yaw_rate\.positive = "cw"/);
  await page.locator("#logs li", { hasText: "City 1" }).first().locator("button.pick").click();
  assert.equal(await banner.isVisible(), false);
  await page.locator("#logs li", { hasText: "City CW" }).locator("button.pick").click();
  assert.equal(await banner.isVisible(), true);
  // Its fix, filled in the column mapper: the preview, then a log of its own with City 1's
  // numbers and no check error.
  const e1 = await page.locator("#logs li", { hasText: "City 1" }).first().locator("button.pick").click().then(() => page.locator("#m-e-hdr").innerText());
  await page.locator("#logs li", { hasText: "City CW" }).locator("button.pick").click();
  await page.locator("#check-remap").click();
  await page.locator("#mapping[open]").waitFor();
  assert.equal(await page.locator("#map-rate-sense").inputValue(), "cw");
  assert.match(await page.locator("#mapping-intro").innerText(), /if the reference is a GPS course.*reference's sign to clockwise instead/);
  assert.equal(await page.locator("#map-lead").inputValue(), "20");
  await page.waitForFunction(() => !document.getElementById("mapping-add").disabled);
  await page.screenshot({ path: join(ARTIFACTS, "check-remap.png") });
  await page.locator("#mapping-add").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City CW (fixed)"));
  assert.equal(await banner.isVisible(), false);
  assert.equal(await page.locator("#logs li", { hasText: "City CW (fixed)" }).locator(".check.error").count(), 0);
  assert.equal(await page.locator("#m-e-hdr").innerText(), e1);
  await page.locator("#logs li", { hasText: "City CW (fixed)" }).locator("button.remove").click();
  await page.locator("#logs li", { hasText: "City CW" }).locator("button.pick").click();
  // The Report leaves it out of its tables and means, as the CLI's report refuses it.
  await page.locator("#tabs button[data-view=report]").click();
  await page.locator("#compare-table table").waitFor();
  assert.equal(await page.locator("#compare-table tr[data-drive='City CW']").count(), 0);
  assert.ok((await page.locator("#compare-table tr[data-drive='City 1']").count()) > 0);
  assert.match(await page.locator("#report-unscored").innerText(), /Left out \(check found an error.*\): City CW\./);
  assert.equal(await banner.isVisible(), false);
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "City CW" }).locator("button.remove").click();
  // Time in microseconds; a gyro in rad/s and clockwise (two errors, each with its fix):
  // check names them, the mapper opens with every fix filled in, and the fixed log scores as
  // City 1.
  const rad = (c) => String((-Number(c) * Math.PI) / 180);
  const mistakes = [
    ["City us", 0, (c) => String(Math.round(Number(c) * 1e6)), /microseconds, not seconds.*time\.unit = "us"/, { "map-time-unit-0": "us" }],
    ["City rad cw", g, rad, /gyro_unit, gyro_sign[\s\S]*the gyro is in rad\/s[\s\S]*opposite ways/, { "map-rate-unit": "rad/s", "map-rate-sense": "cw" }],
  ];
  for (const [n, col, f, said, filled] of mistakes) {
    const file = join(dir, `${n.replaceAll(" ", "-")}.csv`);
    writeFileSync(file, lines.map((l, i) => (l.startsWith("# name:") ? `# name: ${n}` : i <= h || !l ? l : l.split(",").map((c, j) => (j === col ? f(c) : c)).join(","))).join("\n"));
    await page.locator("#file-input").setInputFiles([file]);
    const nBadge = page.locator("#logs li", { hasText: n }).locator(".check.error");
    await nBadge.waitFor();
    assert.match(`${await nBadge.innerText()} ${await nBadge.getAttribute("title")}`, said);
    await page.locator("#check-remap").click();
    await page.locator("#mapping[open]").waitFor();
    for (const [id, want] of Object.entries(filled)) assert.equal(await page.locator(`#${id}`).inputValue(), want, `${n}: ${id}`);
    await page.waitForFunction(() => !document.getElementById("mapping-add").disabled);
    await page.locator("#mapping-add").click();
    await page.waitForFunction((x) => document.querySelector("#logs li.selected")?.innerText.includes(`${x} (fixed)`), n);
    assert.equal(await page.locator("#m-e-hdr").innerText(), e1, n);
    for (const x of [`${n} (fixed)`, n]) await page.locator("#logs li", { hasText: x }).first().locator("button.remove").click();
  }
  // Information (`check`'s info findings) gets a quiet note of its own: City 1 without its
  // speed column and its lead-in, at 1 Hz (too sparse for the gyro's own white-noise test
  // of standing, which needs 5 rows a second), has nothing that shows when it stands.
  const bare = join(dir, "city-bare.csv");
  const v = lines[h].split(",").indexOf("speed_mps");
  const rows = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").split("\n");
  writeFileSync(
    bare,
    rows
      .filter((l, i) => i <= h || !l || (i - h - 1) % 10 === 0)
      .map((l, i) => (l.startsWith("# name:") ? "# name: City bare" : l.startsWith("# bias_s:") ? "# bias_s: 0" : i < h || !l ? l : l.split(",").filter((_, j) => j !== v).join(",")))
      .join("\n"),
  );
  await page.locator("#file-input").setInputFiles([bare]);
  const info = page.locator("#logs li", { hasText: "City bare" }).locator(".check.info");
  await info.waitFor();
  assert.match(await info.innerText(), /no stops/);
  assert.match(await info.getAttribute("title"), /a speed column, or # bias_s: N/);
  assert.equal(await page.locator("#logs li", { hasText: "City bare" }).locator(".check.warning, .check.error").count(), 0);
  await page.locator("#logs li", { hasText: "City bare" }).locator("button.remove").click();
});

test("a log with a 60 s gap becomes two drives, each marked as split, with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-gap-"));
  const file = join(dir, "city-gap.csv");
  const lines = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").split("\n");
  const name = lines.findIndex((l) => l.startsWith("# name:"));
  lines[name] = "# name: City gap";
  writeFileSync(file, lines.filter((l) => !(l && !l.startsWith("#") && Number(l.split(",")[0]) >= 300 && Number(l.split(",")[0]) < 360)).join("\n"));
  await page.locator("#file-input").setInputFiles([file]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City gap (part 1 of 2)"));
  assert.equal(await page.locator("#logs li", { hasText: "City gap (part" }).count(), 2);
  assert.match(await page.locator("#logs li", { hasText: "City gap (part 2 of 2)" }).locator(".check.split").getAttribute("title"), /60\.1 s at line/);
  const native = JSON.parse(cli("hdr", file, "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native[0].E_psi_hdr_deg.toFixed(2));
});

test("a drive without a reference heading is shown, not scored: the HDR view says so, the Report skips it", async () => {
  // City 1 with its GPS course dropped: speed and gyro only, a drive with no reference.
  const dir = mkdtempSync(join(tmpdir(), "gd-noref-"));
  const file = join(dir, "city-no-gps.csv");
  const lines = readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").split("\n");
  const h = lines.findIndex((l) => l.startsWith("time_s"));
  const r = lines[h].split(",").indexOf("ref_heading_deg");
  writeFileSync(file, lines.map((l, i) => (l.startsWith("# name:") ? "# name: City no GPS" : i < h || !l ? l : l.split(",").filter((_, j) => j !== r).join(","))).join("\n"));
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#file-input").setInputFiles([file]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City no GPS"));
  const item = page.locator("#logs li", { hasText: "City no GPS" });
  assert.match(await item.innerText(), /drive · 19\.4 min · no reference: not scored/);
  await page.waitForSelector("#m-bias-pipeline");
  assert.match(await page.locator("#m-unscored").innerText(), /Not scored: missing column ref_heading_deg/);
  // The pipeline's final bias is the CLI's, which runs the drive unscored too (exit 0).
  const native = JSON.parse(cli("pipeline", file, "--json"));
  assert.match(native.not_scored, /ref_heading_deg/);
  assert.equal(await page.locator("#m-bias-pipeline").innerText(), native.final_bias_dps.toFixed(4));
  // No error to draw: the chart is hidden, not the last drive's left standing.
  assert.equal(await page.locator("#c-error").isVisible(), false);
  assert.equal(await page.locator("#c-heading").isVisible(), true);
  await page.screenshot({ path: join(ARTIFACTS, "no-reference.png"), fullPage: true });
  // The Report scores the other drives and names the one it cannot.
  await page.locator("#tabs button[data-view=report]").click();
  await page.waitForSelector("#report-table table");
  assert.match(await page.locator("#report-unscored").innerText(), /Not scored \(no reference heading\): City no GPS\./);
  assert.equal(await page.locator("#report-table tr", { hasText: "City no GPS" }).count(), 0);
  assert.ok((await page.locator("#report-table tr", { hasText: "City 1" }).count()) > 0);
  await item.locator("button.remove").click();
  assert.equal(await page.locator("#report-unscored").isVisible(), false);
  // The column there but with no value in it is no reference either (core's rule, as the CLI).
  const blank = join(dir, "city-blank-gps.csv");
  writeFileSync(blank, lines.map((l, i) => (l.startsWith("# name:") ? "# name: City blank GPS" : i <= h || !l ? l : l.split(",").map((c, j) => (j === r ? "" : c)).join(","))).join("\n"));
  await page.locator("#file-input").setInputFiles([blank]);
  const blankItem = page.locator("#logs li", { hasText: "City blank GPS" });
  await blankItem.waitFor();
  assert.match(await blankItem.innerText(), /drive · 19\.4 min · no reference: not scored/);
  await page.waitForSelector("#report-table table");
  assert.match(await page.locator("#report-unscored").innerText(), /Not scored \(no reference heading\): City blank GPS\./);
  assert.match(JSON.parse(cli("pipeline", blank, "--json")).not_scored, /ref_heading_deg column is empty/);
  await blankItem.locator("button.remove").click();
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.waitForSelector("#m-e-hdr");
  assert.equal(await page.locator("#c-error").isVisible(), true);
});

test("log management: same name made unique, the same file re-opened, a log removed, an error dismissed", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-manage-"));
  const copy = join(dir, "rural-copy.csv");
  writeFileSync(copy, readFileSync(join(SAMPLES, "test", "rural-3.csv")));
  const before = await page.locator("#logs li").count();
  await page.locator("#file-input").setInputFiles([copy]);
  await page.locator("#file-input").setInputFiles([copy]); // the same file again: loads again
  await page.waitForFunction((n) => document.querySelectorAll("#logs li").length === n + 2, before);
  const names = await page.locator("#logs li b").allInnerTexts();
  const copies = names.filter((n) => n.startsWith("Rural 3"));
  assert.equal(new Set(copies).size, copies.length, `unique names: ${names.join(" | ")}`);
  assert.ok(copies.length >= 2, names.join(" | "));
  const last = copies[copies.length - 1];
  await page.getByRole("button", { name: `Remove ${last}`, exact: true }).click();
  await page.waitForFunction((n) => document.querySelectorAll("#logs li").length === n + 1, before);
  assert.ok(!(await page.locator("#logs li b").allInnerTexts()).includes(last));
  await page.getByRole("button", { name: `Remove ${copies[copies.length - 2]}`, exact: true }).click();
  const bad = join(dir, "broken2.csv");
  writeFileSync(bad, "time_s,gyro_dps\n0,x\n");
  await page.locator("#file-input").setInputFiles([bad]);
  await page.waitForSelector("#logs li.bad");
  await page.locator("#logs li.bad button.remove").last().click();
  await page.waitForFunction(() => ![...document.querySelectorAll("#logs li.bad")].some((li) => li.innerText.includes("broken2")));
});

test("the list highlights the log each view plots", async () => {
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=gyrodometry]").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Robot straight"));
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("City 1"));
});

test("a large log is parsed in a Web Worker, handed to the page in chunks, and gives the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-big-"));
  const big = join(dir, "long-drive.csv");
  cli("simulate", "drive", "--scenario", "mixed", "--minutes", "450", "--seed", "77", "--name", "Long drive", "--out", big);
  await page.locator("#file-input").setInputFiles([big]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Long drive"), null, { timeout: 60000 });
  // 270 000 rows: more than one chunk (CHUNK_ROWS in web/loading.js) crosses to the page.
  assert.ok(await page.evaluate(() => window.gyrodrift.state.entries.find((e) => e.name === "Long drive").log.toColumns().columns.time_s.length > 250000));
  const native = JSON.parse(cli("hdr", big, "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  assert.equal(await page.locator("#progress").isVisible(), false);
  // Its pipeline and its Track paths are computed in the worker (the page does not pause)
  // and equal the CLI's and the page module's own.
  assert.ok(await page.evaluate(() => window.gyrodrift.state.entries.find((e) => e.name === "Long drive").workerKey != null));
  await page.waitForSelector("#m-e-pipeline", { timeout: 60000 });
  const pipe = JSON.parse(cli("pipeline", big, "--json"));
  assert.equal(await page.locator("#m-e-pipeline").innerText(), pipe.E_psi_pipeline_deg.toFixed(2));
  await page.locator("#tabs button[data-view=track]").click();
  await page.waitForFunction(() => !document.getElementById("track-busy").textContent && window.gyrodrift.state.specs["c-track"]?.title.startsWith("Long drive"), null, { timeout: 60000 });
  const same = await page.evaluate(() => {
    const { gd, state } = window.gyrodrift;
    const e = state.entries.find((x) => x.name === "Long drive");
    const here = gd.track(e.log, { resample: state.resample, ...state.params });
    const pipe = gd.pipelineTrack(e.log, { bias_s: state.params.bias_s ?? null });
    const equal = (name, p) => {
      const drawn = state.specs["c-track"].series.find((s) => s.name === name);
      return drawn.x.length === p.x_m.length && drawn.x.every((v, i) => v === p.x_m[i]) && drawn.y.every((v, i) => v === p.y_m[i]);
    };
    return [equal("HDR", here.hdr), equal("pipeline (recommended)", pipe.pipeline), equal("smoothed (offline)", pipe.smoothed)];
  });
  assert.deepEqual(same, [true, true, true], "the worker's HDR and pipeline paths are the page module's");
  await page.locator("#tabs button[data-view=hdr]").click();
});

test("a log's name is text everywhere, never markup (list, overlay row, tooltip)", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-name-"));
  const evil = '<img src=x onerror="window.__xss=1">';
  const file = join(dir, "evil.csv");
  writeFileSync(file, readFileSync(join(SAMPLES, "train", "city-1.csv"), "utf8").replace(/^# name: .*$/m, `# name: ${evil}`));
  await page.locator("#file-input").setInputFiles([file]);
  await page.waitForFunction((n) => window.gyrodrift.state.entries.some((e) => e.name === n), evil);
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: evil }).locator("button.overlay").click();
  await page.waitForSelector("#overlay-metrics .overlay-row");
  assert.match(await page.locator("#overlay-metrics").innerText(), /<img src=x onerror/);
  await page.locator("#c-error").scrollIntoViewIfNeeded();
  const box = await page.locator("#c-error").boundingBox();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.5);
  await page.locator("#c-error ~ .tip").waitFor({ state: "visible" });
  assert.match(await page.locator("#c-error ~ .tip").innerText(), /<img src=x onerror=.*: HDR/);
  await page.locator("#logs li", { hasText: evil }).locator("button.overlay").click();
  await page.locator("#logs li", { hasText: evil }).locator("button.pick").click();
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.__xss), undefined);
  assert.equal(await page.locator("#view-hdr img, #view-allan img, #logs img, #overlay-metrics img").count(), 0);
  await page.locator("#logs li", { hasText: evil }).locator("button.remove").click();
  await page.locator("#tabs button[data-view=hdr]").click();
  await page.locator("#logs li", { hasText: "City 1" }).locator("button.pick").click();
});
