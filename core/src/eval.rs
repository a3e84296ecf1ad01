//! The one evaluation path: a log is prepared once (static bias, 1 Hz blocks with still
//! flags, reference), every method runs over that preparation, and every heading is scored
//! by the same metric code. `pipeline::run`, `compare`, the battery and the wasm `compare`
//! all go through it, so a method is only an estimator.

use crate::error::{Error, Result};
use crate::hdr::{self, HdrParams};
use crate::log::{Column, DriveLog};
use crate::metrics::{self, Reference};
use crate::pipeline::{self, PipelineParams, PipelineTrace};
use crate::preprocess::{self, Samples};
use crate::still::{self, Blocks, StillOptions};
use serde::{Deserialize, Serialize};

/// A drift-reduction method as the evaluation runs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// Integration of (rate - eps0), the paper's "without HDR".
    Raw,
    /// HDR (methods.md) with these parameters.
    Hdr(HdrParams),
    /// x-io Fusion's gyroscope offset on the rows.
    FusionOffset,
    /// Plain zero-rate update at stops.
    Zaru { min_still_s: f64 },
    /// The recommended pipeline, causal.
    Pipeline(PipelineParams),
    /// The pipeline's offline smoothed mode (non-causal).
    PipelineSmoothed(PipelineParams),
}

/// Columns of [`standard_methods`]: the comparison's methods in order.
pub mod col {
    pub const RAW: usize = 0;
    pub const HDR_TABLE_III: usize = 1;
    pub const FUSION_OFFSET: usize = 2;
    pub const ZARU: usize = 3;
    pub const PIPELINE: usize = 4;
    pub const SMOOTHED: usize = 5;
    /// Present only with tuned HDR parameters.
    pub const HDR_TUNED: usize = 6;
}

/// Every method the comparison and the battery score, in [`col`] order: raw, Table-III HDR,
/// Fusion offset, ZARU (its own 2 s), the pipeline, its smoothed mode, then tuned HDR.
pub fn standard_methods(params: &PipelineParams, tuned: Option<HdrParams>) -> Vec<Method> {
    let mut m = vec![
        Method::Raw,
        Method::Hdr(HdrParams::table_iii()),
        Method::FusionOffset,
        Method::Zaru { min_still_s: crate::peers::ZARU_MIN_STILL_S },
        Method::Pipeline(*params),
        Method::PipelineSmoothed(*params),
    ];
    m.extend(tuned.map(Method::Hdr));
    m
}

/// One method's score on one log.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MethodScore {
    pub e_psi_deg: f64,
    pub ne_psi_deg_per_min: f64,
}

/// A log prepared once for every method.
#[derive(Debug, Clone)]
pub struct Prepared<'a> {
    pub log: &'a DriveLog,
    pub bias_s: f64,
    /// Static bias over the lead-in (Eq. 2's eps0), deg/s.
    pub eps0_dps: f64,
    /// The paper's 1 Hz blocks with still flags (HDR, raw, ZARU and the pipeline run on
    /// them), and what the flags were decided from (`blocks.source`).
    pub blocks: Blocks,
    pub duration_min: f64,
    still_opts: StillOptions,
    reference: Result<Reference>,
}

impl<'a> Prepared<'a> {
    pub fn new(log: &'a DriveLog, bias_s: Option<f64>, still_opts: &StillOptions) -> Result<Self> {
        let bias_s = log.bias_s(bias_s);
        let gyro = log.require(Column::GyroDps, "needed for the yaw rate")?;
        log.check_span()?;
        let eps0_dps = preprocess::static_bias_dps(log.time_s(), gyro, bias_s)?;
        let blocks = still::blocks(log, bias_s, still_opts)?;
        Ok(Prepared {
            log,
            bias_s,
            eps0_dps,
            blocks,
            duration_min: log.duration_min(),
            still_opts: *still_opts,
            reference: Reference::from_log(log),
        })
    }

    /// The reference heading, or why there is none.
    pub fn reference(&self) -> Result<&Reference> {
        self.reference.as_ref().map_err(|e| e.clone())
    }

    fn samples(&self) -> Samples {
        Samples { time_s: self.blocks.time_s.clone(), rate_dps: self.blocks.rate_dps.clone() }
    }

    /// End of the stationary lead-in (absolute time), for the pipeline: the declared one,
    /// or earlier the first block in which the speed or the wheels show the vehicle moving
    /// (a `# bias_s:`, or the 20 s default, longer than the standing is not stop evidence).
    pub fn lead_in_end_s(&self) -> f64 {
        self.lead_in_end_on(&self.blocks)
    }

    fn lead_in_end_on(&self, blocks: &Blocks) -> f64 {
        let declared = self.log.time_s().first().map_or(f64::NEG_INFINITY, |t0| t0 + self.bias_s);
        blocks.first_moving_s.map_or(declared, |t| declared.min(t))
    }

