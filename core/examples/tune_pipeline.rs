//! Chooses the pipeline's Kalman-filter constants on the simulator's TRAINING drives only
//! (never on test or real drives): a grid over road_sigma, bias walk, gate and the
//! temperature prior, scored by mean NE_psi. Run:
//! `cargo run --release -p gyrodrift --example tune_pipeline -- sample-logs/train/*.csv`

use gyrodrift::pipeline::{self, PipelineParams};
use gyrodrift::{metrics, still};

fn main() {
    let logs: Vec<gyrodrift::DriveLog> = std::env::args()
        .skip(1)
        .map(|p| gyrodrift::parse_log(std::fs::File::open(&p).expect("open")).expect("parse"))
        .collect();
    let prepared: Vec<_> = logs
        .iter()
        .map(|l| {
            let p = PipelineParams::default();
            let (b, _) = still::blocks(l, l.bias_s(None), &p.still).expect("blocks");
            (b, metrics::Reference::from_log(l).expect("reference"), l.duration_min())
        })
        .collect();
    let mut rows = Vec::new();
    for road in [0.05, 0.1, 0.2, 0.3, 0.5] {
        for walk in [0.0005, 0.001, 0.002, 0.005, 0.01] {
            for gate in [0.3, 0.564, 1.0] {
                for temp in [0.0, 0.02] {
                    let p = PipelineParams { road_sigma_dps: road, bias_walk_dps_per_sqrt_s: walk, gate_dps: gate, temp_coeff_sigma_dps_per_c: temp, ..Default::default() };
                    let mut sum = 0.0;
                    for (l, (b, r, d)) in logs.iter().zip(&prepared) {
                        let (b0, s0) = pipeline::initial_bias(l, &p).expect("bias");
                        let tr = pipeline::run_blocks(b, p, b0, s0).expect("run");
                        sum += metrics::score(&tr.time_s, &tr.heading_deg, r).expect("score").e_psi_deg / d;
                    }
                    rows.push((sum / logs.len() as f64, road, walk, gate, temp));
                }
            }
        }
    }
    rows.sort_by(|a, b| a.0.total_cmp(&b.0));
    println!("mean NE_psi (deg/min)  road_sigma_dps  bias_walk_dps_per_sqrt_s  gate_dps  temp_coeff_sigma");
    for r in rows.iter().take(12) {
        println!("{:>10.4} {:>10} {:>10} {:>8} {:>8}", r.0, r.1, r.2, r.3, r.4);
    }
}
