//! Property tests: any block sequence, the whole run bounded.

use super::*;

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]
    /// No divergence by construction, whatever the gyro does: on any finite block sequence
    /// (rates far beyond any bias, stops in turns, irregular block times) every output is
    /// finite, and the bias estimate, causal and smoothed, stays within the widest bias the
    /// filter accepts about the turn-on bias the lead-in showed (it learns only from stops
    /// and straight-road modes plausible as a bias; without the projection in `bias()` a
    /// warm-up term fitted to a fast change extrapolated to 10 deg/s here).
    #[test]
    fn never_diverges_on_any_block_sequence(
        blocks in any_blocks(400),
        lead_in_s in 0.0f64..30.0,
    ) {
        let p = PipelineParams::default();
        let mut f = Pipeline::new(p, 0.0, p.prior_bias_sigma_dps, lead_in_s).unwrap();
        f.record((0..params::N_MODELS).collect(), blocks.len());
        let mut t = 0.0;
        for (dt, rate, still) in blocks {
            t += dt;
            let centre = f.centre_dps();
            let o = f.update(t, rate, still).unwrap();
            proptest::prop_assert!(o.heading_deg.is_finite() && o.bias_sigma_dps.is_finite() && o.heading_sigma_deg.is_finite() && o.heading_sigma_deg >= 0.0);
            proptest::prop_assert!((o.bias_dps - centre).abs() <= p.max_bias_dps + 1e-9, "bias {} at {t} s", o.bias_dps);
        }
        for b in f.smoothed_bias() {
            proptest::prop_assert!(b.is_finite() && (b - f.centre_dps()).abs() <= p.max_bias_dps + 1e-9, "smoothed bias {b}");
        }
    }

    /// The whole run bounded too, the smoothed bias after it is held to the causal heading at
    /// stops included: the hold shifts a span's bias by whatever the causal heading did over
    /// it, and reached 9.8 deg/s across a declared lead-in that covers a turn, -6.0 after a
    /// turn into a stop with a slow rotation (below), before it was projected after the hold.
    #[test]
    fn the_whole_run_is_bounded_smoothed_bias_after_the_hold_included(
        items in any_blocks(300),
        lead_in_s in 0.0f64..30.0,
    ) {
        let p = PipelineParams::default();
        let blocks = blocks_of(&items);
        let tr = run_blocks(&blocks, p, lead_in_s).unwrap();
        // The turn-on bias is a mean of lead-in or stop blocks: at most their largest rate.
        let lead_max = (0..blocks.len()).filter(|&i| blocks.time_s[i] < lead_in_s || blocks.still[i]).map(|i| blocks.rate_dps[i].abs()).fold(0.0, f64::max);
        // Both headings' biases are the bank's (causal, or smoothed and projected after the
        // hold), bounded as that, moved by the blend by less than the guard: the mean of moves
        // each within blend_sigmas of the bank's causal sigma, grown as the blend's walk since
        // the last stop (at most since the start).
        for i in 0..tr.time_s.len() {
            let grown = p.blend_walk_dps_per_sqrt_s.powi(2) * (tr.time_s[i] - tr.time_s[0]);
            let bound = p.max_bias_dps + lead_max + p.blend_sigmas * (tr.bias_sigma_dps[i].powi(2) + grown).sqrt();
            for (what, x, h) in [("causal", tr.bias_dps[i], tr.heading_deg[i]), ("smoothed", tr.bias_smoothed_dps[i], tr.heading_smoothed_deg[i])] {
                proptest::prop_assert!(x.is_finite() && x.abs() <= bound && h.is_finite(), "{what} bias {x} beyond {bound}, heading {h}");
            }
        }
    }
}
