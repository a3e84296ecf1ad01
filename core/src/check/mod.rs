//! `gyrodrift check`: what a log looks like before any method runs on it. Sample rate and
//! jitter, gaps, the unit the numbers seem to be in (time in milliseconds, heading in
//! radians, gyro in rad/s or clockwise, found by comparing the integrated gyro with the
//! reference heading's change), the static bias, outliers, and whether the bias moves
//! between standings (`drift.rs`). Each finding says how to fix it.

use crate::log::DriveLog;
use serde::{Deserialize, Serialize};
use units::units_and_sign;

pub mod drift;
mod speed;
#[cfg(test)]
mod tests;
mod units;
mod wheels;

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
    /// lead_in, no_stops, bias_drift, no_reference, outlier, reference_turn, speed_unit, wheel_units.
    pub code: String,
    pub message: String,
    /// The recipe field or setting that fixes it.
    pub fix: Option<String>,
    /// The value that fix sets, where it is one a front can fill in (time_unit: "ms", "us"
    /// or "ns", the recipe's `time.unit`; gyro_unit: "rad/s", "mrad/s" or "deg/h", its
    /// `yaw_rate.unit`).
    #[serde(default)]
    pub fix_value: Option<String>,
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
    /// Each standing of 7 s or more the speed or the wheels show: its start (s, the log's
    /// time) and the gyro's median rate there, deg/s: the bias as it moves (`drift.rs`).
    #[serde(default)]
    pub stop_bias_dps: Vec<(f64, f64)>,
    pub findings: Vec<Finding>,
}

