//! The canonical drive-log CSV v1 (methods.md, "Canonical drive-log CSV"): `# key: value`
//! metadata lines, one header row, then rows; free column order, unknown columns ignored,
//! an empty cell is a missing value. Parsed streaming from any `Read` with the `csv` crate.
//!
//! Missing cells are stored as NaN: finite input is enforced, so NaN can mean nothing else.

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::Write;

/// The static-bias window when neither the options nor the log's `# bias_s:` give one, s.
pub const DEFAULT_BIAS_S: f64 = 20.0;

/// A metadata value (or key) must be one line of printable text.
pub fn check_meta_text(key: &str, value: &str) -> Result<()> {
    if key.chars().chain(value.chars()).any(char::is_control) {
        return Err(Error::Param { name: format!("metadata {key}"), message: "contains a line break or another control character".into() });
    }
    Ok(())
}

/// The columns of the v1 format, in the order they are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Column {
    TimeS,
    GyroDps,
    TempC,
    RefHeadingDeg,
    SpeedMps,
    OdoLeftM,
    OdoRightM,
    TableRateDps,
}

impl Column {
    /// The physical range of a cell: beyond it a value is a unit or logging mistake (a gyro
    /// far past any full scale, a cabin hotter than an engine bay), refused with its line.
    pub fn physical_range(self) -> Option<(f64, f64, &'static str)> {
        match self {
            Column::GyroDps | Column::TableRateDps => Some((-10_000.0, 10_000.0, "deg/s")),
            Column::TempC => Some((-60.0, 150.0, "deg C")),
            Column::SpeedMps => Some((-150.0, 150.0, "m/s")),
            Column::RefHeadingDeg => Some((-100_000.0, 100_000.0, "deg")),
            _ => None,
        }
    }

    /// The range check of one cell: the message when `v` is outside `physical_range`.
    pub fn check_physical(self, v: f64) -> std::result::Result<(), String> {
        match self.physical_range() {
            Some((lo, hi, unit)) if !(v.is_nan() || (lo..=hi).contains(&v)) => {
                Err(format!("{v:?} {unit} is outside the physical range [{lo}, {hi}] {unit}: a unit mistake?"))
            }
            _ => Ok(()),
        }
    }

    pub const ALL: [Column; 8] = [
        Column::TimeS,
        Column::GyroDps,
        Column::TempC,
        Column::RefHeadingDeg,
        Column::SpeedMps,
        Column::OdoLeftM,
        Column::OdoRightM,
        Column::TableRateDps,
    ];

    /// The header name of the column in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            Column::TimeS => "time_s",
            Column::GyroDps => "gyro_dps",
            Column::TempC => "temp_c",
            Column::RefHeadingDeg => "ref_heading_deg",
            Column::SpeedMps => "speed_mps",
            Column::OdoLeftM => "odo_left_m",
            Column::OdoRightM => "odo_right_m",
            Column::TableRateDps => "table_rate_dps",
        }
    }

    pub fn from_name(name: &str) -> Option<Column> {
        Column::ALL.iter().copied().find(|c| c.name() == name)
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// `# key: value` lines before the header. Known keys are typed; others are kept as text.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct LogMeta {
    pub name: Option<String>,
    pub wheelbase_m: Option<f64>,
    pub bias_s: Option<f64>,
    pub description: Option<String>,
    /// Any other `# key: value` pairs, kept verbatim.
    #[serde(default)]
    pub other: BTreeMap<String, String>,
}

/// A parsed log: one vector per present column, all of the same length as `time_s`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DriveLog {
    pub meta: LogMeta,
    /// 1-based line number in the file of each row (for error messages after parsing).
    pub line: Vec<u64>,
    columns: [Option<Vec<f64>>; 8],
}

/// Limits for untrusted input.
#[derive(Debug, Clone, Copy)]
pub struct ParseOptions {
    /// More data rows than this is an error rather than an out-of-memory abort.
    pub max_rows: usize,
    /// Caps on the file's bytes and one line's.
    pub limits: crate::table::Limits,
    /// The file's lines before the log's first (0; more for a log joined on after another),
    /// so errors and `DriveLog::line` name the file's lines.
    pub lines_before: u64,
}

impl Default for ParseOptions {
    fn default() -> Self {
        // 30 M rows ~ 830 h at 10 Hz, ~2 GB of columns: beyond that a log is a mistake.
        ParseOptions { max_rows: 30_000_000, limits: Default::default(), lines_before: 0 }
    }
}

