//! The pipeline live: rows in (time, raw yaw rate, speed), the heading out per row. Rows
//! are gathered into the batch path's 1 Hz blocks (block k holds the rows with
//! floor(t - t0) = k, stamped with its last row: `preprocess::blocks_1hz`), a block is
//! judged still as `still::blocks` judges it, and each block updates the [`Pipeline`] when
//! the first row of the next one arrives. Between block ends the heading moves with the
//! open block's mean rate so far less the bias; each closed block's output (heading, bias,
//! their sigmas, stop) is the batch pipeline's at that block, bit for bit (tested).
//!
//! Stillness: once a row has brought a speed, by speed (every speed of the block below
//! `still_speed_mps`; a block without one is moving), as the batch path does for a log with
//! a speed column. Before that, by the gyro alone, as the batch path does for a log without
//! speed or wheels: the declared lead-in's blocks stand, and after it `still::GyroStill`
//! (the batch path's own) judges each block against the lead-in (its spread, and the
//! agreement of the last block means). Without a usable lead-in (`GyroStill::reference`)
//! and without speeds no block after the lead-in is still, as in the batch path. (The
//! batch path's third source, wheel travel, is not streamed.)
//! A declared lead-in ends early at the first block whose speeds show the vehicle moving,
//! as `Prepared::lead_in_end_s` ends it for the batch path.

use super::{Pipeline, PipelineOutput, PipelineParams};
use crate::error::{Error, Result};

/// The open block: its index, rows, sum of rates and of their squares, the largest |speed|
/// and how many speeds.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Copy, Default)]
struct Open {
    k: f64,
    n: usize,
    sum_dps: f64,
    sum2: f64,
    last_s: f64,
    speed_max_mps: f64,
    speeds: usize,
}

/// The streaming pipeline on raw rows (see the module's doc).
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone)]
pub struct PipelineStream {
    params: PipelineParams,
    filter: Option<Pipeline>,
    t0_s: f64,
    open: Open,
    /// The last closed block's output and stamp, and the bias after it (what the open block
    /// is integrated with: the batch path's bias before that block).
    last: Option<(PipelineOutput, f64)>,
    bias_dps: f64,
    heading_deg: f64,
    /// The gyro-only detector (before a speed is seen).
    gyro_still: crate::still::GyroStill,
    /// A row has brought a finite speed: stillness is judged by speed from then on.
    speed_seen: bool,
    /// The heading's blend with the experts', as the batch path blends it.
    blend: super::blend::Blend,
}

impl PipelineStream {
    /// The settings as for the batch pipeline (`bias_s`: the declared stationary lead-in
    /// from the first row, None = 20 s).
    pub fn new(params: PipelineParams) -> Result<Self> {
        params.validate()?;
        Ok(PipelineStream {
            params,
            filter: None,
            t0_s: 0.0,
            open: Open::default(),
            last: None,
            bias_dps: 0.0,
            heading_deg: 0.0,
            gyro_still: Default::default(),
            speed_seen: false,
            blend: super::blend::Blend::of(&params),
        })
    }

    /// One row: time (s, increasing), raw yaw rate (deg/s) and speed (m/s; NaN when the row
    /// has none). Returns the heading (deg, from 0 at the first row). An error (a non-finite
    /// time or rate, a time that does not increase) leaves the state as it was.
    pub fn update(&mut self, time_s: f64, rate_dps: f64, speed_mps: f64) -> Result<f64> {
        if !(time_s.is_finite() && rate_dps.is_finite()) || (self.open.n > 0 && !(time_s > self.open.last_s)) {
            return Err(Error::data(format!("pipeline row at {time_s} s: rate {rate_dps} deg/s, time must be finite and increase")));
        }
        if self.filter.is_none() {
            let lead_in_end_s = super::clock_s(time_s + self.lead_in_s(), time_s);
            self.filter = Some(Pipeline::new(self.params, 0.0, self.params.prior_bias_sigma_dps, lead_in_end_s)?);
            self.t0_s = time_s;
        }
        self.speed_seen |= speed_mps.is_finite();
        let k = crate::preprocess::block_index(time_s, self.t0_s);
        if self.open.n > 0 && k != self.open.k {
            self.close()?;
        }
        let o = &mut self.open;
        if o.n == 0 {
            *o = Open { k, ..Open::default() };
        }
        o.n += 1;
        o.sum_dps += rate_dps;
        o.sum2 += rate_dps * rate_dps;
        o.last_s = time_s;
        if speed_mps.is_finite() {
            o.speed_max_mps = o.speed_max_mps.max(speed_mps.abs());
            o.speeds += 1;
        }
        self.heading_deg = self.provisional_heading_deg();
        Ok(self.heading_deg)
    }

