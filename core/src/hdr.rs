//! Heuristic Drift Reduction (Borenstein & Ojeda, seed 000, enhanced algorithm Eqs. 7-14)
//! as a streaming estimator, read exactly as methods.md fixes it. The batch `run` is the
//! same `update` in a loop, plus the raw baseline and the metrics.

use crate::error::{Error, Result};
use crate::log::DriveLog;
use crate::metrics::{self, Reference};
use crate::preprocess::{self, Samples};
use serde::{Deserialize, Serialize};

/// HDR's five tunable parameters; defaults are the paper's Table III.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HdrParams {
    /// Nominal increment i_c of the binary I-controller, deg/s (per second of time).
    #[serde(alias = "i_c")]
    pub i_c_dps: f64,
    /// Low-pass filter time constant tau, s.
    #[serde(alias = "tau")]
    pub tau_s: f64,
    /// Turn-switch threshold theta_w, deg/s.
    #[serde(alias = "theta_w")]
    pub theta_w_dps: f64,
    /// Repetition attenuator constant c1 (> 0).
    pub c1: f64,
    /// Repetition attenuator power c2.
    pub c2: f64,
}

impl Default for HdrParams {
    /// Table III of the HDR paper.
    fn default() -> Self {
        HdrParams { i_c_dps: 0.0422, tau_s: 0.75, theta_w_dps: 0.564, c1: 0.16, c2: 1.80 }
    }
}

impl HdrParams {
    /// Table III of the HDR paper.
    pub fn table_iii() -> Self {
        Self::default()
    }

    /// Every parameter finite and in range: i_c, tau, theta_w >= 0, c1 > 0, c2 >= 0.
    pub fn validate(&self) -> Result<()> {
        let check = |name: &str, v: f64, ok: bool, what: &str| -> Result<()> {
            if !v.is_finite() || !ok {
                Err(Error::param(name, format!("{v:?} is not {what}")))
            } else {
                Ok(())
            }
        };
        // Upper ends: far beyond any gyro or vehicle, so only mistakes are refused.
        check("i_c", self.i_c_dps, (0.0..=10.0).contains(&self.i_c_dps), "a rate in [0, 10] deg/s")?;
        check("tau", self.tau_s, (0.0..=3600.0).contains(&self.tau_s), "a time in [0, 3600] s")?;
        check("theta_w", self.theta_w_dps, (0.0..=100.0).contains(&self.theta_w_dps), "a rate in [0, 100] deg/s")?;
        check("c1", self.c1, self.c1 > 0.0 && self.c1 <= 1e6, "a number in (0, 1e6]")?;
        check("c2", self.c2, (0.0..=100.0).contains(&self.c2), "a number in [0, 100]")?;
        Ok(())
    }
}

impl crate::options::Settings for HdrParams {
    fn validate(&self) -> Result<()> {
        HdrParams::validate(self)
    }
}

/// SIGN(x) of the paper: 1, 0, -1 for x > 0, x == 0, x < 0 (branch-free).
#[inline]
pub fn sign(x: f64) -> f64 {
    ((x > 0.0) as i32 - (x < 0.0) as i32) as f64
}

/// The repetition attenuator R = (1 + c1) / (1 + c1 r^c2) (Eq. 10).
#[inline]
pub fn attenuation(c1: f64, c2: f64, r: u64) -> f64 {
    (1.0 + c1) / (1.0 + c1 * libm::pow(r as f64, c2))
}

/// One step's output of the estimator.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HdrOutput {
    pub time_s: f64,
    /// Filtered rate omega' (Eq. 7), eps0 removed, deg/s.
    pub rate_filtered_dps: f64,
    /// Corrected rate omega = omega' + I (Eq. 12), deg/s.
    pub rate_corrected_dps: f64,
    /// De-lagged rate omega_d (Eq. 13), the one integrated, deg/s.
    pub rate_delag_dps: f64,
    /// Heading psi (Eq. 14), starting at 0, unwrapped, deg.
    pub heading_deg: f64,
    /// Controller output I, deg/s; -I is the drift estimate.
    pub i_dps: f64,
    /// Turn switch W (Eq. 8): true while HDR corrects (not turning).
    pub turn_switch: bool,
    /// Repetition count r (Eq. 9).
    pub r: u64,
    /// Repetition attenuation R (Eq. 10).
    pub attenuation: f64,
}

