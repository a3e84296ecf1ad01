//! Simulated turntable calibration sessions (after Ojeda, Chung & Borenstein): a stationary
//! lead-in, then rates -100..100 deg/s in 10 deg/s steps at chamber temperatures 25-45 C,
//! with a temperature-dependent bias, a cubic scale-factor error and noise; and long static
//! logs for Allan deviation.

use super::{round_to, GyroModel, GyroSpec, SimRng};
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// A turntable session to simulate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TurntableConfig {
    pub temperatures_c: Vec<f64>,
    pub rates_dps: Vec<f64>,
    pub seconds_per_set: f64,
    pub seed: u64,
}

impl Default for TurntableConfig {
    fn default() -> Self {
        TurntableConfig {
            temperatures_c: vec![25.0, 30.0, 35.0, 40.0, 45.0],
            rates_dps: (-10..=10).map(|k| k as f64 * 10.0).collect(),
            seconds_per_set: 20.0,
            seed: 1,
        }
    }
}

const LEAD_IN_S: f64 = 20.0;

/// Simulates a session at 10 Hz: time_s, gyro_dps, temp_c, table_rate_dps.
pub fn simulate_turntable(cfg: &TurntableConfig) -> DriveLog {
    let mut rng = SimRng::new(cfg.seed ^ 0x7AB1_E5EE);
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::TempC, Column::TableRateDps]);
    log.meta.bias_s = Some(LEAD_IN_S);
    log.meta.description = Some(format!("simulated turntable calibration session, seed {}", cfg.seed));
    let mut gyro = GyroModel::draw(&GyroSpec::crs03_like(), 25.0, &mut rng);
    // A chamber-controlled session: slow bias wander only, and a scale factor that grows with T.
    gyro.gm_sigma_dps *= 0.2;
    gyro.full_scale_dps = 150.0; // the turntable's rates stay inside the range: no clipping
    let scale_tc = rng.range(-3e-4, 3e-4); // per deg C
    let quad_tc = rng.range(-3e-4, 3e-4); // deg/s per (deg C)^2
    let mut i = 0usize;
    let mut push = |log: &mut DriveLog, rng: &mut SimRng, gyro: &mut GyroModel, w: f64, temp: f64, secs: f64| {
        for _ in 0..(secs * 10.0).round() as usize {
            let t = i as f64 / 10.0;
            let temp_now = temp + 0.05 * rng.normal();
            let dtemp = temp_now - 25.0;
            let extra = scale_tc * dtemp * w + quad_tc * dtemp * dtemp;
            let g = gyro.measure(w, temp_now, 0.1, rng) + extra;
            log.push_row(&[
                (Column::TimeS, t),
                (Column::GyroDps, round_to(g, 4)),
                (Column::TempC, round_to(temp_now, 2)),
                (Column::TableRateDps, w),
            ]);
            i += 1;
        }
    };
    let first_temp = cfg.temperatures_c.first().copied().unwrap_or(25.0);
    push(&mut log, &mut rng, &mut gyro, 0.0, first_temp, LEAD_IN_S);
    for &temp in &cfg.temperatures_c {
        for &w in &cfg.rates_dps {
            push(&mut log, &mut rng, &mut gyro, w, temp, cfg.seconds_per_set);
        }
    }
    log
}

/// A long static log to simulate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StaticConfig {
    pub minutes: f64,
    pub seed: u64,
}

/// Simulates a gyro at rest at 10 Hz (time_s, gyro_dps, temp_c): white noise, Gauss-Markov
/// bias instability and a slow temperature wander, for Allan deviation.
pub fn simulate_static(cfg: &StaticConfig) -> DriveLog {
    let mut rng = SimRng::new(cfg.seed ^ 0x57A7_1C5E);
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::TempC]);
    log.meta.bias_s = Some(LEAD_IN_S);
    log.meta.description = Some(format!("simulated static gyro log, {} min, seed {}", cfg.minutes, cfg.seed));
    let mut gyro = GyroModel::draw(&GyroSpec::crs03_like(), 24.0, &mut rng);
    gyro.lsb_dps = 0.001; // a finer ADC for the noise study
    let n = (cfg.minutes * 600.0).round() as usize;
    for i in 0..=n {
        let t = i as f64 / 10.0;
        let temp = 24.0 + 0.3 * libm::sin(2.0 * std::f64::consts::PI * t / 5400.0);
        let g = gyro.measure(0.0, temp, 0.1, &mut rng);
        log.push_row(&[(Column::TimeS, t), (Column::GyroDps, round_to(g, 4)), (Column::TempC, round_to(temp, 3))]);
    }
    log
}
