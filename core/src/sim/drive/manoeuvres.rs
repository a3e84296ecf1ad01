//! Manoeuvres: the phases a drive goes through (straights, turns, clothoid curves, stops,
//! lane changes, ramps, roundabouts), each giving a target speed and the road's yaw rate.

use super::road::Style;
use super::DT;
use crate::sim::SimRng;

#[derive(Debug, Clone, Copy)]
pub(super) enum Phase {
    Still {
        left_s: f64,
    },
    Straight {
        left_m: f64,
    },
    /// A yaw of `left_deg` (signed) at a peak rate, target speed while turning.
    Turn {
        left_deg: f64,
        peak_dps: f64,
        speed_mps: f64,
        ramp_dps2: f64,
        rate_dps: f64,
    },
    Stop {
        wait_s: f64,
    },
    Lane {
        t_s: f64,
        dur_s: f64,
        amp_dps: f64,
    },
}

/// Picks the maneuver after a straight: its phases in order.
pub(super) fn next_phases(st: &Style, v: f64, rng: &mut SimRng) -> Vec<Phase> {
    let u = rng.uniform();
    let mut acc = st.p_turn;
    if u < acc {
        let speed = rng.range(4.0, 6.5);
        let radius = rng.range(8.0, 14.0);
        return vec![Phase::turn(90.0 * rng.sign(), speed, radius, 25.0)];
    }
    acc += st.p_curve;
    if u < acc {
        let angle = rng.range(st.curve_deg.0, st.curve_deg.1) * rng.sign();
        let radius = rng.range(st.curve_radius_m.0, st.curve_radius_m.1);
        let speed = st.cruise_mps.min(libm::sqrt(2.5 * radius)); // lateral accel <= 2.5 m/s^2
                                                                 // Clothoid transitions: the lateral acceleration ramps at a comfortable 0.3-0.6 m/s^3
                                                                 // (road design), so the yaw rate ramps at jerk / speed.
        let ramp = (rng.range(0.3, 0.6) / speed).to_degrees();
        return vec![Phase::turn(angle, speed, radius, ramp)];
    }
    acc += st.p_stop;
    if u < acc {
        return vec![Phase::Stop { wait_s: rng.range(5.0, 45.0) }];
    }
    acc += st.p_lane;
    if u < acc {
        // One lane width (3-3.7 m) sideways in 4-8 s: a full sine of yaw rate whose double
        // integral at speed v is the offset, so the heading excursion shrinks with speed.
        let dur = rng.range(4.0, 8.0);
        let offset_m = rng.range(3.0, 3.7);
        let amp = (2.0 * std::f64::consts::PI * offset_m / (v.max(5.0) * dur * dur)).to_degrees();
        return vec![Phase::Lane { t_s: 0.0, dur_s: dur, amp_dps: amp * rng.sign() }];
    }
    acc += st.p_ramp;
    if u < acc {
        // an exit or entry ramp: a 90-degree or a cloverleaf 270-degree loop
        let angle = if rng.chance(0.5) { 90.0 } else { 270.0 } * rng.sign();
        let radius = rng.range(50.0, 120.0);
        let speed = libm::sqrt(3.0 * radius);
        return vec![Phase::turn(angle, speed, radius, 5.0)];
    }
    acc += st.p_roundabout;
    if u < acc {
        return roundabout(rng);
    }
    vec![Phase::Straight { left_m: rng.range(st.straight_m.0, st.straight_m.1) }]
}

/// A roundabout, driven counter-clockwise (right-hand traffic): a deflection right on entry,
/// the circle left (R 12-25 m), a deflection right on exit; leaving straight on (45 %), to
/// the left (40 %) or back (15 %), so the circle turns 50-270 deg.
fn roundabout(rng: &mut SimRng) -> Vec<Phase> {
    let net_deg = if rng.chance(0.45) {
        0.0
    } else if rng.chance(0.4 / 0.55) {
        90.0
    } else {
        180.0
    };
    let entry_deg = rng.range(25.0, 45.0);
    let exit_deg = rng.range(25.0, 45.0);
    let radius = rng.range(12.0, 25.0);
    let speed = libm::sqrt(2.5 * radius);
    vec![
        Phase::turn(-entry_deg, speed, 2.0 * radius, 25.0),
        Phase::turn(net_deg + entry_deg + exit_deg, speed, radius, 25.0),
        Phase::turn(-exit_deg, speed, 2.0 * radius, 25.0),
    ]
}

