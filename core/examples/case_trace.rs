#![allow(clippy::needless_range_loop)]
//! Prints one simulated battery case's bias over time: the truth (the same drive with an
//! ideal gyro subtracted), the pipeline (causal, smoothed) and HDR's drift estimate.
//! `cargo run --release --example case_trace -- BASE PROFILE` (BASE as `gyrodrift battery` names it).
//! `ERR='{"bias_dps":0.15,"warmup_dps":0.86,"warmup_tau_s":300}'` replaces the profile's
//! errors (JSON, the keys of `sim::GyroErrors`), so a probe drive's `# description:` with
//! `cfg:SCENARIO:MINUTES:SEED` traces with its truth.
use gyrodrift::pipeline::{PipelineParams, PipelineTrace};
use gyrodrift::{battery, eval::Prepared, hdr, preprocess::block_average_1hz, sim, Column};
fn main() {
    let a: Vec<String> = std::env::args().collect();
    if a[1].ends_with(".csv") {
        return trace_csv(&a);
    }
    // BASE is a battery base, or `cfg:SCENARIO:MINUTES:SEED` for a CRS03 drive as the samples make.
    let (cfg, base_log) = if let Some(c) = a[1].strip_prefix("cfg:") {
        let p: Vec<&str> = c.split(':').collect();
        let cfg = sim::DriveConfig { scenario: p[0].parse().unwrap(), minutes: p[1].parse().unwrap(), seed: p[2].parse().unwrap() };
        (cfg, sim::drive::simulate_drive(&cfg))
    } else {
        let base = battery::simulated_bases(20.0).into_iter().find(|b| b.name == a[1]).expect("base");
        let parts: Vec<&str> = a[1].split('-').collect();
        let cfg = sim::DriveConfig { scenario: parts[1].parse().unwrap(), minutes: 20.0, seed: parts[3].parse().unwrap() };
        (cfg, base.log)
    };
    let mut prof = battery::profiles().into_iter().find(|p| p.name == a[2]).expect("profile");
    if let Ok(j) = std::env::var("ERR") {
        prof.errors = serde_json::from_str(&j).expect("ERR: gyro errors as JSON");
    }
    // Same seed, same road: an ideal gyro gives the true rate.
    let ideal = sim::GyroSpec::ideal();
    let truth = sim::drive::simulate_drive_with(&cfg, &ideal);
    let log = sim::inject(&base_log, &prof.errors).unwrap();
    let skip = base_log.len() - log.len();
    let t = log.time_s();
    let err: Vec<f64> =
        log.column(Column::GyroDps).unwrap().iter().zip(&truth.column(Column::GyroDps).unwrap()[skip..]).map(|(g, w)| g - w).collect();
    let true_bias = block_average_1hz(t, &err);
    let road = block_average_1hz(t, &truth.column(Column::GyroDps).unwrap()[skip..]);
    let prep = Prepared::new(&log, None, &Default::default()).unwrap();
    let tr = prep.pipeline_trace(&Default::default()).unwrap();
    let h = hdr::run(&log, &Default::default()).unwrap();
    let drift = h.trace.drift_estimate_dps();
    let mut f =
        gyrodrift::pipeline::Pipeline::new(Default::default(), 0.0, PipelineParams::default().prior_bias_sigma_dps, prep.lead_in_end_s())
            .unwrap();
    let mut n_straight = 0;
    let mut w = Vec::new();
    let mut straight_road = Vec::new();
    for i in 0..prep.blocks.len() {
        let o = f.update(prep.blocks.time_s[i], prep.blocks.rate_dps[i], prep.blocks.still[i]).unwrap();
        n_straight += o.straight as usize;
        w.push(f.weights());
        if o.straight {
            straight_road.push((prep.blocks.time_s[i], road.rate_dps.get(i).copied().unwrap_or(f64::NAN)));
        }
    }
    println!("straight blocks {n_straight} of {}", prep.blocks.len());
    let step: usize = a.get(3).map_or(60, |s| s.parse().unwrap());
    // The true road rate on the blocks the pipeline took as straight, per window of `step` s.
    for c in straight_road.chunk_by(|x, y| (x.0 / step as f64) as i64 == (y.0 / step as f64) as i64) {
        let m = c.iter().map(|x| x.1).sum::<f64>() / c.len() as f64;
        println!("straight {:6.0} n {:3} true road rate mean {:7.4}", c[0].0, c.len(), m);
    }
    if std::env::var("HEADINGS").is_ok() {
        // Heading error of the causal pipeline: its heading less the true rate's integral.
        let mut psi_true = 0.0;
        for i in 0..tr.time_s.len() {
            let dt = if i == 0 { 0.0 } else { tr.time_s[i] - tr.time_s[i - 1] };
            psi_true += road.rate_dps.get(i).copied().unwrap_or(0.0) * dt;
            println!("E {:.0} {:.3} stop {} bias {:.4}", tr.time_s[i], tr.heading_deg[i] - psi_true, tr.stop[i] as u8, tr.bias_dps[i]);
        }
        return;
    }
    print_trace(&tr, &w, &prep, &true_bias.rate_dps, &drift, h.eps0_dps, step);
}

