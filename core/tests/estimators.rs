//! The estimators on logs with known truth.
mod common;

use gyrodrift::gyrodometry::{self, GyrodometryOptions};
use gyrodrift::hdr::{self, HdrOptions, HdrParams};
use gyrodrift::{calibration, parse_log_str, Column, DriveLog};

#[test]
fn zero_bias_gives_zero_raw_error_on_rows() {
    let log = common::drive(10.0, |_| 0.0);
    let opts = HdrOptions { resample: false, bias_s: Some(20.0), ..Default::default() };
    let r = hdr::run(&log, &opts).unwrap().result.unwrap();
    assert!(r.E_psi_raw_deg < 1e-9, "{}", r.E_psi_raw_deg);
    assert_eq!(r.eps0_dps, 0.0);
    assert_eq!(r.n_processed, 6001);
    assert_eq!(r.n_samples, 601);
}

#[test]
fn constant_bias_ramp_matches_closed_form() {
    // Straight drive, bias b from t = 0, no static-bias removal: raw heading = b (t - t_first).
    let b = 0.05;
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]);
    for i in 0..=6000 {
        let t = i as f64 / 10.0;
        let r = if i % 10 == 0 { 90.0 } else { f64::NAN };
        log.push_row(&[(Column::TimeS, t), (Column::GyroDps, b), (Column::RefHeadingDeg, r)]);
    }
    // Rows: reference at t = 0..600 s, aligned at t = 0: E = b * mean(0..600) = b * 300.
    let rows = HdrOptions { resample: false, bias_s: Some(0.0), ..Default::default() };
    let r = hdr::run(&log, &rows).unwrap().result.unwrap();
    assert!((r.E_psi_raw_deg - b * 300.0).abs() < 1e-9, "{}", r.E_psi_raw_deg);
    assert!((r.NE_psi_raw_deg_per_min - b * 300.0 / 10.0).abs() < 1e-10);
    let blocks = HdrOptions { resample: true, ..rows };
    let r = hdr::run(&log, &blocks).unwrap();
    let res = r.result.unwrap();
    // Closed form: psi(stamp_j) = b (stamp_j - 0.9) for j < 600; the last block (t = 600.0,
    // T = 0.1) adds b * 0.1 -> psi = b * 599.1. Errors vs aligned psi(1) = b * 0.1:
    // k = 1..599 -> b (k - 1); k = 600 -> b (599.1 - 0.1) = b * 599.
    let sum: f64 = (1..=599).map(|k| b * (k as f64 - 1.0)).sum::<f64>() + b * 599.0;
    assert!((res.E_psi_raw_deg - sum / 600.0).abs() < 1e-9, "{} vs {}", res.E_psi_raw_deg, sum / 600.0);
    assert_eq!(res.n_samples, 600);
    assert_eq!(res.n_processed, 601);
}

#[test]
fn hdr_removes_most_of_a_constant_drift() {
    // 1.5 deg/s zero-rate offset measured in the 20 s lead-in, then the bias drifts by
    // +0.02 deg/s (1.2 deg/min), as in the paper's warm-up: HDR should beat raw by far.
    let log = common::drive(20.0, |t| 1.5 + if t > 25.0 { 0.02 } else { 0.0 });
    let run = hdr::run(&log, &HdrOptions::default()).unwrap();
    let r = run.result.unwrap();
    assert!((r.eps0_dps - 1.5).abs() < 1e-12);
    assert!(r.E_psi_raw_deg > 5.0, "raw {}", r.E_psi_raw_deg);
    assert!(r.improvement > 3.0, "raw {} hdr {}", r.E_psi_raw_deg, r.E_psi_hdr_deg);
    // -I tracks the drift on the straights: at the end, -I is near 0.02 deg/s
    let last_i = *run.trace.i_dps.last().unwrap();
    assert!((-last_i - 0.02).abs() < 0.02, "-I = {}", -last_i);
}

