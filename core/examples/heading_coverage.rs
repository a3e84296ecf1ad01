//! How well the pipeline's heading sigma describes its heading error, on the battery's
//! cases: at every scored reference sample, the aligned causal heading's error against the
//! reference over the causal heading's sigma; the share of samples within 1 and 2 sigma (a
//! Gaussian's 68 % and 95 %), over all samples and per case, and the cases that miss most.
//! Nothing in the sigma was chosen on these cases (it has no constant of its own).
//!
//! `cargo run --release --example heading_coverage -- RECORDED.csv ...` (the battery's
//! recorded bases, imported by their recipes, as for `bank_ceiling`); `SPLIT=scoring` for
//! the scoring cases (default: training).
mod common;

use gyrodrift::battery::{self, Base, Profile};
use gyrodrift::eval::Prepared;
use gyrodrift::metrics::{error_series, score};
use gyrodrift::pipeline::PipelineParams;

/// One case: its label, whether its base is simulated, and per scored sample |error| and sigma.
struct Case {
    label: String,
    simulated: bool,
    abs_err: Vec<f64>,
    sigma: Vec<f64>,
}

impl Case {
    fn within(&self, k: f64) -> usize {
        self.abs_err.iter().zip(&self.sigma).filter(|(e, s)| **e <= k * **s).count()
    }

    /// The median of |error| / sigma over the samples with a sigma (a Gaussian's is 0.674):
    /// far below, the sigma is too wide for this case; far above, too narrow.
    fn median_z(&self) -> f64 {
        let mut z: Vec<f64> = self.abs_err.iter().zip(&self.sigma).filter(|(_, s)| **s > 0.0).map(|(e, s)| e / s).collect();
        z.sort_by(f64::total_cmp);
        z.get(z.len() / 2).copied().unwrap_or(f64::NAN)
    }
}

fn main() {
    let scoring = std::env::var("SPLIT").is_ok_and(|s| s == "scoring");
    let bases = common::bases_from_args();
    let profiles = battery::profiles();
    let cases: Vec<Case> = bases
        .iter()
        .flat_map(|b| profiles.iter().map(move |p| (b, p)))
        .filter(|(b, p)| (b.training && p.training) != scoring)
        .filter_map(|(b, p)| run_case(b, p))
        .collect();
    let split = if scoring { "scoring" } else { "training" };
    println!(
        "| {split} cases | cases | samples | within 1 sigma | within 2 sigma | cases with >= 90 % within 2 sigma | cases with < 50 % |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (label, pick) in [("all", None), ("recorded", Some(false)), ("simulated", Some(true))] {
        let some: Vec<&Case> = cases.iter().filter(|c| pick.is_none_or(|s| c.simulated == s)).collect();
        summary_row(label, &some);
    }
    widths(&cases);
    worst_cases(&cases);
}

/// How many cases have a sigma too wide or too narrow for their errors, by the median of
/// |error| / sigma against a Gaussian's 0.674: over 3x too wide (median below 0.225), 1.5-3x
/// too wide, within 1.5x, 1.5-3x too narrow, over 3x too narrow.
fn widths(cases: &[Case]) {
    let g = 0.674;
    let edges = [g / 3.0, g / 1.5, g * 1.5, g * 3.0];
    println!("\n| cases: the sigma against the errors (median of abs error / sigma; a Gaussian 0.674) | all | recorded | simulated |\n|---|---:|---:|---:|");
    let labels = ["over 3x too wide", "1.5-3x too wide", "within 1.5x", "1.5-3x too narrow", "over 3x too narrow"];
    for (k, label) in labels.iter().enumerate() {
        let count = |pick: Option<bool>| {
            cases
                .iter()
                .filter(|c| pick.is_none_or(|s| c.simulated == s))
                .filter(|c| edges.iter().filter(|&&e| c.median_z() >= e).count() == k)
                .count()
        };
        println!("| {label} | {} | {} | {} |", count(None), count(Some(false)), count(Some(true)));
    }
}

/// The case's causal heading and sigma at the scored reference samples (None without a reference).
fn run_case(b: &Base, pr: &Profile) -> Option<Case> {
    let params = PipelineParams::default();
    let log = gyrodrift::sim::inject(&b.log, &pr.errors).unwrap();
    let prep = Prepared::new(&log, None, &params.still).unwrap();
    let reference = prep.reference().ok()?;
    let bl = &prep.blocks;
    // The shipped causal heading (the bank's blended with HDR's and Fusion's offset's) and the bank's sigma.
    let tr = prep.pipeline_trace(&params).unwrap();
    let (psi, sig) = (tr.heading_deg, tr.heading_sigma_deg);
    let shift = score(&bl.time_s, &psi, reference).ok()?.shift_deg;
    let aligned: Vec<f64> = psi.iter().map(|p| p + shift).collect();
    let (_, err) = error_series(&bl.time_s, &aligned, reference);
    // The sigma at the same samples: the series of (sigma - reference) plus the reference.
    let (_, s_minus_r) = error_series(&bl.time_s, &sig, reference);
    let (_, minus_r) = error_series(&bl.time_s, &vec![0.0; bl.len()], reference);
    Some(Case {
        label: format!("{} / {}", b.name, pr.name),
        simulated: b.simulated,
        abs_err: err.iter().map(|e| e.abs()).collect(),
        sigma: s_minus_r.iter().zip(&minus_r).map(|(a, b)| a - b).collect(),
    })
}

fn summary_row(label: &str, cases: &[&Case]) {
    let n: usize = cases.iter().map(|c| c.abs_err.len()).sum();
    let (in1, in2): (usize, usize) = (cases.iter().map(|c| c.within(1.0)).sum(), cases.iter().map(|c| c.within(2.0)).sum());
    let share = |c: &&Case| c.within(2.0) as f64 / c.abs_err.len() as f64;
    let good = cases.iter().filter(|c| share(c) >= 0.9).count();
    let bad = cases.iter().filter(|c| share(c) < 0.5).count();
    let pct = |k: usize| 100.0 * k as f64 / n as f64;
    println!("| {label} | {} | {n} | {:.1} % | {:.1} % | {good} | {bad} |", cases.len(), pct(in1), pct(in2));
}

/// The 15 cases with the fewest samples within 2 sigma.
fn worst_cases(cases: &[Case]) {
    let mut by: Vec<(f64, &Case)> = cases.iter().map(|c| (c.within(2.0) as f64 / c.abs_err.len() as f64, c)).collect();
    by.sort_by(|a, b| a.0.total_cmp(&b.0));
    println!("\n| case | within 2 sigma | mean abs error (deg) | median sigma (deg) |\n|---|---:|---:|---:|");
    for (share, c) in by.iter().take(15) {
        let mut s = c.sigma.clone();
        s.sort_by(f64::total_cmp);
        let mean = c.abs_err.iter().sum::<f64>() / c.abs_err.len() as f64;
        println!("| {} | {:.0} % | {mean:.2} | {:.2} |", c.label, 100.0 * share, s[s.len() / 2]);
    }
}
