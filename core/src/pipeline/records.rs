//! What the offline smoother keeps of the recorded hypotheses, compactly: each block's
//! posterior and time step, and only those priors that are not the block before's
//! posterior predicted (where a stop guard re-opened the bias or the warm-up was sized).
//! The transition and the other priors are recomputed when read, by the same code the
//! filter ran, so the smoother sees exactly what it would have seen stored (224 bytes per
//! hypothesis and block before, its weight included, 104 now: a 15 M-row log's records took
//! 0.97 GB).

use super::model::{Model, State};
use nalgebra::{Matrix3, Vector3};

/// The records of `k` hypotheses, block-major.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Default)]
pub(super) struct Records {
    /// The recorded hypotheses' dynamics (their states unused).
    models: Vec<Model>,
    road_corr_s: f64,
    dt_s: Vec<f64>,
    post: Vec<State>,
    weights: Vec<f64>,
    /// (record index, prior) where the prior is not the previous posterior predicted.
    priors: Vec<(usize, State)>,
    /// The current block's priors are kept.
    changed: bool,
}

impl Records {
    /// Records of these hypotheses, with room for `blocks` blocks reserved at once (grown
    /// by doubling, the records of a long log asked for up to twice their size).
    pub(super) fn new(models: Vec<Model>, road_corr_s: f64, blocks: usize) -> Self {
        let n = blocks.saturating_mul(models.len());
        Records {
            models,
            road_corr_s,
            dt_s: Vec::with_capacity(blocks),
            post: Vec::with_capacity(n),
            weights: Vec::with_capacity(n),
            priors: Vec::new(),
            changed: true,
        }
    }

    /// How many hypotheses are recorded.
    pub(super) fn k(&self) -> usize {
        self.models.len()
    }

    /// The prior as the filter computes it from the last posterior.
    fn predicted(&self, j: usize, dt: f64, post: State) -> State {
        let mut m = Model { x: post.0, p: post.1, ..self.models[j] };
        m.predict(dt, libm::exp(-dt / self.road_corr_s));
        (m.x, m.p)
    }

    /// A new block: its step. `changed`: the filter changed a state between the last
    /// posteriors and this block's priors (sized the warm-up, re-opened the bias), so its
    /// priors are kept as they are.
    pub(super) fn start_block(&mut self, dt: f64, changed: bool) {
        self.dt_s.push(dt);
        self.changed = changed || self.dt_s.len() == 1;
    }

    /// The block's next hypothesis (`j`, in order): its prior, posterior and weight.
    pub(super) fn push(&mut self, j: usize, prior: State, post: State, w: f64) {
        let i = self.post.len();
        if self.changed {
            self.priors.push((i, prior));
        } else {
            debug_assert!(
                self.predicted(j, *self.dt_s.last().unwrap(), self.post[i - self.k()]) == prior,
                "a prior the records cannot derive"
            );
        }
        self.post.push(post);
        self.weights.push(w);
    }

    /// Blocks recorded.
    pub(super) fn blocks(&self) -> usize {
        self.dt_s.len()
    }

    /// Rauch-Tung-Striebel smoothing of hypothesis `j`, backward from the last block: each
    /// block's smoothed state and weight, last block first.
    pub(super) fn smooth(&self, j: usize, mut visit: impl FnMut(usize, Vector3<f64>, f64)) {
        let (k, n) = (self.k(), self.dt_s.len());
        let (mut next, mut cursor) = (Vector3::zeros(), self.priors.len());
        for t in (0..n).rev() {
            let (x, p) = self.post[t * k + j];
            let xs = if t + 1 == n {
                x
            } else {
                let (i, dt) = ((t + 1) * k + j, self.dt_s[t + 1]);
                // The explicit priors in index order: walk back to the last at or before i.
                while cursor > 0 && self.priors[cursor - 1].0 > i {
                    cursor -= 1;
                }
                let (xp, q) = match self.priors.get(cursor.wrapping_sub(1)) {
                    Some(&(at, prior)) if at == i => prior,
                    _ => self.predicted(j, dt, (x, p)),
                };
                let f = self.models[j].transition(dt, libm::exp(-dt / self.road_corr_s));
                let pf = Matrix3::from_fn(|r, c| p[(r, c)] * f[c]);
                // A hypothesis without a warm-up term has a zero row: regularise.
                match (q + Matrix3::identity() * 1e-12).try_inverse() {
                    Some(inv) => x + pf * inv * (next - xp),
                    None => x,
                }
            };
            next = xs;
            visit(t, xs, self.weights[t * k + j]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three blocks of a warm-up hypothesis, each posterior a made-up update of its prior.
    /// Smoothing reads the derived priors exactly as if every prior had been kept; and a
    /// block marked changed (a re-opened bias) is smoothed with the prior it was given.
    #[test]
    fn derived_priors_smooth_as_kept_ones_and_a_changed_block_keeps_its_own() {
        let model = Model::with_dynamics(1e-4, 0.09, 200.0);
        let run = |keep_all: bool, reopen: f64| {
            let (mut r, mut kept) = (Records::new(vec![model], 10.0, 3), Vec::new());
            let mut m = Model { x: Vector3::new(0.5, 0.1, 0.0), p: Matrix3::from_diagonal(&Vector3::new(0.04, 0.01, 0.09)), ..model };
            for (t, z) in [0.52, 0.47, 0.55].into_iter().enumerate() {
                if t > 0 {
                    m.predict(1.0, libm::exp(-0.1));
                }
                m.p[(0, 0)] += reopen * f64::from(u8::from(t == 2));
                let prior = (m.x, m.p);
                m.update(super::super::model::H_ROAD, z, 0.0025, false);
                r.start_block(if t > 0 { 1.0 } else { 0.0 }, keep_all || reopen > 0.0 && t == 2);
                r.push(0, prior, (m.x, m.p), 1.0);
                kept.push((prior, (m.x, m.p)));
            }
            let mut out = vec![Vector3::zeros(); 3];
            r.smooth(0, |t, xs, _| out[t] = xs);
            (out, r.priors.len(), kept)
        };
        // The smoother's equations on the priors and posteriors as the filter had them.
        let rts = |kept: &[(State, State)]| {
            let f = model.transition(1.0, libm::exp(-0.1));
            let mut xs = vec![kept[2].1 .0; 3];
            for t in (0..2).rev() {
                let ((x, p), (xp, q)) = (kept[t].1, kept[t + 1].0);
                let gain = Matrix3::from_fn(|r, c| p[(r, c)] * f[c]) * (q + Matrix3::identity() * 1e-12).try_inverse().unwrap();
                xs[t] = x + gain * (xs[t + 1] - xp);
            }
            xs
        };
        let (derived, n_derived, as_had) = run(false, 0.0);
        let (kept, n_kept, _) = run(true, 0.0);
        assert_eq!((n_derived, n_kept), (1, 3));
        assert_eq!(derived, kept);
        assert_eq!(derived, rts(&as_had));
        let (reopened, n_reopened, as_had) = run(false, 0.25);
        assert_eq!(n_reopened, 2);
        assert_eq!(reopened, rts(&as_had));
        assert_ne!(reopened[1], derived[1]);
    }
}
