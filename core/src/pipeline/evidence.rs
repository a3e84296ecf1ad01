//! Which blocks are evidence about the bias, judged without the bias estimate (so a large
//! unknown bias cannot lock itself out): stop blocks, trimmed at both ends, plausible as a
//! bias and steady within their stop; and straight-road blocks, near the dominant rate (the
//! half-sample mode) of the recent moving blocks, HDR's heuristic.

use super::noise::NoiseLevel;
use super::params::PipelineParams;
use std::collections::VecDeque;

/// The evidence rules' state: the current stop and its delayed blocks, and the window of
/// recent moving blocks.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Default)]
pub(super) struct Evidence {
    stop_start_s: Option<f64>,
    pending: VecDeque<(f64, f64)>,
    pub(super) stop: StopStats,
    window: VecDeque<(f64, f64)>,
    /// The window's rates in order (`f64::total_cmp`), kept as blocks come and go, so the
    /// mode needs no sort per block; empty until rebuilt, as after a resumed snapshot.
    #[cfg_attr(feature = "snapshot", serde(skip))]
    sorted: Vec<f64>,
    /// The declared lead-in's last block rate, evidence or not (None before it).
    lead_last_dps: Option<f64>,
    /// The turn-on bias, the centre of the biases accepted: the lead-in's, or where there
    /// was none, a long standing's beyond the bounds about 0 (0 until then), and whether
    /// one of them has set it.
    pub(super) centre_dps: f64,
    centre_known: bool,
    /// This stop's steady run of blocks refused only as implausible, while no lead-in set
    /// the centre.
    refused: StopStats,
    /// The last block was the declared lead-in's.
    in_lead: bool,
    /// The gyro's noise at a standstill, from consecutive still blocks (`noise.rs`), and the
    /// last still block's rate (None after a moving one).
    noise: NoiseLevel,
    last_still_dps: Option<f64>,
}

/// A standing this long (s) at a steady rate is the bias, however large: a road vehicle
/// whose speed or wheels say it stands does not turn at more than `max_bias_dps` for this
/// long (a slow turn with the GPS speed held at zero lasts seconds).
const LONG_STANDING_S: f64 = 10.0;

impl Evidence {
    /// This block's stop evidence: the lead-in's blocks at once, a stop's once they are
    /// `min_still_s` from both of its ends (so delayed); either plausible as a bias and
    /// steady within its stop or lead-in. Never judged by closeness to the estimate.
    pub(super) fn stops(&mut self, p: &PipelineParams, time_s: f64, rate_dps: f64, still: bool, lead_in: bool) -> Vec<f64> {
        let mut stops: Vec<f64> = Vec::new();
        let lead_last = self.lead_last_dps;
        let after_lead = std::mem::replace(&mut self.in_lead, lead_in);
        if let Some(last) = self.last_still_dps.filter(|_| still || lead_in) {
            self.noise.add((rate_dps - last) * (rate_dps - last) / 2.0);
        }
        self.last_still_dps = (still || lead_in).then_some(rate_dps);
        if lead_in {
            self.lead_last_dps = Some(rate_dps);
            stops.push(rate_dps);
        } else if still {
            let start = *self.stop_start_s.get_or_insert(time_s);
            // A standing that goes on after the lead-in is steady as the lead-in's blocks
            // are (its first blocks still trimmed: the declared end may be the pull-away).
            if start == time_s && !after_lead {
                self.stop = StopStats::default();
                self.refused = StopStats::default();
            }
            self.pending.push_back((time_s, rate_dps));
            while let Some(&(t, z)) = self.pending.front() {
                if t - start < p.min_still_s {
                    self.pending.pop_front();
                } else if time_s - t >= p.min_still_s {
                    self.pending.pop_front();
                    stops.push(z);
                } else {
                    break;
                }
            }
        } else {
            self.stop_start_s = None;
            self.pending.clear();
        }
        // Plausible as a bias, stop or declared lead-in alike: within max_bias_dps of the
        // turn-on bias; a faster rate is a turn (a slow turn with the GPS speed held at zero,
        // a `# bias_s:` that covers a turn). A lead-in block also when the lead-in's block
        // before agrees with it: a turn-on bias beyond max_bias_dps (an uncalibrated MEMS
        // part) that the standing shows is learned, as the static bias takes it, not refused
        // for good (a turn is not that steady). And steady within the stop or the
        // lead-in: a block far from its mean is a slow turn (a car that pulls away before
        // the declared lead-in ends).
        let (max, tol) = (p.max_bias_dps, 4.0 * self.stop_sigma_dps(p) + 0.1);
        let (mean, n, centre) = (self.stop.mean, self.stop.n, self.centre_dps);
        let plausible = |z: f64| (z - centre).abs() <= max || lead_in && lead_last.is_some_and(|l| (z - l).abs() <= tol);
        if !lead_in && !self.centre_known {
            for &z in stops.iter().filter(|z| !plausible(**z)) {
                self.refuse(time_s, z, tol);
            }
        }
        stops.retain(|&z| plausible(z) && (n == 0 || (z - mean).abs() <= tol));
        // Without a lead-in, a long steady standing beyond the bounds: its mean rate is the
        // bias (one block's evidence; the stop's next blocks add theirs).
        if self.refused.last_s - self.refused.first_s >= LONG_STANDING_S {
            (self.centre_dps, self.centre_known) = (self.refused.mean, true);
            stops = vec![self.refused.mean];
            self.stop = StopStats::default();
            self.refused = StopStats::default();
        }
        for &z in &stops {
            self.stop.add(time_s, z);
        }
        if lead_in && !stops.is_empty() {
            (self.centre_dps, self.centre_known) = (self.stop.mean, true);
        }
        stops
    }

