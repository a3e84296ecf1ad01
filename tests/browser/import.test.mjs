// Raw logger exports in the dashboard: presets, recipes saved and dropped, the mapping
// panel for files no preset fits, large exports in the Web Worker; each with the CLI's numbers.
import { test } from "node:test";
import assert from "node:assert/strict";
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { execFileSync } from "node:child_process";
import { join } from "node:path";
import { ROOT, cli } from "../node/helpers.mjs";
import { openDashboard, ARTIFACTS, page } from "./harness.mjs";

openDashboard();

const WILD = join(ROOT, "sample-logs", "wild");

const wildFiles = (d) => readdirSync(join(WILD, d)).sort().map((f) => join(WILD, d, f));

/** The CLI's HDR result on the same raw files, imported by the detected preset. */
function cliOnRaw(files) {
  const out = join(mkdtempSync(join(tmpdir(), "gd-raw-")), "imported.csv");
  cli("import", ...files, "--out", out);
  return JSON.parse(cli("hdr", out, "--json"));
}

for (const [dir, name] of [["sensorlog", "SensorLog.csv (SensorLog)"], ["sensor-logger", "Gyroscope.csv (Sensor Logger)"], ["phyphox", "Gyroscope.csv (phyphox, CSV export)"]]) {
  test(`a ${dir} export opens by drop alone (detected preset) with the CLI's numbers`, async () => {
    const files = wildFiles(dir);
    await page.locator("#file-input").setInputFiles(files);
    await page.waitForFunction((n) => document.querySelector("#logs li.selected")?.innerText.includes(n), name);
    const li = page.locator("#logs li.selected");
    assert.match(await li.innerText(), /imported:/);
    const native = cliOnRaw(files);
    assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
    assert.equal(await page.locator("#m-improvement").innerText(), native.improvement.toFixed(2));
  });
}

test("a zipped export (as Sensor Logger shares one) opens by drop alone with the CLI's numbers", async () => {
  const zip = join(mkdtempSync(join(tmpdir(), "gd-zip-")), "Drive 2026-11-27.zip");
  const script = "import sys, os, zipfile\nz = zipfile.ZipFile(sys.argv[1], 'w', zipfile.ZIP_DEFLATED)\nfor f in sys.argv[2:]: z.write(f, 'Drive/' + os.path.basename(f))";
  execFileSync("python3", ["-c", script, zip, ...wildFiles("sensor-logger")]);
  const before = await page.locator("#logs li").count();
  await page.locator("#file-input").setInputFiles([zip]);
  await page.waitForFunction((n) => document.querySelectorAll("#logs li").length > n, before);
  const li = page.locator("#logs li.selected");
  assert.match(await li.innerText(), /Drive 2026-11-27[\s\S]*imported:/);
  const native = cliOnRaw([zip]);
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
});

test("a dropped folder (an unzipped export) opens as its files do, hidden files left out", async () => {
  const files = wildFiles("sensor-logger");
  const contents = files.map((f) => [f.split("/").pop(), readFileSync(f, "utf8")]);
  const before = await page.locator("#logs li").count();
  // A folder entry as the browser hands one over (webkitGetAsEntry), with a .DS_Store.
  await page.evaluate(async (contents) => {
    const { filesOf, loadFiles } = await import("/loading.js");
    const fileEntry = (name, body) => ({ name, isFile: true, isDirectory: false, file: (ok) => ok(new File([body], name)) });
    const children = [...contents.map(([n, body]) => fileEntry(n, body)), fileEntry(".DS_Store", "\u0000\u0001binary")];
    const batches = [children.slice(0, 2), children.slice(2), []];
    const folder = { name: "Drive", isFile: false, isDirectory: true, createReader: () => ({ readEntries: (ok) => ok(batches.shift()) }) };
    await loadFiles(await filesOf([folder]));
  }, contents);
  await page.waitForFunction((n) => document.querySelectorAll("#logs li").length > n, before);
  assert.match(await page.locator("#logs li.selected").innerText(), /Gyroscope\.csv \(Sensor Logger\)[\s\S]*imported:/);
  assert.equal(await page.locator("#m-e-hdr").innerText(), cliOnRaw(files).E_psi_hdr_deg.toFixed(2));
});

