//! TypeScript types: The paper's methods: HDR, Gyrodometry, calibration (options, Result keys of methods.md, runs with series, streaming states).

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_METHODS: &'static str = r#"
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

/** The last closed 1 s block of the streaming pipeline (`PipelineEstimator`, full module). */
export interface PipelineState {
  /** Heading at the block's end, deg (from 0 at the first row; corrected at stops). */
  heading_deg: number;
  /** Bias used for the block and its sigma, deg/s. */
  bias_dps: number;
  bias_sigma_dps: number;
  /** The heading's sigma from the bias model, deg (not the gyro's scale or noise). */
  heading_sigma_deg: number;
  /** The block brought stop evidence; was straight-road evidence; a guard re-opened the bias. */
  stop: boolean;
  straight: boolean;
  reopened: boolean;
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
"#;
