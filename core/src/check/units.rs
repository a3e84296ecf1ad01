//! Units and sign: the integrated gyro against the reference heading's change on clear
//! turns says whether the gyro is in rad/s, mrad/s or deg/h or clockwise, or the heading in
//! radians, and the gyro's scale error.

use super::{finding, outliers, CheckReport, Severity};
use crate::line::LineSums;
use crate::log::{Column, DriveLog};
use crate::metrics::{value_at, Reference};
use crate::preprocess;

/// The static bias, outliers, and the gyro's units and sign against the reference (or the
/// reference's, in radians). Returns the static bias over which the lead-in is taken to be
/// moving (any, where the reference says so).
pub(super) fn units_and_sign(r: &mut CheckReport, log: &DriveLog, standing_s: Option<f64>) -> f64 {
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
        let gyro = gyro_heading(log, eps0);
        let ratio = |in_radians, road| gyro.as_ref().and_then(|gy| ratio_of(log, gy, in_radians, road));
        let (k, se) = ratio(false, true).unzip();
        // A lead-in nothing says stands (no speed, no wheels) may be a turn: if its bias
        // alone puts the gyro out with the reference and the straight road's rate does not,
        // the lead-in is wrong (the bias warning below), not the units.
        if standing_s.is_none() && eps0.is_some() && k.is_some_and(near_one) && !ratio(false, false).is_some_and(|(k, _)| near_one(k)) {
            limit_dps = 0.0;
        }
        r.gyro_over_reference = k;
        // A reference that never leaves +-pi may be radians: see whether the gyro agrees.
        let within_pi =
            log.column(Column::RefHeadingDeg).is_some_and(|h| h.iter().all(|v| v.is_nan() || v.abs() <= std::f64::consts::PI + 1e-3));
        let k_rad = if within_pi { ratio(true, true).map(|(k, _)| k) } else { None };
        match (k, k_rad) {
            (k, Some(kr)) if near_one(kr) && !k.is_some_and(near_one) => {
                let message = format!(
                    "ref_heading_deg stays within +-pi and, read as radians, agrees with the gyro ({kr:.3}): the heading is in radians"
                );
                r.findings.push(finding(Severity::Error, "heading_unit", message, Some("heading.unit = \"rad\" in the recipe")));
                // Turning the other way as well (a GPS course in radians): the sign's own finding.
                if kr < 0.0 {
                    opposite_ways(r);
                }
            }
            (Some(k), _) => units_from_ratio(r, k, se.unwrap_or(0.0)),
            _ => {}
        }
        // Unless the units or sign are off (an error above), or the reference in radians.
        if let (Some(gy), None | Some(true), None) = (&gyro, k.map(near_one), k_rad) {
            reference_turns(r, log, gy, k.map_or(1.0, f64::signum));
        }
    }
    limit_dps
}

