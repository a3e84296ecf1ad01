//! The drift-reduction pipeline that goes beyond the paper: one Kalman filter on the gyro
//! bias (and, with temp_c, its temperature coefficient) fed by two kinds of evidence:
//!
//! - at stops the true rate is zero (zero angular rate update): strong evidence, and the
//!   heading is held while standing;
//! - while driving straight (|rate - bias| < gate) the true rate is probably near zero,
//!   HDR's heuristic, but taken as weak evidence: road curvature is measurement noise.
//!
//! The gain of the straight-driving evidence follows the bias uncertainty, which grows as a
//! random walk between observations: after a stop, or on a gyro whose lead-in pins the bias,
//! the heuristic barely moves it (a good gyro is not made worse); on long stretches without
//! stops it takes over as HDR does. It runs on the paper's 1 Hz blocks. The parameters are
//! fixed by rule (docs/pipeline.md), not tuned to a log.

use crate::error::{Error, Result};
use crate::log::DriveLog;
use crate::metrics::{self, Reference};
use crate::still::{self, Blocks, StillOptions, StillSource};
use serde::{Deserialize, Serialize};

/// Settings of the pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PipelineParams {
    pub still: StillOptions,
    /// A block counts as a stop once the vehicle has stood this long (braking and GPS
    /// speed lag excluded), s.
    pub min_still_s: f64,
    /// A flagged block counts as standing only if its rate is within this of the bias:
    /// GPS receivers hold their position at low speed, so speed alone flags slow turns, deg/s.
    pub still_rate_dps: f64,
    /// Noise of one 1 s stop block as a bias measurement, deg/s.
    pub stop_sigma_dps: f64,
    /// Straight-driving gate on |block rate - bias|, deg/s (HDR's theta_w role).
    pub gate_dps: f64,
    /// Road curvature seen as noise of one straight-driving block, deg/s.
    pub road_sigma_dps: f64,
    /// Bias random walk, deg/s per sqrt(s): how fast the bias may wander.
    pub bias_walk_dps_per_sqrt_s: f64,
    /// Bias uncertainty at the start when the log has no stationary lead-in, deg/s.
    pub prior_bias_sigma_dps: f64,
    /// Prior uncertainty of the bias temperature coefficient, deg/s per deg C (0 = no
    /// temperature term).
    pub temp_coeff_sigma_dps_per_c: f64,
    /// Static-bias window, s; None = the log's `# bias_s:` or 20 s.
    pub bias_s: Option<f64>,
}

impl Default for PipelineParams {
    fn default() -> Self {
        PipelineParams {
            still: StillOptions::default(),
            min_still_s: 2.0,
            still_rate_dps: 0.5,
            stop_sigma_dps: 0.02,
            gate_dps: 0.564,
            road_sigma_dps: 0.1,
            bias_walk_dps_per_sqrt_s: 0.002,
            prior_bias_sigma_dps: 0.2,
            temp_coeff_sigma_dps_per_c: 0.02,
            bias_s: None,
        }
    }
}