#[test]
fn streaming_equals_batch() {
    let log = common::drive(5.0, |t| 0.3 + 0.001 * t);
    let opts = HdrOptions::default();
    let run = hdr::run(&log, &opts).unwrap();
    let (eps0, samples) = gyrodrift::preprocess::prepare(&log, None, true).unwrap();
    let mut est = hdr::Hdr::new(HdrParams::default(), eps0).unwrap();
    let shift = run.trace.heading_hdr_deg[0];
    for (i, (&t, &w)) in samples.time_s.iter().zip(&samples.rate_dps).enumerate() {
        let o = est.update(t, w).unwrap();
        assert_eq!((o.heading_deg + shift).to_bits(), run.trace.heading_hdr_deg[i].to_bits());
        assert_eq!(o.i_dps.to_bits(), run.trace.i_dps[i].to_bits());
    }
}

#[test]
fn csv_round_trip_gives_identical_results() {
    let log = common::drive(5.0, |t| 0.7 + 0.002 * t);
    let text = common::to_csv(&log);
    let back = parse_log_str(&text).unwrap();
    let a = hdr::run(&log, &HdrOptions::default()).unwrap().result.unwrap();
    let b = hdr::run(&back, &HdrOptions::default()).unwrap().result.unwrap();
    assert_eq!(a, b);
}

#[test]
fn no_reference_fails_metrics_but_estimators_run() {
    let text = "time_s,gyro_dps,ref_heading_deg\n0,0.1,\n1,0.2,\n2,0.1,\n";
    let log = parse_log_str(text).unwrap();
    let run = hdr::run(&log, &HdrOptions { resample: false, ..Default::default() }).unwrap();
    assert_eq!(run.trace.time_s.len(), 3);
    let e = run.result.unwrap_err().to_string();
    assert!(e.contains("no valid reference heading"), "{e}");
    let no_col = parse_log_str("time_s,gyro_dps\n0,0.1\n1,0.2\n").unwrap();
    let e = hdr::run(&no_col, &HdrOptions::default()).unwrap().result.unwrap_err().to_string();
    assert!(e.contains("ref_heading_deg"), "{e}");
}

#[test]
fn gyrodometry_rejects_bumps_on_a_robot_run() {
    // Straight 10 cm/s run, b = 0.5 m, 10 Hz; every 10 s a bump: the right wheel travels 1 cm
    // extra in one interval (1.15 deg of false odometry turn); gyro has noise-free truth + 0.01.
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::OdoLeftM, Column::OdoRightM, Column::RefHeadingDeg]);
    log.meta.wheelbase_m = Some(0.5);
    let (mut l, mut r) = (0.0, 0.0);
    for i in 0..=1200 {
        let t = i as f64 / 10.0;
        if i > 0 && t > 5.0 {
            l += 0.01;
            r += 0.01;
            if i % 100 == 50 {
                r += 0.01;
            }
        }
        let reference = if i % 10 == 0 { 0.0 } else { f64::NAN };
        log.push_row(&[
            (Column::TimeS, t),
            (Column::GyroDps, 0.01),
            (Column::OdoLeftM, l),
            (Column::OdoRightM, r),
            (Column::RefHeadingDeg, reference),
        ]);
    }
    let run = gyrodometry::run(&log, &GyrodometryOptions { bias_s: Some(0.0), ..Default::default() }).unwrap();
    let res = run.result.unwrap();
    assert_eq!(res.n_gyro_intervals, 11, "one per bump");
    let bump = 0.01f64 / 0.5 * 180.0 / std::f64::consts::PI;
    assert!((res.final_err_odo_deg - 11.0 * bump).abs() < 1e-9, "{}", res.final_err_odo_deg);
    assert!((res.final_err_gyro_deg - 0.01 * 120.0).abs() < 1e-9);
    // gyrodometry only takes the gyro's 0.001 deg in the 11 bump intervals
    assert!((res.final_err_gyrodometry_deg - 11.0 * 0.001).abs() < 1e-9, "{}", res.final_err_gyrodometry_deg);
    assert!(res.E_psi_gyrodometry_deg < res.E_psi_odo_deg / 50.0);
}

