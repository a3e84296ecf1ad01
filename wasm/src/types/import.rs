//! TypeScript types: Simulation requests and the import of recorded logs (recipes, detection).

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_IMPORT: &'static str = r#"
/** What to simulate; the same seed gives the same log natively and in wasm. */
export interface SimRequest {
  kind?: "drive" | "robot" | "turntable" | "static";
  /** Drive: city, downtown, suburbs, rural, highway, mixed. Robot: straight, turns. */
  scenario?: string | null;
  minutes?: number | null;
  seed?: number;
  name?: string | null;
  /** Gyro errors added to the simulated rate (null: the simulated gyro as it is). */
  errors?: GyroErrors | null;
}
/** Gyro errors to add to a log's yaw rate (`addGyroErrors`, `SimRequest.errors`): the
 * robustness battery's classes; they combine; every field defaults to none. */
export interface GyroErrors {
  /** Constant turn-on bias, deg/s. */
  bias_dps?: number;
  /** Warm-up: this much extra bias at the start, decaying with warmup_tau_s, deg/s. */
  warmup_dps?: number;
  warmup_tau_s?: number;
  walk_dps_per_sqrt_s?: number;
  /** Bias steps of this size (random sign), deg/s, every step_every_s on average (0: none). */
  step_dps?: number;
  step_every_s?: number;
  /** Scale-factor error (fraction of the rate). */
  scale?: number;
  /** Rate-dependent bias, deg/s per deg/s of |rate|. */
  rate_dep?: number;
  /** Bias per m/s^2 of lateral acceleration (needs speed_mps). */
  g_sens_dps_per_mps2?: number;
  /** White noise per row, deg/s. */
  noise_dps?: number;
  /** Vibration noise and rectified bias at 30 m/s, scaled by speed (needs speed_mps), deg/s. */
  vibration_noise_dps?: number;
  vibration_bias_dps?: number;
  /** Quantisation step, deg/s (0: none). */
  lsb_dps?: number;
  /** Cut the stationary lead-in, so the drive starts moving. */
  cut_lead_in?: boolean;
  /** Drop the speed and wheel columns (a logger with a gyro alone). */
  gyro_only?: boolean;
  seed?: number;
}
/** One of the robustness battery's error profiles (`batteryProfiles()`). */
export interface BatteryProfile {
  name: string;
  errors: Required<GyroErrors>;
  /** A training profile (where choices are made) or a scoring one. */
  training: boolean;
}
/** Import recipe (the CLI's TOML/JSON recipe as an object; see sample-logs/recipes/). */
export type Sense = "ccw" | "cw";
export interface RateSpec {
  table: string;
  column?: string;
  axes?: [string, string, string];
  signs?: [number, number, number];
  gravity?: { axes: [string, string, string]; table?: string; signs?: [number, number, number]; first_s?: number };
  unit: "deg/s" | "rad/s" | "mrad/s" | "deg/h" | "counts";
  scale?: number;
  offset?: number;
  positive: Sense;
}
export interface TableSpec {
  id: string;
  file: string;
  format?: "csv" | "whitespace" | "nmea" | "gpx";
  /** Separator of a csv table (default ","), and numbers written with a decimal comma. */
  delimiter?: "," | ";" | "\t" | "|";
  decimal_comma?: boolean;
  skip_lines?: number;
  columns?: string[];
  record?: string;
  /** The rows' time; absent for a GPX table (its points' `<time>`). */
  time?: {
    column?: string; format?: "seconds" | "iso8601" | "time_of_day"; unit?: "s" | "ms" | "us" | "ns"; period_s?: number; relative?: boolean;
    /** Rows repeating a time: merged (default), the first kept, or an error. */
    duplicates?: "mean" | "drop" | "error";
    /** Rows a little earlier than the one before (up to max_backward_s, default 1 s): sorted in (default), dropped, or an error. */
    backward?: "sort" | "drop" | "error";
    max_backward_s?: number;
  };
  offset_s?: number;
}
export interface Recipe {
  name?: string;
  description?: string;
  bias_s?: number;
  table: TableSpec[];
  yaw_rate: RateSpec;
  positions?: { table: string; kind: "latlon" | "utm" | "ecef" | "enu" | "nmea"; columns: string[] };
  heading?:
    | { source: "column"; table: string; column: string; unit: "deg" | "rad"; positive: Sense; speed_column?: string; speed_unit?: "m/s" | "km/h" | "mph" | "kn" | "knots"; min_speed_mps?: number; time_column?: string }
    | { source: "positions"; min_distance_m?: number; min_speed_mps?: number };
  speed?: { source: "column"; table: string; column: string; unit: "m/s" | "km/h" | "mph" | "kn" | "knots"; time_column?: string } | { source: "positions"; window_s?: number };
  odometry?: { table: string; left: string[]; right: string[]; kind: "speed" | "travel"; unit: string; track_m: number };
  temperature?: { table: string; column: string; unit: "C" | "K" | "F" };
  align?: { rate: RateSpec; max_lag_s?: number };
  /** Keep only rows with start <= time_s <= end (s from the first gyro sample). */
  span_s?: [number, number];
}
export interface ImportSummary {
  n_rows: number;
  n_gyro: number;
  n_reference: number;
  duration_min: number;
  up?: [number, number, number];
  align_offset_s?: number;
  start_time_s: number;
  /** What the time policies did, over all tables. */
  time_fixes: { merged_duplicates: number; dropped_duplicates: number; sorted_backward: number; dropped_backward: number };
}
/** A raw file's dialect and header, as `sniffFile` reads them. */
export interface Sniffed {
  name: string;
  delimiter: "," | ";" | "\t" | "|";
  decimal_comma: boolean;
  skip_lines: number;
  header: string[];
}
/** What `detectImport` found: the logger's preset and its recipe, ready for `importLog`. */
export interface Detection {
  preset: string;
  title: string;
  recipe: Recipe;
  /** [role, file name] of each file the recipe reads. */
  used: [string, string][];
  /** Files no part of the preset took. */
  ignored: string[];
}
/** A draft recipe from raw files' column names (`draftRecipe`): check each guess before use. */
export interface Draft {
  recipe: Recipe;
  /** One line per guess: which column was read as what, and why. */
  guesses: string[];
}

