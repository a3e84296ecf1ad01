//! TypeScript types: Logs: metadata, columns, and what `checkLog` and `Log.splitAtGaps` say of a log.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_LOG: &'static str = r#"
/** Kind of a log, from its columns. */
export type LogKind = "drive" | "robot" | "turntable" | "static";

/** `# key: value` metadata of a log. */
export interface LogMeta {
  name?: string;
  wheelbase_m?: number;
  bias_s?: number;
  description?: string;
  other: Record<string, string>;
}

/** A parsed log as plain data (transferable from a worker). */
export interface LogColumns {
  meta: LogMeta;
  line: Float64Array;
  columns: Record<string, Float64Array>;
}

/** The kind of a parser's refusal that another way of reading mends (core's
 * `log::accept::Refusal`): a time that repeats or steps back by at most 1 s (`logInTimeOrder`
 * puts it in order), a clock reset and a second log joined on (`logsJoined` reads each part),
 * a row cut short (`logInTimeOrder` drops a cut last line), a table without `time_s` (a
 * logger's own export: `detectImport` finds its preset, `importLog` reads it by a recipe, which
 * `draftRecipe` drafts). A table's refusal of a log `checkLog` finds an error in is the
 * other kind, `CheckRefusal`. */
export type RefusalCode = "time_order" | "clock_reset" | "joined" | "cut_row" | "foreign";

/** What `Log.parse`, `Log.fromBytes`, `logInTimeOrder` and `logsJoined` throw: an Error naming
 * the line and column, with `code` where another way of reading mends it. */
export interface ParseError extends Error {
  code?: RefusalCode;
}

/** What the tables over logs (`report`, `compare`, `battery`, `tune`, ...) throw for a log
 * `checkLog` finds an error in (time not in seconds, heading in radians, gyro in another unit
 * or clockwise): `log` names it; its fix is `checkLog`'s, or `ignore_check` runs it anyway. */
export interface CheckRefusal extends Error {
  code: "check";
  log: string;
}

/** One finding of `checkLog`, with the recipe field or setting that fixes it. */
export interface CheckFinding {
  severity: "error" | "warning" | "info";
  code:
    | "time_unit" | "gap" | "heading_unit" | "gyro_unit" | "gyro_sign" | "gyro_scale" | "bias" | "lead_in" | "no_stops" | "bias_drift"
    | "no_reference" | "outlier" | "reference_turn" | "speed_unit" | "wheel_units";
  message: string;
  fix?: string;
  /** The value the fix sets where a front can fill it in (time_unit: "ms", "us" or "ns";
   * gyro_unit: "rad/s", "mrad/s" or "deg/h"). */
  fix_value?: string;
}

/** `Log.splitAtGaps`: the drives between a log's gaps in time. */
export interface GapSplit {
  parts: Log[];
  /** Each gap: the time before it, its length (s), the line of the row after it. */
  gaps: { at_s: number; length_s: number; line: number }[];
  /** Parts under 30 s, dropped. */
  dropped: number;
  summary: string | null;
}

/** `checkLog`: what a log looks like before any method runs. */
export interface CheckReport {
  rows: number;
  duration_min: number;
  median_step_s: number;
  jitter_p95: number;
  /** [start time, length] of each gap, s. */
  gaps_s: [number, number][];
  eps0_dps?: number;
  gyro_over_reference?: number;
  /** [start time, median gyro rate (deg/s)] of each standing of 7 s or more the speed or the
   * wheels show: the bias as it moves (a `bias_drift` finding where they disagree). */
  stop_bias_dps: [number, number][];
  findings: CheckFinding[];
}
"#;
