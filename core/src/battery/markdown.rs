//! The battery as Markdown: the summaries, the goals with their verdicts, every case.

use super::{Battery, Summary};
use std::fmt::Write;

impl Battery {
    /// The summaries by split, and of the drives a user added (a part of the scoring cases).
    fn splits(&self) -> [(&'static str, &Option<Summary>); 3] {
        [("training", &self.training), ("scoring", &self.scoring), ("added", &self.added)]
    }

    /// Markdown: the two summaries, then every case (best causal method in bold).
    pub fn to_markdown(&self, cases: bool) -> String {
        let mut s = String::new();
        let head = |s: &mut String, first: &str, last: Option<&str>| {
            let _ = write!(s, "| {first} |");
            for m in self.methods.iter().map(String::as_str).chain(last) {
                let _ = write!(s, " {m} |");
            }
            let _ = writeln!(s, "\n|---|{}", "---:|".repeat(self.methods.len() + last.is_some() as usize));
        };
        let _ = writeln!(s, "Mean NE_psi (deg/min) per method; \"smoothed\" is offline (non-causal) and not a peer.\n");
        head(&mut s, "cases", Some("pipeline / best other"));
        for (label, sm) in self.splits() {
            if let Some(sm) = sm {
                let _ = write!(s, "| {label} ({}) |", sm.n_cases);
                for v in &sm.mean {
                    let _ = write!(s, " {v:.3} |");
                }
                let _ = writeln!(s, " {:.2}x |", sm.mean_ratio);
            }
        }
        let _ = writeln!(s);
        if self.added.is_some() {
            let _ = writeln!(s, "\"added\": the cases on the drives given as logs (`--logs`), which are scoring cases too.\n");
        }
        for (label, sm) in self.splits() {
            if let Some(sm) = sm {
                let _ = writeln!(
                    s,
                    "- {label}: pipeline within 1.25x best other + 0.05 on {} of {} ({:.0} %); worse than 2x + 0.05 on {}; worse than raw by > 10 % on {}; worst {:.2}x ({})",
                    sm.n_within,
                    sm.n_cases,
                    100.0 * sm.n_within as f64 / sm.n_cases as f64,
                    sm.n_over_2x,
                    sm.n_worse_than_raw,
                    sm.worst_ratio,
                    sm.worst
                );
            }
        }
        let _ = writeln!(s, "\nThe same two counts for every method against the best of its others (the pipeline is one of a peer's others; smoothed is measured against every causal method):\n");
        head(&mut s, "cases: within 1.25x + 0.05 / worse than 2x + 0.05", None);
        for (label, sm) in self.splits() {
            if let Some(sm) = sm {
                let _ = write!(s, "| {label} ({}) |", sm.n_cases);
                for (w, o) in sm.each_within.iter().zip(&sm.each_over_2x) {
                    let _ = write!(s, " {w} / {o} |");
                }
                let _ = writeln!(s);
            }
        }
        let _ = writeln!(s, "\nThe robustness issue's goals, measured on each split (`Summary::goals`):\n");
        let _ = writeln!(s, "| cases | goal | measured | verdict |\n|---|---|---|---|");
        for (label, sm) in self.splits() {
            for g in sm.iter().flat_map(|sm| &sm.goals) {
                let verdict = if g.holds { "holds" } else { "**misses**" };
                let measured = if g.measured.fract() == 0.0 { format!("{:.0}", g.measured) } else { format!("{:.3}", g.measured) };
                let _ = writeln!(s, "| {label} | {} | {measured} ({}) | {verdict} |", g.goal, g.detail);
            }
        }
        if !self.skipped.is_empty() {
            let _ = writeln!(s, "- skipped: {}", self.skipped.iter().map(|(c, e)| format!("{c} ({e})")).collect::<Vec<_>>().join("; "));
        }
        if cases {
            let _ = writeln!(s);
            head(&mut s, "case (T = training)", Some("pipeline / best other"));
            for c in &self.cases {
                let best = c.ne_psi.get(c.best).copied();
                let _ = write!(s, "| {}{} / {} |", if c.training { "T " } else { "" }, c.base, c.profile);
                for v in &c.ne_psi {
                    if Some(*v) == best {
                        let _ = write!(s, " **{v:.3}** |");
                    } else {
                        let _ = write!(s, " {v:.3} |");
                    }
                }
                let _ = writeln!(s, " {:.2}x{} |", c.ratio, if c.within { "" } else { " !" });
            }
        }
        s
    }
}