    /// The pipeline's trace (unaligned) on these blocks.
    pub fn pipeline_trace(&self, params: &PipelineParams) -> Result<PipelineTrace> {
        if params.still != self.still_opts {
            // Still flags follow the method's own thresholds.
            let blocks = still::blocks(self.log, self.bias_s, &params.still)?;
            return pipeline::run_blocks(&blocks, *params, self.lead_in_end_on(&blocks));
        }
        pipeline::run_blocks(&self.blocks, *params, self.lead_in_end_s())
    }

    /// A method's heading (time, unaligned heading).
    pub fn heading(&self, method: &Method) -> Result<(Vec<f64>, Vec<f64>)> {
        match method {
            Method::Raw => {
                let mut raw = hdr::RawIntegrator::new(self.eps0_dps);
                let psi = self.blocks.time_s.iter().zip(&self.blocks.rate_dps).map(|(&t, &w)| raw.update(t, w)).collect();
                Ok((self.blocks.time_s.clone(), psi))
            }
            Method::Hdr(p) => {
                let mut psi = Vec::with_capacity(self.blocks.len());
                hdr::headings_only(&self.samples(), *p, self.eps0_dps, &mut psi)?;
                Ok((self.blocks.time_s.clone(), psi))
            }
            Method::FusionOffset => crate::peers::fusion_offset_heading(self.log, self.bias_s),
            Method::Zaru { min_still_s } => {
                Ok((self.blocks.time_s.clone(), crate::peers::zaru_heading(&self.blocks, *min_still_s, self.eps0_dps)))
            }
            Method::Pipeline(p) => self.pipeline_trace(p).map(|t| (t.time_s, t.heading_deg)),
            Method::PipelineSmoothed(p) => self.pipeline_trace(p).map(|t| (t.time_s, t.heading_smoothed_deg)),
        }
    }

    /// A method's E_psi and NE_psi against the reference.
    pub fn score(&self, method: &Method) -> Result<MethodScore> {
        Ok(self.score_all(std::slice::from_ref(method))?[0])
    }

    /// Every method of a list, scored; both pipeline modes share one run.
    pub fn score_all(&self, methods: &[Method]) -> Result<Vec<MethodScore>> {
        let reference = self.reference()?;
        let mut cached: Option<(PipelineParams, PipelineTrace)> = None;
        let mut out = Vec::with_capacity(methods.len());
        for m in methods {
            let (t, psi) = match m {
                Method::Pipeline(p) | Method::PipelineSmoothed(p) => {
                    let tr = match cached.take() {
                        Some((q, tr)) if q == *p => tr,
                        _ => self.pipeline_trace(p)?,
                    };
                    let psi = if matches!(m, Method::Pipeline(_)) { tr.heading_deg.clone() } else { tr.heading_smoothed_deg.clone() };
                    let t = tr.time_s.clone();
                    cached = Some((*p, tr));
                    (t, psi)
                }
                _ => self.heading(m)?,
            };
            out.push(self.score_heading(&t, &psi, reference)?);
        }
        Ok(out)
    }

    /// The causal and smoothed headings of a pipeline run already made on these blocks,
    /// scored as [`Self::score_all`] scores them.
    pub fn score_trace(&self, trace: &PipelineTrace) -> Result<[MethodScore; 2]> {
        let reference = self.reference()?;
        let t = &trace.time_s;
        Ok([self.score_heading(t, &trace.heading_deg, reference)?, self.score_heading(t, &trace.heading_smoothed_deg, reference)?])
    }

    /// One heading's score. Inlined: as a call of its own it cost the size-capped browser
    /// module 48 bytes gzipped (measured 2026-11-26).
    #[inline(always)]
    fn score_heading(&self, t: &[f64], psi: &[f64], reference: &Reference) -> Result<MethodScore> {
        let s = metrics::score(t, psi, reference)?;
        if !s.e_psi_deg.is_finite() {
            return Err(Error::data("the heading error is not finite"));
        }
        Ok(MethodScore { e_psi_deg: s.e_psi_deg, ne_psi_deg_per_min: metrics::ne_psi(s.e_psi_deg, self.duration_min) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{simulate, SimRequest};

    #[test]
    fn raw_and_hdr_equal_the_paper_run_bit_for_bit() {
        let log = simulate(&SimRequest { scenario: Some("city".into()), minutes: Some(5.0), seed: 5, ..Default::default() }).unwrap();
        let prep = Prepared::new(&log, None, &StillOptions::default()).unwrap();
        let h = hdr::run(&log, &Default::default()).unwrap().result.unwrap();
        assert_eq!(prep.score(&Method::Raw).unwrap().e_psi_deg, h.E_psi_raw_deg);
        assert_eq!(prep.score(&Method::Hdr(HdrParams::default())).unwrap().e_psi_deg, h.E_psi_hdr_deg);
        let all =
            prep.score_all(&[Method::Raw, Method::Pipeline(Default::default()), Method::PipelineSmoothed(Default::default())]).unwrap();
        assert_eq!(all[1], prep.score(&Method::Pipeline(Default::default())).unwrap());
        assert_eq!(all[2], prep.score(&Method::PipelineSmoothed(Default::default())).unwrap());
    }
}
