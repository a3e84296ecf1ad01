//! The bank's ceiling on the battery's training cases: every single hypothesis of the
//! pipeline's bank run alone (causal heading), scored like the battery. The best of them in
//! hindsight per case says whether a better weighing could win a case (some hypothesis
//! does) or whether no hypothesis of the model can (docs/pipeline.md).
//! `cargo run --release --example bank_ceiling -- RECORDED.csv ... > ceiling.json`
//! (the battery's recorded training bases, imported by their recipes).
use gyrodrift::{battery, eval::Prepared, pipeline::Pipeline, pipeline::PipelineParams, pipeline::N_MODELS};

fn main() {
    let files: Vec<String> = std::env::args().skip(1).collect();
    let mut bases: Vec<battery::Base> = files
        .iter()
        .map(|f| {
            let log = gyrodrift::parse_log(std::fs::File::open(f).unwrap()).unwrap();
            let stem = std::path::Path::new(f).file_stem().unwrap().to_string_lossy().into_owned();
            battery::recorded_base(&stem, log)
        })
        .collect();
    bases.extend(battery::simulated_bases(20.0));
    let params = PipelineParams::default();
    let mut out = Vec::new();
    for b in bases.iter().filter(|b| b.training) {
        for pr in battery::profiles().iter().filter(|p| p.training) {
            let log = gyrodrift::sim::inject(&b.log, &pr.errors).unwrap();
            let prep = Prepared::new(&log, None, &params.still).unwrap();
            let Ok(reference) = prep.reference() else { continue };
            let mut ne = Vec::new();
            for k in 0..N_MODELS {
                let mut f = Pipeline::new(params, 0.0, params.prior_bias_sigma_dps, prep.lead_in_end_s()).unwrap();
                f.restrict(&[k]);
                let bl = &prep.blocks;
                let psi: Vec<f64> =
                    (0..bl.len()).map(|i| f.update(bl.time_s[i], bl.rate_dps[i], bl.still[i]).unwrap().heading_deg).collect();
                // A hypothesis the bank never weighs (logw -inf) still runs alone here.
                let s = gyrodrift::metrics::score(&bl.time_s, &psi, reference).unwrap();
                ne.push(gyrodrift::metrics::ne_psi(s.e_psi_deg, prep.duration_min));
            }
            out.push(format!("{{\"base\":\"{}\",\"profile\":\"{}\",\"ne\":{:?}}}", b.name, pr.name, ne));
        }
    }
    println!("[{}]", out.join(",\n"));
}
