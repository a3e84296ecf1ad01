//! TypeScript types of the option and result objects (the Result keys of methods.md),
//! added to the generated `.d.ts`; checked by `tsc --noEmit` in the tests.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
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

/** HDR's five parameters; missing ones take the paper's Table III. Short names (i_c, tau, theta_w) are accepted too. */
export interface HdrParams {
  /** Nominal increment i_c, deg/s per second (Table III: 0.0422). */
  i_c_dps?: number;
  /** Low-pass filter time constant, s (0.75). */
  tau_s?: number;
  /** Turn-switch threshold, deg/s (0.564). */
  theta_w_dps?: number;
  /** Repetition attenuator constant, > 0 (0.16). */
  c1?: number;
  /** Repetition attenuator power (1.80). */
  c2?: number;
}

/** Options of an HDR run. */
export interface HdrOptions extends HdrParams {
  /** Static-bias window, s; default: the log's `# bias_s:` or 20. */
  bias_s?: number | null;
  /** Block-average to 1 Hz first, as the paper (default true). */
  resample?: boolean;
}

/** Result keys of `hdr` (methods.md). */
export interface HdrResult {
  E_psi_raw_deg: number;
  E_psi_hdr_deg: number;
  NE_psi_raw_deg_per_min: number;
  NE_psi_hdr_deg_per_min: number;
  improvement: number;
  duration_min: number;
  n_samples: number;
  n_processed: number;
  eps0_dps: number;
  resampled: boolean;
}

/** Per-sample series at the estimator samples (1 Hz blocks or rows). */
export interface HdrTrace {
  time_s: Float64Array;
  heading_raw_deg: Float64Array;
  heading_hdr_deg: Float64Array;
  rate_raw_dps: Float64Array;
  rate_corrected_dps: Float64Array;
  /** Controller output I; -I is the drift estimate. */
  i_dps: Float64Array;
  /** The drift estimate -I, deg/s. */
  drift_estimate_dps: Float64Array;
  /** 1 where the turn switch let HDR correct. */
  turn_switch: Uint8Array;
  attenuation: Float64Array;
}

export interface HdrRun {
  result: HdrResult | null;
  /** Why there is no result (e.g. no reference heading); the trace is still there. */
  error: string | null;
  eps0_dps: number;
  trace: HdrTrace;
  /** The valid reference samples, unwrapped (null without a usable reference). */
  reference: { time_s: Float64Array; heading_deg: Float64Array } | null;
  /** Signed heading errors (estimate minus reference) at the scored reference samples. */
  errors: { time_s: Float64Array; raw_deg: Float64Array; hdr_deg: Float64Array } | null;
}

/** One step of the streaming HDR estimator. */
export interface HdrState {
  time_s: number;
  rate_filtered_dps: number;
  rate_corrected_dps: number;
  rate_delag_dps: number;
  heading_deg: number;
  i_dps: number;
  turn_switch: boolean;
  r: number;
  attenuation: number;
}

export interface GyrodometryOptions {
  /** Threshold rate, deg/s (1.25 = 0.125 deg per 0.1 s). */
  thres_rate_dps?: number;
  /** Wheelbase, m; default: the log's `# wheelbase_m:`. */
  wheelbase_m?: number | null;
  bias_s?: number | null;
}

/** Result keys of `gyrodometry` (methods.md). */
export interface GyrodometryResult {
  E_psi_odo_deg: number;
  E_psi_gyro_deg: number;
  E_psi_gyrodometry_deg: number;
  NE_psi_odo_deg_per_min: number;
  NE_psi_gyro_deg_per_min: number;
  NE_psi_gyrodometry_deg_per_min: number;
  final_err_odo_deg: number;
  final_err_gyro_deg: number;
  final_err_gyrodometry_deg: number;
  n_gyro_intervals: number;
  n_samples: number;
  eps0_dps: number;
  duration_min: number;
  wheelbase_m: number;
  thres_rate_dps: number;
}