    /// A stop block's noise, what a stop's steadiness is judged by: the setting, or the
    /// gyro's measured at a standstill where larger (deg/s).
    pub(super) fn stop_sigma_dps(&self, p: &PipelineParams) -> f64 {
        self.noise.at_least(p.stop_sigma_dps)
    }

    /// A stop block refused only as implausible joins this stop's steady run of such blocks
    /// (a block far from the run's mean starts a new one).
    fn refuse(&mut self, time_s: f64, z: f64, tol: f64) {
        if self.refused.n > 0 && (z - self.refused.mean).abs() > tol {
            self.refused = StopStats::default();
        }
        self.refused.add(time_s, z);
    }

    /// A moving block is straight-road evidence when it is within the gate of the dominant
    /// rate of the recent moving blocks, and that rate is plausible as a bias (within
    /// max_bias_dps of the turn-on bias).
    pub(super) fn is_straight(&mut self, p: &PipelineParams, time_s: f64, rate_dps: f64) -> bool {
        if self.sorted.len() != self.window.len() {
            self.sorted = self.window.iter().map(|w| w.1).collect();
            self.sorted.sort_by(f64::total_cmp);
        }
        self.window.push_back((time_s, rate_dps));
        let at = self.sorted.partition_point(|v| v.total_cmp(&rate_dps).is_lt());
        self.sorted.insert(at, rate_dps);
        while let Some(&(_, r)) = self.window.front().filter(|&&(t, _)| time_s - t > p.road_window_s) {
            self.window.pop_front();
            if let Ok(i) = self.sorted.binary_search_by(|v| v.total_cmp(&r)) {
                self.sorted.remove(i);
            }
        }
        if self.window.len() < 5 {
            return false;
        }
        // The dominant rate is a bias only if a bias could be that large (a drive in circles
        // is not straight).
        let (mode, step) = self.window_mode_and_step();
        // A quantised gyro (one row per block) puts the mode on its lattice: keep the gate
        // two steps wide so the selection stays centred.
        let gate = p.road_gate_dps.max(2.0 * step);
        (mode - self.centre_dps).abs() <= p.max_bias_dps && (rate_dps - mode).abs() <= gate
    }

    /// The dominant rate of the recent moving blocks (where a road vehicle drives
    /// straight), and the smallest non-zero step between them: the gyro's quantisation
    /// when a block holds one row (infinite steps count as 1 deg/s).
    fn window_mode_and_step(&self) -> (f64, f64) {
        let r = &self.sorted;
        let step = r.windows(2).map(|w| w[1] - w[0]).filter(|&d| d > 1e-6).fold(1.0, f64::min);
        (half_sample_mode_of_sorted(r), step)
    }
}

