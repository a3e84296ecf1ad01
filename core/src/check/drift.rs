//! Whether the gyro's bias moves while driving: the rate the gyro reads at each standing the
//! speed or the wheels show is its bias then, so standings that disagree say the bias
//! drifts (a warm-up, a walk, a re-calibration). It tells the user the gyro's class from the
//! log itself: a method holding one bias (raw integration after the lead-in) drifts with it.

use super::{finding, CheckReport, Severity};
use crate::still::{Blocks, StillSource};

/// A standing counts from this many still 1 s blocks in a row; its first and last are
/// dropped (braking, pulling away), so its rate is the median of five or more.
const STANDING_MIN_BLOCKS: usize = 7;

/// Standings further apart than this say the bias moves, deg/s: 0.1 deg/s held is 6 deg of
/// heading a minute. The recorded drives' standings agree within 0.05 (the three Pixel 6a
/// drives, 42-142 min, 8-23 standings; the VN-100 town drive, 11 min; the rest stand once
/// or never: `gyrodrift check --json` on each recipe's import, README).
pub const BIAS_DRIFT_DPS: f64 = 0.1;

/// Each standing the speed or the wheels show (at least `STANDING_MIN_BLOCKS` s): the stamp
/// of its first kept block, s, and the median of its kept blocks' rates, deg/s. Empty where
/// only the gyro judges standing: a steady turn would read as a moved bias.
pub fn standings(blocks: &Blocks) -> Vec<(f64, f64)> {
    if !matches!(blocks.source, StillSource::Speed | StillSource::Odometry) {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut k = 0;
    while k < blocks.len() {
        let run = blocks.still[k..].iter().take_while(|&&s| s).count();
        if run >= STANDING_MIN_BLOCKS {
            let kept = k + 1..k + run - 1;
            let mut rates = blocks.rate_dps[kept.clone()].to_vec();
            out.push((blocks.time_s[kept.start], crate::metrics::quantile_mut(&mut rates, 0.5)));
        }
        k += run.max(1);
    }
    out
}

/// The first standing and the one whose rate is furthest from it (the first itself when
/// alone), in `standings`' form; None without standings.
pub fn furthest(standings: &[(f64, f64)]) -> Option<((f64, f64), (f64, f64))> {
    let &first = standings.first()?;
    let far = standings.iter().copied().max_by(|a, b| (a.1 - first.1).abs().total_cmp(&(b.1 - first.1).abs()))?;
    Some((first, far))
}

/// The standings' rates (`r.stop_bias_dps`) and, where a later one is more than
/// `BIAS_DRIFT_DPS` from the first, a finding naming the first and the furthest.
pub(super) fn bias_drift(r: &mut CheckReport, blocks: &Blocks) {
    r.stop_bias_dps = standings(blocks);
    let Some(((t0, b0), (t1, b1))) = furthest(&r.stop_bias_dps) else { return };
    let d = b1 - b0;
    if d.abs() > BIAS_DRIFT_DPS {
        let message = format!(
            "the gyro's bias moves while driving: it reads {b0:.2} deg/s standing at {t0:.0} s and {b1:.2} at {t1:.0} s ({:.0} deg of heading a minute where the first is held): a warm-up or a drift, which ZARU and the pipeline follow at each stop and raw integration does not",
            d.abs() * 60.0
        );
        r.findings.push(finding(
            Severity::Info,
            "bias_drift",
            message,
            Some("gyrodrift pipeline, or a lead-in once the gyro has warmed up"),
        ));
    }
}
