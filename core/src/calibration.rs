//! Gyro calibration (Ojeda, Chung & Borenstein, seed 002): static bias (Eq. 1), data sets
//! averaged per turntable rate (Eq. 6), the error model e(w_g, T) cubic in rate and quadratic
//! in temperature fitted by least squares (Eqs. 9-12), compensation (Eqs. 13, 15, 16) and the
//! error per nominal 360-degree turn (Eq. 14); methods.md detail 8.

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use crate::preprocess;
use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

/// Settings of a calibration fit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CalibrationOptions {
    /// Polynomial degree in the gyro rate w_g (paper: 3).
    pub p: usize,
    /// Polynomial degree in temperature T (paper: 2).
    pub q: usize,
    /// Stationary lead-in for w_s and w_s*, s; None = `# bias_s:` or 20 s.
    pub bias_s: Option<f64>,
}

impl Default for CalibrationOptions {
    fn default() -> Self {
        CalibrationOptions { p: 3, q: 2, bias_s: None }
    }
}

impl crate::options::Settings for CalibrationOptions {
    /// Degrees 0..8 and the static-bias window.
    fn validate(&self) -> Result<()> {
        for (name, d) in [("p", self.p), ("q", self.q)] {
            if d > 8 {
                return Err(Error::param(name, format!("{d} is not a degree 0..8")));
            }
        }
        crate::options::check_bias_s(self.bias_s)
    }
}

/// The error model e(w_g, T) = sum_j sum_k `C[j][k]` T^j w_g^k (Eq. 12, ascending powers).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ErrorModel {
    pub p: usize,
    pub q: usize,
    /// q+1 rows (T^0..T^q), each p+1 entries (w_g^0..w_g^p).
    pub c: Vec<Vec<f64>>,
}

impl ErrorModel {
    /// e(w_g, T), deg/s (Eq. 12).
    pub fn eval(&self, w_g_dps: f64, temp_c: f64) -> f64 {
        let mut e = 0.0;
        let mut tj = 1.0;
        for row in &self.c {
            let mut wk = 1.0;
            let mut s = 0.0;
            for &c in row {
                s += c * wk;
                wk *= w_g_dps;
            }
            e += s * tj;
            tj *= temp_c;
        }
        e
    }

    /// Least-squares fit of E = V C (Eqs. 9-11) over set averages, via QR on a
    /// column-scaled V (the raw columns span many decades: T^2 w^3 ~ 1e9).
    pub fn fit(w_g_dps: &[f64], temp_c: &[f64], err_dps: &[f64], p: usize, q: usize) -> Result<ErrorModel> {
        let n = w_g_dps.len();
        let m = (p + 1) * (q + 1);
        if n < m {
            return Err(Error::data(format!(
                "too few calibration sets: {n} for p = {p}, q = {q} (the model needs at least (p+1)(q+1) = {m})"
            )));
        }
        let mut v = DMatrix::<f64>::zeros(n, m);
        for i in 0..n {
            let mut tj = 1.0;
            for j in 0..=q {
                let mut wk = 1.0;
                for k in 0..=p {
                    v[(i, j * (p + 1) + k)] = tj * wk;
                    wk *= w_g_dps[i];
                }
                tj *= temp_c[i];
            }
        }
        let mut scale = vec![1.0; m];
        for (col, s) in scale.iter_mut().enumerate() {
            let mx = v.column(col).amax();
            if mx > 0.0 {
                *s = mx;
                v.column_mut(col).scale_mut(1.0 / mx);
            }
        }
        let e = DVector::from_column_slice(err_dps);
        // Householder QR (no hypot or other libm calls inside, unlike SVD's Givens
        // rotations), so native and wasm agree bit for bit: R x = Q^T e.
        let qr = v.qr();
        let qte = qr.q().transpose() * e;
        let r = qr.r();
        let tiny = 1e-12 * r.diagonal().amax();
        if r.diagonal().iter().any(|d| d.abs() <= tiny) {
            return Err(Error::data(format!(
                "the calibration sets do not determine the model (p = {p}, q = {q}): e.g. fewer than {} \
                 distinct temperatures or {} distinct rates",
                q + 1,
                p + 1
            )));
        }
        let x = r.solve_upper_triangular(&qte).ok_or_else(|| Error::data("least squares failed: singular system"))?;
        let mut c = vec![vec![0.0; p + 1]; q + 1];
        for j in 0..=q {
            for k in 0..=p {
                let idx = j * (p + 1) + k;
                c[j][k] = x[idx] / scale[idx];
            }
        }
        if c.iter().flatten().any(|v| !v.is_finite()) {
            return Err(Error::data("least squares gave non-finite coefficients"));
        }
        Ok(ErrorModel { p, q, c })
    }
}

