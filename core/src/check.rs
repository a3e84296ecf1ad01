//! `gyrodrift check`: what a log looks like before any method runs on it. Sample rate and
//! jitter, gaps, the unit the numbers seem to be in (time in milliseconds, heading in
//! radians, gyro in rad/s or clockwise, found by comparing the integrated gyro with the
//! reference heading's change), the static bias, outliers. Each finding says how to fix it.

use crate::log::{Column, DriveLog};
use crate::metrics::{value_at, Reference};
use crate::preprocess;
use serde::{Deserialize, Serialize};

/// How much a finding matters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Severity {
    /// The results would be wrong: fix before using them.
    Error,
    /// The results may mislead.
    Warning,
    Info,
}

impl Severity {
    pub fn name(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        }
    }
}

/// One thing the check found, and what to do about it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Finding {
    pub severity: Severity,
    /// A stable name: time_unit, gap, heading_unit, gyro_unit, gyro_sign, gyro_scale, bias,
    /// lead_in, no_stops, no_reference, outlier.
    pub code: String,
    pub message: String,
    /// The recipe field or setting that fixes it.
    pub fix: Option<String>,
}

/// What the check measured, and its findings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CheckReport {
    pub rows: usize,
    pub duration_min: f64,
    /// Median time step of the gyro rows, s, and its 95th percentile over the median.
    pub median_step_s: f64,
    pub jitter_p95: f64,
    /// Gaps longer than the gap threshold: (start time, length), s.
    pub gaps_s: Vec<(f64, f64)>,
    /// Static bias over the lead-in, deg/s (as the methods would take it).
    pub eps0_dps: Option<f64>,
    /// Integrated gyro over reference heading change on the largest turns (1 = as expected).
    pub gyro_over_reference: Option<f64>,
    pub findings: Vec<Finding>,
}

fn finding(severity: Severity, code: &str, message: String, fix: Option<&str>) -> Finding {
    Finding { severity, code: code.into(), message, fix: fix.map(str::to_string) }
}

