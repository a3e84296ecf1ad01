//! One hypothesis of the pipeline's bank: a 3-state Kalman filter (settled bias, warm-up
//! term, road rate) with its transition and scalar updates, and the Huber likelihood that
//! weighs it.

use nalgebra::{Matrix3, RowVector3, Vector3};

/// State [settled bias b_inf, warm-up term d, road rate c] and its covariance; the bias
/// is b_inf + d.
pub type State = (Vector3<f64>, Matrix3<f64>);

/// One hypothesis: its bias random walk, road-rate variance, warm-up decay time (infinite
/// = no warm-up term), state, and log weight.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Model {
    pub(super) walk2: f64,
    pub(super) road_var: f64,
    pub(super) warm_tau_s: f64,
    pub(super) x: Vector3<f64>,
    pub(super) p: Matrix3<f64>,
    pub(super) logw: f64,
    /// The bias integrated since the start (deg) and its covariance with `x`: a stop's evidence about today's bias also corrects the integral of the
    /// bias since the last good evidence (as a zero-velocity update corrects an INS's
    /// heading through the heading-bias covariance).
    pub(super) h: f64,
    pub(super) p_hx: Vector3<f64>,
    /// The variance of that integral (deg^2).
    pub(super) p_hh: f64,
}

/// Below this a state or covariance entry is flushed to zero (far above the subnormal range,
/// far below any value that moves a bias in deg/s).
const TINY: f64 = 1e-100;

/// Sets the entries under [`TINY`] to zero.
fn flush_tiny(values: &mut [f64]) {
    for v in values {
        if v.abs() < TINY {
            *v = 0.0;
        }
    }
}

/// The warm-up term's decay over dt (1 without a warm-up term, `tau_s` infinite).
pub(super) fn warm_decay(tau_s: f64, dt: f64) -> f64 {
    if tau_s.is_finite() {
        libm::exp(-dt / tau_s)
    } else {
        1.0
    }
}

pub(super) const H_STOP: RowVector3<f64> = RowVector3::new(1.0, 1.0, 0.0);
pub(super) const H_ROAD: RowVector3<f64> = RowVector3::new(1.0, 1.0, 1.0);

impl Model {
    /// A hypothesis with these dynamics, its state and weight all zero (for tests).
    #[cfg(test)]
    pub(super) fn with_dynamics(walk2: f64, road_var: f64, warm_tau_s: f64) -> Self {
        Model {
            walk2,
            road_var,
            warm_tau_s,
            x: Vector3::zeros(),
            p: Matrix3::zeros(),
            logw: 0.0,
            h: 0.0,
            p_hx: Vector3::zeros(),
            p_hh: 0.0,
        }
    }

    /// Diagonal of the transition over dt (road factor `a`).
    pub(super) fn transition(&self, dt: f64, a: f64) -> Vector3<f64> {
        Vector3::new(1.0, warm_decay(self.warm_tau_s, dt), a)
    }

    /// Predict over dt: bias random walk, warm-up decay, road rate Gauss-Markov.
    pub(super) fn predict(&mut self, dt: f64, a: f64) {
        self.predict_with(dt, self.transition(dt, a));
    }

    /// [`Model::predict`] with the transition's diagonal `f` given (the bank computes each
    /// warm-up decay once per block, not once per hypothesis).
    pub(super) fn predict_with(&mut self, dt: f64, f: Vector3<f64>) {
        // The integral takes the bias before the block (as the heading integrates it).
        let pb = self.p.row(0) + self.p.row(1);
        self.p_hh += dt * (2.0 * (self.p_hx[0] + self.p_hx[1]) + dt * (pb[0] + pb[1]));
        self.h += dt * (self.x[0] + self.x[1]);
        self.p_hx += dt * pb.transpose();
        self.p_hx.component_mul_assign(&f);
        self.x.component_mul_assign(&f);
        self.p = Matrix3::from_fn(|i, j| self.p[(i, j)] * f[i] * f[j]);
        self.p[(0, 0)] += self.walk2 * dt;
        self.p[(2, 2)] += self.road_var * (1.0 - f[2] * f[2]);
        // A warm-up term decays without end: after a day or two its state and covariance
        // reach subnormal numbers, on which every operation is many times slower (a 5-day
        // log ran 4x slower per block than an hour's). Values this small are zero.
        flush_tiny(self.x.as_mut_slice());
        flush_tiny(self.p.as_mut_slice());
        flush_tiny(self.p_hx.as_mut_slice());
    }

    pub(super) fn bias(&self) -> (f64, f64) {
        (self.x[0] + self.x[1], self.p[(0, 0)] + self.p[(0, 1)] + self.p[(1, 0)] + self.p[(1, 1)])
    }