/** A column of one of the files: its index in `ColumnGuesses.files` (the files in name order) and its name. */
export interface ColumnRef {
  file: number;
  column: string;
}
/** What a column's name (and first value) says it is, read as each kind it could be. */
export interface ColumnReading {
  name: string;
  /** As a time: a unit or a format. */
  time: "s" | "ms" | "us" | "ns" | "iso8601" | "time_of_day";
  rate_unit: "rad/s" | "deg/s";
  speed_unit: "m/s" | "km/h" | "mph" | "kn";
  angle_unit: "deg" | "rad";
}
/** What raw files' columns are (`columnGuesses`), by name; a role no column reads as is left out. */
export interface ColumnGuesses {
  /** The files in name order. */
  files: {
    name: string;
    /** A GPX track, read whole. */
    gpx: boolean;
    /** An NMEA log: the sentence to read ("$GPRMC", else a GGA); absent for other files. */
    nmea?: string;
    time_column: string;
    columns: ColumnReading[];
  }[];
  yaw_rate?: ColumnRef;
  /** Gyro x, y, z in one file. */
  gyro_axes?: ColumnRef[];
  /** Accelerometer (or gravity) x, y, z in one file. */
  accel_axes?: ColumnRef[];
  /** The yaw rate is better read as the gyro axes projected on the accelerometer's up (any mounting). */
  yaw_from_axes: boolean;
  course?: ColumnRef;
  lat_lon?: { file: number; lat: string; lon: string };
  speed?: ColumnRef;
  temperature?: ColumnRef;
}

export interface ImportResult {
  log: Log;
  summary: ImportSummary;
}
"#;
