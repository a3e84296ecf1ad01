//! Recorded roads against simulated ones: per drive, pooled, per road class, and the
//! two-sample distance of each distribution.

use super::samples::{road_samples, ClassedSamples, RoadClass, RoadSamples, RoadSummary};
use super::spectrum::BAND_NAMES;
use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use serde::Serialize;

/// Two-sample Kolmogorov-Smirnov distances between two pools, one per distribution.
#[derive(Debug, Clone, Serialize)]
pub struct RoadDistance {
    pub abs_rate: f64,
    pub straight_runs: f64,
    pub slow_rate: f64,
    pub curve_runs: f64,
    pub curve_deg: f64,
    pub curve_radius: f64,
    /// Per spectrum band (`spectrum::BANDS`): the distance of the windows' band powers.
    pub spectrum: [f64; 5],
    /// S-manoeuvres (lane-change-like): length and excursion.
    pub s_length: f64,
    pub s_peak: f64,
    /// Fast sway (10 s windows' residual spread).
    pub sway: f64,
}

impl RoadDistance {
    pub fn between(a: &RoadSamples, b: &RoadSamples) -> RoadDistance {
        RoadDistance {
            abs_rate: ks_distance(&a.abs_rate_dps, &b.abs_rate_dps),
            straight_runs: ks_distance(&a.straight_runs_s, &b.straight_runs_s),
            slow_rate: ks_distance(&a.slow_rate_dps, &b.slow_rate_dps),
            curve_runs: ks_distance(&a.curve_runs_s, &b.curve_runs_s),
            curve_deg: ks_distance(&a.curve_deg, &b.curve_deg),
            curve_radius: ks_distance(&a.curve_radius_m, &b.curve_radius_m),
            spectrum: std::array::from_fn(|k| ks_distance(&a.band_power_dps2[k], &b.band_power_dps2[k])),
            s_length: ks_distance(&a.s_length_s, &b.s_length_s),
            s_peak: ks_distance(&a.s_peak_deg, &b.s_peak_deg),
            sway: ks_distance(&a.sway_dps, &b.sway_dps),
        }
    }

    /// The distances in the order of `STATISTICS`.
    pub fn values(&self) -> [f64; 6] {
        [self.abs_rate, self.straight_runs, self.slow_rate, self.curve_runs, self.curve_deg, self.curve_radius]
    }
}

/// The compared distributions: name, unit, and the samples of a pool.
pub const STATISTICS: [(&str, &str); 6] = [
    ("abs yaw rate", "deg/s"),
    ("straight run", "s"),
    ("30 s yaw rate", "deg/s"),
    ("curve length", "s"),
    ("curve angle", "deg"),
    ("curve radius", "m"),
];

/// The samples of statistic `i` of `STATISTICS`.
pub fn statistic(s: &RoadSamples, i: usize) -> &[f64] {
    [&s.abs_rate_dps, &s.straight_runs_s, &s.slow_rate_dps, &s.curve_runs_s, &s.curve_deg, &s.curve_radius_m][i]
}

/// One road class: the recorded and simulated pools' summaries and their distances.
#[derive(Debug, Clone, Serialize)]
pub struct ClassComparison {
    pub class: RoadClass,
    pub recorded: RoadSummary,
    pub simulated: RoadSummary,
    pub distance: RoadDistance,
}

/// Recorded against simulated roads: per drive, pooled, per class, and the distances.
#[derive(Debug, Clone, Serialize)]
pub struct RoadComparison {
    pub recorded: Vec<(String, RoadSummary)>,
    /// Recorded drives left out: no speed column, so no block is known to be moving.
    pub skipped: Vec<String>,
    pub simulated: Vec<(String, RoadSummary)>,
    pub recorded_pool: RoadSummary,
    pub simulated_pool: RoadSummary,
    pub distance: RoadDistance,
    pub classes: Vec<ClassComparison>,
    /// The pooled samples (for plots), not serialised.
    #[serde(skip)]
    pub pools: (ClassedSamples, ClassedSamples),
}

/// The Table II and IV sample drives' roads, simulated with an ideal gyro (the true rate).
pub fn simulated_samples() -> Result<Vec<(String, ClassedSamples)>> {
    let mut out = Vec::new();
    for s in crate::sim::samples::SAMPLE_LOGS.iter().filter(|s| s.kind == crate::sim::SimKind::Drive) {
        let cfg = crate::sim::drive::DriveConfig {
            scenario: s.scenario.unwrap_or("city").parse()?,
            minutes: s.minutes.unwrap_or(20.0),
            seed: s.seed,
        };
        let log = crate::sim::drive::simulate_drive_with(&cfg, &crate::sim::GyroSpec::ideal());
        out.push((s.name.to_string(), road_samples(&log, 0.0)?));
    }
    Ok(out)
}

