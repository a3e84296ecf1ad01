//! The road samples of one drive: its moving 1 Hz blocks, classified by speed, and the
//! distributions measured on them.

use super::events::s_manoeuvres;
use super::spectrum::{Spectrum, STEP_S, WINDOW_S};
use super::{CLASS_WINDOW_S, HIGHWAY_MIN_MPS, MOVING_MPS, STILL_MPS, THETA_W_DPS, URBAN_MAX_MPS};
use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use crate::metrics::{mean_std, quantile, quantile_mut};
use crate::preprocess::blocks_1hz;
use serde::Serialize;

/// A road class, judged by the mean speed of the minute around a block.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum RoadClass {
    Urban,
    Rural,
    Highway,
}

impl RoadClass {
    pub const ALL: [RoadClass; 3] = [RoadClass::Urban, RoadClass::Rural, RoadClass::Highway];

    pub fn of_speed(mps: f64) -> RoadClass {
        if mps < URBAN_MAX_MPS {
            RoadClass::Urban
        } else if mps > HIGHWAY_MIN_MPS {
            RoadClass::Highway
        } else {
            RoadClass::Rural
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            RoadClass::Urban => "urban",
            RoadClass::Rural => "rural",
            RoadClass::Highway => "highway",
        }
    }
}

/// The samples behind the statistics (pooled over drives before comparing).
#[derive(Debug, Clone, Default, Serialize)]
pub struct RoadSamples {
    pub moving_min: f64,
    /// |yaw rate| of each moving 1 Hz block, bias removed, deg/s.
    pub abs_rate_dps: Vec<f64>,
    /// Lengths of runs of consecutive moving blocks below theta_w, s.
    pub straight_runs_s: Vec<f64>,
    /// |mean yaw rate| over 30 s windows (every 10 s) of moving blocks all below 3 deg/s:
    /// the slow curvature of roads that look straight, deg/s.
    pub slow_rate_dps: Vec<f64>,
    /// Lengths of runs of consecutive moving blocks at or above theta_w (curves, turns), s.
    pub curve_runs_s: Vec<f64>,
    /// |heading change| over each such run, deg.
    pub curve_deg: Vec<f64>,
    /// Radius of each such run: mean speed over mean |yaw rate| (in rad/s), m.
    pub curve_radius_m: Vec<f64>,
    /// Yaw-rate power per period band (`spectrum::BANDS`) of each 64 s window of
    /// consecutive moving blocks, (deg/s)^2.
    pub band_power_dps2: [Vec<f64>; 5],
    /// Length of each S-manoeuvre (lane-change-like, `events::s_manoeuvres`), s.
    pub s_length_s: Vec<f64>,
    /// Its largest heading excursion, deg.
    pub s_peak_deg: Vec<f64>,
    /// Fast sway: the residual standard deviation about the least-squares line of each
    /// 10 s window (every 5 s) of consecutive moving blocks all below 3 deg/s, deg/s. The
    /// line takes the road's slow curvature out, so what is left is the driver's weaving
    /// and quick steering, which HDR's turn switch and sign steps see on every straight.
    pub sway_dps: Vec<f64>,
}

/// Window and step of the fast-sway statistic, s.
pub const SWAY_WINDOW_S: usize = 10;
pub const SWAY_STEP_S: usize = 5;

/// Residual standard deviation of `y` (one value a second) about its least-squares line
/// (n - 2 degrees of freedom); None under 3 values.
pub fn detrended_std(y: &[f64]) -> Option<f64> {
    let n = y.len();
    if n < 3 {
        return None;
    }
    let xm = (n - 1) as f64 / 2.0;
    let ym = y.iter().sum::<f64>() / n as f64;
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for (i, &v) in y.iter().enumerate() {
        let dx = i as f64 - xm;
        sxx += dx * dx;
        sxy += dx * (v - ym);
        syy += (v - ym) * (v - ym);
    }
    Some(((syy - sxy * sxy / sxx).max(0.0) / (n - 2) as f64).sqrt())
}

