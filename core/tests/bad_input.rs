//! Bad input never panics: property tests over the parser and the estimators.
mod common;

use gyrodrift::hdr::{self, Hdr, HdrOptions, HdrParams};
use gyrodrift::{allan, calibration, gyrodometry, parse_log, parse_log_str};
use proptest::prelude::*;

/// Runs every method on a parsed log; errors are fine, panics are not.
fn run_everything(text: &str) {
    if let Ok(log) = parse_log_str(text) {
        let _ = hdr::run(&log, &HdrOptions::default());
        let _ = hdr::run(&log, &HdrOptions { resample: false, ..Default::default() });
        let _ = gyrodometry::run(&log, &gyrodometry::GyrodometryOptions { wheelbase_m: Some(0.5), ..Default::default() });
        let _ = calibration::run(&log, &calibration::CalibrationOptions { p: 1, q: 0, bias_s: Some(1.0) });
        let _ = allan::run(&log);
        let _ = gyrodrift::pipeline::run(&log, &Default::default());
        let _ = gyrodrift::pipeline::run(&log, &gyrodrift::pipeline::PipelineParams { bias_s: Some(0.0), ..Default::default() });
        let _ = gyrodrift::compare::compare(&[("x".into(), &log)], &Default::default(), None);
    }
}

fn cell() -> impl Strategy<Value = String> {
    prop_oneof![
        Just(String::new()),
        (-1e6f64..1e6).prop_map(|v| v.to_string()),
        (0u32..100).prop_map(|v| v.to_string()),
        Just("nan".to_string()),
        Just("1.2.3".to_string()),
        Just("-inf".to_string()),
        "[ -~]{0,6}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        if let Ok(log) = parse_log(&bytes[..]) {
            let _ = hdr::run(&log, &HdrOptions::default());
        }
    }

    #[test]
    fn csv_shaped_garbage_never_panics(
        header in proptest::sample::subsequence(vec!["time_s", "gyro_dps", "temp_c", "ref_heading_deg", "speed_mps", "odo_left_m", "odo_right_m", "table_rate_dps", "x"], 0..9).prop_shuffle(),
        rows in proptest::collection::vec(proptest::collection::vec(cell(), 0..10), 0..30),
        meta in proptest::option::of("# (bias_s|wheelbase_m|name): [ -~]{0,5}\n"),
    ) {
        let mut text = meta.unwrap_or_default();
        text.push_str(&header.join(","));
        text.push('\n');
        for r in &rows {
            text.push_str(&r.join(","));
            text.push('\n');
        }
        run_everything(&text);
    }

    #[test]
    fn valid_logs_run_and_give_finite_results(
        rates in proptest::collection::vec(-50f64..50.0, 12..200),
        dts in proptest::collection::vec(0.01f64..2.0, 200),
        bias in -3f64..3.0,
    ) {
        let mut text = String::from("time_s,gyro_dps,ref_heading_deg\n");
        let mut t = 0.0;
        for (i, w) in rates.iter().enumerate() {
            text.push_str(&format!("{t},{},{}\n", w + bias, (i * 7 % 360) as f64));
            t += dts[i];
        }
        let log = parse_log_str(&text).unwrap();
        for resample in [true, false] {
            let run = hdr::run(&log, &HdrOptions { resample, bias_s: Some(1.0), ..Default::default() }).unwrap();
            prop_assert!(run.trace.heading_hdr_deg.iter().all(|v| v.is_finite()));
            let r = run.result.unwrap();
            prop_assert!(r.E_psi_raw_deg.is_finite() && r.E_psi_hdr_deg.is_finite());
        }
    }

    #[test]
    fn hdr_parameters_in_range_never_fail(
        i_c in 0f64..1.0, tau in 0f64..5.0, theta_w in 0f64..5.0, c1 in 1e-3f64..5.0, c2 in 0f64..4.0,
        rates in proptest::collection::vec(-20f64..20.0, 1..100),
    ) {
        let mut h = Hdr::new(HdrParams { i_c_dps: i_c, tau_s: tau, theta_w_dps: theta_w, c1, c2 }, 0.1).unwrap();
        for (i, w) in rates.iter().enumerate() {
            let o = h.update(i as f64 * 0.5, *w).unwrap();
            prop_assert!(o.heading_deg.is_finite());
            prop_assert!(o.attenuation > 0.0 && o.attenuation <= 1.0 + 1e-12);
        }
    }

    #[test]
    fn out_of_range_parameters_are_errors(v in -10f64..-1e-9) {
        for key in ["i_c", "tau", "theta_w", "c1", "c2"] {
            let e = gyrodrift::options::from_pairs::<HdrOptions>(&[(key.to_string(), v)]).unwrap_err();
            prop_assert!(matches!(&e, gyrodrift::Error::Param { name, .. } if name == key), "{}", e);
        }
    }
}

#[test]
fn static_log_shorter_than_10_samples() {
    let log = parse_log_str("time_s,gyro_dps\n0,1\n0.1,1\n0.2,1\n").unwrap();
    let e = allan::run(&log).unwrap_err().to_string();
    assert_eq!(e, "too short for Allan deviation: 3 gyro samples (at least 10 are needed)");
}

#[test]
fn missing_gyro_column_names_it() {
    let log = parse_log_str("time_s,ref_heading_deg\n0,1\n").unwrap();
    let e = hdr::run(&log, &HdrOptions::default()).unwrap_err().to_string();
    assert_eq!(e, "missing column gyro_dps: needed for the yaw rate");
}