impl PipelineParams {
    /// Every setting finite and in range.
    pub fn validate(&self) -> Result<()> {
        let pos = [
            ("still_speed_mps", self.still.still_speed_mps),
            ("still_travel_m", self.still.still_travel_m),
            ("still_gyro_factor", self.still.still_gyro_factor),
            ("stop_sigma_dps", self.stop_sigma_dps),
            ("road_sigma_dps", self.road_sigma_dps),
            ("prior_bias_sigma_dps", self.prior_bias_sigma_dps),
        ];
        for (name, v) in pos {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::param(name, format!("{v} is not a number > 0")));
            }
        }
        let nonneg = [
            ("min_still_s", self.min_still_s),
            ("gate_dps", self.gate_dps),
            ("still_rate_dps", self.still_rate_dps),
            ("bias_walk_dps_per_sqrt_s", self.bias_walk_dps_per_sqrt_s),

            ("temp_coeff_sigma_dps_per_c", self.temp_coeff_sigma_dps_per_c),
        ];
        for (name, v) in nonneg {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::param(name, format!("{v} is not a number >= 0")));
            }
        }
        if let Some(b) = self.bias_s {
            if !(b.is_finite() && b >= 0.0) {
                return Err(Error::param("bias_s", format!("{b} is not a time >= 0 s")));
            }
        }
        Ok(())
    }

    /// Sets a setting by name (the field names; CLI `--set`).
    pub fn set(&mut self, key: &str, value: f64) -> Result<()> {
        match key {
            "still_speed_mps" => self.still.still_speed_mps = value,
            "still_travel_m" => self.still.still_travel_m = value,
            "still_gyro_factor" => self.still.still_gyro_factor = value,
            "min_still_s" => self.min_still_s = value,
            "still_rate_dps" => self.still_rate_dps = value,
            "stop_sigma_dps" => self.stop_sigma_dps = value,
            "gate_dps" => self.gate_dps = value,
            "road_sigma_dps" => self.road_sigma_dps = value,
            "bias_walk_dps_per_sqrt_s" => self.bias_walk_dps_per_sqrt_s = value,

            "prior_bias_sigma_dps" => self.prior_bias_sigma_dps = value,
            "temp_coeff_sigma_dps_per_c" => self.temp_coeff_sigma_dps_per_c = value,
            "bias_s" => self.bias_s = Some(value),
            _ => {
                return Err(Error::param(
                    key,
                    "unknown key (still_speed_mps, still_travel_m, still_gyro_factor, min_still_s, still_rate_dps, stop_sigma_dps, gate_dps, road_sigma_dps, bias_walk_dps_per_sqrt_s, prior_bias_sigma_dps, temp_coeff_sigma_dps_per_c, bias_s)",
                ))
            }
        }
        self.validate()
    }
}

/// What one block did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PipelineOutput {
    pub heading_deg: f64,
    /// Bias estimate used for this block (before its own update), deg/s.
    pub bias_dps: f64,
    /// Its standard deviation, deg/s.
    pub bias_sigma_dps: f64,
    /// The block was a stop (zero angular rate update, heading held).
    pub stop: bool,
    /// The block updated the bias as straight driving.
    pub straight: bool,
}

/// The streaming pipeline: state x = [bias b, temperature coefficient k] with covariance P;
/// the bias at temperature T is b + k (T - T_ref).
#[derive(Debug, Clone)]
pub struct Pipeline {
    p: PipelineParams,
    x: [f64; 2],
    cov: [[f64; 2]; 2],
    temp_ref_c: Option<f64>,
    last_time_s: Option<f64>,
    heading_deg: f64,
    still_run_s: f64,
}

impl Pipeline {
    /// Starts from a bias estimate and its standard deviation.
    pub fn new(params: PipelineParams, bias_dps: f64, bias_sigma_dps: f64) -> Result<Self> {
        params.validate()?;
        let k = params.temp_coeff_sigma_dps_per_c;
        Ok(Pipeline {
            p: params,
            x: [bias_dps, 0.0],
            cov: [[bias_sigma_dps * bias_sigma_dps, 0.0], [0.0, k * k]],
            temp_ref_c: None,
            last_time_s: None,
            heading_deg: 0.0,
            still_run_s: 0.0,
        })
    }