/// One row of the comparison table.
#[derive(Debug, Clone, Serialize)]
pub struct RoadSummary {
    pub moving_min: f64,
    pub rate_p50_dps: f64,
    pub rate_p75_dps: f64,
    pub rate_p90_dps: f64,
    pub below_theta_w: f64,
    pub straight_run_mean_s: f64,
    pub straight_run_p90_s: f64,
    pub slow_rate_p50_dps: f64,
    pub slow_rate_p90_dps: f64,
    pub curve_run_p50_s: f64,
    pub curve_deg_p50: f64,
    pub curve_radius_p50_m: f64,
    /// Root of the mean power per spectrum band over the windows, deg/s.
    pub band_rms_dps: [f64; 5],
    /// S-manoeuvres (lane-change-like) per moving minute, their median length and excursion.
    pub s_per_min: f64,
    pub s_length_p50_s: f64,
    pub s_peak_p50_deg: f64,
    /// Fast sway (`RoadSamples::sway_dps`): quartiles, deg/s.
    pub sway_p25_dps: f64,
    pub sway_p50_dps: f64,
    pub sway_p75_dps: f64,
    /// Curve runs turning more than 180 degrees (roundabouts, ramps) per moving hour.
    pub loops_per_hour: f64,
}

impl RoadSamples {
    pub fn extend(&mut self, other: &RoadSamples) {
        self.moving_min += other.moving_min;
        self.abs_rate_dps.extend(&other.abs_rate_dps);
        self.straight_runs_s.extend(&other.straight_runs_s);
        self.slow_rate_dps.extend(&other.slow_rate_dps);
        self.curve_runs_s.extend(&other.curve_runs_s);
        self.curve_deg.extend(&other.curve_deg);
        self.curve_radius_m.extend(&other.curve_radius_m);
        for (a, b) in self.band_power_dps2.iter_mut().zip(&other.band_power_dps2) {
            a.extend(b);
        }
        self.s_length_s.extend(&other.s_length_s);
        self.s_peak_deg.extend(&other.s_peak_deg);
        self.sway_dps.extend(&other.sway_dps);
    }

    /// The summary figures.
    pub fn summary(&self) -> RoadSummary {
        let below = self.abs_rate_dps.iter().filter(|&&x| x < THETA_W_DPS).count() as f64 / self.abs_rate_dps.len().max(1) as f64;
        RoadSummary {
            moving_min: self.moving_min,
            rate_p50_dps: quantile(&self.abs_rate_dps, 0.5),
            rate_p75_dps: quantile(&self.abs_rate_dps, 0.75),
            rate_p90_dps: quantile(&self.abs_rate_dps, 0.9),
            below_theta_w: below,
            straight_run_mean_s: mean_std(&self.straight_runs_s).0,
            straight_run_p90_s: quantile(&self.straight_runs_s, 0.9),
            slow_rate_p50_dps: quantile(&self.slow_rate_dps, 0.5),
            slow_rate_p90_dps: quantile(&self.slow_rate_dps, 0.9),
            curve_run_p50_s: quantile(&self.curve_runs_s, 0.5),
            curve_deg_p50: quantile(&self.curve_deg, 0.5),
            curve_radius_p50_m: quantile(&self.curve_radius_m, 0.5),
            band_rms_dps: self.band_power_dps2.each_ref().map(|p| mean_std(p).0.sqrt()),
            s_per_min: self.s_length_s.len() as f64 / self.moving_min,
            s_length_p50_s: quantile(&self.s_length_s, 0.5),
            s_peak_p50_deg: quantile(&self.s_peak_deg, 0.5),
            sway_p25_dps: quantile(&self.sway_dps, 0.25),
            sway_p50_dps: quantile(&self.sway_dps, 0.5),
            sway_p75_dps: quantile(&self.sway_dps, 0.75),
            loops_per_hour: self.curve_deg.iter().filter(|&&d| d > 180.0).count() as f64 / (self.moving_min / 60.0),
        }
    }

