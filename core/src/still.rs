//! Still detection on the 1 Hz blocks (methods.md detail 2's blocks): is the vehicle
//! standing in a block? From the speed when the log has it, else from the wheel travel,
//! else from the gyro alone (the block's spread no larger than the stationary lead-in's,
//! or, with no lead-in to compare with, block means that scatter no more than white noise).
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
    /// lead-in's (needs 5 rows per block and a lead-in of 10 rows) ...
    pub still_gyro_factor: f64,
    /// ... and the standard deviation of the last [`AGREE_BLOCKS`] block means at most this
    /// times the lead-in's block means' ([`GyroStill`]).
    pub still_agree_factor: f64,
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
}

/// Blocks whose means must agree for the gyro alone to call the last of them still.
pub const AGREE_BLOCKS: usize = 5;

/// Blocks whose means must scatter no more than their rows' white noise would, for the gyro
/// alone to call the last of them still when no lead-in gives a reference. On the training
/// bases' drives no 10-block window of moving blocks passed (5 blocks: 0.4-3 % did).
pub const WHITE_BLOCKS: usize = 10;

/// The gyro-only detector, block by block. The declared stationary lead-in's blocks stand
/// and set the reference; after it a block is still when its spread is at most
/// `still_gyro_factor` times the lead-in's rows' and the means of the last [`AGREE_BLOCKS`]
/// blocks agree as the lead-in's block means do: their standard deviation at most
/// `still_agree_factor` times the lead-in's. The spread alone cannot tell an idling engine
/// from a smooth drive (an idle shakes the gyro more than a slow turn does); a moving
/// vehicle's rate wanders from second to second (steering, curves, sway), a standing one's
/// does not. Without a usable lead-in the wander alone decides: a block is still when the
/// means of the last [`WHITE_BLOCKS`] blocks scatter no more than their rows' own noise
/// predicts (sample variance of the means <= the pooled row variance / rows per block), as
/// a standing gyro's white noise does and a moving vehicle's steering does not.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GyroStill {
    /// The lead-in's rows: count, sum, sum of squares.
    lead: (usize, f64, f64),
    /// The lead-in's blocks of 5 rows or more: rows, mean, row variance (`block_stats`).
    lead_blocks: Vec<(usize, f64, f64)>,
    /// The last [`AGREE_BLOCKS`] block means after the lead-in (started with its last ones).
    means: Vec<f64>,
    /// Once the lead-in is over: its rows' and its block means' standard deviations, or
    /// None when it cannot be used (the white-noise test then decides alone).
    reference: Option<Option<(f64, f64)>>,
    /// Without a reference: the last [`WHITE_BLOCKS`] blocks' rows, mean and row variance.
    white: Vec<(usize, f64, f64)>,
    /// Blocks called still by the white-noise test.
    white_stills: usize,
}

impl GyroStill {
    /// One block (`n` finite rows summing to `sum`, their squares to `sum2`), within the
    /// declared lead-in or after it: is it still? A block of fewer than 5 rows after the
    /// lead-in is not, and restarts the window.
    pub fn update(&mut self, opts: &StillOptions, lead_in: bool, n: usize, sum: f64, sum2: f64) -> bool {
        let mean = sum / n as f64;
        if lead_in {
            self.lead = (self.lead.0 + n, self.lead.1 + sum, self.lead.2 + sum2);
            self.lead_blocks.extend((n >= 5).then(|| block_stats(n, sum, sum2)));
            return true;
        }
        let Some((std, scatter)) = self.reference() else { return self.white_update(n, sum, sum2) };
        if n < 5 {
            self.means.clear();
            return false;
        }
        self.means.push(mean);
        if self.means.len() > AGREE_BLOCKS {
            self.means.drain(..1);
        }
        let agree = self.means.len() == AGREE_BLOCKS && crate::metrics::mean_std(&self.means).1 <= opts.still_agree_factor * scatter;
        agree && (sum2 / n as f64 - mean * mean).max(0.0).sqrt() <= opts.still_gyro_factor * std
    }

