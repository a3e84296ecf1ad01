//! Automatic HDR parameter tuning: the five parameters that minimise the mean NE_psi over
//! a set of training drives (the paper's "painstakingly hand-tuned" Table III, automated),
//! regularised toward Table III and judged by leave-one-drive-out cross-validation: tuned
//! parameters are recommended only when their cross-validated score beats Table III's.
//! Bounded Nelder-Mead (argmin) on coordinates scaled to the bounds; deterministic.
//! Drives are prepared once (static bias, 1 Hz blocks, reference) and evaluated in parallel
//! natively (feature `parallel`, rayon); the per-sample loop allocates nothing.

use crate::error::{Error, Result};
use crate::hdr::{self, HdrOptions, HdrParams};
use crate::log::DriveLog;
use crate::metrics::{self, Reference};
use crate::preprocess::{self, Samples};
use crate::report::{Report, ReportRow};
use argmin::core::{CostFunction, Executor};
use argmin::solver::neldermead::NelderMead;
use serde::{Deserialize, Serialize};

/// A drive made ready for many HDR evaluations.
#[derive(Debug, Clone)]
pub struct PreparedDrive {
    pub name: String,
    pub eps0_dps: f64,
    pub samples: Samples,
    pub reference: Reference,
    pub duration_min: f64,
    pub e_psi_raw_deg: f64,
}

impl PreparedDrive {
    pub fn new(name: &str, log: &DriveLog, bias_s: Option<f64>, resample: bool) -> Result<Self> {
        let wrap = |e: Error| e.within(name);
        let (eps0, samples) = preprocess::prepare(log, bias_s, resample).map_err(wrap)?;
        let reference = Reference::from_log(log).map_err(wrap)?;
        let mut raw = hdr::RawIntegrator::new(eps0);
        let psi: Vec<f64> = samples.time_s.iter().zip(&samples.rate_dps).map(|(&t, &w)| raw.update(t, w)).collect();
        let e_raw = metrics::score(&samples.time_s, &psi, &reference).map_err(wrap)?.e_psi_deg;
        Ok(PreparedDrive {
            name: name.to_string(),
            eps0_dps: eps0,
            samples,
            reference,
            duration_min: log.duration_min(),
            e_psi_raw_deg: e_raw,
        })
    }

    /// E_psi of HDR with these parameters.
    pub fn e_psi_hdr_deg(&self, params: HdrParams, buf: &mut Vec<f64>) -> Result<f64> {
        hdr::headings_only(&self.samples, params, self.eps0_dps, buf)?;
        Ok(metrics::score(&self.samples.time_s, buf, &self.reference)?.e_psi_deg)
    }

    /// The report row for these parameters.
    pub fn row(&self, params: HdrParams) -> Result<ReportRow> {
        let e = self.e_psi_hdr_deg(params, &mut Vec::new())?;
        Ok(ReportRow {
            name: self.name.clone(),
            duration_min: self.duration_min,
            E_psi_raw_deg: self.e_psi_raw_deg,
            NE_psi_raw_deg_per_min: metrics::ne_psi(self.e_psi_raw_deg, self.duration_min),
            E_psi_hdr_deg: e,
            NE_psi_hdr_deg_per_min: metrics::ne_psi(e, self.duration_min),
            improvement: metrics::improvement(self.e_psi_raw_deg, e),
        })
    }
}

/// The report for prepared drives with given parameters.
pub fn report(drives: &[PreparedDrive], params: HdrParams) -> Result<Report> {
    Report::from_rows(drives.iter().map(|d| d.row(params)).collect::<Result<Vec<_>>>()?)
}