/// One calibration data set: a maximal run of rows with the same table rate (Eq. 6).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CalSet {
    pub table_rate_dps: f64,
    /// Mean gyro output w_g over the set.
    pub w_g_dps: f64,
    /// Mean temperature over the set (0 when q = 0 and there is no temp_c).
    pub temp_c: f64,
    /// Row index range [start, end) in the log.
    pub start: usize,
    pub end: usize,
    /// Residual (mean corrected rate minus table rate), static bias only: w_g - w_s.
    pub residual_static_only_dps: f64,
    /// Residual after compensation (Eq. 16).
    pub residual_compensated_dps: f64,
}

/// Splits the log into data sets (maximal runs of the same non-empty table_rate_dps).
fn find_sets(log: &DriveLog, gyro: &[f64], temp: Option<&[f64]>, need_temp: bool) -> Result<Vec<CalSet>> {
    let table = log.require(Column::TableRateDps, "needed by calibration (the turntable's rate)")?;
    let mut sets = Vec::new();
    let mut i = 0;
    let n = log.len();
    while i < n {
        let w = table[i];
        if w.is_nan() {
            i += 1;
            continue;
        }
        let start = i;
        while i < n && table[i] == w {
            i += 1;
        }
        let (mut sg, mut ng, mut st, mut nt) = (0.0, 0usize, 0.0, 0usize);
        for r in start..i {
            if !gyro[r].is_nan() {
                sg += gyro[r];
                ng += 1;
            }
            if let Some(tc) = temp {
                if !tc[r].is_nan() {
                    st += tc[r];
                    nt += 1;
                }
            }
        }
        if ng == 0 {
            continue;
        }
        if need_temp && nt == 0 {
            return Err(Error::Cell {
                line: log.line[start],
                column: "temp_c".into(),
                message: format!("the data set at {w} deg/s has no temperature (needed for q > 0)"),
            });
        }
        let temp_c = if nt > 0 { st / nt as f64 } else { 0.0 };
        sets.push(CalSet {
            table_rate_dps: w,
            w_g_dps: sg / ng as f64,
            temp_c,
            start,
            end: i,
            residual_static_only_dps: f64::NAN,
            residual_compensated_dps: f64::NAN,
        });
    }
    Ok(sets)
}

/// The Result keys of methods.md for `calibrate`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CalibrationResult {
    #[serde(rename = "C")]
    pub c: Vec<Vec<f64>>,
    pub p: usize,
    pub q: usize,
    pub n_sets: usize,
    pub fit_residual_rms_dps: f64,
    pub w_s_dps: f64,
    pub w_s_star_dps: f64,
    pub residual_rms_static_only_dps: f64,
    pub residual_rms_compensated_dps: f64,
    pub turn360_err_static_only_max_deg: f64,
    pub turn360_err_static_only_rms_deg: f64,
    pub turn360_err_compensated_max_deg: f64,
    pub turn360_err_compensated_rms_deg: f64,
}

/// A calibration run: the result, the model and the per-set table (for plots).
#[derive(Debug, Clone)]
pub struct CalibrationRun {
    pub result: CalibrationResult,
    pub model: ErrorModel,
    pub sets: Vec<CalSet>,
}

/// Error per nominal 360-degree turn at rate w: residual * 360 / |w| (Eq. 14).
pub fn turn360_err_deg(residual_dps: f64, rate_dps: f64) -> f64 {
    residual_dps * 360.0 / rate_dps.abs()
}

fn rms(v: impl Iterator<Item = f64>) -> f64 {
    let (mut s, mut n) = (0.0, 0usize);
    for x in v {
        s += x * x;
        n += 1;
    }
    if n == 0 {
        f64::NAN
    } else {
        (s / n as f64).sqrt()
    }
}

fn max_abs(v: impl Iterator<Item = f64>) -> f64 {
    v.fold(f64::NAN, |m, x| if m.is_nan() || x.abs() > m { x.abs() } else { m })
}