    /// One 1 Hz block: its end time, mean raw rate, mean temperature (NaN if none), and
    /// whether the vehicle stood during it.
    pub fn update(&mut self, time_s: f64, rate_dps: f64, temp_c: f64, still: bool) -> Result<PipelineOutput> {
        if !(time_s.is_finite() && rate_dps.is_finite()) || self.last_time_s.is_some_and(|t| !(time_s > t)) {
            return Err(Error::data(format!("pipeline update at {time_s} s: rate {rate_dps} deg/s, time must be finite and increase")));
        }
        let dt = self.last_time_s.map_or(0.0, |t| time_s - t);
        // Predict: the bias wanders as a random walk.
        self.cov[0][0] += self.p.bias_walk_dps_per_sqrt_s * self.p.bias_walk_dps_per_sqrt_s * dt;
        // Measurement row H = [1, T - T_ref].
        let h1 = if temp_c.is_finite() && self.p.temp_coeff_sigma_dps_per_c > 0.0 {
            temp_c - *self.temp_ref_c.get_or_insert(temp_c)
        } else {
            0.0
        };
        let bias = self.x[0] + self.x[1] * h1;
        let var = self.cov[0][0] + 2.0 * h1 * self.cov[0][1] + h1 * h1 * self.cov[1][1];
        let innovation = rate_dps - bias;
        let still = still && innovation.abs() < self.p.still_rate_dps;
        self.still_run_s = if still { self.still_run_s + dt } else { 0.0 };
        let stop = still && self.still_run_s >= self.p.min_still_s;
        // Heading: the corrected rate, held while standing.
        if !still {
            self.heading_deg += (rate_dps - bias) * dt;
        }
        let straight = !still && innovation.abs() < self.p.gate_dps;
        let r = if stop {
            Some(self.p.stop_sigma_dps * self.p.stop_sigma_dps)
        } else if straight {
            Some(self.p.road_sigma_dps * self.p.road_sigma_dps)
        } else {
            None
        };
        if let Some(r) = r {
            let ph = [self.cov[0][0] + self.cov[0][1] * h1, self.cov[1][0] + self.cov[1][1] * h1];
            let s = var + r;
            let gain = [ph[0] / s, ph[1] / s];
            self.x[0] += gain[0] * innovation;
            self.x[1] += gain[1] * innovation;
            let c = self.cov;
            for i in 0..2 {
                for j in 0..2 {
                    // P = P - K (H P)
                    self.cov[i][j] = c[i][j] - gain[i] * ph[j];
                }
            }
        }
        self.last_time_s = Some(time_s);
        Ok(PipelineOutput { heading_deg: self.heading_deg, bias_dps: bias, bias_sigma_dps: var.sqrt(), stop, straight })
    }
}

/// The per-block series of a pipeline run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PipelineTrace {
    pub time_s: Vec<f64>,
    /// Aligned to the reference when the log has one.
    pub heading_deg: Vec<f64>,
    pub bias_dps: Vec<f64>,
    pub bias_sigma_dps: Vec<f64>,
    pub stop: Vec<bool>,
}

/// The bias to start from: the lead-in mean with the uncertainty of a stop of that length,
/// or zero with the prior when there is no lead-in.
pub fn initial_bias(log: &DriveLog, params: &PipelineParams) -> Result<(f64, f64)> {
    let bias_s = log.bias_s(params.bias_s);
    if bias_s == 0.0 {
        return Ok((0.0, params.prior_bias_sigma_dps));
    }
    let gyro = log.require(crate::log::Column::GyroDps, "needed for the yaw rate")?;
    let eps0 = crate::preprocess::static_bias_dps(log.time_s(), gyro, bias_s)?;
    Ok((eps0, params.stop_sigma_dps / bias_s.max(1.0).sqrt()))
}

/// Runs the pipeline over a log's blocks (unaligned heading).
pub fn run_blocks(blocks: &Blocks, params: PipelineParams, bias_dps: f64, bias_sigma_dps: f64) -> Result<PipelineTrace> {
    let mut p = Pipeline::new(params, bias_dps, bias_sigma_dps)?;
    let n = blocks.len();
    let mut tr = PipelineTrace {
        time_s: blocks.time_s.clone(),
        heading_deg: Vec::with_capacity(n),
        bias_dps: Vec::with_capacity(n),
        bias_sigma_dps: Vec::with_capacity(n),
        stop: Vec::with_capacity(n),
    };
    for i in 0..n {
        let o = p.update(blocks.time_s[i], blocks.rate_dps[i], blocks.temp_c[i], blocks.still[i])?;
        tr.heading_deg.push(o.heading_deg);
        tr.bias_dps.push(o.bias_dps);
        tr.bias_sigma_dps.push(o.bias_sigma_dps);
        tr.stop.push(o.stop);
    }
    Ok(tr)
}