/// Mean NE_psi of HDR over the drives: the tuning objective.
pub fn objective(drives: &[PreparedDrive], params: HdrParams) -> Result<f64> {
    let ne = |d: &PreparedDrive| -> Result<f64> {
        let mut buf = Vec::with_capacity(d.samples.len());
        Ok(metrics::ne_psi(d.e_psi_hdr_deg(params, &mut buf)?, d.duration_min))
    };
    #[cfg(feature = "parallel")]
    let values: Vec<Result<f64>> = {
        use rayon::prelude::*;
        drives.par_iter().map(ne).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let values: Vec<Result<f64>> = drives.iter().map(ne).collect();
    let mut sum = 0.0;
    for v in values {
        sum += v?;
    }
    Ok(sum / drives.len().max(1) as f64)
}

/// Search bounds of the five parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TuneOptions {
    pub lower: HdrParams,
    pub upper: HdrParams,
    /// Where the search starts (Table III by default).
    pub start: HdrParams,
    /// Nelder-Mead iterations per restart.
    pub max_iters: u64,
    /// Restarts from the best point found (each with a fresh simplex).
    pub restarts: u32,
    /// Penalty toward Table III, deg/min per unit squared distance in the bounds-scaled
    /// coordinates (0 = none): five parameters on a few drives over-fit without it.
    pub regularization_deg_per_min: f64,
    /// Leave-one-drive-out cross-validation (needs 3 drives or more).
    pub cross_validate: bool,
}

impl crate::options::Settings for TuneOptions {
    /// A valid start, bounds with upper above lower, a penalty >= 0.
    fn validate(&self) -> Result<()> {
        if !(self.regularization_deg_per_min.is_finite() && self.regularization_deg_per_min >= 0.0) {
            return Err(Error::param("regularization_deg_per_min", "must be a number >= 0"));
        }
        self.start.validate()?;
        let (lo, hi) = (to_vec(&self.lower), to_vec(&self.upper));
        if (0..5).any(|k| !(lo[k].is_finite() && hi[k].is_finite() && hi[k] > lo[k])) {
            return Err(Error::param("bounds", "each upper bound must exceed its lower bound"));
        }
        Ok(())
    }
}

impl Default for TuneOptions {
    fn default() -> Self {
        TuneOptions {
            lower: HdrParams { i_c_dps: 0.0, tau_s: 0.0, theta_w_dps: 0.02, c1: 0.005, c2: 0.1 },
            upper: HdrParams { i_c_dps: 0.3, tau_s: 5.0, theta_w_dps: 3.0, c1: 3.0, c2: 4.0 },
            start: HdrParams::default(),
            max_iters: 250,
            restarts: 2,
            regularization_deg_per_min: 0.05,
            cross_validate: true,
        }
    }
}

fn to_vec(p: &HdrParams) -> [f64; 5] {
    [p.i_c_dps, p.tau_s, p.theta_w_dps, p.c1, p.c2]
}

fn from_vec(v: &[f64]) -> HdrParams {
    HdrParams { i_c_dps: v[0], tau_s: v[1], theta_w_dps: v[2], c1: v[3], c2: v[4] }
}

/// The outcome of a tuning run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TuneResult {
    pub params: HdrParams,
    /// Mean NE_psi over the training drives with the start parameters and with the tuned ones.
    pub objective_start_deg_per_min: f64,
    pub objective_tuned_deg_per_min: f64,
    pub n_evaluations: u64,
    /// Leave-one-drive-out cross-validation, when run.
    pub cv: Option<CrossValidation>,
    /// The parameters to use: the tuned ones only when cross-validation says they beat
    /// Table III on drives they were not tuned on (or when it was not run); else Table III.
    pub recommended: HdrParams,
    pub recommended_is_tuned: bool,
}

/// One held-out drive: its NE_psi with Table III and with parameters tuned on the others.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CvFold {
    pub held_out: String,
    pub ne_psi_table_iii_deg_per_min: f64,
    pub ne_psi_tuned_deg_per_min: f64,
    pub params: HdrParams,
}

/// Leave-one-drive-out cross-validation of the tuning.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CrossValidation {
    pub folds: Vec<CvFold>,
    /// Mean held-out NE_psi with Table III and with the fold's tuned parameters.
    pub cv_table_iii_deg_per_min: f64,
    pub cv_tuned_deg_per_min: f64,
}

struct Problem<'a> {
    drives: &'a [PreparedDrive],
    lo: [f64; 5],
    hi: [f64; 5],
    /// Table III in unit-cube coordinates, and the penalty weight toward it.
    anchor: [f64; 5],
    lambda: f64,
    evals: &'a std::cell::Cell<u64>,
    progress: &'a dyn Fn(u64),
}

