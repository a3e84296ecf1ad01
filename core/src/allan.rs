//! Overlapping Allan deviation of a rate signal (named in seeds 000 and 002 for choosing the
//! static-bias averaging time), with angle random walk and bias instability (methods.md detail 9).

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// The Result keys of methods.md for `allan`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct AllanResult {
    /// Mean sample interval T0 = (t_last - t_first) / (N - 1), s.
    pub T0_s: f64,
    /// Cluster sizes m in {1..9} x 10^d with m <= N / 10.
    pub m: Vec<usize>,
    pub tau_s: Vec<f64>,
    pub adev_dps: Vec<f64>,
    /// Angle random walk: adev at m = round(1 s / T0), times sqrt(1 s).
    pub arw_deg_per_sqrt_s: f64,
    pub arw_deg_per_sqrt_h: f64,
    /// min(adev over the grid) / 0.664.
    pub bias_instability_dps: f64,
    pub bias_instability_dph: f64,
    pub tau_at_min_s: f64,
}

/// The cluster-size grid {1..9} x 10^d, m <= n / 10.
pub fn m_grid(n: usize) -> Vec<usize> {
    let mut out = Vec::new();
    let mut dec = 1usize;
    'outer: loop {
        for k in 1..=9 {
            let m = k * dec;
            if m > n / 10 {
                break 'outer;
            }
            out.push(m);
        }
        dec *= 10;
    }
    out
}

/// Overlapping Allan deviation at cluster size m for rate samples y at interval t0.
/// sigma^2 = 1 / (2 (N - 2m + 1)) * sum_k (ybar_{k+m} - ybar_k)^2 over the N - 2m + 1
/// overlapping pairs of m-sample means, computed from the running sum (the integrated angle).
pub fn overlapping_adev(cum: &[f64], m: usize) -> f64 {
    // cum[k] = sum of y[0..k], len N + 1
    let n = cum.len() - 1;
    if m == 0 || 2 * m > n {
        return f64::NAN;
    }
    let terms = n - 2 * m + 1;
    let inv_m = 1.0 / m as f64;
    let mut s = 0.0;
    for k in 0..terms {
        let d = (cum[k + 2 * m] - 2.0 * cum[k + m] + cum[k]) * inv_m;
        s += d * d;
    }
    (s / (2.0 * terms as f64)).sqrt()
}

/// Running sum of the rate minus its mean (the mean cancels in every cluster difference
/// and removing it keeps the sum small, so round-off stays at the noise's own scale).
pub fn centred_cumsum(y: &[f64]) -> Vec<f64> {
    let mean = y.iter().sum::<f64>() / y.len().max(1) as f64;
    let mut cum = Vec::with_capacity(y.len() + 1);
    let mut s = 0.0;
    cum.push(0.0);
    for &v in y {
        s += v - mean;
        cum.push(s);
    }
    cum
}

/// Allan deviation of a rate series sampled at mean interval t0_s.
pub fn allan(rate_dps: &[f64], t0_s: f64) -> Result<AllanResult> {
    let n = rate_dps.len();
    if n < 10 {
        return Err(Error::data(format!("too short for Allan deviation: {n} gyro samples (at least 10 are needed)")));
    }
    if !(t0_s.is_finite() && t0_s > 0.0) {
        return Err(Error::data("the sample interval must be > 0"));
    }
    let cum = centred_cumsum(rate_dps);
    let m = m_grid(n);
    let tau_s: Vec<f64> = m.iter().map(|&m| m as f64 * t0_s).collect();
    let adev_dps: Vec<f64> = m.iter().map(|&m| overlapping_adev(&cum, m)).collect();
    let m1 = ((1.0 / t0_s).round() as usize).max(1);
    let arw = overlapping_adev(&cum, m1) * 1.0f64.sqrt();
    let (imin, &amin) = adev_dps.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)).ok_or_else(|| Error::data("empty Allan grid"))?;
    Ok(AllanResult {
        T0_s: t0_s,
        tau_at_min_s: tau_s[imin],
        m,
        tau_s,
        adev_dps: adev_dps.clone(),
        arw_deg_per_sqrt_s: arw,
        arw_deg_per_sqrt_h: arw * 60.0,
        bias_instability_dps: amin / 0.664,
        bias_instability_dph: amin / 0.664 * 3600.0,
    })
}

/// The angle-random-walk line adev = ARW / sqrt(tau) (slope -1/2 on log-log axes).
pub fn arw_line_dps(arw_deg_per_sqrt_s: f64, tau_s: &[f64]) -> Vec<f64> {
    tau_s.iter().map(|t| arw_deg_per_sqrt_s / t.sqrt()).collect()
}

