use super::*;

const EPS: f64 = 1e-12;

fn close(a: f64, b: f64) {
    assert!((a - b).abs() < EPS * (1.0 + b.abs()), "{a} != {b}");
}

#[test]
fn sign_is_three_valued() {
    assert_eq!(sign(2.0), 1.0);
    assert_eq!(sign(-0.1), -1.0);
    assert_eq!(sign(0.0), 0.0);
    assert_eq!(sign(-0.0), 0.0);
}

#[test]
fn attenuation_eq10_hand_worked() {
    // r = 1: (1 + c1) / (1 + c1) = 1
    assert_eq!(attenuation(0.16, 1.8, 1), 1.0);
    // r = 2, c2 = 2: 1.16 / (1 + 0.16 * 4) = 1.16 / 1.64
    close(attenuation(0.16, 2.0, 2), 1.16 / 1.64);
    // r = 10, c1 = 1, c2 = 1: 2 / 11
    close(attenuation(1.0, 1.0, 10), 2.0 / 11.0);
}

#[test]
fn r_table_matches_powf_bit_for_bit() {
    // The lookup inside the step itself: a steady small positive rate and a tiny gain keep
    // the sign, so r counts up through the first table (256), its doublings and past the
    // cap (2^20), where powf takes over. Every step's R must equal Eq. 10 to the bit.
    let p = HdrParams { i_c_dps: 1e-12, ..HdrParams::default() };
    assert_eq!(attenuation(p.c1, p.c2, 1), 1.0, "R(1) = 1 exactly, used as the reset value");
    let n = R_TABLE_MAX + 1000;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.01).collect();
    let w = vec![0.1; n];
    let mut h = Hdr::new(p, 0.0).unwrap();
    let (mut checked, mut max_r) = (0usize, 0u64);
    h.update_slice(&t, &w, |o| {
        if o.r > 1 {
            assert_eq!(o.attenuation.to_bits(), attenuation(p.c1, p.c2, o.r).to_bits(), "r = {}", o.r);
            checked += 1;
            max_r = max_r.max(o.r);
        }
    })
    .unwrap();
    assert!(max_r > R_TABLE_MAX as u64 && checked > R_TABLE_MAX, "r reached {max_r}");
    // The streaming path shares the step: spot-check it across the first boundary.
    let mut g = Hdr::new(p, 0.0).unwrap();
    for k in 0..300 {
        let o = g.update(k as f64 * 0.01, 0.1).unwrap();
        assert_eq!(o.attenuation.to_bits(), attenuation(p.c1, p.c2, o.r).to_bits());
    }
}

#[test]
fn params_validation() {
    assert!(HdrParams::default().validate().is_ok());
    let bad = [
        HdrParams { tau_s: -0.1, ..Default::default() },
        HdrParams { i_c_dps: -1.0, ..Default::default() },
        HdrParams { c1: 0.0, ..Default::default() },
        HdrParams { c1: -1.0, ..Default::default() },
        HdrParams { theta_w_dps: f64::NAN, ..Default::default() },
        HdrParams { c2: f64::INFINITY, ..Default::default() },
    ];
    for p in bad {
        assert!(matches!(p.validate(), Err(Error::Param { .. })), "{p:?}");
    }
    let e = HdrParams { tau_s: -0.1, ..Default::default() }.validate().unwrap_err();
    assert_eq!(e.to_string(), "parameter tau: -0.1 is not a time in [0, 3600] s");
    let e = HdrParams { i_c_dps: 1e300, ..Default::default() }.validate().unwrap_err();
    assert_eq!(e.to_string(), "parameter i_c: 1e300 is not a rate in [0, 10] deg/s");
}