/// Checks a parsed log.
pub fn check(log: &DriveLog) -> CheckReport {
    let t = log.time_s();
    let mut steps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    steps.sort_by(f64::total_cmp);
    let pick = |q: f64| steps.get(((steps.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(f64::NAN);
    let (median, p95) = (pick(0.5), pick(0.95));
    let mut r = CheckReport {
        rows: log.len(),
        duration_min: log.duration_min(),
        median_step_s: median,
        jitter_p95: p95 / median,
        gaps_s: Vec::new(),
        eps0_dps: None,
        gyro_over_reference: None,
        findings: Vec::new(),
    };
    time_unit(&mut r, t);
    gaps(&mut r, log);
    let standing_s = lead_in(&mut r, log);
    let limit_dps = units_and_sign(&mut r, log, standing_s);
    if log.kind() == crate::log::LogKind::Drive && !log.has_reference() {
        let message = "no reference heading: the methods run, nothing is scored, and the gyro's units and sign go unchecked";
        r.findings.push(finding(Severity::Info, "no_reference", message.into(), Some("add a ref_heading_deg column (the GPS course)")));
    }
    // (A lead-in the speed shows running into the drive is reported as that, with its fix.)
    if let Some(b) = r.eps0_dps.filter(|b| b.abs() > limit_dps && standing_s.is_none()) {
        let message = format!("static bias {b:.2} deg/s over the lead-in: the vehicle may not stand still then");
        r.findings.push(finding(
            Severity::Warning,
            "bias",
            message,
            Some("bias_s = 0 when the log starts moving (# bias_s: 0, or --set bias_s=0)"),
        ));
    }
    r
}

/// The gaps in time (`log::gaps`), the first five as findings.
fn gaps(r: &mut CheckReport, log: &DriveLog) {
    r.gaps_s = crate::log::gaps::find_gaps(log).iter().map(|g| (g.at_s, g.length_s)).collect();
    for &(at, len) in r.gaps_s.iter().take(5) {
        let message = format!("a gap of {len:.1} s at t = {at:.1} s: no method may integrate across it, so the log is scored in parts");
        r.findings.push(finding(
            Severity::Warning,
            "gap",
            message,
            Some("split into parts there (--gaps split, the default; --gaps error refuses the log)"),
        ));
    }
}

/// The static bias, outliers, and the gyro's units and sign against the reference (or the
/// reference's, in radians). Returns the static bias over which the lead-in is taken to be
/// moving (any, where the reference says so).
fn units_and_sign(r: &mut CheckReport, log: &DriveLog, standing_s: Option<f64>) -> f64 {
    let t = log.time_s();
    let mut limit_dps = 5.0;
    if let Some(g) = log.column(Column::GyroDps) {
        let bias_s = log.bias_s(None);
        r.eps0_dps = preprocess::static_bias_dps(t, g, bias_s).ok();
        outliers(r, g);
        // Units and sign are judged with the bias of the standing, not of a lead-in that
        // runs into the drive (which the lead_in finding reports): a turn inside it would
        // read as a scale error.
        // Without a lead-in (0 s) the turn-on bias is unmeasured: None, estimated below.
        let eps0 = match standing_s {
            Some(s) => (s > 0.0).then(|| preprocess::static_bias_dps(t, g, s).unwrap_or(0.0)),
            None => (bias_s > 0.0).then(|| r.eps0_dps.unwrap_or(0.0)),
        };
        let near_one = |x: f64| (x.abs() - 1.0).abs() < 0.25;
        let k = gyro_over_reference(log, eps0, false, true);
        // A lead-in nothing says stands (no speed, no wheels) may be a turn: if its bias
        // alone puts the gyro out with the reference and the straight road's rate does not,
        // the lead-in is wrong (the bias warning below), not the units.
        if standing_s.is_none()
            && eps0.is_some()
            && k.is_some_and(near_one)
            && !gyro_over_reference(log, eps0, false, false).is_some_and(near_one)
        {
            limit_dps = 0.0;
        }
        r.gyro_over_reference = k;
        // A reference that never leaves +-pi may be radians: see whether the gyro agrees.
        let within_pi =
            log.column(Column::RefHeadingDeg).is_some_and(|h| h.iter().all(|v| v.is_nan() || v.abs() <= std::f64::consts::PI + 1e-3));
        let k_rad = if within_pi { gyro_over_reference(log, eps0, true, true) } else { None };
        match (k, k_rad) {
            (k, Some(kr)) if near_one(kr) && !k.is_some_and(near_one) => {
                let cw = if kr < 0.0 { ", positive = \"cw\"" } else { "" };
                let message = format!(
                    "ref_heading_deg stays within +-pi and, read as radians, agrees with the gyro ({kr:.3}): the heading is in radians"
                );
                let fix = format!("heading.unit = \"rad\"{cw} in the recipe");
                r.findings.push(finding(Severity::Error, "heading_unit", message, Some(&fix)));
            }
            (Some(k), _) => units_from_ratio(r, k),
            _ => {}
        }
    }
    limit_dps
}

/// A stationary lead-in the speed (or the wheels) says is not: the first 1 s block they
/// show moving in starts within it (`still::blocks`, as the pipeline ends its lead-in),
/// and the standing before it (s, returned) is the lead-in to declare instead.
fn lead_in(r: &mut CheckReport, log: &DriveLog) -> Option<f64> {
    let bias_s = log.bias_s(None);
    let blocks = crate::still::blocks(log, bias_s, &Default::default()).ok()?;
    if blocks.source == crate::still::StillSource::None {
        let message =
            "no speed, wheel travel or stationary lead-in (3 s at 5 Hz or more): no stops for ZARU and the pipeline (which learns the bias from the road alone)";
        r.findings.push(finding(Severity::Info, "no_stops", message.into(), Some("a speed column, or # bias_s: N for a standing start")));
    }
    let m = (blocks.first_moving_s? - log.time_s().first()?).floor();
    let k = (m - 1.0).max(0.0);
    let by = if blocks.source == crate::still::StillSource::Odometry { "wheel travel" } else { "speed" };
    (m < bias_s).then(|| {
        let message = format!("the stationary lead-in (bias_s = {bias_s} s) is not: the {by} shows the vehicle moving {m} s in; its static bias is taken over driving");
        let fix = format!("bias_s = {k}, the standing before it (# bias_s: {k} in the log, or --set bias_s={k})");
        r.findings.push(finding(Severity::Warning, "lead_in", message, Some(&fix)));
        k
    })
}

/// Time in milliseconds: a median step of 2 s or more on a log spanning days of "seconds".
fn time_unit(r: &mut CheckReport, t: &[f64]) {
    if r.median_step_s >= 2.0 && t.len() > 100 {
        let message = format!(
            "time_s steps by {:.0} (median) over {} rows: milliseconds, not seconds? ({:.0} min as seconds)",
            r.median_step_s, r.rows, r.duration_min
        );
        r.findings.push(finding(
            Severity::Error,
            "time_unit",
            message,
            Some("time.unit = \"ms\" in the recipe (or divide time_s by 1000)"),
        ));
    }
}

/// Gyro cells far beyond a road vehicle's yaw rate.
fn outliers(r: &mut CheckReport, g: &[f64]) {
    let n = g.iter().filter(|v| v.abs() > 300.0).count();
    if n > 0 {
        let message = format!("{n} gyro value(s) above 300 deg/s: counts or a wrong unit, or spikes");
        r.findings.push(finding(Severity::Warning, "outlier", message, Some("check yaw_rate.unit and scale in the recipe")));
    }
}

/// One window between two reference samples: the integrated gyro's and the reference's
/// heading change (deg), its length and its middle (s).
struct Window {
    gyro_deg: f64,
    ref_deg: f64,
    dt_s: f64,
    mid_s: f64,
}

/// The windows the gyro is compared with the reference on, the gyro less `eps0` (deg/s).
/// With `steady_ends`, 10-60 s windows that end where the reference heading is steady
/// (within 1.5 deg over +-2 s), so a window holds whole turns: a lag between the gyro and
/// the reference (1 s means stamped at their end, a late GPS course) cuts none. Without
/// (a drive in circles is never steady), 10-30 s windows between any reference samples.
/// None without a reference or blocks.
fn windows(log: &DriveLog, eps0: Option<f64>, in_radians: bool, steady_ends: bool) -> Option<Vec<Window>> {
    let mut reference = Reference::from_log(log).ok()?;
    if in_radians {
        // Radians wrap at +-pi, which the degree unwrap leaves alone: convert, then unwrap.
        let deg: Vec<f64> = reference.heading_deg.iter().map(|h| h.to_degrees()).collect();
        reference.heading_deg = crate::metrics::unwrap_deg(&deg);
    }
    let g = log.column(Column::GyroDps)?;
    let blocks = preprocess::block_average_1hz(log.time_s(), g);
    let (rt, rh) = (&reference.time_s, &reference.heading_deg);
    if blocks.len() < 20 || rt.len() < 10 {
        return None;
    }
    // The paper's "without HDR" heading on the blocks.
    let mut raw = crate::hdr::RawIntegrator::new(eps0.unwrap_or(0.0));
    let psi: Vec<f64> = blocks.time_s.iter().zip(&blocks.rate_dps).map(|(&t, &w)| raw.update(t, w)).collect();
    let (first, last) = (rt[0], rt[rt.len() - 1]);
    let steady = |t: f64| !steady_ends || (value_at(rt, rh, (t + 2.0).min(last)) - value_at(rt, rh, (t - 2.0).max(first))).abs() < 1.5;
    let max_s = if steady_ends { 60.0 } else { 30.0 };
    let mut out = Vec::new();
    let mut a: Option<usize> = None;
    for b in 0..rt.len() {
        if !steady(rt[b]) {
            continue;
        }
        if let Some(i) = a {
            let dt = rt[b] - rt[i];
            if dt < 10.0 {
                continue;
            }
            let gyro_deg = value_at(&blocks.time_s, &psi, rt[b]) - value_at(&blocks.time_s, &psi, rt[i]);
            let ref_deg = rh[b] - rh[i];
            if dt <= max_s && gyro_deg.is_finite() && ref_deg.is_finite() {
                out.push(Window { gyro_deg, ref_deg, dt_s: dt, mid_s: 0.5 * (rt[b] + rt[i]) });
            }
        }
        a = Some(b);
    }
    Some(out)
}

/// The ratio of the integrated gyro's heading change to the reference's over the largest
/// turns (median), or None without turns. With `road`, each turn first loses the bias the
/// windows the reference says are straight (2 deg) show within 300 s of it (their median
/// rate, if 3 or more: a turn-on bias without a lead-in, a warm-up after one); without,
/// the gyro less the lead-in's bias alone.
fn turn_ratio(windows: &[Window], road: bool) -> Option<f64> {
    let big = windows.iter().map(|w| w.ref_deg.abs()).fold(0.0, f64::max);
    // Only clear turns (20 deg or more in a window) say anything about scale and sign.
    let min_turn = (0.3 * big).max(20.0);
    // (Loops, not collects: each collect is code of its own in the size-capped wasm module.)
    let (mut ratios, mut near) = (Vec::new(), Vec::new());
    for turn in windows.iter().filter(|w| w.ref_deg.abs() >= min_turn) {
        near.clear();
        for w in windows {
            if road && w.ref_deg.abs() < 2.0 && (w.mid_s - turn.mid_s).abs() <= 300.0 {
                near.push(w.gyro_deg / w.dt_s);
            }
        }
        let bias = if near.len() >= 3 { crate::metrics::quantile_mut(&mut near, 0.5) } else { 0.0 };
        ratios.push((turn.gyro_deg - bias * turn.dt_s) / turn.ref_deg);
    }
    (ratios.len() >= 3).then(|| crate::metrics::quantile_mut(&mut ratios, 0.5))
}

/// [`turn_ratio`] on the windows with steady ends, else on any (a drive in circles).
fn gyro_over_reference(log: &DriveLog, eps0: Option<f64>, in_radians: bool, road: bool) -> Option<f64> {
    [true, false].into_iter().find_map(|steady| turn_ratio(&windows(log, eps0, in_radians, steady)?, road))
}

/// What a gyro-over-reference ratio says about units and sign.
fn units_from_ratio(r: &mut CheckReport, k: f64) {
    let deg = 180.0 / std::f64::consts::PI;
    let near = |x: f64, want: f64| (x / want - 1.0).abs() < 0.25;
    let (code, message, fix) = if near(k, 1.0) {
        if (k - 1.0).abs() > 0.03 {
            let m = format!("the gyro's heading change is {k:.3} times the reference's: a scale error of {:+.1} %", (k - 1.0) * 100.0);
            r.findings.push(finding(Severity::Info, "gyro_scale", m, Some("yaw_rate.scale in the recipe, or calibrate")));
        }
        return;
    } else if near(k, -1.0) {
        (
            "gyro_sign",
            "the gyro turns the other way from the reference: clockwise-positive, not counter-clockwise".to_string(),
            "yaw_rate.positive = \"cw\" in the recipe (or negate gyro_dps)",
        )
    } else if near(k, 1.0 / deg) {
        (
            "gyro_unit",
            format!("the gyro's heading change is {k:.4} of the reference's (1/57.3): the gyro is in rad/s"),
            "yaw_rate.unit = \"rad/s\" in the recipe",
        )
    } else if near(k, -1.0 / deg) {
        (
            "gyro_unit",
            format!("the gyro's heading change is {k:.4} of the reference's: rad/s and clockwise"),
            "yaw_rate.unit = \"rad/s\", positive = \"cw\"",
        )
    } else if near(k, deg) {
        (
            "heading_unit",
            format!("the reference changes {:.4} of the gyro's heading (1/57.3): ref_heading_deg is in radians", 1.0 / k),
            "heading.unit = \"rad\" in the recipe",
        )
    } else if near(k, -deg) {
        (
            "heading_unit",
            "ref_heading_deg is in radians and turns the other way (clockwise)".to_string(),
            "heading.unit = \"rad\", positive = \"cw\"",
        )
    } else {
        (
            "gyro_scale",
            format!("the gyro's heading change is {k:.3} times the reference's: a unit or scale mistake"),
            "yaw_rate.unit and scale in the recipe",
        )
    };
    r.findings.push(finding(Severity::Error, code, message, Some(fix)));
}

impl CheckReport {
    /// The report as text, a finding a line.
    pub fn to_text(&self) -> String {
        let mut s = format!(
            "{} rows, {:.1} min, median step {:.4} s (95th percentile {:.2}x), {} gap(s)",
            self.rows,
            self.duration_min,
            self.median_step_s,
            self.jitter_p95,
            self.gaps_s.len()
        );
        if let Some(b) = self.eps0_dps {
            s.push_str(&format!(", static bias {b:.4} deg/s"));
        }
        if let Some(k) = self.gyro_over_reference {
            s.push_str(&format!(", gyro / reference heading change {k:.3}"));
        }
        s.push('\n');
        if self.findings.is_empty() {
            s.push_str("no findings\n");
        }
        for f in &self.findings {
            s.push_str(&format!("{} [{}]: {}", f.severity.name(), f.code, f.message));
            if let Some(fix) = &f.fix {
                s.push_str(&format!("; fix: {fix}"));
            }
            s.push('\n');
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::parse_log;

    fn city() -> DriveLog {
        let p = concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/city-1.csv");
        parse_log(std::fs::File::open(p).unwrap()).unwrap()
    }

    fn codes(log: &DriveLog) -> Vec<String> {
        check(log).findings.into_iter().filter(|f| f.severity != Severity::Info).map(|f| f.code).collect()
    }

    /// The log without one of its columns.
    fn without(log: &DriveLog, c: Column) -> DriveLog {
        let kept: Vec<(Column, Vec<f64>)> = log.columns().into_iter().filter(|(k, _)| *k != c).map(|(k, v)| (k, v.to_vec())).collect();
        DriveLog::from_columns(log.meta.clone(), vec![0; log.len()], kept).unwrap()
    }

    fn scaled(log: &DriveLog, c: Column, k: f64) -> DriveLog {
        let mut l = log.clone();
        l.column_mut(c).unwrap().iter_mut().for_each(|v| *v *= k);
        l
    }

    #[test]
    fn the_city_drive_as_shipped_is_clean() {
        let r = check(&city());
        assert!(codes(&city()).is_empty(), "{}", r.to_text());
        assert!((r.median_step_s - 0.1).abs() < 1e-9);
        assert!((r.gyro_over_reference.unwrap() - 1.0).abs() < 0.05, "{:?}", r.gyro_over_reference);
    }

    /// A drive without a reference heading: information that nothing is scored and units
    /// and sign go unchecked; none for a drive with one, or for a static session.
    #[test]
    fn a_drive_without_a_reference_is_told_what_goes_unchecked() {
        let info = |log: &DriveLog| check(log).findings.into_iter().filter(|f| f.code == "no_reference").count();
        let log = city();
        assert_eq!(info(&log), 0);
        let noref = without(&log, Column::RefHeadingDeg);
        assert_eq!(info(&noref), 1);
        assert!(codes(&noref).is_empty(), "{}", check(&noref).to_text());
        let mut blank = log.clone();
        blank.column_mut(Column::RefHeadingDeg).unwrap().iter_mut().for_each(|v| *v = f64::NAN);
        assert_eq!(info(&blank), 1);
        assert_eq!(info(&without(&noref, Column::SpeedMps)), 0, "a gyro alone is a static session");
    }

    #[test]
    fn unit_sign_and_gap_mistakes_are_found_with_their_fix() {
        let log = city();
        let rad = 1.0 / (180.0 / std::f64::consts::PI);
        let mut radians = scaled(&log, Column::RefHeadingDeg, rad);
        // Radians wrap at +-pi.
        radians
            .column_mut(Column::RefHeadingDeg)
            .unwrap()
            .iter_mut()
            .for_each(|v| *v = (*v + std::f64::consts::PI).rem_euclid(2.0 * std::f64::consts::PI) - std::f64::consts::PI);
        let cases = [
            ("time_unit", scaled(&log, Column::TimeS, 1000.0)),
            ("heading_unit", radians),
            ("gyro_unit", scaled(&log, Column::GyroDps, rad)),
            ("gyro_sign", scaled(&log, Column::GyroDps, -1.0)),
        ];
        for (want, l) in cases {
            let r = check(&l);
            let f = r.findings.iter().find(|f| f.code == want).unwrap_or_else(|| panic!("{want} not found: {}", r.to_text()));
            assert!(f.fix.is_some());
        }
        // A 60 s gap: rows between 300 and 360 s removed.
        let mut gap = log.clone();
        gap.retain_rows(|t| !(300.0..360.0).contains(&t));
        let r = check(&gap);
        assert_eq!(r.gaps_s.len(), 1, "{}", r.to_text());
        assert!((r.gaps_s[0].1 - 60.0).abs() < 0.2);
        assert!(codes(&gap).contains(&"gap".to_string()));
    }

    /// A declared lead-in (60 s) longer than the standing (20 s): found with the standing
    /// as its fix; units and sign are judged with the standing's bias, so the drive's first
    /// turns inside the lead-in are not read as a scale error.
    #[test]
    fn a_lead_in_longer_than_the_standing_is_found_with_the_standing_as_its_fix() {
        let mut log = city();
        log.meta.bias_s = Some(60.0);
        let r = check(&log);
        assert_eq!(codes(&log), ["lead_in"], "{}", r.to_text());
        let f = &r.findings.iter().find(|f| f.code == "lead_in").unwrap();
        assert!(f.fix.as_deref().unwrap().starts_with("bias_s = 19,"), "{}", r.to_text());
        assert!((r.gyro_over_reference.unwrap() - 1.0).abs() < 0.05, "{:?}", r.gyro_over_reference);
        // As shipped (20 s) or without a speed column, nothing to say.
        assert!(codes(&city()).is_empty());
        let no_speed = without(&log, Column::SpeedMps);
        assert!(!codes(&no_speed).contains(&"lead_in".to_string()));
        assert!(f.message.contains("the speed shows"), "{}", f.message);
        // The same drive with wheel travel instead of a speed: the wheels say it moved.
        let dt = 0.1;
        let speed = log.column(Column::SpeedMps).unwrap();
        let travel: Vec<f64> = speed
            .iter()
            .scan(0.0, |d, v| {
                *d += v * dt;
                Some(*d)
            })
            .collect();
        let mut cols: Vec<(Column, Vec<f64>)> = no_speed.columns().into_iter().map(|(c, v)| (c, v.to_vec())).collect();
        cols.push((Column::OdoLeftM, travel.clone()));
        cols.push((Column::OdoRightM, travel));
        let wheels = DriveLog::from_columns(log.meta.clone(), vec![0; log.len()], cols).unwrap();
        let r = check(&wheels);
        let f = r.findings.iter().find(|f| f.code == "lead_in").unwrap_or_else(|| panic!("{}", r.to_text()));
        assert!(f.message.contains("the wheel travel shows"), "{}", f.message);
        // Neither speed nor wheels: the gyro against the lead-in finds the stops; without a
        // lead-in nothing can, which the check says.
        let info = |l: &DriveLog| check(l).findings.iter().any(|f| f.code == "no_stops" && f.severity == Severity::Info);
        assert!(!info(&city()) && !info(&no_speed));
        let mut cut = no_speed.clone();
        cut.meta.bias_s = Some(0.0);
        assert!(info(&cut), "{}", check(&cut).to_text());
    }

    /// No speed, and a default lead-in whose gyro reads 4 deg/s more than the bias (a turn):
    /// the bias warning with its fix, not a scale error; a real 50 % scale error stays one.
    #[test]
    fn a_turning_lead_in_without_speed_is_not_a_scale_error() {
        let log = city();
        let mut turn = without(&log, Column::SpeedMps);
        let t0 = log.time_s()[0];
        let lead: Vec<bool> = log.time_s().iter().map(|&t| t - t0 < 20.0).collect();
        turn.column_mut(Column::GyroDps).unwrap().iter_mut().zip(&lead).for_each(|(w, &l)| *w += if l { 4.0 } else { 0.0 });
        let r = check(&turn);
        assert_eq!(codes(&turn), ["bias"], "{}", r.to_text());
        assert!((r.gyro_over_reference.unwrap() - 1.0).abs() < 0.05, "{}", r.to_text());
        assert!(r.findings[r.findings.len() - 1].fix.as_deref().unwrap().starts_with("bias_s = 0"));
        // Without the fallback the lead-in's bias reads as a unit or scale mistake.
        assert!(gyro_over_reference(&turn, r.eps0_dps, false, false).is_some_and(|k| (k - 1.0).abs() > 0.25));
        // A 50 % scale error with a standing lead-in: the road's rate does not excuse it.
        let mut wrong = turn.clone();
        wrong.column_mut(Column::GyroDps).unwrap().iter_mut().zip(&lead).for_each(|(w, &l)| *w = 1.5 * (*w - if l { 4.0 } else { 0.0 }));
        let r = check(&wrong);
        assert_eq!(codes(&wrong), ["gyro_scale"], "{}", r.to_text());
    }

    /// A gyro warming by 1 deg/s after its lead-in, logged at 1 Hz as 1 s means stamped at
    /// their end (a lag of half a second on the reference): the straight road near each turn
    /// takes the warm-up out, and windows between steady headings hold whole turns.
    #[test]
    fn a_warm_up_and_lagging_1_hz_means_are_not_a_scale_error() {
        let log = city();
        let (t, g) = (log.time_s(), log.column(Column::GyroDps).unwrap());
        let h = log.column(Column::RefHeadingDeg).unwrap();
        let t0 = t[0];
        let mut rows: Vec<[f64; 3]> = Vec::new();
        for k in (0..t.len() - 9).step_by(10) {
            let warm = |t: f64| if t - t0 > 20.0 { 1.0 - (-(t - t0 - 20.0) / 300.0).exp() } else { 0.0 };
            let mean = (k..k + 10).map(|i| g[i] + warm(t[i])).sum::<f64>() / 10.0;
            let href = (k..k + 10).rev().map(|i| h[i]).find(|v| !v.is_nan()).unwrap_or(f64::NAN);
            rows.push([t[k + 9], mean, href]);
        }
        let col = |j: usize| rows.iter().map(|r| r[j]).collect::<Vec<f64>>();
        let cols = vec![(Column::TimeS, col(0)), (Column::GyroDps, col(1)), (Column::RefHeadingDeg, col(2))];
        let one_hz = DriveLog::from_columns(log.meta.clone(), vec![0; rows.len()], cols).unwrap();
        let r = check(&one_hz);
        assert!((r.gyro_over_reference.unwrap() - 1.0).abs() < 0.03, "{}", r.to_text());
        assert!(codes(&one_hz).is_empty(), "{}", r.to_text());
        // With the lead-in's bias alone the warm-up reads as a scale error.
        let k = gyro_over_reference(&one_hz, r.eps0_dps, false, false).unwrap();
        assert!((k - 1.0).abs() > 0.1, "{k}");
    }

    /// A turn-on bias of 1.5 deg/s and no lead-in (the robustness battery's "bias -1.5 cut"):
    /// the straight windows give the bias, so the turns are not read as a 31 % scale error.
    #[test]
    fn a_large_bias_without_a_lead_in_is_not_a_scale_error() {
        let mut log = city();
        log.meta.bias_s = Some(0.0);
        // City 1's own bias (1.95 deg/s) out, -1.5 in.
        let eps0 = check(&city()).eps0_dps.unwrap();
        log.column_mut(Column::GyroDps).unwrap().iter_mut().for_each(|w| *w -= eps0 + 1.5);
        let r = check(&log);
        assert!(codes(&log).is_empty(), "{}", r.to_text());
        assert!((r.gyro_over_reference.unwrap() - 1.0).abs() < 0.05, "{:?}", r.gyro_over_reference);
    }
}
