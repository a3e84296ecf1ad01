//! The pipeline's result does not depend on where the log's time starts: a log stamped in
//! epoch seconds gives what the same log from 0 gives (its decisions run on `clock_s`).

use super::*;
use crate::eval::Prepared;
use crate::Column;

/// Epoch seconds of a 2025 drive: rounding of times this large is about 2e-7 s.
const EPOCH_S: f64 = 1_763_892_000.0;

fn shifted(log: &crate::DriveLog, by_s: f64) -> crate::DriveLog {
    let mut out = log.clone();
    for t in out.column_mut(Column::TimeS).unwrap() {
        *t += by_s;
    }
    out
}

fn city_without_lead_in() -> crate::DriveLog {
    let mut log =
        crate::sim::drive::simulate_drive(&crate::sim::DriveConfig { scenario: crate::sim::Scenario::City, minutes: 8.0, seed: 3 });
    log.meta.bias_s = Some(0.0);
    log
}

/// The batch trace's values, all but the stamps.
fn values(log: &crate::DriveLog, params: &PipelineParams) -> Vec<[f64; 5]> {
    let prep = Prepared::new(log, params.bias_s, &params.still).unwrap();
    let tr = prep.pipeline_trace(params).unwrap();
    (0..tr.time_s.len())
        .map(|i| [tr.heading_deg[i], tr.heading_smoothed_deg[i], tr.bias_dps[i], tr.bias_sigma_dps[i], f64::from(u8::from(tr.stop[i]))])
        .collect()
}

/// The stream's heading after every row.
fn streamed(log: &crate::DriveLog, params: PipelineParams) -> Vec<f64> {
    let (t, w, v) = (log.time_s(), log.column(Column::GyroDps).unwrap(), log.column(Column::SpeedMps));
    let mut s = PipelineStream::new(params).unwrap();
    (0..t.len()).map(|i| s.update(t[i], w[i], v.map_or(f64::NAN, |v| v[i])).unwrap()).collect()
}

#[test]
fn an_epoch_stamped_log_gives_the_same_pipeline_as_from_zero() {
    let with_lead_in =
        crate::sim::drive::simulate_drive(&crate::sim::DriveConfig { scenario: crate::sim::Scenario::City, minutes: 8.0, seed: 3 });
    for log in [with_lead_in, city_without_lead_in()] {
        let params = PipelineParams { bias_s: Some(log.bias_s(None)), ..Default::default() };
        let (from_zero, epoch) = (values(&log, &params), values(&shifted(&log, EPOCH_S), &params));
        assert_eq!(from_zero.len(), epoch.len());
        for (i, (a, b)) in from_zero.iter().zip(&epoch).enumerate() {
            assert_eq!(a, b, "block {i}");
        }
        assert_eq!(streamed(&log, params), streamed(&shifted(&log, EPOCH_S), params));
        // And a start that is not a whole second.
        assert_eq!(values(&log, &params), values(&shifted(&log, 37.25), &params));
    }
}