/// The pipeline's result keys (issue: E_psi_*, NE_psi_*, improvement_pipeline,
/// duration_min), with the peers and a description of what the pipeline saw.
#[allow(non_snake_case)]
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PipelineResult {
    pub E_psi_raw_deg: f64,
    pub E_psi_hdr_deg: f64,
    pub E_psi_pipeline_deg: f64,
    pub NE_psi_raw_deg_per_min: f64,
    pub NE_psi_hdr_deg_per_min: f64,
    pub NE_psi_pipeline_deg_per_min: f64,
    /// E_psi(raw) / E_psi(pipeline).
    pub improvement_pipeline: f64,
    pub duration_min: f64,
    /// The peers on the same metric: x-io Fusion's gyroscope offset and a plain zero-rate
    /// update at stops.
    pub E_psi_fusion_offset_deg: f64,
    pub E_psi_zaru_deg: f64,
    pub NE_psi_fusion_offset_deg_per_min: f64,
    pub NE_psi_zaru_deg_per_min: f64,
    /// Where the still flags came from: speed, odometry, gyro or none.
    pub still_source: StillSource,
    /// Time counted as stops (zero angular rate updates), s.
    pub stop_s: f64,
    /// Bias estimate and its standard deviation at the end, deg/s.
    pub final_bias_dps: f64,
    pub final_bias_sigma_dps: f64,
    pub n_samples: usize,
}

/// A batch run: the trace always, the metrics when the log has a usable reference.
#[derive(Debug, Clone)]
pub struct PipelineRun {
    pub trace: PipelineTrace,
    pub still_source: StillSource,
    pub result: Result<PipelineResult>,
}

