//! The bank's ceiling on the battery's training cases: every hypothesis of the pipeline's
//! bank run alone (causal heading), scored like the battery against the best causal peer
//! (raw, Table-III HDR, cross-validated tuned HDR, Fusion's offset, ZARU). The best of them
//! in hindsight per case says whether a better weighing could win a case (some hypothesis
//! does) or whether no hypothesis of the model can (docs/pipeline.md).
//!
//! `cargo run --release --example bank_ceiling -- RECORDED.csv ...` (the battery's recorded
//! training bases, imported by their recipes) prints the table; with `CEILING_JSON=FILE`
//! it also writes every case: `ne`, each hypothesis' NE_psi alone, and `share`, its mean
//! weight in the whole bank over the log.
mod common;

use gyrodrift::battery::{self, best_peer, summarize, CaseRow, PIPELINE};
use gyrodrift::eval::{standard_methods, Prepared};
use gyrodrift::pipeline::{Pipeline, PipelineParams, N_MODELS};

struct Case {
    name: String,
    peers: Vec<f64>,
    ne: Vec<f64>,
    share: Vec<f64>,
}

fn main() {
    let bases = common::bases_from_args();
    let tuned = battery::TunedHdr::from_result(&battery::tune_hdr(&bases).expect("tuning"));
    let params = PipelineParams::default();
    let kept: Vec<usize> = (0..N_MODELS)
        .filter(|&k| {
            let (walk, road, _) = params.hypothesis(k);
            params.identifiable(walk, road)
        })
        .collect();
    let cases = run_cases(&bases, &params, &tuned);
    if let Ok(path) = std::env::var("CEILING_JSON") {
        let rows: Vec<String> = cases
            .iter()
            .map(|c| format!("{{\"case\":\"{}\",\"peers\":{:?},\"ne\":{:?},\"share\":{:?}}}", c.name, c.peers, c.ne, c.share))
            .collect();
        std::fs::write(path, format!("[{}]\n", rows.join(",\n"))).unwrap();
    }
    print_table(&cases, &params, &kept);
}

/// Every training case: the peers' NE_psi, each hypothesis' alone, and the bank's weights.
fn run_cases(bases: &[battery::Base], params: &PipelineParams, tuned: &battery::TunedHdr) -> Vec<Case> {
    let params = *params;
    let mut cases = Vec::new();
    for b in bases.iter().filter(|b| b.training) {
        for pr in battery::profiles().iter().filter(|p| p.training) {
            let log = gyrodrift::sim::inject(&b.log, &pr.errors).unwrap();
            let prep = Prepared::new(&log, None, &params.still).unwrap();
            let Ok(reference) = prep.reference() else { continue };
            let peers: Vec<f64> = prep
                .score_all(&standard_methods(&params, Some(tuned.for_base(&b.name))))
                .unwrap()
                .iter()
                .map(|s| s.ne_psi_deg_per_min)
                .collect();
            let bl = &prep.blocks;
            let run = |only: Option<usize>| {
                let mut f = Pipeline::new(params, 0.0, params.prior_bias_sigma_dps, prep.lead_in_end_s()).unwrap();
                if let Some(k) = only {
                    f.restrict(&[k]);
                }
                let psi: Vec<f64> =
                    (0..bl.len()).map(|i| f.update(bl.time_s[i], bl.rate_dps[i], bl.still[i]).unwrap().heading_deg).collect();
                (psi, f.weight_sums().iter().map(|w| w / bl.len() as f64).collect::<Vec<f64>>())
            };
            let ne: Vec<f64> = (0..N_MODELS)
                .map(|k| {
                    let s = gyrodrift::metrics::score(&bl.time_s, &run(Some(k)).0, reference).unwrap();
                    gyrodrift::metrics::ne_psi(s.e_psi_deg, prep.duration_min)
                })
                .collect();
            cases.push(Case { name: format!("{} / {}", b.name, pr.name), peers, ne, share: run(None).1 });
        }
    }
    cases
}

/// The table of docs/pipeline.md: the bank against three oracles over its hypotheses.
fn print_table(cases: &[Case], params: &PipelineParams, kept: &[usize]) {
    println!(
        "| on the {} training cases | within 1.25x + 0.05 | worse than 2x + 0.05 | worse than raw | worst | mean NE_psi |",
        cases.len()
    );
    println!("|---|---:|---:|---:|---:|---:|");
    // Each pick in the pipeline's column, counted by the battery's own summary.
    let row = |label: &str, pick: &dyn Fn(&Case) -> f64| {
        let rows: Vec<CaseRow> = cases
            .iter()
            .map(|c| {
                let mut ne = c.peers.clone();
                ne[PIPELINE] = pick(c);
                CaseRow::new(c.name.clone(), String::new(), true, false, 0.0, ne)
            })
            .collect();
        let s = summarize(&rows.iter().collect::<Vec<_>>()).expect("training cases");
        let pct = 100.0 * s.n_within as f64 / s.n_cases as f64;
        println!(
            "| {label} | {} ({pct:.0} %) | {} | {} | {:.2}x | {:.3} |",
            s.n_within, s.n_over_2x, s.n_worse_than_raw, s.worst_ratio, s.mean[PIPELINE]
        );
    };
    row("the pipeline (the bank, weighed by likelihood)", &|c| c.peers[PIPELINE]);
    let best = |c: &Case| kept.iter().map(|&k| c.ne[k]).fold(f64::INFINITY, f64::min);
    row("the best hypothesis per case, chosen in hindsight (an oracle)", &best);
    // One hypothesis per base: the one within 1.25x on most of its profiles.
    let base_of = |c: &Case| c.name.split(" / ").next().unwrap().to_string();
    let per_base = |c: &Case| {
        let same: Vec<&Case> = cases.iter().filter(|d| base_of(d) == base_of(c)).collect();
        let score = |k: usize| same.iter().filter(|d| d.ne[k] <= 1.25 * best_peer(&d.peers) + 0.05).count();
        let k = kept.iter().copied().rev().max_by_key(|&k| score(k)).unwrap();
        c.ne[k]
    };
    row("the best hypothesis per base, one for all its profiles (an oracle that knows the drive)", &per_base);
    let fixed = *kept.iter().rev().max_by_key(|&&k| cases.iter().filter(|c| c.ne[k] <= 1.25 * best_peer(&c.peers) + 0.05).count()).unwrap();
    let (walk, road, tau) = params.hypothesis(fixed);
    let label = format!("the best single fixed hypothesis (walk {walk:.0e}, road {road} deg/s, warm-up {tau} s)");
    row(&label, &|c| c.ne[fixed]);
}