    /// The declared stationary lead-in from the first row, s.
    fn lead_in_s(&self) -> f64 {
        self.params.bias_s.unwrap_or(crate::log::DEFAULT_BIAS_S)
    }

    /// Closes the open block: the pipeline's update on it.
    fn close(&mut self) -> Result<()> {
        let o = self.open;
        let opts = &self.params.still;
        let still = match self.speed_seen {
            true => opts.still_by_speed(o.speeds, o.speed_max_mps),
            false => self.gyro_still.update(opts, o.k < self.lead_in_s(), o.n, o.sum_dps, o.sum2),
        };
        if let Some(filter) = self.filter.as_mut() {
            // Decisions on the pipeline's clock, as `run_blocks` makes them.
            let at_s = super::clock_s(o.last_s, self.t0_s);
            if opts.moving_by_speed(o.speeds, o.speed_max_mps) {
                filter.end_lead_in(at_s);
            }
            filter.gyro_stills = !self.speed_seen;
            let rate_dps = o.sum_dps / o.n as f64;
            let settled_dps = filter.settled_bias_dps();
            let bank = filter.update(at_s, rate_dps, still)?;
            let out = self.blend.update(at_s >= filter.lead_in_end_s(), at_s, rate_dps, bank, settled_dps, filter.quiet())?;
            self.last = Some((out, o.last_s));
            self.bias_dps = filter.bias().0;
        }
        self.open.n = 0;
        Ok(())
    }

    /// The last closed block's heading, moved by the open block's mean rate less the bias
    /// (over the time on the pipeline's clock).
    fn provisional_heading_deg(&self) -> f64 {
        let o = &self.open;
        let dt_s = |stamp_s| super::clock_s(o.last_s, self.t0_s) - super::clock_s(stamp_s, self.t0_s);
        match self.last {
            Some((out, stamp_s)) => out.heading_deg + (o.sum_dps / o.n as f64 - self.bias_dps) * dt_s(stamp_s),
            None => 0.0,
        }
    }

    /// The heading after the last row, deg.
    pub fn heading_deg(&self) -> f64 {
        self.heading_deg
    }

    /// The last closed block's output (bias, its sigma, the heading's sigma, stop), if any.
    pub fn last_block(&self) -> Option<PipelineOutput> {
        self.last.map(|(o, _)| o)
    }
}

/// The live pipeline saved and resumed (`snapshot`): the settings checked as a new
/// estimator's, and the bank as many hypotheses as the settings make.
#[cfg(feature = "snapshot")]
impl crate::snapshot::Resumable for PipelineStream {
    const KIND: &'static str = "PipelineEstimator";
    fn restored(self) -> Result<Self> {
        self.params.validate()?;
        if self.filter.as_ref().is_some_and(|f| !f.is_whole_bank()) {
            return Err(Error::data("restoring a PipelineEstimator: the saved bank is not the settings' (start afresh)"));
        }
        Ok(self)
    }
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::Prepared;

    /// Streams `log` (NaN speed where it has no speed column) and checks that every closed
    /// block's output equals the batch trace's (unaligned) at that block, bit for bit, and,
    /// with the bank's heading alone (no blend, which moves a block's heading
    /// only when it closes), at a block's last row, the heading where the block brought no
    /// stop. Returns the batch path's still source.
    fn assert_stream_equals_batch(log: &crate::DriveLog) -> crate::still::StillSource {
        let params = PipelineParams { bias_s: Some(log.bias_s(None)), ..Default::default() };
        assert_stream_equals_batch_with(log, PipelineParams { blend_sigmas: 0.0, ..params }, true);
        assert_stream_equals_batch_with(log, params, false)
    }

