//! Small synthetic logs with known truth for the integration tests.
#![allow(dead_code)]

use gyrodrift::{Column, DriveLog};

/// Truth yaw rate (deg/s) of a simple drive: 30 s still, then 60 s legs joined by 90-degree
/// turns of 9 s at 10 deg/s, alternating left and right.
pub fn truth_rate_dps(t: f64) -> f64 {
    if t < 30.0 {
        return 0.0;
    }
    let u = (t - 30.0) % 69.0;
    let leg = ((t - 30.0) / 69.0).floor() as i64;
    if u >= 60.0 {
        if leg % 2 == 0 {
            10.0
        } else {
            -10.0
        }
    } else {
        0.0
    }
}

/// A 10 Hz drive: gyro = truth + bias(t); reference = truth heading at every 10th row (1 Hz),
/// wrapped to [0, 360) and written as a GPS would give it. Truth integrates the same rates by
/// the rectangle rule, so raw integration with zero bias reproduces it exactly.
pub fn drive(minutes: f64, bias: impl Fn(f64) -> f64) -> DriveLog {
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]);
    log.meta.name = Some("synthetic".into());
    let n = (minutes * 600.0) as usize;
    let mut psi = 0.0;
    for i in 0..=n {
        let t = i as f64 / 10.0;
        let w = truth_rate_dps(t);
        if i > 0 {
            psi += w * 0.1;
        }
        let reference = if i % 10 == 0 { (psi + 45.0).rem_euclid(360.0) } else { f64::NAN };
        log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w + bias(t)), (Column::RefHeadingDeg, reference)]);
    }
    log
}

/// Writes a log to CSV text.
pub fn to_csv(log: &DriveLog) -> String {
    let mut buf = Vec::new();
    log.write_csv(&mut buf).unwrap();
    String::from_utf8(buf).unwrap()
}
