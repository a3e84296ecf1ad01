//! The causal estimator: a bank of small Kalman filters, one per bias-dynamics hypothesis
//! (random walks, warm-up terms, road rates: `model.rs`), weighed by how well each predicted
//! the evidence. State x = [b_inf, d, c]: the settled bias, a decaying warm-up term, and the
//! yaw rate of the "straight" road (curvature and sway, a Gauss-Markov process with the
//! road's correlation time), so consecutive
//! straight blocks are not counted as independent and the innovations stay white under a
//! right hypothesis (which is what lets them weigh the hypotheses). No evidence is gated by
//! closeness to the current estimate, so a large unknown bias cannot lock it out
//! (`evidence.rs`):
//!
//! - stop blocks (judged by speed, wheels or the gyro's own spread; trimmed at both ends;
//!   plausible, and steady within the stop): rate = b;
//! - moving blocks near the dominant rate of the recent drive (its half-sample mode, i.e.
//!   "straight", HDR's heuristic): rate = b + c.
//!
//! A guard re-opens the bias uncertainty when a steady stop disagrees with the estimate
//! beyond its uncertainty (a bias step, an OS re-calibration).
//!
//! Each hypothesis also carries the integral of its bias and that integral's covariance
//! with the state, so a stop corrects the heading accumulated since the last good evidence
//! (the causal E[heading | evidence so far], as a zero-velocity update corrects an INS);
//! straight-road evidence corrects only the bias from then on (letting it rewrite the past
//! amplified its errors on good gyros: docs/pipeline.md).
//!
//! The heading's corrections and sigma: `filter/heading.rs`; the warm-up prior sized by the
//! lead-in: `filter/warm.rs`.

use super::evidence::Evidence;
use super::model::{log_likelihood, warm_decay, Model, State, H_ROAD, H_STOP};
use super::params::{PipelineParams, N_MODELS};
use super::records::Records;
use super::smoother;
use crate::error::{Error, Result};
use crate::line::LineSums;
use nalgebra::{Matrix3, Vector3};
use std::borrow::Cow;

mod heading;
mod warm;

/// What one block did.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[cfg_attr(feature = "snapshot", derive(serde::Deserialize))]
pub struct PipelineOutput {
    /// Heading from (rate - bias) integrated with the bias known before each block, and
    /// corrected at stops by what the stop says about the bias since (causal), deg.
    pub heading_deg: f64,
    /// Bias estimate used for this block (before its own evidence), deg/s.
    pub bias_dps: f64,
    /// Its standard deviation, deg/s.
    pub bias_sigma_dps: f64,
    /// The heading's standard deviation from the bias alone (deg): each hypothesis'
    /// uncertainty about the integral of the bias since the start, and its distance from the
    /// integral the heading has taken off, mixed with the weights. Not the gyro's noise, its
    /// scale error, or a bias the model does not describe.
    pub heading_sigma_deg: f64,
    /// The block brought stop evidence (possibly of an earlier, delayed stop block).
    pub stop: bool,
    /// The block was straight-road evidence.
    pub straight: bool,
    /// A guard re-opened the bias uncertainty at this block.
    pub reopened: bool,
}

/// The streaming drift reducer on 1 Hz blocks.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone)]
pub struct Pipeline {
    p: PipelineParams,
    models: Vec<Model>,
    last_time_s: Option<f64>,
    lead_in_end_s: f64,
    heading_deg: f64,
    /// The raw rate integrated (deg): less the heading, the bias integral the heading took off.
    rate_integral_deg: f64,
    evidence: Evidence,
    /// This stop's evidence so far as one change: the bias change, the walk model's integral
    /// correction, and the heading correction applied (deg/s, deg, deg).
    stop_change: (f64, f64, f64),
    /// Hypotheses whose blocks are recorded for the smoother, and their records with the
    /// block's weights (`records.rs`).
    recorded: Vec<usize>,
    records: Records,
    /// Sum of each hypothesis' weight over the blocks (to pick the ones to smooth).
    weight_sum: Vec<f64>,
    /// Straight blocks since the last stop evidence (time, rate less the bias used), that
    /// evidence's time, and the time of the latest stop evidence (taken over at the next
    /// moving block): what dates a change a stop reveals (`dating`).
    residuals: Vec<(f64, f64)>,
    dating_t0_s: Option<f64>,
    last_stop_s: Option<f64>,
    /// The declared lead-in gave stop evidence, and the warm-up prior has been sized by it.
    lead_in_seen: bool,
    /// The bank has known its bias once: a stop (the lead-in's included), or three sigma
    /// within Table-III HDR's straight threshold. Until then it is acquiring a bias it had no
    /// evidence of, and straight-road evidence also corrects the heading (`update`).
    acquired: bool,
    warm_up_sized: bool,
    /// The lead-in's blocks for the least-squares trend of its rate in time (t from the
    /// declared end), and whether that trend was a warm-up the warm-up prior cannot hold
    /// (`size_warm_up`).
    lead_trend: LineSums,
    warming: bool,
    /// The still flags come from the gyro alone (`Blocks::source`; the stream sets it per
    /// block): see [`Pipeline::update`].
    pub gyro_stills: bool,
    /// Road evidence taken at face value, every block a Gaussian update (the offline
    /// smoother's passes, `smoother.rs`); the causal bank bounds a far block's step.
    #[cfg_attr(feature = "snapshot", serde(skip))]
    pub(super) gaussian_road: bool,
    /// The log weights normalised, kept from the block that last changed them (each block
    /// reads them several times); empty until then, as after a resumed snapshot.
    #[cfg_attr(feature = "snapshot", serde(skip))]
    weights: Vec<f64>,
}

