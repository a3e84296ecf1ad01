//! Gyro error classes added to a log's yaw rate: the robustness battery puts them on
//! recorded drives (real roads, real GPS truth) and on simulated ones, so a drift reducer
//! is judged on gyros nobody tuned it to. Every class is a field of [`GyroErrors`]; they
//! combine. Deterministic: same seed, same errors (xoshiro + libm, as the simulator).

use super::SimRng;
use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// The speed at which the vibration settings apply (highway speed), m/s.
pub const VIBRATION_REF_MPS: f64 = 30.0;

/// Errors to add to the recorded rate `w`: bias(t) + scale * w + rate_dep * |w| +
/// g-sensitivity times lateral acceleration + vibration (bias and noise growing with speed),
/// white noise on top, then quantisation. Zero everywhere = no change.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GyroErrors {
    /// Constant turn-on bias, deg/s.
    pub bias_dps: f64,
    /// Warm-up drift: this much extra bias at the start, decaying with `warmup_tau_s`, deg/s.
    pub warmup_dps: f64,
    pub warmup_tau_s: f64,
    /// Bias random walk, deg/s per sqrt(s).
    pub walk_dps_per_sqrt_s: f64,
    /// Bias steps (an OS re-calibration): size of each step, random sign, deg/s, and the
    /// mean time between steps (exponential), s (0 = no steps).
    pub step_dps: f64,
    pub step_every_s: f64,
    /// Scale-factor error (fraction of the rate).
    pub scale: f64,
    /// Rate-dependent bias, deg/s per deg/s of |rate| (an asymmetric scale error).
    pub rate_dep: f64,
    /// Bias per m/s^2 of lateral acceleration (speed x yaw rate), deg/s per m/s^2
    /// (g-sensitivity; needs speed_mps, else nothing is added).
    pub g_sens_dps_per_mps2: f64,
    /// White noise added per row, deg/s.
    pub noise_dps: f64,
    /// Vibration: road and engine vibration grows with speed. White noise per row of this
    /// sigma at [`VIBRATION_REF_MPS`], scaled by speed / that speed (none at rest), deg/s
    /// (needs speed_mps, else nothing is added).
    pub vibration_noise_dps: f64,
    /// Vibration rectification: the bias a MEMS gyro shows under vibration (a datasheet's
    /// "vibration rectification error"), at [`VIBRATION_REF_MPS`] and scaled as the noise,
    /// so the bias while driving differs from the bias at stops, deg/s.
    pub vibration_bias_dps: f64,
    /// Quantisation step of the output, deg/s (0 = none).
    pub lsb_dps: f64,
    /// Cut the stationary lead-in (`# bias_s:` rows) so the drive starts moving, with
    /// bias_s = 0 (no static bias is removed).
    pub cut_lead_in: bool,
    /// Drop the speed and wheel-odometry columns once the errors are added (a logger with
    /// a gyro alone), so standing must be judged from the gyro.
    pub gyro_only: bool,
    pub seed: u64,
}

impl Default for GyroErrors {
    fn default() -> Self {
        GyroErrors {
            bias_dps: 0.0,
            warmup_dps: 0.0,
            warmup_tau_s: 600.0,
            walk_dps_per_sqrt_s: 0.0,
            step_dps: 0.0,
            step_every_s: 0.0,
            scale: 0.0,
            rate_dep: 0.0,
            g_sens_dps_per_mps2: 0.0,
            noise_dps: 0.0,
            vibration_noise_dps: 0.0,
            vibration_bias_dps: 0.0,
            lsb_dps: 0.0,
            cut_lead_in: false,
            gyro_only: false,
            seed: 1,
        }
    }
}

impl crate::options::Settings for GyroErrors {
    fn validate(&self) -> Result<()> {
        GyroErrors::validate(self)
    }
}

