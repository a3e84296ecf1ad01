//! The robustness issue's goals, measured on one split's cases, so the verdicts in
//! docs/battery.md come from a command anyone can re-run (`gyrodrift battery`), not by hand.

use super::{best_peer, CaseRow, PIPELINE};
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

/// The six goals on these cases; a goal with no case to judge it (no simulated or
/// good-gyro base in the split) is left out.
pub fn goals(cases: &[&CaseRow]) -> Vec<GoalCheck> {
    let n = cases.len();
    if n == 0 {
        return Vec::new();
    }
    let m = cases[0].ne_psi.len();
    let means: Vec<f64> = (0..m).map(|j| mean(cases.iter().map(|c| c.ne_psi[j])).0).collect();
    let best_other = best_peer(&means);
    let mut out = vec![check(
        "mean NE_psi <= 0.7x the best other method's mean",
        means[PIPELINE] / best_other,
        0.7,
        false,
        format!("{:.3} against {:.3}", means[PIPELINE], best_other),
    )];
    let over: Vec<&&CaseRow> = cases.iter().filter(|c| c.ne_psi[PIPELINE] > 2.0 * best_peer(&c.ne_psi) + 0.05).collect();
    let worst = cases.iter().max_by(|a, b| a.ratio.total_cmp(&b.ratio)).expect("n > 0");
    out.push(check(
        "no case worse than 2x the best other + 0.05",
        over.len() as f64,
        0.0,
        false,
        format!("{} of {n}; worst {:.2}x ({} / {})", over.len(), worst.ratio, worst.base, worst.profile),
    ));
    let within = cases.iter().filter(|c| c.within).count();
    out.push(check(">= 90 % of cases within 1.25x the best other + 0.05", within as f64 / n as f64, 0.9, true, format!("{within} of {n}")));
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
    let worse_raw = cases.iter().filter(|c| c.ne_psi[PIPELINE] > 1.1 * c.ne_psi[col::RAW] + 1e-9).count();
    out.push(check("never worse than raw integration by more than 10 %", worse_raw as f64, 0.0, false, format!("{worse_raw} of {n}")));
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