/// A row's temperature: its own, else `fallback` (its set's or the lead-in's mean).
fn temp_at(temp: Option<&[f64]>, r: usize, fallback: f64) -> f64 {
    match temp {
        Some(t) if !t[r].is_nan() => t[r],
        _ => fallback,
    }
}

/// w_s* (Eq. 15): the stationary lead-in's mean rate less the fitted model, 0 without a lead-in.
fn lead_in_bias_compensated_dps(
    log: &DriveLog,
    gyro: &[f64],
    temp: Option<&[f64]>,
    model: &ErrorModel,
    bias_s: f64,
    need_temp: bool,
) -> Result<f64> {
    let t0 = log.time_s()[0];
    let lead: Vec<usize> = (0..log.len()).take_while(|&r| log.time_s()[r] - t0 < bias_s).filter(|&r| !gyro[r].is_nan()).collect();
    if lead.is_empty() {
        return Ok(0.0);
    }
    let lead_temps: Vec<f64> = lead.iter().filter_map(|&r| temp.map(|t| t[r]).filter(|v| !v.is_nan())).collect();
    if need_temp && lead_temps.is_empty() {
        return Err(Error::Cell {
            line: log.line[lead[0]],
            column: "temp_c".into(),
            message: "the stationary lead-in has no temperature (needed for w_s*, Eq. 15)".into(),
        });
    }
    let t_mean = if lead_temps.is_empty() { 0.0 } else { lead_temps.iter().sum::<f64>() / lead_temps.len() as f64 };
    Ok(lead.iter().map(|&r| gyro[r] - model.eval(gyro[r], temp_at(temp, r, t_mean))).sum::<f64>() / lead.len() as f64)
}

/// Each set's residual against the table rate, static bias only (Eq. 1) and compensated
/// (Eq. 16), on per-sample corrected rates averaged over the set.
fn correct_sets(sets: &mut [CalSet], gyro: &[f64], temp: Option<&[f64]>, model: &ErrorModel, w_s: f64, w_s_star: f64) {
    for s in sets.iter_mut() {
        let (mut so, mut co, mut n) = (0.0, 0.0, 0usize);
        for r in s.start..s.end {
            let g = gyro[r];
            if g.is_nan() {
                continue;
            }
            so += g - w_s;
            co += g - model.eval(g, temp_at(temp, r, s.temp_c)) - w_s_star; // Eq. 16
            n += 1;
        }
        s.residual_static_only_dps = so / n as f64 - s.table_rate_dps;
        s.residual_compensated_dps = co / n as f64 - s.table_rate_dps;
    }
}

