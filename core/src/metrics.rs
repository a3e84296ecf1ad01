//! Heading metrics of the HDR seed (Eqs. 15-16) with methods.md details 3-6: unwrap the
//! reference, align the trace at the first scored sample, interpolate, E_psi, NE_psi.

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// The valid reference samples of a log, unwrapped (detail 6).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Reference {
    pub time_s: Vec<f64>,
    pub heading_deg: Vec<f64>,
}

impl Reference {
    /// The non-empty `ref_heading_deg` cells, unwrapped; an error if there are none.
    pub fn from_log(log: &DriveLog) -> Result<Reference> {
        let col = log.require(Column::RefHeadingDeg, "needed for the heading metrics")?;
        let mut time_s = Vec::new();
        let mut raw = Vec::new();
        for (&t, &h) in log.time_s().iter().zip(col) {
            if !h.is_nan() {
                time_s.push(t);
                raw.push(h);
            }
        }
        if time_s.is_empty() {
            return Err(Error::data("no valid reference heading: the ref_heading_deg column is empty, so E_psi cannot be computed"));
        }
        Ok(Reference { time_s, heading_deg: unwrap_deg(&raw) })
    }
}

/// Wraps an angle difference into [-180, 180): `d - 360 * floor((d + 180) / 360)`.
#[inline]
pub fn wrap_diff_deg(d: f64) -> f64 {
    d - 360.0 * ((d + 180.0) / 360.0).floor()
}

/// Unwraps headings: each steps to the equivalent value nearest the previous unwrapped
/// one (detail 6); the first is kept as is.
pub fn unwrap_deg(headings: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(headings.len());
    let mut prev = f64::NAN;
    for &x in headings {
        let u = if out.is_empty() { x } else { prev + wrap_diff_deg(x - prev) };
        out.push(u);
        prev = u;
    }
    out
}

/// Linear interpolation of a trace at `t` with j = last sample with `t_j <= t` (detail 4).
/// `j` must satisfy that; returns psi_j at an exact hit or at the last sample.
#[inline]
pub fn interp_at(time_s: &[f64], psi: &[f64], j: usize, t: f64) -> f64 {
    if time_s[j] == t || j + 1 == time_s.len() {
        psi[j]
    } else {
        psi[j] + (psi[j + 1] - psi[j]) * (t - time_s[j]) / (time_s[j + 1] - time_s[j])
    }
}

/// A series' value at time t, linearly interpolated (detail 4's rule), NaN outside it.
pub fn value_at(x: &[f64], y: &[f64], t: f64) -> f64 {
    let n = x.len().min(y.len());
    if n == 0 || !(t >= x[0] && t <= x[n - 1]) {
        return f64::NAN;
    }
    let j = x[..n].partition_point(|&v| v <= t).saturating_sub(1);
    interp_at(&x[..n], &y[..n], j, t)
}

/// How a heading trace scores against the reference.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Score {
    /// Constant added to the trace so it equals the reference at the first scored sample.
    pub shift_deg: f64,
    /// E_psi (Eq. 15): mean |psi(t_k) - ref_k| over the scored samples, no wrapping.
    pub e_psi_deg: f64,
    /// Scored reference samples (alignment sample included).
    pub n_samples: usize,
    /// Signed error (estimate minus reference) at the last scored sample.
    pub final_err_deg: f64,
}

/// The metric sample set (detail 4): each valid reference sample inside the trace's span,
/// as (t_k, psi(t_k) interpolated, ref_k).
fn scored_samples<'a>(time_s: &'a [f64], psi_deg: &'a [f64], reference: &'a Reference) -> impl Iterator<Item = (f64, f64, f64)> + 'a {
    let span = time_s.first().zip(time_s.last()).map(|(&a, &b)| (a, b));
    let mut j = 0usize;
    reference
        .time_s
        .iter()
        .zip(&reference.heading_deg)
        .skip_while(move |(&t, _)| span.is_some_and(|(a, _)| t < a))
        .take_while(move |(&t, _)| span.is_some_and(|(_, b)| t <= b))
        .map(move |(&t, &r)| {
            while j + 1 < time_s.len() && time_s[j + 1] <= t {
                j += 1;
            }
            (t, interp_at(time_s, psi_deg, j, t), r)
        })
}