/// Runs the pipeline, Table-III HDR, raw integration and the two peers on a log.
pub fn run(log: &DriveLog, params: &PipelineParams) -> Result<PipelineRun> {
    params.validate()?;
    let bias_s = log.bias_s(params.bias_s);
    let (blocks, source) = still::blocks(log, bias_s, &params.still)?;
    let (b0, s0) = initial_bias(log, params)?;
    let mut trace = run_blocks(&blocks, *params, b0, s0)?;
    let hdr_opts = crate::hdr::HdrOptions { bias_s: Some(bias_s), ..Default::default() };
    let hdr = crate::hdr::run(log, &hdr_opts)?;
    let stop_s: f64 = (1..blocks.len()).filter(|&i| trace.stop[i]).map(|i| blocks.time_s[i] - blocks.time_s[i - 1]).sum();
    let result = Reference::from_log(log).and_then(|reference| {
        let hdr = hdr.result?;
        let pipe = metrics::score(&trace.time_s, &trace.heading_deg, &reference)?;
        trace.heading_deg.iter_mut().for_each(|p| *p += pipe.shift_deg);
        let fusion = crate::peers::fusion_offset_heading(log, bias_s)?;
        let fusion = metrics::score(&fusion.0, &fusion.1, &reference)?;
        let zaru = crate::peers::zaru_heading(&blocks, params.min_still_s, hdr.eps0_dps);
        let zaru = metrics::score(&blocks.time_s, &zaru, &reference)?;
        let d = log.duration_min();
        Ok(PipelineResult {
            E_psi_raw_deg: hdr.E_psi_raw_deg,
            E_psi_hdr_deg: hdr.E_psi_hdr_deg,
            E_psi_pipeline_deg: pipe.e_psi_deg,
            NE_psi_raw_deg_per_min: hdr.NE_psi_raw_deg_per_min,
            NE_psi_hdr_deg_per_min: hdr.NE_psi_hdr_deg_per_min,
            NE_psi_pipeline_deg_per_min: metrics::ne_psi(pipe.e_psi_deg, d),
            improvement_pipeline: metrics::improvement(hdr.E_psi_raw_deg, pipe.e_psi_deg),
            duration_min: d,
            E_psi_fusion_offset_deg: fusion.e_psi_deg,
            E_psi_zaru_deg: zaru.e_psi_deg,
            NE_psi_fusion_offset_deg_per_min: metrics::ne_psi(fusion.e_psi_deg, d),
            NE_psi_zaru_deg_per_min: metrics::ne_psi(zaru.e_psi_deg, d),
            still_source: source,
            stop_s,
            final_bias_dps: trace.bias_dps.last().copied().unwrap_or(f64::NAN),
            final_bias_sigma_dps: trace.bias_sigma_dps.last().copied().unwrap_or(f64::NAN),
            n_samples: pipe.n_samples,
        })
    });
    Ok(PipelineRun { trace, still_source: source, result })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fixed constants, so the hand-worked numbers do not follow the tuned defaults.
    fn params() -> PipelineParams {
        PipelineParams {
            temp_coeff_sigma_dps_per_c: 0.0,
            road_sigma_dps: 0.5,
            bias_walk_dps_per_sqrt_s: 0.0005,
            gate_dps: 1.0,
            ..PipelineParams::default()
        }
    }

    #[test]
    fn kalman_step_hand_worked() {
        // First block turning (outside the gate: no update). P0 = 0.04, one straight block
        // 1 s later: P = 0.04 + 0.0005^2 * 1, R = 0.25, innovation 0.3: K = P / (P + R), b = 0.3 K.
        let mut p = Pipeline::new(params(), 0.0, 0.2).unwrap();
        assert!(!p.update(0.0, 10.0, f64::NAN, false).unwrap().straight);
        let o = p.update(1.0, 0.3, f64::NAN, false).unwrap();
        assert!(o.straight && !o.stop);
        assert_eq!(o.heading_deg, 0.3, "integrates rate - bias(before update) = 0.3 deg/s over 1 s");
        let pp = 0.04 + 0.0005f64.powi(2);
        let k = pp / (pp + 0.25);
        assert!((p.x[0] - 0.3 * k).abs() < 1e-15);
        assert!((p.cov[0][0] - (1.0 - k) * pp).abs() < 1e-15);
    }

    #[test]
    fn stops_hold_the_heading_and_pin_the_bias() {
        let mut p = Pipeline::new(params(), 0.0, 0.2).unwrap();
        let mut last = None;
        for i in 0..30 {
            last = Some(p.update(i as f64, 0.5, f64::NAN, true).unwrap());
        }
        let o = last.unwrap();
        assert_eq!(o.heading_deg, 0.0, "heading held while standing");
        assert!(o.stop);
        assert!((p.x[0] - 0.5).abs() < 1e-3, "bias -> the standing rate: {}", p.x[0]);
        // Turning at 10 deg/s is outside the gate: no update, heading integrates.
        let b = p.x[0];
        let o = p.update(30.0, 10.0, f64::NAN, false).unwrap();
        assert!(!o.straight && !o.stop);
        assert_eq!(p.x[0], b);
        assert!((o.heading_deg - (10.0 - b)).abs() < 1e-12);
    }

    #[test]
    fn first_stop_blocks_are_not_used_until_min_still() {
        let mut p = Pipeline::new(params(), 0.0, 0.2).unwrap();
        assert!(!p.update(0.0, 0.5, f64::NAN, true).unwrap().stop, "run 0 s");
        assert!(!p.update(1.0, 0.5, f64::NAN, true).unwrap().stop, "run 1 s");
        assert!(p.update(2.0, 0.5, f64::NAN, true).unwrap().stop, "run 2 s = min_still_s");
    }

    #[test]
    fn temperature_term_learns_the_coefficient_from_stops_at_two_temperatures() {
        let pr = PipelineParams { temp_coeff_sigma_dps_per_c: 0.02, ..PipelineParams::default() };
        let mut p = Pipeline::new(pr, 0.0, 0.2).unwrap();
        // bias = 0.1 + 0.01 (T - 20): stops at 20 C and at 30 C.
        let mut t = 0.0;
        for (temp, n) in [(20.0, 60), (30.0, 60)] {
            for _ in 0..n {
                p.update(t, 0.1 + 0.01 * (temp - 20.0), temp, true).unwrap();
                t += 1.0;
            }
        }
        assert!((p.x[0] - 0.1).abs() < 0.005, "b {}", p.x[0]);
        assert!((p.x[1] - 0.01).abs() < 0.001, "k {}", p.x[1]);
    }

    #[test]
    fn bad_updates_are_errors() {
        let mut p = Pipeline::new(params(), 0.0, 0.2).unwrap();
        p.update(1.0, 0.0, f64::NAN, false).unwrap();
        assert!(p.update(1.0, 0.0, f64::NAN, false).is_err());
        assert!(p.update(2.0, f64::NAN, f64::NAN, false).is_err());
        assert!(PipelineParams { gate_dps: -1.0, ..params() }.validate().is_err());
        assert!(PipelineParams::default().set("nope", 1.0).is_err());
    }
}
