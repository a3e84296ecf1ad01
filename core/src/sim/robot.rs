//! Simulated differential-drive robot runs for Gyrodometry, after Borenstein & Feng's
//! LabMate experiments: 10 cm/s, bumps (cables) under one wheel. At a bump the robot first
//! swerves toward it and then away; the encoders see a swerve of their own, and since the
//! climbing wheel covers less ground for its encoder count, the true heading keeps a small
//! net change that odometry never sees (its "catastrophic" error).

use super::{round_to, GyroModel, GyroSpec, SimRng};
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// A robot run to simulate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RobotConfig {
    pub minutes: f64,
    /// Square path with 90-degree turns on the spot, instead of one straight run.
    pub with_turns: bool,
    pub seed: u64,
}

/// LabMate-like wheelbase, m.
pub const WHEELBASE_M: f64 = 0.34;
const DT: f64 = 0.1;
const SPEED: f64 = 0.10;
const LEAD_IN_S: f64 = 10.0;

struct Bump {
    start_s: f64,
    dur_s: f64,
    /// Peak true swerve rate, deg/s (sign: toward the bumped wheel's side first).
    amp_dps: f64,
    /// Odometry's swerve, deg/s (larger: the bumped wheel's encoder sees the climb).
    odo_amp_dps: f64,
    /// Net true heading change, deg (never seen by odometry).
    net_deg: f64,
}

/// Simulates a robot run at 10 Hz: time_s, gyro_dps, odo_left_m, odo_right_m, ref_heading_deg
/// (the "sonar" truth at every row, 0.05 deg noise).
pub fn simulate_robot(cfg: &RobotConfig) -> DriveLog {
    let mut rng = SimRng::new(cfg.seed ^ 0x0B07_5EED);
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::OdoLeftM, Column::OdoRightM, Column::RefHeadingDeg]);
    log.meta.wheelbase_m = Some(WHEELBASE_M);
    log.meta.bias_s = Some(LEAD_IN_S);
    log.meta.description = Some(format!(
        "simulated LabMate-like robot run ({}), 10 cm/s, bumps under one wheel, seed {}",
        if cfg.with_turns { "square path" } else { "straight" },
        cfg.seed
    ));
    let mut gyro = GyroModel::draw(&GyroSpec::robot_gyro(), 22.0, &mut rng);
    // Systematic odometry error after UMBmark calibration: tiny wheel-diameter mismatch.
    let (e_left, e_right) = (1.0 + 0.0001 * rng.normal(), 1.0 + 0.0001 * rng.normal());
    let total_s = cfg.minutes * 60.0;
    // Bumps at random times while driving, all under one wheel (15 in 2:20 min under the
    // right wheel, as in the paper's Fig. 2): +1 = left wheel (turns ccw first), -1 = right.
    let side = rng.sign();
    let n_bumps = ((total_s - LEAD_IN_S) / 140.0 * 15.0).round().max(1.0) as usize;
    let mut bumps: Vec<Bump> = (0..n_bumps)
        .map(|_| {
            let amp = rng.range(5.0, 10.0);
            Bump {
                start_s: rng.range(LEAD_IN_S + 2.0, total_s - 2.0),
                dur_s: rng.range(0.6, 1.2),
                amp_dps: side * amp,
                odo_amp_dps: side * amp * rng.range(1.5, 2.5),
                net_deg: -side * rng.range(0.2, 0.7),
            }
        })
        .collect();
    bumps.sort_by(|a, b| a.start_s.total_cmp(&b.start_s));
    let (mut heading, mut left, mut right) = (0.0f64, 0.0f64, 0.0f64);
    let leg_s = 30.0;
    let turn_rate = 20.0;
    let n = (total_s * 10.0).round() as usize;
    for i in 0..=n {
        let t = i as f64 / 10.0;
        let moving = t > LEAD_IN_S;
        // Commanded motion: straight, or on a square path 30 s legs and 90-degree turns.
        let (mut v, mut w_cmd) = (if moving { SPEED } else { 0.0 }, 0.0);
        if cfg.with_turns && moving {
            let cycle = leg_s + 90.0 / turn_rate;
            let u = (t - LEAD_IN_S) % cycle;
            if u >= leg_s {
                v = 0.0;
                w_cmd = turn_rate;
            }
        }
        let mut true_rate = w_cmd;
        let mut odo_rate = w_cmd;
        if v > 0.0 {
            for b in &bumps {
                if t > b.start_s && t <= b.start_s + b.dur_s {
                    let ph = libm::sin(2.0 * std::f64::consts::PI * (t - b.start_s) / b.dur_s);
                    true_rate += b.amp_dps * ph + b.net_deg / b.dur_s;
                    odo_rate += b.odo_amp_dps * ph;
                }
            }
        }
        if i > 0 {
            heading += true_rate * DT;
            let d_theta = odo_rate.to_radians() * DT;
            left += (v * DT - d_theta * WHEELBASE_M / 2.0) * e_left;
            right += (v * DT + d_theta * WHEELBASE_M / 2.0) * e_right;
        }
        let g = gyro.measure(if i == 0 { 0.0 } else { true_rate }, 22.0, DT, &mut rng);
        let reference = heading + 0.05 * rng.normal();
        log.push_row(&[
            (Column::TimeS, t),
            (Column::GyroDps, round_to(g, 3)),
            (Column::OdoLeftM, round_to(left, 5)),
            (Column::OdoRightM, round_to(right, 5)),
            (Column::RefHeadingDeg, round_to(reference, 3)),
        ]);
    }
    log
}
