//! Import of recorded logs in any tabular format into the canonical v1 log, driven by a
//! declarative recipe: which files, which columns, units, sign or axis (or projection onto
//! gravity), time format, and how the reference heading, speed and wheel travel are
//! obtained. Tables are merged on time: every gyro row and every reference sample becomes a
//! row; speed, temperature and wheel travel are interpolated onto the rows; the reference
//! heading is never resampled (methods.md, detail 2).
//!
//! Transcendental functions come from `libm`, so the wasm package imports bit-identically.
//! Core reads the files through [`Files`] (any `Read`); the recipe arrives deserialized
//! (the CLI reads TOML, the wasm package takes a JS object), so core knows no file system.

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog, LogMeta};
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use std::io::{BufRead, BufReader, Read};

/// A whole import recipe (see `sample-logs/recipes/README.md` for the format by example).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Recipe {
    /// Written as `# name:`.
    pub name: Option<String>,
    /// Written as `# description:`.
    pub description: Option<String>,
    /// Static-bias window for the log (`# bias_s:`), e.g. 0 when the log starts moving.
    pub bias_s: Option<f64>,
    /// The input files, each with its time column.
    #[serde(rename = "table")]
    pub tables: Vec<TableSpec>,
    /// The yaw rate (required).
    pub yaw_rate: RateSpec,
    /// Positions, when the heading or the speed is derived from them.
    pub positions: Option<PositionsSpec>,
    /// The reference heading (needed for the metrics).
    pub heading: Option<HeadingSpec>,
    pub speed: Option<SpeedSpec>,
    /// Left and right wheel speed or travel, for Gyrodometry on cars.
    pub odometry: Option<OdometrySpec>,
    pub temperature: Option<ValueSpec>,
    /// Shift the gyro table's clock onto the others' by cross-correlating rates.
    pub align: Option<AlignSpec>,
    /// Keep only the rows with start <= time_s <= end (seconds from the first gyro sample).
    pub span_s: Option<[f64; 2]>,
}

/// One input file.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TableSpec {
    /// The name other sections use to refer to this table.
    pub id: String,
    /// The file, relative to the data folder the caller resolves it in.
    pub file: String,
    #[serde(default)]
    pub format: TableFormat,
    /// Lines to skip before the header (or the first row), e.g. 1 for a `sep=,` line.
    #[serde(default)]
    pub skip_lines: usize,
    /// Column names of a file without a header row (the header is then not read).
    pub columns: Option<Vec<String>>,
    /// Keep only the rows whose first field equals this (e.g. `odom3`, `$VNYMR`).
    pub record: Option<String>,
    pub time: TimeSpec,
    /// Added to this table's times, seconds (a known clock offset).
    #[serde(default)]
    pub offset_s: f64,
}

/// How a table is split into fields.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TableFormat {
    /// Comma-separated, quotes allowed, spaces around fields trimmed.
    #[default]
    Csv,
    /// Fields separated by runs of spaces or tabs.
    Whitespace,
    /// NMEA-like sentences: comma-separated, a trailing `*hh` checksum stripped.
    Nmea,
}

/// The time of a table's rows.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TimeSpec {
    /// The time column; absent = row index times `period_s`.
    pub column: Option<String>,
    /// `seconds` (numbers, with `unit`) or `iso8601` (e.g. `2023-08-06 10:48:05-04:00`).
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
}

fn default_time_unit() -> String {
    "s".into()
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TimeFormat {
    #[default]
    Seconds,
    Iso8601,
}

/// Which way a positive value turns the vehicle, seen from above.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sense {
    /// Counter-clockwise (left turn) positive: the v1 convention.
    Ccw,
    /// Clockwise positive: a GPS course or bearing, a z-down gyro axis.
    Cw,
}

impl Sense {
    fn factor(self) -> f64 {
        match self {
            Sense::Ccw => 1.0,
            Sense::Cw => -1.0,
        }
    }
}

/// A yaw rate: one column, or a 3-axis gyro projected on the up direction.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RateSpec {
    pub table: String,
    /// The yaw-axis column (single axis).
    pub column: Option<String>,
    /// Three gyro columns (x, y, z) to project on gravity.
    pub axes: Option<Vec<String>>,
    /// Per-axis factors (e.g. [1, -1, 1]) that undo a negation made upstream, so that
    /// `axes` form a right-handed triad (with `axes`; default all 1).
    pub signs: Option<Vec<f64>>,
    /// The accelerometer that gives the up direction (with `axes`).
    pub gravity: Option<GravitySpec>,
    /// deg/s, rad/s, deg/h, or counts (with `scale`).
    pub unit: String,
    /// Multiplier to the unit (e.g. 1/6258 rad/s per count), applied after `offset`.
    #[serde(default = "one")]
    pub scale: f64,
    /// Subtracted from the raw value first (e.g. 32768 counts).
    #[serde(default)]
    pub offset: f64,
    /// The sense of positive values (after projection: ccw for a right-handed triad).
    pub positive: Sense,
}

fn one() -> f64 {
    1.0
}

/// Up = the mean specific force over the first `first_s` seconds (vehicle at rest).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GravitySpec {
    /// Accelerometer x, y, z columns in the gyro's table and frame.
    pub axes: Vec<String>,
    /// Per-axis factors for the accelerometer, as `signs` for the gyro.
    pub signs: Option<Vec<f64>>,
    #[serde(default = "default_gravity_s")]
    pub first_s: f64,
}

fn default_gravity_s() -> f64 {
    10.0
}

/// Positions from which a course and a speed are derived.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PositionsSpec {
    pub table: String,
    /// latlon (deg), utm (easting, northing m), ecef (x, y, z m) or enu (east, north m).
    pub kind: PositionKind,
    pub columns: Vec<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PositionKind {
    Latlon,
    Utm,
    Ecef,
    Enu,
}

/// The reference heading: an angle column, or the course of the positions. Written flat
/// with a `source` field (`source = "column"` or `"positions"`).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(try_from = "HeadingWire")]
pub enum HeadingSpec {
    /// A heading, course or bearing column; kept only while the speed column is above
    /// `min_speed_mps` (a course is noise when standing).
    Column {
        table: String,
        column: String,
        /// deg or rad.
        unit: String,
        positive: Sense,
        /// A speed column of the same table, m/s, gating the heading.
        speed_column: Option<String>,
        min_speed_mps: f64,
    },
    /// The course over ground between positions at least `min_distance_m` apart (default
    /// 2 m), stamped at the middle of the segment, kept when the segment's speed is at least
    /// `min_speed_mps` (default 1 m/s).
    Positions { min_distance_m: f64, min_speed_mps: f64 },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
enum Source {
    Column,
    Positions,
}

/// The flat form of `heading` in a recipe (a plain struct: no buffering of tagged enums,
/// which costs the wasm package size).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct HeadingWire {
    source: Source,
    table: Option<String>,
    column: Option<String>,
    unit: Option<String>,
    positive: Option<Sense>,
    speed_column: Option<String>,
    min_speed_mps: Option<f64>,
    min_distance_m: Option<f64>,
}

/// A field the chosen `source` needs, or an error naming it.
fn needed<T>(v: Option<T>, section: &str, field: &str, source: &str) -> std::result::Result<T, String> {
    v.ok_or_else(|| format!("{section}: source = \"{source}\" needs `{field}`"))
}

