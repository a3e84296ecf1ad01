//! A deterministic simulator of the logs the three papers used: road drives with a low-cost
//! MEMS rate gyro and 1 Hz GPS course (HDR), differential-drive robot runs over bumps
//! (Gyrodometry), turntable sessions and static logs (calibration, Allan deviation).
//!
//! Same seed, same output, natively and in wasm: the random numbers come from xoshiro256++
//! and every transcendental function from the pure-Rust `libm`, never from the platform.
//! The error model and its ranges are documented in `docs/simulator.md`.

pub mod drive;
pub mod errors;
pub mod gyro;
pub mod roads;
pub mod robot;
pub mod samples;
pub mod turntable;

use rand_xoshiro::rand_core::{Rng, SeedableRng};
use rand_xoshiro::Xoshiro256PlusPlus;
use serde::{Deserialize, Serialize};

pub use drive::{simulate_drive, DriveConfig, Scenario};
pub use errors::{inject, GyroErrors};
pub use gyro::{GyroModel, GyroSpec};
pub use robot::{simulate_robot, RobotConfig};
pub use turntable::{simulate_static, simulate_turntable, StaticConfig, TurntableConfig};

/// The random source of the simulator: xoshiro256++ seeded by SplitMix64 from a u64.
#[derive(Debug, Clone)]
pub struct SimRng(Xoshiro256PlusPlus);

impl SimRng {
    pub fn new(seed: u64) -> Self {
        SimRng(Xoshiro256PlusPlus::seed_from_u64(seed))
    }
    /// Uniform in [0, 1) with 53 random bits.
    pub fn uniform(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }
    /// Standard normal by Box-Muller (libm, so identical on every platform).
    pub fn normal(&mut self) -> f64 {
        let u1 = 1.0 - self.uniform(); // (0, 1]
        let u2 = self.uniform();
        libm::sqrt(-2.0 * libm::log(u1)) * libm::cos(2.0 * std::f64::consts::PI * u2)
    }
    /// True with probability p.
    pub fn chance(&mut self, p: f64) -> bool {
        self.uniform() < p
    }
    /// +1 or -1 with equal probability.
    pub fn sign(&mut self) -> f64 {
        if self.chance(0.5) {
            1.0
        } else {
            -1.0
        }
    }
}

/// Rounds to a number of decimals, so logs are compact and re-parse to the same values.
pub fn round_to(x: f64, decimals: i32) -> f64 {
    let s = libm::pow(10.0, decimals as f64);
    libm::round(x * s) / s
}

/// Which kind of log to simulate (the CLI's `simulate drive|robot|turntable|static`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SimKind {
    Drive,
    Robot,
    Turntable,
    Static,
}

/// One request for any kind of log, as the CLI and the wasm package take it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SimRequest {
    pub kind: SimKind,
    /// Drive scenario (drives), or "straight"/"turns" (robot runs).
    pub scenario: Option<String>,
    /// Length of the log in minutes (defaults per kind).
    pub minutes: Option<f64>,
    pub seed: u64,
    /// Name written as `# name:`.
    pub name: Option<String>,
    /// Gyro errors added to the simulated rate (the battery's classes, `errors::inject`);
    /// None = the simulated gyro as it is.
    pub errors: Option<GyroErrors>,
}

impl crate::options::Settings for SimRequest {
    /// A length in (0, 1440] min.
    fn validate(&self) -> crate::Result<()> {
        match self.minutes {
            Some(m) if !(m.is_finite() && m > 0.0 && m <= 24.0 * 60.0) => {
                Err(crate::Error::param("minutes", format!("{m} is not a duration in (0, 1440] min")))
            }
            _ => self.errors.as_ref().map_or(Ok(()), GyroErrors::validate),
        }
    }
}

impl Default for SimRequest {
    fn default() -> Self {
        SimRequest { kind: SimKind::Drive, scenario: None, minutes: None, seed: 1, name: None, errors: None }
    }
}

/// Simulates the log a request describes.
pub fn simulate(req: &SimRequest) -> crate::Result<crate::DriveLog> {
    crate::options::Settings::validate(req)?;
    let mut log = match req.kind {
        SimKind::Drive => {
            let scenario = match &req.scenario {
                Some(s) => s.parse::<Scenario>()?,
                None => Scenario::Mixed,
            };
            simulate_drive(&DriveConfig { scenario, minutes: req.minutes.unwrap_or(20.0), seed: req.seed })
        }
        SimKind::Robot => {
            let with_turns = match req.scenario.as_deref() {
                None | Some("straight") => false,
                Some("turns") => true,
                Some(other) => return Err(crate::Error::param("scenario", format!("\"{other}\" is not a robot run (straight, turns)"))),
            };
            simulate_robot(&RobotConfig { minutes: req.minutes.unwrap_or(140.0 / 60.0), with_turns, seed: req.seed })
        }
        SimKind::Turntable => simulate_turntable(&TurntableConfig { seed: req.seed, ..Default::default() }),
        SimKind::Static => simulate_static(&StaticConfig { minutes: req.minutes.unwrap_or(120.0), seed: req.seed }),
    };
    if let Some(e) = &req.errors {
        log = inject(&log, e)?;
    }
    if let Some(n) = &req.name {
        log.meta.name = Some(n.clone());
    }
    Ok(log)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rng_is_deterministic_and_normal_has_unit_variance() {
        let mut a = SimRng::new(42);
        let mut b = SimRng::new(42);
        for _ in 0..10 {
            assert_eq!(a.uniform().to_bits(), b.uniform().to_bits());
        }
        let n = 100_000;
        let xs: Vec<f64> = (0..n).map(|_| a.normal()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n as f64;
        assert!(mean.abs() < 0.02 && (var - 1.0).abs() < 0.02, "{mean} {var}");
    }

    #[test]
    fn round_to_decimals() {
        assert_eq!(round_to(1.23456, 2), 1.23);
        assert_eq!(round_to(-0.0049, 2), -0.0);
    }
}
