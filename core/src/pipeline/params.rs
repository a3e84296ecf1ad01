//! Settings of the recommended drift reducer, with units in every name. The values are
//! set by rule (docs/pipeline.md says which rule), not fitted to a table.

use crate::error::{Error, Result};
use crate::still::StillOptions;
use serde::{Deserialize, Serialize};

/// Bias-dynamics hypotheses (log-spaced bias walks) ...
pub const N_WALKS: usize = 5;
/// ... times road hypotheses (road rate sigma / spread, x 1, x spread) ...
pub const N_ROADS: usize = 3;
/// ... times warm-up hypotheses (none, and a decaying term with each of two time constants)
pub const N_WARMS: usize = 3;
/// ... = the filter bank.
pub const N_MODELS: usize = N_WALKS * N_ROADS * N_WARMS;

/// Settings of the pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PipelineParams {
    pub still: StillOptions,
    /// Stop blocks count only this far from both ends of a stop (braking, GPS speed lag,
    /// pulling away into a turn), s. Delays the stop evidence by this much.
    pub min_still_s: f64,
    /// Noise of one 1 s stop block as a measurement of the bias (idle vibration), deg/s.
    /// The gyro's own, measured at standstill, replaces it where larger in the steadiness
    /// tests and the weights, not in the update (`noise.rs`).
    pub stop_sigma_dps: f64,
    /// A stop block whose rate is further than this from the turn-on bias (the lead-in's; 0
    /// without one) is not standing (a slow turn with the GPS speed held at zero), deg/s.
    /// Also the widest bias change the filter will accept.
    pub max_bias_dps: f64,
    /// A steady stop this long that disagrees with the bias estimate means the bias has
    /// moved (a step, a re-calibration): the filter re-opens its uncertainty, s.
    pub jump_min_s: f64,
    /// Yaw rate of "straight" road (curvature, sway): standard deviation of the road-rate
    /// state, deg/s.
    pub road_sigma_dps: f64,
    /// The bank also tries road_sigma_dps divided and multiplied by this (>= 1; 1 = one road).
    pub road_sigma_spread: f64,
    /// Its correlation time (Gauss-Markov), s.
    pub road_corr_s: f64,
    /// White noise of one straight block on top of it, deg/s.
    pub block_sigma_dps: f64,
    /// Window of moving blocks whose dominant rate (half-sample mode) marks straight
    /// driving, s.
    pub road_window_s: f64,
    /// A moving block within this of the window's dominant rate is straight, deg/s.
    pub road_gate_dps: f64,
    /// Slowest and fastest bias random walk of the filter bank, deg/s per sqrt(s).
    pub bias_walk_min_dps_per_sqrt_s: f64,
    pub bias_walk_max_dps_per_sqrt_s: f64,
    /// Warm-up term: prior size of a bias part that decays after power-on, deg/s (after a
    /// declared lead-in, at most this: it is sized by the turn-on bias the lead-in shows),
    /// and the two decay times the bank tries, s.
    pub warm_sigma_dps: f64,
    pub warm_tau_short_s: f64,
    pub warm_tau_long_s: f64,
    /// Uncertainty of the bias at the start, before any evidence (a lead-in's or a stop's),
    /// deg/s. By rule half of `max_bias_dps`, so any turn-on bias the filter accepts is
    /// plausible from the first block (0.5 before: a 1.5-3 deg/s bias without a lead-in
    /// was then learned too slowly, and trusted too little once learned).
    pub prior_bias_sigma_dps: f64,
    /// Innovations beyond this many sigma count linearly, not quadratically, in the
    /// hypotheses' log likelihood (Huber's k; infinite = Gaussian). 3 by convention.
    pub huber_k: f64,
    /// Hypothesis weights forget with this time constant, so the bank can switch, s.
    pub forget_s: f64,
    /// The heading moves by the mean of the bank's move and those of Table-III HDR and
    /// Fusion's offset over each block where the bias an expert implies differs from the
    /// bank's by less than this many of the bank's bias sigma (`blend.rs`); 0 = the bank's
    /// alone. 2 by convention (95 %). `hdr_blend_sigmas` (HDR alone, before) is its alias.
    #[serde(alias = "hdr_blend_sigmas")]
    pub blend_sigmas: f64,
    /// Between stops the guard's sigma grows as a bias walk of this since the last stop block
    /// (or the experts' start): there the bank knows its bias from the road alone, whose
    /// curvature it models as white over `road_corr_s` while real roads meander for minutes,
    /// so its sigma is too narrow for the guard to take on faith (`blend.rs`), deg/s per
    /// sqrt(s); 0 = the bank's sigma alone. Chosen on the training cases among the bank's
    /// three fastest walks (0.001, 0.003, 0.01; docs/pipeline.md).
    pub blend_walk_dps_per_sqrt_s: f64,
    /// Once the experts have started, while the bank's settled bias (the bias less its
    /// warm-up term) is further than this from where the last stop (or the experts' start)
    /// left it, the heading moves by Table-III HDR's move alone: a settled bias that the road
    /// alone moves that far is long bends read as straight road (`blend.rs`, `fallback.rs`),
    /// deg/s; 0 = never (after a lead-in on a quiet gyro, `blend_move_quiet_dps` instead).
    /// Without a stationary lead-in a move that outlasts `road_window_s` is
    /// taken as the gyro's until the next stop, unless it is coming back faster than the
    /// bank's fastest walk over half that window (a bend leaving it). Chosen on the training
    /// cases and the independent generator's draw 0 (docs/pipeline.md).
    pub blend_move_dps: f64,
    /// The same threshold after a stationary lead-in on a quiet gyro (its standstill noise,
    /// as `noise.rs` measures it, within `stop_sigma_dps`): there the settled bias is known
    /// from the lead-in and steady, and a move of one straight-road gate (`road_gate_dps`'s
    /// 0.15) is already a bend read as road; a noisy gyro keeps `blend_move_dps`, its settled
    /// bias jittering and HDR, which the fallback follows, spoiled by its noise. deg/s; 0 =
    /// `blend_move_dps` here too. Chosen on the training populations (fifty-seventh
    /// session, docs/pipeline.md).
    pub blend_move_quiet_dps: f64,
    /// Static-bias window (stationary lead-in), s; None = the log's `# bias_s:` or 20 s.
    pub bias_s: Option<f64>,
}