/// Fields that the chosen `source` does not use: an error naming the first one given.
fn unused(section: &str, source: &str, given: &[(&str, bool)]) -> std::result::Result<(), String> {
    match given.iter().find(|(_, g)| *g) {
        Some((name, _)) => Err(format!("{section}: `{name}` is not used with source = \"{source}\"")),
        None => Ok(()),
    }
}

impl TryFrom<HeadingWire> for HeadingSpec {
    type Error = String;
    fn try_from(w: HeadingWire) -> std::result::Result<Self, String> {
        match w.source {
            Source::Column => {
                unused("heading", "column", &[("min_distance_m", w.min_distance_m.is_some())])?;
                Ok(HeadingSpec::Column {
                    table: needed(w.table, "heading", "table", "column")?,
                    column: needed(w.column, "heading", "column", "column")?,
                    unit: needed(w.unit, "heading", "unit", "column")?,
                    positive: needed(w.positive, "heading", "positive", "column")?,
                    speed_column: w.speed_column,
                    min_speed_mps: w.min_speed_mps.unwrap_or(0.0),
                })
            }
            Source::Positions => {
                unused(
                    "heading",
                    "positions",
                    &[
                        ("table", w.table.is_some()),
                        ("column", w.column.is_some()),
                        ("unit", w.unit.is_some()),
                        ("positive", w.positive.is_some()),
                        ("speed_column", w.speed_column.is_some()),
                    ],
                )?;
                Ok(HeadingSpec::Positions {
                    min_distance_m: w.min_distance_m.unwrap_or(2.0),
                    min_speed_mps: w.min_speed_mps.unwrap_or(1.0),
                })
            }
        }
    }
}

/// Vehicle speed: a column, or derived from the positions over `window_s` (default 1 s).
/// Written flat with a `source` field.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(try_from = "SpeedWire")]
pub enum SpeedSpec {
    Column {
        table: String,
        column: String,
        /// m/s, km/h or mph.
        unit: String,
    },
    Positions {
        window_s: f64,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpeedWire {
    source: Source,
    table: Option<String>,
    column: Option<String>,
    unit: Option<String>,
    window_s: Option<f64>,
}

impl TryFrom<SpeedWire> for SpeedSpec {
    type Error = String;
    fn try_from(w: SpeedWire) -> std::result::Result<Self, String> {
        match w.source {
            Source::Column => {
                unused("speed", "column", &[("window_s", w.window_s.is_some())])?;
                Ok(SpeedSpec::Column {
                    table: needed(w.table, "speed", "table", "column")?,
                    column: needed(w.column, "speed", "column", "column")?,
                    unit: needed(w.unit, "speed", "unit", "column")?,
                })
            }
            Source::Positions => {
                unused("speed", "positions", &[("table", w.table.is_some()), ("column", w.column.is_some()), ("unit", w.unit.is_some())])?;
                Ok(SpeedSpec::Positions { window_s: w.window_s.unwrap_or(1.0) })
            }
        }
    }
}

/// Left and right wheel speeds (integrated) or cumulative travel; each side may average
/// several columns (e.g. front and rear).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OdometrySpec {
    pub table: String,
    pub left: Vec<String>,
    pub right: Vec<String>,
    /// `speed` (m/s, km/h, mph: integrated over time) or `travel` (m).
    pub kind: OdometryKind,
    pub unit: String,
    /// Distance between the left and right wheels, m (`# wheelbase_m:` of the log).
    pub track_m: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OdometryKind {
    Speed,
    Travel,
}

/// A plain value column (temperature: unit C, K or F).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ValueSpec {
    pub table: String,
    pub column: String,
    pub unit: String,
}

/// Finds the offset of the gyro table's clock by cross-correlating its yaw rate with a
/// reference rate from another table (e.g. a reference unit's gyro), within `max_lag_s`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlignSpec {
    pub rate: RateSpec,
    #[serde(default = "default_max_lag")]
    pub max_lag_s: f64,
}

fn default_max_lag() -> f64 {
    15.0
}

/// The input files, opened by name (the recipe's `file` values).
pub trait Files {
    fn open(&mut self, name: &str) -> Result<Box<dyn Read + '_>>;
}

impl<F: FnMut(&str) -> Result<Box<dyn Read>>> Files for F {
    fn open(&mut self, name: &str) -> Result<Box<dyn Read + '_>> {
        self(name)
    }
}

/// In-memory files (the wasm package, tests).
impl Files for BTreeMap<String, Vec<u8>> {
    fn open(&mut self, name: &str) -> Result<Box<dyn Read + '_>> {
        match self.get(name) {
            Some(b) => Ok(Box::new(b.as_slice())),
            None => Err(Error::File(format!("{name}: the recipe names this file, but it was not given"))),
        }
    }
}

/// What the import did, for the user to check (sign, alignment, counts).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ImportSummary {
    pub n_rows: usize,
    pub n_gyro: usize,
    pub n_reference: usize,
    pub duration_min: f64,
    /// The unit up vector found from the accelerometer, when projecting.
    pub up: Option<[f64; 3]>,
    /// The clock offset found by alignment, seconds (added to the gyro table's times).
    pub align_offset_s: Option<f64>,
    /// The first gyro time in the source clock (the log's time 0), seconds.
    pub start_time_s: f64,
}

/// A table read from a file: the time of each row and the columns the recipe uses.
struct Table {
    file: String,
    time_s: Vec<f64>,
    line: Vec<u64>,
    cols: BTreeMap<String, Vec<f64>>,
}

impl Table {
    fn col(&self, name: &str, used_by: &str) -> Result<&[f64]> {
        self.cols.get(name).map(|v| v.as_slice()).ok_or_else(|| Error::missing(name, &format!("{used_by} (in {})", self.file)))
    }
}

fn recipe_err(field: &str, message: impl Into<String>) -> Error {
    Error::Param { name: format!("recipe {field}"), message: message.into() }
}

/// Factor from `unit` to deg/s.
fn rate_unit(unit: &str, field: &str) -> Result<f64> {
    Ok(match unit {
        "deg/s" | "dps" => 1.0,
        "rad/s" => 180.0 / std::f64::consts::PI,
        "mrad/s" => 0.18 / std::f64::consts::PI,
        "deg/h" => 1.0 / 3600.0,
        // Raw counts: `scale` converts them to deg/s.
        "counts" => 1.0,
        _ => return Err(recipe_err(field, format!("unit \"{unit}\" is not a rate unit (deg/s, rad/s, mrad/s, deg/h, counts)"))),
    })
}

fn angle_unit(unit: &str, field: &str) -> Result<f64> {
    Ok(match unit {
        "deg" => 1.0,
        "rad" => 180.0 / std::f64::consts::PI,
        _ => return Err(recipe_err(field, format!("unit \"{unit}\" is not an angle unit (deg, rad)"))),
    })
}

fn speed_unit(unit: &str, field: &str) -> Result<f64> {
    Ok(match unit {
        "m/s" => 1.0,
        "km/h" => 1.0 / 3.6,
        "mph" => 0.44704,
        _ => return Err(recipe_err(field, format!("unit \"{unit}\" is not a speed unit (m/s, km/h, mph)"))),
    })
}