/// Innovations (in standard deviations of a hypothesis' prediction) beyond which a still
/// block judged by the gyro alone does not move that hypothesis: the step guard's 4.
const GYRO_STILL_GATE: f64 = 4.0;

/// Innovations (in standard deviations of a hypothesis' prediction) beyond which a straight
/// block, once the bias is acquired, moves that hypothesis only as far as one at this bound
/// would (`model::bounded_influence_noise`): the same 4.
const ROAD_BOUND_SIGMA: f64 = GYRO_STILL_GATE;

impl Pipeline {
    /// Starts from a bias estimate and its standard deviation; blocks stamped before
    /// `lead_in_end_s` are a declared stationary lead-in (stop evidence, no trimming).
    pub fn new(params: PipelineParams, bias_dps: f64, bias_sigma_dps: f64, lead_in_end_s: f64) -> Result<Self> {
        params.validate()?;
        if !(bias_dps.is_finite() && bias_sigma_dps.is_finite() && bias_sigma_dps > 0.0) {
            return Err(Error::param("prior_bias_sigma_dps", format!("start {bias_dps} +- {bias_sigma_dps} deg/s is not usable")));
        }
        // A hypothesis that cannot tell its bias from its road has no weight, ever (if the
        // settings leave none that can, every one is kept).
        let any = (0..N_MODELS).any(|i| {
            let (w, r, _) = params.hypothesis(i);
            params.identifiable(w, r)
        });
        let models = (0..N_MODELS)
            .map(|i| {
                let (w, r, tau) = params.hypothesis(i);
                let warm_var = if tau.is_finite() { params.warm_sigma_dps * params.warm_sigma_dps } else { 0.0 };
                // The warm-up term is the bias' change from its start value, independent of
                // it: b_inf = b_start - d, so b_inf carries both variances and the covariance
                // -warm_var, and evidence at the start moves b_start alone, not d.
                let mut p = Matrix3::from_diagonal(&Vector3::new(bias_sigma_dps * bias_sigma_dps + warm_var, warm_var, r * r));
                p[(0, 1)] = -warm_var;
                p[(1, 0)] = -warm_var;
                Model {
                    walk2: w * w,
                    road_var: r * r,
                    warm_tau_s: tau,
                    x: Vector3::new(bias_dps, 0.0, 0.0),
                    p,
                    logw: if !any || params.identifiable(w, r) { 0.0 } else { f64::NEG_INFINITY },
                    h: 0.0,
                    p_hx: Vector3::zeros(),
                    p_hh: 0.0,
                }
            })
            .collect();
        let mut bank = Pipeline {
            p: params,
            models,
            last_time_s: None,
            lead_in_end_s,
            heading_deg: 0.0,
            rate_integral_deg: 0.0,
            evidence: Evidence::default(),
            stop_change: (0.0, 0.0, 0.0),
            recorded: Vec::new(),
            records: Records::default(),
            weight_sum: vec![0.0; N_MODELS],
            residuals: Vec::new(),
            dating_t0_s: None,
            last_stop_s: None,
            lead_in_seen: false,
            acquired: false,
            warm_up_sized: false,
            lead_trend: LineSums::default(),
            warming: false,
            gaussian_road: false,
            gyro_stills: false,
            weights: Vec::new(),
        };
        bank.reweigh();
        Ok(bank)
    }

    /// Where the declared stationary lead-in ends (absolute time, s).
    pub fn lead_in_end_s(&self) -> f64 {
        self.lead_in_end_s
    }