impl Problem<'_> {
    /// Unit-cube coordinates to parameters, clamped into the bounds.
    fn params(&self, u: &[f64]) -> HdrParams {
        let v: Vec<f64> = (0..5).map(|k| self.lo[k] + (self.hi[k] - self.lo[k]) * u[k].clamp(0.0, 1.0)).collect();
        let mut p = from_vec(&v);
        p.c1 = p.c1.max(1e-9);
        p
    }
}

impl Problem<'_> {
    /// Regularisation: lambda * squared distance to Table III in unit-cube coordinates.
    fn penalty(&self, u: &[f64]) -> f64 {
        self.lambda * (0..5).map(|k| (u[k].clamp(0.0, 1.0) - self.anchor[k]).powi(2)).sum::<f64>()
    }
}

impl CostFunction for Problem<'_> {
    type Param = Vec<f64>;
    type Output = f64;
    fn cost(&self, u: &Vec<f64>) -> std::result::Result<f64, argmin::core::Error> {
        self.evals.set(self.evals.get() + 1);
        if self.evals.get().is_multiple_of(16) {
            (self.progress)(self.evals.get());
        }
        // Outside the unit cube: the clamped cost plus a penalty, so the simplex walks back.
        let outside: f64 = u.iter().map(|&x| (x - x.clamp(0.0, 1.0)).abs()).sum();
        let c = objective(self.drives, self.params(u)).map_err(|e| argmin::core::Error::msg(e.to_string()))?;
        Ok(c + outside + self.penalty(u))
    }
}

/// Tunes the five HDR parameters on the training drives.
pub fn tune(drives: &[PreparedDrive], opts: &TuneOptions) -> Result<TuneResult> {
    tune_with_progress(drives, opts, &|_| {})
}

/// An upper estimate of the objective evaluations one tuning run makes (for progress bars;
/// cross-validation adds one run per drive).
pub fn expected_evaluations(opts: &TuneOptions) -> u64 {
    (opts.restarts as u64 + 1) * (opts.max_iters * 2 + 6)
}

/// Evaluations of `tune_with_progress` on `n_drives` drives, cross-validation included.
pub fn expected_evaluations_for(opts: &TuneOptions, n_drives: usize) -> u64 {
    let folds = if opts.cross_validate && n_drives >= 3 { n_drives as u64 } else { 0 };
    expected_evaluations(opts) * (1 + folds)
}

/// Leave-one-drive-out: tune on all drives but one, score the one left out; Table III on
/// the same drive for comparison.
pub fn cross_validate(drives: &[PreparedDrive], opts: &TuneOptions, progress: &dyn Fn(u64)) -> Result<CrossValidation> {
    if drives.len() < 3 {
        return Err(Error::data("cross-validation needs 3 drives or more"));
    }
    let per_run = expected_evaluations(opts);
    let mut folds = Vec::with_capacity(drives.len());
    for (i, held) in drives.iter().enumerate() {
        let rest: Vec<PreparedDrive> = drives.iter().enumerate().filter(|(j, _)| *j != i).map(|(_, d)| d.clone()).collect();
        let done = (i as u64 + 1) * per_run;
        let r = tune_once(&rest, opts, &|e| progress(done + e))?;
        let ne = |p: HdrParams| -> Result<f64> { Ok(metrics::ne_psi(held.e_psi_hdr_deg(p, &mut Vec::new())?, held.duration_min)) };
        folds.push(CvFold {
            held_out: held.name.clone(),
            ne_psi_table_iii_deg_per_min: ne(HdrParams::table_iii())?,
            ne_psi_tuned_deg_per_min: ne(r.params)?,
            params: r.params,
        });
    }
    let n = folds.len() as f64;
    Ok(CrossValidation {
        cv_table_iii_deg_per_min: folds.iter().map(|f| f.ne_psi_table_iii_deg_per_min).sum::<f64>() / n,
        cv_tuned_deg_per_min: folds.iter().map(|f| f.ne_psi_tuned_deg_per_min).sum::<f64>() / n,
        folds,
    })
}

