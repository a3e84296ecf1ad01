//! When did the bias change that a stop just revealed? A stop shows today's bias; the
//! heading needs how long the old estimate was wrong. The Kalman filter's answer (its
//! integral's covariance) is the random walk's: the change spread evenly since the last
//! evidence. A bias that steps (an OS re-calibration, a knock) is not a walk, and the
//! straight-road blocks since the last stop say when it happened: after a change the
//! rate on straights sits off the old estimate by the change. This dates it.

/// Expected age (s) at `t_z` of a bias change of `delta` (deg/s), given the straight-road
/// residuals since the last evidence `t0` (block time, rate less the bias used then) with
/// noise variance `sigma2` per block (deg/s)^2, and the filter's own expected age
/// `prior_age_s`, which sets the prior: a point mass at `t0` (the error is older than the
/// last evidence) and a uniform part over (t0, t_z], weighted so the prior's mean age is
/// `prior_age_s` (uniform over the last 2 x `prior_age_s` when that is under half the span).
/// A step and the walk's ramp are weighed by how well each explains the residuals, so a
/// gradual change keeps the walk's age.
pub fn expected_age_s(residuals: &[(f64, f64)], t0: f64, t_z: f64, delta: f64, prior_age_s: f64, sigma2: f64) -> f64 {
    let span = t_z - t0;
    if !(span > 0.0 && prior_age_s > 0.0 && sigma2 > 0.0 && delta != 0.0) {
        return prior_age_s;
    }
    // Prior: mass `old` at t0, the rest uniform over (t_z - len, t_z].
    let (old, len) = if prior_age_s >= span {
        (1.0, span)
    } else if 2.0 * prior_age_s >= span {
        (2.0 * prior_age_s / span - 1.0, span)
    } else {
        (0.0, 2.0 * prior_age_s)
    };
    let start = t_z - len;
    // Candidate change times: t0, and the uniform part cut at the residuals' times (the
    // likelihood is constant between them). Log likelihood of a change at tau relative to
    // none: the residuals after tau are shifted by delta. Residuals are in time order;
    // suffix[i] sums the terms of residuals i.. .
    let per = |nu: f64| (nu * delta - 0.5 * delta * delta) / sigma2;
    let mut suffix = vec![0.0; residuals.len() + 1];
    for i in (0..residuals.len()).rev() {
        suffix[i] = suffix[i + 1] + per(residuals[i].1);
    }
    let first_after = |tau: f64| residuals.partition_point(|r| r.0 <= tau);
    // Pieces: (log weight, mean age) for the point mass and each uniform interval.
    let mut pieces: Vec<(f64, f64)> = Vec::new();
    if old > 0.0 {
        pieces.push((libm::log(old) + suffix[first_after(t0)], span));
    }
    if old < 1.0 {
        let mut i = first_after(start);
        let mut lo = start;
        while lo < t_z {
            let hi = if i < residuals.len() && residuals[i].0 < t_z { residuals[i].0 } else { t_z };
            if hi > lo {
                let w = (1.0 - old) * (hi - lo) / len;
                pieces.push((libm::log(w) + suffix[i], t_z - 0.5 * (lo + hi)));
            }
            lo = hi;
            i += 1;
        }
    }
    let m = pieces.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let (num, den) = pieces.iter().fold((0.0, 0.0), |(n, d), &(lw, age)| {
        let w = libm::exp(lw - m);
        (n + w * age, d + w)
    });
    if !(den > 0.0) {
        return prior_age_s;
    }
    // The walk's answer as a model of its own: the same prior mean age as a ramp (the old
    // part from t0, the rest growing linearly over the prior's span). The two models'
    // evidence (relative to no change) weighs their ages.
    let ramp = |t: f64| {
        let x = ((t - start) / len).clamp(0.0, 1.0);
        delta * (old + (1.0 - old) * x)
    };
    let ll_ramp: f64 = residuals
        .iter()
        .filter(|r| r.0 > t0)
        .map(|r| {
            let m = ramp(r.0);
            (r.1 * m - 0.5 * m * m) / sigma2
        })
        .sum();
    let ll_step = m + libm::log(den);
    let p_step = 1.0 / (1.0 + libm::exp((ll_ramp - ll_step).clamp(-700.0, 700.0)));
    p_step * num / den + (1.0 - p_step) * prior_age_s
}

