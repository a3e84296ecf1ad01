//! Still detection on the 1 Hz blocks (methods.md detail 2's blocks): is the vehicle
//! standing in a block? From the speed when the log has it, else from the wheel travel,
//! else from the gyro alone (the block's spread no larger than the stationary lead-in's).
//! The zero-angular-rate update of the pipeline and of the ZARU peer rests on it.

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// Thresholds of the still detector.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct StillOptions {
    /// Standing when every speed of the block is below this, m/s.
    pub still_speed_mps: f64,
    /// Standing when the wheels travelled less than this in the block, m (no speed column).
    pub still_travel_m: f64,
    /// Gyro only: standing when the block's standard deviation is at most this times the
    /// lead-in's (needs 5 rows per block and a lead-in of 10 rows).
    pub still_gyro_factor: f64,
}

impl StillOptions {
    /// Standing by speed: the block has speeds and every one is below `still_speed_mps`
    /// (`speed_max_mps` the largest |speed| of the block).
    pub fn still_by_speed(&self, speeds: usize, speed_max_mps: f64) -> bool {
        speeds > 0 && speed_max_mps < self.still_speed_mps
    }

    /// Moving by speed: the block has speeds and one reaches `still_speed_mps` (a block
    /// without speeds is not standing by speed, but says nothing of moving either).
    pub fn moving_by_speed(&self, speeds: usize, speed_max_mps: f64) -> bool {
        speeds > 0 && speed_max_mps >= self.still_speed_mps
    }

    /// Standing by the gyro alone: the block has 5 rows or more (`n` rows summing to `sum`,
    /// their squares to `sum2`) and its standard deviation is at most `still_gyro_factor`
    /// times the lead-in's (`lead_std`, from [`lead_in_std`]).
    pub fn still_by_gyro(&self, n: usize, sum: f64, sum2: f64, lead_std: f64) -> bool {
        let mean = sum / n as f64;
        let var = (sum2 / n as f64 - mean * mean).max(0.0);
        n >= 5 && var.sqrt() <= self.still_gyro_factor * lead_std
    }
}

/// The lead-in's gyro spread for the gyro-only detector: its standard deviation when the
/// lead-in has 10 finite rows or more and they are not all equal, else None (never still).
pub fn lead_in_std(lead_dps: &[f64]) -> Option<f64> {
    let std = crate::metrics::mean_std(lead_dps).1;
    (lead_dps.len() >= 10 && std > 0.0).then_some(std)
}

impl Default for StillOptions {
    fn default() -> Self {
        StillOptions { still_speed_mps: 0.2, still_travel_m: 0.05, still_gyro_factor: 1.5 }
    }
}

/// What the still flags were decided from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StillSource {
    Speed,
    Odometry,
    Gyro,
    /// No speed, no wheels, and no lead-in to compare the gyro with: never still.
    None,
}

impl StillSource {
    /// Its name as the JSON and the CSV rows spell it (speed, odometry, gyro, none).
    pub fn name(self) -> &'static str {
        match self {
            StillSource::Speed => "speed",
            StillSource::Odometry => "odometry",
            StillSource::Gyro => "gyro",
            StillSource::None => "none",
        }
    }
}

/// The 1 Hz blocks of a log with what the pipeline needs per block.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Blocks {
    /// Stamp of the block's last row (detail 2).
    pub time_s: Vec<f64>,
    /// Mean raw gyro of the block, deg/s.
    pub rate_dps: Vec<f64>,
    /// Mean temperature of the block, deg C (NaN without temperature).
    pub temp_c: Vec<f64>,
    /// The vehicle stood during the whole block.
    pub still: Vec<bool>,
    /// The stamp of the first block in which the speed or the wheels show the vehicle
    /// moving (None: they never do, or the log has neither). What ends a declared
    /// stationary lead-in early for the pipeline.
    pub first_moving_s: Option<f64>,
}

impl Blocks {
    pub fn len(&self) -> usize {
        self.time_s.len()
    }
    pub fn is_empty(&self) -> bool {
        self.time_s.is_empty()
    }
}

#[derive(Default)]
struct Acc {
    n: usize,
    sum: f64,
    sum2: f64,
    temp_sum: f64,
    temp_n: usize,
    speed_max: f64,
    speed_n: usize,
    odo_first: Option<(f64, f64)>,
    odo_last: Option<(f64, f64)>,
}

impl Acc {
    /// One row's gyro, temperature, speed and wheel odometry (NaN cells skipped).
    fn add(&mut self, g: f64, temp: Option<f64>, speed: Option<f64>, odo: Option<(f64, f64)>) {
        if g.is_finite() {
            self.n += 1;
            self.sum += g;
            self.sum2 += g * g;
        }
        if let Some(v) = temp.filter(|v| v.is_finite()) {
            self.temp_sum += v;
            self.temp_n += 1;
        }
        if let Some(v) = speed.filter(|v| v.is_finite()) {
            self.speed_max = if self.speed_n == 0 { v.abs() } else { self.speed_max.max(v.abs()) };
            self.speed_n += 1;
        }
        if let Some((l, r)) = odo.filter(|(l, r)| l.is_finite() && r.is_finite()) {
            self.odo_first.get_or_insert((l, r));
            self.odo_last = Some((l, r));
        }
    }
}