/// The gyro column's rows with a value, and their mean sample interval T0.
fn gyro_series(log: &DriveLog) -> Result<(Vec<f64>, f64)> {
    let gyro = log.require(Column::GyroDps, "needed for Allan deviation")?;
    let mut t = Vec::with_capacity(gyro.len());
    let mut y = Vec::with_capacity(gyro.len());
    for (&ti, &g) in log.time_s().iter().zip(gyro) {
        if !g.is_nan() {
            t.push(ti);
            y.push(g);
        }
    }
    if y.len() < 10 {
        return Err(Error::data(format!("too short for Allan deviation: {} gyro samples (at least 10 are needed)", y.len())));
    }
    let t0 = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    Ok((y, t0))
}

/// Allan deviation of a log's gyro column (rows with a gyro value).
pub fn run(log: &DriveLog) -> Result<AllanResult> {
    let (y, t0) = gyro_series(log)?;
    allan(&y, t0)
}

/// Allan deviation of a log's gyro column with the confidence of each point.
pub fn run_with_confidence(log: &DriveLog) -> Result<(AllanResult, AllanConfidence)> {
    let (y, t0) = gyro_series(log)?;
    let r = allan(&y, t0)?;
    let c = confidence(&r, y.len());
    Ok((r, c))
}

/// A result and its confidence as the bindings give them: the Result keys, and `confidence`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AllanWithConfidence<'a> {
    #[serde(flatten)]
    pub result: &'a AllanResult,
    pub confidence: &'a AllanConfidence,
}

/// How well each Allan deviation is known (beyond methods.md, which takes the plain
/// minimum): a one-sigma (about 68 %) band per cluster time, and the cluster times whose
/// band reaches the minimum's, i.e. where the minimum could as well lie. The last, longest
/// clusters have few independent averages and wide bands.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AllanConfidence {
    /// Gyro samples N the deviations were computed from.
    pub n_samples: usize,
    /// adev * (1 - e) and adev * (1 + e) with e = relative_error(N, m), per tau.
    pub adev_low_dps: Vec<f64>,
    pub adev_high_dps: Vec<f64>,
    /// The minimum's band, deg/s, and the bias instability's (band / 0.664).
    pub min_low_dps: f64,
    pub min_high_dps: f64,
    pub bias_instability_low_dps: f64,
    pub bias_instability_high_dps: f64,
    /// The contiguous cluster times around the minimum whose band reaches below the
    /// minimum's upper bound, s: the flat bottom of the curve.
    pub tau_min_range_s: [f64; 2],
    /// The cluster time whose upper bound is lowest, and its deviation: the point the
    /// noisy long-tau tail cannot drag down, a conservative place for the minimum.
    pub tau_tightest_s: f64,
    pub adev_tightest_dps: f64,
}

/// Relative one-sigma error of an Allan deviation from N samples at cluster size m,
/// 1 / sqrt(2 (N / m - 1)) (IEEE Std 952-1997, Annex C; El-Sheimy et al. 2008, Eq. 12).
/// Conservative for the overlapping estimator, which averages more pairs.
pub fn relative_error(n: usize, m: usize) -> f64 {
    let k = n as f64 / m.max(1) as f64;
    if k > 1.0 {
        1.0 / (2.0 * (k - 1.0)).sqrt()
    } else {
        f64::INFINITY
    }
}