test("the import recipe saves as TOML and, dropped with the files, imports the same log; no fit is a clear error", async () => {
  const files = wildFiles("px4");
  await page.locator("#file-input").setInputFiles(files);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("PX4"));
  const e1 = await page.locator("#m-e-hdr").innerText();
  const [dl] = await Promise.all([page.waitForEvent("download"), page.locator("#logs li.selected button.link").click()]);
  assert.match(dl.suggestedFilename(), /\.recipe\.toml$/);
  const recipe = join(mkdtempSync(join(tmpdir(), "gd-recipe-")), "px4.toml");
  await dl.saveAs(recipe);
  assert.match(readFileSync(recipe, "utf8"), /\[yaw_rate\][\s\S]*table = "imu"/);
  const n = await page.locator("#logs li").count();
  await page.locator("#file-input").setInputFiles([...files, recipe]);
  await page.waitForFunction((k) => document.querySelectorAll("#logs li").length === k + 1, n);
  assert.match(await page.locator("#logs li.selected").innerText(), /your recipe/);
  assert.equal(await page.locator("#m-e-hdr").innerText(), e1);
  await page.screenshot({ path: join(ARTIFACTS, "imported.png") });
  const odd = join(mkdtempSync(join(tmpdir(), "gd-odd-")), "Gyroscope.csv");
  writeFileSync(odd, "time,seconds_elapsed,x,y\n0,0,1,2\n");
  await page.locator("#file-input").setInputFiles([odd]);
  // No preset fits: the mapping panel says why; cancelled, the why stays as an error entry.
  await page.waitForSelector("#mapping[open]");
  assert.match(await page.locator("#mapping-why").innerText(), /closest preset is sensor-logger/);
  await page.locator("#mapping-cancel").click();
  await page.waitForFunction(() => [...document.querySelectorAll("#logs li.bad")].some((l) => l.innerText.includes("closest preset")));
  assert.match(await page.locator("#logs li.bad").last().innerText(), /Gyroscope\.csv: closest preset is sensor-logger .* lacks the column z/);
  assert.equal(await page.locator("#logs li:not(.bad)").count() >= n, true);
});