#[test]
fn calibration_recovers_a_known_error_model() {
    // Turntable, 10 Hz: 20 s still at 25 C, then nominal rates -100..100 deg/s in 10 deg/s steps
    // at 25, 35, 45 C, 10 s per set. The error e(w_g, T) is an exact polynomial of the gyro
    // output (the model's form), so the table rate is w = w_g - e(w_g, T) (Eq. 2); no noise.
    let err = |wg: f64, temp: f64| 0.8 + 0.01 * (temp - 25.0) + 0.002 * wg + 1e-6 * wg * wg * wg + 2e-6 * (temp - 25.0) * wg;
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::TempC, Column::TableRateDps]);
    let mut i = 0;
    let mut push = |log: &mut DriveLog, wg: f64, w: f64, temp: f64, secs: f64| {
        for _ in 0..(secs * 10.0) as usize {
            log.push_row(&[(Column::TimeS, i as f64 / 10.0), (Column::GyroDps, wg), (Column::TempC, temp), (Column::TableRateDps, w)]);
            i += 1;
        }
    };
    // still: table rate 0, gyro output the fixed point w_g = e(w_g, 25)
    let mut wg0 = 0.0;
    for _ in 0..50 {
        wg0 = err(wg0, 25.0);
    }
    push(&mut log, wg0, 0.0, 25.0, 20.0);
    let mut sets = vec![];
    for temp in [25.0, 35.0, 45.0] {
        for k in -10..=10 {
            let wg = k as f64 * 10.0;
            let w = wg - err(wg, temp);
            push(&mut log, wg, w, temp, 10.0);
            sets.push((wg, w, temp));
        }
    }
    let run = calibration::run(&log, &calibration::CalibrationOptions { bias_s: Some(20.0), ..Default::default() }).unwrap();
    let r = &run.result;
    assert_eq!(r.n_sets, 1 + 63);
    assert!(r.fit_residual_rms_dps < 1e-9, "{}", r.fit_residual_rms_dps);
    assert!(r.residual_rms_compensated_dps < 1e-9, "{}", r.residual_rms_compensated_dps);
    assert!((r.w_s_dps - wg0).abs() < 1e-12, "Eq. 1");
    assert!(r.w_s_star_dps.abs() < 1e-9, "Eq. 15");
    assert!(r.turn360_err_compensated_max_deg < 1e-6);
    // static only: residual = (w_g - w_s) - w = e(w_g, T) - w_s; Eq. 14 per set with |w| >= 5
    let so: Vec<f64> = sets.iter().filter(|s| s.1.abs() >= 5.0).map(|&(wg, w, t)| (err(wg, t) - wg0) * 360.0 / w.abs()).collect();
    let max = so.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let rms = (so.iter().map(|v| v * v).sum::<f64>() / so.len() as f64).sqrt();
    assert!((r.turn360_err_static_only_max_deg - max).abs() < 1e-9, "{} vs {max}", r.turn360_err_static_only_max_deg);
    assert!((r.turn360_err_static_only_rms_deg - rms).abs() < 1e-9);
    // residual at the sets, static only, includes the lead-in set (0 error by construction)
    let all: Vec<f64> = std::iter::once(0.0).chain(sets.iter().map(|&(wg, _, t)| err(wg, t) - wg0)).collect();
    let rms_all = (all.iter().map(|v| v * v).sum::<f64>() / all.len() as f64).sqrt();
    assert!((r.residual_rms_static_only_dps - rms_all).abs() < 1e-9);
    assert_eq!(r.c.len(), 3);
    assert_eq!(r.c[0].len(), 4);
}

#[test]
fn calibration_with_too_few_sets_or_no_temperature_is_an_error() {
    let text = "time_s,gyro_dps,temp_c,table_rate_dps\n0,0.1,25,0\n1,10.1,25,10\n2,20.1,25,20\n";
    let log = parse_log_str(text).unwrap();
    let e = calibration::run(&log, &Default::default()).unwrap_err().to_string();
    assert!(e.contains("too few calibration sets: 3"), "{e}");
    let log = parse_log_str("time_s,gyro_dps,table_rate_dps\n0,0.1,0\n").unwrap();
    let e = calibration::run(&log, &Default::default()).unwrap_err().to_string();
    assert!(e.contains("temp_c"), "{e}");
}
