//! Time in a recipe's tables: the time column's format and unit, and the policies for the
//! mess raw exports have (a repeated timestamp, a row written a little late, a clock reset),
//! with counts of what they did.

use super::*;

/// The time of a table's rows.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TimeSpec {
    /// The time column; absent = row index times `period_s`.
    pub column: Option<String>,
    /// `seconds` (numbers, with `unit`), `iso8601` (e.g. `2023-08-06 10:48:05-04:00`) or
    /// `time_of_day` (`13:05:09.250`, `13:05:09:250`, NMEA's `130509.25`; no date: the
    /// day is counted on where the time passes midnight).
    #[serde(default)]
    pub format: TimeFormat,
    /// Unit of numeric times: s, ms, us, ns.
    #[serde(default = "default_time_unit")]
    pub unit: String,
    /// Sample period for tables without a time column (or with a wrong one), seconds.
    pub period_s: Option<f64>,
    /// Subtract the table's first time (for a sensor's own clock, then aligned).
    #[serde(default)]
    pub relative: bool,
    /// Rows with the same time (a logger writing one sample twice): `mean` (the default:
    /// one row, each column the mean of its present values), `drop` (keep the first) or
    /// `error`.
    #[serde(default)]
    pub duplicates: DuplicatePolicy,
    /// A row earlier than the one before it by at most `max_backward_s` (out-of-order
    /// writes): `sort` (the default: the rows are put in time order), `drop` (the late row
    /// is dropped) or `error`. A larger step back is a clock reset: always an error.
    #[serde(default)]
    pub backward: BackwardPolicy,
    #[serde(default = "default_max_backward_s")]
    pub max_backward_s: f64,
}

/// The serde defaults: no column (a recipe must name one, or a period), seconds, the
/// default policies.
impl Default for TimeSpec {
    fn default() -> Self {
        TimeSpec {
            column: None,
            format: TimeFormat::Seconds,
            unit: default_time_unit(),
            period_s: None,
            relative: false,
            duplicates: DuplicatePolicy::Mean,
            backward: BackwardPolicy::Sort,
            max_backward_s: default_max_backward_s(),
        }
    }
}

pub(super) fn default_max_backward_s() -> f64 {
    MAX_BACKWARD_S
}

/// The largest step back a row may take and be sorted in (1 s); beyond it, a clock reset.
pub const MAX_BACKWARD_S: f64 = 1.0;

/// Whether time `t` after the latest time `latest` is a clock reset in a v1 log: more than
/// [`MAX_BACKWARD_S`] back (the parser's refusal, `put_v1_in_time_order`, and where
/// `accept::parse_joined` cuts a log).
pub(crate) fn is_clock_reset(latest: f64, t: f64) -> bool {
    latest - t > MAX_BACKWARD_S
}

/// What the import does with rows that repeat a time.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DuplicatePolicy {
    #[default]
    Mean,
    Drop,
    Error,
}

/// What the import does with rows that step back in time a little.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BackwardPolicy {
    #[default]
    Sort,
    Drop,
    Error,
}

pub(super) fn default_time_unit() -> String {
    "s".into()
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TimeFormat {
    #[default]
    Seconds,
    Iso8601,
    TimeOfDay,
}

/// A time of day (s since midnight) on the table's own clock: the day it falls in is the
/// first row's, plus one each time the time of day falls more than 12 h below the latest
/// time so far (midnight passed); a row more than 12 h above it is a late row of the day
/// before (written just after midnight passed). `day_s` carries the days counted so far.
pub(super) fn past_midnight(time_of_day_s: f64, day_s: &mut f64, latest_s: f64) -> f64 {
    while time_of_day_s + *day_s < latest_s - 43_200.0 {
        *day_s += 86_400.0;
    }
    let t = time_of_day_s + *day_s;
    if t > latest_s + 43_200.0 && *day_s > 0.0 {
        t - 86_400.0
    } else {
        t
    }
}

/// Counts of the time policies' work.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct TimeFixes {
    pub merged_duplicates: usize,
    pub dropped_duplicates: usize,
    pub sorted_backward: usize,
    pub dropped_backward: usize,
}

impl TimeFixes {
    /// What the time policies did ("2 rows of a repeated time merged, 1 late rows put in
    /// time order"; empty when nothing): the import's summary and a fixed log's warning.
    pub fn to_text(&self) -> String {
        let said: Vec<String> = [
            (self.merged_duplicates, "rows of a repeated time merged"),
            (self.dropped_duplicates, "rows of a repeated time dropped"),
            (self.sorted_backward, "late rows put in time order"),
            (self.dropped_backward, "late rows dropped"),
        ]
        .iter()
        .filter(|(n, _)| *n > 0)
        .map(|(n, what)| format!("{n} {what}"))
        .collect();
        said.join(", ")
    }
}