export interface GyrodometryTrace {
  time_s: Float64Array;
  heading_odo_deg: Float64Array;
  heading_gyro_deg: Float64Array;
  heading_gyrodometry_deg: Float64Array;
  /** 1 where the gyro increment was used. */
  used_gyro: Uint8Array;
}

export interface GyrodometryRun {
  result: GyrodometryResult | null;
  error: string | null;
  eps0_dps: number;
  trace: GyrodometryTrace;
}

export interface GyrodometryState {
  time_s: number;
  heading_odo_deg: number;
  heading_gyro_deg: number;
  heading_deg: number;
  used_gyro: boolean;
}

export interface CalibrationOptions {
  /** Degree in rate (3). */
  p?: number;
  /** Degree in temperature (2). */
  q?: number;
  bias_s?: number | null;
}

/** One turntable data set. */
export interface CalSet {
  table_rate_dps: number;
  w_g_dps: number;
  temp_c: number;
  start: number;
  end: number;
  residual_static_only_dps: number;
  residual_compensated_dps: number;
}

/** Result keys of `calibrate` (methods.md). */
export interface CalibrationResult {
  /** q+1 rows (T^0..T^q) of p+1 coefficients (w_g^0..w_g^p). */
  C: number[][];
  p: number;
  q: number;
  n_sets: number;
  fit_residual_rms_dps: number;
  w_s_dps: number;
  w_s_star_dps: number;
  residual_rms_static_only_dps: number;
  residual_rms_compensated_dps: number;
  turn360_err_static_only_max_deg: number;
  turn360_err_static_only_rms_deg: number;
  turn360_err_compensated_max_deg: number;
  turn360_err_compensated_rms_deg: number;
}

export interface CalibrationRun extends CalibrationResult {
  sets: CalSet[];
}

/** One finding of `checkLog`, with the recipe field or setting that fixes it. */
export interface CheckFinding {
  severity: "error" | "warning" | "info";
  code: "time_unit" | "gap" | "heading_unit" | "gyro_unit" | "gyro_sign" | "gyro_scale" | "bias" | "outlier";
  message: string;
  fix: string | null;
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
  eps0_dps: number | null;
  gyro_over_reference: number | null;
  findings: CheckFinding[];
}

/** Result keys of `allan` (methods.md). */
export interface AllanResult {
  T0_s: number;
  m: number[];
  tau_s: Float64Array;
  adev_dps: Float64Array;
  /** ARW / sqrt(tau) on the same taus: the -1/2 slope line (wasm only, not a Result key). */
  arw_line_dps?: Float64Array;
  arw_deg_per_sqrt_s: number;
  arw_deg_per_sqrt_h: number;
  bias_instability_dps: number;
  bias_instability_dph: number;
  tau_at_min_s: number;
  /** How well each point is known (wasm only, beyond methods.md): core's AllanConfidence. */
  confidence?: AllanConfidence;
}

/** A one-sigma (about 68 %) band per cluster time, 1 / sqrt(2 (N/m - 1)) (IEEE 952 Annex C),
 * and the cluster times whose band reaches the minimum's (the curve's flat bottom). */
export interface AllanConfidence {
  n_samples: number;
  adev_low_dps: Float64Array;
  adev_high_dps: Float64Array;
  min_low_dps: number;
  min_high_dps: number;
  bias_instability_low_dps: number;
  bias_instability_high_dps: number;
  tau_min_range_s: [number, number];
  /** The cluster time with the lowest upper bound, and its deviation. */
  tau_tightest_s: number;
  adev_tightest_dps: number;
}

export interface ReportRow {
  name: string;
  duration_min: number;
  E_psi_raw_deg: number;
  NE_psi_raw_deg_per_min: number;
  E_psi_hdr_deg: number;
  NE_psi_hdr_deg_per_min: number;
  improvement: number;
}

/** The HDR paper's Table II for a set of drives. */
export interface Report {
  rows: ReportRow[];
  total_duration_min: number;
  mean_E_psi_raw_deg: number;
  mean_NE_psi_raw_deg_per_min: number;
  mean_E_psi_hdr_deg: number;
  mean_NE_psi_hdr_deg_per_min: number;
  mean_improvement: number;
  std_improvement: number;
}

