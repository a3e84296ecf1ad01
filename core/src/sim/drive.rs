//! Simulated road drives for HDR: a stationary lead-in, then straights with human swaying,
//! curves, 90-degree turns, stops at lights, lane changes and ramps, mixed per scenario;
//! a CRS03-like gyro warming up with the cabin; 1 Hz GPS course, noisier when slow and
//! missing below 2 m/s.

use super::{round_to, GyroModel, GyroSpec, SimRng};
use crate::error::Error;
use crate::log::{Column, DriveLog};
use serde::{Deserialize, Serialize};

/// Kinds of drive, after the descriptions in the HDR paper's Tables II and IV.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Scenario {
    /// Mostly straight streets, turns at intersections, stops at lights.
    City,
    /// Dense 90-degree turns (City 2: over 40 in 21.6 min).
    Downtown,
    /// Mostly curving streets.
    Suburbs,
    /// Long straights, some curves.
    Rural,
    /// Long straights, gentle curves, lane changes, ramps.
    Highway,
    /// City, rural and highway stretches in turn.
    Mixed,
}

impl std::str::FromStr for Scenario {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        Ok(match s {
            "city" => Scenario::City,
            "downtown" => Scenario::Downtown,
            "suburbs" => Scenario::Suburbs,
            "rural" => Scenario::Rural,
            "highway" => Scenario::Highway,
            "mixed" => Scenario::Mixed,
            _ => {
                return Err(Error::param(
                    "scenario",
                    format!("\"{s}\" is not a drive scenario (city, downtown, suburbs, rural, highway, mixed)"),
                ))
            }
        })
    }
}

/// A drive to simulate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DriveConfig {
    pub scenario: Scenario,
    /// Total length including the 20 s stationary lead-in.
    pub minutes: f64,
    pub seed: u64,
}

/// Road and driver behaviour of one scenario.
#[derive(Debug, Clone, Copy)]
struct Style {
    cruise_mps: f64,
    straight_m: (f64, f64),
    p_turn: f64,
    p_curve: f64,
    p_stop: f64,
    p_lane: f64,
    p_ramp: f64,
    curve_deg: (f64, f64),
    curve_radius_m: (f64, f64),
    /// Human sway: the rate sigma of a damped oscillation about the road heading, deg/s
    /// (2.5x the first guesses, by the recorded roads: docs/simulator.md).
    sway_dps: f64,
    /// Road meander: a Gauss-Markov curvature in distance (sigma, deg/m; correlation
    /// length, m), so roads that look straight still turn slowly, as recorded ones do.
    meander_deg_per_m: f64,
    meander_len_m: f64,
}