impl Default for PipelineParams {
    fn default() -> Self {
        PipelineParams {
            still: StillOptions::default(),
            min_still_s: 1.0,
            stop_sigma_dps: 0.05,
            max_bias_dps: 5.0,
            jump_min_s: 3.0,
            road_sigma_dps: 0.3,
            road_sigma_spread: 5.0,
            road_corr_s: 10.0,
            block_sigma_dps: 0.05,
            road_window_s: 60.0,
            road_gate_dps: 0.15,
            bias_walk_min_dps_per_sqrt_s: 1e-4,
            bias_walk_max_dps_per_sqrt_s: 1e-2,
            warm_sigma_dps: 0.3,
            warm_tau_short_s: 200.0,
            warm_tau_long_s: 800.0,
            prior_bias_sigma_dps: 2.5,
            huber_k: 3.0,
            forget_s: 600.0,
            blend_sigmas: 2.0,
            blend_walk_dps_per_sqrt_s: 0.003,
            blend_move_dps: 0.3,
            blend_move_quiet_dps: 0.15,
            bias_s: None,
        }
    }
}

impl crate::options::Settings for PipelineParams {
    fn validate(&self) -> Result<()> {
        PipelineParams::validate(self)
    }
}

impl PipelineParams {
    /// The bias walks of the bank, log-spaced from the slowest to the fastest.
    pub fn bias_walks_dps_per_sqrt_s(&self) -> [f64; N_WALKS] {
        let (lo, hi) = (self.bias_walk_min_dps_per_sqrt_s, self.bias_walk_max_dps_per_sqrt_s);
        std::array::from_fn(|i| if lo == hi { lo } else { lo * libm::pow(hi / lo, i as f64 / (N_WALKS - 1) as f64) })
    }

    /// The warm-up decay times of the bank: none (infinite), then the two settings.
    pub fn warm_taus_s(&self) -> [f64; N_WARMS] {
        [f64::INFINITY, self.warm_tau_short_s, self.warm_tau_long_s]
    }

    /// The road-rate sigmas of the bank: road_sigma_dps divided and multiplied by the spread.
    pub fn road_sigmas_dps(&self) -> [f64; N_ROADS] {
        let (r, k) = (self.road_sigma_dps, self.road_sigma_spread);
        [r / k, r, r * k]
    }