#[test]
fn first_steps_value_by_value() {
    // Parameters chosen for hand arithmetic: i_c = 0.1, tau = 1, theta_w = 0.5, c1 = 1, c2 = 1.
    // eps0 = 1; raw rates 1.2, 1.0, 0.8, 3.0 at t = 0, 1, 2, 3 (T = 1 s).
    let p = HdrParams { i_c_dps: 0.1, tau_s: 1.0, theta_w_dps: 0.5, c1: 1.0, c2: 1.0 };
    let mut h = Hdr::new(p, 1.0).unwrap();
    // i = 0: x = 0.2; w_f = 0.2; omega_0 = 0.2; psi 0.
    let o0 = h.update(0.0, 1.2).unwrap();
    close(o0.rate_filtered_dps, 0.2);
    close(o0.rate_corrected_dps, 0.2);
    assert_eq!(o0.heading_deg, 0.0);
    assert_eq!(o0.r, 1);
    // i = 1: x = 0; w_f = (0*1 + 1*0.2)/2 = 0.1; W = |0.2| < 0.5 -> 1;
    // r = 2 (omega_{-1} := omega_0); R = 2/(1+2) = 2/3; I = 0 - 1 * 2/3 * 0.1 = -1/15;
    // omega = 0.1 - 1/15 = 1/30; omega_d = 1/30 + (1/30 - 0.2) = -2/15; psi = -2/15.
    let o1 = h.update(1.0, 1.0).unwrap();
    close(o1.rate_filtered_dps, 0.1);
    assert!(o1.turn_switch);
    assert_eq!(o1.r, 2);
    close(o1.attenuation, 2.0 / 3.0);
    close(o1.i_dps, -1.0 / 15.0);
    close(o1.rate_corrected_dps, 1.0 / 30.0);
    close(o1.rate_delag_dps, -2.0 / 15.0);
    close(o1.heading_deg, -2.0 / 15.0);
    // i = 2: x = -0.2; w_f = (-0.2 + 0.1)/2 = -0.05; W: |1/30| < 0.5 -> 1;
    // sign(omega_1) = sign(omega_0) = + -> r = 3, R = 2/4 = 0.5;
    // I = -1/15 - 0.5*0.1 = -7/60; omega = -0.05 - 7/60 = -1/6;
    // omega_d = -1/6 + (-1/6 - 1/30) = -11/30; psi = -2/15 - 11/30 = -1/2.
    let o2 = h.update(2.0, 0.8).unwrap();
    close(o2.rate_filtered_dps, -0.05);
    assert_eq!(o2.r, 3);
    close(o2.attenuation, 0.5);
    close(o2.i_dps, -7.0 / 60.0);
    close(o2.rate_corrected_dps, -1.0 / 6.0);
    close(o2.rate_delag_dps, -11.0 / 30.0);
    close(o2.heading_deg, -0.5);
    // i = 3: x = 2; w_f = (2 - 0.05)/2 = 0.975; W: |-1/6| < 0.5 -> 1;
    // sign(omega_2) = - != sign(omega_1) = + -> r = 1, R = 1; I = -7/60 + 0.1 = -1/60;
    // omega = 0.975 - 1/60 = 0.958333..; omega_d = omega + (omega + 1/6) ; psi += omega_d.
    let o3 = h.update(3.0, 3.0).unwrap();
    assert_eq!(o3.r, 1);
    close(o3.i_dps, -1.0 / 60.0);
    let omega3 = 0.975 - 1.0 / 60.0;
    close(o3.rate_corrected_dps, omega3);
    close(o3.rate_delag_dps, omega3 + (omega3 + 1.0 / 6.0));
    close(o3.heading_deg, -0.5 + omega3 + (omega3 + 1.0 / 6.0));
    // i = 4: |omega_3| = 0.958 >= 0.5 -> switch off, I unchanged.
    let o4 = h.update(4.0, 1.0).unwrap();
    assert!(!o4.turn_switch);
    close(o4.i_dps, -1.0 / 60.0);
}

#[test]
fn i_c_scales_with_sample_interval() {
    // Eq. 11 with T = 0.5 s: the increment is i_c * 0.5.
    let p = HdrParams { i_c_dps: 0.1, tau_s: 0.0, theta_w_dps: 1.0, c1: 1.0, c2: 0.0 };
    let mut h = Hdr::new(p, 0.0).unwrap();
    h.update(0.0, 0.3).unwrap();
    let o = h.update(0.5, 0.3).unwrap();
    // c2 = 0 -> R = 1 always; I = -0.1 * 0.5
    close(o.i_dps, -0.05);
    // tau = 0: w_f = x; omega = 0.3 - 0.05; de-lag term is 0; psi = 0.25 * 0.5
    close(o.heading_deg, 0.125);
}

#[test]
fn update_rejects_bad_time_and_rate() {
    let mut h = Hdr::new(HdrParams::default(), 0.0).unwrap();
    h.update(1.0, 0.0).unwrap();
    assert!(h.update(1.0, 0.0).is_err());
    assert!(h.update(0.5, 0.0).is_err());
    assert!(h.update(2.0, f64::NAN).is_err());
    // state unchanged by the rejected samples
    assert!(h.update(2.0, 0.0).is_ok());
}

