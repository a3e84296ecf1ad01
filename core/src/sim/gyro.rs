//! The simulated rate gyro: zero-rate offset, bias change with temperature, Gauss-Markov
//! bias instability, white noise, scale-factor error and cubic non-linearity, saturation
//! and quantisation. Ranges and reasons are in docs/simulator.md.

use super::SimRng;
use serde::{Deserialize, Serialize};

/// Ranges from which one gyro unit's error parameters are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GyroSpec {
    /// |zero-rate offset| upper bound, deg/s.
    pub offset_max_dps: f64,
    /// |bias temperature coefficient| range, deg/s per deg C.
    pub temp_coeff_dps_per_c: (f64, f64),
    /// Gauss-Markov bias instability sigma range, deg/s, and correlation time range, s.
    pub gm_sigma_dps: (f64, f64),
    pub gm_tau_s: (f64, f64),
    /// White noise per sample (at 10 Hz) range, deg/s.
    pub noise_dps: (f64, f64),
    /// |scale-factor error| upper bound (fraction).
    pub scale_error_max: f64,
    /// |cubic non-linearity at full scale| upper bound, deg/s.
    pub nonlinearity_max_dps: f64,
    pub full_scale_dps: f64,
    /// Quantisation step, deg/s.
    pub lsb_dps: f64,
}

impl GyroSpec {
    /// A low-cost MEMS rate gyro like the HDR paper's Silicon Sensing CRS03-04.
    pub fn crs03_like() -> Self {
        GyroSpec {
            offset_max_dps: 2.0,
            temp_coeff_dps_per_c: (0.004, 0.015),
            gm_sigma_dps: (0.005, 0.02),
            gm_tau_s: (100.0, 600.0),
            noise_dps: (0.05, 0.12),
            scale_error_max: 0.02,
            nonlinearity_max_dps: 0.3,
            full_scale_dps: 100.0,
            lsb_dps: 0.025,
        }
    }

    /// An ideal gyro: the true rate, no error of any kind (the truth of a simulated drive).
    pub fn ideal() -> Self {
        GyroSpec {
            offset_max_dps: 0.0,
            temp_coeff_dps_per_c: (0.0, 0.0),
            gm_sigma_dps: (0.0, 0.0),
            gm_tau_s: (1.0, 1.0),
            noise_dps: (0.0, 0.0),
            scale_error_max: 0.0,
            nonlinearity_max_dps: 0.0,
            full_scale_dps: 1e9,
            lsb_dps: 1e-9,
        }
    }

    /// A consumer MEMS gyro (phone or automotive IMU class) after factory calibration:
    /// small offset and temperature drift, finer resolution. The robustness battery adds
    /// its error classes on top.
    pub fn consumer_mems() -> Self {
        GyroSpec {
            offset_max_dps: 0.05,
            temp_coeff_dps_per_c: (0.0005, 0.002),
            gm_sigma_dps: (0.002, 0.005),
            gm_tau_s: (100.0, 600.0),
            noise_dps: (0.03, 0.08),
            scale_error_max: 0.005,
            nonlinearity_max_dps: 0.05,
            full_scale_dps: 250.0,
            lsb_dps: 0.0076,
        }
    }

    /// A better gyro of the kind Gyrodometry used on the LabMate (Gyrostar class), on a robot.
    pub fn robot_gyro() -> Self {
        GyroSpec {
            offset_max_dps: 0.5,
            temp_coeff_dps_per_c: (0.0, 0.0),
            gm_sigma_dps: (0.02, 0.05),
            gm_tau_s: (60.0, 200.0),
            noise_dps: (0.02, 0.05),
            scale_error_max: 0.005,
            nonlinearity_max_dps: 0.1,
            full_scale_dps: 90.0,
            lsb_dps: 0.01,
        }
    }
}

/// One gyro unit with drawn parameters and its bias-instability state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GyroModel {
    pub offset_dps: f64,
    pub temp_coeff_dps_per_c: f64,
    pub temp_ref_c: f64,
    pub gm_sigma_dps: f64,
    pub gm_tau_s: f64,
    pub noise_dps: f64,
    pub scale_error: f64,
    pub nonlinearity_dps: f64,
    pub full_scale_dps: f64,
    pub lsb_dps: f64,
    gm_state_dps: f64,
}

impl GyroModel {
    /// Draws a unit from the spec; `temp_ref_c` is where the offset holds.
    pub fn draw(spec: &GyroSpec, temp_ref_c: f64, rng: &mut SimRng) -> Self {
        let gm_sigma = rng.range(spec.gm_sigma_dps.0, spec.gm_sigma_dps.1);
        GyroModel {
            offset_dps: rng.range(-spec.offset_max_dps, spec.offset_max_dps),
            temp_coeff_dps_per_c: rng.sign() * rng.range(spec.temp_coeff_dps_per_c.0, spec.temp_coeff_dps_per_c.1),
            temp_ref_c,
            gm_sigma_dps: gm_sigma,
            gm_tau_s: rng.range(spec.gm_tau_s.0, spec.gm_tau_s.1),
            noise_dps: rng.range(spec.noise_dps.0, spec.noise_dps.1),
            scale_error: rng.range(-spec.scale_error_max, spec.scale_error_max),
            nonlinearity_dps: rng.range(-spec.nonlinearity_max_dps, spec.nonlinearity_max_dps),
            full_scale_dps: spec.full_scale_dps,
            lsb_dps: spec.lsb_dps,
            gm_state_dps: gm_sigma * rng.normal(),
        }
    }

    /// The bias (all rate-independent error) at a temperature, without noise, deg/s.
    pub fn bias_dps(&self, temp_c: f64) -> f64 {
        self.offset_dps + self.temp_coeff_dps_per_c * (temp_c - self.temp_ref_c) + self.gm_state_dps
    }

    /// One output sample for a true rate over an interval of dt_s seconds.
    pub fn measure(&mut self, true_rate_dps: f64, temp_c: f64, dt_s: f64, rng: &mut SimRng) -> f64 {
        // First-order Gauss-Markov bias: exact discretisation.
        let a = libm::exp(-dt_s / self.gm_tau_s);
        self.gm_state_dps = a * self.gm_state_dps + self.gm_sigma_dps * libm::sqrt(1.0 - a * a) * rng.normal();
        let u = true_rate_dps / self.full_scale_dps;
        let out = true_rate_dps * (1.0 + self.scale_error)
            + self.nonlinearity_dps * u * u * u
            + self.bias_dps(temp_c)
            + self.noise_dps * rng.normal();
        let clipped = out.clamp(-self.full_scale_dps, self.full_scale_dps);
        libm::round(clipped / self.lsb_dps) * self.lsb_dps
    }
}