/// Running mean and spread of the current stop's evidence (Welford).
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct StopStats {
    pub(super) n: usize,
    pub(super) first_s: f64,
    pub(super) last_s: f64,
    pub(super) mean: f64,
    pub(super) m2: f64,
    pub(super) reopened: bool,
}

impl StopStats {
    pub(super) fn add(&mut self, t: f64, z: f64) {
        if self.n == 0 {
            self.first_s = t;
        }
        self.last_s = t;
        self.n += 1;
        let d = z - self.mean;
        self.mean += d / self.n as f64;
        self.m2 += d * (z - self.mean);
    }
    pub(super) fn std(&self) -> f64 {
        if self.n < 2 {
            f64::INFINITY
        } else {
            (self.m2 / (self.n - 1) as f64).sqrt()
        }
    }
}

/// Bickel's half-sample mode: the densest point of a sample, robust to half of it being
/// elsewhere (the turns). Sorts `x` in place; `x` must not be empty. Equally dense halves
/// (a quantised gyro's lattice makes many) are not resolved to the lowest: the search goes
/// on within their span, or, where that span is the whole sample, ends at their mean centre.
pub fn half_sample_mode(x: &mut [f64]) -> f64 {
    x.sort_by(f64::total_cmp);
    half_sample_mode_of_sorted(x)
}

/// [`half_sample_mode`] of a sample already in order (`f64::total_cmp`).
fn half_sample_mode_of_sorted(x: &[f64]) -> f64 {
    // Widths within this are equal (deg/s): a constant added to a lattice rounds its
    // differences apart by 1e-16, and the mode must move with the constant, not jump.
    const TIE: f64 = 1e-9;
    let mut s = x;
    while s.len() > 3 {
        let h = s.len().div_ceil(2);
        let width = |i: usize| s[i + h - 1] - s[i];
        let min = (0..=s.len() - h).map(width).fold(f64::INFINITY, f64::min);
        let ties: Vec<usize> = (0..=s.len() - h).filter(|&i| width(i) <= min + TIE).collect();
        let (lo, hi) = (ties[0], ties[ties.len() - 1]);
        if lo == hi {
            s = &s[lo..lo + h];
        } else if hi + h - lo < s.len() {
            s = &s[lo..hi + h];
        } else {
            return ties.iter().map(|&i| (s[i] + s[i + h - 1]) / 2.0).sum::<f64>() / ties.len() as f64;
        }
    }
    match s.len() {
        3 => {
            let d = (s[1] - s[0]) - (s[2] - s[1]);
            if d < -TIE {
                (s[0] + s[1]) / 2.0
            } else if d > TIE {
                (s[1] + s[2]) / 2.0
            } else {
                s[1]
            }
        }
        2 => (s[0] + s[1]) / 2.0,
        _ => s[0],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kept order is the window's, sorted, as blocks come and go: a quantised gyro's
    /// repeated rates (0.0 and -0.0 among them) and a gap longer than the window, and after
    /// the order is lost (a resumed snapshot keeps none) it is rebuilt.
    #[test]
    fn the_kept_order_is_the_window_sorted_as_blocks_come_and_go() {
        let p = PipelineParams::default();
        let mut e = Evidence::default();
        let mut t = 0.0;
        for i in 0..400u32 {
            t += if i == 200 { 2.0 * p.road_window_s } else { 1.0 };
            let rate = [0.0, -0.0, 0.1, 0.1, -0.2, 0.3, 0.1][(i as usize * 5) % 7] + f64::from(i % 3) * 0.1;
            if i == 300 {
                e.sorted.clear();
            }
            e.is_straight(&p, t, rate);
            let mut want: Vec<f64> = e.window.iter().map(|w| w.1).collect();
            want.sort_by(f64::total_cmp);
            let same = want.len() == e.sorted.len() && want.iter().zip(&e.sorted).all(|(a, b)| a.to_bits() == b.to_bits());
            assert!(same, "block {i}: {:?} against {want:?}", e.sorted);
        }
        assert_eq!(e.window.len(), 61, "the blocks of the last 60 s, both ends kept");
    }
}
