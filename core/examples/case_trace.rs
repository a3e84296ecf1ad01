#![allow(clippy::needless_range_loop)]
//! Prints one simulated battery case's bias over time: the truth (the same drive with an
//! ideal gyro subtracted), the pipeline (causal, smoothed) and HDR's drift estimate.
//! `cargo run --release --example case_trace -- BASE PROFILE` (BASE as `gyrodrift battery` names it).
use gyrodrift::{battery, eval::Prepared, hdr, preprocess::block_average_1hz, sim, Column};
fn main() {
    let a: Vec<String> = std::env::args().collect();
    if a[1].ends_with(".csv") {
        return trace_csv(&a);
    }
    let base = battery::simulated_bases(20.0).into_iter().find(|b| b.name == a[1]).expect("base");
    let prof = battery::profiles().into_iter().find(|p| p.name == a[2]).expect("profile");
    // Same seed, same road: an ideal gyro gives the true rate.
    let parts: Vec<&str> = a[1].split('-').collect();
    let seed: u64 = parts[3].parse().unwrap();
    let cfg = sim::DriveConfig { scenario: parts[1].parse().unwrap(), minutes: 20.0, seed };
    let ideal = sim::GyroSpec::ideal();
    let truth = sim::drive::simulate_drive_with(&cfg, &ideal);
    let log = sim::inject(&base.log, &prof.errors).unwrap();
    let skip = base.log.len() - log.len();
    let t = log.time_s();
    let err: Vec<f64> =
        log.column(Column::GyroDps).unwrap().iter().zip(&truth.column(Column::GyroDps).unwrap()[skip..]).map(|(g, w)| g - w).collect();
    let true_bias = block_average_1hz(t, &err);
    let prep = Prepared::new(&log, None, &Default::default()).unwrap();
    let tr = prep.pipeline_trace(&Default::default()).unwrap();
    let h = hdr::run(&log, &Default::default()).unwrap();
    let drift = h.trace.drift_estimate_dps();
    let mut f = gyrodrift::pipeline::Pipeline::new(Default::default(), 0.0, 0.5, prep.lead_in_end_s()).unwrap();
    let mut n_straight = 0;
    let mut w = Vec::new();
    for i in 0..prep.blocks.len() {
        let o = f.update(prep.blocks.time_s[i], prep.blocks.rate_dps[i], prep.blocks.still[i]).unwrap();
        n_straight += o.straight as usize;
        w.push(f.weights());
    }
    println!("straight blocks {n_straight} of {}", prep.blocks.len());
    let step: usize = a.get(3).map_or(60, |s| s.parse().unwrap());
    for i in (0..tr.time_s.len()).step_by(step) {
        println!(
            "{:6.0} w {:.2} {:.2} {:.2} stop {} rate {:8.3} true {:7.4} pipe {:7.4} +- {:6.4} smooth {:7.4} hdr {:7.4}",
            tr.time_s[i],
            w[i][..9].iter().sum::<f64>(),
            w[i][18..27].iter().sum::<f64>(),
            w[i][36..].iter().sum::<f64>(),
            tr.stop[i] as u8,
            prep.blocks.rate_dps[i],
            true_bias.rate_dps[i],
            tr.bias_dps[i],
            tr.bias_sigma_dps[i],
            tr.bias_smoothed_dps[i],
            drift[i] + h.eps0_dps
        );
    }
}

/// A recorded log (CSV v1) with a profile: no truth, HDR's estimate beside the pipeline's.
fn trace_csv(a: &[String]) {
    let base = gyrodrift::parse_log(std::fs::File::open(&a[1]).unwrap()).unwrap();
    let prof = battery::profiles().into_iter().find(|p| p.name == a[2]).expect("profile");
    let log = sim::inject(&base, &prof.errors).unwrap();
    let prep = Prepared::new(&log, None, &Default::default()).unwrap();
    let tr = prep.pipeline_trace(&Default::default()).unwrap();
    let h = hdr::run(&log, &Default::default()).unwrap();
    let drift = h.trace.drift_estimate_dps();
    let mut f = gyrodrift::pipeline::Pipeline::new(Default::default(), 0.0, 0.5, prep.lead_in_end_s()).unwrap();
    let step: usize = a.get(3).map_or(60, |s| s.parse().unwrap());
    for i in 0..prep.blocks.len() {
        let o = f.update(prep.blocks.time_s[i], prep.blocks.rate_dps[i], prep.blocks.still[i]).unwrap();
        if i % step == 0 {
            println!(
                "{:7.0} still {} stop {} straight {} rate {:8.3} pipe {:7.4} +- {:6.4} smooth {:7.4} hdr {:7.4}",
                tr.time_s[i] - tr.time_s[0],
                prep.blocks.still[i] as u8,
                o.stop as u8,
                o.straight as u8,
                prep.blocks.rate_dps[i],
                tr.bias_dps[i],
                tr.bias_sigma_dps[i],
                tr.bias_smoothed_dps[i],
                drift[i] + h.eps0_dps
            );
        }
    }
}