    fn assert_stream_equals_batch_with(log: &crate::DriveLog, params: PipelineParams, rows: bool) -> crate::still::StillSource {
        let prep = Prepared::new(log, params.bias_s, &params.still).unwrap();
        let batch = prep.pipeline_trace(&params).unwrap();
        let t = log.time_s();
        let w = log.column(crate::Column::GyroDps).unwrap();
        let v = log.column(crate::Column::SpeedMps);
        let mut s = PipelineStream::new(params).unwrap();
        let mut closed = Vec::new();
        let mut at_last_row = Vec::new();
        for i in 0..t.len() {
            let before = s.last.map(|(_, stamp)| stamp);
            let psi = s.update(t[i], w[i], v.map_or(f64::NAN, |v| v[i])).unwrap();
            if i + 1 < t.len() && (t[i + 1] - t[0]).floor() != (t[i] - t[0]).floor() {
                at_last_row.push(psi);
            }
            if let Some((o, stamp)) = s.last.filter(|(_, stamp)| Some(*stamp) != before) {
                closed.push((stamp, o));
            }
        }
        assert_eq!(closed.len(), batch.time_s.len() - 1, "every block but the open last one");
        for (j, (stamp, o)) in closed.iter().enumerate() {
            assert_eq!(*stamp, batch.time_s[j]);
            assert_eq!(o.heading_deg, batch.heading_deg[j], "block {j}");
            assert_eq!(o.bias_dps, batch.bias_dps[j]);
            assert_eq!(o.heading_sigma_deg, batch.heading_sigma_deg[j]);
            assert_eq!(o.stop, batch.stop[j], "block {j}");
        }
        let lead_in_blocks = batch.time_s.iter().filter(|&&b| b < prep.lead_in_end_s()).count();
        assert!(batch.stop.iter().skip(lead_in_blocks).any(|&s| s), "the drive has stops after its lead-in");
        for (j, psi) in at_last_row.iter().enumerate().skip(1).filter(|(j, _)| rows && !batch.stop[*j]) {
            assert!((psi - batch.heading_deg[j]).abs() < 1e-9, "block {j}: {psi} against {}", batch.heading_deg[j]);
        }
        prep.blocks.source
    }

    /// The log's time and gyro alone, with this declared lead-in.
    fn gyro_alone(full: &crate::DriveLog, bias_s: Option<f64>) -> crate::DriveLog {
        let mut log = crate::DriveLog::with_columns(&[crate::Column::GyroDps]);
        log.meta.bias_s = bias_s;
        for (&t, &w) in full.time_s().iter().zip(full.column(crate::Column::GyroDps).unwrap()) {
            log.push_row(&[(crate::Column::TimeS, t), (crate::Column::GyroDps, w)]);
        }
        log
    }

    fn city(minutes: f64) -> crate::DriveLog {
        crate::sim::drive::simulate_drive(&crate::sim::DriveConfig { scenario: crate::sim::Scenario::City, minutes, seed: 3 })
    }

    /// On a simulated drive (a speed in every row, stops, a declared lead-in) the stream
    /// judges stillness by speed and gives the batch pipeline's headings.
    #[test]
    fn the_stream_gives_the_batch_pipelines_headings() {
        assert_eq!(assert_stream_equals_batch(&city(6.0)), crate::still::StillSource::Speed);
    }

    /// The same drive with its gyro alone: both judge stillness by the gyro against the
    /// lead-in's spread, and still agree (the stops are found by the gyro).
    #[test]
    fn without_speed_the_stream_judges_stops_by_the_gyro_as_the_batch_path_does() {
        let full = city(6.0);
        let log = gyro_alone(&full, full.meta.bias_s);
        assert_eq!(assert_stream_equals_batch(&log), crate::still::StillSource::Gyro);
    }

    /// A declared lead-in (60 s) longer than the standing (20 s): both paths end it at the
    /// first block the speed shows moving, and still agree.
    #[test]
    fn a_declared_lead_in_longer_than_the_standing_ends_where_the_speed_moves() {
        let mut log = city(6.0);
        log.meta.bias_s = Some(60.0);
        let prep = Prepared::new(&log, None, &PipelineParams::default().still).unwrap();
        let t0 = log.time_s()[0];
        assert!(prep.lead_in_end_s() < t0 + 25.0, "ends at {}", prep.lead_in_end_s() - t0);
        assert_eq!(assert_stream_equals_batch(&log), crate::still::StillSource::Speed);
    }