    /// The white-noise test (no reference): is the block still? Blocks of fewer than 5 rows
    /// are not, and restart the window; rows all equal (a quantised standing) say nothing.
    fn white_update(&mut self, n: usize, sum: f64, sum2: f64) -> bool {
        if n < 5 {
            self.white.clear();
            return false;
        }
        self.white.push(block_stats(n, sum, sum2));
        if self.white.len() > WHITE_BLOCKS {
            self.white.drain(..1);
        }
        if self.white.len() < WHITE_BLOCKS {
            return false;
        }
        let still = white_variance_ratio(&self.white).is_some_and(|r| r <= 1.0);
        self.white_stills += still as usize;
        still
    }

    /// How far the declared lead-in's 1 s means wander beyond its rows' white noise (the
    /// square root of `white_variance_ratio` over its blocks): about 1 for a standing, far
    /// more for a lead-in over driving. None as that ratio is.
    pub fn lead_in_wander(&self) -> Option<f64> {
        white_variance_ratio(&self.lead_blocks).map(f64::sqrt)
    }

    /// The lead-in's rows' and block means' standard deviations, fixed at the first call:
    /// None unless it had 10 rows or more, 3 blocks of 5 rows or more, and neither its rows
    /// nor its block means were all equal (nothing to compare with). The window starts
    /// with its last block means (a standing goes on).
    pub fn reference(&mut self) -> Option<(f64, f64)> {
        *self.reference.get_or_insert_with(|| {
            let (n, sum, sum2) = self.lead;
            let std = ((sum2 - sum * sum / n as f64) / (n as f64 - 1.0)).max(0.0).sqrt();
            let m: Vec<f64> = self.lead_blocks.iter().map(|b| b.1).collect();
            let (k, scatter) = (m.len(), crate::metrics::mean_std(&m).1);
            self.means = m[k.saturating_sub(AGREE_BLOCKS - 1)..].to_vec();
            (n >= 10 && k >= 3 && std > 0.0 && scatter > 0.0).then_some((std, scatter))
        })
    }
}

/// How much more the block means (rows, mean, row variance per block) scatter than their
/// rows' white noise predicts: the sample variance of the means over the pooled row variance
/// per rows per block (1 in expectation for a standing gyro's white noise). None under 3
/// blocks, or when the rows are all equal (a rounding residue of 1e-16 x mean^2 is not
/// noise).
pub fn white_variance_ratio(blocks: &[(usize, f64, f64)]) -> Option<f64> {
    let k = blocks.len() as f64;
    let rows_per_block = blocks.iter().map(|b| b.0 as f64).sum::<f64>() / k;
    let row_var = blocks.iter().map(|b| b.2).sum::<f64>() / k;
    let mean_of_means = blocks.iter().map(|b| b.1).sum::<f64>() / k;
    let means_var = blocks.iter().map(|b| (b.1 - mean_of_means).powi(2)).sum::<f64>() / (k - 1.0);
    (blocks.len() >= 3 && row_var > 1e-12 * (1.0 + mean_of_means * mean_of_means)).then(|| means_var / (row_var / rows_per_block))
}

/// A block's rows, mean and row variance (sample; 0 at worst) from its count, sum and sum
/// of squares.
fn block_stats(n: usize, sum: f64, sum2: f64) -> (usize, f64, f64) {
    let mean = sum / n as f64;
    (n, mean, ((sum2 - sum * mean) / (n as f64 - 1.0)).max(0.0))
}

impl Default for StillOptions {
    fn default() -> Self {
        StillOptions { still_speed_mps: 0.2, still_travel_m: 0.05, still_gyro_factor: 1.5, still_agree_factor: 2.0 }
    }
}