    /// Scalar measurement z = h x + noise(r); returns the innovation and its variance.
    /// `correct_integral`: the evidence also corrects the bias integral (stops); otherwise
    /// the integral keeps its mean and only its covariance with `x` follows the update.
    pub(super) fn update(&mut self, h: RowVector3<f64>, z: f64, r: f64, correct_integral: bool) -> (f64, f64) {
        self.update_bounded(h, z, r, f64::INFINITY, correct_integral)
    }

    /// [`Model::update`] whose step is bounded beyond `bound_sigma` sigma of the prediction
    /// ([`bounded_influence_noise`]; infinite: the Gaussian update). Returns the innovation
    /// and its variance at face value (noise `r`), what weighs the hypothesis.
    pub(super) fn update_bounded(&mut self, h: RowVector3<f64>, z: f64, r: f64, bound_sigma: f64, correct_integral: bool) -> (f64, f64) {
        let ph = self.p * h.transpose();
        let hph = (h * ph)[0];
        let nu = z - (h * self.x)[0];
        let s = hph + r;
        let s_step = hph + bounded_influence_noise(nu, s, r, bound_sigma);
        let k = ph / s_step;
        let hp = (h * self.p_hx)[0];
        if correct_integral {
            let k_h = hp / s_step;
            self.h += k_h * nu;
            self.p_hh -= k_h * hp;
            self.p_hx -= k_h * ph;
        } else {
            self.p_hx -= hp * k;
        }
        self.x += k * nu;
        self.p -= k * ph.transpose();
        self.p = 0.5 * (self.p + self.p.transpose());
        (nu, s)
    }
}

/// The measurement noise that gives an innovation `nu` (of variance `s`, measurement noise
/// `r` in it) beyond `k` sigma the step an innovation at `k` sigma would take: `r` grown so
/// the gain times `nu` is the Gaussian gain times `k` sigma (Huber's M-estimate step, as
/// iteratively reweighted least squares weighs a residual by k / |z|). Within `k` sigma, `r`.
/// A block of a bend read as straight road, tens of sigma off, then moves a hypothesis no
/// further than one at `k` sigma; unlike a gate, a large bias is still followed, a bounded
/// step a block.
pub(super) fn bounded_influence_noise(nu: f64, s: f64, r: f64, k: f64) -> f64 {
    let z = nu.abs() / s.sqrt();
    if z > k {
        s * z / k - (s - r)
    } else {
        r
    }
}

