//! The half-sample mode the lead-in's static bias is taken with.

use super::*;

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
