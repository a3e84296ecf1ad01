//! The warm-up term's prior, sized once the declared lead-in ends: by the turn-on bias the
//! lead-in showed (a calibrated gyro is not given a 0.3 deg/s warm-up to fit to the road's
//! slow curves), and the lead-in's own trend, which marks a warm-up beyond the prior that
//! the bank cannot hold (the blend's fallback then off). Beyond the paper.

use super::Pipeline;

impl Pipeline {
    /// Sizes the warm-up prior by the turn-on bias the lead-in showed: a warm-up is part of
    /// the turn-on bias that decays, so a gyro that starts within 0.01 deg/s of zero (a
    /// calibrated one) is not given a 0.3 deg/s warm-up to fit to the road's slow curves
    /// on a drive without stops. The prior's scale becomes max(|b|, sigma_b) (the turn-on
    /// bias, or its uncertainty), at most `warm_sigma_dps`. With b_start = b_inf + d fixed,
    /// d is scaled by rho (x' = A x, P' = A P A^T, A = [[1, 1 - rho, 0], [0, rho, 0],
    /// [0, 0, 1]]), which after a short lead-in that told nothing of d is the prior's
    /// rescaling. Logs without a lead-in keep the default (docs/pipeline.md).
    /// A lead-in of three blocks or more whose rate trends beyond three of its standard
    /// errors, faster than even the fastest modelled warm-up could with the prior's
    /// `warm_sigma_dps` (|slope| x tau > it), shows a warm-up the bank cannot hold: its
    /// settled bias will move, and the blend's fallback, whose premise is that it should
    /// not, is off (`warming`).
    pub(super) fn size_warm_up(&mut self) {
        self.warm_up_sized = true;
        let (slope, var, _) = self.lead_trend.slope();
        let sigma = self.p.warm_sigma_dps;
        let fastest_s = self.p.warm_tau_short_s.min(self.p.warm_tau_long_s);
        self.warming = self.lead_trend.count() > 2.0 && slope * slope > 9.0 * var && slope.abs() * fastest_s > sigma;
        let (b, p) = self.bias();
        let rho = b.abs().max(p.sqrt()).min(sigma) / sigma;
        for m in self.models.iter_mut().filter(|m| m.warm_tau_s.is_finite()) {
            m.x[0] += (1.0 - rho) * m.x[1];
            m.x[1] *= rho;
            m.p_hx[0] += (1.0 - rho) * m.p_hx[1];
            m.p_hx[1] *= rho;
            for c in 0..3 {
                m.p[(0, c)] += (1.0 - rho) * m.p[(1, c)];
                m.p[(1, c)] *= rho;
            }
            for r in 0..3 {
                m.p[(r, 0)] += (1.0 - rho) * m.p[(r, 1)];
                m.p[(r, 1)] *= rho;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::model::Model;
    use crate::pipeline::PipelineParams;

    /// A lead-in stop at the start reads 3 deg/s (noise 0.05): with the start bias 0 +- 0.5,
    /// every hypothesis takes 3 x 0.25 / (0.25 + 0.0025) = 2.970297 as its bias, and none
    /// puts any of it into the warm-up term (which is the change from the start, so the
    /// start says nothing of it: before, 26 % went there and decayed away).
    #[test]
    fn evidence_at_the_start_moves_the_start_bias_not_the_warm_up_hand_worked() {
        let mut f = Pipeline::new(PipelineParams::default(), 0.0, 0.5, 10.0).unwrap();
        f.update(1.0, 3.0, true).unwrap();
        for m in &f.models {
            assert_eq!(m.x[1], 0.0);
            assert!((m.bias().0 - 3.0 * 0.25 / 0.2525).abs() < 1e-12, "{}", m.bias().0);
            assert!((m.bias().1 - 0.25 * 0.0025 / 0.2525).abs() < 1e-12);
        }
    }

    /// A lead-in of nine 1 s blocks at 0.05 deg/s (noise 0.05) leaves the bias at 0.05 +-
    /// about 0.05 / 3 = 0.0167: the turn-on bias is 1/6 of the 0.3 deg/s warm-up prior, so every
    /// warm-up term is scaled by rho = 1/6 (its variance by 1/36), the start bias and its
    /// variance kept. A lead-in at 1 deg/s leaves the prior as it is.
    #[test]
    fn the_lead_in_sizes_the_warm_up_prior_hand_worked() {
        for (z, rho_expected) in [(0.05, 1.0 / 6.0), (1.0, 1.0)] {
            let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 10.0).unwrap();
            for t in 1..10 {
                f.update(t as f64, z, true).unwrap();
            }
            assert!(f.lead_in_seen && !f.warm_up_sized);
            let (b, p) = f.bias();
            // The walks widen it a little over the nine seconds (at most by 0.01^2 x 9).
            assert!((b - z).abs() < 1e-4 && p.sqrt() > 0.05 / 3.0 && p.sqrt() < 0.02, "{b} {p}");
            let before: Vec<Model> = f.models.clone();
            f.size_warm_up();
            let rho = b.abs().max(p.sqrt()).min(0.3) / 0.3;
            assert!((rho - rho_expected).abs() < 1e-3, "{rho}");
            let sum = |m: &Model| (m.x[0] + m.x[1], m.p[(0, 0)] + 2.0 * m.p[(0, 1)] + m.p[(1, 1)], m.p[(0, 1)] + m.p[(1, 1)]);
            for (m, o) in f.models.iter().zip(&before) {
                let k = if o.warm_tau_s.is_finite() { rho } else { 1.0 };
                assert!((sum(m).0 - sum(o).0).abs() < 1e-12 && (sum(m).1 - sum(o).1).abs() < 1e-12);
                assert!((m.p[(1, 1)] - k * k * o.p[(1, 1)]).abs() < 1e-12);
                // Cov(b_start, d) scales with d.
                assert!((sum(m).2 - k * sum(o).2).abs() < 1e-12);
                assert_eq!(m.x[2], o.x[2]);
            }
            // Through `update`: once, at the first block past the lead-in.
            let mut g = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 10.0).unwrap();
            for t in 1..10 {
                g.update(t as f64, z, true).unwrap();
            }
            g.update(10.0, z, false).unwrap();
            assert!(g.warm_up_sized);
        }
    }

    /// A 20 s lead-in falling by 0.0065 deg/s per s (a 2.2 deg/s warm-up, 300 s), block noise
    /// +-0.01: the fastest modelled warm-up (200 s) would need 1.3 deg/s, beyond the 0.3 deg/s
    /// prior, so the settled bias is not a number after it (the fallback off). A lead-in as
    /// noisy but flat, or falling by 0.001 deg/s per s (0.2 deg/s at 200 s, within the prior),
    /// keeps it.
    #[test]
    fn a_lead_in_trending_beyond_the_warm_up_prior_leaves_no_settled_bias() {
        for (slope, warming) in [(-0.0065, true), (0.0, false), (-0.001, false)] {
            let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 20.5).unwrap();
            for t in 1..=20 {
                let noise = if t % 2 == 0 { 0.01 } else { -0.01 };
                f.update(t as f64, 2.0 + slope * t as f64 + noise, true).unwrap();
                assert!(f.settled_bias_dps().is_finite());
            }
            f.update(21.0, 1.87, false).unwrap();
            assert_eq!(f.warming, warming, "slope {slope}");
            assert_eq!(f.settled_bias_dps().is_nan(), warming);
        }
    }
}