    /// Samples of moving blocks `(second, rate deg/s, speed m/s)`; a gap in the seconds ends
    /// every run and window.
    fn of_blocks(moving: &[(i64, f64, f64)]) -> RoadSamples {
        let mut s = RoadSamples {
            moving_min: moving.len() as f64 / 60.0,
            abs_rate_dps: moving.iter().map(|m| m.1.abs()).collect(),
            ..Default::default()
        };
        let mut start = 0;
        for i in 0..moving.len() {
            let straight = moving[i].1.abs() < THETA_W_DPS;
            let ends = i + 1 == moving.len() || moving[i + 1].0 != moving[i].0 + 1 || (moving[i + 1].1.abs() < THETA_W_DPS) != straight;
            if ends {
                let run = &moving[start..=i];
                if straight {
                    s.straight_runs_s.push(run.len() as f64);
                } else {
                    let n = run.len() as f64;
                    let turned: f64 = run.iter().map(|m| m.1).sum();
                    let mean_rate_rad = run.iter().map(|m| m.1.abs()).sum::<f64>() / n * std::f64::consts::PI / 180.0;
                    s.curve_runs_s.push(n);
                    s.curve_deg.push(turned.abs());
                    s.curve_radius_m.push(run.iter().map(|m| m.2).sum::<f64>() / n / mean_rate_rad);
                }
                start = i + 1;
            }
        }
        for i in (0..moving.len().saturating_sub(30)).step_by(10) {
            let w = &moving[i..i + 30];
            if w[29].0 - w[0].0 == 29 && w.iter().all(|m| m.1.abs() < 3.0) {
                s.slow_rate_dps.push((w.iter().map(|m| m.1).sum::<f64>() / 30.0).abs());
            }
        }
        for w in consecutive_windows(moving, SWAY_WINDOW_S, SWAY_STEP_S).filter(|w| w.iter().all(|m| m.1.abs() < 3.0)) {
            let rates: Vec<f64> = w.iter().map(|m| m.1).collect();
            s.sway_dps.extend(detrended_std(&rates));
        }
        let mut start = 0;
        for i in 0..moving.len() {
            if i + 1 == moving.len() || moving[i + 1].0 != moving[i].0 + 1 {
                let rates: Vec<f64> = moving[start..=i].iter().map(|m| m.1).collect();
                for m in s_manoeuvres(&rates) {
                    s.s_length_s.push(m.length_s);
                    s.s_peak_deg.push(m.peak_deg);
                }
                start = i + 1;
            }
        }
        let spectrum = Spectrum::default();
        for w in consecutive_windows(moving, WINDOW_S, STEP_S) {
            let rates: Vec<f64> = w.iter().map(|m| m.1).collect();
            for (band, p) in s.band_power_dps2.iter_mut().zip(spectrum.band_powers(&rates)) {
                band.push(p);
            }
        }
        s
    }
}

/// Windows of `len` moving blocks starting every `step`, those over consecutive seconds
/// only (a stop or a gap ends every window).
fn consecutive_windows(moving: &[(i64, f64, f64)], len: usize, step: usize) -> impl Iterator<Item = &[(i64, f64, f64)]> {
    (0..(moving.len() + 1).saturating_sub(len))
        .step_by(step)
        .map(move |i| &moving[i..i + len])
        .filter(move |w| w[len - 1].0 - w[0].0 == len as i64 - 1)
}

/// A drive's samples: all moving blocks, and those of each road class.
#[derive(Debug, Clone, Default, Serialize)]
pub struct ClassedSamples {
    pub all: RoadSamples,
    /// Urban, rural, highway (the order of `RoadClass::ALL`).
    pub class: [RoadSamples; 3],
}

