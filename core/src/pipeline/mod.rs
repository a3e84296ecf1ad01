//! The recommended drift reduction, beyond the paper: a bank of small Kalman filters (bias
//! walks x warm-up terms x road levels, weighed by their Huber likelihood) fed by stops and
//! by HDR's straight-road heuristic; a guard re-opens the bias when a stop says it moved. Causal and streaming ([`Pipeline`]), with an offline smoothed
//! mode (Rauch-Tung-Striebel over the whole log, held to the causal heading at stops;
//! labelled non-causal). Design and what was
//! tried and dropped: docs/pipeline.md. `gyrodrift hdr` stays the paper's exact method.

mod blend;
mod dating;
mod evidence;
mod fallback;
pub mod filter;
mod model;
mod noise;
pub mod params;
mod records;
mod smoother;
pub mod stream;

pub use evidence::half_sample_mode;
pub use filter::{Pipeline, PipelineOutput};
pub use model::State;
pub use params::{PipelineParams, N_MODELS, N_ROADS, N_WALKS, N_WARMS};
pub use smoother::N_SMOOTHED;
pub use stream::PipelineStream;

use crate::error::Result;
use crate::eval::{Method, Prepared};
use crate::log::DriveLog;
use crate::still::{Blocks, StillSource};
use serde::{Deserialize, Serialize};

/// The per-block series of a pipeline run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PipelineTrace {
    pub time_s: Vec<f64>,
    /// Causal heading (aligned to the reference when the log has one).
    pub heading_deg: Vec<f64>,
    /// The causal heading's standard deviation from the bias model ([`PipelineOutput`]).
    pub heading_sigma_deg: Vec<f64>,
    /// Smoothed heading: uses the whole log, not available live (aligned likewise).
    pub heading_smoothed_deg: Vec<f64>,
    /// The bias the causal heading integrated: the bank's, moved by the blend (`blend.rs`).
    pub bias_dps: Vec<f64>,
    /// The bank's bias sigma (the blend's guard; not the blended bias' own uncertainty).
    pub bias_sigma_dps: Vec<f64>,
    /// The bias the smoothed heading integrated: the bank's smoothed, blended likewise.
    pub bias_smoothed_dps: Vec<f64>,
    /// The block brought stop evidence.
    pub stop: Vec<bool>,
    /// The bank's bias and its sigma at the last block (NaN without blocks), deg/s: the
    /// model's estimate of the gyro's bias, which the blended series move by per block.
    pub final_bias_dps: f64,
    pub final_bias_sigma_dps: f64,
}

impl PipelineTrace {
    /// The trace CSV's columns, the CLI's, the wasm `runPipeline`'s and Python's.
    pub fn columns(&self) -> [(&'static str, crate::series::Column<'_>); 8] {
        use crate::series::{values, Column};
        [
            ("time_s", values(&self.time_s)),
            ("heading_deg", values(&self.heading_deg)),
            ("heading_sigma_deg", values(&self.heading_sigma_deg)),
            ("heading_smoothed_deg", values(&self.heading_smoothed_deg)),
            ("bias_dps", values(&self.bias_dps)),
            ("bias_sigma_dps", values(&self.bias_sigma_dps)),
            ("bias_smoothed_dps", values(&self.bias_smoothed_dps)),
            ("stop", Column::Flags(&self.stop)),
        ]
    }

    /// Writes the per-block trace as CSV: the causal heading and its sigma, the smoothed
    /// heading (non-causal), the bias (causal, its sigma, smoothed) and the stop flag (0/1).
    pub fn write_csv<W: std::io::Write>(&self, out: W) -> Result<()> {
        crate::series::write_csv(&self.columns(), out)
    }

    /// Time whose stop evidence was used, s.
    pub fn stop_s(&self) -> f64 {
        // + 0: an empty float sum is -0 in Rust, which printed as "-0 s".
        (1..self.time_s.len()).filter(|&i| self.stop[i]).map(|i| self.time_s[i] - self.time_s[i - 1]).sum::<f64>() + 0.0
    }

    /// The estimator's figures at the end of the log (`stop_s`: [`Self::stop_s`], passed in
    /// because `run` computes it once for its result too; `duration_min`: the log's), with
    /// or without a reference.
    pub fn summary(&self, still_source: StillSource, stop_s: f64, duration_min: f64) -> PipelineSummary {
        let last = |x: &[f64]| x.last().copied().unwrap_or(f64::NAN);
        let change = |x: &[f64]| last(x) - x.first().copied().unwrap_or(f64::NAN);
        PipelineSummary {
            duration_min,
            still_source,
            stop_s,
            final_bias_dps: self.final_bias_dps,
            final_bias_sigma_dps: self.final_bias_sigma_dps,
            heading_change_deg: change(&self.heading_deg),
            heading_change_sigma_deg: last(&self.heading_sigma_deg),
            heading_change_smoothed_deg: change(&self.heading_smoothed_deg),
        }
    }
}