fn time_unit(unit: &str) -> Result<f64> {
    Ok(match unit {
        "s" => 1.0,
        "ms" => 1e-3,
        "us" => 1e-6,
        "ns" => 1e-9,
        _ => return Err(recipe_err("table.time.unit", format!("\"{unit}\" is not a time unit (s, ms, us, ns)"))),
    })
}

/// Parses an ISO 8601 date-time (`YYYY-MM-DD[T ]hh:mm:ss[.fff][Z|±hh:mm]`) into seconds
/// since 1970-01-01 UTC; no offset means UTC.
pub fn parse_iso8601(s: &str) -> Option<f64> {
    let s = s.trim();
    let b = s.as_bytes();
    if b.len() < 19 || b[4] != b'-' || b[7] != b'-' || !(b[10] == b'T' || b[10] == b' ') || b[13] != b':' || b[16] != b':' {
        return None;
    }
    let num = |r: std::ops::Range<usize>| -> Option<i64> {
        let t = s.get(r)?;
        if t.bytes().all(|c| c.is_ascii_digit()) {
            t.parse().ok()
        } else {
            None
        }
    };
    let (y, mo, d) = (num(0..4)?, num(5..7)?, num(8..10)?);
    let (h, mi) = (num(11..13)?, num(14..16)?);
    if !(1..=12).contains(&mo) || !(1..=31).contains(&d) || h > 23 || mi > 59 {
        return None;
    }
    // Seconds with an optional fraction, then the zone.
    let rest = &s[17..];
    let end = rest.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(rest.len());
    let sec: f64 = rest[..end].parse().ok()?;
    if !(0.0..61.0).contains(&sec) {
        return None;
    }
    let zone = &rest[end..];
    let offset_s = match zone {
        "" | "Z" => 0,
        z if (z.starts_with('+') || z.starts_with('-')) && (z.len() == 6 || z.len() == 5 || z.len() == 3) => {
            let sign = if z.starts_with('-') { -1 } else { 1 };
            let digits: String = z[1..].chars().filter(|c| *c != ':').collect();
            if digits.len() != 4 && digits.len() != 2 || !digits.bytes().all(|c| c.is_ascii_digit()) {
                return None;
            }
            let zh: i64 = digits[..2].parse().ok()?;
            let zm: i64 = if digits.len() == 4 { digits[2..].parse().ok()? } else { 0 };
            sign * (zh * 3600 + zm * 60)
        }
        _ => return None,
    };
    // Days from civil (H. Hinnant's algorithm).
    let y2 = if mo <= 2 { y - 1 } else { y };
    let era = y2.div_euclid(400);
    let yoe = y2 - era * 400;
    let mp = (mo + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    let days = era * 146_097 + doe - 719_468;
    Some((days * 86_400 + h * 3600 + mi * 60 - offset_s) as f64 + sec)
}

/// Calls `row(line, fields)` for every data line after `skip_lines`, streaming: CSV and NMEA
/// through one `csv` reader (quotes, trimmed fields), whitespace files line by line.
fn for_each_row(spec: &TableSpec, reader: Box<dyn Read + '_>, row: &mut dyn FnMut(u64, &[&str]) -> Result<()>) -> Result<()> {
    let mut reader = BufReader::with_capacity(1 << 16, reader);
    let mut raw = Vec::new();
    let mut line_no: u64 = 0;
    for _ in 0..spec.skip_lines {
        raw.clear();
        if reader.read_until(b'\n', &mut raw)? == 0 {
            return Err(Error::File("the file ends within the skipped lines".into()));
        }
        line_no += 1;
    }
    match spec.format {
        TableFormat::Whitespace => loop {
            raw.clear();
            if reader.read_until(b'\n', &mut raw)? == 0 {
                return Ok(());
            }
            line_no += 1;
            if line_no == 1 && raw.starts_with(b"\xEF\xBB\xBF") {
                raw.drain(..3);
            }
            let text = std::str::from_utf8(&raw).map_err(|_| Error::Line { line: line_no, message: "not valid UTF-8 text".into() })?;
            let fields: Vec<&str> = text.split_whitespace().collect();
            if !fields.is_empty() {
                row(line_no, &fields)?;
            }
        },
        TableFormat::Csv | TableFormat::Nmea => {
            let mut rdr = csv::ReaderBuilder::new().has_headers(false).flexible(true).trim(csv::Trim::All).from_reader(reader);
            let mut rec = csv::StringRecord::new();
            loop {
                let more = rdr.read_record(&mut rec).map_err(|e| {
                    let line = e.position().map_or(0, |p| p.line()) + line_no;
                    match e.kind() {
                        csv::ErrorKind::Utf8 { .. } => Error::Line { line, message: "not valid UTF-8 text".into() },
                        _ => Error::Line { line, message: e.to_string() },
                    }
                })?;
                if !more {
                    return Ok(());
                }
                let line = line_no + rec.position().map_or(0, |p| p.line());
                let mut fields: Vec<&str> = rec.iter().collect();
                if fields.iter().all(|f| f.is_empty()) {
                    continue;
                }
                if spec.format == TableFormat::Nmea {
                    if let Some(last) = fields.last_mut() {
                        if let Some(star) = last.find('*') {
                            *last = &last[..star];
                        }
                    }
                }
                row(line, &fields)?;
            }
        }
    }
}

/// Reads the columns `wanted` (and the time) of one table, streaming.
fn read_table(spec: &TableSpec, wanted: &BTreeSet<String>, files: &mut dyn Files) -> Result<Table> {
    let file = spec.file.clone();
    let at = |e: Error| -> Error { e.within(&file) };
    let scale = time_unit(&spec.time.unit)?;
    if let Some(p) = spec.time.period_s {
        if !(p.is_finite() && p > 0.0) {
            return Err(recipe_err(&format!("table {} time.period_s", spec.id), format!("{p} is not a period > 0")));
        }
    } else if spec.time.column.is_none() {
        return Err(recipe_err(&format!("table {}", spec.id), "time needs a column or a period_s"));
    }
    let reader = files.open(&spec.file)?;
    let mut header: Option<Vec<String>> = spec.columns.clone();
    // Indices of the wanted columns and of the time, once the header is known.
    let mut idx: Vec<(String, usize)> = Vec::new();
    let mut time_idx: Option<usize> = None;
    let mut resolved = false;
    let time_name = spec.time.column.clone().unwrap_or_else(|| "time".into());
    let mut t = Table { file: file.clone(), time_s: Vec::new(), line: Vec::new(), cols: BTreeMap::new() };
    let mut cols: Vec<Vec<f64>> = Vec::new();
    let mut row_n: u64 = 0;
    let mut on_row = |line: u64, fields: &[&str]| -> Result<()> {
        let Some(h) = &header else {
            header = Some(fields.iter().map(|f| f.to_string()).collect());
            return Ok(());
        };
        if !resolved {
            let index_of = |name: &str| h.iter().position(|x| x == name);
            for name in wanted {
                match index_of(name) {
                    Some(j) => idx.push((name.clone(), j)),
                    None => {
                        return Err(Error::missing(
                            name,
                            &format!("named by the recipe for table {}; the header has: {}", spec.id, h.join(", ")),
                        ))
                    }
                }
            }
            if let Some(c) = &spec.time.column {
                time_idx = Some(index_of(c).ok_or_else(|| Error::missing(c, &format!("the time of table {}", spec.id)))?);
            }
            cols = vec![Vec::new(); idx.len()];
            resolved = true;
        }
        if let Some(rec) = &spec.record {
            if fields.first() != Some(&rec.as_str()) {
                return Ok(());
            }
        }
        let cell = |j: usize, name: &str| -> Result<f64> {
            let text = fields.get(j).copied().unwrap_or("");
            if text.is_empty() || text.eq_ignore_ascii_case("nan") {
                return Ok(f64::NAN);
            }
            match text.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(Error::Cell { line, column: name.to_string(), message: format!("\"{text}\" is not a number") }),
            }
        };
        let time = match (spec.time.period_s, time_idx) {
            (Some(p), _) => row_n as f64 * p,
            (None, Some(j)) => {
                let v = match spec.time.format {
                    TimeFormat::Seconds => cell(j, &time_name)? * scale,
                    TimeFormat::Iso8601 => {
                        let text = fields.get(j).copied().unwrap_or("");
                        parse_iso8601(text).ok_or_else(|| Error::Cell {
                            line,
                            column: time_name.clone(),
                            message: format!("\"{text}\" is not an ISO 8601 time"),
                        })?
                    }
                };
                if v.is_nan() {
                    return Err(Error::Cell { line, column: time_name.clone(), message: "empty time".into() });
                }
                v
            }
            (None, None) => return Err(recipe_err(&format!("table {}", spec.id), "time needs a column or a period_s")),
        };
        if let Some(&prev) = t.time_s.last() {
            if !(time > prev) {
                return Err(Error::Cell {
                    line,
                    column: time_name.clone(),
                    message: format!("time {time} does not increase (previous row {prev})"),
                });
            }
        }
        for (k, (name, j)) in idx.iter().enumerate() {
            cols[k].push(cell(*j, name)?);
        }
        t.time_s.push(time);
        t.line.push(line);
        row_n += 1;
        Ok(())
    };
    for_each_row(spec, reader, &mut on_row).map_err(at)?;
    if header.is_none() {
        return Err(at(Error::File("empty file: no header row".into())));
    }
    if t.time_s.is_empty() {
        return Err(at(Error::File(format!("table {} has no data rows", spec.id))));
    }
    let first = t.time_s[0];
    for x in t.time_s.iter_mut() {
        if spec.time.relative {
            *x -= first;
        }
        *x += spec.offset_s;
    }
    for ((name, _), v) in idx.into_iter().zip(cols) {
        t.cols.insert(name, v);
    }
    Ok(t)
}

