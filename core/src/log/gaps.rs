//! Gaps in time (a logger pause, a lost connection): no method may integrate across one as if
//! the rate had stayed constant (a 60 s gap on City 1 turns HDR's E_psi from 5 deg into 242).
//! The policy splits the log there into parts that are drives of their own, or refuses it.

use super::{Column, DriveLog};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// A gap is a step longer than this many median steps (and at least `GAP_MIN_S`).
pub const GAP_STEPS: f64 = 20.0;
pub const GAP_MIN_S: f64 = 5.0;
/// A part shorter than this says nothing about drift; it is dropped and counted.
pub const MIN_PART_S: f64 = 30.0;
/// Metadata key of a part after the first: the static bias (deg/s) already removed from its
/// gyro, measured on the first part's lead-in (the gyro is the same; the car is not still).
pub const BIAS_REMOVED_KEY: &str = "static_bias_removed_dps";

/// What a command does with a log that has gaps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GapPolicy {
    /// Each stretch between gaps is scored as a drive of its own (the forgiving default).
    #[default]
    Split,
    /// A gap is an error naming its line.
    Error,
}

/// One gap: the row before it, its length, the line of the row after it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Gap {
    pub at_s: f64,
    pub length_s: f64,
    pub line: u64,
}

/// The parts of a log and what splitting did.
#[derive(Debug, Clone)]
pub struct Split {
    pub parts: Vec<DriveLog>,
    pub gaps: Vec<Gap>,
    /// Parts dropped for lasting under `MIN_PART_S`: (first time, seconds).
    pub dropped: Vec<(f64, f64)>,
}

impl Split {
    /// One line for the user, or None when the log had no gap.
    pub fn summary(&self) -> Option<String> {
        if self.gaps.is_empty() {
            return None;
        }
        // Folded, not `join`ed: a `[String]` join is a second instance in the browser's
        // size-capped module (BENCHMARKS.md).
        let gaps = self.gaps.iter().map(|g| format!("{:.1} s at line {}", g.length_s, g.line)).reduce(|a, b| a + ", " + &b);
        let dropped = match self.dropped.len() {
            0 => String::new(),
            n => format!(", {n} part(s) under {MIN_PART_S} s dropped"),
        };
        Some(format!(
            "split at {} gap(s) ({}) into {} part(s) scored as drives of their own{dropped}",
            self.gaps.len(),
            gaps.unwrap_or_default(),
            self.parts.len()
        ))
    }
}

/// The threshold of a gap for these times: `GAP_STEPS` median steps, at least `GAP_MIN_S`.
pub fn gap_threshold_s(time_s: &[f64]) -> f64 {
    let mut steps: Vec<f64> = time_s.windows(2).map(|w| w[1] - w[0]).collect();
    if steps.is_empty() {
        return GAP_MIN_S;
    }
    (GAP_STEPS * crate::metrics::quantile_mut(&mut steps, 0.5)).max(GAP_MIN_S)
}

/// The gaps of a log.
pub fn find_gaps(log: &DriveLog) -> Vec<Gap> {
    let t = log.time_s();
    let limit = gap_threshold_s(t);
    (1..t.len())
        .filter(|&i| t[i] - t[i - 1] > limit)
        .map(|i| Gap { at_s: t[i - 1], length_s: t[i] - t[i - 1], line: log.line.get(i).copied().unwrap_or(i as u64 + 2) })
        .collect()
}

