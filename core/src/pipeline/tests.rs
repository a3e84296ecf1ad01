//! Hand-worked steps of the filter bank and its behaviour on logs with known truth.

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

/// The bank drops the pair that cannot tell bias from road: walk x sqrt(10 s) > 0.5 x road
/// sigma. Defaults: 0.01 x 3.162 = 0.0316 > 0.5 x 0.06 = 0.03 (dropped); 0.00316 x 3.162 =
/// 0.01 <= 0.03 (kept); so exactly the three warm-up variants of (fastest walk, narrowest
/// road), indices 36, 37, 38, have no weight, before and after evidence. Settings that
/// leave no pair identifiable keep them all.
#[test]
fn the_bank_drops_the_hypotheses_that_cannot_tell_bias_from_road_hand_worked() {
    let p = PipelineParams::default();
    assert!(!p.identifiable(0.01, 0.06) && p.identifiable(10f64.powf(-2.5), 0.06) && p.identifiable(0.01, 0.3));
    let mut f = Pipeline::new(p, 0.0, 0.5, 0.0).unwrap();
    for k in 0..120 {
        f.update(k as f64, 0.1 * (k as f64 * 0.3).sin(), k < 20).unwrap();
    }
    let w = f.weights();
    let zero: Vec<usize> = (0..N_MODELS).filter(|&i| w[i] == 0.0).collect();
    assert_eq!(zero, vec![36, 37, 38]);
    assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    let none = PipelineParams { bias_walk_min_dps_per_sqrt_s: 0.01, road_sigma_dps: 0.01, road_sigma_spread: 1.0, ..p };
    let g = Pipeline::new(none, 0.0, 0.5, 0.0).unwrap();
    assert!(g.weights().iter().all(|&v| (v - 1.0 / N_MODELS as f64).abs() < 1e-12));
}

#[test]
fn walks_are_log_spaced() {
    let w = PipelineParams::default().bias_walks_dps_per_sqrt_s();
    let want = [1e-4, 10f64.powf(-3.5), 1e-3, 10f64.powf(-2.5), 1e-2];
    for i in 0..5 {
        assert!((w[i] / want[i] - 1.0).abs() < 1e-12, "{w:?}");
    }
    let r = PipelineParams { road_sigma_dps: 0.3, road_sigma_spread: 5.0, ..PipelineParams::default() }.road_sigmas_dps();
    assert!((r[0] - 0.06).abs() < 1e-15 && r[1] == 0.3 && (r[2] - 1.5).abs() < 1e-15);
}