impl GyroErrors {
    /// The settings that differ from no errors, as `key=value` (what `--error` takes), so a
    /// log's description says how to make it again.
    pub fn changed(&self) -> Vec<String> {
        let (Ok(serde_json::Value::Object(me)), Ok(serde_json::Value::Object(none))) =
            (serde_json::to_value(self), serde_json::to_value(GyroErrors::default()))
        else {
            return Vec::new();
        };
        let as_number = |v: &serde_json::Value| match v {
            serde_json::Value::Bool(b) => u8::from(*b).to_string(),
            other => other.to_string(),
        };
        me.iter().filter(|(k, v)| none.get(k.as_str()) != Some(v)).map(|(k, v)| format!("{k}={}", as_number(v))).collect()
    }

    /// Every setting finite and in range.
    pub fn validate(&self) -> Result<()> {
        let all = [
            ("bias_dps", self.bias_dps),
            ("warmup_dps", self.warmup_dps),
            ("warmup_tau_s", self.warmup_tau_s),
            ("walk_dps_per_sqrt_s", self.walk_dps_per_sqrt_s),
            ("step_dps", self.step_dps),
            ("step_every_s", self.step_every_s),
            ("scale", self.scale),
            ("rate_dep", self.rate_dep),
            ("g_sens_dps_per_mps2", self.g_sens_dps_per_mps2),
            ("noise_dps", self.noise_dps),
            ("vibration_noise_dps", self.vibration_noise_dps),
            ("vibration_bias_dps", self.vibration_bias_dps),
            ("lsb_dps", self.lsb_dps),
        ];
        for (name, v) in all {
            if !v.is_finite() {
                return Err(Error::param(name, format!("{v} is not a finite number")));
            }
        }
        for (name, v) in [
            ("warmup_tau_s", self.warmup_tau_s),
            ("walk_dps_per_sqrt_s", self.walk_dps_per_sqrt_s),
            ("step_every_s", self.step_every_s),
            ("noise_dps", self.noise_dps),
            ("vibration_noise_dps", self.vibration_noise_dps),
            ("lsb_dps", self.lsb_dps),
        ] {
            if v < 0.0 {
                return Err(Error::param(name, format!("{v} is negative")));
            }
        }
        if self.warmup_dps != 0.0 && self.warmup_tau_s <= 0.0 {
            return Err(Error::param("warmup_tau_s", "must be > 0 with a warm-up"));
        }
        Ok(())
    }
}

/// The bias of the injected errors over time (without the rate-dependent terms), deg/s:
/// one value per row of `time_s`. Exposed so tests can check each class.
pub fn bias_series(time_s: &[f64], e: &GyroErrors) -> Vec<f64> {
    let mut rng = SimRng::new(e.seed ^ 0xB1A5_E77E);
    let Some(&t0) = time_s.first() else { return Vec::new() };
    let mut walk = 0.0;
    let mut steps = 0.0;
    let mut next_step = if e.step_every_s > 0.0 { t0 - e.step_every_s * libm::log(1.0 - rng.uniform()) } else { f64::INFINITY };
    let mut prev = t0;
    let mut out = Vec::with_capacity(time_s.len());
    for &t in time_s {
        let dt = (t - prev).max(0.0);
        prev = t;
        if e.walk_dps_per_sqrt_s > 0.0 {
            walk += e.walk_dps_per_sqrt_s * libm::sqrt(dt) * rng.normal();
        }
        while t >= next_step {
            steps += e.step_dps * rng.sign();
            next_step -= e.step_every_s * libm::log(1.0 - rng.uniform());
        }
        let warm = if e.warmup_dps != 0.0 { e.warmup_dps * libm::exp(-(t - t0) / e.warmup_tau_s) } else { 0.0 };
        out.push(e.bias_dps + warm + walk + steps);
    }
    out
}

