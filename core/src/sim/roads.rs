//! Road geometry statistics that matter to drift estimators, measured the same way on recorded
//! and simulated drives so the simulator can be held against reality (issue 13): how much of
//! the moving time the yaw rate stays below HDR's theta_w, how long such "straight" runs
//! last, and how far the slow (30 s) yaw rate strays from zero on roads that look straight.

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use crate::metrics::{mean_std, quantile, quantile_mut};
use crate::preprocess::blocks_1hz;
use serde::Serialize;

/// Moving means faster than this, m/s; still means slower than `STILL_MPS`.
pub const MOVING_MPS: f64 = 3.0;
pub const STILL_MPS: f64 = 0.3;
/// HDR's Table-III threshold theta_w, deg/s: below it HDR calls the road straight.
pub const THETA_W_DPS: f64 = 0.564;

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
}

impl RoadSamples {
    pub fn extend(&mut self, other: &RoadSamples) {
        self.moving_min += other.moving_min;
        self.abs_rate_dps.extend(&other.abs_rate_dps);
        self.straight_runs_s.extend(&other.straight_runs_s);
        self.slow_rate_dps.extend(&other.slow_rate_dps);
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
        }
    }
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
}

/// Two-sample Kolmogorov-Smirnov distances between two pools, one per distribution.
#[derive(Debug, Clone, Serialize)]
pub struct RoadDistance {
    pub abs_rate: f64,
    pub straight_runs: f64,
    pub slow_rate: f64,
}

pub fn distance(a: &RoadSamples, b: &RoadSamples) -> RoadDistance {
    RoadDistance {
        abs_rate: ks_distance(&a.abs_rate_dps, &b.abs_rate_dps),
        straight_runs: ks_distance(&a.straight_runs_s, &b.straight_runs_s),
        slow_rate: ks_distance(&a.slow_rate_dps, &b.slow_rate_dps),
    }
}

/// The road samples of a drive log with a speed column. The gyro bias is the median rate of
/// still blocks (at least 10 of them), else `bias_dps` (0 for a calibrated gyro; a simulated
/// drive passes its truth by using an ideal gyro).
pub fn road_samples(log: &DriveLog, bias_dps: f64) -> Result<RoadSamples> {
    let gyro = log.require(Column::GyroDps, "road statistics")?;
    let speed = log.require(Column::SpeedMps, "road statistics (moving or still)")?;
    let t = log.time_s();
    let (mut blocks, mut last_v) = (Vec::new(), f64::NAN);
    for b in blocks_1hz(t) {
        let mean = |v: &[f64]| {
            let (s, n) = v.iter().filter(|x| !x.is_nan()).fold((0.0, 0usize), |(s, n), &x| (s + x, n + 1));
            if n > 0 {
                Some(s / n as f64)
            } else {
                None
            }
        };
        if let Some(v) = mean(&speed[b.clone()]) {
            last_v = v;
        }
        if let Some(g) = mean(&gyro[b.clone()]) {
            blocks.push(((t[b.start] - t[0]).floor() as i64, g, last_v));
        }
    }
    let mut still: Vec<f64> = blocks.iter().filter(|b| b.2 < STILL_MPS).map(|b| b.1).collect();
    let bias = if still.len() >= 10 { quantile_mut(&mut still, 0.5) } else { bias_dps };
    let moving: Vec<(i64, f64)> = blocks.iter().filter(|b| b.2 > MOVING_MPS).map(|b| (b.0, b.1 - bias)).collect();
    if moving.is_empty() {
        return Err(Error::data(format!("no block moves faster than {MOVING_MPS} m/s")));
    }
    let mut s = RoadSamples {
        moving_min: moving.len() as f64 / 60.0,
        abs_rate_dps: moving.iter().map(|m| m.1.abs()).collect(),
        ..Default::default()
    };
    let mut run = 0usize;
    for (i, &(k, w)) in moving.iter().enumerate() {
        let next_to_prev = i > 0 && moving[i - 1].0 + 1 == k;
        if w.abs() < THETA_W_DPS {
            run = if next_to_prev { run + 1 } else { 1 };
        } else {
            run = 0;
        }
        let ends = i + 1 == moving.len() || moving[i + 1].0 != k + 1 || moving[i + 1].1.abs() >= THETA_W_DPS;
        if run > 0 && ends {
            s.straight_runs_s.push(run as f64);
            run = 0;
        }
    }
    for i in (0..moving.len().saturating_sub(30)).step_by(10) {
        let w = &moving[i..i + 30];
        if w[29].0 - w[0].0 == 29 && w.iter().all(|m| m.1.abs() < 3.0) {
            s.slow_rate_dps.push((w.iter().map(|m| m.1).sum::<f64>() / 30.0).abs());
        }
    }
    Ok(s)
}

/// Recorded against simulated roads: per drive, pooled, and the distances of the pools.
#[derive(Debug, Clone, Serialize)]
pub struct RoadComparison {
    pub recorded: Vec<(String, RoadSummary)>,
    pub simulated: Vec<(String, RoadSummary)>,
    pub recorded_pool: RoadSummary,
    pub simulated_pool: RoadSummary,
    pub distance: RoadDistance,
}