/// Times, yaw rates (deg/s, CCW positive) and, when projected, the up vector.
type YawRate = (Vec<f64>, Vec<f64>, Option<[f64; 3]>);

/// The yaw rate of a table in deg/s, CCW positive (and the up vector when projected).
fn yaw_rate(spec: &RateSpec, tables: &BTreeMap<String, Table>, field: &str) -> Result<YawRate> {
    let t = tables.get(&spec.table).ok_or_else(|| recipe_err(&format!("{field}.table"), format!("no table with id \"{}\"", spec.table)))?;
    let unit = rate_unit(&spec.unit, &format!("{field}.unit"))?;
    if !(spec.scale.is_finite() && spec.scale != 0.0 && spec.offset.is_finite()) {
        return Err(recipe_err(&format!("{field}.scale"), "scale must be finite and non-zero, offset finite"));
    }
    let k = unit * spec.scale * spec.sense_factor();
    let conv = |x: f64| (x - spec.offset) * k;
    match (&spec.column, &spec.axes, &spec.gravity) {
        (Some(c), None, None) => {
            let v = t.col(c, field)?;
            Ok((t.time_s.clone(), v.iter().map(|&x| conv(x)).collect(), None))
        }
        (None, Some(axes), Some(g)) => {
            if axes.len() != 3 || g.axes.len() != 3 {
                return Err(recipe_err(field, "axes and gravity.axes need three columns each"));
            }
            let gyro: Vec<&[f64]> = axes.iter().map(|a| t.col(a, field)).collect::<Result<_>>()?;
            let signs = |v: &Option<Vec<f64>>, f: &str| -> Result<[f64; 3]> {
                match v {
                    None => Ok([1.0; 3]),
                    Some(v) if v.len() == 3 && v.iter().all(|x| *x == 1.0 || *x == -1.0) => Ok([v[0], v[1], v[2]]),
                    Some(_) => Err(recipe_err(f, "needs three factors, each 1 or -1")),
                }
            };
            let gs = signs(&spec.signs, &format!("{field}.signs"))?;
            let acs = signs(&g.signs, &format!("{field}.gravity.signs"))?;
            let acc: Vec<&[f64]> = g.axes.iter().map(|a| t.col(a, &format!("{field}.gravity"))).collect::<Result<_>>()?;
            let t0 = t.time_s[0];
            let mut m = [0.0; 3];
            let mut n = 0usize;
            for i in 0..t.time_s.len() {
                if t.time_s[i] - t0 >= g.first_s {
                    break;
                }
                let a = [acc[0][i] * acs[0], acc[1][i] * acs[1], acc[2][i] * acs[2]];
                if a.iter().all(|x| x.is_finite()) {
                    for j in 0..3 {
                        m[j] += a[j];
                    }
                    n += 1;
                }
            }
            let norm = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
            if n == 0 || norm == 0.0 {
                return Err(Error::data(format!(
                    "{}: no accelerometer values in the first {} s to find the up direction",
                    t.file, g.first_s
                )));
            }
            let up = [m[0] / norm, m[1] / norm, m[2] / norm];
            let rate = (0..t.time_s.len()).map(|i| (0..3).map(|j| conv(gyro[j][i]) * gs[j] * up[j]).sum::<f64>()).collect();
            Ok((t.time_s.clone(), rate, Some(up)))
        }
        _ => Err(recipe_err(field, "give either `column` (one axis) or `axes` with `gravity` (projection on up)")),
    }
}

impl RateSpec {
    fn sense_factor(&self) -> f64 {
        self.positive.factor()
    }
}

