//! HDR batch runs: the raw baseline, options of a run, the per-sample trace, the Result
//! keys, and `run` over a log (static bias, 1 Hz blocks, estimator, metrics).

use super::{Hdr, HdrParams};
use crate::error::{Error, Result};
use crate::log::DriveLog;
use crate::metrics::{self, Reference};
use crate::preprocess::{self, Samples};
use serde::{Deserialize, Serialize};

/// The paper's "without HDR" baseline: integrate (w_raw - eps0) with no filter.
#[derive(Debug, Clone, Default)]
pub struct RawIntegrator {
    eps0_dps: f64,
    last_time_s: Option<f64>,
    heading_deg: f64,
}

impl RawIntegrator {
    pub fn new(eps0_dps: f64) -> Self {
        RawIntegrator { eps0_dps, last_time_s: None, heading_deg: 0.0 }
    }
    /// psi_i = psi_{i-1} + (w_raw_i - eps0) T_i; psi_0 = 0.
    #[inline]
    pub fn update(&mut self, time_s: f64, rate_raw_dps: f64) -> f64 {
        if let Some(t) = self.last_time_s {
            self.heading_deg += (rate_raw_dps - self.eps0_dps) * (time_s - t);
        }
        self.last_time_s = Some(time_s);
        self.heading_deg
    }
}

/// Options of a batch HDR run. (De)serialized flat: the five parameters, bias_s, resample.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(from = "HdrOptionsFlat", into = "HdrOptionsFlat")]
pub struct HdrOptions {
    pub params: HdrParams,
    /// Static-bias window, s; None = the log's `# bias_s:` or 20 s.
    pub bias_s: Option<f64>,
    /// Block-average to 1 Hz first (the paper's pre-processing; default true).
    pub resample: bool,
}

impl Default for HdrOptions {
    fn default() -> Self {
        HdrOptions { params: HdrParams::default(), bias_s: None, resample: true }
    }
}

/// The flat wire form of `HdrOptions` (no `flatten`, so errors name the field).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct HdrOptionsFlat {
    #[serde(alias = "i_c")]
    i_c_dps: f64,
    #[serde(alias = "tau")]
    tau_s: f64,
    #[serde(alias = "theta_w")]
    theta_w_dps: f64,
    c1: f64,
    c2: f64,
    bias_s: Option<f64>,
    resample: bool,
}

impl Default for HdrOptionsFlat {
    fn default() -> Self {
        HdrOptions::default().into()
    }
}

impl From<HdrOptionsFlat> for HdrOptions {
    fn from(f: HdrOptionsFlat) -> Self {
        HdrOptions {
            params: HdrParams { i_c_dps: f.i_c_dps, tau_s: f.tau_s, theta_w_dps: f.theta_w_dps, c1: f.c1, c2: f.c2 },
            bias_s: f.bias_s,
            resample: f.resample,
        }
    }
}

impl From<HdrOptions> for HdrOptionsFlat {
    fn from(o: HdrOptions) -> Self {
        let p = o.params;
        HdrOptionsFlat {
            i_c_dps: p.i_c_dps,
            tau_s: p.tau_s,
            theta_w_dps: p.theta_w_dps,
            c1: p.c1,
            c2: p.c2,
            bias_s: o.bias_s,
            resample: o.resample,
        }
    }
}

impl crate::options::Settings for HdrOptions {
    /// The five parameters and the static-bias window.
    fn validate(&self) -> Result<()> {
        self.params.validate()?;
        crate::options::check_bias_s(self.bias_s)
    }
}

/// Per-sample series of a batch run, at the estimator samples (blocks or rows).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct HdrTrace {
    pub time_s: Vec<f64>,
    /// Raw baseline heading, aligned to the reference (unshifted if there is none).
    pub heading_raw_deg: Vec<f64>,
    /// HDR heading, aligned to the reference (unshifted if there is none).
    pub heading_hdr_deg: Vec<f64>,
    pub rate_raw_dps: Vec<f64>,
    pub rate_corrected_dps: Vec<f64>,
    pub i_dps: Vec<f64>,
    pub turn_switch: Vec<bool>,
    pub attenuation: Vec<f64>,
}

impl HdrTrace {
    /// The drift estimate -I at each sample, deg/s (the paper's Figs. 3 and 5).
    pub fn drift_estimate_dps(&self) -> Vec<f64> {
        self.i_dps.iter().map(|i| -i).collect()
    }

