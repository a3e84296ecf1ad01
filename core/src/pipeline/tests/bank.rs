//! The bank: its hypotheses, road and stop evidence, steps, acquisition without lock-out,
//! bad input.

use super::*;

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
    let p00 = 0.25 + 4.0 * 1e-6;
    let s = p00 + 0.09 + 0.0025;
    // The heading integrates rate - bias(before) = 0.3 deg/s over 4 s, less what the
    // evidence says that cost while the bank acquires its bias (no stop yet, sigma 0.5):
    // the integral's covariance with the bias, 0.25 + (0.25 + 1e-6) + (0.25 + 2e-6) +
    // (0.25 + 3e-6), times the innovation 0.3 over S.
    let cost = (1.0 + 6e-6) * 0.3 / s;
    assert!((o.heading_deg - (1.2 - cost)).abs() < 1e-12, "{} vs {}", o.heading_deg, 1.2 - cost);
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
        origin_s: 0.0,
        first_moving_s: None,
        lead_in_wander: None,
        source: crate::still::StillSource::Speed,
    };
    let tr = run_blocks(&blocks, PipelineParams::default(), 20.0).unwrap();
    let err = |i: usize| tr.heading_deg[i] - (1..=i).map(wobble).sum::<f64>();
    let moved = err(n - 1) - err(649);
    assert!(moved.abs() < 2.0, "heading error moved by {moved} deg across the step and stop");
    assert!((tr.bias_dps[n - 1] - 0.2).abs() < 0.01, "bias {}", tr.bias_dps[n - 1]);
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
    for (key, v) in [("blend_move_dps", -0.1), ("blend_move_dps", f64::NAN), ("blend_move_dps", 1e6)] {
        assert!(crate::options::from_pairs::<PipelineParams>(&[(key.into(), v)]).is_err(), "{key} {v}");
    }
}

#[test]
fn the_blend_guard_keeps_its_first_name_as_an_alias() {
    let by = |key: &str| crate::options::from_pairs::<PipelineParams>(&[(key.into(), 3.0)]).unwrap().blend_sigmas;
    assert_eq!((by("blend_sigmas"), by("hdr_blend_sigmas")), (3.0, 3.0));
    assert_eq!(PipelineParams::default().blend_sigmas, 2.0);
}

#[test]
fn a_bend_read_as_straight_moves_a_known_bias_a_bounded_step() {
    // One hypothesis with a narrow road (0.06 deg/s): a 20 s lead-in at 0.2 deg/s, a
    // straight road at that bias, then a 2.6 deg/s bend of 40 s. Once the bend fills most
    // of the 60 s road window its rate is the window's dominant one and its blocks pass as
    // straight, 30 sigma from the hypothesis. Taken at face value each moves the bias by
    // its gain times 2.4 deg/s; bounded, by its gain times 4 sigma of the prediction.
    let narrow = PipelineParams { road_sigma_dps: 0.06, ..one_model() };
    let run = |gaussian_road: bool| {
        let mut f = Pipeline::new(narrow, 0.0, 0.5, 20.0).unwrap();
        f.gaussian_road = gaussian_road;
        let (mut worst, mut steps): (f64, Vec<f64>) = (0.0, Vec::new());
        for t in 0..300 {
            let (rate, still) = match t {
                0..20 => (0.2, true),
                100..140 => (2.6, false),
                _ => (0.2 + 0.02 * ((t % 5) as f64 - 2.0), false),
            };
            let (b, p) = f.bias();
            let o = f.update(t as f64 + 1.0, rate, still).unwrap();
            if o.straight && rate > 1.0 {
                // The bound, near enough: gain P / S times 4 sqrt(S), S taken as P + the road
                // state's stationary variance + the block noise (the prediction adds a little).
                let s = p + 0.06 * 0.06 + 0.05 * 0.05;
                steps.push((f.bias().0 - b) / (4.0 * p / s.sqrt()));
            }
            worst = worst.max((f.bias().0 - 0.2).abs());
        }
        (worst, steps)
    };
    let (face_value, face_steps) = run(true);
    let (bounded, steps) = run(false);
    assert_eq!(steps.len(), 10, "the bend's last 10 blocks pass as straight: {steps:?}");
    assert!(face_steps[0] > 5.0, "at face value the first takes 7 bounds: {face_steps:?}");
    // (each a little under 1: the bound above is a little wider than the filter's own)
    assert!(steps.iter().all(|&k| k > 0.5 && k <= 1.0), "each within the bound, none refused: {steps:?}");
    assert!(bounded < 0.6 * face_value, "worst bias error {bounded} against {face_value}");
}