/// A row's time against the one before (`prev`) and the latest so far: a repeat or a small
/// step back is left to the policies unless they say `error`; a step back past
/// `max_backward_s` is a clock reset, an error naming the line.
pub(super) fn check_step(spec: &TimeSpec, time: f64, prev: Option<f64>, latest: f64, line: u64, column: &str) -> Result<()> {
    let Some(prev) = prev else { return Ok(()) };
    let err = |message: String| Err(Error::Cell { line, column: column.to_string(), message });
    if time == prev && spec.duplicates == DuplicatePolicy::Error {
        return err(format!("time {time} repeats the previous row's (time.duplicates = \"mean\" or \"drop\" merges or drops such rows)"));
    }
    if time < latest {
        if latest - time > spec.max_backward_s {
            return err(format!(
                "time {time} goes back {:.3} s from {latest}: a clock reset? (more than time.max_backward_s = {} s; split the file, or span_s)",
                latest - time,
                spec.max_backward_s
            ));
        }
        if spec.backward == BackwardPolicy::Error {
            return err(format!("time {time} goes back from {latest} (time.backward = \"sort\" or \"drop\" handles such rows)"));
        }
    }
    Ok(())
}

/// A v1 log's rows in file order (`log::parse_log_in_time_order`) put in time order by the
/// default policies (rows of one time merged by their mean, rows up to 1 s late sorted in);
/// a step back past 1 s is a clock reset, an error naming the line.
pub(crate) fn put_v1_in_time_order(time: &mut Vec<f64>, line: &mut Vec<u64>, cols: &mut [Vec<f64>]) -> Result<TimeFixes> {
    let spec = TimeSpec::default();
    let mut latest = f64::NEG_INFINITY;
    for (&t, &l) in time.iter().zip(line.iter()) {
        if is_clock_reset(latest, t) {
            let message = format!(
                "time {t} goes back {:.3} s from {latest}: a clock reset? (rows up to 1 s late are sorted in; the joined-logs rule `split` reads each part as a log of its own)",
                latest - t
            );
            return Err(Error::Cell { line: l, column: "time_s".into(), message });
        }
        latest = latest.max(t);
    }
    Ok(put_in_time_order(&spec, time, line, cols))
}

/// Applies the time policies to rows read in file order: late rows sorted in (a stable sort,
/// so equal times keep their order) or dropped, then rows of one time merged (each column's
/// mean of its present values) or all but the first dropped. Times strictly increase after.
pub(super) fn put_in_time_order(spec: &TimeSpec, time: &mut Vec<f64>, line: &mut Vec<u64>, cols: &mut [Vec<f64>]) -> TimeFixes {
    let mut fixes = TimeFixes::default();
    let in_order = time.windows(2).all(|w| w[1] > w[0]);
    if in_order {
        return fixes;
    }
    // Which rows stay, in which order.
    let mut order: Vec<usize> = Vec::with_capacity(time.len());
    let mut latest = f64::NEG_INFINITY;
    for i in 0..time.len() {
        if time[i] < latest {
            match spec.backward {
                BackwardPolicy::Drop => {
                    fixes.dropped_backward += 1;
                    continue;
                }
                _ => fixes.sorted_backward += 1,
            }
        }
        latest = latest.max(time[i]);
        order.push(i);
    }
    order.sort_by(|&a, &b| time[a].total_cmp(&time[b]));
    // Groups of one time become one row.
    let (mut t2, mut l2) = (Vec::with_capacity(order.len()), Vec::with_capacity(order.len()));
    let mut c2: Vec<Vec<f64>> = cols.iter().map(|_| Vec::with_capacity(order.len())).collect();
    let mut g = 0;
    while g < order.len() {
        let mut end = g + 1;
        while end < order.len() && time[order[end]] == time[order[g]] {
            end += 1;
        }
        let group = &order[g..end];
        t2.push(time[group[0]]);
        l2.push(line[group[0]]);
        for (c, out) in cols.iter().zip(c2.iter_mut()) {
            let v = match spec.duplicates {
                DuplicatePolicy::Mean => {
                    let (s, n) = group.iter().map(|&i| c[i]).filter(|x| !x.is_nan()).fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
                    if n > 0 {
                        s / n as f64
                    } else {
                        f64::NAN
                    }
                }
                _ => c[group[0]],
            };
            out.push(v);
        }
        match spec.duplicates {
            DuplicatePolicy::Mean => fixes.merged_duplicates += group.len() - 1,
            _ => fixes.dropped_duplicates += group.len() - 1,
        }
        g = end;
    }
    *time = t2;
    *line = l2;
    for (c, v) in cols.iter_mut().zip(c2) {
        *c = v;
    }
    fixes
}
