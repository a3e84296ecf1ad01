//! Hand-worked steps of the filter bank and its behaviour on logs with known truth, by
//! topic; the helpers they share.

mod bank;
mod lead_in;
mod mode;
mod origin;
mod properties;
mod smoothed;

use super::smoother::hold_to_stops;
use super::*;

/// One hypothesis (walk min = max, one road), so the numbers are a plain Kalman filter;
/// fixed constants, so the hand-worked numbers do not follow the defaults.
fn one_model() -> PipelineParams {
    PipelineParams {
        bias_walk_min_dps_per_sqrt_s: 0.001,
        bias_walk_max_dps_per_sqrt_s: 0.001,
        road_sigma_dps: 0.3,
        road_sigma_spread: 1.0,
        road_corr_s: 10.0,
        block_sigma_dps: 0.05,
        min_still_s: 2.0,
        stop_sigma_dps: 0.05,
        warm_sigma_dps: 1e-12,
        ..PipelineParams::default()
    }
}

/// Arbitrary block sequences for the property tests: (duration s, rate deg/s, still), rates
/// far beyond any bias, stops anywhere, irregular times.
fn any_blocks(max_len: usize) -> impl proptest::strategy::Strategy<Value = Vec<(f64, f64, bool)>> {
    proptest::collection::vec((0.2f64..3.0, -40.0f64..40.0, proptest::prelude::any::<bool>()), 1..max_len)
}

/// 1 Hz-ish blocks from (duration s, rate deg/s, still) triples, times accumulated.
fn blocks_of(items: &[(f64, f64, bool)]) -> crate::still::Blocks {
    let mut b = crate::still::Blocks::default();
    let mut t = 0.0;
    for &(dt, rate, still) in items {
        t += dt;
        b.time_s.push(t);
        b.rate_dps.push(rate);
        b.temp_c.push(f64::NAN);
        b.still.push(still);
    }
    b
}

/// A pipeline after a declared 20 s lead-in of 1 s blocks at `rate_dps`, alternately
/// `wiggle_dps` above and below it.
fn after_lead_in(rate_dps: f64, wiggle_dps: f64) -> Pipeline {
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 20.0).unwrap();
    for i in 0..20_u32 {
        f.update(i as f64, rate_dps + if i.is_multiple_of(2) { wiggle_dps } else { -wiggle_dps }, true).unwrap();
    }
    f
}