/** Tuning bounds (give all five fields of lower/upper) and search settings. */
export interface TuneOptions {
  lower?: HdrParams;
  upper?: HdrParams;
  start?: HdrParams;
  max_iters?: number;
  restarts?: number;
  /** Penalty toward Table III, deg/min per unit squared distance in bounds-scaled coordinates. */
  regularization_deg_per_min?: number;
  /** Leave-one-drive-out cross-validation (3 drives or more). */
  cross_validate?: boolean;
}

export interface CvFold {
  held_out: string;
  ne_psi_table_iii_deg_per_min: number;
  ne_psi_tuned_deg_per_min: number;
  params: Required<HdrParams>;
}

export interface CrossValidation {
  folds: CvFold[];
  cv_table_iii_deg_per_min: number;
  cv_tuned_deg_per_min: number;
}

export interface TuneResult {
  params: Required<HdrParams>;
  objective_start_deg_per_min: number;
  objective_tuned_deg_per_min: number;
  n_evaluations: number;
  cv: CrossValidation | null;
  /** Tuned only if cross-validation says they beat Table III on held-out drives. */
  recommended: Required<HdrParams>;
  recommended_is_tuned: boolean;
}

export interface Comparison {
  table_iii: Report;
  tuned: Report;
}

export interface TuneReport {
  result: TuneResult;
  train: Comparison;
  test: Comparison | null;
}

/** A path in metres. */
export interface Path {
  x_m: Float64Array;
  y_m: Float64Array;
}

/** Dead-reckoned paths of a drive with speed. */
export interface Tracks {
  raw: Path;
  hdr: Path;
  reference: Path | null;
}

/** What a page draws: a time window (null: all) and its width in pixel columns. Series
 * given to a view keep per column the first and last sample and each series' extremes. */
export interface ChartView {
  x_range?: [number, number] | null;
  columns: number;
}

/** A chart for drawChart: series are decimated to the canvas width in core. */
export interface ChartSpec {
  title?: string;
  x_label?: string;
  y_label?: string;
  x_range?: [number, number] | null;
  y_range?: [number, number] | null;
  log_x?: boolean;
  log_y?: boolean;
  /** x is time in seconds: drawn in s, min or h by the span shown, labelled "x_label (unit)". */
  time_x?: boolean;
  /** Draw the legend inside the plot (default true). */
  legend?: boolean;
  series: { name: string; color: string; x: ArrayLike<number>; y: ArrayLike<number>; width?: number; points?: boolean; path?: boolean }[];
  shade?: { x: ArrayLike<number>; mask: ArrayLike<number>; color: string; label?: string } | null;
  cursor_x?: number | null;
  dpr?: number;
}

/** Where drawChart put the plot area (canvas pixels) and its data ranges. */
export interface ChartLayout {
  left: number;
  top: number;
  right: number;
  bottom: number;
  x_min: number;
  x_max: number;
  y_min: number;
  y_max: number;
  /** The time axis's unit ("s", "min", "h"), "" when x is not time. Ranges stay in seconds. */
  x_unit: string;
  /** Seconds in one x_unit (60 for "min"), 1 when x is not time. */
  x_unit_s: number;
  /** Where the ticks are, as labelled: round values (1, 2 or 5 times a power of ten apart)
   * in the axis's unit, whole decades on a log axis. */
  x_ticks: Float64Array;
  y_ticks: Float64Array;
}