/// As `tune`, calling `progress(evaluations so far)` every 16 evaluations. With
/// `cross_validate` (and 3 drives or more) the tuning is repeated once per held-out drive.
pub fn tune_with_progress(drives: &[PreparedDrive], opts: &TuneOptions, progress: &dyn Fn(u64)) -> Result<TuneResult> {
    let mut r = tune_once(drives, opts, progress)?;
    if opts.cross_validate && drives.len() >= 3 {
        let cv = cross_validate(drives, opts, progress)?;
        r.recommended_is_tuned = cv.cv_tuned_deg_per_min < cv.cv_table_iii_deg_per_min;
        r.cv = Some(cv);
    } else {
        r.recommended_is_tuned = true;
    }
    r.recommended = if r.recommended_is_tuned { r.params } else { HdrParams::table_iii() };
    Ok(r)
}

/// One regularised tuning run (no cross-validation).
fn tune_once(drives: &[PreparedDrive], opts: &TuneOptions, progress: &dyn Fn(u64)) -> Result<TuneResult> {
    crate::options::Settings::validate(opts)?;
    if drives.is_empty() {
        return Err(Error::data("no training drives"));
    }
    let lo = to_vec(&opts.lower);
    let hi = to_vec(&opts.upper);
    let evals = std::cell::Cell::new(0);
    let t3 = to_vec(&HdrParams::table_iii());
    let anchor: [f64; 5] = std::array::from_fn(|k| ((t3[k] - lo[k]) / (hi[k] - lo[k])).clamp(0.0, 1.0));
    let lambda = opts.regularization_deg_per_min;
    let problem = Problem { drives, lo, hi, anchor, lambda, evals: &evals, progress };
    let s = to_vec(&opts.start);
    let start_u: Vec<f64> = (0..5).map(|k| ((s[k] - lo[k]) / (hi[k] - lo[k])).clamp(0.0, 1.0)).collect();
    let start_objective = objective(drives, opts.start)?;
    let start_cost = start_objective + problem.penalty(&start_u);
    let mut best_u: Vec<f64> = start_u;
    let mut best_cost = start_cost;
    let mut best_params = opts.start;
    for round in 0..=opts.restarts {
        let step = 0.15 / (1.0 + round as f64);
        let mut simplex = vec![best_u.clone()];
        for k in 0..5 {
            let mut v = best_u.clone();
            v[k] = if v[k] + step <= 1.0 { v[k] + step } else { v[k] - step };
            simplex.push(v);
        }
        let solver = NelderMead::new(simplex).with_sd_tolerance(1e-7).map_err(|e| Error::data(format!("tuning: {e}")))?;
        let round_problem = Problem { drives, lo, hi, anchor, lambda, evals: &evals, progress };
        let res = Executor::new(round_problem, solver)
            .configure(|st| st.max_iters(opts.max_iters))
            .run()
            .map_err(|e| Error::data(format!("tuning: {e}")))?;
        if let Some(u) = res.state.best_param {
            let p = problem.params(&u);
            let c = objective(drives, p)? + problem.penalty(&u);
            if c < best_cost {
                best_cost = c;
                best_params = p;
                best_u = u.iter().map(|x| x.clamp(0.0, 1.0)).collect();
            }
        }
    }
    Ok(TuneResult {
        params: best_params,
        objective_start_deg_per_min: start_objective,
        objective_tuned_deg_per_min: objective(drives, best_params)?,
        n_evaluations: evals.get(),
        cv: None,
        recommended: best_params,
        recommended_is_tuned: true,
    })
}

/// Prepares named logs with the HDR options' bias window and resampling.
pub fn prepare_all(logs: &[(String, &DriveLog)], opts: &HdrOptions) -> Result<Vec<PreparedDrive>> {
    logs.iter().map(|(n, l)| PreparedDrive::new(n, l, opts.bias_s, opts.resample)).collect()
}

/// Table III against tuned parameters on one set of drives.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Comparison {
    pub table_iii: Report,
    pub tuned: Report,
}