    /// Ends the declared stationary lead-in at `time_s` if it was to end later: a block
    /// stamped then or after is not lead-in evidence (the speed showed the vehicle moving).
    pub fn end_lead_in(&mut self, time_s: f64) {
        self.lead_in_end_s = self.lead_in_end_s.min(time_s);
    }

    /// Keeps only these hypotheses (indices into the full bank), for the smoother's second
    /// pass: the bank then weighs and mixes only them.
    pub fn restrict(&mut self, hypotheses: &[usize]) {
        self.models = hypotheses.iter().filter(|&&i| i < self.models.len()).map(|&i| self.models[i]).collect();
        self.weight_sum = vec![0.0; self.models.len()];
        self.recorded.clear();
        self.reweigh();
    }

    /// The whole bank, unrestricted and recording nothing (a live stream's): what a
    /// resumed stream must be (`snapshot`).
    #[cfg(feature = "snapshot")]
    pub(super) fn is_whole_bank(&self) -> bool {
        self.models.len() == N_MODELS && self.weight_sum.len() == N_MODELS && self.recorded.is_empty()
    }

    /// Records these hypotheses' blocks from now on (for `smoothed_bias`), with room for
    /// `blocks` blocks reserved at once (`records.rs`).
    pub fn record(&mut self, hypotheses: Vec<usize>, blocks: usize) {
        self.recorded = hypotheses.into_iter().filter(|&i| i < self.models.len()).collect();
        self.records = Records::new(self.recorded.iter().map(|&i| self.models[i]).collect(), self.p.road_corr_s, blocks);
    }

    /// The turn-on bias, the centre of the biases the filter accepts: the lead-in's, or a
    /// long standing's beyond the bounds where there was no lead-in (0 before), deg/s.
    pub fn centre_dps(&self) -> f64 {
        self.evidence.centre_dps
    }

    /// Each hypothesis' weight summed over the blocks so far.
    pub fn weight_sums(&self) -> &[f64] {
        &self.weight_sum
    }

    /// Rauch-Tung-Striebel smoothing of the recorded hypotheses, mixed with their weights
    /// (renormalised among them) at each block: the smoothed bias per recorded block.
    pub fn smoothed_bias(&self) -> Vec<f64> {
        smoother::rts_mixed(&self.records, &self.p, self.evidence.centre_dps)
    }

    /// Whether the gyro is quiet: its standstill noise as measured so far (`noise.rs`) within
    /// the stop's setting `stop_sigma_dps` (the blend's fallback threshold, `fallback.rs`).
    pub fn quiet(&self) -> bool {
        self.evidence.stop_sigma_dps(&self.p) <= self.p.stop_sigma_dps
    }

    /// Normalised hypothesis weights.
    pub fn weights(&self) -> Vec<f64> {
        self.current_weights().into_owned()
    }