/// Local east/north (m) of positions, relative to the first valid one.
fn local_en(spec: &PositionsSpec, t: &Table) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let need = match spec.kind {
        PositionKind::Ecef => 3,
        _ => 2,
    };
    if spec.columns.len() != need {
        return Err(recipe_err("positions.columns", format!("{:?} positions need {need} columns", spec.kind)));
    }
    let c: Vec<&[f64]> = spec.columns.iter().map(|n| t.col(n, "positions")).collect::<Result<_>>()?;
    let mut time = Vec::new();
    let (mut e, mut nn) = (Vec::new(), Vec::new());
    let first = (0..t.time_s.len()).find(|&i| (0..need).all(|j| c[j][i].is_finite()));
    let Some(i0) = first else {
        return Err(Error::data(format!("{}: no complete position", t.file)));
    };
    // WGS84
    const A: f64 = 6_378_137.0;
    const E2: f64 = 6.694_379_990_14e-3;
    let (lat0, lon0) = match spec.kind {
        PositionKind::Latlon => (c[0][i0].to_radians(), c[1][i0].to_radians()),
        PositionKind::Ecef => {
            let (x, y, z) = (c[0][i0], c[1][i0], c[2][i0]);
            let p = (x * x + y * y).sqrt();
            let mut lat = libm::atan2(z, p * (1.0 - E2));
            for _ in 0..5 {
                let s = libm::sin(lat);
                let n = A / (1.0 - E2 * s * s).sqrt();
                lat = libm::atan2(z + E2 * n * s, p);
            }
            (lat, libm::atan2(y, x))
        }
        _ => (0.0, 0.0),
    };
    let s2 = libm::sin(lat0) * libm::sin(lat0);
    let r_n = A / (1.0 - E2 * s2).sqrt(); // prime vertical
    let r_m = A * (1.0 - E2) / libm::pow(1.0 - E2 * s2, 1.5); // meridional
    for i in 0..t.time_s.len() {
        if !(0..need).all(|j| c[j][i].is_finite()) {
            continue;
        }
        let (de, dn) = match spec.kind {
            PositionKind::Latlon => ((c[1][i].to_radians() - lon0) * r_n * libm::cos(lat0), (c[0][i].to_radians() - lat0) * r_m),
            PositionKind::Utm | PositionKind::Enu => (c[0][i] - c[0][i0], c[1][i] - c[1][i0]),
            PositionKind::Ecef => {
                let d = [c[0][i] - c[0][i0], c[1][i] - c[1][i0], c[2][i] - c[2][i0]];
                let (sl, cl, so, co) = (libm::sin(lat0), libm::cos(lat0), libm::sin(lon0), libm::cos(lon0));
                (-so * d[0] + co * d[1], -sl * co * d[0] - sl * so * d[1] + cl * d[2])
            }
        };
        time.push(t.time_s[i]);
        e.push(de);
        nn.push(dn);
    }
    Ok((time, e, nn))
}

/// Course over ground (deg, clockwise from north) between positions at least
/// `min_distance_m` apart, stamped at the segment's middle; segments slower than
/// `min_speed_mps` restart the anchor without a sample.
pub fn course_from_positions(
    time_s: &[f64],
    east_m: &[f64],
    north_m: &[f64],
    min_distance_m: f64,
    min_speed_mps: f64,
) -> (Vec<f64>, Vec<f64>) {
    let (mut ts, mut course) = (Vec::new(), Vec::new());
    let mut a = 0usize;
    for i in 1..time_s.len() {
        let (de, dn) = (east_m[i] - east_m[a], north_m[i] - north_m[a]);
        let d = (de * de + dn * dn).sqrt();
        if d >= min_distance_m {
            let dt = time_s[i] - time_s[a];
            if d / dt >= min_speed_mps {
                ts.push(0.5 * (time_s[i] + time_s[a]));
                course.push(libm::atan2(de, dn).to_degrees());
            }
            a = i;
        } else if time_s[i] - time_s[a] > min_distance_m / min_speed_mps.max(1e-3) {
            // Too slow to reach the distance at the minimum speed: restart here.
            a = i;
        }
    }
    (ts, course)
}

/// Speed (m/s) from positions: distance to the last position at least `window_s` earlier.
pub fn speed_from_positions(time_s: &[f64], east_m: &[f64], north_m: &[f64], window_s: f64) -> (Vec<f64>, Vec<f64>) {
    let (mut ts, mut v) = (Vec::new(), Vec::new());
    let mut k = 0usize;
    for i in 0..time_s.len() {
        while k + 1 < i && time_s[k + 1] <= time_s[i] - window_s {
            k += 1;
        }
        let dt = time_s[i] - time_s[k];
        if i > k && dt >= window_s {
            let (de, dn) = (east_m[i] - east_m[k], north_m[i] - north_m[k]);
            ts.push(time_s[i]);
            v.push((de * de + dn * dn).sqrt() / dt);
        }
    }
    (ts, v)
}

/// Cumulative travel (m) from speeds (m/s) by the trapezoid rule; empty cells are skipped.
pub fn integrate_speed(time_s: &[f64], speed_mps: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(time_s.len());
    let mut acc = 0.0;
    let mut prev: Option<(f64, f64)> = None;
    for (&t, &v) in time_s.iter().zip(speed_mps) {
        if v.is_finite() {
            if let Some((tp, vp)) = prev {
                acc += 0.5 * (v + vp) * (t - tp);
            }
            prev = Some((t, v));
            out.push(acc);
        } else {
            out.push(f64::NAN);
        }
    }
    out
}

/// Linear interpolation of the finite samples (ts, vs) at each of the increasing times
/// `at` (the metrics' rule, `metrics::interp_at`); NaN outside their span.
pub fn interpolate(ts: &[f64], vs: &[f64], at: &[f64]) -> Vec<f64> {
    let (pt, pv): (Vec<f64>, Vec<f64>) = ts.iter().zip(vs).filter(|(_, v)| v.is_finite()).map(|(&t, &v)| (t, v)).unzip();
    let mut j = 0usize;
    at.iter()
        .map(|&t| match (pt.first(), pt.last()) {
            (Some(&a), Some(&b)) if t >= a && t <= b => {
                while j + 1 < pt.len() && pt[j + 1] <= t {
                    j += 1;
                }
                crate::metrics::interp_at(&pt, &pv, j, t)
            }
            _ => f64::NAN,
        })
        .collect()
}

/// Means of (ts, vs) in bins of `dt` from `t0`, NaN where a bin is empty.
fn bin_means(ts: &[f64], vs: &[f64], t0: f64, dt: f64, n: usize) -> Vec<f64> {
    let mut sum = vec![0.0; n];
    let mut cnt = vec![0usize; n];
    for (&t, &v) in ts.iter().zip(vs) {
        let k = ((t - t0) / dt).floor();
        if v.is_finite() && k >= 0.0 && (k as usize) < n {
            sum[k as usize] += v;
            cnt[k as usize] += 1;
        }
    }
    sum.iter().zip(&cnt).map(|(&s, &c)| if c > 0 { s / c as f64 } else { f64::NAN }).collect()
}

