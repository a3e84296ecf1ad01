//! The robustness issue's goals, measured on one split's cases, so the verdicts in
//! docs/battery.md come from a command anyone can re-run (`gyrodrift battery`), not by hand.

use super::{best_peer, summarize, CaseRow, Summary, PIPELINE};
use crate::eval::col;
use serde::{Deserialize, Serialize};

/// Recorded bases whose name starts with this are the good gyro of the issue's goal "no
/// worse than raw by more than 10 % as recorded" (the Pixel 6a drives: a calibrated phone).
pub const GOOD_GYRO_PREFIX: &str = "pixel6a-";

/// One goal: the figure measured and the bound it must meet.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GoalCheck {
    /// The goal as the issue states it.
    pub goal: String,
    /// The measured figure, in the unit of `target`.
    pub measured: f64,
    /// The bound: `measured <= target`, or `measured >= target` when `at_least`.
    pub target: f64,
    pub at_least: bool,
    pub holds: bool,
    /// The counts and cases behind the figure.
    pub detail: String,
}

fn check(goal: &str, measured: f64, target: f64, at_least: bool, detail: String) -> GoalCheck {
    let holds = if at_least { measured >= target } else { measured <= target };
    GoalCheck { goal: goal.to_string(), measured, target, at_least, holds, detail }
}

fn mean(v: impl Iterator<Item = f64>) -> (f64, usize) {
    let (s, n) = v.fold((0.0, 0), |(s, n), x| (s + x, n + 1));
    (if n == 0 { f64::NAN } else { s / n as f64 }, n)
}

/// The six goals on these cases (their [`summarize`]'s goals; none without cases).
pub fn goals(cases: &[&CaseRow]) -> Vec<GoalCheck> {
    summarize(cases).map_or_else(Vec::new, |s| s.goals)
}

/// The goals from a split's summary and its cases: the summary's figures, and the two goals
/// that concern some bases only; a goal with no case to judge it (no simulated or good-gyro
/// base in the split) is left out.
pub(super) fn goals_of(s: &Summary, cases: &[&CaseRow]) -> Vec<GoalCheck> {
    let n = s.n_cases;
    let best_other = best_peer(&s.mean);
    let mut out = vec![
        check(
            "mean NE_psi <= 0.7x the best other method's mean",
            s.mean_ratio,
            0.7,
            false,
            format!("{:.3} against {best_other:.3}", s.mean[PIPELINE]),
        ),
        check(
            "no case worse than 2x the best other + 0.05",
            s.n_over_2x as f64,
            0.0,
            false,
            format!("{} of {n}; worst {:.2}x ({})", s.n_over_2x, s.worst_ratio, s.worst),
        ),
        check(
            ">= 90 % of cases within 1.25x the best other + 0.05",
            s.n_within as f64 / n as f64,
            0.9,
            true,
            format!("{} of {n}", s.n_within),
        ),
    ];
    let sims: Vec<&&CaseRow> = cases.iter().filter(|c| c.simulated).collect();
    if !sims.is_empty() {
        let (p, k) = mean(sims.iter().map(|c| c.ne_psi[PIPELINE]));
        let (h, _) = mean(sims.iter().map(|c| c.ne_psi[col::HDR_TABLE_III]));
        out.push(check(
            "simulated drives: mean NE_psi <= 0.7x Table-III HDR's",
            p / h,
            0.7,
            false,
            format!("{p:.3} against {h:.3} over {k} cases"),
        ));
    }
    out.push(check(
        "never worse than raw integration by more than 10 %",
        s.n_worse_than_raw as f64,
        0.0,
        false,
        format!("{} of {n}", s.n_worse_than_raw),
    ));
    let good: Vec<&&CaseRow> =
        cases.iter().filter(|c| !c.simulated && c.profile == "as-is" && c.base.starts_with(GOOD_GYRO_PREFIX)).collect();
    if !good.is_empty() {
        let worst = good.iter().map(|c| c.ne_psi[PIPELINE] / c.ne_psi[col::RAW]).fold(0.0, f64::max);
        let each: Vec<String> =
            good.iter().map(|c| format!("{} {:.3} against raw {:.3}", c.base, c.ne_psi[PIPELINE], c.ne_psi[col::RAW])).collect();
        out.push(check("good gyro as recorded (Pixel 6a): pipeline / raw <= 1.1", worst, 1.1, false, each.join("; ")));
    }
    out
}