/** What to simulate; the same seed gives the same log natively and in wasm. */
export interface SimRequest {
  kind?: "drive" | "robot" | "turntable" | "static";
  /** Drive: city, downtown, suburbs, rural, highway, mixed. Robot: straight, turns. */
  scenario?: string | null;
  minutes?: number | null;
  seed?: number;
  name?: string | null;
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
  format?: "csv" | "whitespace" | "nmea";
  /** Separator of a csv table (default ","), and numbers written with a decimal comma. */
  delimiter?: "," | ";" | "\t" | "|";
  decimal_comma?: boolean;
  skip_lines?: number;
  columns?: string[];
  record?: string;
  time: {
    column?: string; format?: "seconds" | "iso8601"; unit?: "s" | "ms" | "us" | "ns"; period_s?: number; relative?: boolean;
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
  positions?: { table: string; kind: "latlon" | "utm" | "ecef" | "enu"; columns: string[] };
  heading?:
    | { source: "column"; table: string; column: string; unit: "deg" | "rad"; positive: Sense; speed_column?: string; speed_unit?: "m/s" | "km/h" | "mph"; min_speed_mps?: number; time_column?: string }
    | { source: "positions"; min_distance_m?: number; min_speed_mps?: number };
  speed?: { source: "column"; table: string; column: string; unit: "m/s" | "km/h" | "mph"; time_column?: string } | { source: "positions"; window_s?: number };
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
  up: [number, number, number] | null;
  align_offset_s: number | null;
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

export interface ImportResult {
  log: Log;
  summary: ImportSummary;
}

/** Settings of the pipeline (all optional; defaults chosen on the battery's training cases). */
export interface PipelineOptions {
  still?: { still_speed_mps?: number; still_travel_m?: number; still_gyro_factor?: number };
  min_still_s?: number;
  stop_sigma_dps?: number;
  max_bias_dps?: number;
  jump_min_s?: number;
  road_sigma_dps?: number;
  road_corr_s?: number;
  road_window_s?: number;
  road_gate_dps?: number;
  bias_walk_min_dps_per_sqrt_s?: number;
  bias_walk_max_dps_per_sqrt_s?: number;
  road_sigma_spread?: number;
  block_sigma_dps?: number;
  warm_sigma_dps?: number;
  warm_tau_short_s?: number;
  warm_tau_long_s?: number;
  prior_bias_sigma_dps?: number;
  forget_s?: number;
  bias_s?: number | null;
}
export type StillSource = "speed" | "odometry" | "gyro" | "none";
/** Result keys of `pipeline`. */
export interface PipelineResult {
  E_psi_raw_deg: number;
  E_psi_hdr_deg: number;
  E_psi_pipeline_deg: number;
  NE_psi_raw_deg_per_min: number;
  NE_psi_hdr_deg_per_min: number;
  NE_psi_pipeline_deg_per_min: number;
  improvement_pipeline: number;
  duration_min: number;
  /** The offline smoothed mode (non-causal: uses the whole log). */
  E_psi_pipeline_smoothed_deg: number;
  NE_psi_pipeline_smoothed_deg_per_min: number;
  E_psi_fusion_offset_deg: number;
  E_psi_zaru_deg: number;
  NE_psi_fusion_offset_deg_per_min: number;
  NE_psi_zaru_deg_per_min: number;
  still_source: StillSource;
  stop_s: number;
  final_bias_dps: number;
  final_bias_sigma_dps: number;
  n_samples: number;
}
export interface PipelineRun {
  result: PipelineResult | null;
  error: string | null;
  still_source: StillSource;
  /** Per 1 Hz block; heading aligned to the reference when there is one. */
  trace: {
    time_s: Float64Array;
    heading_deg: Float64Array;
    /** Offline smoothed heading (non-causal). */
    heading_smoothed_deg: Float64Array;
    bias_dps: Float64Array;
    bias_sigma_dps: Float64Array;
    bias_smoothed_dps: Float64Array;
    stop: Uint8Array;
  };
  /** Signed heading errors at the scored reference samples (null without a reference). */
  errors: { time_s: Float64Array; pipeline_deg: Float64Array; smoothed_deg: Float64Array } | null;
}
export interface CompareRow {
  name: string;
  duration_min: number;
  raw: number;
  hdr_table_iii: number;
  hdr_tuned: number | null;
  pipeline: number;
  /** Offline smoothed mode (non-causal). */
  pipeline_smoothed: number;
  fusion_offset: number;
  zaru: number;
}
export interface Compare {
  rows: CompareRow[];
  mean: CompareRow;
  tuned_params: HdrParams | null;
}
"#;