/// The pipeline's clock: time since the log's first row, on a microsecond grid. Its
/// windows compare whole seconds, which float rounding of epoch-second times (about 2e-7 s
/// at 1.8e9) would decide; on the grid a log gives the same result wherever its time starts.
pub(crate) fn clock_s(time_s: f64, origin_s: f64) -> f64 {
    ((time_s - origin_s) * 1e6).round() / 1e6
}

/// Runs the filter over the blocks from bias 0 +- the prior, then the smoother
/// (`smoother.rs`); the heading traces are unaligned. Blocks stamped before `lead_in_end_s`
/// are the lead-in. Every step runs on the pipeline's clock (`clock_s`): the trace's times
/// are the clock's until the end, when it takes the blocks' stamps.
pub fn run_blocks(blocks: &Blocks, params: PipelineParams, lead_in_end_s: f64) -> Result<PipelineTrace> {
    let n = blocks.len();
    let lead_in_end_s = clock_s(lead_in_end_s, blocks.origin_s);
    let mut f = Pipeline::new(params, 0.0, params.prior_bias_sigma_dps, lead_in_end_s)?;
    f.gyro_stills = blocks.source == StillSource::Gyro;
    let clock = blocks.time_s.iter().map(|&t| clock_s(t, blocks.origin_s)).collect();
    let mut tr = PipelineTrace { time_s: clock, final_bias_dps: f64::NAN, final_bias_sigma_dps: f64::NAN, ..Default::default() };
    let (mut blend, mut blended) = (blend::Blend::of(&params), Vec::with_capacity(n));
    let mut bend_evidence = Vec::with_capacity(n);
    for i in 0..n {
        let (t, rate) = (tr.time_s[i], blocks.rate_dps[i]);
        let settled_dps = f.settled_bias_dps();
        let o = f.update(t, rate, blocks.still[i])?;
        tr.heading_deg.push(o.heading_deg);
        tr.heading_sigma_deg.push(o.heading_sigma_deg);
        tr.bias_dps.push(o.bias_dps);
        tr.bias_sigma_dps.push(o.bias_sigma_dps);
        tr.stop.push(o.stop);
        (tr.final_bias_dps, tr.final_bias_sigma_dps) = (o.bias_dps, o.bias_sigma_dps);
        bend_evidence.push((settled_dps, f.quiet()));
        blended.push(blend.update(t >= f.lead_in_end_s(), t, rate, o, settled_dps, f.quiet())?);
    }
    // The smoothed mode is held to the bank's causal heading at stops; the trace then takes
    // the blended heading and bias (`blend.rs`), and the smoothed mode is blended alike.
    tr.bias_smoothed_dps = smoother::smoothed_bias(blocks, params, lead_in_end_s, &tr)?;
    for (i, o) in blended.iter().enumerate() {
        (tr.heading_deg[i], tr.bias_dps[i]) = (o.heading_deg, o.bias_dps);
    }
    blend_smoothed(blocks, params, f.lead_in_end_s(), &mut tr, &bend_evidence)?;
    tr.time_s.clone_from(&blocks.time_s);
    Ok(tr)
}

/// The smoothed heading: the smoothed bias integrated, blended with the experts as the
/// causal heading is (guarded by the bank's causal bias sigma, the smoother keeping none,
/// grown between the bank's stops as the causal guard is; the bank's stops pass whole),
/// the bend fallback included: `bend_evidence` is the causal bank's settled bias and
/// quiet flag per block, as the causal blend had them (a bend the bank read as road is in
/// the smoothed bias too). Sets `heading_smoothed_deg` and the bias it integrated.
fn blend_smoothed(
    blocks: &Blocks,
    params: PipelineParams,
    lead_in_end_s: f64,
    tr: &mut PipelineTrace,
    bend_evidence: &[(f64, bool)],
) -> Result<()> {
    let mut blend = blend::Blend::of(&params);
    let mut h = 0.0;
    for i in 0..blocks.len() {
        let (t, rate) = (tr.time_s[i], blocks.rate_dps[i]);
        if i > 0 {
            h += (rate - tr.bias_smoothed_dps[i]) * (t - tr.time_s[i - 1]);
        }
        let smoothed = PipelineOutput {
            heading_deg: h,
            bias_dps: tr.bias_smoothed_dps[i],
            bias_sigma_dps: tr.bias_sigma_dps[i],
            heading_sigma_deg: 0.0,
            stop: tr.stop[i],
            straight: false,
            reopened: false,
        };
        let (settled_dps, quiet) = bend_evidence[i];
        let o = blend.update(t >= lead_in_end_s, t, rate, smoothed, settled_dps, quiet)?;
        tr.heading_smoothed_deg.push(o.heading_deg);
        tr.bias_smoothed_dps[i] = o.bias_dps;
    }
    Ok(())
}

