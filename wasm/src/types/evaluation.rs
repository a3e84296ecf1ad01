//! TypeScript types: Allan deviation, the Table II report, the pipeline, the comparison of every method and the robustness battery.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_EVALUATION: &'static str = r#"
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

/** Settings of the pipeline (all optional; defaults chosen on the battery's training cases). */
export interface PipelineOptions {
  still?: { still_speed_mps?: number; still_travel_m?: number; still_gyro_factor?: number; still_agree_factor?: number };
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
  /** Over each block the heading moves by the mean of the bank's move and those of Table-III
   * HDR and Fusion's offset where the bias an expert implies differs from the bank's by less
   * than this many of the bank's bias sigma (2); 0 = the bank's alone. */
  blend_sigmas?: number;
  /** Between stops that guard's sigma grows as a bias walk of this since the last stop,
   * deg/s per sqrt(s) (0.003); 0 = the bank's sigma alone. */
  blend_walk_dps_per_sqrt_s?: number;
  /** While the bank's settled bias (less its warm-up term) is further than this from where
   * the last stop left it, the heading moves by Table-III HDR's move (its bias held near the
   * bank's): long bends read as straight road, deg/s (0.3; after a lead-in on a quiet gyro
   * `blend_move_quiet_dps`); 0 = never. Without a stationary
   * lead-in a move that outlasts `road_window_s` is taken as the gyro's, unless it is
   * coming back (a bend leaving the window). */
  blend_move_dps?: number;
  /** The same threshold after a stationary lead-in on a quiet gyro (its standstill noise
   * within `stop_sigma_dps`), deg/s (0.15); 0 = `blend_move_dps` there too. */
  blend_move_quiet_dps?: number;
  /** @deprecated The name of `blend_sigmas` while it blended HDR alone. */
  hdr_blend_sigmas?: number;
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
/** The pipeline's end figures, which need no reference (a drive with no GPS course). */
export interface PipelineSummary {
  duration_min: number;
  still_source: StillSource;
  stop_s: number;
  /** The bank's bias estimate and its sigma at the last block (deg/s). */
  final_bias_dps: number;
  final_bias_sigma_dps: number;
  /** Heading turned from the first block to the last (causal, its sigma; smoothed), deg. */
  heading_change_deg: number;
  heading_change_sigma_deg: number;
  heading_change_smoothed_deg: number;
}
export interface PipelineRun {
  result: PipelineResult | null;
  error: string | null;
  still_source: StillSource;
  summary: PipelineSummary;
  /** Per 1 Hz block; heading aligned to the reference when there is one. */
  trace: {
    time_s: Float64Array;
    heading_deg: Float64Array;
    /** The causal heading's standard deviation from the bias model (deg): the gyro's
     * noise, scale error and biases the model does not describe are not in it. */
    heading_sigma_deg: Float64Array;
    /** Offline smoothed heading (non-causal). */
    heading_smoothed_deg: Float64Array;
    /** The bias the causal heading integrated: the bank's, moved by the blend with
     * Table-III HDR and Fusion's offset (deg/s). */
    bias_dps: Float64Array;
    /** The bank's bias sigma (deg/s): the blend's guard, not the blended bias' own. */
    bias_sigma_dps: Float64Array;
    /** The bias the smoothed heading integrated, blended likewise (deg/s). */
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
  hdr_tuned?: number;
  pipeline: number;
  /** Offline smoothed mode (non-causal). */
  pipeline_smoothed: number;
  fusion_offset: number;
  zaru: number;
}
export interface Compare {
  rows: CompareRow[];
  mean: CompareRow;
  tuned_params?: HdrParams;
}
/** One battery case: a drive with one error profile; NE_psi (deg/min) per method in the
 * order of `Battery.methods`. */
export interface BatteryCase {
  base: string;
  profile: string;
  training: boolean;
  simulated: boolean;
  duration_min: number;
  ne_psi: number[];
  /** The pipeline's NE_psi over the best other causal method's. */
  ratio: number;
  /** Within 1.25x the best other + 0.05 deg/min. */
  within: boolean;
  /** Column of the best causal method (the pipeline included, the smoothed mode not). */
  best: number;
}
/** One of the robustness issue's goals, measured. */
export interface BatteryGoal {
  goal: string;
  measured: number;
  target: number;
  at_least: boolean;
  holds: boolean;
  detail: string;
}
/** Means, counts and the worst case over some cases. */
export interface BatterySummary {
  n_cases: number;
  mean: number[];
  mean_ratio: number;
  n_within: number;
  n_over_2x: number;
  worst: string;
  worst_ratio: number;
  n_worse_than_raw: number;
  each_within: number[];
  each_over_2x: number[];
  goals: BatteryGoal[];
}
/** `battery(logs)`: the error profiles on these drives (all scoring cases, also summarised
 * as `added`); `skipped` lists the cases that could not be scored, with why. */
export interface Battery {
  methods: string[];
  cases: BatteryCase[];
  /** Absent (undefined) when no case is of that split: the page's drives are all scoring. */
  training?: BatterySummary;
  scoring?: BatterySummary;
  added?: BatterySummary;
  skipped: [string, string][];
}
"#;