/// The lag (s) to add to series a's times so that it best matches series b: the maximum
/// of the normalised cross-correlation on a 20 Hz grid, refined by a parabola.
pub fn best_lag_s(ta: &[f64], a: &[f64], tb: &[f64], b: &[f64], max_lag_s: f64) -> Result<f64> {
    const DT: f64 = 0.05;
    let (Some(&b0), Some(&b1)) = (tb.first(), tb.last()) else {
        return Err(Error::data("alignment: the reference rate is empty"));
    };
    if !(max_lag_s.is_finite() && max_lag_s > 0.0 && max_lag_s <= 600.0) {
        return Err(recipe_err("align.max_lag_s", format!("{max_lag_s} is not a lag in (0, 600] s")));
    }
    // 20 Hz bins over the reference: a span of days means a wrong time unit, not a drive.
    if !(b1 - b0 <= 86_400.0) {
        return Err(Error::data(format!("alignment: the reference rate spans {} s (over a day): check the time units", b1 - b0)));
    }
    let n = ((b1 - b0) / DT).floor() as usize + 1;
    let gb = bin_means(tb, b, b0, DT, n);
    let max_k = (max_lag_s / DT).round() as i64;
    let mut best = (f64::NEG_INFINITY, 0i64);
    let mut scores = BTreeMap::new();
    for k in -max_k..=max_k {
        let shifted: Vec<f64> = ta.iter().map(|&t| t + k as f64 * DT).collect();
        let ga = bin_means(&shifted, a, b0, DT, n);
        let (mut sab, mut saa, mut sbb, mut sa, mut sb, mut m) = (0.0, 0.0, 0.0, 0.0, 0.0, 0usize);
        for (x, y) in ga.iter().zip(&gb) {
            if x.is_finite() && y.is_finite() {
                sab += x * y;
                saa += x * x;
                sbb += y * y;
                sa += x;
                sb += y;
                m += 1;
            }
        }
        if m < 100 {
            continue;
        }
        let mf = m as f64;
        let cov = sab - sa * sb / mf;
        let den = ((saa - sa * sa / mf) * (sbb - sb * sb / mf)).sqrt();
        let r = if den > 0.0 { cov / den } else { 0.0 };
        scores.insert(k, r);
        if r > best.0 {
            best = (r, k);
        }
    }
    if !best.0.is_finite() {
        return Err(Error::data("alignment: the gyro and the reference rate do not overlap by 5 s at any lag"));
    }
    let k = best.1;
    let (ym, y0, yp) = (scores.get(&(k - 1)), Some(best.0), scores.get(&(k + 1)));
    let frac = match (ym, y0, yp) {
        (Some(&ym), Some(y0), Some(&yp)) if ym - 2.0 * y0 + yp < 0.0 => 0.5 * (ym - yp) / (ym - 2.0 * y0 + yp),
        _ => 0.0,
    };
    Ok((k as f64 + frac) * DT)
}

