//! Two peers of the pipeline, scored with the same metric code:
//!
//! - x-io Fusion's gyroscope offset algorithm (`FusionOffset.c`, reimplemented from its
//!   published source on the yaw axis): after the rate has stayed within 3 deg/s for 5 s, the
//!   offset follows the rate through a first-order low-pass filter with a 0.02 Hz cutoff;
//! - a plain zero-rate update at stops: the bias is the mean rate of the current stop, and
//!   the heading is held while standing.

use crate::error::Result;
use crate::log::DriveLog;
use crate::preprocess;
use crate::still::Blocks;

/// The ZARU peer counts a stop after this long, s (fixed: a peer does not follow the
/// pipeline's settings).
pub const ZARU_MIN_STILL_S: f64 = 2.0;

/// x-io Fusion's `FusionOffset`, one axis.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone)]
pub struct FusionOffset {
    filter_coefficient: f64,
    timeout: u32,
    timer: u32,
    offset_dps: f64,
}

impl FusionOffset {
    pub const CUTOFF_FREQUENCY_HZ: f64 = 0.02;
    pub const TIMEOUT_S: u32 = 5;
    pub const THRESHOLD_DPS: f64 = 3.0;

    /// `FusionOffsetInitialise(offset, sampleRate)`; the rate is an integer in Fusion.
    pub fn new(sample_rate_hz: u32) -> Self {
        let rate = sample_rate_hz.max(1);
        FusionOffset {
            filter_coefficient: 2.0 * std::f64::consts::PI * Self::CUTOFF_FREQUENCY_HZ * (1.0 / rate as f64),
            timeout: Self::TIMEOUT_S * rate,
            timer: 0,
            offset_dps: 0.0,
        }
    }

    /// `FusionOffsetUpdate`: the rate with the offset removed.
    pub fn update(&mut self, rate_dps: f64) -> f64 {
        let g = rate_dps - self.offset_dps;
        if g.abs() > Self::THRESHOLD_DPS {
            self.timer = 0;
            return g;
        }
        if self.timer < self.timeout {
            self.timer += 1;
            return g;
        }
        self.offset_dps += g * self.filter_coefficient;
        g
    }

    /// As `new`, with the offset already at `offset_dps` (an estimate known at the start).
    pub fn starting_at(sample_rate_hz: u32, offset_dps: f64) -> Self {
        FusionOffset { offset_dps, ..Self::new(sample_rate_hz) }
    }

    pub fn offset_dps(&self) -> f64 {
        self.offset_dps
    }
}

/// Heading from the rows with FusionOffset after the static bias (unaligned), at the
/// sample rate of the rows (rounded, as Fusion takes an integer rate).
pub fn fusion_offset_heading(log: &DriveLog, bias_s: f64) -> Result<(Vec<f64>, Vec<f64>)> {
    let (eps0, rows) = preprocess::prepare(log, Some(bias_s), false)?;
    let n = rows.len();
    let span = rows.time_s[n - 1] - rows.time_s[0];
    let rate_hz = if n > 1 && span > 0.0 { ((n - 1) as f64 / span).round() as u32 } else { 1 };
    let mut f = FusionOffset::new(rate_hz);
    let mut psi = Vec::with_capacity(n);
    let mut h = 0.0;
    for i in 0..n {
        let w = f.update(rows.rate_dps[i] - eps0);
        if i > 0 {
            h += w * (rows.time_s[i] - rows.time_s[i - 1]);
        }
        psi.push(h);
    }
    Ok((rows.time_s, psi))
}

/// A plain zero-rate update, streaming on 1 Hz blocks: a block counts as a stop once the
/// vehicle has stood `min_still_s`; the bias is then the mean rate of the stop's counted
/// blocks, kept until the next stop; the heading is held while standing.
#[derive(Debug, Clone)]
pub struct Zaru {
    min_still_s: f64,
    bias_dps: f64,
    heading_deg: f64,
    run_s: f64,
    sum: f64,
    n: usize,
    last_time_s: Option<f64>,
}

impl Zaru {
    /// Starts from the static bias.
    pub fn new(min_still_s: f64, eps0_dps: f64) -> Self {
        Zaru { min_still_s, bias_dps: eps0_dps, heading_deg: 0.0, run_s: 0.0, sum: 0.0, n: 0, last_time_s: None }
    }

    /// The bias in use (before the next block's evidence), deg/s.
    pub fn bias_dps(&self) -> f64 {
        self.bias_dps
    }

    /// One block; returns the heading.
    pub fn update(&mut self, time_s: f64, rate_dps: f64, still: bool) -> f64 {
        let dt = self.last_time_s.map_or(0.0, |t| time_s - t);
        self.last_time_s = Some(time_s);
        if still {
            self.run_s += dt;
            if self.run_s >= self.min_still_s {
                self.sum += rate_dps;
                self.n += 1;
                self.bias_dps = self.sum / self.n as f64;
            }
        } else {
            (self.run_s, self.sum, self.n) = (0.0, 0.0, 0);
            self.heading_deg += (rate_dps - self.bias_dps) * dt;
        }
        self.heading_deg
    }
}

/// Heading on the blocks with [`Zaru`] (unaligned).
pub fn zaru_heading(blocks: &Blocks, min_still_s: f64, eps0_dps: f64) -> Vec<f64> {
    let mut z = Zaru::new(min_still_s, eps0_dps);
    (0..blocks.len()).map(|i| z.update(blocks.time_s[i], blocks.rate_dps[i], blocks.still[i])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fusion_offset_hand_worked() {
        // 10 Hz: coefficient 2 pi 0.02 / 10, timeout 50 samples.
        let mut f = FusionOffset::new(10);
        for _ in 0..50 {
            assert_eq!(f.update(1.0), 1.0);
        }
        assert_eq!(f.offset_dps(), 0.0, "no change until the timer has run out");
        let c = 2.0 * std::f64::consts::PI * 0.02 / 10.0;
        assert_eq!(f.update(1.0), 1.0);
        assert!((f.offset_dps() - c).abs() < 1e-15);
        assert!((f.update(1.0) - (1.0 - c)).abs() < 1e-15);
        assert!((f.offset_dps() - (c + (1.0 - c) * c)).abs() < 1e-15);
        // A turn resets the timer.
        let off = f.offset_dps();
        f.update(10.0);
        f.update(1.0);
        assert_eq!(f.offset_dps(), off);
    }

    #[test]
    fn zaru_hand_worked() {
        let b = Blocks {
            time_s: vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0],
            rate_dps: vec![0.2, 0.2, 0.4, 1.2, 5.2, 0.0],
            temp_c: vec![f64::NAN; 6],
            still: vec![true, true, true, false, false, true],
            origin_s: 0.0,
            first_moving_s: None,
            lead_in_wander: None,
            source: crate::still::StillSource::Speed,
        };
        // Stop blocks 0..2: run 0, 1, 2 s -> only block 2 counts (min 2 s): bias 0.4.
        // Block 3: 1.2 - 0.4 = 0.8; block 4: 5.2 - 0.4 -> 0.8 + 4.8 = 5.6; block 5 held.
        let psi = zaru_heading(&b, 2.0, 0.1);
        assert_eq!(psi.len(), 6);
        assert!((psi[3] - 0.8).abs() < 1e-12 && (psi[4] - 5.6).abs() < 1e-12 && psi[5] == psi[4]);
    }
}