fn finding(severity: Severity, code: &str, message: String, fix: Option<&str>) -> Finding {
    Finding { severity, code: code.into(), message, fix: fix.map(str::to_string), fix_value: None }
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
        stop_bias_dps: Vec::new(),
        findings: Vec::new(),
    };
    // Time in another unit: the other checks read it as that unit, so they say what they
    // would once it is fixed, not what a log 1000 times too long looks like.
    let in_seconds = time_unit(&mut r, t).map(|per_s| {
        let mut log = log.clone();
        if let Some(t) = log.column_mut(crate::log::Column::TimeS) {
            t.iter_mut().for_each(|v| *v /= per_s);
        }
        log
    });
    let log = in_seconds.as_ref().unwrap_or(log);
    gaps(&mut r, log);
    let blocks = crate::still::blocks(log, log.bias_s(None), &Default::default()).ok();
    let (standing_s, shown_by) = blocks.as_ref().map_or((None, None), |b| lead_in(&mut r, log, b));
    if let Some(b) = &blocks {
        drift::bias_drift(&mut r, b);
    }
    let limit_dps = units_and_sign(&mut r, log, standing_s);
    speed::speed_unit(&mut r, log);
    wheels::wheel_units(&mut r, log);
    if log.kind() == crate::log::LogKind::Drive && !log.has_reference() {
        let message = "no reference heading: the methods run, nothing is scored, and the gyro's units and sign go unchecked";
        r.findings.push(finding(Severity::Info, "no_reference", message.into(), Some("add a ref_heading_deg column (the GPS course)")));
    }
    // (A lead-in the speed shows running into the drive is reported as that, with its fix.)
    // Where the speed or the wheels show the standing, the bias is the gyro's and changes
    // after the lead-in (a part warming up); where nothing shows it, the lead-in may be a turn.
    if let Some(b) = r.eps0_dps.filter(|b| b.abs() > limit_dps && standing_s.is_none()) {
        let (message, fix) = match shown_by {
            Some(by) => (
                format!("static bias {b:.2} deg/s over the lead-in, where the {by} shows a standing: the gyro's bias changes after it (warming up?)"),
                "a longer standing, once the gyro has warmed up",
            ),
            None => (
                format!("static bias {b:.2} deg/s over the lead-in: the vehicle may not stand still then"),
                "bias_s = 0 when the log starts moving (# bias_s: 0, or --set bias_s=0)",
            ),
        };
        r.findings.push(finding(Severity::Warning, "bias", message, Some(fix)));
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

/// How far a lead-in's 1 s means may wander beyond its rows' white noise (standard
/// deviations, `still::Blocks::lead_in_wander`) and still pass for a standing: the recorded
/// and simulated standing lead-ins measured 0.1-1.2, lead-ins over driving 4.4-5.
const LEAD_IN_WANDER_MAX: f64 = 3.0;

/// Without speed or wheels, a declared (or the default) lead-in whose 1 s means wander far
/// more than the gyro's own noise predicts is driving, not standing: its static bias is
/// taken over driving, and the gyro's standings are judged against it.
fn lead_in_by_gyro(r: &mut CheckReport, bias_s: f64, wander: f64) {
    if wander > LEAD_IN_WANDER_MAX {
        let message = format!(
            "the stationary lead-in (bias_s = {bias_s} s) does not look like a standing: its 1 s means wander {wander:.1}x more than the gyro's own noise predicts (a standing's 0.1-1.2x), so its static bias is taken over driving"
        );
        r.findings.push(finding(
            Severity::Warning,
            "lead_in",
            message,
            Some("# bias_s: 0 when the log starts moving (or the standing's length in s)"),
        ));
    }
}

/// A stationary lead-in the speed (or the wheels) says is not: the first 1 s block they
/// show moving in starts within it (`still::blocks`, as the pipeline ends its lead-in),
/// and the standing before it (s, returned) is the lead-in to declare instead. Also
/// returned: what showed a lead-in standing throughout ("speed", "wheel travel"), if any.
fn lead_in(r: &mut CheckReport, log: &DriveLog, blocks: &crate::still::Blocks) -> (Option<f64>, Option<&'static str>) {
    let bias_s = log.bias_s(None);
    if blocks.source == crate::still::StillSource::None {
        let message =
            "no speed, wheel travel or stationary lead-in (3 s at 5 Hz or more), and no 10 s standing the gyro shows alone (at 5 Hz or more): no stops for ZARU and the pipeline (which learns the bias from the road alone)";
        r.findings.push(finding(Severity::Info, "no_stops", message.into(), Some("a speed column, or # bias_s: N for a standing start")));
    }
    if let Some(wander) = blocks.lead_in_wander {
        lead_in_by_gyro(r, bias_s, wander);
    }
    let by = if blocks.source == crate::still::StillSource::Odometry { "wheel travel" } else { "speed" };
    let Some(&t0) = log.time_s().first() else {
        return (None, None);
    };
    // Every lead-in block still by the speed or the wheels.
    let mut lead = blocks.time_s.iter().zip(&blocks.still).take_while(|(&t, _)| t - t0 <= bias_s).peekable();
    let shown = matches!(blocks.source, crate::still::StillSource::Speed | crate::still::StillSource::Odometry)
        && lead.peek().is_some()
        && lead.all(|(_, &s)| s);
    let Some(m) = blocks.first_moving_s.map(|t| (t - t0).floor()).filter(|&m| m < bias_s) else {
        return (None, shown.then_some(by));
    };
    let k = (m - 1.0).max(0.0);
    let message = format!("the stationary lead-in (bias_s = {bias_s} s) is not: the {by} shows the vehicle moving {m} s in; its static bias is taken over driving");
    let fix = format!("bias_s = {k}, the standing before it (# bias_s: {k} in the log, or --set bias_s={k})");
    r.findings.push(finding(Severity::Warning, "lead_in", message, Some(&fix)));
    (Some(k), None)
}

/// Time in milliseconds, microseconds or nanoseconds: a median step of 2 s or more on a log
/// spanning days of "seconds". The unit is the first that brings the step within a logger's
/// (2 s or less: 10 ms read as microseconds would be 0.01 ms); returned as units per second.
fn time_unit(r: &mut CheckReport, t: &[f64]) -> Option<f64> {
    if r.median_step_s < 2.0 || t.len() <= 100 {
        return None;
    }
    const UNITS: [(&str, &str, f64); 3] = [("ms", "milliseconds", 1e3), ("us", "microseconds", 1e6), ("ns", "nanoseconds", 1e9)];
    let (unit, name, per_s) = UNITS.into_iter().find(|u| r.median_step_s / u.2 <= 2.0).unwrap_or(UNITS[2]);
    let message = format!(
        "time_s steps by {:.0} (median) over {} rows: {name}, not seconds? ({:.0} min as seconds, {:.1} min in {name}; the other checks read it in {name})",
        r.median_step_s,
        r.rows,
        r.duration_min,
        r.duration_min / per_s
    );
    let fix = format!("time.unit = \"{unit}\" in the recipe (or divide time_s by {per_s:.0})");
    let mut f = finding(Severity::Error, "time_unit", message, Some(&fix));
    f.fix_value = Some(unit.into());
    r.findings.push(f);
    Some(per_s)
}

/// Gyro cells far beyond a road vehicle's yaw rate.
fn outliers(r: &mut CheckReport, g: &[f64]) {
    let n = g.iter().filter(|v| v.abs() > 300.0).count();
    if n > 0 {
        let message = format!("{n} gyro value(s) above 300 deg/s: counts or a wrong unit, or spikes");
        r.findings.push(finding(Severity::Warning, "outlier", message, Some("check yaw_rate.unit and scale in the recipe")));
    }
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