    /// Writes the per-sample trace CSV of methods.md: time_s, heading_raw_deg, heading_hdr_deg
    /// (the first three of [`HdrTrace::columns`], a test holds them equal; written directly,
    /// as the spec's fixed format: the generic writer would add 0.3 KB to the page's module).
    pub fn write_csv<W: std::io::Write>(&self, out: W) -> Result<()> {
        use std::io::Write as _;
        let mut out = std::io::BufWriter::new(out);
        writeln!(out, "time_s,heading_raw_deg,heading_hdr_deg")?;
        for i in 0..self.time_s.len() {
            writeln!(out, "{},{},{}", self.time_s[i], self.heading_raw_deg[i], self.heading_hdr_deg[i])?;
        }
        out.flush()?;
        Ok(())
    }

    /// Every series of the wasm `runHdr` and Python's `run_hdr`: methods.md's trace CSV
    /// first, then the rates, the drift estimate -I, the turn switch and the attenuation.
    pub fn columns(&self) -> [(&'static str, crate::series::Column<'_>); 9] {
        use crate::series::{values, Column};
        [
            ("time_s", values(&self.time_s)),
            ("heading_raw_deg", values(&self.heading_raw_deg)),
            ("heading_hdr_deg", values(&self.heading_hdr_deg)),
            ("rate_raw_dps", values(&self.rate_raw_dps)),
            ("rate_corrected_dps", values(&self.rate_corrected_dps)),
            ("i_dps", values(&self.i_dps)),
            ("drift_estimate_dps", Column::Values(self.drift_estimate_dps().into())),
            ("turn_switch", Column::Flags(&self.turn_switch)),
            ("attenuation", values(&self.attenuation)),
        ]
    }
}

/// The Result keys of methods.md for `hdr`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct HdrResult {
    pub E_psi_raw_deg: f64,
    pub E_psi_hdr_deg: f64,
    pub NE_psi_raw_deg_per_min: f64,
    pub NE_psi_hdr_deg_per_min: f64,
    pub improvement: f64,
    pub duration_min: f64,
    pub n_samples: usize,
    pub n_processed: usize,
    pub eps0_dps: f64,
    pub resampled: bool,
}

/// A batch run: the trace always, the metrics when the log has a usable reference.
#[derive(Debug, Clone)]
pub struct HdrRun {
    pub eps0_dps: f64,
    pub trace: HdrTrace,
    pub result: Result<HdrResult>,
}

/// What an HDR run says without a reference heading to score against: the estimator's
/// own figures at the end of the log.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HdrSummary {
    pub duration_min: f64,
    /// Static bias over the lead-in (Eq. 2), deg/s.
    pub eps0_dps: f64,
    /// The drift estimate -I at the end, deg/s.
    pub final_drift_estimate_dps: f64,
    /// Heading turned from the first sample to the last, raw and with HDR, deg.
    pub heading_change_raw_deg: f64,
    pub heading_change_hdr_deg: f64,
    pub n_processed: usize,
}

impl HdrRun {
    /// The estimator's figures at the end of the log (`duration_min`: the log's), with or
    /// without a reference.
    pub fn summary(&self, duration_min: f64) -> HdrSummary {
        let t = &self.trace;
        let change = |x: &[f64]| x.last().copied().unwrap_or(f64::NAN) - x.first().copied().unwrap_or(f64::NAN);
        HdrSummary {
            duration_min,
            eps0_dps: self.eps0_dps,
            final_drift_estimate_dps: t.i_dps.last().map_or(f64::NAN, |i| -i),
            heading_change_raw_deg: change(&t.heading_raw_deg),
            heading_change_hdr_deg: change(&t.heading_hdr_deg),
            n_processed: t.time_s.len(),
        }
    }

    /// For plots: the unwrapped reference and the errors of the raw and HDR headings at the
    /// scored samples; None when there is no result.
    pub fn errors(&self, log: &DriveLog) -> Option<(Reference, metrics::ErrorSeries)> {
        let t = &self.trace;
        self.result.as_ref().ok().and_then(|_| metrics::ErrorSeries::of(log, &t.time_s, &[&t.heading_raw_deg, &t.heading_hdr_deg]))
    }

    /// As [`HdrRun::errors`], against the reference of a preparation (not read again).
    pub fn errors_against(&self, reference: &Reference) -> Option<metrics::ErrorSeries> {
        let t = &self.trace;
        self.result.as_ref().ok().map(|_| metrics::ErrorSeries::against(reference, &t.time_s, &[&t.heading_raw_deg, &t.heading_hdr_deg]))
    }
}