    /// Hypothesis `i` of the bank: its bias walk (deg/s per sqrt(s)), road sigma (deg/s) and
    /// warm-up decay time (s, infinite = none), walk-major as the bank orders them.
    pub fn hypothesis(&self, i: usize) -> (f64, f64, f64) {
        let (walks, roads, warms) = (self.bias_walks_dps_per_sqrt_s(), self.road_sigmas_dps(), self.warm_taus_s());
        (walks[i / (N_ROADS * N_WARMS)], roads[(i / N_WARMS) % N_ROADS], warms[i % N_WARMS])
    }

    /// Whether the bank keeps the hypothesis pairing this bias walk with this road: one whose
    /// bias walks, over one road correlation time, by more than half its road's spread
    /// cannot tell its bias from its road and chases the road's curves (docs/pipeline.md).
    /// With the defaults it drops the fastest walk with the narrowest road only.
    pub fn identifiable(&self, walk_dps_per_sqrt_s: f64, road_sigma_dps: f64) -> bool {
        walk_dps_per_sqrt_s * libm::sqrt(self.road_corr_s) <= 0.5 * road_sigma_dps
    }

    /// A bias projected onto the turn-on bias `centre_dps` +- max_bias_dps, the widest the
    /// filter accepts (causal, smoothed and held alike). `max` / `min`: `f64::clamp` links a
    /// panic message (BENCHMARKS.md).
    pub fn bounded_bias_dps(&self, b: f64, centre_dps: f64) -> f64 {
        b.max(centre_dps - self.max_bias_dps).min(centre_dps + self.max_bias_dps)
    }

    /// Every setting finite and in range.
    pub fn validate(&self) -> Result<()> {
        let pos = [
            ("still_speed_mps", self.still.still_speed_mps),
            ("still_travel_m", self.still.still_travel_m),
            ("still_gyro_factor", self.still.still_gyro_factor),
            ("still_agree_factor", self.still.still_agree_factor),
            ("stop_sigma_dps", self.stop_sigma_dps),
            ("max_bias_dps", self.max_bias_dps),
            ("road_sigma_dps", self.road_sigma_dps),
            ("road_corr_s", self.road_corr_s),
            ("block_sigma_dps", self.block_sigma_dps),
            ("road_window_s", self.road_window_s),
            ("road_gate_dps", self.road_gate_dps),
            ("bias_walk_min_dps_per_sqrt_s", self.bias_walk_min_dps_per_sqrt_s),
            ("bias_walk_max_dps_per_sqrt_s", self.bias_walk_max_dps_per_sqrt_s),
            ("prior_bias_sigma_dps", self.prior_bias_sigma_dps),
            ("warm_sigma_dps", self.warm_sigma_dps),
            ("warm_tau_short_s", self.warm_tau_short_s),
            ("warm_tau_long_s", self.warm_tau_long_s),
            ("forget_s", self.forget_s),
        ];
        for (name, v) in pos {
            if !(v.is_finite() && v > 0.0 && v < 1e6) {
                return Err(Error::param(name, format!("{v} is not a number in (0, 1e6)")));
            }
        }
        if !(self.huber_k > 0.0) {
            return Err(Error::param("huber_k", format!("{} is not a positive number of sigma", self.huber_k)));
        }
        let non_negative = [
            ("min_still_s", self.min_still_s),
            ("jump_min_s", self.jump_min_s),
            ("blend_sigmas", self.blend_sigmas),
            ("blend_walk_dps_per_sqrt_s", self.blend_walk_dps_per_sqrt_s),
            ("blend_move_dps", self.blend_move_dps),
            ("blend_move_quiet_dps", self.blend_move_quiet_dps),
        ];
        for (name, v) in non_negative {
            if !(0.0..1e6).contains(&v) {
                return Err(Error::param(name, format!("{v} is not a number in [0, 1e6)")));
            }
        }
        if !(self.road_sigma_spread >= 1.0 && self.road_sigma_spread <= 100.0) {
            return Err(Error::param("road_sigma_spread", format!("{} is not in [1, 100]", self.road_sigma_spread)));
        }
        if self.bias_walk_min_dps_per_sqrt_s > self.bias_walk_max_dps_per_sqrt_s {
            return Err(Error::param("bias_walk_min_dps_per_sqrt_s", "is above bias_walk_max_dps_per_sqrt_s"));
        }
        crate::options::check_bias_s(self.bias_s)
    }
}