/// Tuning plus the reports a user wants to see: training and (optional) test drives,
/// each with Table III and with the tuned parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TuneReport {
    pub result: TuneResult,
    pub train: Comparison,
    pub test: Option<Comparison>,
}

/// Tunes on `train` and reports on both sets.
pub fn tune_and_report(train: &[PreparedDrive], test: &[PreparedDrive], opts: &TuneOptions) -> Result<TuneReport> {
    tune_and_report_with_progress(train, test, opts, &|_| {})
}

/// As `tune_and_report`, with a progress callback (evaluations so far).
pub fn tune_and_report_with_progress(
    train: &[PreparedDrive],
    test: &[PreparedDrive],
    opts: &TuneOptions,
    progress: &dyn Fn(u64),
) -> Result<TuneReport> {
    let result = tune_with_progress(train, opts, progress)?;
    let compare = |set: &[PreparedDrive]| -> Result<Comparison> {
        Ok(Comparison { table_iii: report(set, HdrParams::table_iii())?, tuned: report(set, result.params)? })
    };
    let train_cmp = compare(train)?;
    let test_cmp = if test.is_empty() { None } else { Some(compare(test)?) };
    Ok(TuneReport { result, train: train_cmp, test: test_cmp })
}

#[cfg(test)]
mod cv_tests {
    use super::*;
    use crate::sim::{simulate, SimRequest};

    fn drives(n: u64) -> Vec<PreparedDrive> {
        (0..n)
            .map(|i| {
                let log = simulate(&SimRequest { scenario: Some("city".into()), minutes: Some(4.0), seed: 40 + i, ..Default::default() })
                    .unwrap();
                PreparedDrive::new(&format!("d{i}"), &log, None, true).unwrap()
            })
            .collect()
    }

    #[test]
    fn cross_validation_holds_each_drive_out_once_and_gates_the_recommendation() {
        let d = drives(3);
        let opts = TuneOptions { max_iters: 20, restarts: 0, ..Default::default() };
        let r = tune(&d, &opts).unwrap();
        let cv = r.cv.as_ref().unwrap();
        assert_eq!(cv.folds.iter().map(|f| f.held_out.as_str()).collect::<Vec<_>>(), ["d0", "d1", "d2"]);
        // Table III's held-out score is its plain mean NE_psi over the drives.
        let t3 = objective(&d, HdrParams::table_iii()).unwrap();
        assert!((cv.cv_table_iii_deg_per_min - t3).abs() < 1e-12);
        let fold0 = tune_once(&d[1..], &opts, &|_| {}).unwrap();
        assert_eq!(cv.folds[0].params, fold0.params, "fold 0 tuned on d1, d2 only");
        assert_eq!(r.recommended_is_tuned, cv.cv_tuned_deg_per_min < cv.cv_table_iii_deg_per_min);
        assert_eq!(r.recommended, if r.recommended_is_tuned { r.params } else { HdrParams::table_iii() });
        // Two drives: no cross-validation; the tuned parameters are returned as they are.
        let r2 = tune(&d[..2], &opts).unwrap();
        assert!(r2.cv.is_none() && r2.recommended_is_tuned);
    }

    #[test]
    fn regularization_pulls_toward_table_iii() {
        let d = drives(2);
        let free = TuneOptions { max_iters: 60, restarts: 0, regularization_deg_per_min: 0.0, cross_validate: false, ..Default::default() };
        let strong = TuneOptions { regularization_deg_per_min: 1000.0, ..free };
        let t3 = HdrParams::table_iii();
        let dist = |p: HdrParams| (p.i_c_dps - t3.i_c_dps).abs() / 0.3 + (p.theta_w_dps - t3.theta_w_dps).abs() / 3.0;
        let a = tune(&d, &free).unwrap().params;
        let b = tune(&d, &strong).unwrap().params;
        // regularised: within a fifth of the free optimum's distance from Table III
        assert!(dist(b) < 0.2 * dist(a), "free {a:?}, regularised {b:?}");
        assert!(tune(&d, &TuneOptions { regularization_deg_per_min: -1.0, ..free }).is_err());
    }
}