/// Every `step` s: the bank's weight by warm-up, walk and road, the rate, the true bias, the
/// pipeline's (causal, smoothed) and HDR's.
fn print_trace(tr: &PipelineTrace, w: &[Vec<f64>], prep: &Prepared, true_bias: &[f64], drift: &[f64], eps0_dps: f64, step: usize) {
    for i in (0..tr.time_s.len()).step_by(step) {
        println!(
            "{:6.0} warm {:.2} {:.2} {:.2} w {:.2} {:.2} {:.2} road {:.2} {:.2} {:.2} stop {} rate {:8.3} true {:7.4} pipe {:7.4} +- {:6.4} smooth {:7.4} hdr {:7.4}",
            tr.time_s[i],
            (0..w[i].len()).filter(|j| j % 3 == 0).map(|j| w[i][j]).sum::<f64>(),
            (0..w[i].len()).filter(|j| j % 3 == 1).map(|j| w[i][j]).sum::<f64>(),
            (0..w[i].len()).filter(|j| j % 3 == 2).map(|j| w[i][j]).sum::<f64>(),
            w[i][..9].iter().sum::<f64>(),
            w[i][18..27].iter().sum::<f64>(),
            w[i][36..].iter().sum::<f64>(),
            (0..w[i].len()).filter(|j| (j / 3) % 3 == 0).map(|j| w[i][j]).sum::<f64>(),
            (0..w[i].len()).filter(|j| (j / 3) % 3 == 1).map(|j| w[i][j]).sum::<f64>(),
            (0..w[i].len()).filter(|j| (j / 3) % 3 == 2).map(|j| w[i][j]).sum::<f64>(),
            tr.stop[i] as u8,
            prep.blocks.rate_dps[i],
            true_bias[i],
            tr.bias_dps[i],
            tr.bias_sigma_dps[i],
            tr.bias_smoothed_dps[i],
            drift[i] + eps0_dps
        );
    }
}

/// A recorded log (CSV v1) with a profile: no truth, HDR's estimate beside the pipeline's.
fn trace_csv(a: &[String]) {
    let base = gyrodrift::parse_log(std::fs::File::open(&a[1]).unwrap()).unwrap();
    let prof = battery::profiles().into_iter().find(|p| p.name == a[2]).expect("profile");
    let log = sim::inject(&base, &prof.errors).unwrap();
    let prep = Prepared::new(&log, None, &Default::default()).unwrap();
    // The injected error per block (the log less the recording).
    let skip = base.len() - log.len();
    let g = log.column(Column::GyroDps).unwrap();
    let inj: Vec<f64> = g.iter().zip(&base.column(Column::GyroDps).unwrap()[skip..]).map(|(a, b)| a - b).collect();
    let inj = block_average_1hz(log.time_s(), &inj).rate_dps;
    let tr = prep.pipeline_trace(&Default::default()).unwrap();
    let h = hdr::run(&log, &Default::default()).unwrap();
    let drift = h.trace.drift_estimate_dps();
    let mut f =
        gyrodrift::pipeline::Pipeline::new(Default::default(), 0.0, PipelineParams::default().prior_bias_sigma_dps, prep.lead_in_end_s())
            .unwrap();
    let step: usize = a.get(3).map_or(60, |s| s.parse().unwrap());
    if std::env::var("HEADINGS").is_ok() {
        for i in 0..tr.time_s.len() {
            println!("H {} {} {} {}", tr.time_s[i], tr.heading_deg[i], prep.blocks.rate_dps[i], tr.bias_dps[i]);
        }
        return;
    }
    for i in 0..prep.blocks.len() {
        let o = f.update(prep.blocks.time_s[i], prep.blocks.rate_dps[i], prep.blocks.still[i]).unwrap();
        if i % step == 0 {
            println!(
                "{:7.0} w {:?} r {:?} still {} stop {} straight {} rate {:8.3} inj {:7.4} pipe {:7.4} +- {:6.4} bank {:7.4} smooth {:7.4} hdr {:7.4}",
                tr.time_s[i] - tr.time_s[0],
                (0..5).map(|k| (f.weights()[k * 9..k * 9 + 9].iter().sum::<f64>() * 100.0).round()).collect::<Vec<_>>(),
                (0..3)
                    .map(|k| ((0..45).filter(|j| (j / 3) % 3 == k).map(|j| f.weights()[j]).sum::<f64>() * 100.0).round())
                    .collect::<Vec<_>>(),
                prep.blocks.still[i] as u8,
                o.stop as u8,
                o.straight as u8,
                prep.blocks.rate_dps[i],
                inj.get(i).copied().unwrap_or(f64::NAN),
                tr.bias_dps[i],
                tr.bias_sigma_dps[i],
                o.bias_dps,
                tr.bias_smoothed_dps[i],
                drift[i] + h.eps0_dps
            );
        }
    }
}
