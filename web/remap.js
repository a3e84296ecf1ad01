// A log check found an error in, opened again in the column mapper with the fix filled in:
// the user sees the preview and adds the fixed log beside the one opened.
import * as gd from "./pkg/gyrodrift.js";
import { state } from "./state.js";
import { selectEntry } from "./controls.js";
import { openMapping } from "./mapping.js";
import { addParsed, inWorker } from "./loading.js";

/** A check error the column mapper fixes: the form's field and the value that fixes it
 * (the time's and the gyro's unit are those check found, its `fix_value`). */
const MAPPER_FIX = {
  gyro_sign: () => ({ "map-rate-sense": "cw" }),
  gyro_unit: (f) => ({ "map-rate-unit": f.fix_value ?? "rad/s" }),
  heading_unit: () => ({ "map-ref-unit": "rad" }),
  time_unit: (f) => ({ "map-time-unit-0": f.fix_value ?? "ms" }),
};

/** Whether the column mapper can fix `entry`'s check errors (a v1 log opened from a file). */
export function canRemap(entry) {
  const errors = entry.errors ?? [];
  return !!entry.source && errors.length > 0 && errors.every((f) => MAPPER_FIX[f.code]);
}

/** Re-imports `entry`'s file with the column mapper, the fix of each check error filled in
 * (a clockwise gyro: right turn positive) and its lead-in, to look at in the preview and add
 * as a log of its own; the log as opened stays until removed. */
export async function remap(entry) {
  const f = entry.source;
  const bytes = { [f.name]: new Uint8Array(await f.arrayBuffer()) };
  const importer = (r) => inWorker({ type: "import", files: bytes, recipe: r, title: "the check's fix" }, [], () => {});
  const fixes = entry.errors;
  const lead = entry.log.meta().bias_s ?? gd.defaultBiasS();
  // A v1 log's reference is counter-clockwise positive already and kept at any speed (not a
  // raw GPS course).
  const preset = Object.assign({ "map-lead": String(lead), "map-ref-sense": "ccw", "map-ref-min-speed": "0" }, ...fixes.map((x) => MAPPER_FIX[x.code](x)));
  const why = `${entry.name}: ${fixes.map((x) => x.message).join("; ")}.`;
  const course = fixes.some((x) => x.code === "gyro_sign")
    ? " The gyro is set to right turn positive; if the reference is a GPS course (clockwise from north), set the reference's sign to clockwise instead and the gyro's back."
    : "";
  const intro = `The fix is filled in below: check that the gyro, integrated, now follows the reference in the preview, then add the log (the one opened stays until you remove it).${course}`;
  const guesses = (await inWorker({ type: "guess", files: bytes }, [], () => {})).data ?? null;
  const mapped = await openMapping([{ name: f.name, bytes: bytes[f.name] }], why, importer, { guesses, draft: null }, preset, intro);
  if (!mapped) return;
  const added = addParsed(`${entry.name} (fixed)`, () => {
    const log = gd.Log.fromColumns(mapped.res.data);
    log.name = `${entry.name} (fixed)`;
    return log;
  });
  if (!added.error) added.imported = { ...mapped.res.detection, recipe: mapped.recipe };
  selectEntry(state.entries.indexOf(added));
}
