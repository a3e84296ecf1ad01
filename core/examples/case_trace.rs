//! Prints one battery case's bias estimates over time (pipeline causal and smoothed, HDR's
//! drift estimate) for a simulated base: `cargo run --release --example case_trace -- BASE PROFILE`.
use gyrodrift::{battery, eval::Prepared, hdr, sim::inject};
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let bases = battery::simulated_bases(20.0);
    let base = bases.iter().find(|b| b.name == a[1]).expect("base");
    let prof = battery::profiles().into_iter().find(|p| p.name == a[2]).expect("profile");
    let log = inject(&base.log, &prof.errors).unwrap();
    let params = Default::default();
    let prep = Prepared::new(&log, None, &Default::default()).unwrap();
    let tr = prep.pipeline_trace(&params).unwrap();
    let h = hdr::run(&log, &Default::default()).unwrap();
    let drift = h.trace.drift_estimate_dps();
    for i in (0..tr.time_s.len()).step_by(30) {
        println!("{:6.0} stop {} rate {:8.3} pipe {:7.4} +- {:6.4} smooth {:7.4} hdr {:7.4}", tr.time_s[i], tr.stop[i] as u8, prep.blocks.rate_dps[i], tr.bias_dps[i], tr.bias_sigma_dps[i], tr.bias_smoothed_dps[i], drift[i] + h.eps0_dps);
    }
}