/// The confidence of an Allan result computed from `n` samples.
pub fn confidence(r: &AllanResult, n: usize) -> AllanConfidence {
    let e: Vec<f64> = r.m.iter().map(|&m| relative_error(n, m).min(1.0)).collect();
    let low: Vec<f64> = r.adev_dps.iter().zip(&e).map(|(a, e)| a * (1.0 - e)).collect();
    let high: Vec<f64> = r.adev_dps.iter().zip(&e).map(|(a, e)| a * (1.0 + e)).collect();
    let imin = r.tau_s.iter().position(|&t| t == r.tau_at_min_s).unwrap_or(0);
    let (min_low, min_high) = (low.get(imin).copied().unwrap_or(f64::NAN), high.get(imin).copied().unwrap_or(f64::NAN));
    let reaches = |i: usize| low[i] <= min_high;
    let (mut a, mut b) = (imin, imin);
    while a > 0 && reaches(a - 1) {
        a -= 1;
    }
    while b + 1 < low.len() && reaches(b + 1) {
        b += 1;
    }
    let tau = |i: usize| r.tau_s.get(i).copied().unwrap_or(f64::NAN);
    let tight = high.iter().enumerate().filter(|(_, h)| h.is_finite()).min_by(|a, b| a.1.total_cmp(b.1)).map_or(imin, |(i, _)| i);
    AllanConfidence {
        tau_tightest_s: tau(tight),
        adev_tightest_dps: r.adev_dps.get(tight).copied().unwrap_or(f64::NAN),
        n_samples: n,
        adev_low_dps: low,
        adev_high_dps: high,
        min_low_dps: min_low,
        min_high_dps: min_high,
        bias_instability_low_dps: min_low / 0.664,
        bias_instability_high_dps: min_high / 0.664,
        tau_min_range_s: [tau(a), tau(b)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_hand_worked() {
        assert_eq!(m_grid(9), Vec::<usize>::new());
        assert_eq!(m_grid(10), vec![1]);
        assert_eq!(m_grid(125), vec![1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
        assert_eq!(m_grid(250), vec![1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 20]);
    }

    #[test]
    fn adev_hand_worked() {
        // y = 0, 1, 0, 1 ; m = 1: pairs (0,1),(1,0),(0,1): diffs 1,-1,1 -> sigma^2 = 3 / (2*3) = 0.5
        let cum = centred_cumsum(&[0.0, 1.0, 0.0, 1.0]);
        assert!((overlapping_adev(&cum, 1) - 0.5f64.sqrt()).abs() < 1e-15);
        // m = 2: means (0.5, 0.5) -> 0
        assert!(overlapping_adev(&cum, 2).abs() < 1e-15);
        assert!(overlapping_adev(&cum, 3).is_nan());
    }

    #[test]
    fn constant_rate_has_zero_adev() {
        let r = allan(&[1.5; 100], 0.1).unwrap();
        assert!(r.adev_dps.iter().all(|&a| a.abs() < 1e-12));
    }

    #[test]
    fn white_noise_slope_minus_half() {
        // deterministic pseudo-random white noise (LCG + Box-Muller), sigma = 0.1 deg/s at 10 Hz
        let mut s: u64 = 12345;
        let mut uni = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((s >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let n = 200_000;
        let y: Vec<f64> = (0..n)
            .map(|_| {
                let (u1, u2) = (uni(), uni());
                0.1 * (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
            })
            .collect();
        let r = allan(&y, 0.1).unwrap();
        // white rate noise: adev(tau) = sigma * sqrt(T0 / tau); ARW = 0.1 * sqrt(0.1) = 0.0316
        assert!((r.arw_deg_per_sqrt_s - 0.1 * 0.1f64.sqrt()).abs() < 0.002, "{}", r.arw_deg_per_sqrt_s);
        assert!((r.arw_deg_per_sqrt_h - r.arw_deg_per_sqrt_s * 60.0).abs() < 1e-12);
        assert!((r.bias_instability_dph - r.bias_instability_dps * 3600.0).abs() < 1e-9);
    }

    #[test]
    fn relative_error_hand_worked() {
        // N = 1000, m = 10: N/m = 100 -> 1 / sqrt(198) = 0.0710669
        assert!((relative_error(1000, 10) - 0.071_066_905).abs() < 1e-8);
        // m = N / 10 (the grid's last): 1 / sqrt(18) = 0.2357
        assert!((relative_error(1000, 100) - 0.235_702_26).abs() < 1e-8);
        assert!(relative_error(10, 10).is_infinite());
    }

    #[test]
    fn confidence_marks_the_flat_bottom() {
        // N = 1000 at T0 = 1 s; the deepest point is the last, noisiest one (m = 100,
        // e = 0.2357), but m = 30 (e = 0.1260) is only 0.3 % above it: both lie in the
        // minimum's band; m = 10 lies above it.
        let r = AllanResult {
            T0_s: 1.0,
            m: vec![1, 10, 30, 100],
            tau_s: vec![1.0, 10.0, 30.0, 100.0],
            adev_dps: vec![0.1, 0.02, 0.00905, 0.00903],
            arw_deg_per_sqrt_s: 0.1,
            arw_deg_per_sqrt_h: 6.0,
            bias_instability_dps: 0.00903 / 0.664,
            bias_instability_dph: 0.00903 / 0.664 * 3600.0,
            tau_at_min_s: 100.0,
        };
        let c = confidence(&r, 1000);
        let e100 = 1.0 / 18f64.sqrt();
        assert!((c.min_low_dps - 0.00903 * (1.0 - e100)).abs() < 1e-15);
        assert!((c.min_high_dps - 0.00903 * (1.0 + e100)).abs() < 1e-15);
        assert!((c.bias_instability_high_dps - c.min_high_dps / 0.664).abs() < 1e-15);
        // m = 10: low = 0.02 * (1 - 0.0711) = 0.01858 > 0.01116: outside the bottom.
        assert_eq!(c.tau_min_range_s, [30.0, 100.0]);
        // Upper bounds: m = 30: 0.00905 * 1.1244 = 0.01018 < m = 100: 0.01116.
        assert_eq!((c.tau_tightest_s, c.adev_tightest_dps), (30.0, 0.00905));
        assert_eq!(c.adev_low_dps.len(), 4);
        assert!(c.adev_low_dps.iter().zip(&c.adev_high_dps).zip(&r.adev_dps).all(|((l, h), a)| l < a && a < h));
    }

    #[test]
    fn short_log_is_an_error() {
        assert!(allan(&[0.0; 9], 0.1).unwrap_err().to_string().contains("at least 10"));
    }
}
