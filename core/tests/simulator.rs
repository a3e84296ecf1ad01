//! The simulator, the shipped sample logs and tuning.
mod common;

use gyrodrift::hdr::{HdrOptions, HdrParams};
use gyrodrift::sim::{self, samples::SAMPLE_LOGS, SimKind, SimRequest};
use gyrodrift::tune::{self, PreparedDrive, TuneOptions};
use gyrodrift::{parse_log, Column, DriveLog, LogKind};
use std::path::Path;

fn csv(log: &DriveLog) -> Vec<u8> {
    let mut b = Vec::new();
    log.write_csv(&mut b).unwrap();
    b
}

#[test]
fn sample_logs_are_reproducible_bit_for_bit() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs");
    for s in SAMPLE_LOGS {
        let want = std::fs::read(dir.join(s.path)).unwrap_or_else(|e| panic!("{}: {e}", s.path));
        let got = csv(&sim::simulate(&s.request()).unwrap());
        assert!(got == want, "{} differs from a fresh simulation; run `gyrodrift samples`", s.path);
    }
}

#[test]
fn every_kind_simulates_and_parses_back() {
    for (kind, scenario, want) in [
        (SimKind::Drive, Some("downtown"), LogKind::Drive),
        (SimKind::Robot, Some("turns"), LogKind::Robot),
        (SimKind::Turntable, None, LogKind::Turntable),
        (SimKind::Static, None, LogKind::Static),
    ] {
        let req = SimRequest { kind, scenario: scenario.map(String::from), minutes: Some(3.0), seed: 5, name: None, errors: None };
        let log = sim::simulate(&req).unwrap();
        assert_eq!(log.kind(), want);
        let back = parse_log(&csv(&log)[..]).unwrap();
        assert_eq!(csv(&back), csv(&log));
    }
    let bad = SimRequest { scenario: Some("moon".into()), ..Default::default() };
    assert!(sim::simulate(&bad).is_err());
    let bad = SimRequest { minutes: Some(-1.0), ..Default::default() };
    assert!(sim::simulate(&bad).is_err());
}

#[test]
fn simulated_drive_has_paper_like_gyro_and_gps() {
    let log = sim::simulate(&SimRequest { scenario: Some("city".into()), minutes: Some(20.0), seed: 3, ..Default::default() }).unwrap();
    let r = gyrodrift::hdr::run(&log, &HdrOptions::default()).unwrap().result.unwrap();
    // the paper's drives: 0.7-3.5 deg/min uncorrected; HDR helps
    assert!(r.NE_psi_raw_deg_per_min > 0.3 && r.NE_psi_raw_deg_per_min < 6.0, "{r:?}");
    assert!(r.improvement > 1.5, "{r:?}");
    // 1 Hz reference, none while stopped in the lead-in
    let refs = log.column(Column::RefHeadingDeg).unwrap();
    assert!(refs[..200].iter().all(|v| v.is_nan()));
    let n_ref = refs.iter().filter(|v| !v.is_nan()).count();
    assert!(n_ref > 800 && n_ref <= 1200, "{n_ref}");
}

fn prepared(logs: &[DriveLog]) -> Vec<PreparedDrive> {
    logs.iter().enumerate().map(|(i, l)| PreparedDrive::new(&format!("d{i}"), l, None, true).unwrap()).collect()
}

#[test]
fn tuning_never_worsens_the_training_objective() {
    let logs: Vec<DriveLog> = (0..3)
        .map(|s| {
            sim::simulate(&SimRequest { scenario: Some("mixed".into()), minutes: Some(8.0), seed: 40 + s, ..Default::default() }).unwrap()
        })
        .collect();
    let drives = prepared(&logs);
    let opts = TuneOptions { max_iters: 60, restarts: 1, ..Default::default() };
    let r = tune::tune(&drives, &opts).unwrap();
    assert!(r.objective_tuned_deg_per_min <= r.objective_start_deg_per_min);
    let check = tune::objective(&drives, r.params).unwrap();
    assert_eq!(check, r.objective_tuned_deg_per_min);
    // deterministic
    assert_eq!(tune::tune(&drives, &opts).unwrap(), r);
}