/// Applies the policy. `bias_s` is the static-bias window the command would use: the first
/// part's lead-in gives the bias removed from the later parts' gyro. A log without gaps is
/// its own one part (moved, not copied).
pub fn split_at_gaps(log: DriveLog, policy: GapPolicy, bias_s: f64) -> Result<Split> {
    let gaps = find_gaps(&log);
    if gaps.is_empty() {
        return Ok(Split { parts: vec![log], gaps, dropped: Vec::new() });
    }
    if policy == GapPolicy::Error {
        let g = gaps[0];
        return Err(Error::Cell {
            line: g.line,
            column: "time_s".into(),
            message: format!(
                "a gap of {:.1} s after t = {} s: no method may integrate across it (split the log: --gaps split)",
                g.length_s, g.at_s
            ),
        });
    }
    let t = log.time_s();
    let mut starts = vec![0];
    starts.extend(gaps.iter().map(|g| t.partition_point(|&x| x <= g.at_s)));
    starts.push(t.len());
    let eps0 = match log.column(Column::GyroDps) {
        Some(g) => crate::preprocess::static_bias_dps(t, g, log.bias_s(Some(bias_s))).unwrap_or(0.0),
        None => 0.0,
    };
    let (mut parts, mut dropped) = (Vec::new(), Vec::new());
    for (k, w) in starts.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let span = t[b - 1] - t[a];
        if span < MIN_PART_S {
            dropped.push((t[a], span));
            continue;
        }
        parts.push(part(&log, a, b, if k == 0 { None } else { Some(eps0) }));
    }
    let n = parts.len();
    let base = log.meta.name.clone().unwrap_or_else(|| "log".into());
    for (i, p) in parts.iter_mut().enumerate() {
        p.meta.name = Some(format!("{base} (part {} of {n})", i + 1));
    }
    Ok(Split { parts, gaps, dropped })
}

/// Rows `a..b` of the log; a later part gets the first part's static bias removed.
fn part(log: &DriveLog, a: usize, b: usize, remove_bias_dps: Option<f64>) -> DriveLog {
    let mut p = log.clone();
    p.keep_range(a, b);
    if let Some(eps0) = remove_bias_dps {
        if let Some(g) = p.column_mut(Column::GyroDps) {
            g.iter_mut().for_each(|v| *v -= eps0);
        }
        p.meta.other.insert(BIAS_REMOVED_KEY.into(), format!("{eps0}"));
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 1 Hz rows of a turning drive with a time jump of `gap_s` after t = 100 s.
    fn drive(gap_s: f64) -> DriveLog {
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]);
        log.meta.name = Some("d".into());
        for i in 0..200 {
            let t = i as f64 + if i > 100 { gap_s } else { 0.0 };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, 0.5), (Column::RefHeadingDeg, 0.0)]);
        }
        log
    }

    #[test]
    fn no_gap_keeps_the_log_whole() {
        let s = split_at_gaps(drive(0.0), GapPolicy::Split, 20.0).unwrap();
        assert_eq!((s.parts.len(), s.gaps.len()), (1, 0));
        assert_eq!(s.parts[0], drive(0.0));
        assert!(s.summary().is_none());
    }

    #[test]
    fn a_gap_splits_into_two_drives_and_the_second_loses_the_first_ones_bias() {
        let s = split_at_gaps(drive(60.0), GapPolicy::Split, 20.0).unwrap();
        // the step 100 -> 161 s is 61 s; the threshold is max(20 x 1 s, 5 s) = 20 s
        assert_eq!(s.gaps, vec![Gap { at_s: 100.0, length_s: 61.0, line: 103 }]);
        assert_eq!(s.parts.len(), 2);
        assert_eq!(s.parts[0].len(), 101);
        assert_eq!(s.parts[1].len(), 99);
        assert_eq!(s.parts[1].time_s()[0], 161.0);
        assert_eq!(s.parts[1].line[0], 103);
        // part 1's lead-in gives 0.5 deg/s; part 2's gyro is already corrected, and says so
        assert_eq!(s.parts[1].column(Column::GyroDps).unwrap()[0], 0.0);
        assert_eq!(s.parts[1].bias_s(Some(20.0)), 0.0);
        assert_eq!(s.parts[0].column(Column::GyroDps).unwrap()[0], 0.5);
        assert_eq!(s.parts[1].meta.name.as_deref(), Some("d (part 2 of 2)"));
        assert!(s.summary().unwrap().contains("61.0 s at line 103"));
    }

    #[test]
    fn short_parts_are_dropped_and_counted() {
        let mut log = drive(60.0);
        log.retain_rows(|t| !(170.0..=200.0).contains(&t)); // parts 0..100 s, 161..169 s, 201..259 s
        let s = split_at_gaps(log, GapPolicy::Split, 20.0).unwrap();
        assert_eq!(s.gaps.len(), 2);
        assert_eq!(s.parts.len(), 2);
        assert_eq!(s.dropped, vec![(161.0, 8.0)]);
    }

    #[test]
    fn the_error_policy_names_the_line() {
        let e = split_at_gaps(drive(60.0), GapPolicy::Error, 20.0).unwrap_err().to_string();
        assert!(e.contains("line 103") && e.contains("61.0 s"), "{e}");
    }
}