/// Runs HDR and the raw baseline over prepared samples (no allocation per sample beyond
/// the trace vectors).
pub fn run_samples(samples: &Samples, params: HdrParams, eps0_dps: f64) -> Result<HdrTrace> {
    let n = samples.len();
    let mut hdr = Hdr::new(params, eps0_dps)?;
    let mut raw = RawIntegrator::new(eps0_dps);
    let mut tr = HdrTrace {
        time_s: samples.time_s.clone(),
        heading_raw_deg: Vec::with_capacity(n),
        heading_hdr_deg: Vec::with_capacity(n),
        rate_raw_dps: samples.rate_dps.clone(),
        rate_corrected_dps: Vec::with_capacity(n),
        i_dps: Vec::with_capacity(n),
        turn_switch: Vec::with_capacity(n),
        attenuation: Vec::with_capacity(n),
    };
    for (&t, &w) in samples.time_s.iter().zip(&samples.rate_dps) {
        tr.heading_raw_deg.push(raw.update(t, w));
    }
    hdr.update_slice(&samples.time_s, &samples.rate_dps, |o| {
        tr.heading_hdr_deg.push(o.heading_deg);
        tr.rate_corrected_dps.push(o.rate_corrected_dps);
        tr.i_dps.push(o.i_dps);
        tr.turn_switch.push(o.turn_switch);
        tr.attenuation.push(o.attenuation);
    })?;
    Ok(tr)
}

/// Only the headings, for tuning: HDR and raw E_psi without building a trace.
pub fn headings_only(samples: &Samples, params: HdrParams, eps0_dps: f64, out_hdr: &mut Vec<f64>) -> Result<()> {
    let mut hdr = Hdr::new(params, eps0_dps)?;
    out_hdr.clear();
    hdr.update_slice(&samples.time_s, &samples.rate_dps, |o| out_hdr.push(o.heading_deg))
}

/// Runs HDR on a log: static bias, optional 1 Hz blocks, estimator, baseline, metrics.
/// Parameter and data errors are returned; a missing reference only fails `result`.
pub fn run(log: &DriveLog, opts: &HdrOptions) -> Result<HdrRun> {
    crate::options::Settings::validate(opts)?;
    run_prepared(log, &prepare(log, opts)?, opts)
}

/// What HDR takes from a log that its parameters do not change: the static bias, the
/// estimator's samples (1 Hz blocks or as logged) and the reference. A page moving a
/// slider prepares once per log and lead-in and re-runs only the method.
#[derive(Debug, Clone)]
pub struct Prepared {
    pub bias_s: Option<f64>,
    pub resample: bool,
    pub eps0_dps: f64,
    pub samples: Samples,
    pub reference: Result<Reference>,
}

impl Prepared {
    /// Whether these options need the same preparation (lead-in and blocks).
    pub fn fits(&self, opts: &HdrOptions) -> bool {
        self.bias_s == opts.bias_s && self.resample == opts.resample
    }
}

/// The preparation of a log for HDR with these options (see [`Prepared`]).
pub fn prepare(log: &DriveLog, opts: &HdrOptions) -> Result<Prepared> {
    let (eps0_dps, samples) = preprocess::prepare(log, opts.bias_s, opts.resample)?;
    log.check_span()?;
    Ok(Prepared { bias_s: opts.bias_s, resample: opts.resample, eps0_dps, samples, reference: Reference::from_log(log) })
}

/// HDR over a log's preparation: the same run as [`run`] for options the preparation fits.
pub fn run_prepared(log: &DriveLog, p: &Prepared, opts: &HdrOptions) -> Result<HdrRun> {
    crate::options::Settings::validate(opts)?;
    if !p.fits(opts) {
        return Err(Error::param("bias_s", "the preparation was made for another bias_s or resample"));
    }
    let (eps0, samples) = (p.eps0_dps, &p.samples);
    let mut trace = run_samples(samples, opts.params, eps0)?;
    let result = p.reference.clone().and_then(|reference| {
        let raw = metrics::score(&trace.time_s, &trace.heading_raw_deg, &reference)?;
        let hdr = metrics::score(&trace.time_s, &trace.heading_hdr_deg, &reference)?;
        trace.heading_raw_deg.iter_mut().for_each(|p| *p += raw.shift_deg);
        trace.heading_hdr_deg.iter_mut().for_each(|p| *p += hdr.shift_deg);
        let d = log.duration_min();
        Ok(HdrResult {
            E_psi_raw_deg: raw.e_psi_deg,
            E_psi_hdr_deg: hdr.e_psi_deg,
            NE_psi_raw_deg_per_min: metrics::ne_psi(raw.e_psi_deg, d),
            NE_psi_hdr_deg_per_min: metrics::ne_psi(hdr.e_psi_deg, d),
            improvement: metrics::improvement(raw.e_psi_deg, hdr.e_psi_deg),
            duration_min: d,
            n_samples: hdr.n_samples,
            n_processed: samples.len(),
            eps0_dps: eps0,
            resampled: opts.resample,
        })
    });
    Ok(HdrRun { eps0_dps: eps0, trace, result })
}
