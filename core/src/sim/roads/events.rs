//! Lane-change-like manoeuvres in the 1 Hz yaw rate: an S-shaped heading excursion (a turn
//! one way, then back) that leaves the heading where it was. Found the same way on recorded
//! and simulated drives, so their rate and shape compare (issue 13, item 1). Roundabouts and
//! ramps show as curve runs of more than 180 degrees (`RoadSamples::curve_deg`).

use super::THETA_W_DPS;

/// The shortest and longest S-manoeuvre, s (lane changes take 3-10 s).
pub const S_MIN_S: usize = 3;
pub const S_MAX_S: usize = 12;
/// The heading must stray at least this far (a lane change at 30 m/s peaks near 2-3 deg),
/// and not beyond the upper limit (that is a turn), deg.
pub const S_PEAK_MIN_DEG: f64 = 1.5;
pub const S_PEAK_MAX_DEG: f64 = 15.0;
/// ...and come back to within this fraction of its excursion of where it started.
pub const S_BACK_FRACTION: f64 = 0.25;

/// One S-manoeuvre: its length and the largest heading excursion during it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SManoeuvre {
    pub length_s: f64,
    pub peak_deg: f64,
}

/// The S-manoeuvres of a stretch of consecutive moving 1 Hz yaw rates (bias removed), deg/s:
/// from a block where the rate crosses theta_w (the one before is under it), the shortest stretch of `S_MIN_S..=S_MAX_S`
/// blocks whose rate crosses theta_w in both directions, whose heading strays between
/// `S_PEAK_MIN_DEG` and `S_PEAK_MAX_DEG` and ends within `S_BACK_FRACTION` of that of its
/// start. Found
/// ones do not overlap (the search goes on after each).
pub fn s_manoeuvres(rate_dps: &[f64]) -> Vec<SManoeuvre> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < rate_dps.len() {
        // an excursion starts where the rate crosses theta_w
        if rate_dps[i].abs() < THETA_W_DPS || (i > 0 && rate_dps[i - 1].abs() >= THETA_W_DPS) {
            i += 1;
            continue;
        }
        match s_from(&rate_dps[i..]) {
            Some(m) => {
                i += m.length_s as usize;
                out.push(m);
            }
            None => i += 1,
        }
    }
    out
}

/// The shortest S-manoeuvre starting at the first block, if any.
fn s_from(rate_dps: &[f64]) -> Option<SManoeuvre> {
    let (mut heading, mut peak, mut pos, mut neg) = (0.0f64, 0.0f64, false, false);
    for (k, &r) in rate_dps.iter().take(S_MAX_S).enumerate() {
        heading += r; // 1 s blocks: deg/s x 1 s
        peak = peak.max(heading.abs());
        pos |= r >= THETA_W_DPS;
        neg |= r <= -THETA_W_DPS;
        let n = k + 1;
        if peak > S_PEAK_MAX_DEG {
            return None;
        }
        if n >= S_MIN_S && pos && neg && peak >= S_PEAK_MIN_DEG && heading.abs() <= S_BACK_FRACTION * peak {
            return Some(SManoeuvre { length_s: n as f64, peak_deg: peak });
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lane_change_hand_worked() {
        // straight, then 1, 2, 0, -2, -1 deg/s: heading 1, 3, 3, 1, 0; peak 3 deg; at 4 s the
        // heading is 1 deg off (over a quarter of 3), at 5 s back: one of 5 s
        let r = [0.0, 0.0, 1.0, 2.0, 0.0, -2.0, -1.0, 0.0, 0.0];
        assert_eq!(s_manoeuvres(&r), vec![SManoeuvre { length_s: 5.0, peak_deg: 3.0 }]);
    }

    #[test]
    fn turns_curves_and_small_wiggles_are_not_lane_changes() {
        // a 90-degree turn: one sign, too far
        assert!(s_manoeuvres(&[0.0, 10.0, 20.0, 20.0, 20.0, 20.0, 0.0, 0.0]).is_empty());
        // a curve that does not come back
        assert!(s_manoeuvres(&[1.0, 1.0, 1.0, 1.0, 1.0, -0.2, -0.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).is_empty());
        // sway under 1.5 deg of excursion
        assert!(s_manoeuvres(&[0.6, 0.6, -0.6, -0.6, 0.6, 0.6, -0.6, -0.6]).is_empty());
        // a slow S of 16 s is longer than S_MAX_S (and starts only where it crosses theta_w)
        let slow: Vec<f64> = (0..16).map(|k| if k < 8 { 0.6 } else { -0.6 }).collect();
        assert!(s_manoeuvres(&slow).is_empty());
    }

    #[test]
    fn two_in_a_row_do_not_overlap() {
        let one = [1.0, 2.0, 0.0, -2.0, -1.0];
        let r: Vec<f64> = one.iter().chain(&[0.0, 0.0]).chain(&one).copied().collect();
        let m = SManoeuvre { length_s: 5.0, peak_deg: 3.0 };
        assert_eq!(s_manoeuvres(&r), vec![m, m]);
    }
}