impl DriveLog {
    /// An empty log with the given columns present (time_s always is).
    pub fn with_columns(columns: &[Column]) -> Self {
        let mut log = DriveLog::default();
        log.columns[Column::TimeS.index()] = Some(Vec::new());
        for c in columns {
            log.columns[c.index()] = Some(Vec::new());
        }
        log
    }

    /// Appends one row; `values` gives the cells of present columns (NaN = missing).
    /// Used by the simulator and importers; time must increase (checked by `validate`).
    pub fn push_row(&mut self, values: &[(Column, f64)]) {
        let n = self.len();
        for col in self.columns.iter_mut().flatten() {
            col.push(f64::NAN);
        }
        for &(c, v) in values {
            if let Some(col) = self.columns[c.index()].as_mut() {
                col[n] = v;
            }
        }
        self.line.push(n as u64 + 2);
    }

    pub fn len(&self) -> usize {
        self.time_s().len()
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    pub fn time_s(&self) -> &[f64] {
        self.columns[0].as_deref().unwrap_or(&[])
    }
    /// The column's cells (NaN = empty cell), or None if the header lacks it.
    pub fn column(&self, c: Column) -> Option<&[f64]> {
        self.columns[c.index()].as_deref()
    }
    /// The column's cells to change in place (the robustness battery's error injection).
    pub fn column_mut(&mut self, c: Column) -> Option<&mut [f64]> {
        self.columns[c.index()].as_deref_mut()
    }
    /// Removes a column (not time_s): the battery's gyro-only logs drop speed and wheels.
    pub fn drop_column(&mut self, c: Column) {
        if c != Column::TimeS {
            self.columns[c.index()] = None;
        }
    }
    /// Keeps only the rows from index `first` on (e.g. to cut a stationary lead-in).
    pub fn drop_first_rows(&mut self, first: usize) {
        let first = first.min(self.len());
        for col in self.columns.iter_mut().flatten() {
            col.drain(..first);
        }
        self.line.drain(..first.min(self.line.len()));
    }
    /// The rows from index `at` on, moved into a log of their own with the same metadata.
    pub(crate) fn split_off(&mut self, at: usize) -> DriveLog {
        let at = at.min(self.len());
        let columns = std::array::from_fn(|i| self.columns[i].as_mut().map(|c| c.split_off(at)));
        DriveLog { meta: self.meta.clone(), line: self.line.split_off(at.min(self.line.len())), columns }
    }
    /// Keeps rows `a..b` (one part of a log split at its gaps).
    pub fn keep_range(&mut self, a: usize, b: usize) {
        for col in self.columns.iter_mut().flatten() {
            col.truncate(b);
            col.drain(..a);
        }
        self.line.truncate(b);
        self.line.drain(..a.min(self.line.len()));
    }
    /// Keeps the rows whose time passes `keep` (a gap cut into a log, a span).
    pub fn retain_rows(&mut self, keep: impl Fn(f64) -> bool) {
        let mask: Vec<bool> = self.time_s().iter().map(|&t| keep(t)).collect();
        for col in self.columns.iter_mut().flatten() {
            let mut m = mask.iter();
            col.retain(|_| *m.next().unwrap_or(&true));
        }
        let mut m = mask.iter();
        self.line.retain(|_| *m.next().unwrap_or(&true));
    }

    /// The column, or an error naming it and the method that needs it.
    pub fn require(&self, c: Column, needed_by: &str) -> Result<&[f64]> {
        self.column(c).ok_or_else(|| Error::missing(c.name(), needed_by))
    }
    pub fn has(&self, c: Column) -> bool {
        self.columns[c.index()].is_some()
    }
    /// Whether there is a reference heading to score against: a `ref_heading_deg` column
    /// with at least one value. Without one the methods run and nothing is scored.
    pub fn has_reference(&self) -> bool {
        self.column(Column::RefHeadingDeg).is_some_and(|h| h.iter().any(|v| !v.is_nan()))
    }
    pub fn present_columns(&self) -> Vec<Column> {
        Column::ALL.iter().copied().filter(|&c| self.has(c)).collect()
    }

    /// Duration T_d in minutes: last minus first time_s of the whole log (methods.md detail 5).
    /// A log a method can score: rows over a span of time (one row, or rows at one time,
    /// would give NaN per minute).
    pub fn check_span(&self) -> Result<()> {
        if self.duration_min() > 0.0 {
            return Ok(());
        }
        Err(Error::data(format!("the log lasts 0 s ({} row(s)): a method needs rows over a span of time", self.len())))
    }

    pub fn duration_min(&self) -> f64 {
        let t = self.time_s();
        match (t.first(), t.last()) {
            (Some(a), Some(b)) => (b - a) / 60.0,
            _ => 0.0,
        }
    }

    /// What kind of log this is, from its columns: turntable, robot, drive or static. A
    /// speed makes a drive without a reference heading too (a drive with no GPS course: the
    /// methods run, nothing is scored), not a static session.
    pub fn kind(&self) -> LogKind {
        if self.has(Column::TableRateDps) {
            LogKind::Turntable
        } else if self.has(Column::OdoLeftM) && self.has(Column::OdoRightM) {
            LogKind::Robot
        } else if self.has(Column::RefHeadingDeg) || self.has(Column::SpeedMps) {
            LogKind::Drive
        } else {
            LogKind::Static
        }
    }

    /// The static-bias window length: the option, else `# bias_s:`, else 20 s (detail 1).
    /// A part split off after a gap has its bias removed already: 0 (see `gaps`).
    pub fn bias_s(&self, option: Option<f64>) -> f64 {
        if self.meta.other.contains_key(gaps::BIAS_REMOVED_KEY) {
            return 0.0;
        }
        option.or(self.meta.bias_s).unwrap_or(DEFAULT_BIAS_S)
    }

    /// Writes the log as CSV v1 (metadata, header of present columns, rows).
    /// Numbers are written with Rust's shortest round-trip formatting, so parse(write(x)) == x.
    pub fn write_csv<W: Write>(&self, out: W) -> Result<()> {
        let m = &self.meta;
        // A line break in a value would write a metadata line of its own (`# bias_s: 0`).
        let texts = [("name", m.name.as_deref()), ("description", m.description.as_deref())];
        for (k, v) in texts.into_iter().filter_map(|(k, v)| v.map(|v| (k, v))).chain(m.other.iter().map(|(k, v)| (k.as_str(), v.as_str())))
        {
            check_meta_text(k, v)?;
        }
        let mut out = std::io::BufWriter::new(out);
        if let Some(v) = &m.name {
            writeln!(out, "# name: {v}")?;
        }
        if let Some(v) = &m.description {
            writeln!(out, "# description: {v}")?;
        }
        if let Some(v) = m.wheelbase_m {
            writeln!(out, "# wheelbase_m: {v}")?;
        }
        if let Some(v) = m.bias_s {
            writeln!(out, "# bias_s: {v}")?;
        }
        for (k, v) in &m.other {
            writeln!(out, "# {k}: {v}")?;
        }
        let cols: Vec<(Column, &[f64])> = Column::ALL.iter().filter_map(|&c| self.column(c).map(|v| (c, v))).collect();
        let header: Vec<&str> = cols.iter().map(|(c, _)| c.name()).collect();
        writeln!(out, "{}", header.join(","))?;
        let mut buf = String::new();
        for i in 0..self.len() {
            buf.clear();
            for (j, (_, v)) in cols.iter().enumerate() {
                if j > 0 {
                    buf.push(',');
                }
                let x = v[i];
                if x.is_finite() {
                    use std::fmt::Write as _;
                    let _ = write!(buf, "{x}");
                }
            }
            buf.push('\n');
            out.write_all(buf.as_bytes())?;
        }
        out.flush()?;
        Ok(())
    }
}

impl DriveLog {
    /// A log from columns (e.g. handed over from a parsing worker), checked as the parser
    /// checks: equal lengths, a finite strictly increasing time, finite or missing values in
    /// range. `line` of another length than the columns numbers the rows from line 2.
    pub fn from_columns(meta: LogMeta, line: Vec<u64>, columns: Vec<(Column, Vec<f64>)>) -> Result<DriveLog> {
        let names: Vec<Column> = columns.iter().map(|(c, _)| *c).collect();
        let mut b = LogBuilder::new(meta, &names, 0)?;
        b.append(line, columns)?;
        b.finish()
    }

    /// The present columns with their values (for handing a parsed log to another thread).
    pub fn columns(&self) -> Vec<(Column, &[f64])> {
        Column::ALL.iter().filter_map(|&c| self.column(c).map(|v| (c, v))).collect()
    }
}

/// The kind of a log, decided by its columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LogKind {
    Drive,
    Robot,
    Turntable,
    Static,
}

pub mod accept;
mod builder;
pub mod dialect;
pub use builder::LogBuilder;
pub mod file;
pub mod gaps;
mod parse;
mod refusal;
#[cfg(feature = "fs")]
pub(crate) use parse::is_bad_time_cell;
pub use parse::{parse_log, parse_log_in_time_order, parse_log_progress, parse_log_str, parse_log_with};

#[cfg(test)]
mod tests;