/// The Table II and IV sample drives' roads, simulated with an ideal gyro (the true rate).
pub fn simulated_samples() -> Result<Vec<(String, RoadSamples)>> {
    let mut out = Vec::new();
    for s in super::samples::SAMPLE_LOGS.iter().filter(|s| s.kind == super::SimKind::Drive) {
        let cfg =
            super::drive::DriveConfig { scenario: s.scenario.unwrap_or("city").parse()?, minutes: s.minutes.unwrap_or(20.0), seed: s.seed };
        let log = super::drive::simulate_drive_with(&cfg, &super::GyroSpec::ideal());
        out.push((s.name.to_string(), road_samples(&log, 0.0)?));
    }
    Ok(out)
}

/// Compares recorded drives (each with a speed column; ones without are skipped) with the
/// simulated sample drives.
pub fn compare(recorded: &[(String, &DriveLog)]) -> Result<RoadComparison> {
    let mut rec = Vec::new();
    for (name, log) in recorded {
        if log.has(Column::SpeedMps) {
            rec.push((name.clone(), road_samples(log, 0.0).map_err(|e| e.within(name))?));
        }
    }
    let sim = simulated_samples()?;
    let pool = |v: &[(String, RoadSamples)]| {
        let mut p = RoadSamples::default();
        v.iter().for_each(|(_, s)| p.extend(s));
        p
    };
    let (rp, sp) = (pool(&rec), pool(&sim));
    let rows = |v: &[(String, RoadSamples)]| v.iter().map(|(n, s)| (n.clone(), s.summary())).collect();
    Ok(RoadComparison {
        recorded: rows(&rec),
        simulated: rows(&sim),
        recorded_pool: rp.summary(),
        simulated_pool: sp.summary(),
        distance: distance(&rp, &sp),
    })
}

impl RoadComparison {
    pub fn to_markdown(&self) -> String {
        let mut out = String::from(
            "| drive | moving (min) | abs rate p50 | p75 | p90 (deg/s) | below theta_w | straight run mean | p90 (s) | 30 s rate p50 | p90 (deg/s) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        );
        let row = |name: &str, s: &RoadSummary| {
            format!(
                "| {name} | {:.1} | {:.2} | {:.2} | {:.2} | {:.2} | {:.1} | {:.0} | {:.3} | {:.3} |\n",
                s.moving_min,
                s.rate_p50_dps,
                s.rate_p75_dps,
                s.rate_p90_dps,
                s.below_theta_w,
                s.straight_run_mean_s,
                s.straight_run_p90_s,
                s.slow_rate_p50_dps,
                s.slow_rate_p90_dps
            )
        };
        for (n, s) in &self.recorded {
            out += &row(&format!("recorded: {n}"), s);
        }
        out += &row("**recorded, pooled**", &self.recorded_pool);
        for (n, s) in &self.simulated {
            out += &row(&format!("simulated: {n}"), s);
        }
        out += &row("**simulated, pooled**", &self.simulated_pool);
        out += &format!(
            "\nTwo-sample Kolmogorov-Smirnov distance, recorded against simulated pool: abs rate {:.3}, straight runs {:.3}, 30 s rate {:.3}\n",
            self.distance.abs_rate, self.distance.straight_runs, self.distance.slow_rate
        );
        out
    }
}

/// The two-sample Kolmogorov-Smirnov statistic: the largest gap between the two empirical
/// distribution functions (0 = same, 1 = disjoint).
pub fn ks_distance(a: &[f64], b: &[f64]) -> f64 {
    if a.is_empty() || b.is_empty() {
        return f64::NAN;
    }
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (mut i, mut j, mut d) = (0usize, 0usize, 0.0f64);
    while i < a.len() && j < b.len() {
        let x = a[i].min(b[j]);
        while i < a.len() && a[i] <= x {
            i += 1;
        }
        while j < b.len() && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / a.len() as f64 - j as f64 / b.len() as f64).abs());
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ks_distance_hand_worked() {
        assert_eq!(ks_distance(&[1.0, 2.0, 3.0], &[1.0, 2.0, 3.0]), 0.0);
        assert_eq!(ks_distance(&[1.0, 2.0], &[3.0, 4.0]), 1.0);
        // F_a jumps to 1/2 at 1 and to 1 at 3; F_b to 1/2 at 2 and to 1 at 4: largest gap 1/2
        assert_eq!(ks_distance(&[1.0, 3.0], &[2.0, 4.0]), 0.5);
        // ties move both functions together
        assert_eq!(ks_distance(&[1.0, 1.0, 2.0, 2.0], &[1.0, 2.0]), 0.0);
    }

    #[test]
    fn samples_of_a_hand_made_drive() {
        // 20 s still with a 0.5 deg/s bias, then 60 s moving: 10 s straight, 5 s at 2 deg/s, 45 s straight
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
        let s = road_samples(&log, 9.0).unwrap();
        assert_eq!(s.abs_rate_dps.len(), 60);
        assert_eq!(s.moving_min, 1.0);
        assert_eq!(s.straight_runs_s, vec![10.0, 45.0]);
        let sum = s.summary();
        assert_eq!(sum.below_theta_w, 55.0 / 60.0);
        assert_eq!(sum.rate_p90_dps, 0.0); // 5 of 60 blocks turn: under 10 %
        assert_eq!(quantile(&s.abs_rate_dps, 0.95), 2.0);
        // windows of 30 s start every 10 s: the first two hold the turn (5 s x 2 deg/s / 30), the third not
        assert_eq!(s.slow_rate_dps.len(), 3);
        assert!((s.slow_rate_dps[0] - 10.0 / 30.0).abs() < 1e-12 && s.slow_rate_dps[2] == 0.0, "{:?}", s.slow_rate_dps);
    }
}