#[derive(Debug, Clone, Copy)]
struct HdrState {
    time_s: f64,
    w_f: f64,
    i: f64,
    r: u64,
    omega1: f64,
    omega2: f64,
    psi: f64,
}

/// The streaming HDR estimator: feed raw yaw-rate samples with `update`.
#[derive(Debug, Clone)]
pub struct Hdr {
    params: HdrParams,
    eps0_dps: f64,
    started: bool,
    s: HdrState,
    /// R(r) for r = 0, 1, 2, ... computed with `powf` once each (bit-identical to Eq. 10;
    /// `powf` per sample would cost ~30 ns, more than the rest of the step).
    r_table: Vec<f64>,
}

const R_TABLE_MAX: usize = 1 << 20;

impl Hdr {
    /// A new estimator with validated parameters and the static bias eps0 to remove.
    pub fn new(params: HdrParams, eps0_dps: f64) -> Result<Self> {
        params.validate()?;
        if !eps0_dps.is_finite() {
            return Err(Error::param("eps0", "the static bias must be finite"));
        }
        let r_table = (0..256u64).map(|r| attenuation(params.c1, params.c2, r)).collect();
        let s = HdrState { time_s: 0.0, w_f: 0.0, i: 0.0, r: 1, omega1: 0.0, omega2: 0.0, psi: 0.0 };
        Ok(Hdr { params, eps0_dps, started: false, s, r_table })
    }

    pub fn params(&self) -> &HdrParams {
        &self.params
    }
    pub fn eps0_dps(&self) -> f64 {
        self.eps0_dps
    }

    /// R(r) from the table, extended on demand (rare: only when a run of equal signs
    /// grows past every earlier one).
    #[cfg(test)]
    fn r_factor(&mut self, r: u64) -> f64 {
        match self.r_table.get(r as usize) {
            Some(&v) => v,
            None => extend_r_table(&mut self.r_table, self.params.c1, self.params.c2, r),
        }
    }

    /// One step of the enhanced algorithm (methods.md steps 1-9) for a raw rate sample.
    /// Time must strictly increase and the rate be finite, or an error is returned and
    /// the state is left unchanged.
    #[inline]
    pub fn update(&mut self, time_s: f64, rate_raw_dps: f64) -> Result<HdrOutput> {
        step(&self.params, self.eps0_dps, &mut self.r_table, &mut self.s, &mut self.started, time_s, rate_raw_dps)
    }

    /// `update` over many samples, calling `sink` with each output: the same steps as
    /// `update`, with the input checked first in one pass and the state held in registers
    /// for the whole slice (the batch path). On an error the samples before it are kept.
    #[inline]
    pub fn update_slice<F: FnMut(&HdrOutput)>(&mut self, time_s: &[f64], rate_raw_dps: &[f64], mut sink: F) -> Result<()> {
        if time_s.len() != rate_raw_dps.len() {
            return Err(Error::data("time and rate series differ in length"));
        }
        let (mut t_prev, mut start) = (self.s.time_s, 0);
        if !self.started {
            let (Some(&t0), Some(&w0)) = (time_s.first(), rate_raw_dps.first()) else { return Ok(()) };
            sink(&self.update(t0, w0)?);
            (t_prev, start) = (t0, 1);
        }
        // The valid prefix: finite values, strictly increasing time.
        let mut end = start;
        for k in start..time_s.len() {
            let (t, w) = (time_s[k], rate_raw_dps[k]);
            if !(t.is_finite() && w.is_finite() && t > t_prev) {
                break;
            }
            t_prev = t;
            end = k + 1;
        }
        let p = self.params;
        let mut st = self.s;
        for k in start..end {
            sink(&step_checked_input(&p, self.eps0_dps, &mut self.r_table, &mut st, time_s[k], rate_raw_dps[k]));
        }
        self.s = st;
        if end < time_s.len() {
            return Err(reject(time_s[end], rate_raw_dps[end], self.s.time_s));
        }
        Ok(())
    }