/// Block-averages a log to 1 Hz (`preprocess::blocks_1hz`, the stamps of
/// `preprocess::block_average_1hz`) and flags the blocks where the vehicle stood.
pub fn blocks(log: &DriveLog, bias_s: f64, opts: &StillOptions) -> Result<(Blocks, StillSource)> {
    let t = log.time_s();
    let gyro = log.require(Column::GyroDps, "needed for the yaw rate")?;
    let speed = log.column(Column::SpeedMps);
    let odo = log.column(Column::OdoLeftM).zip(log.column(Column::OdoRightM));
    let temp = log.column(Column::TempC);
    // Lead-in spread for the gyro-only detector.
    let lead: Vec<f64> = match t.first() {
        Some(&t0) => t.iter().zip(gyro).take_while(|(&ti, _)| ti - t0 < bias_s).filter(|(_, g)| g.is_finite()).map(|(_, &g)| g).collect(),
        None => Vec::new(),
    };
    let lead_std = lead_in_std(&lead);
    let source = if speed.is_some_and(|s| s.iter().any(|v| v.is_finite())) {
        StillSource::Speed
    } else if odo.is_some() {
        StillSource::Odometry
    } else if lead_std.is_some() {
        StillSource::Gyro
    } else {
        StillSource::None
    };
    let mut out = Blocks::default();
    if t.is_empty() {
        return Err(Error::data("the log has no rows"));
    }
    let flush = |a: &Acc, stamp: f64, out: &mut Blocks| {
        if a.n == 0 {
            return;
        }
        let travel = match (a.odo_first, a.odo_last) {
            (Some(f), Some(l)) => Some((l.0 - f.0).abs() + (l.1 - f.1).abs()),
            _ => None,
        };
        let still = match source {
            StillSource::Speed => opts.still_by_speed(a.speed_n, a.speed_max),
            StillSource::Odometry => travel.is_some_and(|d| d < opts.still_travel_m),
            StillSource::Gyro => lead_std.is_some_and(|s| opts.still_by_gyro(a.n, a.sum, a.sum2, s)),
            StillSource::None => false,
        };
        let moving = match source {
            StillSource::Speed => opts.moving_by_speed(a.speed_n, a.speed_max),
            StillSource::Odometry => travel.is_some_and(|d| d >= opts.still_travel_m),
            _ => false,
        };
        if moving && out.first_moving_s.is_none() {
            out.first_moving_s = Some(stamp);
        }
        out.time_s.push(stamp);
        out.rate_dps.push(a.sum / a.n as f64);
        out.temp_c.push(if a.temp_n > 0 { a.temp_sum / a.temp_n as f64 } else { f64::NAN });
        out.still.push(still);
    };
    for b in crate::preprocess::blocks_1hz(t) {
        let mut acc = Acc::default();
        for i in b.clone() {
            acc.add(gyro[i], temp.map(|c| c[i]), speed.map(|c| c[i]), odo.map(|(l, r)| (l[i], r[i])));
        }
        flush(&acc, t[b.end - 1], &mut out);
    }
    if out.is_empty() {
        return Err(Error::data("the gyro_dps column has no values"));
    }
    Ok((out, source))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preprocess::block_average_1hz;

    /// The name is the serde one, so the text output, the JSON and the CSV rows agree.
    #[test]
    fn a_still_source_is_named_as_serde_names_it() {
        for s in [StillSource::Speed, StillSource::Odometry, StillSource::Gyro, StillSource::None] {
            assert_eq!(serde_json::to_value(s).unwrap(), s.name());
        }
    }

    fn log(speed: bool) -> DriveLog {
        let mut cols = vec![Column::GyroDps, Column::TempC];
        if speed {
            cols.push(Column::SpeedMps);
        }
        let mut l = DriveLog::with_columns(&cols);
        for i in 0..100 {
            let t = i as f64 * 0.1;
            // stands for 5 s, drives 3 s, stands again
            let v = if (5.0..8.0).contains(&t) { 3.0 } else { 0.05 };
            let g = 0.1 + if i % 2 == 0 { 0.01 } else { -0.01 } + if (5.0..8.0).contains(&t) { 0.5 * (i % 3) as f64 } else { 0.0 };
            l.push_row(&[(Column::TimeS, t), (Column::GyroDps, g), (Column::TempC, 20.0 + t), (Column::SpeedMps, v)]);
        }
        l
    }

    #[test]
    fn blocks_equal_the_block_average_and_flag_stops_by_speed() {
        let l = log(true);
        let (b, src) = blocks(&l, 4.0, &StillOptions::default()).unwrap();
        let s = block_average_1hz(l.time_s(), l.column(Column::GyroDps).unwrap());
        assert_eq!(src, StillSource::Speed);
        assert_eq!(b.time_s, s.time_s);
        assert_eq!(b.rate_dps, s.rate_dps);
        // block k holds t in [k, k+1): rows 20 + {k, k+.1, ..., k+.9} -> mean 20 + k + 0.45
        assert!((b.temp_c[3] - 23.45).abs() < 1e-12);
        assert_eq!(b.still, vec![true, true, true, true, true, false, false, false, true, true]);
        // Moving from t = 5 s: block 5 (rows 5.0-5.9) is the first the speed shows moving.
        assert_eq!(b.first_moving_s, Some(b.time_s[5]));
    }

    #[test]
    fn gyro_only_detector_uses_the_lead_in_spread() {
        let l = log(false);
        let (b, src) = blocks(&l, 4.0, &StillOptions::default()).unwrap();
        assert_eq!(src, StillSource::Gyro);
        assert_eq!(b.still, vec![true, true, true, true, true, false, false, false, true, true]);
        // The gyro judges standing against the lead-in, not moving: nothing ends a lead-in.
        assert_eq!(b.first_moving_s, None);
        // No lead-in: nothing to compare with, never still.
        let (b, src) = blocks(&l, 0.0, &StillOptions::default()).unwrap();
        assert_eq!(src, StillSource::None);
        assert!(b.still.iter().all(|s| !s));
    }
}