test("files no preset fits open the mapping panel: guessed columns, live preview, added with the CLI's numbers, recipe saved", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-map-"));
  // A logger of our own: ms time, rate in deg/s, course clockwise, speed in km/h, ';' and decimal commas.
  const v1 = join(dir, "drive.csv");
  cli("simulate", "drive", "--scenario", "city", "--minutes", "4", "--seed", "5", "--out", v1);
  const lines = readFileSync(v1, "utf8").split("\n").filter((l) => l && !l.startsWith("#"));
  const head = lines[0].split(",");
  const col = (name) => head.indexOf(name);
  const out = ["stamp_ms;yaw_rate_dps;course;v_kmh"];
  for (const l of lines.slice(1)) {
    const f = l.split(",");
    const ref = f[col("ref_heading_deg")];
    const course = ref === "" ? "" : String(-Number(ref)).replace(".", ",");
    out.push([String(Math.round(Number(f[col("time_s")]) * 1000)), f[col("gyro_dps")].replace(".", ","), course, String(Number(f[col("speed_mps")]) * 3.6).replace(".", ",")].join(";"));
  }
  const mine = join(dir, "my-logger.csv");
  writeFileSync(mine, out.join("\n") + "\n");
  await page.locator("#file-input").setInputFiles([mine]);
  await page.waitForSelector("#mapping[open]");
  // The guesses: time stamp_ms in ms, the rate in deg/s, the course clockwise, km/h.
  assert.equal(await page.locator("#map-time-0").inputValue(), "stamp_ms");
  assert.equal(await page.locator("#map-time-unit-0").inputValue(), "ms");
  assert.equal(await page.locator("#map-rate").inputValue(), "0:yaw_rate_dps");
  assert.equal(await page.locator("#map-rate-unit").inputValue(), "deg/s");
  assert.equal(await page.locator("#map-ref").inputValue(), "0:course");
  assert.equal(await page.locator("#map-speed-unit").inputValue(), "km/h");
  await page.waitForFunction(() => /reference headings, 4\.0 min/.test(document.getElementById("mapping-preview").textContent));
  // A wrong choice shows its error in place; putting it back restores the preview.
  await page.locator("#map-time-unit-0").selectOption("iso8601");
  await page.waitForFunction(() => document.getElementById("mapping-preview").classList.contains("bad"));
  assert.match(await page.locator("#mapping-preview").innerText(), /line 2, column stamp_ms: .* not an ISO 8601 time/);
  assert.equal(await page.locator("#mapping-add").isDisabled(), true);
  // The time-of-day format is offered too, and refuses a number the same way.
  await page.locator("#map-time-unit-0").selectOption("time_of_day");
  await page.waitForFunction(() => /not a time of day/.test(document.getElementById("mapping-preview").textContent));
  await page.locator("#map-time-unit-0").selectOption("ms");
  await page.waitForFunction(() => /4\.0 min/.test(document.getElementById("mapping-preview").textContent));
  await page.locator("#map-lead").fill("20");
  await page.waitForFunction(() => /4\.0 min/.test(document.getElementById("mapping-preview").textContent) && !document.getElementById("mapping-add").disabled);
  // The preview is drawn at the size shown, in device pixels.
  assert.ok(await page.evaluate(() => {
    const c = document.getElementById("mapping-plot");
    return c.width === Math.round(c.clientWidth * devicePixelRatio) && c.height === Math.round(c.clientHeight * devicePixelRatio);
  }));
  await page.screenshot({ path: join(ARTIFACTS, "mapping.png") });
  const [dl] = await Promise.all([page.waitForEvent("download"), page.locator("#mapping-save").click()]);
  const recipe = join(dir, "mine.toml");
  await dl.saveAs(recipe);
  await page.locator("#mapping-add").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("my-logger.csv (mapped)"));
  assert.match(await page.locator("#logs li.selected").innerText(), /imported: your column mapping/);
  const imported = join(dir, "imported.csv");
  cli("import", "--recipe", recipe, "--data", dir, "--out", imported);
  const native = JSON.parse(cli("hdr", imported, "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  // Close to the simulated log itself (ms time, negated course and km/h undone; the course
  // gated below 18 km/h = 5 m/s): a wrong unit or sign would be tens of degrees off.
  const orig = JSON.parse(cli("hdr", v1, "--json"));
  assert.ok(Math.abs(native.E_psi_hdr_deg - orig.E_psi_hdr_deg) < 0.5, `${native.E_psi_hdr_deg} vs ${orig.E_psi_hdr_deg}`);
  // Cancel keeps the detection's error entry.
  await page.locator("#file-input").setInputFiles([mine]);
  await page.waitForSelector("#mapping[open]");
  await page.locator("#mapping-cancel").click();
  await page.waitForFunction(() => [...document.querySelectorAll("#logs li.bad")].some((l) => l.innerText.includes("my-logger.csv: no logger preset")));
  // The first choices are core's reading of the columns (columnGuesses), which reads the
  // first row too: a time column named "time" holding ISO 8601 is chosen as such, where the
  // names alone say seconds. Two files: each column found in its own file (core lists the
  // files in name order, the panel in the order dropped), three axes, positions, knots.
  const imu = join(dir, "z-imu.csv");
  writeFileSync(imu, "time,gyro_x,gyro_y,gyro_z,acc_x,acc_y,acc_z\n2026-11-27T10:00:00.0Z,0,0,0.01,0,0,9.8\n2026-11-27T10:00:00.1Z,0,0,0.02,0,0,9.8\n");
  const gps = join(dir, "a-gps.csv");
  writeFileSync(gps, "utc,lat,lon,speed_kn\n2026-11-27T10:00:00Z,42,11,10\n");
  await page.locator("#file-input").setInputFiles([imu, gps]);
  await page.waitForSelector("#mapping[open]");
  const z = (await page.locator("#map-time-0").getAttribute("aria-label")).includes("z-imu.csv") ? 0 : 1;
  const a = 1 - z;
  assert.equal(await page.locator(`#map-time-${z}`).inputValue(), "time");
  assert.equal(await page.locator(`#map-time-unit-${z}`).inputValue(), "iso8601");
  assert.equal(await page.locator(`#map-time-${a}`).inputValue(), "utc");
  assert.equal(await page.locator(`#map-time-unit-${a}`).inputValue(), "iso8601");
  assert.equal(await page.locator("#map-rate").inputValue(), `${z}:gyro_z`);
  assert.equal(await page.locator("#map-rate-unit").inputValue(), "rad/s");
  assert.equal(await page.locator("#map-rate-mode").inputValue(), "three"); // right in any mounting
  assert.deepEqual(await Promise.all(["#map-axis-x", "#map-acc-z"].map((id) => page.locator(id).inputValue())), [`${z}:gyro_x`, `${z}:acc_z`]);
  assert.equal(await page.locator("#map-ref-mode").inputValue(), "positions");
  assert.deepEqual(await Promise.all(["#map-lat", "#map-lon"].map((id) => page.locator(id).inputValue())), [`${a}:lat`, `${a}:lon`]);
  assert.equal(await page.locator("#map-speed").inputValue(), `${a}:speed_kn`);
  assert.equal(await page.locator("#map-speed-unit").inputValue(), "kn");
  // A unit follows the column chosen, as core reads that column's name.
  await page.locator("#map-speed").selectOption(`${z}:gyro_x`);
  assert.equal(await page.locator("#map-speed-unit").inputValue(), "m/s");
  await page.locator(`#map-time-${z}`).selectOption("gyro_y");
  assert.equal(await page.locator(`#map-time-unit-${z}`).inputValue(), "s");
  await page.locator("#mapping-cancel").click();
});