impl ClassedSamples {
    pub fn extend(&mut self, other: &ClassedSamples) {
        self.all.extend(&other.all);
        for (a, b) in self.class.iter_mut().zip(&other.class) {
            a.extend(b);
        }
    }
}

/// The road samples of a drive log with a speed column. The gyro bias is the median rate of
/// still blocks (at least 10 of them), else `bias_dps` (0 for a calibrated gyro; a simulated
/// drive passes its truth by using an ideal gyro).
pub fn road_samples(log: &DriveLog, bias_dps: f64) -> Result<ClassedSamples> {
    let gyro = log.require(Column::GyroDps, "road statistics")?;
    let speed = log.require(Column::SpeedMps, "road statistics (moving or still)")?;
    let t = log.time_s();
    let mean = |v: &[f64]| {
        let (s, n) = v.iter().filter(|x| !x.is_nan()).fold((0.0, 0usize), |(s, n), &x| (s + x, n + 1));
        (n > 0).then(|| s / n as f64)
    };
    let (mut blocks, mut last_v) = (Vec::new(), f64::NAN);
    for b in blocks_1hz(t) {
        if let Some(v) = mean(&speed[b.clone()]) {
            last_v = v;
        }
        if let Some(g) = mean(&gyro[b.clone()]) {
            blocks.push(((t[b.start] - t[0]).floor() as i64, g, last_v));
        }
    }
    let mut still: Vec<f64> = blocks.iter().filter(|b| b.2 < STILL_MPS).map(|b| b.1).collect();
    let bias = if still.len() >= 10 { quantile_mut(&mut still, 0.5) } else { bias_dps };
    // each block's class by the mean speed of the blocks within half a window of it
    let speeds: Vec<f64> = blocks.iter().map(|b| b.2).collect();
    let half = CLASS_WINDOW_S / 2;
    let class_of = |i: usize| RoadClass::of_speed(mean(&speeds[i.saturating_sub(half)..(i + half + 1).min(speeds.len())]).unwrap_or(0.0));
    let moving: Vec<(i64, f64, f64, RoadClass)> =
        blocks.iter().enumerate().filter(|(_, b)| b.2 > MOVING_MPS).map(|(i, b)| (b.0, b.1 - bias, b.2, class_of(i))).collect();
    if moving.is_empty() {
        return Err(Error::data(format!("no block moves faster than {MOVING_MPS} m/s")));
    }
    let strip = |c: Option<RoadClass>| -> Vec<(i64, f64, f64)> {
        moving.iter().filter(|m| c.is_none_or(|c| m.3 == c)).map(|m| (m.0, m.1, m.2)).collect()
    };
    Ok(ClassedSamples { all: RoadSamples::of_blocks(&strip(None)), class: RoadClass::ALL.map(|c| RoadSamples::of_blocks(&strip(Some(c)))) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_of_a_hand_made_drive() {
        // 20 s still with a 0.5 deg/s bias, then 60 s moving at 10 m/s: 10 s straight, 5 s at
        // 2 deg/s, 45 s straight
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]);
        for i in 0..800 {
            let t = i as f64 / 10.0;
            let (v, w) = if t < 20.0 {
                (0.0, 0.0)
            } else if (30.0..35.0).contains(&t) {
                (10.0, 2.0)
            } else {
                (10.0, 0.0)
            };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w + 0.5), (Column::SpeedMps, v)]);
        }
        let c = road_samples(&log, 9.0).unwrap();
        let s = &c.all;
        assert_eq!(s.abs_rate_dps.len(), 60);
        assert_eq!(s.moving_min, 1.0);
        assert_eq!(s.straight_runs_s, vec![10.0, 45.0]);
        // the curve: 5 s, 10 deg, radius 10 m/s / (2 deg/s in rad/s) = 286.48 m
        assert_eq!(s.curve_runs_s, vec![5.0]);
        assert!((s.curve_deg[0] - 10.0).abs() < 1e-12);
        assert!((s.curve_radius_m[0] - 10.0 / 2f64.to_radians()).abs() < 1e-9, "{:?}", s.curve_radius_m);
        let sum = s.summary();
        assert_eq!(sum.below_theta_w, 55.0 / 60.0);
        assert_eq!(sum.rate_p90_dps, 0.0); // 5 of 60 blocks turn: under 10 %
        assert_eq!(quantile(&s.abs_rate_dps, 0.95), 2.0);
        // windows of 30 s start every 10 s: the first two hold the turn (5 s x 2 deg/s / 30), the third not
        assert_eq!(s.slow_rate_dps.len(), 3);
        assert!((s.slow_rate_dps[0] - 10.0 / 30.0).abs() < 1e-12 && s.slow_rate_dps[2] == 0.0, "{:?}", s.slow_rate_dps);
        // the minute around each moving block averages at most 10 m/s: urban
        assert_eq!(c.class[0].abs_rate_dps.len(), 60);
        assert!(c.class[1].abs_rate_dps.is_empty() && c.class[2].abs_rate_dps.is_empty());
    }

    #[test]
    fn spectrum_windows_cover_consecutive_moving_seconds_only() {
        // 200 s moving at a steady 1 deg/s, 30 s still, 100 s moving with a 4 s-period sway
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]);
        for i in 0..3300 {
            let t = i as f64 / 10.0;
            let (v, w) = if t < 200.0 {
                (10.0, 1.0)
            } else if t < 230.0 {
                (0.0, 0.0)
            } else {
                (10.0, (2.0 * std::f64::consts::PI * t / 4.0).sin())
            };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w), (Column::SpeedMps, v)]);
        }
        let s = road_samples(&log, 0.0).unwrap().all;
        // the moving blocks are seconds 0-199 and 230-329 (300 in all); windows start at
        // moving-block indices 0, 32, ..., 224; those within one stretch: 0..=128 in the
        // first (5), 224 (seconds 254-317) in the second; 160 and 192 straddle the stop
        let p = &s.band_power_dps2;
        assert_eq!(p[0].len(), 6, "{p:?}");
        // a steady rate has no power once the window's mean is removed
        assert!(p.iter().all(|b| b[..5].iter().all(|&x| x < 1e-20)), "{p:?}");
        // 1 s blocks (means of 10 samples) of a 4 s sine: amplitude sin(pi/4) / (10
        // sin(pi/40)) = 0.90124, power 0.40612, at bin 16 (the 4-2 s band); Hann leaks a
        // quarter of it to bins 15 (the 8-4 s band) and 17: 1/6 and 5/6 of the power
        let last: Vec<f64> = p.iter().map(|b| b[5]).collect();
        let a = (std::f64::consts::PI / 4.0).sin() / (10.0 * (std::f64::consts::PI / 40.0).sin());
        let power = a * a / 2.0;
        let want = [0.0, 0.0, 0.0, power / 6.0, power * 5.0 / 6.0];
        assert!(last.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-9), "{last:?} against {want:?}");
    }

    #[test]
    fn lane_changes_and_loops_of_a_hand_made_drive() {
        // 120 s moving at 10 m/s: a lane change (1, 2, 0, -2, -1 deg/s) at 20-24 s and a
        // 200-degree loop (20 deg/s for 10 s) at 60-69 s
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]);
        let lane = [1.0, 2.0, 0.0, -2.0, -1.0];
        for i in 0..1200 {
            let t = i as f64 / 10.0;
            let sec = t.floor() as usize;
            let w = match sec {
                20..=24 => lane[sec - 20],
                60..=69 => 20.0,
                _ => 0.0,
            };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w), (Column::SpeedMps, 10.0)]);
        }
        let s = road_samples(&log, 0.0).unwrap().all;
        let sum = s.summary();
        assert_eq!((s.s_length_s, s.s_peak_deg), (vec![5.0], vec![3.0]));
        // 1 S in 2 moving minutes; 1 loop in 2 minutes = 30 per hour
        assert_eq!((sum.s_per_min, sum.loops_per_hour), (0.5, 30.0));
    }

    /// A line leaves nothing; a single 1 deg/s block among ten zeros: mean 0.1, slope
    /// Sxy / Sxx = 4.5 / 82.5, residual sum of squares 0.9 - 4.5^2 / 82.5 = 0.654545..., over
    /// 8 degrees of freedom: std 0.286039...
    #[test]
    fn detrended_std_hand_worked() {
        let line: Vec<f64> = (0..10).map(|i| 0.3 + 0.05 * i as f64).collect();
        assert!(detrended_std(&line).unwrap() < 1e-12);
        let mut y = vec![0.0; 10];
        y[9] = 1.0;
        assert!((detrended_std(&y).unwrap() - (0.654_545_454_545_454_5f64 / 8.0).sqrt()).abs() < 1e-12);
        assert_eq!(detrended_std(&[1.0, 2.0]), None);
    }

    /// Sway windows: 10 consecutive moving seconds, every 5 s, none holding a turn (3 deg/s or
    /// more) or a stop; an alternating +-0.2 deg/s weave gives each the same spread.
    #[test]
    fn sway_windows_of_a_hand_made_drive() {
        // 60 s moving with a +-0.2 weave, a 2 s turn at 4 deg/s at 30-31 s
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]);
        for i in 0..600 {
            let t = i as f64 / 10.0;
            let sec = t.floor() as usize;
            let w = if sec == 30 || sec == 31 {
                4.0
            } else if sec.is_multiple_of(2) {
                0.2
            } else {
                -0.2
            };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w), (Column::SpeedMps, 10.0)]);
        }
        let s = road_samples(&log, 0.0).unwrap().all;
        // windows start at 0, 5, ..., 50; those holding second 30 or 31 (25, 30) are skipped
        assert_eq!(s.sway_dps.len(), 9, "{:?}", s.sway_dps);
        let want = detrended_std(&[0.2, -0.2, 0.2, -0.2, 0.2, -0.2, 0.2, -0.2, 0.2, -0.2]).unwrap();
        assert!(s.sway_dps.iter().all(|&v| (v - want).abs() < 1e-9), "{:?} {want}", s.sway_dps);
        assert!(want > 0.2 && want < 0.23, "{want}");
    }

    #[test]
    fn classes_by_the_speed_of_the_surrounding_minute() {
        assert_eq!(RoadClass::of_speed(13.9), RoadClass::Urban);
        assert_eq!(RoadClass::of_speed(20.0), RoadClass::Rural);
        assert_eq!(RoadClass::of_speed(25.1), RoadClass::Highway);
        // 200 s at 10 m/s then 200 s at 30 m/s: a block is highway once the minute around it
        // averages over 25 m/s; runs end at the class boundary
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]);
        for i in 0..4000 {
            let t = i as f64 / 10.0;
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, 0.0), (Column::SpeedMps, if t < 200.0 { 10.0 } else { 30.0 })]);
        }
        let c = road_samples(&log, 0.0).unwrap();
        let n: Vec<usize> = c.class.iter().map(|s| s.abs_rate_dps.len()).collect();
        assert_eq!(n.iter().sum::<usize>(), 400);
        // the window [i-30, i+30] holds k = i - 169 blocks at 30 m/s; its mean 10 + 20 k/61 is
        // under 14 for k <= 12 (i <= 181) and over 25 for k >= 46 (i >= 215)
        assert_eq!(n, vec![182, 33, 185], "{n:?}");
        assert_eq!(c.all.straight_runs_s, vec![400.0]);
        assert_eq!(c.class[2].straight_runs_s, vec![185.0]);
    }
}