    /// The normalised weights: those kept if current, else computed from the log weights.
    fn current_weights(&self) -> Cow<'_, [f64]> {
        if self.weights.len() == self.models.len() {
            Cow::Borrowed(&self.weights)
        } else {
            Cow::Owned(self.normalised_weights())
        }
    }

    /// The log weights normalised, computed.
    fn normalised_weights(&self) -> Vec<f64> {
        let m = self.models.iter().map(|m| m.logw).fold(f64::NEG_INFINITY, f64::max);
        let e: Vec<f64> = self.models.iter().map(|x| libm::exp(x.logw - m)).collect();
        let s: f64 = e.iter().sum();
        e.into_iter().map(|v| v / s).collect()
    }

    /// Keeps the normalised weights of the log weights as they now are (after any change).
    fn reweigh(&mut self) {
        self.weights = self.normalised_weights();
    }

    /// The bank's bias estimate and variance (moment-matched mixture), the estimate projected
    /// onto the widest bias the filter accepts: a warm-up term fitted to a fast change can
    /// extrapolate beyond any evidence (10 deg/s from stops of at most 5, found by the
    /// property test), which no gyro it accepts has.
    pub fn bias(&self) -> (f64, f64) {
        let w = self.current_weights();
        let b: f64 = self.models.iter().zip(w.iter()).map(|(m, wi)| wi * m.bias().0).sum();
        let p: f64 = self.models.iter().zip(w.iter()).map(|(m, wi)| wi * (m.bias().1 + (m.bias().0 - b).powi(2))).sum();
        (self.p.bounded_bias_dps(b, self.evidence.centre_dps), p)
    }

    /// The settled bias, `b_inf` mixed with the weights: the bias less its warm-up term, so
    /// a warm-up the bank models does not move it (deg/s). The blend's fallback watches it
    /// before each block (`blend.rs`).
    /// Not a number (no fallback) after a lead-in that showed a warm-up beyond the prior.
    pub fn settled_bias_dps(&self) -> f64 {
        if self.warming {
            return f64::NAN;
        }
        self.models.iter().zip(self.current_weights().iter()).map(|(m, wi)| wi * m.x[0]).sum()
    }

    /// One block: its end time, mean raw rate, and whether the vehicle stood. With
    /// `gyro_stills` (no speed, no wheels: the gyro's noise judged the standing) a steady
    /// turn can pass for a standing, so after the declared lead-in a still block moves only
    /// the hypotheses it is plausible for (within 4 sigma of their prediction) and the step
    /// guard does not re-open any: such a block cannot show a step that a standing judged by
    /// speed would (on a simulated drive with 10 % of its rows dropped, a 2.4 deg/s curve
    /// passed as two still blocks and took the bias from -0.26 to 1.94 deg/s). The road's
    /// dominant rate, never gated, still acquires any bias.
    pub fn update(&mut self, time_s: f64, rate_dps: f64, still: bool) -> Result<PipelineOutput> {
        if !(time_s.is_finite() && rate_dps.is_finite()) || self.last_time_s.is_some_and(|t| !(time_s > t)) {
            return Err(Error::data(format!("pipeline update at {time_s} s: rate {rate_dps} deg/s, time must be finite and increase")));
        }
        let dt = self.last_time_s.map_or(0.0, |t| time_s - t);
        self.last_time_s = Some(time_s);
        let sized = time_s >= self.lead_in_end_s && self.lead_in_seen && !self.warm_up_sized;
        if sized {
            self.size_warm_up();
        }
        let (b_before, p_before) = self.bias();
        self.heading_deg += (rate_dps - b_before) * dt;
        self.rate_integral_deg += rate_dps * dt;
        // Predict: each hypothesis' random walk and the road rate; weights forget toward equal.
        let lam = libm::exp(-dt / self.p.forget_s);
        let a = libm::exp(-dt / self.p.road_corr_s);
        // The bank holds a few warm-up times: each one's decay computed once per block.
        let decays = self.p.warm_taus_s().map(|tau| (tau, warm_decay(tau, dt)));
        for m in self.models.iter_mut() {
            let decay = decays.iter().find(|d| d.0 == m.warm_tau_s).map_or_else(|| warm_decay(m.warm_tau_s, dt), |d| d.1);
            m.predict_with(dt, Vector3::new(1.0, decay, a));
            if m.logw.is_finite() {
                m.logw *= lam;
            }
        }
        // Gather this block's evidence, then the guards, then the updates.
        let lead_in = time_s < self.lead_in_end_s;
        let stops = self.evidence.stops(&self.p, time_s, rate_dps, still, lead_in);
        self.lead_in_seen |= lead_in && !stops.is_empty();
        if lead_in {
            self.lead_trend.add(time_s - self.lead_in_end_s, rate_dps);
        }
        let reopened = !stops.is_empty() && !self.evidence.stop.reopened && !lead_in && !self.gyro_stills && self.stop_guard();
        let straight = !still && !lead_in && self.evidence.is_straight(&self.p, time_s, rate_dps);
        self.dating_t0_s.get_or_insert(time_s);
        if !still {
            if let Some(t) = self.last_stop_s.take() {
                self.residuals.clear();
                self.dating_t0_s = Some(t);
                self.stop_change = (0.0, 0.0, 0.0);
            }
        }
        if straight {
            self.residuals.push((time_s, rate_dps - b_before));
        }
        let priors: Vec<State> = self.recorded.iter().map(|&i| (self.models[i].x, self.models[i].p)).collect();
        let h_before = if stops.is_empty() { Vec::new() } else { self.integrals() };
        for &z in &stops {
            self.stop_update(z, !lead_in, self.gyro_stills && !lead_in);
        }
        // While the bank acquires a bias it had no evidence of (no lead-in, no stop yet), the
        // road that shows the bias also shows what it cost the heading, through the same
        // covariance a stop corrects it by; once known, road evidence no longer rewrites the
        // past (a curve read as straight would: docs/pipeline.md).
        self.acquired |= !stops.is_empty() || super::blend::within_hdr_reach(p_before.sqrt());
        let h_road = if straight && !self.acquired { self.integrals() } else { Vec::new() };
        if straight {
            self.road_update(rate_dps, !self.acquired);
        }
        self.reweigh();
        let w = self.weights.clone();
        if !h_road.is_empty() {
            self.heading_deg -= self.integral_change(&h_road, &w);
        }
        self.keep_records(dt, sized || reopened, &priors, &w);
        if !stops.is_empty() {
            self.correct_heading_at_stop(&h_before, &w, b_before, time_s);
        }
        let out = PipelineOutput {
            heading_deg: self.heading_deg,
            bias_dps: b_before,
            bias_sigma_dps: p_before.sqrt(),
            heading_sigma_deg: self.heading_variance(&w).sqrt(),
            stop: !stops.is_empty(),
            straight,
            reopened,
        };
        Ok(out)
    }

    /// A steady stop that a hypothesis cannot explain: for it the bias moved, re-open its
    /// uncertainty. Judged per hypothesis: the bank's mixed variance grows with their spread,
    /// so a step that the slow hypotheses miss and the fast ones follow would hide from it.
    fn stop_guard(&mut self) -> bool {
        let s = self.evidence.stop;
        let r = self.p.stop_sigma_dps * self.p.stop_sigma_dps;
        let steady = s.std() <= 3.0 * self.evidence.stop_sigma_dps(&self.p);
        let long = s.last_s - s.first_s >= self.p.jump_min_s;
        if !(steady && long) {
            return false;
        }
        let mut reopened = false;
        for m in self.models.iter_mut().filter(|m| m.logw.is_finite()) {
            let (b, p) = m.bias();
            if (s.mean - b).abs() > 4.0 * (p + r / s.n as f64).sqrt() {
                m.p[(0, 0)] += (s.mean - b).powi(2);
                reopened = true;
            }
        }
        self.evidence.stop.reopened = reopened;
        reopened
    }

    /// The block's weights added to each hypothesis' sum, and the recorded hypotheses'
    /// prior and posterior kept for the smoother (`records.rs`): the priors are the
    /// posteriors before predicted, but where the block sized the warm-up or re-opened the
    /// bias (`restarted`).
    fn keep_records(&mut self, dt: f64, restarted: bool, priors: &[State], w: &[f64]) {
        for (s, wi) in self.weight_sum.iter_mut().zip(w) {
            *s += wi;
        }
        if !self.recorded.is_empty() {
            self.records.start_block(dt, restarted);
            for (j, &i) in self.recorded.iter().enumerate() {
                self.records.push(j, priors[j], (self.models[i].x, self.models[i].p), w[i]);
            }
        }
    }

    /// Stop evidence (rate = b). Its likelihood weighs the hypotheses; `weigh` = false for
    /// the declared lead-in (before any hypothesis could differ). `gate`: a hypothesis the
    /// evidence is beyond [`GYRO_STILL_GATE`] sigma of is weighed but not moved.
    /// The update takes the setting's noise; the weights take the gyro's own where larger
    /// (`noise.rs`): a noisy gyro's stop blocks judged by the setting's look like a moving
    /// bias and hand the bank to its fast walks.
    fn stop_update(&mut self, z: f64, weigh: bool, gate: bool) {
        let r = self.p.stop_sigma_dps * self.p.stop_sigma_dps;
        let widen = self.evidence.stop_sigma_dps(&self.p).powi(2) - r;
        for m in &mut self.models {
            let (b, p) = m.bias();
            let (nu, s) =
                if gate && (z - b).abs() > GYRO_STILL_GATE * (p + r).sqrt() { (z - b, p + r) } else { m.update(H_STOP, z, r, true) };
            let ll = log_likelihood(nu, s + widen, self.p.huber_k);
            if weigh {
                m.logw += ll;
            }
        }
    }

    /// Straight-road evidence (rate = b + c, block noise on top); weighs the hypotheses.
    /// `correct_integral`: it also corrects the bias integrals (while acquiring, `update`).
    /// Once the bias is acquired, a block beyond [`ROAD_BOUND_SIGMA`] of a hypothesis'
    /// prediction moves it only as far as a block at that bound would: a bend that fills
    /// the road window is read as straight for a few blocks, tens of sigma off, and each of
    /// them moved a narrow-road hypothesis' bias by 0.1-0.3 deg/s (docs/pipeline.md). While
    /// acquiring, every block counts in full, as it must to learn a bias it had no evidence of.
    fn road_update(&mut self, rate_dps: f64, correct_integral: bool) {
        let r = self.p.block_sigma_dps * self.p.block_sigma_dps;
        let bound_sigma = if correct_integral || self.gaussian_road { f64::INFINITY } else { ROAD_BOUND_SIGMA };
        for m in &mut self.models {
            let (nu, s) = m.update_bounded(H_ROAD, rate_dps, r, bound_sigma, correct_integral);
            m.logw += log_likelihood(nu, s, self.p.huber_k);
        }
    }
}
