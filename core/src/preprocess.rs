//! From log rows to estimator samples: the static bias eps0 and the paper's 1 Hz block
//! averaging (HDR seed, second Eq. 14; methods.md details 1-2).

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};

/// Estimator input: time stamps and raw yaw rates (eps0 not yet removed).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Samples {
    pub time_s: Vec<f64>,
    pub rate_dps: Vec<f64>,
}

impl Samples {
    pub fn len(&self) -> usize {
        self.time_s.len()
    }
    pub fn is_empty(&self) -> bool {
        self.time_s.is_empty()
    }
}

/// Static bias eps0 (Eq. 2's eps_0): mean of the non-empty gyro cells of the rows with
/// `t_i - t_0 < bias_s`, on the raw rows (detail 1). `bias_s = 0` means no removal.
pub fn static_bias_dps(time_s: &[f64], gyro_dps: &[f64], bias_s: f64) -> Result<f64> {
    if !(bias_s.is_finite() && bias_s >= 0.0) {
        return Err(Error::param("bias_s", format!("{bias_s} s is not a time >= 0")));
    }
    if bias_s == 0.0 {
        return Ok(0.0);
    }
    let Some(&t0) = time_s.first() else {
        return Err(Error::data("the log has no rows"));
    };
    let (mut sum, mut n) = (0.0, 0usize);
    for (&t, &g) in time_s.iter().zip(gyro_dps) {
        if t - t0 >= bias_s {
            break;
        }
        if !g.is_nan() {
            sum += g;
            n += 1;
        }
    }
    if n == 0 {
        return Err(Error::data(format!("no gyro_dps value in the first {bias_s} s for the static bias (set bias_s = 0 to skip it)")));
    }
    Ok(sum / n as f64)
}

/// The rows that have a gyro value, unresampled (the "no resampling" option).
pub fn gyro_rows(log: &DriveLog) -> Result<Samples> {
    let gyro = log.require(Column::GyroDps, "needed for the yaw rate")?;
    let mut s = Samples::default();
    for (&t, &g) in log.time_s().iter().zip(gyro) {
        if !g.is_nan() {
            s.time_s.push(t);
            s.rate_dps.push(g);
        }
    }
    if s.is_empty() {
        return Err(Error::data("the gyro_dps column has no values"));
    }
    Ok(s)
}

/// The paper's 1 Hz blocks (detail 2) as row ranges: block k holds the rows with
/// `k <= t_i - t_0 < k+1`, `k = floor(t_i - t_0)`. The one block iterator of the crate: the
/// averaging below and the still detection both walk it.
pub fn blocks_1hz(time_s: &[f64]) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
    let t0 = time_s.first().copied().unwrap_or(0.0);
    let mut start = 0;
    std::iter::from_fn(move || {
        let &first = time_s.get(start)?;
        let k = block_index(first, t0);
        let len = time_s[start + 1..].iter().take_while(|&&t| block_index(t, t0) == k).count();
        let block = start..start + 1 + len;
        start = block.end;
        Some(block)
    })
}

/// The 1 Hz block of a row at `time_s` in a log starting at `t0_s`: floor(t - t0) (detail
/// 2; also the live pipeline's, `pipeline::PipelineStream`).
pub fn block_index(time_s: f64, t0_s: f64) -> f64 {
    (time_s - t0_s).floor()
}

/// 1 Hz block averaging (detail 2): rate = mean of a block's non-empty gyro cells; stamp =
/// time of its last row; blocks with no gyro value are dropped.
pub fn block_average_1hz(time_s: &[f64], gyro_dps: &[f64]) -> Samples {
    let mut out = Samples::default();
    for b in blocks_1hz(time_s) {
        let (sum, n) = gyro_dps[b.clone()].iter().filter(|g| !g.is_nan()).fold((0.0, 0usize), |(s, n), &g| (s + g, n + 1));
        if n > 0 {
            out.time_s.push(time_s[b.end - 1]);
            out.rate_dps.push(sum / n as f64);
        }
    }
    out
}

/// Static bias and the estimator samples of a log, resampled to 1 Hz or not.
pub fn prepare(log: &DriveLog, bias_s: Option<f64>, resample: bool) -> Result<(f64, Samples)> {
    let gyro = log.require(Column::GyroDps, "needed for the yaw rate")?;
    let eps0 = static_bias_dps(log.time_s(), gyro, log.bias_s(bias_s))?;
    let samples = if resample {
        let s = block_average_1hz(log.time_s(), gyro);
        if s.is_empty() {
            return Err(Error::data("the gyro_dps column has no values"));
        }
        s
    } else {
        gyro_rows(log)?
    };
    Ok((eps0, samples))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn static_bias_uses_rows_before_bias_s_and_skips_empty_cells() {
        let t = [0.0, 0.5, 1.0, 1.5, 2.0];
        let g = [1.0, f64::NAN, 3.0, 100.0, 100.0];
        // rows with t - t0 < 1.5: 0, 0.5, 1.0 -> mean(1, 3) = 2
        assert_eq!(static_bias_dps(&t, &g, 1.5).unwrap(), 2.0);
        assert_eq!(static_bias_dps(&t, &g, 0.0).unwrap(), 0.0);
        assert!(static_bias_dps(&t, &[f64::NAN; 5], 1.0).is_err());
        assert!(static_bias_dps(&t, &g, -1.0).is_err());
    }

    #[test]
    fn block_average_hand_worked() {
        // t0 = 10.0; blocks: k=0 {10.0,10.5,10.9}, k=1 {11.0(no gyro),11.2}, k=2 {12.1 no gyro}, k=3 {13.0}
        let t = [10.0, 10.5, 10.9, 11.0, 11.2, 12.1, 13.0];
        let g = [1.0, 2.0, 6.0, f64::NAN, 4.0, f64::NAN, -1.0];
        let s = block_average_1hz(&t, &g);
        assert_eq!(s.time_s, vec![10.9, 11.2, 13.0]);
        assert_eq!(s.rate_dps, vec![3.0, 4.0, -1.0]);
    }

    #[test]
    fn block_stamp_is_last_row_even_without_gyro() {
        let t = [0.0, 0.5, 0.9];
        let g = [2.0, 4.0, f64::NAN];
        let s = block_average_1hz(&t, &g);
        assert_eq!(s.time_s, vec![0.9]);
        assert_eq!(s.rate_dps, vec![3.0]);
    }
}
