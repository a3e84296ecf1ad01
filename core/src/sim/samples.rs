//! The logs the project ships in `sample-logs/`: nine training drives shaped like the HDR
//! paper's Table II, five test drives like its Table IV, two robot runs, a turntable session
//! and a static log. `gyrodrift samples --out sample-logs` rewrites them bit-identically.

use super::{SimKind, SimRequest};

/// One shipped sample log: its path under `sample-logs/` and the request that makes it.
#[derive(Debug, Clone, Copy)]
pub struct SampleLog {
    pub path: &'static str,
    pub name: &'static str,
    pub kind: SimKind,
    pub scenario: Option<&'static str>,
    pub minutes: Option<f64>,
    pub seed: u64,
}

impl SampleLog {
    pub fn request(&self) -> SimRequest {
        SimRequest {
            kind: self.kind,
            scenario: self.scenario.map(str::to_string),
            minutes: self.minutes,
            seed: self.seed,
            name: Some(self.name.to_string()),
            errors: None,
        }
    }

    /// The request of another realisation of this log: the seed + 1000 x `k` (0 = shipped).
    pub fn realisation(&self, k: u64) -> SimRequest {
        SimRequest { seed: self.seed + 1000 * k, ..self.request() }
    }
}

const fn drive(path: &'static str, name: &'static str, scenario: &'static str, minutes: f64, seed: u64) -> SampleLog {
    SampleLog { path, name, kind: SimKind::Drive, scenario: Some(scenario), minutes: Some(minutes), seed }
}

/// Every shipped sample log.
pub const SAMPLE_LOGS: &[SampleLog] = &[
    // Training set, after Table II (name, duration, kind of roads).
    drive("train/city-1.csv", "City 1", "city", 19.4, 101),
    drive("train/suburbs.csv", "Suburbs", "suburbs", 24.3, 102),
    drive("train/mixed.csv", "Mixed", "mixed", 20.0, 103),
    drive("train/rural-1.csv", "Rural 1", "rural", 12.9, 104),
    drive("train/rural-2.csv", "Rural 2", "rural", 18.9, 105),
    drive("train/highway-1.csv", "Highway 1", "highway", 52.1, 106),
    drive("train/highway-2.csv", "Highway 2", "highway", 50.4, 107),
    drive("train/highway-mix.csv", "Highway Mix", "mixed", 47.6, 108),
    drive("train/city-2.csv", "City 2", "downtown", 21.6, 109),
    // Test set, after Table IV.
    drive("test/city-3.csv", "City 3", "city", 22.2, 201),
    drive("test/mixed-2.csv", "Mixed 2", "mixed", 19.2, 202),
    drive("test/rural-3.csv", "Rural 3", "rural", 16.6, 203),
    drive("test/highway-3.csv", "Highway 3", "highway", 36.9, 204),
    drive("test/highway-4.csv", "Highway 4", "highway", 43.2, 205),
    // Gyrodometry: a straight 2:20 min run with 15 bumps (the paper's Fig. 2) and a square path.
    SampleLog {
        path: "robot/straight.csv",
        name: "Robot straight",
        kind: SimKind::Robot,
        scenario: Some("straight"),
        minutes: Some(140.0 / 60.0),
        seed: 301,
    },
    SampleLog {
        path: "robot/square.csv",
        name: "Robot square",
        kind: SimKind::Robot,
        scenario: Some("turns"),
        minutes: Some(5.0),
        seed: 302,
    },
    // Calibration and Allan deviation.
    SampleLog {
        path: "turntable/session.csv",
        name: "Turntable session",
        kind: SimKind::Turntable,
        scenario: None,
        minutes: None,
        seed: 401,
    },
    SampleLog { path: "static/static-2h.csv", name: "Static 2 h", kind: SimKind::Static, scenario: None, minutes: Some(120.0), seed: 501 },
];

/// The training drives' paths.
pub fn training() -> impl Iterator<Item = &'static SampleLog> {
    SAMPLE_LOGS.iter().filter(|s| s.path.starts_with("train/"))
}

/// The test drives' paths.
pub fn test_set() -> impl Iterator<Item = &'static SampleLog> {
    SAMPLE_LOGS.iter().filter(|s| s.path.starts_with("test/"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn realisation_zero_is_the_shipped_request_and_k_shifts_the_seed() {
        let s = &SAMPLE_LOGS[0];
        assert_eq!(s.realisation(0), s.request());
        let r = s.realisation(3);
        assert_eq!(r.seed, s.seed + 3000);
        assert_eq!((r.kind, r.scenario.as_deref(), r.minutes), (s.kind, s.scenario, s.minutes));
    }
}