/// Fits and evaluates the calibration on a turntable log.
pub fn run(log: &DriveLog, opts: &CalibrationOptions) -> Result<CalibrationRun> {
    crate::options::Settings::validate(opts)?;
    if log.is_empty() {
        return Err(Error::data("the log has no rows"));
    }
    let gyro = log.require(Column::GyroDps, "needed by calibration")?;
    let temp = log.column(Column::TempC);
    let need_temp = opts.q > 0;
    if need_temp && temp.is_none() {
        return Err(Error::missing("temp_c", "needed by calibration with q > 0 (use --set q=0 without it)"));
    }
    let mut sets = find_sets(log, gyro, temp, need_temp)?;
    let m = (opts.p + 1) * (opts.q + 1);
    if sets.len() < m {
        return Err(Error::data(format!(
            "too few calibration sets: {} for p = {}, q = {} (the model needs at least (p+1)(q+1) = {m})",
            sets.len(),
            opts.p,
            opts.q
        )));
    }
    let wg: Vec<f64> = sets.iter().map(|s| s.w_g_dps).collect();
    let tc: Vec<f64> = sets.iter().map(|s| s.temp_c).collect();
    // Eq. 2: e = w_g - w per set.
    let err: Vec<f64> = sets.iter().map(|s| s.w_g_dps - s.table_rate_dps).collect();
    let model = ErrorModel::fit(&wg, &tc, &err, opts.p, opts.q)?;
    let fit_residual_rms_dps = rms((0..sets.len()).map(|i| err[i] - model.eval(wg[i], tc[i])));

    // Eq. 1 and Eq. 15 on the stationary lead-in.
    let bias_s = log.bias_s(opts.bias_s);
    let w_s = preprocess::static_bias_dps(log.time_s(), gyro, bias_s)?;
    let w_s_star = lead_in_bias_compensated_dps(log, gyro, temp, &model, bias_s, need_temp)?;
    correct_sets(&mut sets, gyro, temp, &model, w_s, w_s_star);
    let turning = || sets.iter().filter(|s| s.table_rate_dps.abs() >= 5.0);
    let t_so = || turning().map(|s| turn360_err_deg(s.residual_static_only_dps, s.table_rate_dps));
    let t_co = || turning().map(|s| turn360_err_deg(s.residual_compensated_dps, s.table_rate_dps));
    let result = CalibrationResult {
        c: model.c.clone(),
        p: opts.p,
        q: opts.q,
        n_sets: sets.len(),
        fit_residual_rms_dps,
        w_s_dps: w_s,
        w_s_star_dps: w_s_star,
        residual_rms_static_only_dps: rms(sets.iter().map(|s| s.residual_static_only_dps)),
        residual_rms_compensated_dps: rms(sets.iter().map(|s| s.residual_compensated_dps)),
        turn360_err_static_only_max_deg: max_abs(t_so()),
        turn360_err_static_only_rms_deg: rms(t_so()),
        turn360_err_compensated_max_deg: max_abs(t_co()),
        turn360_err_compensated_rms_deg: rms(t_co()),
    };
    Ok(CalibrationRun { result, model, sets })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eval_eq12_hand_worked() {
        // e = (1 + 2w) + T (3 + 0 w) with p = 1, q = 1: at w = 2, T = 10 -> 5 + 30 = 35
        let m = ErrorModel { p: 1, q: 1, c: vec![vec![1.0, 2.0], vec![3.0, 0.0]] };
        assert_eq!(m.eval(2.0, 10.0), 35.0);
    }

    #[test]
    fn fit_recovers_an_exact_polynomial() {
        let truth =
            ErrorModel { p: 3, q: 2, c: vec![vec![0.5, 0.01, 1e-4, 2e-6], vec![0.02, -1e-4, 0.0, 1e-8], vec![-3e-4, 1e-6, 0.0, 0.0]] };
        let (mut w, mut t, mut e) = (vec![], vec![], vec![]);
        for temp in [25.0, 35.0, 45.0] {
            for k in -10..=10 {
                let wg = k as f64 * 10.0 + 0.3;
                w.push(wg);
                t.push(temp);
                e.push(truth.eval(wg, temp));
            }
        }
        let fit = ErrorModel::fit(&w, &t, &e, 3, 2).unwrap();
        for i in 0..w.len() {
            assert!((fit.eval(w[i], t[i]) - e[i]).abs() < 1e-9);
        }
    }

    #[test]
    fn too_few_sets_is_an_error() {
        let e = ErrorModel::fit(&[1.0; 11], &[20.0; 11], &[0.0; 11], 3, 2).unwrap_err();
        assert!(e.to_string().contains("too few calibration sets: 11"), "{e}");
    }

    #[test]
    fn one_temperature_cannot_fit_a_temperature_model() {
        let w: Vec<f64> = (0..20).map(|k| k as f64 * 10.0 - 100.0).collect();
        let e = ErrorModel::fit(&w, &[30.0; 20], &[0.1; 20], 3, 2).unwrap_err();
        assert!(e.to_string().contains("do not determine the model"), "{e}");
        assert!(ErrorModel::fit(&w, &[30.0; 20], &[0.1; 20], 3, 0).is_ok());
    }

    #[test]
    fn turn360_hand_worked() {
        // 0.1 deg/s residual at 10 deg/s: a 36 s turn accrues 3.6 deg
        assert!((turn360_err_deg(0.1, -10.0) - 3.6).abs() < 1e-12);
    }

    #[test]
    fn options_by_name() {
        use crate::options::from_pairs;
        let o: CalibrationOptions = from_pairs(&[("p".into(), 2.0), ("q".into(), 0.0)]).unwrap();
        assert_eq!((o.p, o.q), (2, 0));
        assert!(from_pairs::<CalibrationOptions>(&[("p".into(), 1.5)]).is_err());
        assert!(from_pairs::<CalibrationOptions>(&[("p".into(), 9.0)]).is_err());
        assert!(from_pairs::<CalibrationOptions>(&[("r".into(), 1.0)]).is_err());
    }
}
