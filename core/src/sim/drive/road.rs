//! Roads and drivers per scenario: what a straight, a curve and the sway look like.

use crate::error::Error;
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

/// Road and driver behaviour of one scenario.
#[derive(Debug, Clone, Copy)]
pub(super) struct Style {
    pub(super) cruise_mps: f64,
    pub(super) straight_m: (f64, f64),
    pub(super) p_turn: f64,
    pub(super) p_curve: f64,
    pub(super) p_stop: f64,
    pub(super) p_lane: f64,
    pub(super) p_ramp: f64,
    /// Roundabouts (none in the first generator; recorded towns loop about once an hour).
    pub(super) p_roundabout: f64,
    pub(super) curve_deg: (f64, f64),
    pub(super) curve_radius_m: (f64, f64),
    /// Human sway: the rate sigma of a damped oscillation about the road heading, deg/s (its
    /// root mean square: the size itself varies slowly, `SWAY_VOL_SIGMA`)
    /// (2.5x the first guesses, by the recorded roads: docs/simulator.md).
    pub(super) sway_dps: f64,
    /// Road meander: a Gauss-Markov curvature in distance (sigma, deg/m; correlation
    /// length, m), so roads that look straight still turn slowly, as recorded ones do.
    pub(super) meander_deg_per_m: f64,
    pub(super) meander_len_m: f64,
}

pub(super) fn style(s: Scenario) -> Style {
    match s {
        Scenario::City | Scenario::Mixed => Style {
            cruise_mps: 13.0,
            straight_m: (150.0, 500.0),
            p_turn: 0.4,
            p_curve: 0.15,
            p_stop: 0.3,
            p_lane: 0.1,
            p_ramp: 0.0,
            p_roundabout: 0.02,
            curve_deg: (15.0, 45.0),
            curve_radius_m: (80.0, 200.0),
            sway_dps: 0.41,
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
            p_roundabout: 0.0,
            curve_deg: (10.0, 20.0),
            curve_radius_m: (60.0, 100.0),
            sway_dps: 0.41,
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
            p_roundabout: 0.02,
            curve_deg: (20.0, 90.0),
            curve_radius_m: (40.0, 150.0),
            sway_dps: 0.31,
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
            p_roundabout: 0.02,
            // Sweeping bends as the recorded rural roads have them, up to 120 deg on radii
            // up to 1.5 km (a minute or two at 0.8-1 deg/s; 10-60 deg on 200-600 m before,
            // when the simulated rural roads had a fifth of the recorded slow curvature:
            // docs/simulator.md, issue 13).
            curve_deg: (10.0, 120.0),
            curve_radius_m: (200.0, 1500.0),
            sway_dps: 0.37,
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
            p_roundabout: 0.0,
            curve_deg: (5.0, 40.0),
            curve_radius_m: (800.0, 2500.0),
            sway_dps: 0.31,
            meander_deg_per_m: 0.0032,
            meander_len_m: 600.0,
        },
    }
}

/// Scenario of a mixed drive at time t: city, rural and highway stretches of ~5 min.
pub(super) fn mixed_style(block: usize) -> Scenario {
    [Scenario::City, Scenario::Rural, Scenario::Highway, Scenario::Rural, Scenario::Suburbs][block % 5]
}
