//! The speed's unit: a road vehicle does not hold 70 m/s (252 km/h) for half a minute, and
//! a speed in km/h or mph read as m/s does on any drive that holds 70 km/h or 70 mph.

use super::{finding, CheckReport, Severity};
use crate::log::{Column, DriveLog};

/// Faster than a road vehicle drives for [`HELD_S`], m/s. The recorded and simulated drives
/// hold at most 36 for 30 s (README, `gyrodrift check`).
const MAX_SPEED_MPS: f64 = 70.0;
const HELD_S: f64 = 30.0;

/// A warning when the speed stays above [`MAX_SPEED_MPS`] for [`HELD_S`] (an empty cell
/// does not break a run).
pub(super) fn speed_unit(r: &mut CheckReport, log: &DriveLog) {
    let Some(v) = log.column(Column::SpeedMps) else { return };
    let mut since_s = None;
    for (&t, &v) in log.time_s().iter().zip(v) {
        if v.abs() > MAX_SPEED_MPS {
            let start = *since_s.get_or_insert(t);
            if t - start >= HELD_S {
                let message = format!("speed_mps stays above 70 m/s (252 km/h) for 30 s from t = {start:.0} s, faster than a road vehicle drives: is it in km/h or mph?");
                let fix = "speed.unit = \"km/h\" or \"mph\" in the recipe (in a v1 log: speed_mps divided by 3.6 or 2.237)";
                r.findings.push(finding(Severity::Warning, "speed_unit", message, Some(fix)));
                return;
            }
        } else if v.is_finite() {
            since_s = None;
        }
    }
}
