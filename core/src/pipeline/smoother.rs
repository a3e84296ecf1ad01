//! The offline smoothed mode (non-causal: it uses the whole log): a pass of the whole bank
//! with every block at face value, then one over the blocks with only the hypotheses that
//! held the most weight in it, recorded;
//! Rauch-Tung-Striebel smoothing of each, mixed by their weights at each block; the result
//! held to the causal heading at stops and bounded like the causal bias.

use super::filter::Pipeline;
use super::params::{PipelineParams, N_MODELS};
use super::records::Records;
use super::PipelineTrace;
use crate::error::Result;
use crate::still::Blocks;

/// How many hypotheses the offline smoother follows (those with the most weight over the
/// log). Following all of them costs 15x the records' memory and trades: better on the
/// simulated drives, worse on the recorded ones (docs/pipeline.md, sixty-third session).
pub const N_SMOOTHED: usize = 3;

/// The smoothed bias per block, held to the causal trace `tr` (its stops and heading; its
/// times on the pipeline's clock). Rauch-Tung-Striebel is the Gaussian model's smoother, so
/// the hypotheses it follows are the Gaussian model's too: picked by their weight over a
/// pass of the whole bank that takes every straight block at face value, not by the causal
/// bank's, whose bounded road steps keep its fast walks in weight (`Pipeline::road_update`;
/// smoothed, a fast walk turns a bend into bias: the simulated rural CRS03 drive as recorded
/// 0.43 -> 0.93 deg/min with the causal bank's picks).
pub(super) fn smoothed_bias(blocks: &Blocks, params: PipelineParams, lead_in_end_s: f64, tr: &PipelineTrace) -> Result<Vec<f64>> {
    let gaussian = || -> Result<Pipeline> {
        let mut g = Pipeline::new(params, 0.0, params.prior_bias_sigma_dps, lead_in_end_s)?;
        g.gyro_stills = blocks.source == crate::still::StillSource::Gyro;
        g.gaussian_road = true;
        Ok(g)
    };
    let run = |g: &mut Pipeline| -> Result<()> {
        for i in 0..blocks.len() {
            g.update(tr.time_s[i], blocks.rate_dps[i], blocks.still[i])?;
        }
        Ok(())
    };
    let mut first = gaussian()?;
    run(&mut first)?;
    let mut order: Vec<usize> = (0..N_MODELS).collect();
    let sums = first.weight_sums();
    // Unstable with the index as tie-break: the stable sort's order, without a stable-sort
    // instance of its own in the browser's size-capped module (BENCHMARKS.md).
    order.sort_unstable_by(|&a, &b| sums[b].total_cmp(&sums[a]).then(a.cmp(&b)));
    order.truncate(N_SMOOTHED);
    let mut g = gaussian()?;
    g.restrict(&order);
    g.record((0..order.len()).collect(), blocks.len());
    run(&mut g)?;
    let mut bias = g.smoothed_bias();
    hold_to_stops(tr, &blocks.rate_dps, &mut bias);
    // Bounded like the causal bias: the hold shifts a span by whatever the causal heading
    // did over it (9.8 deg/s across a lead-in over a turn; pipeline::tests).
    bias.iter_mut().for_each(|b| *b = params.bounded_bias_dps(*b, g.centre_dps()));
    Ok(bias)
}

/// Rauch-Tung-Striebel smoothing of the recorded hypotheses, mixed with their weights
/// (renormalised among them) at each block: the bias per block, bounded like the causal one.
pub(super) fn rts_mixed(records: &Records, params: &PipelineParams, centre_dps: f64) -> Vec<f64> {
    let k = records.k();
    if k == 0 {
        return Vec::new();
    }
    let n = records.blocks();
    let mut out = vec![0.0; n];
    let mut norm = vec![0.0; n];
    for j in 0..k {
        records.smooth(j, |t, xs, w| {
            out[t] += w * (xs[0] + xs[1]);
            norm[t] += w;
        });
    }
    out.iter().zip(&norm).map(|(o, w)| params.bounded_bias_dps(if *w > 0.0 { o / w } else { *o / k as f64 }, centre_dps)).collect()
}

/// Holds the smoothed heading to the causal one at every block with stop evidence: between
/// two such blocks the smoothed bias is shifted by the constant that makes its integral
/// meet the causal heading's change (a constant bias error, as smoothing leaves one). A
/// stop fixes the heading better than a smoothed bias integrated from the start can: on a
/// calibrated phone gyro the unheld integral was worse than raw. After the last stop the
/// smoothed bias is left as it is.
pub(super) fn hold_to_stops(tr: &PipelineTrace, rate_dps: &[f64], bias_dps: &mut [f64]) {
    let t = &tr.time_s;
    let (mut j, mut turned) = (0, 0.0);
    for i in 1..t.len() {
        turned += (rate_dps[i] - bias_dps[i]) * (t[i] - t[i - 1]);
        if tr.stop[i] {
            let shift = (turned - (tr.heading_deg[i] - tr.heading_deg[j])) / (t[i] - t[j]);
            bias_dps[j + 1..=i].iter_mut().for_each(|b| *b += shift);
            (j, turned) = (i, 0.0);
        }
    }
}