/// Runs a recipe: reads the tables, derives the channels, merges on time.
pub fn import(recipe: &Recipe, files: &mut dyn Files) -> Result<(DriveLog, ImportSummary)> {
    if recipe.tables.is_empty() {
        return Err(recipe_err("table", "at least one [[table]] is needed"));
    }
    // Which columns each table must provide.
    let mut wanted: BTreeMap<String, BTreeSet<String>> = recipe.tables.iter().map(|t| (t.id.clone(), BTreeSet::new())).collect();
    let mut want = |table: &str, cols: &[&String], field: &str| -> Result<()> {
        let set =
            wanted.get_mut(table).ok_or_else(|| recipe_err(&format!("{field}.table"), format!("no [[table]] with id \"{table}\"")))?;
        set.extend(cols.iter().map(|c| (*c).clone()));
        Ok(())
    };
    let rate_cols = |r: &RateSpec| -> Vec<String> {
        let mut v: Vec<String> = r.column.iter().cloned().collect();
        v.extend(r.axes.iter().flatten().cloned());
        v.extend(r.gravity.iter().flat_map(|g| g.axes.iter().cloned()));
        v
    };
    let rc = rate_cols(&recipe.yaw_rate);
    want(&recipe.yaw_rate.table, &rc.iter().collect::<Vec<_>>(), "yaw_rate")?;
    if let Some(a) = &recipe.align {
        let c = rate_cols(&a.rate);
        want(&a.rate.table, &c.iter().collect::<Vec<_>>(), "align.rate")?;
    }
    if let Some(p) = &recipe.positions {
        want(&p.table, &p.columns.iter().collect::<Vec<_>>(), "positions")?;
    }
    match &recipe.heading {
        Some(HeadingSpec::Column { table, column, speed_column, .. }) => {
            let mut c = vec![column];
            c.extend(speed_column.iter());
            want(table, &c, "heading")?;
        }
        Some(HeadingSpec::Positions { .. }) if recipe.positions.is_none() => {
            return Err(recipe_err("heading", "source = \"positions\" needs a [positions] section"));
        }
        _ => {}
    }
    match &recipe.speed {
        Some(SpeedSpec::Column { table, column, .. }) => want(table, &[column], "speed")?,
        Some(SpeedSpec::Positions { .. }) if recipe.positions.is_none() => {
            return Err(recipe_err("speed", "source = \"positions\" needs a [positions] section"));
        }
        _ => {}
    }
    if let Some(o) = &recipe.odometry {
        want(&o.table, &o.left.iter().chain(&o.right).collect::<Vec<_>>(), "odometry")?;
    }
    if let Some(v) = &recipe.temperature {
        want(&v.table, &[&v.column], "temperature")?;
    }

    let mut tables = BTreeMap::new();
    for spec in &recipe.tables {
        if tables.contains_key(&spec.id) {
            return Err(recipe_err("table.id", format!("\"{}\" is used twice", spec.id)));
        }
        let t = read_table(spec, &wanted[&spec.id], files)?;
        tables.insert(spec.id.clone(), t);
    }

    let (mut gyro_t, gyro_v, up) = yaw_rate(&recipe.yaw_rate, &tables, "yaw_rate")?;
    let mut align_offset = None;
    if let Some(a) = &recipe.align {
        let (rt, rv, _) = yaw_rate(&a.rate, &tables, "align.rate")?;
        let lag = best_lag_s(&gyro_t, &gyro_v, &rt, &rv, a.max_lag_s)?;
        gyro_t.iter_mut().for_each(|t| *t += lag);
        align_offset = Some(lag);
    }

    // Reference heading, deg CCW (time, value).
    let mut positions = None;
    if let Some(p) = &recipe.positions {
        let t = tables.get(&p.table).ok_or_else(|| recipe_err("positions.table", format!("no table \"{}\"", p.table)))?;
        positions = Some(local_en(p, t)?);
    }
    let (ref_t, ref_v) = match &recipe.heading {
        None => (Vec::new(), Vec::new()),
        Some(HeadingSpec::Column { table, column, unit, positive, speed_column, min_speed_mps }) => {
            let t = &tables[table];
            let k = angle_unit(unit, "heading.unit")? * positive.factor();
            let v = t.col(column, "heading")?;
            let s = match speed_column {
                Some(c) => Some(t.col(c, "heading.speed_column")?),
                None => None,
            };
            let (mut ts, mut vs) = (Vec::new(), Vec::new());
            for i in 0..t.time_s.len() {
                let moving = s.is_none_or(|s| s[i] >= *min_speed_mps);
                if v[i].is_finite() && moving {
                    ts.push(t.time_s[i]);
                    vs.push(crate::metrics::wrap_diff_deg(v[i] * k));
                }
            }
            (ts, vs)
        }
        Some(HeadingSpec::Positions { min_distance_m, min_speed_mps }) => {
            if !(min_distance_m.is_finite() && *min_distance_m > 0.0 && min_speed_mps.is_finite() && *min_speed_mps >= 0.0) {
                return Err(recipe_err("heading", "min_distance_m must be > 0 and min_speed_mps >= 0"));
            }
            let (pt, e, n) = positions.as_ref().ok_or_else(|| recipe_err("heading", "needs [positions]"))?;
            let (ts, course) = course_from_positions(pt, e, n, *min_distance_m, *min_speed_mps);
            (ts, course.iter().map(|c| crate::metrics::wrap_diff_deg(-c)).collect())
        }
    };
    let speed: Option<(Vec<f64>, Vec<f64>)> = match &recipe.speed {
        None => None,
        Some(SpeedSpec::Column { table, column, unit }) => {
            let t = &tables[table];
            let k = speed_unit(unit, "speed.unit")?;
            Some((t.time_s.clone(), t.col(column, "speed")?.iter().map(|v| v * k).collect()))
        }
        Some(SpeedSpec::Positions { window_s }) => {
            if !(window_s.is_finite() && *window_s > 0.0) {
                return Err(recipe_err("speed.window_s", format!("{window_s} is not a time > 0")));
            }
            let (pt, e, n) = positions.as_ref().ok_or_else(|| recipe_err("speed", "needs [positions]"))?;
            Some(speed_from_positions(pt, e, n, *window_s))
        }
    };
    let odo: Option<(Vec<f64>, Vec<f64>, Vec<f64>)> = match &recipe.odometry {
        None => None,
        Some(o) => {
            if !(o.track_m.is_finite() && o.track_m > 0.0) {
                return Err(recipe_err("odometry.track_m", format!("{} is not a distance > 0", o.track_m)));
            }
            if o.left.is_empty() || o.right.is_empty() {
                return Err(recipe_err("odometry", "left and right need one column or more each"));
            }
            let t = &tables[&o.table];
            let k = match o.kind {
                OdometryKind::Speed => speed_unit(&o.unit, "odometry.unit")?,
                OdometryKind::Travel => match o.unit.as_str() {
                    "m" => 1.0,
                    "km" => 1000.0,
                    u => return Err(recipe_err("odometry.unit", format!("\"{u}\" is not a distance unit (m, km)"))),
                },
            };
            let side = |cols: &[String]| -> Result<Vec<f64>> {
                let c: Vec<&[f64]> = cols.iter().map(|n| t.col(n, "odometry")).collect::<Result<_>>()?;
                let mean: Vec<f64> = (0..t.time_s.len()).map(|i| c.iter().map(|c| c[i]).sum::<f64>() / c.len() as f64 * k).collect();
                Ok(match o.kind {
                    OdometryKind::Speed => integrate_speed(&t.time_s, &mean),
                    OdometryKind::Travel => mean,
                })
            };
            Some((t.time_s.clone(), side(&o.left)?, side(&o.right)?))
        }
    };
    let temp: Option<(Vec<f64>, Vec<f64>)> = match &recipe.temperature {
        None => None,
        Some(v) => {
            let t = &tables[&v.table];
            let c = t.col(&v.column, "temperature")?;
            let conv: fn(f64) -> f64 = match v.unit.as_str() {
                "C" | "degC" => |x| x,
                "K" => |x| x - 273.15,
                "F" => |x| (x - 32.0) / 1.8,
                u => return Err(recipe_err("temperature.unit", format!("\"{u}\" is not a temperature unit (C, K, F)"))),
            };
            Some((t.time_s.clone(), c.iter().map(|&x| conv(x)).collect()))
        }
    };

    // Rows: the gyro samples and the reference samples inside the gyro's span, on one time line.
    let (g0, g1) = (gyro_t[0], gyro_t[gyro_t.len() - 1]);
    let mut rows: Vec<(f64, f64, f64)> = gyro_t.iter().zip(&gyro_v).map(|(&t, &v)| (t, v, f64::NAN)).collect();
    rows.extend(ref_t.iter().zip(&ref_v).filter(|(&t, _)| t >= g0 && t <= g1).map(|(&t, &v)| (t, f64::NAN, v)));
    rows.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut merged: Vec<(f64, f64, f64)> = Vec::with_capacity(rows.len());
    for r in rows {
        match merged.last_mut() {
            Some(last) if last.0 == r.0 => {
                if r.1.is_finite() {
                    last.1 = r.1;
                }
                if r.2.is_finite() {
                    last.2 = r.2;
                }
            }
            _ => merged.push(r),
        }
    }
    let times: Vec<f64> = merged.iter().map(|r| r.0).collect();
    let mut data: Vec<(Column, Vec<f64>)> = vec![(Column::GyroDps, merged.iter().map(|r| r.1).collect())];
    if recipe.heading.is_some() {
        data.push((Column::RefHeadingDeg, merged.iter().map(|r| r.2).collect()));
    }
    if let Some((ts, vs)) = &speed {
        data.push((Column::SpeedMps, interpolate(ts, vs, &times)));
    }
    if let Some((ts, l, r)) = &odo {
        data.push((Column::OdoLeftM, interpolate(ts, l, &times)));
        data.push((Column::OdoRightM, interpolate(ts, r, &times)));
    }
    if let Some((ts, vs)) = &temp {
        data.push((Column::TempC, interpolate(ts, vs, &times)));
    }
    let start = g0;
    let mut columns = vec![(Column::TimeS, times.iter().map(|t| t - start).collect::<Vec<f64>>())];
    columns.extend(data);
    if let Some([a, b]) = recipe.span_s {
        if !(a.is_finite() && b.is_finite() && a < b) {
            return Err(recipe_err("span_s", format!("[{a}, {b}] is not a time span (start < end)")));
        }
        let keep: Vec<bool> = columns[0].1.iter().map(|&t| t >= a && t <= b).collect();
        for (_, v) in columns.iter_mut() {
            let mut k = keep.iter();
            v.retain(|_| *k.next().unwrap_or(&false));
        }
        if columns[0].1.is_empty() {
            return Err(Error::data(format!("span_s [{a}, {b}] keeps no rows: the log spans {} s", g1 - g0)));
        }
    }
    // Equal times after the shift to 0 are impossible (the shift is exact for distinct
    // doubles only up to rounding): merge rows that collapse.
    let (columns, _) = dedup_rows(columns);
    let mut meta = LogMeta {
        name: recipe.name.clone(),
        description: recipe.description.clone(),
        bias_s: recipe.bias_s,
        wheelbase_m: recipe.odometry.as_ref().map(|o| o.track_m),
        ..LogMeta::default()
    };
    meta.other.insert("source_start_time_s".into(), format!("{start}"));
    if let Some(lag) = align_offset {
        meta.other.insert("align_offset_s".into(), format!("{lag}"));
    }
    let log = DriveLog::from_columns(meta, Vec::new(), columns)?;
    let finite = |c: Column| log.column(c).map_or(0, |v| v.iter().filter(|x| x.is_finite()).count());
    let n_reference = finite(Column::RefHeadingDeg);
    let summary = ImportSummary {
        n_rows: log.len(),
        n_gyro: finite(Column::GyroDps),
        n_reference,
        duration_min: log.duration_min(),
        up,
        align_offset_s: align_offset,
        start_time_s: start,
    };
    Ok((log, summary))
}