/// Long-run variance per block of the residuals (they are correlated over tens of
/// seconds: curvature, sway), from the spread of means of `batch` consecutive residuals,
/// or None with fewer than five batches.
pub fn long_run_variance(residuals: &[(f64, f64)], batch: usize) -> Option<f64> {
    let means: Vec<f64> = residuals.chunks_exact(batch.max(1)).map(|c| c.iter().map(|r| r.1).sum::<f64>() / c.len() as f64).collect();
    if means.len() < 5 {
        return None;
    }
    let m = means.iter().sum::<f64>() / means.len() as f64;
    let var = means.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (means.len() - 1) as f64;
    Some(var * batch.max(1) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_run_variance_of_batch_means_hand_worked() {
        // Batches of 2: means 1, 3, 1, 3, 1, 3 (mean 2, sample variance 6 / 5 = 1.2), x 2.
        let r: Vec<(f64, f64)> =
            [0.0, 2.0, 2.0, 4.0, 1.0, 1.0, 3.0, 3.0, 0.0, 2.0, 3.0, 3.0].iter().enumerate().map(|(i, &v)| (i as f64, v)).collect();
        assert!((long_run_variance(&r, 2).unwrap() - 2.4).abs() < 1e-12);
        assert_eq!(long_run_variance(&r[..9], 2), None);
    }

    #[test]
    fn without_residuals_the_prior_age_comes_back() {
        // Uniform over (0, 100]: mean age 50; a point mass takes it to 80 (old = 0.6).
        assert!((expected_age_s(&[], 0.0, 100.0, 0.2, 50.0, 1.0) - 50.0).abs() < 1e-9);
        assert!((expected_age_s(&[], 0.0, 100.0, 0.2, 80.0, 1.0) - 80.0).abs() < 1e-9);
        // Under half the span: uniform over the last 2 x 20 s.
        assert!((expected_age_s(&[], 0.0, 100.0, 0.2, 20.0, 1.0) - 20.0).abs() < 1e-9);
    }

    /// Two residuals of 1, at 25 and 75 s, span (0, 100], uniform prior (walk age 50),
    /// delta 1, sigma2 1. A step before 25 s explains both (per residual nu - 1/2 = 1/2),
    /// between 25 and 75 one, after 75 none: log likelihoods 1, 1/2, 0, prior weights 1/4,
    /// 1/2, 1/4, mean ages 87.5, 50, 12.5. The ramp t / 100 reads 1/4 and 3/4: log
    /// likelihood (1/4 - 1/32) + (3/4 - 9/32) = 11/16. Evidence e^1/4 + e^0.5/2 + 1/4 against
    /// e^(11/16) weighs the step's age against the walk's 50.
    #[test]
    fn a_change_is_dated_by_the_residuals_hand_worked() {
        let got = expected_age_s(&[(25.0, 1.0), (75.0, 1.0)], 0.0, 100.0, 1.0, 50.0, 1.0);
        let e = std::f64::consts::E;
        let z_step = 0.25 * e + 0.5 * e.sqrt() + 0.25;
        let age_step = (0.25 * e * 87.5 + 0.5 * e.sqrt() * 50.0 + 0.25 * 12.5) / z_step;
        let z_ramp = (11.0f64 / 16.0).exp();
        let want = (z_step * age_step + z_ramp * 50.0) / (z_step + z_ramp);
        assert!((got - want).abs() < 1e-9, "{got} vs {want}");
        assert!(got > 50.0 && got < age_step);
    }

    #[test]
    fn straights_on_the_old_bias_make_the_change_recent_a_ramp_keeps_the_walks_age() {
        // 600 straight blocks, a change of 0.17 found at 634 s; the walk spreads it (317 s).
        // On the old bias (residual 0) a step is the better model, and recent: each block
        // on the old bias costs a change before it 0.17^2 / 2 / 1.8 = 0.008 nats.
        let at = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> { (0..600).map(|i| (i as f64, f(i as f64))).collect() };
        let age = expected_age_s(&at(&|_| 0.0), 0.0, 634.0, 0.17, 317.0, 1.8);
        assert!(age > 100.0 && age < 250.0, "{age}");
        // Straights that already showed the change date it toward the start.
        let age = expected_age_s(&at(&|_| 0.17), 0.0, 634.0, 0.17, 317.0, 1.8);
        assert!(age > 400.0, "{age}");
        // Straights on the walk's ramp keep (nearly) the walk's age.
        let age = expected_age_s(&at(&|t| 0.17 * t / 634.0), 0.0, 634.0, 0.17, 317.0, 1.8);
        assert!((age / 317.0 - 1.0).abs() < 0.1, "{age}");
    }
}