#[test]
fn raw_integrator_hand_worked() {
    let mut r = RawIntegrator::new(0.5);
    assert_eq!(r.update(0.0, 9.0), 0.0);
    assert_eq!(r.update(1.0, 1.5), 1.0);
    assert_eq!(r.update(3.0, 0.0), 0.0);
}

#[test]
fn options_by_name() {
    let set: Vec<(String, f64)> = [("i_c", 0.01), ("tau", 2.0), ("theta_w", 0.3), ("c1", 0.5), ("c2", 1.0), ("bias_s", 10.0)]
        .map(|(k, v)| (k.to_string(), v))
        .to_vec();
    let o: HdrOptions = crate::options::from_pairs(&set).unwrap();
    assert_eq!(o.params, HdrParams { i_c_dps: 0.01, tau_s: 2.0, theta_w_dps: 0.3, c1: 0.5, c2: 1.0 });
    assert_eq!(o.bias_s, Some(10.0));
    assert!(o.resample);
    assert!(crate::options::from_pairs::<HdrOptions>(&[("gain".into(), 1.0)]).is_err());
    assert!(crate::options::from_pairs::<HdrOptions>(&[("bias_s".into(), -1.0)]).is_err());
    assert!(crate::options::from_pairs::<HdrOptions>(&[("c1".into(), 0.0)]).is_err());
}

#[test]
fn options_deserialize_with_defaults_and_aliases() {
    let o: HdrOptions = serde_json::from_str(r#"{"i_c": 0.01, "resample": false}"#).unwrap();
    assert_eq!(o.params.i_c_dps, 0.01);
    assert_eq!(o.params.tau_s, 0.75);
    assert!(!o.resample);
    let o: HdrOptions = serde_json::from_str(r#"{"tau_s": 1.5}"#).unwrap();
    assert_eq!(o.params.tau_s, 1.5);
    assert!(serde_json::from_str::<HdrOptions>(r#"{"tau_s": "x"}"#).is_err());
}

mod serde_options {
    #[test]
    fn unknown_option_is_rejected() {
        let e = serde_json::from_str::<super::super::HdrOptions>(r#"{"taus": 1.0}"#).unwrap_err();
        assert!(e.to_string().contains("unknown field `taus`"), "{e}");
    }
}

/// A preparation reused across parameters gives the plain run's numbers bit for bit; one
/// made for another lead-in is refused.
#[test]
fn prepared_runs_equal_plain_runs() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/city-1.csv")).unwrap();
    let log = crate::parse_log_str(&text).unwrap();
    let base = HdrOptions::default();
    let prep = prepare(&log, &base).unwrap();
    for i_c in [0.0, 0.01, 0.0422, 0.1] {
        let opts = HdrOptions { params: HdrParams { i_c_dps: i_c, ..base.params }, ..base };
        let a = run(&log, &opts).unwrap();
        let b = run_prepared(&log, &prep, &opts).unwrap();
        assert_eq!(a.result, b.result, "i_c {i_c}");
        assert_eq!(a.trace.heading_hdr_deg, b.trace.heading_hdr_deg);
        let (_, e1) = a.errors(&log).unwrap();
        let e2 = b.errors_against(prep.reference.as_ref().unwrap()).unwrap();
        assert_eq!(e1.errors_deg, e2.errors_deg);
    }
    let other = HdrOptions { bias_s: Some(5.0), ..base };
    assert!(!prep.fits(&other));
    assert!(run_prepared(&log, &prep, &other).unwrap_err().to_string().contains("preparation"));
}

#[test]
fn update_slice_headings_equals_update_and_keeps_the_samples_before_an_error() {
    let t = [0.0, 0.1, 0.2, 0.3, 0.3, 0.5];
    let w = [1.0, 0.2, -0.3, 4.0, 1.0, 1.0];
    let mut a = Hdr::new(HdrParams::default(), 0.5).unwrap();
    let mut b = a.clone();
    let want: Vec<f64> = (0..4).map(|k| a.update(t[k], w[k]).unwrap().heading_deg).collect();
    let (mut got, mut last) = (vec![9.0], None);
    let e = b.update_slice_headings(&t, &w, &mut got, &mut last).unwrap_err();
    assert!(e.to_string().contains("time"), "{e}");
    assert_eq!(got[0], 9.0, "appended, not overwritten");
    assert_eq!(&got[1..], &want[..]);
    assert_eq!(last.unwrap().heading_deg, want[3]);
    // The state is the one after the fourth sample: the next sample continues from it.
    assert_eq!(b.update(0.6, 1.0).unwrap().heading_deg, a.update(0.6, 1.0).unwrap().heading_deg);
}
