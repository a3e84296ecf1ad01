//! The pipeline on the shipped simulated drives (known truth, CRS03-class gyros warming up
//! after a 20 s lead-in): far below raw integration, causal and smoothed. Table-III HDR is
//! better on these drives (a documented miss, docs/pipeline.md).

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
    let (mut raw, mut smooth, mut pipe) = (0.0, 0.0, 0.0);
    for l in &logs {
        let r = pipeline::run(l, &PipelineParams::default()).unwrap().result.unwrap();
        raw += r.NE_psi_raw_deg_per_min;
        smooth += r.NE_psi_pipeline_smoothed_deg_per_min;
        pipe += r.NE_psi_pipeline_deg_per_min;
    }
    let n = logs.len() as f64;
    (raw / n, smooth / n, pipe / n)
}

#[test]
fn pipeline_beats_raw_on_the_simulated_test_drives() {
    let (raw, smooth, pipe) = means("test");
    assert_eq!(drives("test").len(), 5);
    // Measured: raw 1.93, pipeline 0.79, smoothed 0.79 deg/min (1.80, 0.47, 0.57 before the
    // simulated drivers swayed as the recorded ones do).
    assert!(pipe < raw / 2.0, "test drives: pipeline {pipe:.4} vs raw {raw:.4} deg/min");
    assert!(smooth < raw / 2.0, "test drives: smoothed {smooth:.4} vs raw {raw:.4} deg/min");
}

#[test]
fn pipeline_trace_is_aligned_and_stops_pin_the_bias() {
    let logs = drives("train");
    let run = pipeline::run(&logs[0], &PipelineParams::default()).unwrap();
    let tr = &run.trace;
    assert_eq!(run.still_source, gyrodrift::still::StillSource::Speed);
    assert!(tr.stop.iter().filter(|&&s| s).count() > 10, "a city drive has stops");
    // After a stop the bias is known better than before it.
    let after_stops: Vec<usize> = (1..tr.time_s.len() - 1).filter(|&i| tr.stop[i] && !tr.stop[i + 1]).collect();
    assert!(!after_stops.is_empty());
    for &i in &after_stops {
        assert!(tr.bias_sigma_dps[i + 1] < 0.05, "sigma after the stop at block {i}: {}", tr.bias_sigma_dps[i + 1]);
    }
    // Aligned: equal to the reference at the first scored reference sample.
    let reference = gyrodrift::metrics::Reference::from_log(&logs[0]).unwrap();
    let s = gyrodrift::metrics::score(&tr.time_s, &tr.heading_deg, &reference).unwrap();
    assert!(s.shift_deg.abs() < 1e-9, "shift {}", s.shift_deg);
}

/// The summary a drive without a reference prints is the scored run's own end figures, and
/// the heading it turned is the truth's within the run's score: on City 1 with its
/// reference and with the reference column dropped.
#[test]
fn the_summary_is_the_runs_end_with_or_without_a_reference() {
    let log = &drives("train")[0];
    let run = pipeline::run(log, &PipelineParams::default()).unwrap();
    let (s, r) = (run.summary(log.duration_min()), run.result.as_ref().unwrap());
    assert_eq!(
        (s.stop_s, s.final_bias_dps, s.final_bias_sigma_dps, s.still_source),
        (r.stop_s, r.final_bias_dps, r.final_bias_sigma_dps, r.still_source)
    );
    let reference = gyrodrift::metrics::Reference::from_log(log).unwrap();
    let (t, h) = (&run.trace.time_s, &run.trace.heading_deg);
    // Over the reference's span (it starts once the car moves) the heading turned is the
    // truth's within a few times the run's mean error.
    let (rt, rh) = (&reference.time_s, &reference.heading_deg);
    let (a, b) = (rt[0], rt[rt.len() - 1].min(t[t.len() - 1]));
    let at = |x: &[f64], y: &[f64], v: f64| gyrodrift::metrics::value_at(x, y, v);
    let (turned, truth) = (at(t, h, b) - at(t, h, a), at(rt, rh, b) - at(rt, rh, a));
    assert!((turned - truth).abs() < 4.0 * r.E_psi_pipeline_deg + 5.0, "{turned} against {truth}");
    assert!((s.heading_change_deg - (h[h.len() - 1] - h[0])).abs() < 1e-9);
    // The same drive without its reference: nothing scored, the same estimate.
    let mut bare = log.clone();
    bare.drop_column(gyrodrift::log::Column::RefHeadingDeg);
    assert!(!bare.has_reference() && log.has_reference());
    let unscored = pipeline::run(&bare, &PipelineParams::default()).unwrap();
    assert!(unscored.result.is_err());
    let u = unscored.summary(bare.duration_min());
    // Equal but for the rounding of the scored trace's alignment shift (an ulp of 562 deg).
    assert_eq!(
        (u.stop_s, u.final_bias_dps, u.final_bias_sigma_dps, u.heading_change_sigma_deg),
        (s.stop_s, s.final_bias_dps, s.final_bias_sigma_dps, s.heading_change_sigma_deg)
    );
    assert!(
        (u.heading_change_deg - s.heading_change_deg).abs() < 1e-9
            && (u.heading_change_smoothed_deg - s.heading_change_smoothed_deg).abs() < 1e-9
    );
}
