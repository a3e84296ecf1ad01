//! The bend fallback beside the blend (`blend.rs`): once the experts have started, the
//! bank's settled bias (its bias less the warm-up term) has no cause to move far between
//! stops, so a move beyond `blend_move_dps` from where the last stop (or the experts' start)
//! left it is long bends read as straight road, and the blend takes Table-III HDR's move
//! alone, held. The anchor restarts after a stop (until the forty-ninth session it was an
//! average over the road window, which a slow run of bends dragged along with the bias:
//! docs/pipeline.md).
//! Without a stationary lead-in nothing has measured the gyro's warm-up, so a move that
//! outlasts the road window (a bend read as road leaves the bank's evidence one window
//! after it fills it) is taken as the gyro's, a warm-up the prior could not size, and the
//! fallback waits for the next stop (fifty-fifth session; until then it waited for a
//! lead-in, and such drives read their bends as bias). Unless the move is coming back: a
//! settled bias back by more than the bank's fastest walk could bring it over half a
//! window is a bend leaving the window, and stays held (fifty-sixth session). After a
//! lead-in, on a quiet gyro, the threshold is `blend_move_quiet_dps` (fifty-seventh
//! session). Beyond the paper.

use std::collections::VecDeque;

/// Watches the bank's settled bias once the experts have started: `blend_move_dps` (0:
/// never), the release without a lead-in (`road_window_s`), whether the lead-in gave stop
/// evidence, and the anchor: the settled bias and the bank's bias at the experts' first
/// block or the first block after a stop (none until then).
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Default)]
pub(super) struct Fallback {
    pub(super) move_dps: f64,
    /// The threshold after a lead-in on a quiet gyro (0: `move_dps`), deg/s.
    pub(super) quiet_dps: f64,
    /// How long a move may last without a lead-in before it is taken as the gyro's, s.
    pub(super) release_s: f64,
    pub(super) lead_in_seen: bool,
    pub(super) anchor_dps: Option<(f64, f64)>,
    /// Since when the settled bias has been beyond `move_dps` from the anchor, s.
    pub(super) beyond_since_s: Option<f64>,
    /// A move outlasted `release_s` without a lead-in: no fallback until the next stop.
    pub(super) released: bool,
    /// How far a move may recede over half a road window and still be released: the bank's
    /// fastest walk over that time, deg/s.
    pub(super) recede_dps: f64,
    /// The current move's distance from the anchor over the last half window: (time s, deg/s).
    pub(super) recent: VecDeque<(f64, f64)>,
}

impl Fallback {
    /// The fallback the pipeline's settings ask for: `blend_move_dps`, released after
    /// `road_window_s`, a move receding by more than the bank's fastest walk over half that
    /// window held.
    pub(super) fn of(p: &super::PipelineParams) -> Self {
        let recede_dps = p.bias_walk_max_dps_per_sqrt_s * libm::sqrt(p.road_window_s / 2.0);
        Fallback {
            move_dps: p.blend_move_dps,
            quiet_dps: p.blend_move_quiet_dps,
            release_s: p.road_window_s,
            recede_dps,
            ..Default::default()
        }
    }

    /// How far the settled bias may move from the anchor: `quiet_dps` after a lead-in on a
    /// quiet gyro (`quiet`: its standstill noise within the stop's setting), else `move_dps`.
    fn threshold_dps(&self, quiet: bool) -> f64 {
        if self.lead_in_seen && quiet && self.quiet_dps > 0.0 {
            self.quiet_dps
        } else {
            self.move_dps
        }
    }

    /// Where the settled bias is further than the threshold from the anchor's (a non-finite
    /// settled bias is none) and the move has not been released, the bank's bias at the
    /// anchor. A stop block restarts the anchor (and ends a release) at the next block.
    /// `quiet`: the gyro's standstill noise is within the stop's setting (`threshold_dps`).
    pub(super) fn moved(&mut self, time_s: f64, settled: f64, bias_dps: f64, stop: bool, quiet: bool) -> Option<f64> {
        if !(self.move_dps > 0.0 && settled.is_finite()) {
            return None;
        }
        let (s_anchor, b_anchor) = *self.anchor_dps.get_or_insert((settled, bias_dps));
        let dist_dps = (settled - s_anchor).abs();
        let beyond = dist_dps > self.threshold_dps(quiet);
        self.beyond_since_s = if beyond { Some(self.beyond_since_s.unwrap_or(time_s)) } else { None };
        let lasted_s = self.beyond_since_s.map_or(0.0, |since| time_s - since);
        let receding = self.receding(time_s, dist_dps, beyond);
        self.released |= !self.lead_in_seen && lasted_s > self.release_s && !receding;
        let out = (beyond && !self.released).then_some(b_anchor);
        if stop {
            (self.anchor_dps, self.beyond_since_s, self.released) = (None, None, false);
            self.recent.clear();
        }
        out
    }

