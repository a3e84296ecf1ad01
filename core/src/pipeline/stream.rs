//! The pipeline live: rows in (time, raw yaw rate, speed), the heading out per row. Rows
//! are gathered into the batch path's 1 Hz blocks (block k holds the rows with
//! floor(t - t0) = k, stamped with its last row: `preprocess::blocks_1hz`), a block is
//! still when every speed in it is below `still_speed_mps` (as `still::blocks` decides from
//! a speed column), and each block updates the [`Pipeline`] when the first row of the next
//! one arrives. Between block ends the heading moves with the open block's mean rate so far
//! less the bias; each closed block's output (heading, bias, their sigmas, stop) is the
//! batch pipeline's at that block, bit for bit (tested).
//!
//! Without any speed no block is still and only straight-road evidence and the declared
//! lead-in teach the bias; the batch path can also judge stillness from wheel travel or from
//! the gyro against its lead-in, which need the whole lead-in first.

use super::{Pipeline, PipelineOutput, PipelineParams};
use crate::error::{Error, Result};

/// The open block: its index, rows, sum of rates, the largest |speed| and how many speeds.
#[derive(Debug, Clone, Copy, Default)]
struct Open {
    k: f64,
    n: usize,
    sum_dps: f64,
    last_s: f64,
    speed_max_mps: f64,
    speeds: usize,
}

/// The streaming pipeline on raw rows (see the module's doc).
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
}

impl PipelineStream {
    /// The settings as for the batch pipeline (`bias_s`: the declared stationary lead-in
    /// from the first row, None = 20 s).
    pub fn new(params: PipelineParams) -> Result<Self> {
        params.validate()?;
        Ok(PipelineStream { params, filter: None, t0_s: 0.0, open: Open::default(), last: None, bias_dps: 0.0, heading_deg: 0.0 })
    }

    /// One row: time (s, increasing), raw yaw rate (deg/s) and speed (m/s; NaN when the row
    /// has none). Returns the heading (deg, from 0 at the first row). An error (a non-finite
    /// time or rate, a time that does not increase) leaves the state as it was.
    pub fn update(&mut self, time_s: f64, rate_dps: f64, speed_mps: f64) -> Result<f64> {
        if !(time_s.is_finite() && rate_dps.is_finite()) || (self.open.n > 0 && !(time_s > self.open.last_s)) {
            return Err(Error::data(format!("pipeline row at {time_s} s: rate {rate_dps} deg/s, time must be finite and increase")));
        }
        if self.filter.is_none() {
            let lead_in_end_s = time_s + self.params.bias_s.unwrap_or(crate::log::DEFAULT_BIAS_S);
            self.filter = Some(Pipeline::new(self.params, 0.0, self.params.prior_bias_sigma_dps, lead_in_end_s)?);
            self.t0_s = time_s;
        }
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
        o.last_s = time_s;
        if speed_mps.is_finite() {
            o.speed_max_mps = o.speed_max_mps.max(speed_mps.abs());
            o.speeds += 1;
        }
        self.heading_deg = self.provisional_heading_deg();
        Ok(self.heading_deg)
    }

    /// Closes the open block: the pipeline's update on it.
    fn close(&mut self) -> Result<()> {
        let o = self.open;
        let still = self.params.still.still_by_speed(o.speeds, o.speed_max_mps);
        if let Some(filter) = self.filter.as_mut() {
            let out = filter.update(o.last_s, o.sum_dps / o.n as f64, still)?;
            self.last = Some((out, o.last_s));
            self.bias_dps = filter.bias().0;
        }
        self.open.n = 0;
        Ok(())
    }

    /// The last closed block's heading, moved by the open block's mean rate less the bias.
    fn provisional_heading_deg(&self) -> f64 {
        let o = &self.open;
        match self.last {
            Some((out, stamp_s)) => out.heading_deg + (o.sum_dps / o.n as f64 - self.bias_dps) * (o.last_s - stamp_s),
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::Prepared;

    /// On a simulated drive (a speed in every row, stops, a declared lead-in), every closed
    /// block's output equals the batch trace's (unaligned) at that block, bit for bit.
    #[test]
    fn the_stream_gives_the_batch_pipelines_headings() {
        let log =
            crate::sim::drive::simulate_drive(&crate::sim::DriveConfig { scenario: crate::sim::Scenario::City, minutes: 6.0, seed: 3 });
        let params = PipelineParams { bias_s: Some(log.bias_s(None)), ..Default::default() };
        let prep = Prepared::new(&log, params.bias_s, &params.still).unwrap();
        let batch = prep.pipeline_trace(&params).unwrap();
        let t = log.time_s();
        let (w, v) = (log.column(crate::Column::GyroDps).unwrap(), log.column(crate::Column::SpeedMps).unwrap());
        let mut s = PipelineStream::new(params).unwrap();
        let mut closed = Vec::new();
        let mut at_last_row = Vec::new();
        for i in 0..t.len() {
            let before = s.last.map(|(_, stamp)| stamp);
            let psi = s.update(t[i], w[i], v[i]).unwrap();
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
        }
        assert!(batch.stop.iter().any(|&s| s), "the drive has stops");
        // Row by row: at a block's last row the heading is the batch heading of that block
        // where the block brought no stop (whose correction comes with the block's close).
        for (j, psi) in at_last_row.iter().enumerate().skip(1).filter(|(j, _)| !batch.stop[*j]) {
            assert!((psi - batch.heading_deg[j]).abs() < 1e-9, "block {j}: {psi} against {}", batch.heading_deg[j]);
        }
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