fn style(s: Scenario) -> Style {
    match s {
        Scenario::City | Scenario::Mixed => Style {
            cruise_mps: 13.0,
            straight_m: (150.0, 500.0),
            p_turn: 0.4,
            p_curve: 0.15,
            p_stop: 0.3,
            p_lane: 0.1,
            p_ramp: 0.0,
            curve_deg: (15.0, 45.0),
            curve_radius_m: (80.0, 200.0),
            sway_dps: 0.5,
            meander_deg_per_m: 0.0105,
            meander_len_m: 80.0,
        },
        Scenario::Downtown => Style {
            cruise_mps: 9.0,
            straight_m: (70.0, 160.0),
            p_turn: 0.65,
            p_curve: 0.0,
            p_stop: 0.3,
            p_lane: 0.05,
            p_ramp: 0.0,
            curve_deg: (10.0, 20.0),
            curve_radius_m: (60.0, 100.0),
            sway_dps: 0.5,
            meander_deg_per_m: 0.0105,
            meander_len_m: 50.0,
        },
        Scenario::Suburbs => Style {
            cruise_mps: 12.0,
            straight_m: (40.0, 200.0),
            p_turn: 0.2,
            p_curve: 0.6,
            p_stop: 0.15,
            p_lane: 0.0,
            p_ramp: 0.0,
            curve_deg: (20.0, 90.0),
            curve_radius_m: (40.0, 150.0),
            sway_dps: 0.375,
            meander_deg_per_m: 0.014,
            meander_len_m: 60.0,
        },
        Scenario::Rural => Style {
            cruise_mps: 22.0,
            straight_m: (600.0, 3000.0),
            p_turn: 0.15,
            p_curve: 0.6,
            p_stop: 0.05,
            p_lane: 0.05,
            p_ramp: 0.0,
            curve_deg: (10.0, 60.0),
            curve_radius_m: (200.0, 600.0),
            sway_dps: 0.3,
            meander_deg_per_m: 0.0025,
            meander_len_m: 200.0,
        },
        Scenario::Highway => Style {
            cruise_mps: 30.0,
            straight_m: (1500.0, 6000.0),
            p_turn: 0.0,
            p_curve: 0.5,
            p_stop: 0.0,
            p_lane: 0.45,
            p_ramp: 0.05,
            curve_deg: (5.0, 40.0),
            curve_radius_m: (800.0, 2500.0),
            sway_dps: 0.2,
            meander_deg_per_m: 0.0032,
            meander_len_m: 600.0,
        },
    }
}

