//! TypeScript types: Tuning HDR with cross-validation.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TUNE: &'static str = r#"
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
  cv?: CrossValidation;
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
  test?: Comparison;
}
"#;