/// Log likelihood of an innovation `nu` of variance `s`, Gaussian within `k` sigma and with
/// Huber's linear tails beyond (Huber 1964): what weighs the hypotheses, so one surprising
/// block (a long curve read as straight) cannot hand the whole bank to one of them.
pub(super) fn log_likelihood(nu: f64, s: f64, k: f64) -> f64 {
    let z2 = nu * nu / s;
    let q = if z2 > k * k { 2.0 * k * z2.sqrt() - k * k } else { z2 };
    -0.5 * q - 0.5 * libm::log(2.0 * std::f64::consts::PI * s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Variance 4 (sigma 2) of which the measurement's 1, k = 3: an innovation of 12 (z 6)
    /// gets noise 4 x 6 / 3 - 3 = 5, so its gain is 1 / (3 + 5) against the Gaussian's 1 / 4:
    /// the step 12 / 8 = 1.5, as the Gaussian's for an innovation at 3 sigma, 6 / 4. Within
    /// 3 sigma (nu 5, z 2.5) the noise stays 1.
    #[test]
    fn a_far_innovation_steps_as_one_at_k_sigma_hand_worked() {
        assert_eq!(bounded_influence_noise(12.0, 4.0, 1.0, 3.0), 5.0);
        assert_eq!(bounded_influence_noise(-12.0, 4.0, 1.0, 3.0), 5.0);
        assert_eq!(bounded_influence_noise(5.0, 4.0, 1.0, 3.0), 1.0);
        // Through a model: the bias steps as far for 12 as the Gaussian update does for 6.
        let h = RowVector3::new(1.0, 0.0, 0.0);
        let mut far = Model::with_dynamics(0.0, 0.0, f64::INFINITY);
        far.p = Matrix3::from_diagonal(&Vector3::new(3.0, 0.0, 0.0));
        let mut at_k = far;
        let mut by_noise = far;
        assert_eq!(far.update_bounded(h, 12.0, 1.0, 3.0, false), (12.0, 4.0), "the innovation at face value");
        by_noise.update(h, 12.0, bounded_influence_noise(12.0, 4.0, 1.0, 3.0), false);
        assert_eq!((far.x, far.p), (by_noise.x, by_noise.p), "the same as the update with the grown noise");
        at_k.update(h, 6.0, 1.0, false);
        assert!((far.x[0] - 4.5).abs() < 1e-12 && (at_k.x[0] - 4.5).abs() < 1e-12, "{} {}", far.x[0], at_k.x[0]);
        // Its variance falls less than a Gaussian update at 3 sigma would take it (3 x 5 / 8
        // against 3 x 1 / 4): the far block told less.
        assert!((far.p[(0, 0)] - 15.0 / 8.0).abs() < 1e-12 && (at_k.p[(0, 0)] - 0.75).abs() < 1e-12);
    }

    /// Within k sigma the Gaussian's -z^2/2; beyond, -(2 k |z| - k^2) / 2, continuous at k.
    /// Variance 4 (sigma 2), k = 3: nu 2 (z 1) gives -1/2 - ln(8 pi)/2; nu 10 (z 5) gives
    /// -(30 - 9) / 2 - ln(8 pi)/2 instead of the Gaussian's -25/2 - ...
    #[test]
    fn huber_log_likelihood_hand_worked() {
        let c = 0.5 * (8.0 * std::f64::consts::PI).ln();
        assert!((log_likelihood(2.0, 4.0, 3.0) - (-0.5 - c)).abs() < 1e-12);
        assert!((log_likelihood(10.0, 4.0, 3.0) - (-10.5 - c)).abs() < 1e-12);
        assert!((log_likelihood(6.0, 4.0, 3.0) - (-4.5 - c)).abs() < 1e-12);
        assert!((log_likelihood(10.0, 4.0, f64::INFINITY) - (-12.5 - c)).abs() < 1e-12);
    }

    /// A bias known to be 0, walking with q per s, unobserved for 10 one-second blocks,
    /// then a stop reads z (no noise): the bias is taken to have ramped from 0 to z, so
    /// its integral (left rectangles, as the heading integrates it) is z (0 + 1 + ... + 9)
    /// / 10 = 4.5 z. Straight-road evidence leaves the integral's mean alone.
    #[test]
    fn a_stop_corrects_the_bias_integral_hand_worked() {
        let q = 1e-4;
        let fresh = || Model::with_dynamics(q, 0.0, f64::INFINITY);
        let mut m = fresh();
        for _ in 0..10 {
            m.predict(1.0, 0.0);
        }
        assert!((m.p[(0, 0)] - 10.0 * q).abs() < 1e-15);
        assert!((m.p_hx[0] - 45.0 * q).abs() < 1e-15);
        // The integral's variance: h = sum_j w_j (9 - j), so q (1 + 4 + ... + 81) = 285 q.
        assert!((m.p_hh - 285.0 * q).abs() < 1e-15, "{}", m.p_hh);
        m.update(H_STOP, 0.2, 0.0, true);
        assert!((m.x[0] - 0.2).abs() < 1e-12);
        assert!((m.h - 0.9).abs() < 1e-12, "{}", m.h);
        // Given the bias now, what is left of it: 285 q - (45 q)^2 / (10 q) = 82.5 q.
        assert!((m.p_hh - 82.5 * q).abs() < 1e-15, "{}", m.p_hh);
        let mut n = fresh();
        for _ in 0..10 {
            n.predict(1.0, 0.0);
        }
        n.update(H_ROAD, 0.2, 0.0, false);
        assert!((n.x[0] - 0.2).abs() < 1e-12);
        assert_eq!(n.h, 0.0);
        // The integral's mean is not corrected, so neither is its variance.
        assert!((n.p_hh - 285.0 * q).abs() < 1e-15);
        // Its covariance with the state follows the update: the bias is now known exactly.
        assert!(n.p_hx[0].abs() < 1e-15);
    }

    /// A warm-up term of 200 s left alone for 145 000 1 s blocks (40 h) decays by e^-725,
    /// into the subnormal range (below 2.2e-308): its state and covariance end exactly zero
    /// instead (subnormal arithmetic made long logs slow), while the settled bias keeps its
    /// walk's variance (145 000 q).
    #[test]
    fn a_decayed_warm_up_is_zero_not_subnormal() {
        let q = 1e-8;
        let mut m = Model {
            x: Vector3::new(0.1, 0.3, 0.0),
            p: Matrix3::from_diagonal(&Vector3::new(0.01, 0.09, 0.01)),
            ..Model::with_dynamics(q, 0.01, 200.0)
        };
        for _ in 0..145_000 {
            m.predict(1.0, libm::exp(-0.1));
        }
        let normal_or_zero = |v: f64| v == 0.0 || v.is_normal();
        assert!(m.x.iter().chain(m.p.iter()).chain(m.p_hx.iter()).all(|&v| normal_or_zero(v)), "{:?} {:?} {:?}", m.x, m.p, m.p_hx);
        assert_eq!((m.x[1], m.p[(1, 1)], m.p[(0, 1)]), (0.0, 0.0, 0.0));
        assert_eq!(m.x[0], 0.1);
        assert!((m.p[(0, 0)] - (0.01 + 145_000.0 * q)).abs() < 1e-12, "{}", m.p[(0, 0)]);
    }
}
