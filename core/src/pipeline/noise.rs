//! The gyro's noise at a standstill, measured from the log: half the squared difference of
//! consecutive still blocks' rates (`evidence.rs`) is, in expectation, the noise variance
//! of a block's mean.
//! A stop is steady when its blocks agree within a few of its blocks' noise; the setting
//! (`stop_sigma_dps`, 0.05 deg/s) is a quiet gyro's, and a noisy gyro's stops judged by it
//! were refused block by block (1 deg/s on each 10 Hz row is 0.32 deg/s on a block's mean);
//! weighed by it, they looked like a moving bias to the bank (`filter.rs`, `stop_update`).
//! The level is a running median, tracked in the log domain by a fixed step toward each new
//! value (a stochastic-approximation median: one odd pair, a slow turn with the GPS speed
//! held at zero, moves it one step, however large; an exponential mean instead took the
//! VN-100 circle drive's turning "standings" for noise and its NE_psi from 1.26 to 69).
//! The median is not the mean: for Gaussian noise each value is sigma^2 times a chi-square
//! of one degree, whose median is 0.455, so the median is divided by it to read sigma^2
//! (as a MAD is scaled by 1.4826).

/// The median's step per block, in natural log of the variance: a factor e in 20 blocks,
/// jitter of about 5 % once there.
const STEP: f64 = 0.05;

/// One over the square root of a one-degree chi-square's median (0.455): the tracked
/// median's square root times this is sigma (a MAD's 1.4826).
const SIGMA_PER_ROOT_MEDIAN: f64 = 1.482_602_218_505_602;

/// Smallest variance tracked (deg^2/s^2): a block of equal rows (a quantised gyro at rest)
/// measures 0, whose log would pin the median.
const FLOOR_DPS2: f64 = 1e-12;

/// The running median of the still blocks' noise variances: the natural log of deg^2/s^2,
/// None before two consecutive still blocks.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct NoiseLevel {
    log_var: Option<f64>,
}

impl NoiseLevel {
    /// One measure of a still block's noise variance (deg^2/s^2; NaN = unknown, skipped).
    pub(super) fn add(&mut self, var_dps2: f64) {
        if var_dps2.is_finite() && var_dps2 >= 0.0 {
            let x = libm::log(var_dps2.max(FLOOR_DPS2));
            self.log_var = Some(self.log_var.map_or(x, |m| m + STEP * (x - m).signum()));
        }
    }

    /// A stop block's noise: the setting `sigma_dps` or the measured one, whichever is
    /// larger (deg/s). What a stop's steadiness is judged by (`evidence.rs`, the step
    /// guard) and its blocks weigh the hypotheses by; the stop's update keeps the setting.
    pub(super) fn at_least(&self, sigma_dps: f64) -> f64 {
        self.log_var.map_or(sigma_dps, |m| sigma_dps.max(SIGMA_PER_ROOT_MEDIAN * libm::exp(m / 2.0)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Blocks 0.04, then 0.09 and 0.01: the first sets the median (0.04, so sigma
    /// 0.2 / 0.6745 = 0.2965), each next one steps it by 0.05 in log toward itself: up, then
    /// down, back to sigma 0.2965; a setting of 0.05 is widened to it, one of 0.4 is kept. NaN
    /// is skipped. A block of equal rows (0) starts from the floor's log and steps from there
    /// (a tie steps up), not from minus infinity.
    #[test]
    fn the_measured_noise_widens_the_setting_only_above_it_hand_worked() {
        let mut n = NoiseLevel::default();
        assert_eq!(n.at_least(0.05), 0.05);
        for v in [0.04, f64::NAN, 0.09] {
            n.add(v);
        }
        let sigma = 0.2 / 0.674_489_750_196_081_7;
        assert!((n.at_least(0.05) - sigma * libm::exp(0.025)).abs() < 1e-12);
        n.add(0.01);
        assert!((n.at_least(0.05) - sigma).abs() < 1e-12 && n.at_least(0.4) == 0.4);
        let mut z = NoiseLevel::default();
        z.add(0.0);
        z.add(0.0);
        assert!((z.at_least(0.0) / libm::exp((libm::log(FLOOR_DPS2) + STEP) / 2.0) - 1.0 / 0.674_489_750_196_081_7).abs() < 1e-12);
    }
}