#[test]
fn road_step_hand_worked() {
    // Straight evidence needs 5 moving blocks in the window; at t = 4 all five read 0.3, so
    // the dominant rate is 0.3 and the block is straight. State [b, c]: the road variance
    // stays stationary (0.3^2) under prediction, the cross terms stay 0, so P = diag(0.25 +
    // 4 * 0.001^2, 0.09). H = [1, 1], R = 0.05^2: S = P00 + P11 + R, K = [P00, P11] / S.
    let mut f = Pipeline::new(one_model(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    for t in 0..4 {
        f.update(t as f64, 0.3, false).unwrap();
        assert_eq!(f.bias().0, 0.0, "no straight evidence before 5 moving blocks");
    }
    let o = f.update(4.0, 0.3, false).unwrap();
    assert!(o.straight);
    assert!((o.heading_deg - 1.2).abs() < 1e-12, "integrates rate - bias(before) = 0.3 deg/s over 4 s");
    let p00 = 0.25 + 4.0 * 1e-6;
    let s = p00 + 0.09 + 0.0025;
    let (b, var) = f.bias();
    assert!((b - 0.3 * p00 / s).abs() < 1e-14, "{b} vs {}", 0.3 * p00 / s);
    assert!((var - (p00 - p00 * p00 / s)).abs() < 1e-14);
    // A turn block (far from the dominant rate) is not evidence.
    assert!(!f.update(5.0, 12.0, false).unwrap().straight);
    assert_eq!(f.bias().0, b);
}

#[test]
fn stop_evidence_waits_for_both_ends_of_the_stop() {
    // min_still 2 s: blocks of a stop from t=10..=16 count from t=12 on, each applied once
    // the stop has lasted 2 s beyond it: block 12 at 14, ..., block 14 at 16.
    let mut f = Pipeline::new(one_model(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    f.update(9.0, 5.0, false).unwrap();
    let stops: Vec<bool> = (10..=16).map(|t| f.update(t as f64, 0.2, true).unwrap().stop).collect();
    assert_eq!(stops, vec![false, false, false, false, true, true, true]);
    // Pulling away discards the pending (last 2 s) blocks.
    assert!(!f.update(17.0, 8.0, false).unwrap().stop);
}

#[test]
fn stop_step_hand_worked_and_heading_is_not_held() {
    // A lead-in block is stop evidence with no trimming and no outlier arm: P = 0.25,
    // R = 0.05^2, rate 0.4: K = P / (P + R).
    let mut f = Pipeline::new(one_model(), 0.0, 0.5, 5.0).unwrap();
    let o = f.update(0.0, 0.4, true).unwrap();
    assert!(o.stop && o.heading_deg == 0.0);
    let k = 0.25 / (0.25 + 0.0025);
    assert!((f.bias().0 - 0.4 * k).abs() < 1e-14);
    // After the lead-in, stop blocks are trimmed: block 2 of a stop starting at 0 is applied
    // at t = 4: P = 0.25 + 4e-6, K = P / (P + R).
    let mut g = Pipeline::new(one_model(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    for t in 0..5 {
        g.update(t as f64, 0.4, true).unwrap();
    }
    let p = 0.25 + 4.0 * 1e-6;
    let k = p / (p + 0.0025);
    let mut h = Pipeline::new(one_model(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    for t in 0..4 {
        h.update(t as f64, 0.4, true).unwrap();
    }
    assert_eq!(h.bias().0, 0.0, "blocks 0-1 trimmed, block 2 waits until t = 4");
    assert!((g.bias().0 - 0.4 * k).abs() < 1e-14, "block 2 applied at t = 4: {}", g.bias().0);
    // The heading integrates rate - bias at stops too (not held), and the stop corrects the
    // integral of the last second's bias by the stop's innovation times the gain of the
    // integral: P_hx / S = P1 / (P1 + q + R), P1 the bias variance after the first block.
    let b = f.bias().0;
    let o = f.update(1.0, 0.4, true).unwrap();
    let p1 = 0.25 * 0.0025 / (0.25 + 0.0025);
    let k_h = p1 / (p1 + 1e-6 + 0.0025);
    assert!((o.heading_deg - (0.4 - b) * (1.0 - k_h)).abs() < 1e-12, "{} against {}", o.heading_deg, (0.4 - b) * (1.0 - k_h));
}

#[test]
fn a_large_bias_at_a_stop_is_acquired_not_locked_out() {
    // Prior 0 +- 0.5, no lead-in, true bias 3 deg/s (6 sigma outside the prior): stop evidence
    // is not gated by closeness to the estimate, so the first stop takes the bias.
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    for t in 0..30 {
        f.update(t as f64, 3.0 + 0.01 * ((t % 3) as f64 - 1.0), true).unwrap();
    }
    // (the warm-up hypotheses still expect part of it to decay: 0.02)
    assert!((f.bias().0 - 3.0).abs() < 0.02, "bias {}", f.bias().0);
}

#[test]
fn a_steady_turn_the_gyro_alone_calls_still_does_not_move_the_bias() {
    // A 20 s lead-in at 0.2 deg/s, straight road at that bias, then a 2.4 deg/s curve whose
    // 8 blocks the gyro-only detector took for a standing. Judged by the gyro, the stop is
    // 40 sigma from every hypothesis: weighed, not followed. Judged by speed (certain), the
    // same blocks are a standing and the bias follows them (no lock-out there).
    let run = |gyro_stills: bool| {
        let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 20.0).unwrap();
        f.gyro_stills = gyro_stills;
        for t in 0..300 {
            let (rate, still) = match t {
                0..20 => (0.2, true),
                200..208 => (2.6, true),
                _ => (0.2 + 0.02 * ((t % 5) as f64 - 2.0), false),
            };
            f.update(t as f64 + 1.0, rate, still).unwrap();
        }
        f.bias().0
    };
    let gated = run(true);
    assert!((gated - 0.2).abs() < 0.02, "gyro-judged: bias {gated}");
    let by_speed = run(false);
    assert!(by_speed > 1.0, "speed-judged: bias {by_speed}");
}

#[test]
fn a_bias_step_at_a_later_stop_reopens_the_estimate() {
    // A long stop pins the bias at 0 (small P); 5 min later the bias has stepped to 1 deg/s:
    // the next steady stop disagrees far beyond P and re-opens it. One slow hypothesis only,
    // so the bank's fast hypothesis cannot take the step first.
    let slow = PipelineParams { bias_walk_min_dps_per_sqrt_s: 1e-4, bias_walk_max_dps_per_sqrt_s: 1e-4, ..PipelineParams::default() };
    let mut f = Pipeline::new(slow, 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    let mut t = 0.0;
    for _ in 0..120 {
        f.update(t, 0.0, true).unwrap();
        t += 1.0;
    }
    let (_, p) = f.bias();
    assert!(p.sqrt() < 0.01);
    for i in 0..300 {
        f.update(t, if (i / 20) % 2 == 0 { 20.0 } else { -20.0 }, false).unwrap();
        t += 1.0;
    }
    let mut reopened = false;
    for _ in 0..30 {
        reopened |= f.update(t, 1.0, true).unwrap().reopened;
        t += 1.0;
    }
    assert!(reopened);
    assert!((f.bias().0 - 1.0).abs() < 0.02, "bias {}", f.bias().0);
}

#[test]
fn the_bank_moves_to_the_fast_hypothesis_on_a_step() {
    // Same step with the default bank: the fast hypothesis predicts the stop and takes the weight.
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    let mut t = 0.0;
    for _ in 0..120 {
        f.update(t, 0.0, true).unwrap();
        t += 1.0;
    }
    for i in 0..300 {
        f.update(t, if (i / 20) % 2 == 0 { 20.0 } else { -20.0 }, false).unwrap();
        t += 1.0;
    }
    for _ in 0..30 {
        f.update(t, 1.0, true).unwrap();
        t += 1.0;
    }
    // Weight of each bias walk (summed over the road hypotheses): the two fastest win.
    let w = f.weights();
    let by_walk: Vec<f64> = w.chunks(N_ROADS * N_WARMS).map(|c| c.iter().sum()).collect();
    assert!(by_walk[3] + by_walk[4] > 0.5, "weights by walk {by_walk:?}");
    assert!((f.bias().0 - 1.0).abs() < 0.02, "bias {}", f.bias().0);
}

#[test]
fn a_large_bias_without_stops_is_acquired_from_the_road() {
    // No stops at all: straights at the bias (3 deg/s) with turns in between; the road guard
    // re-opens after a window and the straight-road evidence takes the bias.
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    for i in 0..900 {
        let turn = if (i / 15) % 4 == 3 { 12.0 * if (i / 60) % 2 == 0 { 1.0 } else { -1.0 } } else { 0.0 };
        let sway = 0.1 * ((i as f64) * 0.7).sin();
        f.update(i as f64, 3.0 + turn + sway, false).unwrap();
    }
    assert!((f.bias().0 - 3.0).abs() < 0.1, "bias {}", f.bias().0);
}

#[test]
fn smoother_of_a_constant_bias_is_constant_and_uses_later_stops() {
    // Moving at 0.1 deg/s bias from the start (no lead-in), a long stop at the end: the
    // smoothed bias at the start already knows the stop's 0.1, the causal one does not.
    let n = 400;
    let blocks = Blocks {
        time_s: (0..n).map(|i| i as f64).collect(),
        rate_dps: (0..n).map(|i| 0.1 + if i < 300 && (i / 20) % 3 == 2 { 15.0 } else { 0.0 }).collect(),
        temp_c: vec![f64::NAN; n],
        still: (0..n).map(|i| i >= 300).collect(),
        first_moving_s: None,
        source: crate::still::StillSource::Speed,
    };
    let tr = run_blocks(&blocks, PipelineParams::default(), f64::NEG_INFINITY).unwrap();
    let (es, ec) = ((tr.bias_smoothed_dps[3] - 0.1).abs(), (tr.bias_dps[3] - 0.1).abs());
    assert!(es < 0.005 && es < ec / 4.0, "smoothed error {es}, causal error {ec}");
    assert!((tr.bias_dps[n - 1] - 0.1).abs() < 0.005);
}

#[test]
fn half_sample_mode_finds_the_dense_cluster() {
    let mut x = vec![0.5, 0.51, 0.49, 0.5, 0.52, 10.0, -8.0, 4.0, 0.48, 20.0];
    assert!((half_sample_mode(&mut x) - 0.5).abs() < 0.02);
    assert_eq!(half_sample_mode(&mut [2.0]), 2.0);
    assert_eq!(half_sample_mode(&mut [1.0, 3.0]), 2.0);
}

#[test]
fn half_sample_mode_of_a_lattice_is_not_pulled_to_its_lowest_value() {
    // A gyro quantised at 0.1 deg/s, one row per block: equally dense halves tie at width 0.
    // Six readings at -0.1 and six at 0: the densest point is between them, not -0.1.
    let mut two = [vec![-0.1; 6], vec![0.0; 6]].concat();
    assert!((half_sample_mode(&mut two) + 0.05).abs() < 1e-12);
    // Symmetric about 0 with a turn on one side: the mode stays at 0.
    let mut sym = [vec![-0.1; 4], vec![0.0; 5], vec![0.1; 4], vec![3.0; 3]].concat();
    assert!(half_sample_mode(&mut sym).abs() < 1e-12);
    // Two lattice values tied, the rest outliers on both sides.
    let mut out = [vec![-5.0; 2], vec![0.2; 5], vec![0.3; 5], vec![7.0; 2]].concat();
    assert!((half_sample_mode(&mut out) - 0.25).abs() < 1e-12);
}

#[test]
fn bad_updates_and_params_are_errors() {
    let mut f = Pipeline::new(one_model(), 0.0, 0.5, f64::NEG_INFINITY).unwrap();
    f.update(1.0, 0.0, false).unwrap();
    assert!(f.update(1.0, 0.0, false).is_err());
    assert!(f.update(2.0, f64::NAN, false).is_err());
    assert!(PipelineParams { road_gate_dps: 0.0, ..one_model() }.validate().is_err());
    assert!(PipelineParams { road_sigma_dps: 1e300, ..one_model() }.validate().is_err());
    assert!(crate::options::from_pairs::<PipelineParams>(&[("nope".into(), 1.0)]).is_err());
    assert!(Pipeline::new(one_model(), 0.0, 0.0, 0.0).is_err());
    assert!(crate::options::from_pairs::<PipelineParams>(&[("blend_sigmas".into(), -1.0)]).is_err());
    assert!(crate::options::from_pairs::<PipelineParams>(&[("blend_walk_dps_per_sqrt_s".into(), -0.001)]).is_err());
    assert!(crate::options::from_pairs::<PipelineParams>(&[("blend_walk_dps_per_sqrt_s".into(), f64::NAN)]).is_err());
}

#[test]
fn the_blend_guard_keeps_its_first_name_as_an_alias() {
    let by = |key: &str| crate::options::from_pairs::<PipelineParams>(&[(key.into(), 3.0)]).unwrap().blend_sigmas;
    assert_eq!((by("blend_sigmas"), by("hdr_blend_sigmas")), (3.0, 3.0));
    assert_eq!(PipelineParams::default().blend_sigmas, 2.0);
}

#[test]
fn smoother_keeps_a_lead_in_it_agrees_with() {
    // 20 s lead-in at 0.1, then 300 s of straight driving at 0.1 with sway: the smoothed
    // bias stays at 0.1 over the lead-in (every hypothesis agrees).
    let n = 320;
    let blocks = Blocks {
        time_s: (0..n).map(|i| i as f64).collect(),
        rate_dps: (0..n).map(|i| 0.1 + if i >= 20 { 0.1 * ((i as f64) * 0.9).sin() } else { 0.0 }).collect(),
        temp_c: vec![f64::NAN; n],
        still: (0..n).map(|i| i < 20).collect(),
        first_moving_s: None,
        source: crate::still::StillSource::Speed,
    };
    let tr = run_blocks(&blocks, PipelineParams::default(), 20.0).unwrap();
    for k in [0, 1, 10, 19] {
        assert!((tr.bias_smoothed_dps[k] - 0.1).abs() < 0.005, "block {k}: smoothed {}", tr.bias_smoothed_dps[k]);
    }
    for k in [100, 319] {
        assert!((tr.bias_smoothed_dps[k] - 0.1).abs() < 0.02, "block {k}: smoothed {}", tr.bias_smoothed_dps[k]);
    }
}

/// A known bias (lead-in), 600 s of straight road on it, then the bias steps by 0.2 deg/s
/// 10 s before a stop; the step went unseen for 12 s (2.4 deg), so the ideal correction
/// leaves the heading error where it was before the step. The walk model's correction
/// (the change spread back over the straights it could not rule out) moves it by -6.3 deg;
/// dated by the straights on the old bias (the step's own blocks are off the road's rate,
/// not straight) by -3.8 deg when each stop block was dated alone; by 0.4 deg since the
/// stop's blocks are dated as one change and the guard judges each hypothesis (without
/// the bank's fastest, non-identifiable pair, either alone failed: -7.8 deg, bias 0.178).
#[test]
fn a_step_just_before_a_stop_is_not_spread_over_the_past() {
    let n = 680;
    let wobble = |i: usize| if (20..660).contains(&i) { 0.1 * ((i as f64) * 0.9).sin() } else { 0.0 };
    let bias = |i: usize| if i >= 650 { 0.2 } else { 0.0 };
    let blocks = Blocks {
        time_s: (0..n).map(|i| i as f64).collect(),
        rate_dps: (0..n).map(|i| bias(i) + wobble(i)).collect(),
        temp_c: vec![f64::NAN; n],
        still: (0..n).map(|i| !(20..660).contains(&i)).collect(),
        first_moving_s: None,
        source: crate::still::StillSource::Speed,
    };
    let tr = run_blocks(&blocks, PipelineParams::default(), 20.0).unwrap();
    let err = |i: usize| tr.heading_deg[i] - (1..=i).map(wobble).sum::<f64>();
    let moved = err(n - 1) - err(649);
    assert!(moved.abs() < 2.0, "heading error moved by {moved} deg across the step and stop");
    assert!((tr.bias_dps[n - 1] - 0.2).abs() < 0.01, "bias {}", tr.bias_dps[n - 1]);
}

/// Causal heading [0, 1, 2, 2.4, 3.4] with rate 1 and a stop at block 3 (its correction
/// -0.6). The smoothed bias 0.1 integrates to 2.7 by block 3, 0.3 more than the causal 2.4:
/// blocks 1-3 take 0.1 + 0.3 / 3 = 0.2, so the smoothed heading [0, 0.8, 1.6, 2.4] meets the
/// causal one there; after the last stop, block 4 keeps 0.1 (heading 3.3).
#[test]
fn smoothed_heading_is_held_to_the_causal_one_at_stops_hand_worked() {
    let tr = PipelineTrace {
        time_s: vec![0.0, 1.0, 2.0, 3.0, 4.0],
        heading_deg: vec![0.0, 1.0, 2.0, 2.4, 3.4],
        stop: vec![false, false, false, true, false],
        ..Default::default()
    };
    let mut b = vec![0.1; 5];
    hold_to_stops(&tr, &[1.0; 5], &mut b);
    let want = [0.1, 0.2, 0.2, 0.2, 0.1];
    assert!(b.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-12), "{b:?}");
}

/// Arbitrary block sequences for the property tests: (duration s, rate deg/s, still), rates
/// far beyond any bias, stops anywhere, irregular times.
fn any_blocks(max_len: usize) -> impl proptest::strategy::Strategy<Value = Vec<(f64, f64, bool)>> {
    proptest::collection::vec((0.2f64..3.0, -40.0f64..40.0, proptest::prelude::any::<bool>()), 1..max_len)
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]
    /// No divergence by construction, whatever the gyro does: on any finite block sequence
    /// (rates far beyond any bias, stops in turns, irregular block times) every output is
    /// finite, and the bias estimate, causal and smoothed, stays within the widest bias the
    /// filter accepts about the turn-on bias the lead-in showed (it learns only from stops
    /// and straight-road modes plausible as a bias; without the projection in `bias()` a
    /// warm-up term fitted to a fast change extrapolated to 10 deg/s here).
    #[test]
    fn never_diverges_on_any_block_sequence(
        blocks in any_blocks(400),
        lead_in_s in 0.0f64..30.0,
    ) {
        let p = PipelineParams::default();
        let mut f = Pipeline::new(p, 0.0, p.prior_bias_sigma_dps, lead_in_s).unwrap();
        f.record((0..params::N_MODELS).collect());
        let mut t = 0.0;
        for (dt, rate, still) in blocks {
            t += dt;
            let centre = f.centre_dps();
            let o = f.update(t, rate, still).unwrap();
            proptest::prop_assert!(o.heading_deg.is_finite() && o.bias_sigma_dps.is_finite() && o.heading_sigma_deg.is_finite() && o.heading_sigma_deg >= 0.0);
            proptest::prop_assert!((o.bias_dps - centre).abs() <= p.max_bias_dps + 1e-9, "bias {} at {t} s", o.bias_dps);
        }
        for b in f.smoothed_bias() {
            proptest::prop_assert!(b.is_finite() && (b - f.centre_dps()).abs() <= p.max_bias_dps + 1e-9, "smoothed bias {b}");
        }
    }

    /// The whole run bounded too, the smoothed bias after it is held to the causal heading at
    /// stops included: the hold shifts a span's bias by whatever the causal heading did over
    /// it, and reached 9.8 deg/s across a declared lead-in that covers a turn, -6.0 after a
    /// turn into a stop with a slow rotation (below), before it was projected after the hold.
    #[test]
    fn the_whole_run_is_bounded_smoothed_bias_after_the_hold_included(
        items in any_blocks(300),
        lead_in_s in 0.0f64..30.0,
    ) {
        let p = PipelineParams::default();
        let blocks = blocks_of(&items);
        let tr = run_blocks(&blocks, p, lead_in_s).unwrap();
        // The turn-on bias is a mean of lead-in or stop blocks: at most their largest rate.
        let lead_max = (0..blocks.len()).filter(|&i| blocks.time_s[i] < lead_in_s || blocks.still[i]).map(|i| blocks.rate_dps[i].abs()).fold(0.0, f64::max);
        // Both headings' biases are the bank's (causal, or smoothed and projected after the
        // hold), bounded as that, moved by the blend by less than the guard: the mean of moves
        // each within blend_sigmas of the bank's causal sigma, grown as the blend's walk since
        // the last stop (at most since the start).
        for i in 0..tr.time_s.len() {
            let grown = p.blend_walk_dps_per_sqrt_s.powi(2) * (tr.time_s[i] - tr.time_s[0]);
            let bound = p.max_bias_dps + lead_max + p.blend_sigmas * (tr.bias_sigma_dps[i].powi(2) + grown).sqrt();
            for (what, x, h) in [("causal", tr.bias_dps[i], tr.heading_deg[i]), ("smoothed", tr.bias_smoothed_dps[i], tr.heading_smoothed_deg[i])] {
                proptest::prop_assert!(x.is_finite() && x.abs() <= bound && h.is_finite(), "{what} bias {x} beyond {bound}, heading {h}");
            }
        }
    }
}

#[test]
fn a_lead_in_block_with_no_plausible_bias_is_not_evidence() {
    // Declared lead-in of 10 s; the vehicle turns at 12 deg/s in it (the header was wrong):
    // that block must not set the bias, the still blocks at 0.4 deg/s must.
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 10.0).unwrap();
    for t in 0..9 {
        f.update(t as f64, if t == 4 { 12.0 } else { 0.4 }, true).unwrap();
    }
    let (b, _) = f.bias();
    assert!((b - 0.4).abs() < 0.01, "bias {b}");
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

#[test]
fn a_turn_into_a_stop_leaves_the_smoothed_bias_bounded() {
    // The property test's shrunk case: 30 s straight, a 40 deg/s block, then a stop whose
    // blocks read -3.9 and -4.1 deg/s (plausible, steady): without the projection after the
    // hold the smoothed bias reached -6.0 deg/s.
    let mut items = vec![(2.0, 0.0, false); 15];
    items.extend([(2.3, 39.6, false), (2.2, 0.0, true), (2.4, -3.93, true), (1.3, -4.15, true), (1.8, 0.0, true)]);
    let tr = run_blocks(&blocks_of(&items), PipelineParams::default(), 0.0).unwrap();
    assert!(tr.bias_smoothed_dps.iter().all(|x| x.abs() <= 5.0), "{:?}", tr.bias_smoothed_dps);
}

#[test]
fn a_declared_lead_in_that_outlasts_the_standing_is_judged_steady_like_a_stop() {
    // `bias_s: 10`, but the car pulls away into a slow 3 deg/s turn after 5 s: the turn's
    // blocks are plausible as a bias (under 5 deg/s) but not steady with the standing
    // ones, so the bias stays the standing rate (0.4; 1.68 with the lead-in exempt).
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 10.0).unwrap();
    for t in 0..9 {
        f.update(t as f64, if t < 5 { 0.4 } else { 3.0 }, true).unwrap();
    }
    let (b, _) = f.bias();
    assert!((b - 0.4).abs() < 0.01, "bias {b}");
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

/// A standing that goes on after the declared lead-in, the car pulling away into a turn
/// while the GPS speed still reads zero (the VN-100 circle with the 20 s default lead-in):
/// the stop's blocks after the lead-in are steady as the lead-in's are, so the turn's
/// 3.3 deg/s is not a bias. Before, the stop started afresh at the lead-in's end, its one
/// block left after trimming had nothing to be steady with, and the bias went to 0.86
/// deg/s (NE_psi 18.5 deg/min where raw integration had 1.8).
#[test]
fn a_standing_that_goes_on_after_the_lead_in_is_judged_steady_with_it() {
    let mut f = after_lead_in(0.01, 0.01);
    for (i, w) in [0.3, 3.3, 9.0].into_iter().enumerate() {
        f.update(20.0 + i as f64, w, true).unwrap();
    }
    for i in 23..30 {
        f.update(i as f64, 14.0, false).unwrap();
    }
    let (b, _) = f.bias();
    assert!(b.abs() < 0.05, "bias {b}");
}

/// A drive that never stops counts +0 s of stops: an empty float sum is -0 in Rust, which
/// the CLI printed as "-0 s counted".
#[test]
fn a_drive_without_stops_counts_plus_zero_seconds_of_stops() {
    let mut csv = String::from("# bias_s: 0\ntime_s,gyro_dps,ref_heading_deg,speed_mps\n");
    for i in 0..120 {
        csv.push_str(&format!("{i},0.1,{},10\n", -0.1 * i as f64));
    }
    let log = crate::parse_log_str(&csv).unwrap();
    let r = run(&log, &PipelineParams::default()).unwrap().result.unwrap();
    assert_eq!(r.stop_s, 0.0);
    assert!(r.stop_s.is_sign_positive(), "{}", r.stop_s);
}

/// A declared 20 s lead-in over a car that stands 5 s (bias 0.1 deg/s) and then drives a
/// steady 0.25 deg/s curve (within the lead-in's steadiness tolerance, 0.3 deg/s): the
/// speed ends the lead-in, so the curve is not taken as the bias; with the speed column
/// gone (nothing says it moved) the whole 20 s is lead-in and the bias is pulled toward
/// the curve.
#[test]
fn the_speed_ends_a_declared_lead_in_that_outlasts_the_standing() {
    use crate::log::{Column, DriveLog};
    let build = |with_speed: bool| {
        let cols: &[Column] = if with_speed { &[Column::GyroDps, Column::SpeedMps] } else { &[Column::GyroDps] };
        let mut log = DriveLog::with_columns(cols);
        log.meta.bias_s = Some(20.0);
        for i in 0..300 {
            let t = i as f64 * 0.1;
            let moving = t >= 5.0;
            let w = 0.1 + if moving { 0.25 } else { 0.0 } + if i % 2 == 0 { 0.01 } else { -0.01 };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w), (Column::SpeedMps, if moving { 10.0 } else { 0.0 })]);
        }
        log
    };
    let bias_at_19 = |log: &DriveLog| {
        let prep = crate::eval::Prepared::new(log, None, &PipelineParams::default().still).unwrap();
        let tr = prep.pipeline_trace(&PipelineParams::default()).unwrap();
        (prep.lead_in_end_s(), tr.bias_dps[20])
    };
    let (end, b) = bias_at_19(&build(true));
    assert!((end - 5.9).abs() < 1e-9, "the lead-in ends with block 5 (rows 5.0-5.9): {end}");
    assert!(b < 0.15, "bias {b}: near the standing's (0.127: the road evidence from 6 s on pulls a little)");
    let (end, b) = bias_at_19(&build(false));
    assert_eq!(end, 20.0);
    assert!(b > 0.2, "bias {b}: the curve taken as standing (0.313)");
}

/// A turn-on bias beyond `max_bias_dps` (7 deg/s: an uncalibrated MEMS part) that the
/// declared lead-in shows is learned, as the static bias takes it, and the stops and
/// straights after it are judged about it. Before, every block was refused as a turn and
/// the bias stayed 0 (E_psi in the thousands of degrees where raw integration had 33).
#[test]
fn a_turn_on_bias_beyond_max_bias_that_the_lead_in_shows_is_learned() {
    let mut f = after_lead_in(7.0, 0.02);
    let wiggle = |i: usize| if i.is_multiple_of(2) { 0.02 } else { -0.02 };
    assert!((f.bias().0 - 7.0).abs() < 0.01 && (f.centre_dps() - 7.0).abs() < 0.01, "bias {:?}, centre {}", f.bias(), f.centre_dps());
    // 200 s of road at 7.05 (a 0.05 deg/s warm-up), with turns; then a stop at 7.05.
    for i in 20..220 {
        let turn = if (i / 15) % 4 == 3 { 12.0 } else { 0.0 };
        f.update(i as f64, 7.05 + turn + wiggle(i), false).unwrap();
    }
    for i in 220..240 {
        f.update(i as f64, 7.05 + wiggle(i), true).unwrap();
    }
    assert!((f.bias().0 - 7.05).abs() < 0.01, "bias {:?}", f.bias());
}

/// Without a lead-in, a turn-on bias beyond `max_bias_dps` (8 deg/s) is acquired at the
/// first standing of 10 s or more (a road vehicle does not turn at 8 deg/s for that long
/// while its speed says it stands), not refused for good; a shorter standing at that rate
/// (a slow turn with the GPS speed held at zero) is not evidence.
#[test]
fn without_a_lead_in_a_long_standing_beyond_max_bias_is_the_bias() {
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, f64::NEG_INFINITY).unwrap();
    let wiggle = |i: usize| if i.is_multiple_of(2) { 0.02 } else { -0.02 };
    let mut t = 0.0;
    let mut drive = |f: &mut Pipeline, n: usize, still: bool| {
        for i in 0..n {
            t += 1.0;
            let turn = if !still && (i / 15) % 4 == 3 { 12.0 } else { 0.0 };
            f.update(t, 8.0 + turn + wiggle(i), still).unwrap();
        }
    };
    drive(&mut f, 120, false);
    drive(&mut f, 8, true);
    assert!(f.bias().0.abs() <= 5.0 && f.centre_dps() == 0.0, "a short standing: {:?}", f.bias());
    drive(&mut f, 60, false);
    drive(&mut f, 15, true);
    assert!((f.bias().0 - 8.0).abs() < 0.02 && (f.centre_dps() - 8.0).abs() < 0.02, "{:?}, centre {}", f.bias(), f.centre_dps());
}

/// On a simulated drive cut from its lead-in, a constant added that takes the turn-on bias
/// beyond `max_bias_dps` (+6 deg/s: about 7.5) is acquired at the first long stop: far
/// better than a zero-rate update at stops (before, the pipeline equalled raw integration,
/// 224 deg/min on the city drive of the probe).
#[test]
fn a_large_bias_without_a_lead_in_is_acquired_on_a_simulated_drive() {
    let cfg = crate::sim::DriveConfig { scenario: crate::sim::Scenario::City, minutes: 10.0, seed: 5 };
    let mut log = crate::sim::drive::simulate_drive(&cfg);
    log.retain_rows(|t| t >= 20.0);
    log.meta.bias_s = Some(0.0);
    log.column_mut(crate::log::Column::GyroDps).unwrap().iter_mut().for_each(|w| *w += 6.0);
    let r = run(&log, &PipelineParams::default()).unwrap().result.unwrap();
    let (pipe, zaru, raw) = (r.NE_psi_pipeline_deg_per_min, r.NE_psi_zaru_deg_per_min, r.NE_psi_raw_deg_per_min);
    assert!(pipe < 0.2 * zaru && pipe < 0.05 * raw, "pipeline {pipe}, ZARU {zaru}, raw {raw}");
}

/// A first lead-in block far beyond any bias (a knock) is not evidence, and does not make
/// the steady blocks after it so: one block agreeing with nothing before it.
#[test]
fn a_knock_at_the_start_of_the_lead_in_is_not_evidence() {
    let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 10.0).unwrap();
    for t in 0..9 {
        f.update(t as f64, if t == 0 { 12.0 } else { 0.4 }, true).unwrap();
    }
    assert!((f.bias().0 - 0.4).abs() < 0.01, "bias {:?}", f.bias());
}

/// On a simulated drive with known truth, a constant added to the gyro that the lead-in
/// measures changes the pipeline's NE_psi by little, within the old bound (+2 deg/s) and
/// beyond it (+6 deg/s: a turn-on bias of about 7.5; before, NE_psi went from 0.5 to 160).
#[test]
fn a_constant_the_lead_in_measures_barely_changes_the_result() {
    let cfg = crate::sim::DriveConfig { scenario: crate::sim::Scenario::City, minutes: 8.0, seed: 5 };
    let ne = |add: f64| {
        let mut log = crate::sim::drive::simulate_drive(&cfg);
        log.column_mut(crate::log::Column::GyroDps).unwrap().iter_mut().for_each(|w| *w += add);
        run(&log, &PipelineParams::default()).unwrap().result.unwrap().NE_psi_pipeline_deg_per_min
    };
    let base = ne(0.0);
    for add in [2.0, -2.0, 6.0, -6.0] {
        let got = ne(add);
        assert!((got - base).abs() <= 0.1 * base + 0.02, "+{add} deg/s: NE_psi {got} against {base}");
    }
}

/// The mode moves with a constant added to the sample (a turn-on bias the lead-in measured
/// shifts every block alike): equal widths on a quantised lattice must stay equal when the
/// constant rounds their differences apart by 1e-16. Both samples are cases where the mode
/// jumped by 0.02-0.07 deg/s (found by search): ties broken by rounding, and the three-value
/// end compared exactly.
#[test]
fn half_sample_mode_moves_with_a_constant_added() {
    let tied = [0.175, 0.175, 0.025, 0.15, 0.075, 0.05, 0.125, 0.05];
    let three = [0.05, 0.1, 0.075, 0.175, 0.15];
    for (x, c) in [(&tied[..], 2.0), (&three[..], -1.0)] {
        let m = half_sample_mode(&mut x.to_vec());
        let shifted = half_sample_mode(&mut x.iter().map(|v| v + c).collect::<Vec<_>>()) - c;
        assert!((shifted - m).abs() < 1e-9, "{x:?} + {c}: {m} against {shifted}");
    }
}

proptest::proptest! {
    /// The same on any sample of a 0.025 deg/s lattice, any constant.
    #[test]
    fn half_sample_mode_is_offset_invariant_on_a_lattice(
        k in proptest::collection::vec(-6i32..6, 1..30),
        c in -6.0f64..6.0,
    ) {
        let x: Vec<f64> = k.iter().map(|&k| 0.1 + 0.025 * k as f64).collect();
        let m = half_sample_mode(&mut x.clone());
        let shifted = half_sample_mode(&mut x.iter().map(|v| v + c).collect::<Vec<_>>()) - c;
        proptest::prop_assert!((shifted - m).abs() < 1e-9, "{:?} + {}: {} against {}", x, c, m, shifted);
    }
}
