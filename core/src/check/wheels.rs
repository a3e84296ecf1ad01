//! The wheels' unit and sides: over the gyro's turns, the heading change the wheel travel
//! gives (Gyrodometry's odometry increment, with `# wheelbase_m:`) against the gyro's own,
//! as the units check compares the gyro with the reference. Travel in mm or cm gives 1000 or
//! 100 times the turn, sides swapped the opposite turn: Gyrodometry's heading is then absurd.

use super::{finding, CheckReport, Severity};
use crate::gyrodometry::odo_increment_deg;
use crate::log::{Column, DriveLog};
use crate::metrics::value_at;

/// A row-to-row rate beyond this is a turn the ratio is taken over, deg/s.
const TURN_DPS: f64 = 5.0;
/// The gyro's turning this much in all is a clear turn, deg.
const MIN_TURN_DEG: f64 = 90.0;

/// The wheels' heading change over the gyro's own (its 1 Hz heading, `units::gyro_heading`)
/// between wheel samples where the gyro turns (signed by the gyro's turn, so left and right
/// turns add), or None without wheels, a wheelbase, 20 s of gyro or a clear turn.
pub(super) fn wheels_over_gyro(log: &DriveLog, eps0_dps: f64) -> Option<f64> {
    let (l, r, b) = (log.column(Column::OdoLeftM)?, log.column(Column::OdoRightM)?, log.meta.wheelbase_m?);
    let (gt, psi) = super::units::gyro_heading(log, Some(eps0_dps))?;
    let mut last: Option<(f64, f64, f64, f64)> = None;
    let (mut wheels_deg, mut gyro_deg) = (0.0, 0.0);
    for ((&t, &l), &r) in log.time_s().iter().zip(l).zip(r).filter(|((_, l), r)| l.is_finite() && r.is_finite()) {
        let heading = value_at(&gt, &psi, t);
        if let Some((t0, h0, l0, r0)) = last {
            let d_gyro = heading - h0;
            if t > t0 && (d_gyro / (t - t0)).abs() > TURN_DPS {
                wheels_deg += odo_increment_deg(l - l0, r - r0, b) * d_gyro.signum();
                gyro_deg += d_gyro.abs();
            }
        }
        last = Some((t, heading, l, r));
    }
    (gyro_deg >= MIN_TURN_DEG).then(|| wheels_deg / gyro_deg)
}

/// A warning or error when the wheels turn 1000 or 100 times the gyro (mm, cm), the other
/// way (sides swapped), or far from it otherwise (the wheelbase or a scale).
pub(super) fn wheel_units(r: &mut CheckReport, log: &DriveLog) {
    let Some(k) = wheels_over_gyro(log, r.eps0_dps.unwrap_or(0.0)) else { return };
    let near = |want: f64| (k / want - 1.0).abs() < 0.25;
    let (severity, message, fix) = if near(1.0) {
        return;
    } else if near(-1.0) {
        (
            Severity::Error,
            format!("the wheels turn {k:.2} times the gyro: the other way; odo_left_m and odo_right_m swapped (or the gyro clockwise)?"),
            "swap odometry.left and right in the recipe (or yaw_rate.positive = \"cw\")",
        )
    } else if near(1000.0) || near(100.0) {
        (
            Severity::Error,
            format!("the wheels turn {k:.0} times the gyro: the wheel travel is in mm or cm, not m"),
            "odometry.unit in the recipe",
        )
    } else {
        (
            Severity::Warning,
            format!("the wheels turn {k:.2} times the gyro: the wheelbase or the wheels' unit?"),
            "# wheelbase_m: (odometry.track_m in the recipe)",
        )
    };
    r.findings.push(finding(severity, "wheel_units", message, Some(fix)));
}
