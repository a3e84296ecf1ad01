//! The offline smoothed mode: constant biases, lead-ins, the hold to the causal heading at
//! stops, bounds.

use super::*;

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
        origin_s: 0.0,
        first_moving_s: None,
        lead_in_wander: None,
        source: crate::still::StillSource::Speed,
    };
    let tr = run_blocks(&blocks, PipelineParams::default(), f64::NEG_INFINITY).unwrap();
    let (es, ec) = ((tr.bias_smoothed_dps[3] - 0.1).abs(), (tr.bias_dps[3] - 0.1).abs());
    assert!(es < 0.005 && es < ec / 4.0, "smoothed error {es}, causal error {ec}");
    assert!((tr.bias_dps[n - 1] - 0.1).abs() < 0.005);
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
        origin_s: 0.0,
        first_moving_s: None,
        lead_in_wander: None,
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