/// A copy of the log with the errors added to gyro_dps (empty cells stay empty).
pub fn inject(log: &DriveLog, e: &GyroErrors) -> Result<DriveLog> {
    e.validate()?;
    let mut out = log.clone();
    if e.cut_lead_in {
        let bias_s = log.bias_s(None);
        let t = log.time_s();
        if let Some(&t0) = t.first() {
            let first = t.iter().position(|&ti| ti - t0 >= bias_s).unwrap_or(t.len());
            out.drop_first_rows(first);
        }
        out.meta.bias_s = Some(0.0);
    }
    let time_s = out.time_s().to_vec();
    if time_s.is_empty() {
        return Err(Error::data("no rows left to add gyro errors to"));
    }
    let bias = bias_series(&time_s, e);
    let speed = out.column(Column::SpeedMps).map(|s| s.to_vec());
    let mut rng = SimRng::new(e.seed ^ 0x4E01_5E00);
    let gyro = out.column_mut(Column::GyroDps).ok_or_else(|| Error::missing("gyro_dps", "needed to add gyro errors"))?;
    for (i, g) in gyro.iter_mut().enumerate() {
        if g.is_nan() {
            continue;
        }
        let w = *g;
        let v_mps = match &speed {
            Some(s) if s[i].is_finite() => s[i].max(0.0),
            _ => 0.0,
        };
        let lat = v_mps * w.to_radians();
        let vib = v_mps / VIBRATION_REF_MPS;
        let mut v = w + bias[i] + e.scale * w + e.rate_dep * w.abs() + e.g_sens_dps_per_mps2 * lat + e.vibration_bias_dps * vib;
        if e.noise_dps > 0.0 {
            v += e.noise_dps * rng.normal();
        }
        if e.vibration_noise_dps > 0.0 {
            v += e.vibration_noise_dps * vib * rng.normal();
        }
        if e.lsb_dps > 0.0 {
            v = libm::round(v / e.lsb_dps) * e.lsb_dps;
        }
        // A log no reader takes back: refused here, not at the next command.
        if let Some((lo, hi, unit)) = Column::GyroDps.physical_range().filter(|(lo, hi, _)| !(*lo..=*hi).contains(&v)) {
            return Err(Error::data(format!(
                "at {} s the gyro errors make the rate {v:?} {unit}, outside the physical range [{lo}, {hi}] {unit}",
                time_s[i]
            )));
        }
        *g = v;
    }
    if e.gyro_only {
        for c in [Column::SpeedMps, Column::OdoLeftM, Column::OdoRightM] {
            out.drop_column(c);
        }
    }
    let changed = e.changed();
    if !changed.is_empty() {
        let added = format!("gyro errors added: {}", changed.join(", "));
        out.meta.description = Some(match out.meta.description.take() {
            Some(d) if !d.is_empty() => format!("{d}; {added}"),
            _ => added,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat_log(n: usize, dt: f64, rate: f64, speed: f64) -> DriveLog {
        let mut l = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]);
        for i in 0..n {
            l.push_row(&[(Column::TimeS, i as f64 * dt), (Column::GyroDps, rate), (Column::SpeedMps, speed)]);
        }
        l.meta.bias_s = Some(5.0);
        l
    }

    #[test]
    fn constant_bias_scale_and_rate_dependence_add_as_specified() {
        let l = flat_log(10, 1.0, 10.0, 0.0);
        let e = GyroErrors { bias_dps: 0.5, scale: 0.02, rate_dep: 0.01, ..Default::default() };
        let g = inject(&l, &e).unwrap();
        // 10 + 0.5 + 0.02 * 10 + 0.01 * 10 = 10.8
        assert!(g.column(Column::GyroDps).unwrap().iter().all(|&v| (v - 10.8).abs() < 1e-12));
    }

    #[test]
    fn warm_up_decays_with_its_time_constant() {
        let t: Vec<f64> = (0..1000).map(|i| i as f64).collect();
        let b = bias_series(&t, &GyroErrors { warmup_dps: 1.0, warmup_tau_s: 100.0, ..Default::default() });
        assert_eq!(b[0], 1.0);
        assert!((b[100] - (-1.0f64).exp()).abs() < 1e-12);
    }

    #[test]
    fn random_walk_grows_as_sqrt_time() {
        // Variance of the walk at 400 s over many seeds: q^2 t = 0.01^2 * 400 = 0.04.
        let t: Vec<f64> = (0..=400).map(|i| i as f64).collect();
        let n = 2000;
        let var: f64 = (0..n)
            .map(|s| {
                let b = bias_series(&t, &GyroErrors { walk_dps_per_sqrt_s: 0.01, seed: s, ..Default::default() });
                b[400] * b[400]
            })
            .sum::<f64>()
            / n as f64;
        assert!((var - 0.04).abs() < 0.006, "{var}");
    }

    #[test]
    fn steps_have_the_given_size_and_rate() {
        let t: Vec<f64> = (0..100_000).map(|i| i as f64).collect();
        let b = bias_series(&t, &GyroErrors { step_dps: 0.1, step_every_s: 1000.0, ..Default::default() });
        let jumps: Vec<f64> = b.windows(2).map(|w| w[1] - w[0]).filter(|d| d.abs() > 1e-9).collect();
        // ~100 steps expected; each +-0.1 (two steps in one row are rare at this rate)
        assert!((70..130).contains(&jumps.len()), "{}", jumps.len());
        assert!(jumps.iter().filter(|d| (d.abs() - 0.1).abs() < 1e-9).count() as f64 > 0.95 * jumps.len() as f64);
    }

    #[test]
    fn g_sensitivity_uses_lateral_acceleration() {
        // 10 m/s at 5.7296 deg/s (0.1 rad/s) -> 1 m/s^2 -> +0.05 deg/s
        let l = flat_log(3, 1.0, 0.1f64.to_degrees(), 10.0);
        let g = inject(&l, &GyroErrors { g_sens_dps_per_mps2: 0.05, ..Default::default() }).unwrap();
        assert!((g.column(Column::GyroDps).unwrap()[1] - (0.1f64.to_degrees() + 0.05)).abs() < 1e-12);
    }

    #[test]
    fn vibration_grows_with_speed_and_is_absent_at_rest() {
        // Rectified bias 0.06 deg/s at 30 m/s: 0.03 at 15 m/s, none at rest.
        for (speed, bias) in [(15.0, 0.03), (0.0, 0.0)] {
            let g = inject(&flat_log(3, 1.0, 2.0, speed), &GyroErrors { vibration_bias_dps: 0.06, ..Default::default() }).unwrap();
            assert!(g.column(Column::GyroDps).unwrap().iter().all(|&v| (v - 2.0 - bias).abs() < 1e-12), "{speed} m/s");
        }
        // Noise 0.4 deg/s at 30 m/s: sigma 0.2 at 15 m/s (20 000 rows: sigma within 2 %, mean
        // within 4 standard errors), nothing at rest.
        let e = GyroErrors { vibration_noise_dps: 0.4, seed: 5, ..Default::default() };
        let g = inject(&flat_log(20_000, 0.1, 0.0, 15.0), &e).unwrap();
        let x = g.column(Column::GyroDps).unwrap();
        let mean = x.iter().sum::<f64>() / x.len() as f64;
        let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / x.len() as f64).sqrt();
        assert!((sd / 0.2 - 1.0).abs() < 0.02 && mean.abs() < 4.0 * 0.2 / (x.len() as f64).sqrt(), "sd {sd}, mean {mean}");
        let still = inject(&flat_log(100, 0.1, 0.0, 0.0), &e).unwrap();
        assert!(still.column(Column::GyroDps).unwrap().iter().all(|&v| v == 0.0));
        assert!(inject(&flat_log(3, 1.0, 0.0, 1.0), &GyroErrors { vibration_noise_dps: -0.1, ..Default::default() }).is_err());
    }

    #[test]
    fn quantisation_and_lead_in_cut() {
        let l = flat_log(10, 1.0, 0.123, 0.0);
        let g = inject(&l, &GyroErrors { lsb_dps: 0.05, cut_lead_in: true, ..Default::default() }).unwrap();
        assert_eq!(g.len(), 5, "rows with t < 5 s cut");
        assert_eq!(g.time_s()[0], 5.0);
        assert_eq!(g.meta.bias_s, Some(0.0));
        assert!(g.column(Column::GyroDps).unwrap().iter().all(|&v| (v - 0.1).abs() < 1e-12));
        assert!(inject(&l, &GyroErrors { bias_dps: f64::NAN, ..Default::default() }).is_err());
    }

    #[test]
    fn gyro_only_drops_speed_and_wheels_after_the_speed_driven_errors() {
        let mut l = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps, Column::OdoLeftM, Column::OdoRightM]);
        for i in 0..3 {
            let t = i as f64;
            l.push_row(&[
                (Column::TimeS, t),
                (Column::GyroDps, 1.0),
                (Column::SpeedMps, 15.0),
                (Column::OdoLeftM, t),
                (Column::OdoRightM, t),
            ]);
        }
        let g = inject(&l, &GyroErrors { vibration_bias_dps: 0.06, gyro_only: true, ..Default::default() }).unwrap();
        assert_eq!(g.present_columns(), vec![Column::TimeS, Column::GyroDps]);
        // The vibration still saw the speed: +0.03 at 15 m/s.
        assert!(g.column(Column::GyroDps).unwrap().iter().all(|&v| (v - 1.03).abs() < 1e-12));
    }

    /// A bias of 2e4 deg/s makes a log no reader takes back: refused at its first row; 9e3
    /// is still a rate (the log's physical range is +-1e4 deg/s).
    #[test]
    fn errors_that_take_the_rate_out_of_range_are_refused_with_the_time() {
        let l = flat_log(10, 1.0, 0.0, 0.0);
        let e = GyroErrors { bias_dps: 2e4, ..Default::default() };
        let msg = inject(&l, &e).unwrap_err().to_string();
        assert!(msg.contains("at 0 s") && msg.contains("outside the physical range [-10000, 10000] deg/s"), "{msg}");
        assert!(inject(&l, &GyroErrors { bias_dps: 9e3, ..Default::default() }).is_ok());
    }

    #[test]
    fn allan_deviation_of_a_static_log_recovers_the_configured_noise_and_walk() {
        // 10 h at rest, 10 Hz: white noise 0.1 deg/s per row (angle random walk
        // N = 0.1 sqrt(0.1 s) = 0.0316 deg/sqrt(s)) and a bias walk K = 0.001 deg/s/sqrt(s),
        // whose Allan deviation is K sqrt(tau / 3) (IEEE 952, Annex C).
        let mut l = flat_log(360_000, 0.1, 0.0, 0.0);
        l.meta.bias_s = Some(0.0);
        let e = GyroErrors { noise_dps: 0.1, walk_dps_per_sqrt_s: 0.001, seed: 3, ..Default::default() };
        let r = crate::allan::run(&inject(&l, &e).unwrap()).unwrap();
        let n = 0.1 * 0.1f64.sqrt();
        assert!((r.arw_deg_per_sqrt_s / n - 1.0).abs() < 0.05, "ARW {} against {n}", r.arw_deg_per_sqrt_s);
        for (&tau, &adev) in r.tau_s.iter().zip(&r.adev_dps) {
            if (1000.0..=3000.0).contains(&tau) {
                let model = (n * n / tau + 0.001 * 0.001 * tau / 3.0).sqrt();
                assert!((adev / model - 1.0).abs() < 0.3, "tau {tau}: adev {adev} against {model}");
            }
        }
    }

    #[test]
    fn same_seed_same_errors() {
        let l = flat_log(500, 0.1, 0.0, 0.0);
        let e = GyroErrors { walk_dps_per_sqrt_s: 0.01, noise_dps: 0.1, step_dps: 0.1, step_every_s: 10.0, seed: 7, ..Default::default() };
        assert_eq!(inject(&l, &e).unwrap(), inject(&l, &e).unwrap());
        assert_ne!(inject(&l, &e).unwrap(), inject(&l, &GyroErrors { seed: 8, ..e }).unwrap());
    }
}
