//! Means, counts and the worst case over a split's cases, and the goals measured from them.

use super::{goals::goals_of, CaseRow, GoalCheck, PIPELINE, SMOOTHED};
use serde::{Deserialize, Serialize};

/// Summary over a set of cases.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    pub n_cases: usize,
    /// Mean NE_psi per method.
    pub mean: Vec<f64>,
    /// Pipeline mean / best other method's mean.
    pub mean_ratio: f64,
    pub n_within: usize,
    /// Cases worse than 2x the best peer + 0.05.
    pub n_over_2x: usize,
    /// Worst case: its label and its ratio to the best peer.
    pub worst: String,
    pub worst_ratio: f64,
    /// Cases where the pipeline is worse than raw integration by more than 10 %.
    pub n_worse_than_raw: usize,
    /// The goal's two counts applied to every method in turn (column order): cases within
    /// 1.25x + 0.05 of the best of the *other* causal methods, and worse than 2x + 0.05. For
    /// the pipeline these are `n_within` and `n_over_2x`; for a peer the pipeline is one
    /// of its others; the smoothed mode is measured against every causal method.
    pub each_within: Vec<usize>,
    pub each_over_2x: Vec<usize>,
    /// The goals measured on these cases (`goals.rs`).
    pub goals: Vec<GoalCheck>,
}

/// Best causal method of a row other than column `j`.
pub(super) fn best_other_than(ne: &[f64], j: usize) -> f64 {
    ne.iter().enumerate().filter(|(i, _)| *i != j && *i != SMOOTHED).map(|(_, v)| *v).fold(f64::INFINITY, f64::min)
}

/// Best causal peer of a row (every column but the pipeline's two).
pub fn best_peer(ne: &[f64]) -> f64 {
    best_other_than(ne, PIPELINE)
}

/// Column of the best causal method of a row (every column but the smoothed mode's; the
/// first of equals).
pub fn best_causal(ne: &[f64]) -> usize {
    (0..ne.len()).filter(|&i| i != SMOOTHED).fold(0, |b, i| if ne[i] < ne[b] { i } else { b })
}

/// Means, ratios and the worst case over some cases (None if there are none).
pub fn summarize(cases: &[&CaseRow]) -> Option<Summary> {
    let first = cases.first()?;
    let m = first.ne_psi.len();
    let n = cases.len() as f64;
    let mean: Vec<f64> = (0..m).map(|j| cases.iter().map(|c| c.ne_psi[j]).sum::<f64>() / n).collect();
    let best_other = best_peer(&mean);
    let worst = cases.iter().max_by(|a, b| a.ratio.total_cmp(&b.ratio))?;
    let within = |j: usize| cases.iter().filter(|c| c.ne_psi[j] <= 1.25 * best_other_than(&c.ne_psi, j) + 0.05).count();
    let over_2x = |j: usize| cases.iter().filter(|c| c.ne_psi[j] > 2.0 * best_other_than(&c.ne_psi, j) + 0.05).count();
    let mut s = Summary {
        each_within: (0..m).map(within).collect(),
        each_over_2x: (0..m).map(over_2x).collect(),
        goals: Vec::new(),
        n_cases: cases.len(),
        mean_ratio: mean[PIPELINE] / best_other,
        n_within: cases.iter().filter(|c| c.within).count(),
        n_over_2x: over_2x(PIPELINE),
        worst: format!("{} / {}", worst.base, worst.profile),
        worst_ratio: worst.ratio,
        n_worse_than_raw: cases.iter().filter(|c| c.ne_psi[PIPELINE] > 1.1 * c.ne_psi[0] + 1e-9).count(),
        mean,
    };
    s.goals = goals_of(&s, cases);
    Some(s)
}
