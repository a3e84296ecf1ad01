//! What the evidence says about the heading the bank took off: each hypothesis' bias
//! integral, the heading's sigma from them, and a stop's correction of the past heading
//! (the causal E[heading | evidence so far], as a zero-velocity update corrects an INS;
//! dated by the straight blocks since the last stop, `dating.rs`). Beyond the paper.

use super::Pipeline;
use crate::pipeline::dating;

impl Pipeline {
    /// Variance of the heading's error from the bias (deg^2), with weights `w`: each
    /// hypothesis' posterior of the bias integral, N(h, p_hh), about the integral the heading
    /// took off (the moment-matched mixture).
    pub(super) fn heading_variance(&self, w: &[f64]) -> f64 {
        let taken = self.rate_integral_deg - self.heading_deg;
        self.models.iter().zip(w).filter(|(_, wi)| **wi > 0.0).map(|(m, wi)| wi * (m.p_hh.max(0.0) + (m.h - taken).powi(2))).sum()
    }

    /// Each hypothesis' bias integral (deg), before an update that may correct it.
    pub(super) fn integrals(&self) -> Vec<f64> {
        self.models.iter().map(|m| m.h).collect()
    }

    /// A stop corrected each hypothesis' bias integral (road evidence does not): the
    /// heading takes their mix, its age (the change spread as a walk) re-dated by the
    /// straight blocks since the last stop (`dating`). The stop's blocks so far are dated as
    /// one change (their sums), and the heading takes what that adds to what they gave
    /// before: a first block's small change is not dated alone with the age of a walk.
    /// `h_before`: each hypothesis' integral before the stop's updates; `w`: the weights after.
    pub(super) fn correct_heading_at_stop(&mut self, h_before: &[f64], w: &[f64], b_before: f64, time_s: f64) {
        let dh = self.integral_change(h_before, w);
        let delta = self.bias().0 - b_before;
        self.stop_change.0 += delta;
        self.stop_change.1 += dh;
        let (delta, dh) = (self.stop_change.0, self.stop_change.1);
        let correction = if delta.abs() > 1e-12 && dh / delta > 0.0 {
            let r = self.p.road_sigma_dps;
            let model = 2.0 * r * r * self.p.road_corr_s + self.p.block_sigma_dps * self.p.block_sigma_dps;
            let sigma2 =
                dating::long_run_variance(&self.residuals, 10).map_or(model, |v| v.max(self.p.block_sigma_dps * self.p.block_sigma_dps));
            let t0 = self.dating_t0_s.unwrap_or(time_s);
            delta * dating::expected_age_s(&self.residuals, t0, time_s, delta, dh / delta, sigma2)
        } else {
            dh
        };
        self.heading_deg -= correction - self.stop_change.2;
        self.stop_change.2 = correction;
        self.last_stop_s = Some(time_s);
    }

    /// The bias integrals' change since `h_before` (each hypothesis' before an update), mixed
    /// with the weights `w`: what the update says the heading took off wrongly.
    #[inline]
    pub(super) fn integral_change(&self, h_before: &[f64], w: &[f64]) -> f64 {
        self.models.iter().zip(h_before).zip(w).map(|((m, hb), wi)| wi * (m.h - hb)).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::PipelineParams;

    /// No lead-in, a gyro reading a constant 2 deg/s on a straight road: a bias the bank had
    /// no evidence of (prior 0 +- 2.5). Until it knows the bias (three sigma within Table
    /// III's theta_w), straight blocks also correct the heading for what the bias cost it,
    /// so the heading ends near the truth (0: 1.04 deg) instead of keeping most of what the
    /// first blocks took off (8.29 deg without the correction); once known, a straight block
    /// moves the heading by its rate less the bias only.
    #[test]
    fn while_acquiring_the_road_corrects_the_heading_then_no_longer() {
        let mut f = Pipeline::new(PipelineParams::default(), 0.0, 2.5, 0.0).unwrap();
        let mut out = None;
        for t in 1..=60 {
            out = Some(f.update(t as f64, 2.0, false).unwrap());
        }
        let out = out.unwrap();
        assert!(f.acquired && (out.bias_dps - 2.0).abs() < 0.01, "{out:?}");
        assert!(out.heading_deg.abs() < 2.0, "{}", out.heading_deg);
        let (b, _) = f.bias();
        let h = f.update(61.0, 2.1, false).unwrap().heading_deg;
        assert!((h - (out.heading_deg + 2.1 - b)).abs() < 1e-9, "{h}");
    }
}