/// What the still flags were decided from.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StillSource {
    Speed,
    Odometry,
    Gyro,
    /// No speed, no wheels, no usable lead-in to compare the gyro with, and no standing the
    /// gyro's white noise shows alone: no block after the declared lead-in is still.
    #[default]
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
    /// Time of the log's first row, which block k counts from (detail 2).
    pub origin_s: f64,
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
    /// Without speed or wheels: how far the declared lead-in's 1 s means wander beyond the
    /// gyro's own noise (`GyroStill::lead_in_wander`), what `check` judges it by.
    pub lead_in_wander: Option<f64>,
    /// What the still flags were decided from. From the gyro alone (`StillSource::Gyro`) a
    /// still block may be a steady turn, which the gyro's noise cannot tell from a standing.
    pub source: StillSource,
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
pub fn blocks(log: &DriveLog, bias_s: f64, opts: &StillOptions) -> Result<Blocks> {
    let t = log.time_s();
    let gyro = log.require(Column::GyroDps, "needed for the yaw rate")?;
    let speed = log.column(Column::SpeedMps);
    let odo = log.column(Column::OdoLeftM).zip(log.column(Column::OdoRightM));
    let temp = log.column(Column::TempC);
    let t0 = t.first().copied().unwrap_or(0.0);
    let mut gyro_still = GyroStill::default();
    let mut source = if speed.is_some_and(|s| s.iter().any(|v| v.is_finite())) {
        StillSource::Speed
    } else if odo.is_some() {
        StillSource::Odometry
    } else {
        StillSource::Gyro
    };
    let mut out = Blocks { origin_s: t0, ..Blocks::default() };
    if t.is_empty() {
        return Err(Error::data("the log has no rows"));
    }
    let mut flush = |a: &Acc, stamp: f64, lead_in: bool, out: &mut Blocks| {
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
            StillSource::Gyro => gyro_still.update(opts, lead_in, a.n, a.sum, a.sum2),
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
        flush(&acc, t[b.end - 1], crate::preprocess::block_index(t[b.start], t0) < bias_s, &mut out);
    }
    if out.is_empty() {
        return Err(Error::data("the gyro_dps column has no values"));
    }
    // No usable lead-in to compare the gyro with, and no standing by the white-noise test:
    // no block after the lead-in is still, and the source says why.
    if source == StillSource::Gyro {
        out.lead_in_wander = gyro_still.lead_in_wander();
    }
    if source == StillSource::Gyro && gyro_still.reference().is_none() && gyro_still.white_stills == 0 {
        source = StillSource::None;
    }
    out.source = source;
    Ok(out)
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
        let b = blocks(&l, 4.0, &StillOptions::default()).unwrap();
        let src = b.source;
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

    /// GyroStill by hand: lead-in blocks of 5 rows with means 1.0, 1.2, 1.4 (scatter 0.2,
    /// so means agree within 2 x 0.2 = 0.4) and rows 0.1 about them.
    #[test]
    fn gyro_still_by_hand() {
        let o = StillOptions::default();
        // A block of 5 rows: n, sum, sum of squares.
        let block = |rows: &[f64]| (rows.len(), rows.iter().sum::<f64>(), rows.iter().map(|v| v * v).sum::<f64>());
        let (mut g, mut lead) = (GyroStill::default(), Vec::new());
        for m in [1.0, 1.2, 1.4] {
            let rows: Vec<f64> = [-0.1, 0.1, -0.1, 0.1, 0.0].iter().map(|d| m + d).collect();
            let (n, s, s2) = block(&rows);
            assert!(g.update(&o, true, n, s, s2), "the lead-in stands");
            lead.extend(rows);
        }
        let lead_std = crate::metrics::mean_std(&lead).1;
        let (std, scatter) = g.clone().reference().unwrap();
        assert!((scatter - 0.2).abs() < 1e-12 && (std - lead_std).abs() < 1e-12, "{std} {scatter}");
        // A block of 5 rows with mean m and standard deviation sd.
        let upd = |g: &mut GyroStill, m: f64, sd: f64| g.update(&o, false, 5, 5.0 * m, 5.0 * (m * m + sd * sd));
        // Window 1.0 1.2 1.4 1.2: four means, not yet five.
        assert!(!upd(&mut g, 1.2, 0.05));
        // 1.0 1.2 1.4 1.2 1.2: deviations -.2 0 .2 0 0, std sqrt(.08 / 4) = 0.141 <= 0.4.
        assert!(upd(&mut g, 1.2, 0.05));
        // 1.2 1.4 1.2 1.2 2.5: mean 1.5, squares .09 .01 .09 .09 1 -> sqrt(1.28 / 4) = 0.566.
        assert!(!upd(&mut g, 2.5, 0.05));
        // Means that agree, but a spread over 1.5 x the lead-in's rows: not still.
        for _ in 0..4 {
            upd(&mut g, 1.2, 0.05);
        }
        assert!(upd(&mut g, 1.2, 1.4 * lead_std));
        assert!(!upd(&mut g, 1.2, 1.6 * lead_std));
        // A block of 4 rows: not still, and the window starts again.
        assert!(!g.update(&o, false, 4, 4.8, 4.0 * 1.44));
        assert!((0..4).all(|_| !upd(&mut g, 1.2, 0.05)) && upd(&mut g, 1.2, 0.05));
        // Lead-ins it cannot use (never still): two blocks; block means all equal.
        let mut two = GyroStill::default();
        for m in [1.0, 1.2] {
            two.update(&o, true, 5, 5.0 * m, 5.0 * (m * m + 0.01));
        }
        assert!(two.reference().is_none() && !upd(&mut two, 1.2, 0.05));
        let mut equal = GyroStill::default();
        for _ in 0..5 {
            equal.update(&o, true, 5, 5.0, 5.0 * 1.01);
        }
        assert!(equal.reference().is_none());
    }

    /// The white-noise test by hand (no lead-in): blocks of 5 rows m + (-0.1, 0.1, -0.1,
    /// 0.1, 0) have row variance 0.04 / 4 = 0.01, so 10 block means may scatter with sample
    /// variance up to 0.01 / 5 = 0.002. Means alternating 1 +- 0.04: 10 x 0.0016 / 9 =
    /// 0.00178, still from the 10th block on; +- 0.05: 10 x 0.0025 / 9 = 0.00278, not.
    #[test]
    fn without_a_lead_in_block_means_that_scatter_as_white_noise_stand() {
        let o = StillOptions::default();
        let upd = |g: &mut GyroStill, m: f64| {
            let rows: Vec<f64> = [-0.1, 0.1, -0.1, 0.1, 0.0].iter().map(|d| m + d).collect();
            g.update(&o, false, 5, rows.iter().sum(), rows.iter().map(|v| v * v).sum())
        };
        let alt = |k: usize, d: f64| if k.is_multiple_of(2) { 1.0 + d } else { 1.0 - d };
        let mut g = GyroStill::default();
        assert!(g.reference().is_none());
        let calls: Vec<bool> = (0..12).map(|k| upd(&mut g, alt(k, 0.04))).collect();
        assert_eq!(calls, (0..12).map(|k| k >= 9).collect::<Vec<_>>());
        assert_eq!(g.white_stills, 3);
        let mut g = GyroStill::default();
        assert!((0..12).all(|k| !upd(&mut g, alt(k, 0.05))));
        // A block of 4 rows is not still and restarts the window.
        let mut g = GyroStill::default();
        (0..10).for_each(|k| _ = upd(&mut g, alt(k, 0.04)));
        assert!(!g.update(&o, false, 4, 4.0, 4.04));
        assert!((0..9).all(|k| !upd(&mut g, alt(k, 0.04))) && upd(&mut g, 1.0));
        // Rows all equal (a quantised standing): nothing to compare with, never still.
        let mut g = GyroStill::default();
        assert!((0..12).all(|_| !g.update(&o, false, 5, 5.0, 5.0)));
    }

    /// The ratio by hand: 4 blocks of 5 rows with row variance 0.01 and means 1.0, 1.2, 1.0,
    /// 1.2 (sample variance 4 x 0.01 / 3 = 0.01333): 0.01333 / (0.01 / 5) = 6.667. Under 3
    /// blocks, or rows all equal: none.
    #[test]
    fn white_variance_ratio_by_hand() {
        let b = |m: f64| (5, m, 0.01);
        let r = white_variance_ratio(&[b(1.0), b(1.2), b(1.0), b(1.2)]).unwrap();
        assert!((r - 0.04 / 3.0 / 0.002).abs() < 1e-9, "{r}");
        assert!(white_variance_ratio(&[b(1.0), b(1.2)]).is_none());
        assert!(white_variance_ratio(&[(5, 1.0, 0.0), (5, 1.0, 0.0), (5, 1.0, 0.0)]).is_none());
    }

    /// A gyro-only log at 10 Hz: `rate(t, row)`, lead-in `bias_s`.
    fn gyro_log(secs: f64, rate: impl Fn(f64, usize) -> f64) -> DriveLog {
        let mut l = DriveLog::with_columns(&[Column::GyroDps]);
        for i in 0..(secs * 10.0) as usize {
            let t = i as f64 * 0.1;
            l.push_row(&[(Column::TimeS, t), (Column::GyroDps, rate(t, i))]);
        }
        l
    }

    /// An idling engine shakes the gyro more than a smooth slow turn does (as on WID car
    /// trial 11): the spread alone calls the turn standing, the block means' wander does not.
    #[test]
    fn gyro_only_detector_tells_an_idle_from_a_smooth_turn() {
        let alt = |i: usize| if i.is_multiple_of(2) { 1.0 } else { -1.0 };
        let idle = |_: f64, i: usize| 0.3 + 1.8 * alt(i) + 0.02 * (0.37 * i as f64).sin();
        let turn = |t: f64, i: usize| -4.7 + 0.3 * (std::f64::consts::TAU * t / 6.0).sin() + 0.5 * alt(i);
        let l = gyro_log(36.0, |t, i| if (6.0..26.0).contains(&t) { turn(t, i) } else { idle(t, i) });
        let b = blocks(&l, 6.0, &StillOptions::default()).unwrap();
        let src = b.source;
        assert_eq!(src, StillSource::Gyro);
        // The turn's blocks spread less than 1.5 x the idle's: spread alone reads them still.
        let lead: Vec<f64> = (0..60).map(|i| idle(i as f64 * 0.1, i)).collect();
        let turn_block: Vec<f64> = (100..110).map(|i| turn(i as f64 * 0.1, i)).collect();
        assert!(crate::metrics::mean_std(&turn_block).1 < 1.5 * crate::metrics::mean_std(&lead).1);
        // The lead-in stands; the turn and the standing's first 4 blocks (their window holds
        // turn blocks) do not; the standing does once 5 of its block means agree.
        let want: Vec<bool> = (0..36).map(|k| !(6..30).contains(&k)).collect();
        assert_eq!(b.still, want);
        // The gyro judges standing, not moving: nothing ends a lead-in.
        assert_eq!(b.first_moving_s, None);
        // No lead-in: the white-noise test alone. The turn's block means wander more than
        // its rows' noise predicts, never still; the final idle's do not, still from its
        // 10th block (the first with a window of idle blocks only).
        let b = blocks(&l, 0.0, &StillOptions::default()).unwrap();
        assert_eq!(b.source, StillSource::Gyro);
        assert_eq!(b.still, (0..36).map(|k| k == 35).collect::<Vec<_>>());
        // Without the final idle nothing stands: the source says so.
        let l = gyro_log(26.0, |t, i| if (6.0..26.0).contains(&t) { turn(t, i) } else { idle(t, i) });
        let b = blocks(&l, 0.0, &StillOptions::default()).unwrap();
        assert_eq!(b.source, StillSource::None);
        assert!(b.still.iter().all(|s| !s));
    }
}