    /// Rows without speed and no lead-in: nothing to judge stillness by, never a stop
    /// (the batch path's `StillSource::None`).
    #[test]
    fn without_speed_or_lead_in_no_block_is_still() {
        let mut s = PipelineStream::new(PipelineParams { bias_s: Some(0.0), ..Default::default() }).unwrap();
        for i in 0..200 {
            s.update(i as f64 * 0.1, 0.3, f64::NAN).unwrap();
            assert!(s.last_block().is_none_or(|o| !o.stop), "row {i}");
        }
        // The same rows with a 5 s lead-in: after it, the steady gyro reads as standing.
        let mut s = PipelineStream::new(PipelineParams { bias_s: Some(5.0), ..Default::default() }).unwrap();
        let mut stops = 0;
        for i in 0..200 {
            let w = 0.3 + if i % 2 == 0 { 0.01 } else { -0.01 } + 0.005 * (0.37 * i as f64).sin();
            s.update(i as f64 * 0.1, w, f64::NAN).unwrap();
            stops += s.last_block().is_some_and(|o| o.stop && i > 70) as usize;
        }
        assert!(stops > 0);
    }

    /// Without speed and with a lead-in too short to judge the gyro against (2 s: 2 blocks,
    /// 3 needed): the lead-in's blocks stand, then the white-noise test alone finds the
    /// standings (each within a second of one the speed shows), in both paths alike.
    #[test]
    fn a_lead_in_too_short_for_the_gyro_gives_the_batch_paths_headings() {
        let full = city(6.0);
        let log = gyro_alone(&full, Some(2.0));
        let params = PipelineParams { bias_s: Some(2.0), ..Default::default() };
        let prep = Prepared::new(&log, params.bias_s, &params.still).unwrap();
        assert_eq!(prep.blocks.source, crate::still::StillSource::Gyro);
        let batch = prep.pipeline_trace(&params).unwrap();
        let by_speed = crate::still::blocks(&full, 2.0, &params.still).unwrap();
        let (t, w) = (log.time_s(), log.column(crate::Column::GyroDps).unwrap());
        let mut s = PipelineStream::new(params).unwrap();
        let (mut j, mut stops) = (0, 0);
        for i in 0..t.len() {
            let before = s.last.map(|(_, stamp)| stamp);
            s.update(t[i], w[i], f64::NAN).unwrap();
            if let Some((o, _)) = s.last.filter(|(_, stamp)| Some(*stamp) != before) {
                assert_eq!((o.heading_deg, o.bias_dps, o.stop), (batch.heading_deg[j], batch.bias_dps[j], batch.stop[j]), "block {j}");
                if o.stop && j >= 2 {
                    stops += 1;
                    assert!(by_speed.still[j - 1] || by_speed.still[j], "block {j} stands, the speed says not");
                }
                j += 1;
            }
        }
        assert_eq!(j, batch.time_s.len() - 1);
        assert!(stops > 0);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(100))]
        /// Any rows (irregular steps, rates far beyond a bias, speeds missing, negative or
        /// infinite, bad rows in between): no panic, a bad row refused, every heading finite.
        #[test]
        fn any_rows_give_finite_headings_or_a_refusal(
            rows in proptest::collection::vec((-0.5f64..3.0, -400.0f64..400.0, proptest::prelude::any::<f64>()), 1..600),
        ) {
            let mut s = PipelineStream::new(PipelineParams::default()).unwrap();
            let mut t = 0.0;
            for (dt, rate, speed) in rows {
                t += dt;
                match s.update(t, rate, speed) {
                    Ok(psi) => proptest::prop_assert!(psi.is_finite()),
                    Err(_) => proptest::prop_assert!(dt <= 0.0),
                }
                if dt <= 0.0 {
                    t -= dt; // the refused row's time is not the stream's
                }
            }
            proptest::prop_assert!(s.last_block().is_none_or(|o| o.heading_sigma_deg.is_finite()));
        }
    }

    /// Before any block closes the heading is 0; a bad row is refused and changes nothing.
    #[test]
    fn bad_rows_are_refused_and_leave_the_state() {
        let mut s = PipelineStream::new(PipelineParams::default()).unwrap();
        assert_eq!(s.update(0.0, 0.5, 0.0).unwrap(), 0.0);
        assert_eq!(s.update(0.5, 0.5, 0.0).unwrap(), 0.0);
        for (t, w) in [(0.5, 0.1), (0.2, 0.1), (f64::NAN, 0.1), (0.7, f64::INFINITY)] {
            assert!(s.update(t, w, 0.0).is_err(), "{t} {w}");
        }
        assert_eq!((s.open.n, s.open.last_s), (2, 0.5));
        // A block closes when the next one's first row arrives: 1.0 s opens block 1.
        s.update(1.0, 0.5, 0.0).unwrap();
        assert_eq!(s.last_block().map(|o| o.stop), Some(true));
        assert!(PipelineStream::new(PipelineParams { road_gate_dps: -1.0, ..Default::default() }).is_err());
    }
}
