//! The pipeline on the shipped simulated drives (known truth): on the test drives, which
//! were not used to choose its constants (core/examples/tune_pipeline.rs uses the training
//! drives only), its mean NE_psi is below Table-III HDR's and far below raw integration.

use gyrodrift::pipeline::{self, PipelineParams};
use std::path::PathBuf;

fn drives(set: &str) -> Vec<gyrodrift::DriveLog> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs").join(set);
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    paths.sort();
    paths.iter().map(|p| gyrodrift::parse_log(std::fs::File::open(p).unwrap()).unwrap()).collect()
}

fn means(set: &str) -> (f64, f64, f64) {
    let logs = drives(set);
    let (mut raw, mut hdr, mut pipe) = (0.0, 0.0, 0.0);
    for l in &logs {
        let r = pipeline::run(l, &PipelineParams::default()).unwrap().result.unwrap();
        raw += r.NE_psi_raw_deg_per_min;
        hdr += r.NE_psi_hdr_deg_per_min;
        pipe += r.NE_psi_pipeline_deg_per_min;
    }
    let n = logs.len() as f64;
    (raw / n, hdr / n, pipe / n)
}

#[test]
fn pipeline_beats_table_iii_hdr_on_the_simulated_test_drives() {
    let (raw, hdr, pipe) = means("test");
    assert_eq!(drives("test").len(), 5);
    assert!(pipe < hdr, "test drives: pipeline {pipe:.4} vs HDR {hdr:.4} deg/min");
    assert!(pipe < raw / 10.0, "test drives: pipeline {pipe:.4} vs raw {raw:.4} deg/min");
}

#[test]
fn pipeline_trace_is_aligned_and_stops_hold_the_heading() {
    let logs = drives("train");
    let run = pipeline::run(&logs[0], &PipelineParams::default()).unwrap();
    let tr = &run.trace;
    assert_eq!(run.still_source, gyrodrift::still::StillSource::Speed);
    assert!(tr.stop.iter().filter(|&&s| s).count() > 10, "a city drive has stops");
    for i in 1..tr.time_s.len() {
        if tr.stop[i] {
            assert_eq!(tr.heading_deg[i], tr.heading_deg[i - 1], "held at a stop (block {i})");
        }
    }
    // Aligned: equal to the reference at the first scored reference sample.
    let reference = gyrodrift::metrics::Reference::from_log(&logs[0]).unwrap();
    let s = gyrodrift::metrics::score(&tr.time_s, &tr.heading_deg, &reference).unwrap();
    assert!(s.shift_deg.abs() < 1e-9, "shift {}", s.shift_deg);
}