/// The pipeline's result keys (E_psi_*, NE_psi_*, improvement_pipeline, duration_min),
/// the smoothed mode, the peers, and what the pipeline saw.
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
    /// The offline smoothed mode (non-causal: uses the whole log).
    pub E_psi_pipeline_smoothed_deg: f64,
    pub NE_psi_pipeline_smoothed_deg_per_min: f64,
    /// The peers on the same metric: x-io Fusion's gyroscope offset and a plain zero-rate
    /// update at stops.
    pub E_psi_fusion_offset_deg: f64,
    pub E_psi_zaru_deg: f64,
    pub NE_psi_fusion_offset_deg_per_min: f64,
    pub NE_psi_zaru_deg_per_min: f64,
    /// Where the still flags came from: speed, odometry, gyro or none.
    pub still_source: StillSource,
    /// Time whose stop evidence was used, s.
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
    /// Time whose stop evidence was used, s (the result's `stop_s`, and the summary's).
    pub stop_s: f64,
    pub result: Result<PipelineResult>,
}

/// What a run says without a reference heading to score against (a drive with no GPS
/// course): the estimator's own figures at the end of the log.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PipelineSummary {
    pub duration_min: f64,
    /// Where the still flags came from: speed, odometry, gyro or none.
    pub still_source: StillSource,
    /// Time whose stop evidence was used, s.
    pub stop_s: f64,
    /// Bias estimate and its standard deviation at the end, deg/s.
    pub final_bias_dps: f64,
    pub final_bias_sigma_dps: f64,
    /// Heading turned from the first block to the last (causal, with its sigma from the
    /// bias model; and smoothed), deg: unscored headings start at 0.
    pub heading_change_deg: f64,
    pub heading_change_sigma_deg: f64,
    pub heading_change_smoothed_deg: f64,
}

impl PipelineRun {
    /// The estimator's figures at the end of the log (`duration_min`: the log's), with or
    /// without a reference.
    pub fn summary(&self, duration_min: f64) -> PipelineSummary {
        self.trace.summary(self.still_source, self.stop_s, duration_min)
    }

    /// For plots: the errors of the causal and smoothed headings at the scored reference
    /// samples; None when there is no result.
    pub fn errors(&self, log: &DriveLog) -> Option<crate::metrics::ErrorSeries> {
        let t = &self.trace;
        self.result.as_ref().ok()?;
        crate::metrics::ErrorSeries::of(log, &t.time_s, &[&t.heading_deg, &t.heading_smoothed_deg]).map(|(_, e)| e)
    }
}

/// Runs the pipeline (causal and smoothed), raw integration, Table-III HDR and the two
/// peers on a log, through the one evaluation path (`eval`).
pub fn run(log: &DriveLog, params: &PipelineParams) -> Result<PipelineRun> {
    params.validate()?;
    let prep = Prepared::new(log, params.bias_s, &params.still)?;
    let mut trace = prep.pipeline_trace(params)?;
    let stop_s = trace.stop_s();
    let result = prep.reference().and_then(|reference| {
        let pipe = crate::metrics::score(&trace.time_s, &trace.heading_deg, reference)?;
        let smooth = crate::metrics::score(&trace.time_s, &trace.heading_smoothed_deg, reference)?;
        trace.heading_deg.iter_mut().for_each(|p| *p += pipe.shift_deg);
        trace.heading_smoothed_deg.iter_mut().for_each(|p| *p += smooth.shift_deg);
        let raw = prep.score(&Method::Raw)?;
        let hdr = prep.score(&Method::Hdr(Default::default()))?;
        let fusion = prep.score(&Method::FusionOffset)?;
        let zaru = prep.score(&Method::Zaru { min_still_s: crate::peers::ZARU_MIN_STILL_S })?;
        let d = prep.duration_min;
        let ne = |e: f64| crate::metrics::ne_psi(e, d);
        Ok(PipelineResult {
            E_psi_raw_deg: raw.e_psi_deg,
            E_psi_hdr_deg: hdr.e_psi_deg,
            E_psi_pipeline_deg: pipe.e_psi_deg,
            NE_psi_raw_deg_per_min: ne(raw.e_psi_deg),
            NE_psi_hdr_deg_per_min: ne(hdr.e_psi_deg),
            NE_psi_pipeline_deg_per_min: ne(pipe.e_psi_deg),
            improvement_pipeline: crate::metrics::improvement(raw.e_psi_deg, pipe.e_psi_deg),
            duration_min: d,
            E_psi_pipeline_smoothed_deg: smooth.e_psi_deg,
            NE_psi_pipeline_smoothed_deg_per_min: ne(smooth.e_psi_deg),
            E_psi_fusion_offset_deg: fusion.e_psi_deg,
            E_psi_zaru_deg: zaru.e_psi_deg,
            NE_psi_fusion_offset_deg_per_min: ne(fusion.e_psi_deg),
            NE_psi_zaru_deg_per_min: ne(zaru.e_psi_deg),
            still_source: prep.blocks.source,
            stop_s,
            final_bias_dps: trace.final_bias_dps,
            final_bias_sigma_dps: trace.final_bias_sigma_dps,
            n_samples: pipe.n_samples,
        })
    });
    Ok(PipelineRun { trace, still_source: prep.blocks.source, stop_s, result })
}

#[cfg(test)]
mod tests;