    /// Forgets the state (keeps parameters and eps0).
    pub fn reset(&mut self) {
        self.started = false;
    }
}

/// One HDR step on explicit state (methods.md steps 1-9); shared by `update` and
/// `update_slice` so that streaming and batch are the same code.
#[inline(always)]
fn step(
    p: &HdrParams,
    eps0_dps: f64,
    r_table: &mut Vec<f64>,
    st: &mut HdrState,
    started: &mut bool,
    time_s: f64,
    rate_raw_dps: f64,
) -> Result<HdrOutput> {
    let dt = time_s - st.time_s;
    if !(rate_raw_dps.is_finite() && time_s.is_finite() && (dt > 0.0 || !*started)) {
        return Err(reject(time_s, rate_raw_dps, st.time_s));
    }
    if !*started {
        let x = rate_raw_dps - eps0_dps;
        // i = 0: w_f = x, I = 0, r = 1, omega_0 = w_f, psi_0 = 0, omega_d0 = omega_0;
        // omega_{-1} := omega_0 so that r_1 = 2 (methods.md step 4).
        *started = true;
        *st = HdrState { time_s, w_f: x, i: 0.0, r: 1, omega1: x, omega2: x, psi: 0.0 };
        return Ok(HdrOutput {
            time_s,
            rate_filtered_dps: x,
            rate_corrected_dps: x,
            rate_delag_dps: x,
            heading_deg: 0.0,
            i_dps: 0.0,
            turn_switch: false,
            r: 1,
            attenuation: 1.0,
        });
    }
    Ok(step_checked_input(p, eps0_dps, r_table, st, time_s, rate_raw_dps))
}

/// Steps 1-9 for i >= 1 on input already checked (finite, time after the previous).
#[inline(always)]
fn step_checked_input(
    p: &HdrParams,
    eps0_dps: f64,
    r_table: &mut Vec<f64>,
    st: &mut HdrState,
    time_s: f64,
    rate_raw_dps: f64,
) -> HdrOutput {
    let s = *st;
    let dt = time_s - s.time_s;
    // Step 1, Eq. 2: remove the static bias.
    let x = rate_raw_dps - eps0_dps;
    // Step 2, Eq. 7: first-order low-pass filter (x T + tau w_f) / (T + tau).
    let w_f = (x * dt + p.tau_s * s.w_f) / (dt + p.tau_s);
    // Step 3, Eq. 8 (inequality fixed): switch on while the previous corrected rate is small.
    let w_on = s.omega1.abs() < p.theta_w_dps;
    // Step 4, Eq. 9: count repetitions of the same sign. Branch-free: on straights the
    // sign of the residual is noise, and a mispredicted branch costs more than the step.
    let sg1 = sign_i(s.omega1);
    let same = sg1 == sign_i(s.omega2);
    // Step 5, Eq. 10: R(r_{i-1} + 1) is looked up before the sign test is known; R(1) = 1
    // exactly, so the reset needs no lookup.
    let r_cont = s.r + 1;
    let big_r_cont = match r_table.get(r_cont as usize) {
        Some(&v) => v,
        None => extend_r_table(r_table, p.c1, p.c2, r_cont),
    };
    let r = std::hint::select_unpredictable(same, r_cont, 1);
    let big_r = std::hint::select_unpredictable(same, big_r_cont, 1.0);
    // Step 6, Eq. 11: binary I-controller, i_c per second of time.
    // SIGN(omega_{i-1}) * W * R * i_c * T as a sign copy and a mask (exact, branch-free).
    let magnitude = big_r * (p.i_c_dps * dt);
    let signed = f64::from_bits(magnitude.to_bits() | (s.omega1.to_bits() & SIGN_BIT));
    let step = f64::from_bits(signed.to_bits() & ((w_on & (sg1 != 0)) as u64).wrapping_neg());
    let i = s.i - step;
    // Step 7, Eq. 12: corrected rate.
    let omega = w_f + i;
    // Step 8, Eq. 13: de-lag the filter.
    let omega_d = omega + (p.tau_s / dt) * (omega - s.omega1);
    // Step 9, Eq. 14 (fixed: psi_0 only as the initial value): integrate.
    let psi = s.psi + omega_d * dt;
    *st = HdrState { time_s, w_f, i, r, omega1: omega, omega2: s.omega1, psi };
    HdrOutput {
        time_s,
        rate_filtered_dps: w_f,
        rate_corrected_dps: omega,
        rate_delag_dps: omega_d,
        heading_deg: psi,
        i_dps: i,
        turn_switch: w_on,
        r,
        attenuation: big_r,
    }
}