/// Compares recorded drives (each with a speed column; ones without are skipped and named)
/// with the simulated sample drives. None with a speed column is an error.
pub fn compare(recorded: &[(String, &DriveLog)]) -> Result<RoadComparison> {
    let (mut rec, mut skipped) = (Vec::new(), Vec::new());
    for (name, log) in recorded {
        if log.has(Column::SpeedMps) {
            rec.push((name.clone(), road_samples(log, 0.0).map_err(|e| e.within(name))?));
        } else {
            skipped.push(name.clone());
        }
    }
    if rec.is_empty() {
        return Err(Error::data(format!(
            "road statistics: no recorded drive has a speed column ({} given), so none shows when it moves",
            recorded.len()
        )));
    }
    let sim = simulated_samples()?;
    let pool = |v: &[(String, ClassedSamples)]| {
        let mut p = ClassedSamples::default();
        v.iter().for_each(|(_, s)| p.extend(s));
        p
    };
    let (rp, sp) = (pool(&rec), pool(&sim));
    let rows = |v: &[(String, ClassedSamples)]| v.iter().map(|(n, s)| (n.clone(), s.all.summary())).collect();
    let classes = RoadClass::ALL
        .iter()
        .enumerate()
        .map(|(i, &class)| ClassComparison {
            class,
            recorded: rp.class[i].summary(),
            simulated: sp.class[i].summary(),
            distance: RoadDistance::between(&rp.class[i], &sp.class[i]),
        })
        .collect();
    Ok(RoadComparison {
        recorded: rows(&rec),
        skipped,
        simulated: rows(&sim),
        recorded_pool: rp.all.summary(),
        simulated_pool: sp.all.summary(),
        distance: RoadDistance::between(&rp.all, &sp.all),
        classes,
        pools: (rp, sp),
    })
}

/// The empirical distribution function of `values` as at most `max_points` steps
/// `(value, fraction at or below)`, for plotting.
pub fn cdf_points(values: &[f64], max_points: usize) -> Vec<(f64, f64)> {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let step = n.div_ceil(max_points.max(1)).max(1);
    let mut out: Vec<(f64, f64)> = (0..n).step_by(step).map(|i| (v[i], (i + 1) as f64 / n as f64)).collect();
    if n > 0 && out.last().is_some_and(|p| p.1 < 1.0) {
        out.push((v[n - 1], 1.0));
    }
    out
}

const SUMMARY_HEAD: &str = "| moving (min) | abs rate p50 | p75 | p90 (deg/s) | below theta_w | straight run mean | p90 (s) | 30 s rate p50 | p90 (deg/s) | curve p50 (s) | curve p50 (deg) | radius p50 (m) |";

fn summary_cells(s: &RoadSummary) -> String {
    format!(
        "| {:.1} | {:.2} | {:.2} | {:.2} | {:.2} | {:.1} | {:.0} | {:.3} | {:.3} | {:.0} | {:.0} | {:.0} |",
        s.moving_min,
        s.rate_p50_dps,
        s.rate_p75_dps,
        s.rate_p90_dps,
        s.below_theta_w,
        s.straight_run_mean_s,
        s.straight_run_p90_s,
        s.slow_rate_p50_dps,
        s.slow_rate_p90_dps,
        s.curve_run_p50_s,
        s.curve_deg_p50,
        s.curve_radius_p50_m
    )
}