    /// Whether the move has come back by more than `recede_dps` over the last half road
    /// window: a bend leaving the window the bank read it in, not a warm-up, which does not
    /// turn back. Keeps the move's recent distances (none while not beyond).
    fn receding(&mut self, time_s: f64, dist_dps: f64, beyond: bool) -> bool {
        if !beyond {
            self.recent.clear();
            return false;
        }
        self.recent.push_back((time_s, dist_dps));
        let half_s = self.release_s / 2.0;
        while self.recent.get(1).is_some_and(|&(t, _)| t <= time_s - half_s) {
            self.recent.pop_front();
        }
        self.recent.front().is_some_and(|&(t, d)| time_s - t >= half_s && d - dist_dps > self.recede_dps)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A slow run of bends: the settled bias creeps 0.002 deg/s per block from 0 (the bank's
    /// bias 0.1 above it). It is moved once more than 0.3 from the anchor (block 151:
    /// 0.302), not before (block 150: 0.3, not beyond), and stays moved, the anchor's bias
    /// (0.1) the hold's other end. An average over 60 s would trail such a creep by 0.12
    /// and never act. A stop restarts the anchor where the bias then is.
    #[test]
    fn a_slow_creep_of_the_settled_bias_is_moved_once_beyond_the_anchor() {
        let mut f = Fallback { move_dps: 0.3, release_s: 60.0, lead_in_seen: true, ..Default::default() };
        for i in 0..=200 {
            let settled = 0.002 * f64::from(i);
            let moved = f.moved(f64::from(i), settled, settled + 0.1, false, false);
            assert_eq!(moved, (i > 150).then_some(0.1), "block {i}");
        }
        assert_eq!(f.moved(201.0, 0.402, 0.502, true, false), Some(0.1));
        assert_eq!(f.moved(202.0, 0.404, 0.504, false, false), None);
        assert_eq!(f.anchor_dps, Some((0.404, 0.504)));
        let mut off = Fallback { move_dps: 0.0, ..Default::default() };
        assert_eq!(off.moved(0.0, 0.0, 0.0, false, false).or(off.moved(1.0, 1.0, 1.0, false, false)), None);
    }

    /// Without a lead-in, a move 0.5 deg/s from the anchor from block 10 on is held for one
    /// road window (60 s: blocks 10-70), then taken as the gyro's (a warm-up nothing
    /// measured) until a stop restarts the anchor; a move back within 0.3 before then
    /// restarts the count. After a lead-in the same move is held as long as it lasts.
    #[test]
    fn without_a_lead_in_a_move_that_outlasts_the_road_window_is_released() {
        for lead_in_seen in [false, true] {
            let mut f = Fallback { move_dps: 0.3, release_s: 60.0, lead_in_seen, ..Default::default() };
            for i in 0..=150 {
                let settled = if i >= 10 { 0.5 } else { 0.0 };
                let held = (10..=70).contains(&i) || (lead_in_seen && i >= 10);
                assert_eq!(f.moved(f64::from(i), settled, settled, false, false), held.then_some(0.0), "block {i}, lead-in {lead_in_seen}");
            }
            f.moved(151.0, 0.5, 0.5, true, false);
            assert!(!f.released && f.anchor_dps.is_none());
            assert_eq!(f.moved(152.0, 1.0, 1.0, false, false), None, "the anchor restarted at the stop's next block");
            assert_eq!(f.moved(153.0, 1.5, 1.5, false, false), Some(1.0), "a new move after the stop is held");
        }
        let mut f = Fallback { move_dps: 0.3, release_s: 60.0, ..Default::default() };
        for i in 0..=100 {
            let settled = if (10..50).contains(&i) || i >= 55 { 0.5 } else { 0.0 };
            assert_eq!(
                f.moved(f64::from(i), settled, settled, false, false).is_some(),
                settled > 0.0,
                "block {i}: the count restarted at 55"
            );
        }
    }

    /// Without a lead-in, a move that comes back by more than `recede_dps` (0.05) over half
    /// a road window is a bend leaving the window, not a warm-up: held past the window. A
    /// move 0.6 from block 10 on that comes back 0.002 deg/s per block from block 40 has come
    /// back 0.06 over the 30 blocks before block 71 (its first past the window) and is held
    /// until it is back within 0.3 (block 190); at 0.001 per block (0.03) it is released
    /// at block 71.
    #[test]
    fn without_a_lead_in_a_move_coming_back_is_held_past_the_road_window() {
        for (per_block, held_until) in [(0.002, 189), (0.001, 70)] {
            let mut f = Fallback { move_dps: 0.3, release_s: 60.0, recede_dps: 0.05, ..Default::default() };
            for i in 0..=200 {
                let settled = if i < 10 { 0.0 } else { 0.6 - per_block * f64::from((i - 40).max(0)) };
                let held = (10..=held_until).contains(&i);
                assert_eq!(f.moved(f64::from(i), settled, settled, false, false), held.then_some(0.0), "block {i}, {per_block} per block");
            }
        }
    }

    /// After a lead-in the threshold is 0.15 on a quiet gyro: a settled bias 0.2 from the
    /// anchor is held, the anchor's bias (0.05) the hold's end; on a noisy gyro, or without
    /// a lead-in, 0.2 is within 0.3 and not held; with the quiet setting 0 the quiet gyro
    /// keeps 0.3 too.
    #[test]
    fn after_a_lead_in_a_quiet_gyros_threshold_is_the_quiet_one() {
        let p = crate::pipeline::PipelineParams::default();
        for (lead_in_seen, quiet, quiet_dps, held) in
            [(true, true, 0.15, true), (true, false, 0.15, false), (false, true, 0.15, false), (true, true, 0.0, false)]
        {
            let mut f = Fallback { lead_in_seen, quiet_dps, ..Fallback::of(&p) };
            assert_eq!(f.moved(0.0, 0.0, 0.05, false, quiet), None);
            assert_eq!(f.moved(1.0, 0.14, 0.19, false, quiet), None, "0.14 is within either threshold");
            let expect = held.then_some(0.05);
            assert_eq!(f.moved(2.0, 0.2, 0.25, false, quiet), expect, "lead-in {lead_in_seen}, quiet {quiet}, {quiet_dps}");
        }
    }
}