const SIGN_BIT: u64 = 0x8000_0000_0000_0000;

/// SIGN as an integer, branch-free.
#[inline(always)]
fn sign_i(x: f64) -> i64 {
    (x > 0.0) as i64 - (x < 0.0) as i64
}

/// Extends the R(r) table up to r (doubling, capped) and returns R(r); past the cap, powf.
#[cold]
#[inline(never)]
fn extend_r_table(table: &mut Vec<f64>, c1: f64, c2: f64, r: u64) -> f64 {
    if r as usize >= R_TABLE_MAX {
        return attenuation(c1, c2, r);
    }
    let start = table.len() as u64;
    let end = (r + 1).max(start * 2).min(R_TABLE_MAX as u64);
    table.extend((start..end).map(|k| attenuation(c1, c2, k)));
    table[r as usize]
}

#[cold]
#[inline(never)]
fn reject(time_s: f64, rate_raw_dps: f64, prev_time_s: f64) -> Error {
    if !rate_raw_dps.is_finite() || !time_s.is_finite() {
        Error::data(format!("HDR update at {time_s} s: rate {rate_raw_dps} deg/s is not finite"))
    } else {
        Error::data(format!("HDR update: time {time_s} s is not after the previous {prev_time_s} s"))
    }
}

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

    /// Writes the per-sample trace CSV of methods.md: time_s, heading_raw_deg, heading_hdr_deg.
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
    let (eps0, samples) = preprocess::prepare(log, opts.bias_s, opts.resample)?;
    let mut trace = run_samples(&samples, opts.params, eps0)?;
    let result = Reference::from_log(log).and_then(|reference| {
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

#[cfg(test)]
mod tests {
    use super::*;

    const EPS: f64 = 1e-12;

    fn close(a: f64, b: f64) {
        assert!((a - b).abs() < EPS * (1.0 + b.abs()), "{a} != {b}");
    }

    #[test]
    fn sign_is_three_valued() {
        assert_eq!(sign(2.0), 1.0);
        assert_eq!(sign(-0.1), -1.0);
        assert_eq!(sign(0.0), 0.0);
        assert_eq!(sign(-0.0), 0.0);
    }

    #[test]
    fn attenuation_eq10_hand_worked() {
        // r = 1: (1 + c1) / (1 + c1) = 1
        assert_eq!(attenuation(0.16, 1.8, 1), 1.0);
        // r = 2, c2 = 2: 1.16 / (1 + 0.16 * 4) = 1.16 / 1.64
        close(attenuation(0.16, 2.0, 2), 1.16 / 1.64);
        // r = 10, c1 = 1, c2 = 1: 2 / 11
        close(attenuation(1.0, 1.0, 10), 2.0 / 11.0);
    }

    #[test]
    fn r_table_matches_powf_bit_for_bit() {
        let p = HdrParams::default();
        let mut h = Hdr::new(p, 0.0).unwrap();
        assert_eq!(attenuation(p.c1, p.c2, 1), 1.0, "R(1) = 1 exactly, used as the reset value");
        for r in [1u64, 2, 255, 256, 257, 500, 3000, 2_000_000] {
            assert_eq!(h.r_factor(r).to_bits(), attenuation(p.c1, p.c2, r).to_bits());
        }
    }

    #[test]
    fn params_validation() {
        assert!(HdrParams::default().validate().is_ok());
        let bad = [
            HdrParams { tau_s: -0.1, ..Default::default() },
            HdrParams { i_c_dps: -1.0, ..Default::default() },
            HdrParams { c1: 0.0, ..Default::default() },
            HdrParams { c1: -1.0, ..Default::default() },
            HdrParams { theta_w_dps: f64::NAN, ..Default::default() },
            HdrParams { c2: f64::INFINITY, ..Default::default() },
        ];
        for p in bad {
            assert!(matches!(p.validate(), Err(Error::Param { .. })), "{p:?}");
        }
        let e = HdrParams { tau_s: -0.1, ..Default::default() }.validate().unwrap_err();
        assert_eq!(e.to_string(), "parameter tau: -0.1 is not a time in [0, 3600] s");
        let e = HdrParams { i_c_dps: 1e300, ..Default::default() }.validate().unwrap_err();
        assert_eq!(e.to_string(), "parameter i_c: 1e300 is not a rate in [0, 10] deg/s");
    }

    #[test]
    fn first_steps_value_by_value() {
        // Parameters chosen for hand arithmetic: i_c = 0.1, tau = 1, theta_w = 0.5, c1 = 1, c2 = 1.
        // eps0 = 1; raw rates 1.2, 1.0, 0.8, 3.0 at t = 0, 1, 2, 3 (T = 1 s).
        let p = HdrParams { i_c_dps: 0.1, tau_s: 1.0, theta_w_dps: 0.5, c1: 1.0, c2: 1.0 };
        let mut h = Hdr::new(p, 1.0).unwrap();
        // i = 0: x = 0.2; w_f = 0.2; omega_0 = 0.2; psi 0.
        let o0 = h.update(0.0, 1.2).unwrap();
        close(o0.rate_filtered_dps, 0.2);
        close(o0.rate_corrected_dps, 0.2);
        assert_eq!(o0.heading_deg, 0.0);
        assert_eq!(o0.r, 1);
        // i = 1: x = 0; w_f = (0*1 + 1*0.2)/2 = 0.1; W = |0.2| < 0.5 -> 1;
        // r = 2 (omega_{-1} := omega_0); R = 2/(1+2) = 2/3; I = 0 - 1 * 2/3 * 0.1 = -1/15;
        // omega = 0.1 - 1/15 = 1/30; omega_d = 1/30 + (1/30 - 0.2) = -2/15; psi = -2/15.
        let o1 = h.update(1.0, 1.0).unwrap();
        close(o1.rate_filtered_dps, 0.1);
        assert!(o1.turn_switch);
        assert_eq!(o1.r, 2);
        close(o1.attenuation, 2.0 / 3.0);
        close(o1.i_dps, -1.0 / 15.0);
        close(o1.rate_corrected_dps, 1.0 / 30.0);
        close(o1.rate_delag_dps, -2.0 / 15.0);
        close(o1.heading_deg, -2.0 / 15.0);
        // i = 2: x = -0.2; w_f = (-0.2 + 0.1)/2 = -0.05; W: |1/30| < 0.5 -> 1;
        // sign(omega_1) = sign(omega_0) = + -> r = 3, R = 2/4 = 0.5;
        // I = -1/15 - 0.5*0.1 = -7/60; omega = -0.05 - 7/60 = -1/6;
        // omega_d = -1/6 + (-1/6 - 1/30) = -11/30; psi = -2/15 - 11/30 = -1/2.
        let o2 = h.update(2.0, 0.8).unwrap();
        close(o2.rate_filtered_dps, -0.05);
        assert_eq!(o2.r, 3);
        close(o2.attenuation, 0.5);
        close(o2.i_dps, -7.0 / 60.0);
        close(o2.rate_corrected_dps, -1.0 / 6.0);
        close(o2.rate_delag_dps, -11.0 / 30.0);
        close(o2.heading_deg, -0.5);
        // i = 3: x = 2; w_f = (2 - 0.05)/2 = 0.975; W: |-1/6| < 0.5 -> 1;
        // sign(omega_2) = - != sign(omega_1) = + -> r = 1, R = 1; I = -7/60 + 0.1 = -1/60;
        // omega = 0.975 - 1/60 = 0.958333..; omega_d = omega + (omega + 1/6) ; psi += omega_d.
        let o3 = h.update(3.0, 3.0).unwrap();
        assert_eq!(o3.r, 1);
        close(o3.i_dps, -1.0 / 60.0);
        let omega3 = 0.975 - 1.0 / 60.0;
        close(o3.rate_corrected_dps, omega3);
        close(o3.rate_delag_dps, omega3 + (omega3 + 1.0 / 6.0));
        close(o3.heading_deg, -0.5 + omega3 + (omega3 + 1.0 / 6.0));
        // i = 4: |omega_3| = 0.958 >= 0.5 -> switch off, I unchanged.
        let o4 = h.update(4.0, 1.0).unwrap();
        assert!(!o4.turn_switch);
        close(o4.i_dps, -1.0 / 60.0);
    }

    #[test]
    fn i_c_scales_with_sample_interval() {
        // Eq. 11 with T = 0.5 s: the increment is i_c * 0.5.
        let p = HdrParams { i_c_dps: 0.1, tau_s: 0.0, theta_w_dps: 1.0, c1: 1.0, c2: 0.0 };
        let mut h = Hdr::new(p, 0.0).unwrap();
        h.update(0.0, 0.3).unwrap();
        let o = h.update(0.5, 0.3).unwrap();
        // c2 = 0 -> R = 1 always; I = -0.1 * 0.5
        close(o.i_dps, -0.05);
        // tau = 0: w_f = x; omega = 0.3 - 0.05; de-lag term is 0; psi = 0.25 * 0.5
        close(o.heading_deg, 0.125);
    }

    #[test]
    fn update_rejects_bad_time_and_rate() {
        let mut h = Hdr::new(HdrParams::default(), 0.0).unwrap();
        h.update(1.0, 0.0).unwrap();
        assert!(h.update(1.0, 0.0).is_err());
        assert!(h.update(0.5, 0.0).is_err());
        assert!(h.update(2.0, f64::NAN).is_err());
        // state unchanged by the rejected samples
        assert!(h.update(2.0, 0.0).is_ok());
    }

    #[test]
    fn raw_integrator_hand_worked() {
        let mut r = RawIntegrator::new(0.5);
        assert_eq!(r.update(0.0, 9.0), 0.0);
        assert_eq!(r.update(1.0, 1.5), 1.0);
        assert_eq!(r.update(3.0, 0.0), 0.0);
    }

    #[test]
    fn options_by_name() {
        let set: Vec<(String, f64)> = [("i_c", 0.01), ("tau", 2.0), ("theta_w", 0.3), ("c1", 0.5), ("c2", 1.0), ("bias_s", 10.0)]
            .map(|(k, v)| (k.to_string(), v))
            .to_vec();
        let o: HdrOptions = crate::options::from_pairs(&set).unwrap();
        assert_eq!(o.params, HdrParams { i_c_dps: 0.01, tau_s: 2.0, theta_w_dps: 0.3, c1: 0.5, c2: 1.0 });
        assert_eq!(o.bias_s, Some(10.0));
        assert!(o.resample);
        assert!(crate::options::from_pairs::<HdrOptions>(&[("gain".into(), 1.0)]).is_err());
        assert!(crate::options::from_pairs::<HdrOptions>(&[("bias_s".into(), -1.0)]).is_err());
        assert!(crate::options::from_pairs::<HdrOptions>(&[("c1".into(), 0.0)]).is_err());
    }

    #[test]
    fn options_deserialize_with_defaults_and_aliases() {
        let o: HdrOptions = serde_json::from_str(r#"{"i_c": 0.01, "resample": false}"#).unwrap();
        assert_eq!(o.params.i_c_dps, 0.01);
        assert_eq!(o.params.tau_s, 0.75);
        assert!(!o.resample);
        let o: HdrOptions = serde_json::from_str(r#"{"tau_s": 1.5}"#).unwrap();
        assert_eq!(o.params.tau_s, 1.5);
        assert!(serde_json::from_str::<HdrOptions>(r#"{"tau_s": "x"}"#).is_err());
    }
}
#[cfg(test)]
mod serde_options {
    #[test]
    fn unknown_option_is_rejected() {
        let e = serde_json::from_str::<super::HdrOptions>(r#"{"taus": 1.0}"#).unwrap_err();
        assert!(e.to_string().contains("unknown field `taus`"), "{e}");
    }
}