impl RoadComparison {
    pub fn to_markdown(&self) -> String {
        let mut out = format!("| drive {SUMMARY_HEAD}\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        let row = |name: &str, s: &RoadSummary| format!("| {name} {}\n", summary_cells(s));
        for (n, s) in &self.recorded {
            out += &row(&format!("recorded: {n}"), s);
        }
        out += &row("**recorded, pooled**", &self.recorded_pool);
        if !self.skipped.is_empty() {
            out += &format!("| (left out, no speed column: {}) |\n", self.skipped.join(", "));
        }
        for (n, s) in &self.simulated {
            out += &row(&format!("simulated: {n}"), s);
        }
        out += &row("**simulated, pooled**", &self.simulated_pool);
        out += &format!("\nBy road class (the mean speed of the minute around each block: urban under 14 m/s, highway over 25, rural between):\n\n| class, source {SUMMARY_HEAD}\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for c in &self.classes {
            out += &row(&format!("{}, recorded", c.class.name()), &c.recorded);
            out += &row(&format!("{}, simulated", c.class.name()), &c.simulated);
        }
        out +=
            "\nTwo-sample Kolmogorov-Smirnov distance, recorded against simulated pool (0 = same distribution, 1 = disjoint):\n\n| pool |";
        for (name, _) in STATISTICS {
            out += &format!(" {name} |");
        }
        out += "\n|---|---:|---:|---:|---:|---:|---:|\n";
        let dist_row = |name: &str, d: &RoadDistance| {
            let cells: String = d.values().iter().map(|v| format!(" {v:.3} |")).collect();
            format!("| {name} |{cells}\n")
        };
        out += &dist_row("all moving", &self.distance);
        for c in &self.classes {
            out += &dist_row(c.class.name(), &c.distance);
        }
        out + &self.spectrum_markdown() + &self.manoeuvre_markdown() + &self.sway_markdown()
    }

    /// Fast sway per class, recorded / simulated quartiles and the distance.
    fn sway_markdown(&self) -> String {
        let mut out = String::from("\nFast sway (the residual spread of 10 s windows of moving blocks, all under 3 deg/s, about their least-squares line: the weaving and quick steering of straight driving), recorded / simulated, deg/s:\n\n| pool | windows | p25 | p50 | p75 | KS |\n|---|---:|---:|---:|---:|---:|\n");
        let mut row = |name: &str, n: (usize, usize), a: &RoadSummary, b: &RoadSummary, d: &RoadDistance| {
            out += &format!(
                "| {name} | {} / {} | {:.3} / {:.3} | {:.3} / {:.3} | {:.3} / {:.3} | {:.3} |\n",
                n.0, n.1, a.sway_p25_dps, b.sway_p25_dps, a.sway_p50_dps, b.sway_p50_dps, a.sway_p75_dps, b.sway_p75_dps, d.sway
            );
        };
        let (rp, sp) = &self.pools;
        row("all moving", (rp.all.sway_dps.len(), sp.all.sway_dps.len()), &self.recorded_pool, &self.simulated_pool, &self.distance);
        for (i, c) in self.classes.iter().enumerate() {
            row(c.class.name(), (rp.class[i].sway_dps.len(), sp.class[i].sway_dps.len()), &c.recorded, &c.simulated, &c.distance);
        }
        out
    }

    /// S-manoeuvres and loops per class, recorded / simulated, with the distances.
    fn manoeuvre_markdown(&self) -> String {
        let mut out = String::from("\nS-manoeuvres (lane-change-like: an excursion of 1.5-15 deg crossing theta_w both ways and coming back within a quarter of it, in 3-12 s) and loops (curve runs over 180 deg: roundabouts, ramps), recorded / simulated:\n\n| pool | S per moving min | S length p50 (s) | S excursion p50 (deg) | KS length | KS excursion | loops per moving hour |\n|---|---:|---:|---:|---:|---:|---:|\n");
        let mut row = |name: &str, r: &RoadSummary, s: &RoadSummary, d: &RoadDistance| {
            out += &format!(
                "| {name} | {:.2} / {:.2} | {:.0} / {:.0} | {:.1} / {:.1} | {:.3} | {:.3} | {:.1} / {:.1} |\n",
                r.s_per_min,
                s.s_per_min,
                r.s_length_p50_s,
                s.s_length_p50_s,
                r.s_peak_p50_deg,
                s.s_peak_p50_deg,
                d.s_length,
                d.s_peak,
                r.loops_per_hour,
                s.loops_per_hour
            );
        };
        row("all moving", &self.recorded_pool, &self.simulated_pool, &self.distance);
        for c in &self.classes {
            row(c.class.name(), &c.recorded, &c.simulated, &c.distance);
        }
        out
    }

    /// The yaw-rate spectrum per class: RMS per band, recorded and simulated, and the
    /// distance of the windows' band powers.
    fn spectrum_markdown(&self) -> String {
        let mut out = String::from("
Yaw-rate spectrum by period band (64 s windows of moving 1 Hz blocks, Hann, mean removed): RMS over the windows in deg/s, recorded / simulated, and the Kolmogorov-Smirnov distance of the windows' band powers:

| pool | windows rec. / sim. |");
        for b in BAND_NAMES {
            out += &format!(" {b} RMS | {b} KS |");
        }
        out += "
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
";
        let row = |name: &str, r: &RoadSamples, s: &RoadSamples, d: &RoadDistance| {
            let (rs, ss) = (r.summary(), s.summary());
            let cells: String =
                (0..5).map(|k| format!(" {:.3} / {:.3} | {:.3} |", rs.band_rms_dps[k], ss.band_rms_dps[k], d.spectrum[k])).collect();
            format!("| {name} | {} / {} |{cells}\n", r.band_power_dps2[0].len(), s.band_power_dps2[0].len())
        };
        let (rp, sp) = &self.pools;
        out += &row("all moving", &rp.all, &sp.all, &self.distance);
        for (i, c) in self.classes.iter().enumerate() {
            out += &row(c.class.name(), &rp.class[i], &sp.class[i], &c.distance);
        }
        out
    }
}

/// The two-sample Kolmogorov-Smirnov statistic: the largest gap between the two empirical
/// distribution functions (0 = same, 1 = disjoint).
pub fn ks_distance(a: &[f64], b: &[f64]) -> f64 {
    if a.is_empty() || b.is_empty() {
        return f64::NAN;
    }
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (mut i, mut j, mut d) = (0usize, 0usize, 0.0f64);
    while i < a.len() && j < b.len() {
        let x = a[i].min(b[j]);
        while i < a.len() && a[i] <= x {
            i += 1;
        }
        while j < b.len() && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / a.len() as f64 - j as f64 / b.len() as f64).abs());
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ks_distance_hand_worked() {
        assert_eq!(ks_distance(&[1.0, 2.0, 3.0], &[1.0, 2.0, 3.0]), 0.0);
        assert_eq!(ks_distance(&[1.0, 2.0], &[3.0, 4.0]), 1.0);
        // F_a jumps to 1/2 at 1 and to 1 at 3; F_b to 1/2 at 2 and to 1 at 4: largest gap 1/2
        assert_eq!(ks_distance(&[1.0, 3.0], &[2.0, 4.0]), 0.5);
        // ties move both functions together
        assert_eq!(ks_distance(&[1.0, 1.0, 2.0, 2.0], &[1.0, 2.0]), 0.0);
    }

    #[test]
    fn cdf_points_hand_worked() {
        assert_eq!(cdf_points(&[3.0, 1.0, 2.0, f64::NAN], 10), vec![(1.0, 1.0 / 3.0), (2.0, 2.0 / 3.0), (3.0, 1.0)]);
        // 10 values in at most 4 points: every third, then the last
        let v: Vec<f64> = (1..=10).map(f64::from).collect();
        assert_eq!(cdf_points(&v, 4), vec![(1.0, 0.1), (4.0, 0.4), (7.0, 0.7), (10.0, 1.0)]);
        assert!(cdf_points(&[], 4).is_empty());
    }

    #[test]
    fn distance_of_a_pool_with_itself_is_zero() {
        let s = RoadSamples { abs_rate_dps: vec![0.1, 0.2], straight_runs_s: vec![3.0], curve_deg: vec![90.0], ..Default::default() };
        let d = RoadDistance::between(&s, &s);
        assert_eq!(d.values()[..2], [0.0, 0.0]);
        assert!(d.slow_rate.is_nan(), "no samples: no distance");
    }

    #[test]
    fn drives_without_speed_are_named_and_none_with_speed_is_an_error() {
        let cfg = crate::sim::drive::DriveConfig { scenario: "city".parse().unwrap(), minutes: 3.0, seed: 5 };
        let with = crate::sim::drive::simulate_drive_with(&cfg, &crate::sim::GyroSpec::ideal());
        let mut without = with.clone();
        without.drop_column(Column::SpeedMps);
        let c = compare(&[("mine".into(), &with), ("no-speed".into(), &without)]).unwrap();
        assert_eq!(c.recorded.iter().map(|r| r.0.as_str()).collect::<Vec<_>>(), ["mine"]);
        assert_eq!(c.skipped, ["no-speed"]);
        assert!(c.to_markdown().contains("left out, no speed column: no-speed"));
        let e = compare(&[("no-speed".into(), &without)]).unwrap_err().to_string();
        assert!(e.contains("no recorded drive has a speed column (1 given)"), "{e}");
    }
}
