//! The yaw-rate spectrum of moving driving (the heading's spectrum times frequency squared),
//! as the power in five period bands per 64 s window of 1 Hz blocks: Hann window, the
//! window's mean removed (the slow rate is a statistic of its own), half-overlapping
//! windows. Sway, lane changes, bends and turns sit in different bands, so recorded and
//! simulated roads compare band by band (issue 13, item 1: heading spectra by road type).

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// Window length, s (1 Hz blocks): DFT bins k = 1..32 are periods 64 s down to 2 s.
pub const WINDOW_S: usize = 64;
/// Windows start every this many seconds (half-overlapping, as Welch's method).
pub const STEP_S: usize = 32;
/// The bands as inclusive DFT-bin ranges of a 64 s window (period = 64 s / k).
pub const BANDS: [(usize, usize); 5] = [(1, 1), (2, 3), (4, 7), (8, 15), (16, 32)];
/// The bands by period, for tables.
pub const BAND_NAMES: [&str; 5] = ["64 s", "32-21 s", "16-9 s", "8-4 s", "4-2 s"];

/// A planned 64-point DFT (rustfft), shared by the windows of a drive.
pub struct Spectrum {
    fft: Arc<dyn Fft<f64>>,
    hann: Vec<f64>,
    hann_sq_sum: f64,
}

impl Default for Spectrum {
    fn default() -> Self {
        let fft = FftPlanner::new().plan_fft_forward(WINDOW_S);
        let hann: Vec<f64> = (0..WINDOW_S).map(|n| 0.5 - 0.5 * (2.0 * std::f64::consts::PI * n as f64 / WINDOW_S as f64).cos()).collect();
        let hann_sq_sum = hann.iter().map(|w| w * w).sum();
        Spectrum { fft, hann, hann_sq_sum }
    }
}

impl Spectrum {
    /// The power of each band in one window of `WINDOW_S` rates, (deg/s)^2: one-sided
    /// periodogram `2 |X_k|^2 / (N sum w^2)` (the Nyquist bin once), so the bands of a window
    /// of white noise add up to its variance.
    pub fn band_powers(&self, rate_dps: &[f64]) -> [f64; 5] {
        assert_eq!(rate_dps.len(), WINDOW_S, "a window is {WINDOW_S} blocks");
        let mean = rate_dps.iter().sum::<f64>() / WINDOW_S as f64;
        let mut buf: Vec<Complex<f64>> = rate_dps.iter().zip(&self.hann).map(|(x, w)| Complex::new((x - mean) * w, 0.0)).collect();
        self.fft.process(&mut buf);
        let scale = WINDOW_S as f64 * self.hann_sq_sum;
        BANDS.map(|(lo, hi)| (lo..=hi).map(|k| if k == WINDOW_S / 2 { 1.0 } else { 2.0 } * buf[k].norm_sqr() / scale).sum())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sine_lands_in_its_band_with_hann_leakage_hand_worked() {
        // amplitude 2 deg/s at bin 8 (period 8 s) plus a constant: power A^2/2 = 2 in all.
        // Hann spreads bin 8 to bins 7 and 9 with a quarter of its power each: bin 7 (band
        // 16-9 s) holds 1/6 of the total, bins 8 and 9 (band 8-4 s) 5/6.
        let x: Vec<f64> = (0..64).map(|n| 0.7 + 2.0 * (2.0 * std::f64::consts::PI * 8.0 * n as f64 / 64.0).sin()).collect();
        let p = Spectrum::default().band_powers(&x);
        let want = [0.0, 0.0, 2.0 / 6.0, 2.0 * 5.0 / 6.0, 0.0];
        for (g, w) in p.iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{p:?}");
        }
    }

    #[test]
    fn white_noise_adds_up_to_its_variance_and_spreads_by_bins() {
        // a deterministic +-1 sequence (variance 1): over many windows the bands hold about
        // their share of the 32 bins (Hann leakage moves little for a flat spectrum)
        let s = Spectrum::default();
        let mut state = 12345u64;
        let (mut total, mut bands, windows) = (0.0, [0.0; 5], 400);
        for _ in 0..windows {
            let x: Vec<f64> = (0..64)
                .map(|_| {
                    state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    if state >> 63 == 1 {
                        1.0
                    } else {
                        -1.0
                    }
                })
                .collect();
            let p = s.band_powers(&x);
            total += p.iter().sum::<f64>() / windows as f64;
            for (b, v) in bands.iter_mut().zip(p) {
                *b += v / windows as f64;
            }
        }
        assert!((total - 1.0).abs() < 0.05, "{total}");
        // bins per band 1, 2, 4, 8, 17 (of 32, the Nyquist bin counted once: 31.5)
        for (b, bins) in bands.iter().zip([1.0, 2.0, 4.0, 8.0, 16.5]) {
            assert!((b - bins / 31.5).abs() < 0.03, "{bands:?}");
        }
    }
}