#[test]
fn tuning_lands_in_the_known_best_region() {
    // Drives whose gyro has a constant bias that the 20 s lead-in measures exactly: any
    // correction can only add error, and with i_c = 0 HDR is exactly raw integration (the
    // de-lag inverts the filter), so the best region is i_c near 0.
    let logs: Vec<DriveLog> = (0..3).map(|k| common::drive(10.0 + k as f64, |_| 0.8)).collect();
    let drives = prepared(&logs);
    let r = tune::tune(&drives, &TuneOptions { max_iters: 150, ..Default::default() }).unwrap();
    assert!(r.params.i_c_dps < 0.005, "{:?}", r.params);
    assert!(r.objective_tuned_deg_per_min < 0.01, "{r:?}");
    // And with a drift that starts after the lead-in, the best i_c is clearly above 0.
    let logs: Vec<DriveLog> = (0..3).map(|k| common::drive(15.0 + k as f64, |t| 0.8 + if t > 25.0 { 0.05 } else { 0.0 })).collect();
    let drives = prepared(&logs);
    let r = tune::tune(&drives, &TuneOptions { max_iters: 150, ..Default::default() }).unwrap();
    assert!(r.params.i_c_dps > 0.005, "{:?}", r.params);
    let table3 = tune::objective(&drives, HdrParams::table_iii()).unwrap();
    assert!(r.objective_tuned_deg_per_min <= table3);
}

/// A request's gyro errors are the battery's, added to the simulated rate: a static log
/// with a 1 deg/s turn-on bias reads its error-free twin + 1 on every row, and nothing
/// else moves. A battery profile by name with a setting on top (its bias set back to 0,
/// the default value, which must still override the profile's) gives the twin itself.
#[test]
fn a_request_with_gyro_errors_adds_them_to_the_simulated_rate() {
    use gyrodrift::options::from_pairs_on;
    let plain = SimRequest { kind: SimKind::Static, minutes: Some(2.0), seed: 9, ..Default::default() };
    let clean = sim::simulate(&plain).unwrap();
    let errors = sim::GyroErrors { bias_dps: 1.0, ..Default::default() };
    let biased = sim::simulate(&SimRequest { errors: Some(errors), ..plain.clone() }).unwrap();
    let (g0, g1) = (clean.column(Column::GyroDps).unwrap(), biased.column(Column::GyroDps).unwrap());
    assert_eq!(g0.len(), g1.len());
    assert!(g0.iter().zip(g1).all(|(a, b)| (b - a - 1.0).abs() < 1e-12));
    assert_eq!(clean.time_s(), biased.time_s());
    assert!(
        biased.meta.description.as_deref().is_some_and(|d| d.ends_with("; gyro errors added: bias_dps=1.0")),
        "{:?}",
        biased.meta.description
    );
    let profile = gyrodrift::battery::profile("bias +0.5").unwrap();
    assert_eq!(profile.errors.bias_dps, 0.5);
    let back: sim::GyroErrors = from_pairs_on(&profile.errors, &[("bias_dps".into(), 0.0)]).unwrap();
    let same = sim::simulate(&SimRequest { errors: Some(back), ..plain.clone() }).unwrap();
    assert_eq!(csv(&same), csv(&clean));
    // Bad settings name the field, a bad profile names the profiles.
    let nan = sim::GyroErrors { scale: f64::NAN, ..Default::default() };
    let e = sim::simulate(&SimRequest { errors: Some(nan), ..plain }).unwrap_err().to_string();
    assert!(e.contains("scale"), "{e}");
    let e = gyrodrift::battery::profile("bias +9").unwrap_err().to_string();
    assert!(e.contains("bias +9") && e.contains("\"cheap MEMS A cut\""), "{e}");
}
