//! Dead-reckoned paths for the Track view: speed integrated along a heading trace, in
//! metres on a local plane (x along heading 0, y along heading 90 deg, CCW positive).

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use crate::metrics::{interp_at, Reference};
use serde::{Deserialize, Serialize};

/// A path in metres.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Path {
    pub x_m: Vec<f64>,
    pub y_m: Vec<f64>,
}

/// Heading of a trace at time t (held at the ends).
fn heading_at(time_s: &[f64], psi_deg: &[f64], t: f64) -> f64 {
    if t <= time_s[0] {
        return psi_deg[0];
    }
    let j = time_s.partition_point(|&v| v <= t).saturating_sub(1);
    interp_at(time_s, psi_deg, j, t)
}

/// Integrates the log's speed along a heading trace: x += v dt cos(psi), y += v dt sin(psi),
/// at every row with a speed (rectangle rule, the speed and heading at the row's end).
pub fn dead_reckon(log: &DriveLog, time_s: &[f64], psi_deg: &[f64]) -> Result<Path> {
    let speed = log.require(Column::SpeedMps, "needed for the track")?;
    if time_s.is_empty() || time_s.len() != psi_deg.len() {
        return Err(Error::data("the heading trace is empty"));
    }
    let mut p = Path::default();
    let (mut x, mut y) = (0.0, 0.0);
    let mut last_t: Option<f64> = None;
    for (&t, &v) in log.time_s().iter().zip(speed) {
        if v.is_nan() {
            continue;
        }
        if let Some(t0) = last_t {
            let h = heading_at(time_s, psi_deg, t).to_radians();
            x += v * (t - t0) * libm::cos(h);
            y += v * (t - t0) * libm::sin(h);
        }
        last_t = Some(t);
        p.x_m.push(x);
        p.y_m.push(y);
    }
    Ok(p)
}

/// The path integrated along the (unwrapped) reference heading.
pub fn reference_path(log: &DriveLog) -> Result<Path> {
    let r = Reference::from_log(log)?;
    dead_reckon(log, &r.time_s, &r.heading_deg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_by_hand() {
        // 1 m/s, heading 0 for 10 s then 90 deg: ends near (10, 10)
        let mut log = DriveLog::with_columns(&[Column::SpeedMps]);
        for i in 0..=20 {
            log.push_row(&[(Column::TimeS, i as f64), (Column::SpeedMps, 1.0)]);
        }
        let t = [0.0, 10.0, 10.0 + 1e-9, 20.0];
        let psi = [0.0, 0.0, 90.0, 90.0];
        let p = dead_reckon(&log, &t, &psi).unwrap();
        let (x, y) = (*p.x_m.last().unwrap(), *p.y_m.last().unwrap());
        assert!((x - 10.0).abs() < 1e-6 && (y - 10.0).abs() < 1e-6, "{x} {y}");
    }
}