/// Scores a trace (unshifted, any start) against the reference (details 3-4).
pub fn score(time_s: &[f64], psi_deg: &[f64], reference: &Reference) -> Result<Score> {
    let (Some(&t_first), Some(&t_last)) = (time_s.first(), time_s.last()) else {
        return Err(Error::data("the heading trace is empty"));
    };
    let mut shift = f64::NAN;
    let (mut sum, mut n, mut last_err) = (0.0, 0usize, 0.0);
    for (_, psi, r) in scored_samples(time_s, psi_deg, reference) {
        if n == 0 {
            shift = r - psi;
        }
        let err = (psi + shift) - r;
        sum += err.abs();
        last_err = err;
        n += 1;
    }
    if n == 0 {
        return Err(Error::data(format!("no valid reference heading between {t_first} s and {t_last} s, where the heading trace is")));
    }
    if n == 1 {
        // The first sample aligns the heading: its error is 0 by construction, so one sample
        // would give E_psi 0 and an improvement of 0/0.
        return Err(Error::data(format!(
            "one valid reference heading between {t_first} s and {t_last} s: it aligns the heading, none is left to score"
        )));
    }
    Ok(Score { shift_deg: shift, e_psi_deg: sum / n as f64, n_samples: n, final_err_deg: last_err })
}

/// The signed error psi(t_k) - ref_k of an (aligned) trace at each scored reference sample,
/// the terms whose mean absolute value is E_psi (for plotting error against time).
pub fn error_series(time_s: &[f64], psi_deg: &[f64], reference: &Reference) -> (Vec<f64>, Vec<f64>) {
    scored_samples(time_s, psi_deg, reference).map(|(t, psi, r)| (t, psi - r)).unzip()
}

/// The errors of several (aligned) headings on one time base at the scored reference
/// samples, for plots: the sample times and one error series per heading.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ErrorSeries {
    pub time_s: Vec<f64>,
    pub errors_deg: Vec<Vec<f64>>,
}

impl ErrorSeries {
    /// `error_series` of each heading; None when the log has no usable reference.
    pub fn of(log: &crate::DriveLog, time_s: &[f64], headings: &[&[f64]]) -> Option<(Reference, ErrorSeries)> {
        let reference = Reference::from_log(log).ok()?;
        let out = ErrorSeries::against(&reference, time_s, headings);
        Some((reference, out))
    }

    /// `error_series` of each heading against a reference taken already.
    pub fn against(reference: &Reference, time_s: &[f64], headings: &[&[f64]]) -> ErrorSeries {
        let mut out = ErrorSeries::default();
        for psi in headings {
            let (t, e) = error_series(time_s, psi, reference);
            out.time_s = t;
            out.errors_deg.push(e);
        }
        out
    }
}

/// NE_psi (Eq. 16): E_psi per minute of drive.
pub fn ne_psi(e_psi_deg: f64, duration_min: f64) -> f64 {
    e_psi_deg / duration_min
}

/// Relative improvement E_psi(raw) / E_psi(method).
pub fn improvement(e_raw_deg: f64, e_method_deg: f64) -> f64 {
    e_raw_deg / e_method_deg
}

/// The q-quantile by nearest rank (index floor(n q)), NaN for no values.
pub fn quantile(values: &[f64], q: f64) -> f64 {
    quantile_mut(&mut values.to_vec(), q)
}