/// Merges consecutive rows whose time became equal (keeping the finite cells).
fn dedup_rows(columns: Vec<(Column, Vec<f64>)>) -> (Vec<(Column, Vec<f64>)>, usize) {
    let t = &columns[0].1;
    let keep: Vec<usize> = (0..t.len()).filter(|&i| i + 1 == t.len() || t[i + 1] > t[i]).collect();
    if keep.len() == t.len() {
        let n = t.len();
        return (columns, n);
    }
    let n = keep.len();
    let out = columns
        .into_iter()
        .map(|(c, v)| {
            let mut w = Vec::with_capacity(n);
            let mut start = 0usize;
            for &i in &keep {
                let cell = (start..=i).rev().map(|j| v[j]).find(|x| x.is_finite()).unwrap_or(f64::NAN);
                w.push(if c == Column::TimeS { v[i] } else { cell });
                start = i + 1;
            }
            (c, w)
        })
        .collect();
    (out, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn iso8601_hand_worked() {
        assert_eq!(parse_iso8601("1970-01-01T00:00:00Z"), Some(0.0));
        assert_eq!(parse_iso8601("1970-01-02 00:00:01"), Some(86_401.0));
        // 2000-03-01 = day 11017 since the epoch (leap year 2000: Feb has 29 days).
        assert_eq!(parse_iso8601("2000-03-01T00:00:00Z"), Some(11_017.0 * 86_400.0));
        // 10:48:05 at -04:00 is 14:48:05 UTC; 2023-08-06 is day 19575.
        assert_eq!(parse_iso8601("2023-08-06 10:48:05-04:00"), Some(19_575.0 * 86_400.0 + 14.0 * 3600.0 + 48.0 * 60.0 + 5.0));
        assert_eq!(parse_iso8601("2023-08-06T10:48:05.25+0130"), Some(19_575.0 * 86_400.0 + 9.0 * 3600.0 + 18.0 * 60.0 + 5.25));
        for bad in ["", "2023-08-06", "2023-13-06 10:48:05", "2023-08-06 10:48:05+4", "2023-08-06X10:48:05", "abcd-08-06 10:48:05"] {
            assert_eq!(parse_iso8601(bad), None, "{bad}");
        }
    }

    #[test]
    fn course_from_positions_hand_worked() {
        // East 3 m per second: course 90 deg, stamped at segment middles.
        let t = [0.0, 1.0, 2.0, 3.0];
        let e = [0.0, 3.0, 6.0, 6.0 + 3.0 * 0.5f64.sqrt()];
        let n = [0.0, 0.0, 0.0, -3.0 * 0.5f64.sqrt()];
        let (ts, c) = course_from_positions(&t, &e, &n, 2.0, 1.0);
        assert_eq!(ts, vec![0.5, 1.5, 2.5]);
        assert!((c[0] - 90.0).abs() < 1e-12 && (c[1] - 90.0).abs() < 1e-12);
        assert!((c[2] - 135.0).abs() < 1e-9, "south-east: {}", c[2]);
        // Standing still (below 2 m): no course at all.
        let (ts, _) = course_from_positions(&t, &[0.0, 0.5, 0.2, 0.9], &[0.0; 4], 2.0, 1.0);
        assert!(ts.is_empty());
    }

    #[test]
    fn speed_and_odometry_hand_worked() {
        let t = [0.0, 0.5, 1.0, 2.0];
        let (ts, v) = speed_from_positions(&t, &[0.0, 1.0, 2.0, 6.0], &[0.0; 4], 1.0);
        assert_eq!(ts, vec![1.0, 2.0]);
        assert_eq!(v, vec![2.0, 4.0]);
        // Trapezoid: 0.5*(2+4)*1 = 3, + 0.5*(4+4)*2 = 8 -> 11.
        assert_eq!(integrate_speed(&[0.0, 1.0, 3.0], &[2.0, 4.0, 4.0]), vec![0.0, 3.0, 11.0]);
        assert_eq!(interpolate(&[0.0, 2.0], &[0.0, 4.0], &[-1.0, 0.5, 2.0, 3.0])[1..3], [1.0, 4.0]);
        assert!(interpolate(&[0.0, 2.0], &[0.0, 4.0], &[-1.0])[0].is_nan());
    }

    fn recipe() -> Recipe {
        let text = r#"{"table": [{"id": "a", "file": "a.csv", "time": {"column": "t"}},
                                {"id": "b", "file": "b.txt", "format": "whitespace", "columns": ["t", "x", "y"], "time": {"column": "t"}}],
            "yaw_rate": {"table": "a", "column": "w", "unit": "rad/s", "positive": "cw"},
            "positions": {"table": "b", "kind": "utm", "columns": ["x", "y"]},
            "heading": {"source": "positions"}, "speed": {"source": "positions"},
            "align": {"rate": {"table": "a", "column": "w", "unit": "deg/s", "positive": "ccw"}}}"#;
        serde_json::from_str(text).unwrap()
    }

    #[test]
    fn a_bad_cell_keeps_its_line_and_column_under_the_file_name() {
        let mut files = BTreeMap::new();
        files.insert("a.csv".to_string(), b"t,w\n0,1\n1,x\n".to_vec());
        files.insert("b.txt".to_string(), b"0 0 0\n1 0 0\n".to_vec());
        let e = import(&recipe(), &mut files).unwrap_err();
        match &e {
            Error::In { name, source } => {
                assert_eq!(name, "a.csv");
                assert!(matches!(**source, Error::Cell { line: 3, ref column, .. } if column == "w"), "{source:?}");
            }
            other => panic!("not wrapped in the file name: {other:?}"),
        }
        assert!(e.to_string().starts_with("a.csv: line 3, column w: "), "{e}");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]
        /// Arbitrary bytes in either file: an error or a log, never a panic.
        #[test]
        fn import_never_panics(a in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..400),
                               b in "[0-9 .\\-e\n]{0,300}") {
            let mut files = BTreeMap::new();
            let mut a_csv = b"t,w\n".to_vec();
            a_csv.extend(&a);
            files.insert("a.csv".to_string(), a_csv);
            files.insert("b.txt".to_string(), b.into_bytes());
            let _ = import(&recipe(), &mut files);
        }

        /// CSV-shaped rows with odd numbers (huge, tiny, negative times).
        #[test]
        fn import_numbers_never_panic(rows in proptest::collection::vec((-1e12f64..1e12, -1e6f64..1e6), 0..60)) {
            let mut a = String::from("t,w\n");
            let mut b = String::new();
            for (i, (t, w)) in rows.iter().enumerate() {
                a.push_str(&format!("{t},{w}\n"));
                b.push_str(&format!("{} {} {}\n", t + i as f64, w, -w));
            }
            let mut files = BTreeMap::new();
            files.insert("a.csv".to_string(), a.into_bytes());
            files.insert("b.txt".to_string(), b.into_bytes());
            let _ = import(&recipe(), &mut files);
        }
    }

    #[test]
    fn best_lag_finds_a_known_shift() {
        // b(t) = a(t - 1.3): a must be shifted by +1.3 s.
        let f = |t: f64| (t * 0.7).sin() + (t * 2.3).sin() * 0.5 + if (t as i64) % 7 == 0 { 1.0 } else { 0.0 };
        let ta: Vec<f64> = (0..4000).map(|i| i as f64 * 0.01).collect();
        let a: Vec<f64> = ta.iter().map(|&t| f(t)).collect();
        let b: Vec<f64> = ta.iter().map(|&t| f(t - 1.3)).collect();
        let lag = best_lag_s(&ta, &a, &ta, &b, 5.0).unwrap();
        assert!((lag - 1.3).abs() < 0.03, "{lag}");
    }
}