impl Phase {
    /// A turn of `left_deg` (signed) at `speed_mps` on radius `radius_m` (peak rate v / R),
    /// the yaw rate ramping at `ramp_dps2` in and out.
    fn turn(left_deg: f64, speed_mps: f64, radius_m: f64, ramp_dps2: f64) -> Phase {
        Phase::Turn { left_deg, peak_dps: (speed_mps / radius_m).to_degrees(), speed_mps, ramp_dps2, rate_dps: 0.0 }
    }

    /// One 0.1 s step of the phase: the target speed and the road's yaw rate.
    pub(super) fn advance(&mut self, st: &Style, v: f64) -> (f64, f64) {
        match self {
            Phase::Still { left_s } => {
                *left_s -= DT;
                (0.0, 0.0)
            }
            Phase::Straight { left_m } => {
                *left_m -= v * DT;
                (st.cruise_mps, 0.0)
            }
            Phase::Turn { left_deg, peak_dps, speed_mps, ramp_dps2, rate_dps } => {
                if v > *speed_mps + 0.5 && rate_dps.abs() < 1e-9 {
                    (*speed_mps, 0.0) // brake before turning
                } else {
                    let remaining = left_deg.abs();
                    let stop_dist = *rate_dps * *rate_dps / (2.0 * *ramp_dps2);
                    let peak = peak_dps.min(v.max(1.0) / 8.0 * 57.29577951308232);
                    *rate_dps = if remaining <= stop_dist + 1e-9 {
                        (*rate_dps - *ramp_dps2 * DT).max(0.5)
                    } else {
                        (*rate_dps + *ramp_dps2 * DT).min(peak)
                    };
                    let step = (*rate_dps * DT).min(remaining);
                    let signed = step * left_deg.signum();
                    *left_deg -= signed;
                    (*speed_mps, signed / DT)
                }
            }
            Phase::Stop { wait_s } => {
                if v < 0.05 {
                    *wait_s -= DT;
                }
                (0.0, 0.0)
            }
            Phase::Lane { t_s, dur_s, amp_dps } => {
                *t_s += DT;
                let u = *t_s / *dur_s;
                (st.cruise_mps, *amp_dps * libm::sin(2.0 * std::f64::consts::PI * u))
            }
        }
    }

    /// The phase has run its course.
    pub(super) fn done(&self) -> bool {
        match *self {
            Phase::Still { left_s } => left_s <= 0.0,
            Phase::Straight { left_m } => left_m <= 0.0,
            Phase::Turn { left_deg, .. } => left_deg.abs() < 1e-9,
            Phase::Stop { wait_s } => wait_s <= 0.0,
            Phase::Lane { t_s, dur_s, .. } => t_s >= dur_s,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::road::{style, Scenario, Style};
    use super::*;

    #[test]
    fn a_roundabout_turns_right_left_right_and_leaves_straight_left_or_back() {
        let mut rng = SimRng::new(5);
        let mut nets = Vec::new();
        for _ in 0..200 {
            let p = roundabout(&mut rng);
            let deg: Vec<f64> = p.iter().map(|ph| if let Phase::Turn { left_deg, .. } = ph { *left_deg } else { f64::NAN }).collect();
            assert_eq!(deg.len(), 3);
            assert!(deg[0] < 0.0 && deg[2] < 0.0 && deg[1] > 0.0, "{deg:?}");
            let net = deg.iter().sum::<f64>();
            assert!([0.0, 90.0, 180.0].iter().any(|n| (net - n).abs() < 1e-9), "net {net}");
            nets.push(net);
        }
        for n in [0.0, 90.0, 180.0] {
            assert!(nets.iter().any(|x| (x - n).abs() < 1e-9), "no exit at {n}");
        }
    }

    #[test]
    fn a_lane_change_moves_one_lane_width_and_keeps_the_heading() {
        let st = style(Scenario::Highway);
        let mut rng = SimRng::new(8);
        for v in [13.0, 30.0] {
            let mut p = next_phases(&Style { p_turn: 0.0, p_curve: 0.0, p_stop: 0.0, p_lane: 1.0, ..st }, v, &mut rng).remove(0);
            assert!(matches!(p, Phase::Lane { .. }));
            let (mut heading_rad, mut lateral_m) = (0.0f64, 0.0f64);
            while !p.done() {
                let (_, rate_dps) = p.advance(&st, v);
                heading_rad += rate_dps.to_radians() * DT;
                lateral_m += v * heading_rad.sin() * DT;
            }
            assert!(heading_rad.to_degrees().abs() < 0.05, "heading back: {}", heading_rad.to_degrees());
            assert!((2.9..3.8).contains(&lateral_m.abs()), "offset {lateral_m} m at {v} m/s");
        }
    }
}