/// As `quantile`, reordering `values` in place instead of copying them.
pub fn quantile_mut(values: &mut [f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let i = ((values.len() as f64 * q) as usize).min(values.len() - 1);
    *values.select_nth_unstable_by(i, f64::total_cmp).1
}

/// Mean and sample standard deviation (n - 1), as in the paper's average rows.
pub fn mean_std(values: &[f64]) -> (f64, f64) {
    let n = values.len();
    if n == 0 {
        return (f64::NAN, f64::NAN);
    }
    let mean = values.iter().sum::<f64>() / n as f64;
    if n == 1 {
        return (mean, 0.0);
    }
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    (mean, var.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_diff_range_and_half_turn() {
        assert_eq!(wrap_diff_deg(190.0), -170.0);
        assert_eq!(wrap_diff_deg(-190.0), 170.0);
        assert_eq!(wrap_diff_deg(180.0), -180.0); // exact half turn steps by -180
        assert_eq!(wrap_diff_deg(-180.0), -180.0);
        assert_eq!(wrap_diff_deg(10.0), 10.0);
        assert_eq!(wrap_diff_deg(720.0 + 5.0), 5.0);
    }

    #[test]
    fn unwrap_hand_worked() {
        let u = unwrap_deg(&[170.0, -170.0, -10.0, 170.0, 350.0]);
        // 170 -> -170 is +20 -> 190; -10 is -200 from 190 -> +160 -> 350;
        // 170 from 350: -180 -> 170; 350 from 170: +180 -> wraps to -180 -> -10
        assert_eq!(u, vec![170.0, 190.0, 350.0, 170.0, -10.0]);
    }

    #[test]
    fn interpolation_hand_worked() {
        let t = [0.0, 1.0, 3.0];
        let p = [0.0, 10.0, 30.0];
        assert_eq!(interp_at(&t, &p, 1, 2.0), 20.0);
        assert_eq!(interp_at(&t, &p, 1, 1.0), 10.0);
        assert_eq!(interp_at(&t, &p, 0, 0.25), 2.5);
        assert_eq!(interp_at(&t, &p, 2, 3.0), 30.0);
    }

    #[test]
    fn score_aligns_at_first_sample_inside_span() {
        // reference at 0.5 (before trace), 1, 2, 3.5 (after trace)
        let reference = Reference { time_s: vec![0.5, 1.0, 2.0, 3.5], heading_deg: vec![99.0, 100.0, 100.0, 0.0] };
        let t = [1.0, 2.0, 3.0];
        let psi = [0.0, 4.0, 8.0];
        let s = score(&t, &psi, &reference).unwrap();
        assert_eq!(s.shift_deg, 100.0);
        assert_eq!(s.n_samples, 2);
        assert_eq!(s.e_psi_deg, 2.0); // errors 0 and 4
        assert_eq!(s.final_err_deg, 4.0);
    }

    #[test]
    fn score_without_reference_in_span_is_an_error() {
        let reference = Reference { time_s: vec![10.0], heading_deg: vec![0.0] };
        assert!(score(&[0.0, 1.0], &[0.0, 0.0], &reference).is_err());
    }

    #[test]
    fn one_reference_sample_only_aligns_and_is_an_error_not_a_0_over_0_improvement() {
        let reference = Reference { time_s: vec![0.5], heading_deg: vec![10.0] };
        let e = score(&[0.0, 1.0], &[0.0, 5.0], &reference).unwrap_err().to_string();
        assert!(e.contains("one valid reference heading"), "{e}");
        let two = Reference { time_s: vec![0.5, 1.0], heading_deg: vec![10.0, 10.0] };
        assert_eq!(score(&[0.0, 1.0], &[0.0, 5.0], &two).unwrap().e_psi_deg, 1.25);
        // errors 0 and 2.5
    }

    #[test]
    fn e_psi_of_constant_bias_ramp_equals_closed_form() {
        // psi(t) = b t against a zero reference sampled at t = 0..N: E = b * mean(0..N) = b N / 2
        let b = 0.37;
        let n = 600;
        let t: Vec<f64> = (0..=n).map(|k| k as f64).collect();
        let psi: Vec<f64> = t.iter().map(|t| b * t).collect();
        let reference = Reference { time_s: t.clone(), heading_deg: vec![0.0; n + 1] };
        let s = score(&t, &psi, &reference).unwrap();
        let closed = b * n as f64 / 2.0;
        assert!((s.e_psi_deg - closed).abs() < 1e-9, "{} vs {}", s.e_psi_deg, closed);
    }

    #[test]
    fn error_series_mean_abs_is_e_psi() {
        let reference = Reference { time_s: vec![0.5, 1.0, 2.0, 2.5], heading_deg: vec![0.0, 1.0, 1.0, 3.0] };
        let t = [1.0, 2.0, 3.0];
        let psi = [0.0, 4.0, 8.0];
        let s = score(&t, &psi, &reference).unwrap();
        let shifted: Vec<f64> = psi.iter().map(|p| p + s.shift_deg).collect();
        let (te, e) = error_series(&t, &shifted, &reference);
        assert_eq!(te, vec![1.0, 2.0, 2.5]);
        assert_eq!(e, vec![0.0, 4.0, 4.0]); // 1+5-1... psi(2.5) = 6 + 1 = 7, minus 3
        let mean = e.iter().map(|v: &f64| v.abs()).sum::<f64>() / 3.0;
        assert!((mean - s.e_psi_deg).abs() < 1e-12);
    }

    #[test]
    fn mean_std_hand_worked() {
        let (m, s) = mean_std(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]);
        assert_eq!(m, 5.0);
        assert!((s - (32.0f64 / 7.0).sqrt()).abs() < 1e-12);
    }
}