#[derive(Debug, Clone, Copy)]
enum Phase {
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

const DT: f64 = 0.1;
const ACCEL: f64 = 1.5;
const BRAKE: f64 = 2.5;
pub const LEAD_IN_S: f64 = 20.0;

/// Picks the maneuver after a straight.
fn next_phase(st: &Style, v: f64, rng: &mut SimRng) -> Phase {
    let u = rng.uniform();
    let mut acc = st.p_turn;
    if u < acc {
        let speed = rng.range(4.0, 6.5);
        let radius = rng.range(8.0, 14.0);
        let peak = (speed / radius).to_degrees();
        return Phase::Turn { left_deg: 90.0 * rng.sign(), peak_dps: peak, speed_mps: speed, ramp_dps2: 25.0, rate_dps: 0.0 };
    }
    acc += st.p_curve;
    if u < acc {
        let angle = rng.range(st.curve_deg.0, st.curve_deg.1) * rng.sign();
        let radius = rng.range(st.curve_radius_m.0, st.curve_radius_m.1);
        let speed = st.cruise_mps.min(libm::sqrt(2.5 * radius)); // lateral accel <= 2.5 m/s^2
        let peak = (speed / radius).to_degrees();
        return Phase::Turn { left_deg: angle, peak_dps: peak, speed_mps: speed, ramp_dps2: 4.0, rate_dps: 0.0 };
    }
    acc += st.p_stop;
    if u < acc {
        return Phase::Stop { wait_s: rng.range(5.0, 45.0) };
    }
    acc += st.p_lane;
    if u < acc {
        return Phase::Lane { t_s: 0.0, dur_s: rng.range(3.0, 5.0), amp_dps: rng.range(1.5, 3.0) * rng.sign() };
    }
    acc += st.p_ramp;
    if u < acc {
        // an exit or entry ramp: a 90-degree or a cloverleaf 270-degree loop
        let angle = if rng.chance(0.5) { 90.0 } else { 270.0 } * rng.sign();
        let radius = rng.range(50.0, 120.0);
        let speed = libm::sqrt(3.0 * radius);
        return Phase::Turn { left_deg: angle, peak_dps: (speed / radius).to_degrees(), speed_mps: speed, ramp_dps2: 5.0, rate_dps: 0.0 };
    }
    let _ = v;
    Phase::Straight { left_m: rng.range(st.straight_m.0, st.straight_m.1) }
}

/// Scenario of a mixed drive at time t: city, rural and highway stretches of ~5 min.
fn mixed_style(block: usize) -> Scenario {
    [Scenario::City, Scenario::Rural, Scenario::Highway, Scenario::Rural, Scenario::Suburbs][block % 5]
}

impl Phase {
    /// One 0.1 s step of the phase: the target speed and the road's yaw rate.
    fn advance(&mut self, st: &Style, v: f64) -> (f64, f64) {
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
    fn done(&self) -> bool {
        match *self {
            Phase::Still { left_s } => left_s <= 0.0,
            Phase::Straight { left_m } => left_m <= 0.0,
            Phase::Turn { left_deg, .. } => left_deg.abs() < 1e-9,
            Phase::Stop { wait_s } => wait_s <= 0.0,
            Phase::Lane { t_s, dur_s, .. } => t_s >= dur_s,
        }
    }
}

/// The simulated GPS course receiver.
struct Gps {
    bias_deg: f64,
    dropout_s: f64,
    /// A multipath excursion (urban canyons): its offset and seconds left.
    jump_deg: f64,
    jump_s: f64,
}

/// GPS course latency, in 0.1 s steps: the course describes the heading this long ago.
const GPS_LATENCY_STEPS: usize = 3;

impl Gps {
    /// The reference heading at a whole second (NaN when none): noisier when slow, none
    /// below 2 m/s, rare dropouts, multipath excursions where `urban`.
    fn course(&mut self, heading_deg: f64, v: f64, urban: bool, rng: &mut SimRng) -> f64 {
        if self.jump_s > 0.0 {
            self.jump_s -= 1.0;
        } else {
            self.jump_deg = 0.0;
            if urban && rng.chance(0.01) {
                self.jump_deg = 6.0 * rng.normal();
                self.jump_s = rng.range(2.0, 6.0);
            }
        }
        let heading_deg = heading_deg + self.jump_deg;
        if self.dropout_s > 0.0 {
            self.dropout_s -= 1.0;
        } else if rng.chance(0.003) {
            self.dropout_s = rng.range(3.0, 20.0);
        } else if v >= 2.0 {
            let sigma = 0.15 + 3.0 / v;
            let course = -(heading_deg + self.bias_deg + sigma * rng.normal());
            let mut reference = -(course.rem_euclid(360.0));
            if reference <= -180.0 {
                reference += 360.0;
            }
            return reference;
        }
        f64::NAN
    }
}

/// Simulates a drive at 10 Hz: time_s, gyro_dps, temp_c, ref_heading_deg (1 Hz), speed_mps.
pub fn simulate_drive(cfg: &DriveConfig) -> DriveLog {
    simulate_drive_with(cfg, &GyroSpec::crs03_like())
}

/// As `simulate_drive`, with the gyro drawn from another spec (same road for the same seed).
pub fn simulate_drive_with(cfg: &DriveConfig, spec: &GyroSpec) -> DriveLog {
    let mut rng = SimRng::new(cfg.seed ^ 0x0D21_5EED);
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::TempC, Column::RefHeadingDeg, Column::SpeedMps]);
    log.meta.bias_s = Some(LEAD_IN_S);
    log.meta.description = Some(format!("simulated {:?} drive, {} min, seed {}", cfg.scenario, cfg.minutes, cfg.seed));
    // Cabin warm-up: the gyro starts at the garage temperature and warms toward cabin comfort.
    let temp_start = rng.range(0.0, 15.0);
    let temp_end = rng.range(20.0, 26.0);
    let warm_tau_s = rng.range(4.0, 12.0) * 60.0;
    let mut gyro = GyroModel::draw(spec, temp_start, &mut rng);
    let mut heading_deg = rng.range(0.0, 360.0);
    let (mut v, mut sway_rate, mut sway_dev) = (0.0f64, 0.0f64, 0.0f64);
    let mut meander_deg_per_m = 0.0f64;
    let mut phase = Phase::Still { left_s: LEAD_IN_S };
    let mut gps = Gps { bias_deg: rng.range(-0.3, 0.3), dropout_s: 0.0, jump_deg: 0.0, jump_s: 0.0 };
    let mut past_heading = [0.0f64; GPS_LATENCY_STEPS + 1];
    let n = (cfg.minutes * 600.0).round() as usize;
    for i in 0..=n {
        let t = i as f64 / 10.0;
        let scenario = if cfg.scenario == Scenario::Mixed { mixed_style((t / 300.0) as usize) } else { cfg.scenario };
        let st = style(scenario);
        // Speed target and road yaw rate of the phase.
        let (target_v, road_rate) = phase.advance(&st, v);
        // Longitudinal dynamics with comfortable limits.
        if v < target_v {
            v = (v + ACCEL * DT).min(target_v);
        } else {
            v = (v - BRAKE * DT).max(target_v);
        }
        // Human swaying: a damped stochastic oscillation of heading about the road's.
        if v > 1.0 {
            let tau_r = 1.5;
            let tau_e = 3.0;
            sway_rate += DT * (-sway_rate / tau_r - sway_dev / (tau_e * tau_r)) + st.sway_dps * libm::sqrt(2.0 * DT / tau_r) * rng.normal();
            sway_dev += sway_rate * DT;
        } else {
            sway_rate = 0.0;
            sway_dev *= 0.9;
        }
        // Road meander: first-order Gauss-Markov curvature over the distance driven.
        let a = libm::exp(-v * DT / st.meander_len_m);
        meander_deg_per_m = a * meander_deg_per_m + st.meander_deg_per_m * libm::sqrt(1.0 - a * a) * rng.normal();
        let meander_rate = v * meander_deg_per_m;
        let true_rate = if i == 0 { 0.0 } else { road_rate + if v > 1.0 { sway_rate + meander_rate } else { 0.0 } };
        heading_deg += true_rate * DT;
        past_heading.rotate_right(1);
        past_heading[0] = heading_deg;
        if i == 0 {
            past_heading = [heading_deg; GPS_LATENCY_STEPS + 1];
        }
        let temp = temp_end + (temp_start - temp_end) * libm::exp(-t / warm_tau_s);
        let g = gyro.measure(true_rate, temp, DT, &mut rng);
        let urban = matches!(scenario, Scenario::City | Scenario::Downtown);
        let reference = if i % 10 == 0 { gps.course(past_heading[GPS_LATENCY_STEPS], v, urban, &mut rng) } else { f64::NAN };
        let speed_meas = (v + 0.03 * rng.normal()).max(0.0);
        log.push_row(&[
            (Column::TimeS, t),
            (Column::GyroDps, round_to(g, 3)),
            (Column::TempC, round_to(temp, 2)),
            (Column::RefHeadingDeg, if reference.is_nan() { f64::NAN } else { round_to(reference, 2) }),
            (Column::SpeedMps, round_to(speed_meas, 2)),
        ]);
        // Phase transitions.
        let done = phase.done();
        if done {
            phase = match phase {
                Phase::Still { .. } | Phase::Turn { .. } | Phase::Stop { .. } | Phase::Lane { .. } => {
                    Phase::Straight { left_m: rng.range(st.straight_m.0, st.straight_m.1) }
                }
                Phase::Straight { .. } => next_phase(&st, v, &mut rng),
            };
        }
    }
    log
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_log_and_scenarios_parse() {
        let cfg = DriveConfig { scenario: Scenario::City, minutes: 3.0, seed: 9 };
        let a = simulate_drive(&cfg);
        let b = simulate_drive(&cfg);
        let (mut ca, mut cb) = (Vec::new(), Vec::new());
        a.write_csv(&mut ca).unwrap();
        b.write_csv(&mut cb).unwrap();
        assert_eq!(ca, cb);
        assert_eq!(a.len(), 1801);
        assert!("highway".parse::<Scenario>().is_ok());
        assert!("moon".parse::<Scenario>().is_err());
    }
}