/// Where the reference first resumes after a gap (5 s or more) a whole turn off the gyro's
/// heading change: a U-turn or a garage ramp while the GPS course was blank. Detail 6's
/// unwrap takes the nearer branch, so from there the reference, and every method's E_psi,
/// is a turn off. Judged unless the units are off (`sign`: the gyro's, +1 unmeasured).
fn reference_turns(r: &mut CheckReport, log: &DriveLog, (gt, psi): &(Vec<f64>, Vec<f64>), sign: f64) {
    let Ok(Reference { time_s: t, heading_deg: h }) = Reference::from_log(log) else { return };
    let at = |x: f64| sign * value_at(gt, psi, x);
    for k in 1..t.len() {
        if t[k] - t[k - 1] >= 5.0 && (at(t[k]) - at(t[k - 1]) - (h[k] - h[k - 1])).abs() > 270.0 {
            let message = format!(
                "the reference resumes a turn off the gyro after its gap at {:.0} s: from there every E_psi is a turn off",
                t[k - 1]
            );
            r.findings.push(finding(Severity::Warning, "reference_turn", message, Some("score the log up to that gap")));
            return;
        }
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

/// The gyro's heading less `eps0` (deg/s) on the 1 Hz blocks, the paper's "without HDR":
/// (block times, heading), or None without a gyro or with under 20 blocks. Computed once
/// for every window below.
pub(super) fn gyro_heading(log: &DriveLog, eps0: Option<f64>) -> Option<(Vec<f64>, Vec<f64>)> {
    let blocks = preprocess::block_average_1hz(log.time_s(), log.column(Column::GyroDps)?);
    if blocks.len() < 20 {
        return None;
    }
    let mut raw = crate::hdr::RawIntegrator::new(eps0.unwrap_or(0.0));
    let psi = blocks.time_s.iter().zip(&blocks.rate_dps).map(|(&t, &w)| raw.update(t, w)).collect();
    Some((blocks.time_s, psi))
}

/// The windows the gyro (its heading `gt`, `psi` from [`gyro_heading`]) is compared with
/// the reference on.
/// With `steady_ends`, 10-60 s windows that end where the reference heading is steady
/// (within 1.5 deg over +-2 s), so a window holds whole turns: a lag between the gyro and
/// the reference (1 s means stamped at their end, a late GPS course) cuts none. Without
/// (a drive in circles is never steady), 10-30 s windows between any reference samples.
/// None without a reference.
fn windows(log: &DriveLog, (gt, psi): &(Vec<f64>, Vec<f64>), in_radians: bool, steady_ends: bool) -> Option<Vec<Window>> {
    let mut reference = Reference::from_log(log).ok()?;
    if in_radians {
        // Radians wrap at +-pi, which the degree unwrap leaves alone: convert, then unwrap.
        let deg: Vec<f64> = reference.heading_deg.iter().map(|h| h.to_degrees()).collect();
        reference.heading_deg = crate::metrics::unwrap_deg(&deg);
    }
    let (rt, rh) = (&reference.time_s, &reference.heading_deg);
    if rt.len() < 10 {
        return None;
    }
    let (first, last) = (*rt.first()?, *rt.last()?);
    let steady = |t: f64| !steady_ends || (value_at(rt, rh, (t + 2.0).min(last)) - value_at(rt, rh, (t - 2.0).max(first))).abs() < 1.5;
    let max_s = if steady_ends { 60.0 } else { 30.0 };
    let mut out = Vec::new();
    // The window's start: time and reference heading.
    let mut start: Option<(f64, f64)> = None;
    for (&t, &h) in rt.iter().zip(rh) {
        if !steady(t) {
            continue;
        }
        if let Some((t0, h0)) = start {
            let dt = t - t0;
            if dt < 10.0 {
                continue;
            }
            let gyro_deg = value_at(gt, psi, t) - value_at(gt, psi, t0);
            let ref_deg = h - h0;
            if dt <= max_s && gyro_deg.is_finite() && ref_deg.is_finite() {
                out.push(Window { gyro_deg, ref_deg, dt_s: dt, mid_s: 0.5 * (t + t0) });
            }
        }
        start = Some((t, h));
    }
    Some(out)
}

/// The ratio of the integrated gyro's heading change to the reference's over the largest
/// turns (median) and its standard error (from the interquartile range; infinite under 3
/// turns), or None with fewer than `min_turns`. With `road`, each turn first loses the bias
/// the windows the reference says are straight (2 deg) show within 300 s of it, if 3 or
/// more (a turn-on bias without a lead-in, a warm-up after one): their rates' least-squares
/// line in time, taken at the turn's middle (held within their span), so a bias warming by
/// degrees per second over those minutes is taken where the turn is (their median, until
/// the fifty-first session, refused such drives as a scale mistake); without `road`, the
/// gyro less the lead-in's bias alone.
fn turn_ratio(windows: &[Window], road: bool, min_turns: usize) -> Option<(f64, f64)> {
    let big = windows.iter().map(|w| w.ref_deg.abs()).fold(0.0, f64::max);
    // Only clear turns (20 deg or more in a window) say anything about scale and sign.
    let min_turn = (0.3 * big).max(20.0);
    // (Loops, not collects: each collect is code of its own in the size-capped wasm module.)
    let mut ratios = Vec::new();
    for turn in windows.iter().filter(|w| w.ref_deg.abs() >= min_turn) {
        // The straight windows near the turn: their rates' line in time (t from the turn's
        // middle) and t's span.
        let (mut line, mut lo, mut hi) = (LineSums::default(), f64::INFINITY, f64::NEG_INFINITY);
        for w in windows {
            let t = w.mid_s - turn.mid_s;
            if road && w.ref_deg.abs() < 2.0 && t.abs() <= 300.0 {
                line.add(t, w.gyro_deg / w.dt_s);
                (lo, hi) = (lo.min(t), hi.max(t));
            }
        }
        let bias = if line.count() >= 3.0 {
            let ((slope, _, sxx), (mean_t, mean_r)) = (line.slope(), line.means());
            let slope = if sxx > 0.0 { slope } else { 0.0 };
            mean_r + slope * (0.0_f64.max(lo).min(hi) - mean_t)
        } else {
            0.0
        };
        ratios.push((turn.gyro_deg - bias * turn.dt_s) / turn.ref_deg);
    }
    let n = ratios.len();
    let mut q = |p: f64| crate::metrics::quantile_mut(&mut ratios, p);
    // The median's standard error: 1.2533 sigma / sqrt(n), sigma = IQR / 1.349.
    let se = if n >= 3 { 0.929 * (q(0.75) - q(0.25)) / (n as f64).sqrt() } else { f64::INFINITY };
    (n >= min_turns.max(1)).then(|| (q(0.5), se))
}

/// [`turn_ratio`] on the windows with steady ends if they hold a clear turn (each whole, so
/// one says units and sign; a scale error needs 3), else on any with 3 turns or more (a
/// drive in circles, never steady, whose 10-30 s windows cut turns: with a lag between the
/// gyro and the reference, 1 s means stamped at their end, they were the cause of 1 Hz
/// logs refused as a unit mistake), the gyro's heading `gyro` from [`gyro_heading`].
fn ratio_of(log: &DriveLog, gyro: &(Vec<f64>, Vec<f64>), in_radians: bool, road: bool) -> Option<(f64, f64)> {
    [(true, 1), (false, 3)].into_iter().find_map(|(steady, n)| turn_ratio(&windows(log, gyro, in_radians, steady)?, road, n))
}

/// The ratio and its standard error from the log alone (the tests' entry).
#[cfg(test)]
pub(super) fn gyro_over_reference(log: &DriveLog, eps0: Option<f64>, in_radians: bool, road: bool) -> Option<(f64, f64)> {
    ratio_of(log, &gyro_heading(log, eps0)?, in_radians, road)
}

/// The gyro and the reference turn opposite ways: one of them is clockwise-positive.
fn opposite_ways(r: &mut CheckReport) {
    let message = "the gyro and the reference turn opposite ways: one of them is clockwise-positive".to_string();
    let fix = "heading.positive or yaw_rate.positive = \"cw\" (a GPS course is cw)";
    r.findings.push(finding(Severity::Error, "gyro_sign", message, Some(fix)));
}

/// What a gyro-over-reference ratio (standard error `se`) says about units and sign.
fn units_from_ratio(r: &mut CheckReport, k: f64, se: f64) {
    let deg = 180.0 / std::f64::consts::PI;
    let near = |x: f64, want: f64| (x / want - 1.0).abs() < 0.25;
    if near(k, 1.0) {
        // A scale error only where the turns tell it apart from none (beyond 2 standard errors).
        if (k - 1.0).abs() > 0.03_f64.max(2.0 * se) {
            let (e, pm) = ((k - 1.0) * 100.0, 200.0 * se);
            let m = format!("the gyro's heading change is {k:.3} times the reference's: a scale error of {e:+.1} % (+-{pm:.1} %)");
            r.findings.push(finding(Severity::Info, "gyro_scale", m, Some("yaw_rate.scale in the recipe, or calibrate")));
        }
        return;
    }
    if near(k, -1.0) {
        return opposite_ways(r);
    }
    // The gyro in a rate unit the recipe reads (its values `k` times deg/s), either sense: a
    // clockwise one is also the sign's finding, so each has its own fix (the dashboard's
    // mapper fills in both).
    for (unit, times) in [("rad/s", 1.0 / deg), ("mrad/s", 1000.0 / deg), ("deg/h", 3600.0)] {
        if let Some(cw) = [false, true].into_iter().find(|&cw| near(k, if cw { -times } else { times })) {
            let message = format!("the gyro's heading change is {k:.4} times the reference's ({times:.4}): the gyro is in {unit}");
            let mut f = finding(Severity::Error, "gyro_unit", message, Some(&format!("yaw_rate.unit = \"{unit}\" in the recipe")));
            f.fix_value = Some(unit.into());
            r.findings.push(f);
            if cw {
                opposite_ways(r);
            }
            return;
        }
    }
    let (code, message, fix) = if near(k, deg) || near(k, -deg) {
        (
            "heading_unit",
            format!("the reference changes {:.4} of the gyro's heading (1/57.3): ref_heading_deg is in radians", 1.0 / k.abs()),
            "heading.unit = \"rad\" in the recipe",
        )
    } else {
        (
            "gyro_scale",
            format!("the gyro's heading change is {k:.3} times the reference's: a unit or scale mistake"),
            "yaw_rate.unit and scale in the recipe",
        )
    };
    r.findings.push(finding(Severity::Error, code, message, Some(fix)));
    // A reference in radians that also turns the other way is the sign's finding too.
    if code == "heading_unit" && k < 0.0 {
        opposite_ways(r);
    }
}
