//! Heuristic Drift Reduction (Borenstein & Ojeda, seed 000, enhanced algorithm Eqs. 7-14)
//! as a streaming estimator, read exactly as methods.md fixes it. The batch `run` is the
//! same `update` in a loop, plus the raw baseline and the metrics.

use crate::error::{Error, Result};
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

#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
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
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone)]
pub struct Hdr {
    params: HdrParams,
    eps0_dps: f64,
    started: bool,
    s: HdrState,
    /// R(r) for r = 0, 1, 2, ... computed with `powf` once each (bit-identical to Eq. 10;
    /// `powf` per sample would cost ~30 ns, more than the rest of the step). Not saved:
    /// the settings give it, and a resumed estimator tables it afresh.
    #[cfg_attr(feature = "snapshot", serde(skip))]
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

    /// `update_slice` keeping the headings (appended to `headings`) and the last output (in
    /// `last`). Not generic, so bindings call a loop compiled with core's optimisation.
    pub fn update_slice_headings(
        &mut self,
        time_s: &[f64],
        rate_raw_dps: &[f64],
        headings: &mut Vec<f64>,
        last: &mut Option<HdrOutput>,
    ) -> Result<()> {
        headings.reserve(time_s.len());
        self.update_slice(time_s, rate_raw_dps, |o| {
            headings.push(o.heading_deg);
            *last = Some(*o);
        })
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

mod batch;
pub use batch::*;

/// A live HDR estimator and its last output, saved and resumed (`snapshot`): the settings
/// checked as a new estimator's, the R(r) table made afresh.
#[cfg(feature = "snapshot")]
impl crate::snapshot::Resumable for (Hdr, Option<HdrOutput>) {
    const KIND: &'static str = "HdrEstimator";
    fn restored(self) -> Result<Self> {
        let (saved, last) = self;
        let fresh = Hdr::new(saved.params, saved.eps0_dps)?;
        Ok((Hdr { started: saved.started, s: saved.s, ..fresh }, last))
    }
}
#[cfg(test)]
mod tests;