test("a gyro CSV beside an NMEA log maps with the GPS log as the reference, as core's draft reads it, with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-nmea-"));
  const v1 = join(dir, "drive.csv");
  cli("simulate", "drive", "--scenario", "city", "--minutes", "4", "--seed", "5", "--out", v1);
  const lines = readFileSync(v1, "utf8").split("\n").filter((l) => l && !l.startsWith("#"));
  const head = lines[0].split(",");
  const col = (name) => head.indexOf(name);
  // The gyro stamped with the time of day from 12:00:00, one $GPRMC per reference sample.
  const clock = (t) => {
    const s = 12 * 3600 + t;
    const hh = String(Math.floor(s / 3600)).padStart(2, "0");
    const mm = String(Math.floor((s % 3600) / 60)).padStart(2, "0");
    return [hh, mm, (s % 60).toFixed(2).padStart(5, "0")];
  };
  const gyro = ["clock,yaw_rate_dps"];
  const nmea = [];
  for (const l of lines.slice(1)) {
    const f = l.split(",");
    const [hh, mm, ss] = clock(Number(f[col("time_s")]));
    gyro.push(`${hh}:${mm}:${ss},${f[col("gyro_dps")]}`);
    const ref = f[col("ref_heading_deg")];
    if (ref !== "") nmea.push(`$GPRMC,${hh}${mm}${ss},A,4220.2340,N,07105.3704,W,${(Number(f[col("speed_mps")]) * 3600 / 1852).toFixed(3)},${((-Number(ref) % 360) + 360) % 360},241126,,,A*00`);
  }
  const [g, n] = [join(dir, "gyro.csv"), join(dir, "gps.nmea")];
  writeFileSync(g, gyro.join("\n") + "\n");
  writeFileSync(n, nmea.join("\n") + "\n");
  await page.locator("#file-input").setInputFiles([g, n]);
  await page.waitForSelector("#mapping[open]");
  assert.equal(await page.locator("#map-ref-mode").inputValue(), "track");
  assert.match(await page.locator("#map-ref-mode option:checked").innerText(), /the GPS log gps\.nmea/);
  // The GPS log's first sentence is not offered as columns.
  assert.ok(!(await page.locator("#map-rate option").allInnerTexts()).some((t) => t.includes("gps.nmea")));
  await page.locator("#map-lead").fill("20");
  await page.waitForFunction(() => /[1-9]\d* reference headings, 4\.0 min/.test(document.getElementById("mapping-preview").textContent) && !document.getElementById("mapping-add").disabled);
  const [dl] = await Promise.all([page.waitForEvent("download"), page.locator("#mapping-save").click()]);
  const recipe = join(dir, "mine.toml");
  await dl.saveAs(recipe);
  await page.locator("#mapping-add").click();
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("gyro.csv (mapped)"));
  const imported = join(dir, "imported.csv");
  cli("import", "--recipe", recipe, "--data", dir, "--out", imported);
  const native = JSON.parse(cli("hdr", imported, "--json"));
  assert.equal(await page.locator("#m-e-hdr").innerText(), native.E_psi_hdr_deg.toFixed(2));
  // Close to the simulated log itself: a wrong course sign or clock would be far off.
  const orig = JSON.parse(cli("hdr", v1, "--json"));
  assert.ok(Math.abs(native.E_psi_hdr_deg - orig.E_psi_hdr_deg) < 1, `${native.E_psi_hdr_deg} vs ${orig.E_psi_hdr_deg}`);
});

test("a large raw export is imported in the Web Worker with the CLI's numbers", async () => {
  const dir = mkdtempSync(join(tmpdir(), "gd-bigraw-"));
  // Sensor Logger's layout: 20 min of a 100 Hz gyro with a 0.2 deg/s bias and a slow turn.
  const rows = ["time,seconds_elapsed,z,y,x"];
  for (let i = 0; i < 120000; i++) {
    const t = i / 100;
    const w = ((0.2 + (t > 600 && t < 690 ? 1 : 0)) * Math.PI) / 180;
    rows.push(`${1763892000000000000 + i * 10000000},${t.toFixed(2)},${w.toFixed(7)},0.0001,-0.0002`);
  }
  const gyro = join(dir, "Gyroscope.csv");
  writeFileSync(gyro, rows.join("\n") + "\n");
  await page.locator("#file-input").setInputFiles([gyro]);
  await page.waitForFunction(() => document.querySelector("#logs li.selected")?.innerText.includes("Gyroscope.csv (Sensor Logger)"), null, { timeout: 60000 });
  assert.equal(await page.locator("#progress").isVisible(), false);
  const out = join(dir, "imported.csv");
  cli("import", gyro, "--out", out);
  const native = JSON.parse(cli("allan", out, "--json"));
  const text = await page.locator("#logs li.selected").innerText();
  assert.match(text, /static · 20\.0 min/);
  assert.ok(text.includes(`ARW ${native.arw_deg_per_sqrt_h.toFixed(2)} deg/√h`), text);
});
