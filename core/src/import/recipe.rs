//! The recipe: which files and columns, units, signs, time formats, and how the reference
//! heading, speed and wheel travel are obtained; the input files; the import summary.

use super::*;

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

impl Recipe {
    /// How its tables' file names end (".txt", ".csv"; lower case, each once): what a fleet
    /// folder's files must end with to be read by it.
    pub fn file_endings(&self) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for t in &self.tables {
            let ext = std::path::Path::new(&t.file).extension().map(|e| format!(".{}", e.to_string_lossy().to_ascii_lowercase()));
            if let Some(e) = ext.filter(|e| !out.contains(e)) {
                out.push(e);
            }
        }
        out
    }

    /// What can be checked before any file is opened: metadata text, numbers finite and in
    /// range, time given one way per table.
    pub fn validate(&self) -> Result<()> {
        for (k, v) in [("name", &self.name), ("description", &self.description)] {
            if let Some(v) = v {
                crate::log::check_meta_text(k, v).map_err(|_| recipe_err(k, "contains a line break or another control character"))?;
            }
        }
        if let Some(b) = self.bias_s.filter(|b| !(b.is_finite() && *b >= 0.0)) {
            return Err(recipe_err("bias_s", format!("{b} is not a time >= 0 s")));
        }
        for t in &self.tables {
            let at = |f: &str| format!("table {} {f}", t.id);
            if !t.offset_s.is_finite() {
                return Err(recipe_err(&at("offset_s"), format!("{} is not a finite time", t.offset_s)));
            }
            match (t.time.column.is_some(), t.time.period_s) {
                // A GPX table is timed by its points' own <time>.
                (true, _) | (_, Some(_)) if t.format == TableFormat::Gpx => {
                    return Err(recipe_err(&at("time"), "a GPX table is timed by its points' <time>: no column or period_s"))
                }
                _ if t.format == TableFormat::Gpx => {}
                (true, Some(_)) => return Err(recipe_err(&at("time"), "give a column or a period_s, not both")),
                (false, None) => return Err(recipe_err(&at("time"), "needs a column or a period_s")),
                (_, Some(p)) if !(p.is_finite() && p > 0.0) => {
                    return Err(recipe_err(&at("time.period_s"), format!("{p} is not a period > 0")))
                }
                _ => {}
            }
            if !matches!(t.delimiter, ',' | ';' | '\t' | '|') {
                return Err(recipe_err(&at("delimiter"), format!("{:?} is not one of \",\" \";\" \"\\t\" \"|\"", t.delimiter)));
            }
            if t.decimal_comma && t.delimiter == ',' {
                return Err(recipe_err(&at("decimal_comma"), "needs a delimiter other than \",\""));
            }
            if !(t.time.max_backward_s.is_finite() && (0.0..=3600.0).contains(&t.time.max_backward_s)) {
                return Err(recipe_err(&at("time.max_backward_s"), format!("{} is not a time in [0, 3600] s", t.time.max_backward_s)));
            }
        }
        if let Some([a, b]) = self.span_s {
            if !(a.is_finite() && b.is_finite() && a < b) {
                return Err(recipe_err("span_s", format!("[{a}, {b}] is not a time span (start < end)")));
            }
        }
        Ok(())
    }
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
    /// Field separator of a `csv` table: `,` (default), `;`, tab or `|`.
    #[serde(default = "default_delimiter")]
    pub delimiter: char,
    /// Numbers written with a decimal comma (`0,25`), as European spreadsheets and phyphox's
    /// "semicolon, decimal comma" export do.
    #[serde(default)]
    pub decimal_comma: bool,
    /// Keep only the rows whose first field equals this (e.g. `odom3`, `$VNYMR`).
    pub record: Option<String>,
    /// The rows' time (required, but for a GPX table, which its points' `<time>` time).
    #[serde(default)]
    pub time: TimeSpec,
    /// Added to this table's times, seconds (a known clock offset).
    #[serde(default)]
    pub offset_s: f64,
}

pub(super) fn default_delimiter() -> char {
    ','
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
    /// A GPX file's track points (`<trkpt>`), in the columns `lat`, `lon`, `ele` and
    /// `speed` (GPX 1.0's, m/s), timed by their `<time>` (s since 1970, UTC).
    Gpx,
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
    pub(super) fn factor(self) -> f64 {
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

pub(super) fn one() -> f64 {
    1.0
}

/// Up = the mean specific force over the first `first_s` seconds (vehicle at rest).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GravitySpec {
    /// Accelerometer x, y, z columns in the gyro's frame ...
    pub axes: Vec<String>,
    /// ... of this table (default: the gyro's; a phone logger writes gravity to its own file).
    pub table: Option<String>,
    /// Per-axis factors for the accelerometer, as `signs` for the gyro.
    pub signs: Option<Vec<f64>>,
    #[serde(default = "default_gravity_s")]
    pub first_s: f64,
}

pub(super) fn default_gravity_s() -> f64 {
    10.0
}

/// Positions from which a course and a speed are derived.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PositionsSpec {
    pub table: String,
    /// latlon (deg), utm (easting, northing m), ecef (x, y, z m), enu (east, north m) or
    /// nmea (NMEA's ddmm.mmmm latitude, its N/S, dddmm.mmmm longitude, its E/W: 4 columns).
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
    Nmea,
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
        /// A speed column of the same table gating the heading, in `speed_unit` (m/s, km/h
        /// or mph; default m/s).
        speed_column: Option<String>,
        speed_unit: Option<String>,
        min_speed_mps: f64,
        /// A slow sensor repeated on every fast row (a phone's location in its IMU rows):
        /// the column of the sensor's own time, s. A sample is taken only where it
        /// changes, stamped with it on the table's clock (see `own_samples`).
        time_column: Option<String>,
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
pub(super) struct HeadingWire {
    source: Source,
    table: Option<String>,
    column: Option<String>,
    unit: Option<String>,
    positive: Option<Sense>,
    speed_column: Option<String>,
    speed_unit: Option<String>,
    min_speed_mps: Option<f64>,
    min_distance_m: Option<f64>,
    time_column: Option<String>,
}

/// A field the chosen `source` needs, or an error naming it.
pub(super) fn needed<T>(v: Option<T>, section: &str, field: &str, source: &str) -> std::result::Result<T, String> {
    v.ok_or_else(|| format!("{section}: source = \"{source}\" needs `{field}`"))
}

/// Fields that the chosen `source` does not use: an error naming the first one given.
pub(super) fn unused(section: &str, source: &str, given: &[(&str, bool)]) -> std::result::Result<(), String> {
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
                let time_column = w.time_column;
                Ok(HeadingSpec::Column {
                    table: needed(w.table, "heading", "table", "column")?,
                    column: needed(w.column, "heading", "column", "column")?,
                    unit: needed(w.unit, "heading", "unit", "column")?,
                    positive: needed(w.positive, "heading", "positive", "column")?,
                    speed_column: w.speed_column,
                    speed_unit: w.speed_unit,
                    min_speed_mps: w.min_speed_mps.unwrap_or(0.0),
                    time_column,
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
                        ("speed_unit", w.speed_unit.is_some()),
                        ("time_column", w.time_column.is_some()),
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
        /// As `heading.time_column`: a sample only where the sensor's own time changes.
        time_column: Option<String>,
    },
    Positions {
        window_s: f64,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SpeedWire {
    source: Source,
    table: Option<String>,
    column: Option<String>,
    unit: Option<String>,
    window_s: Option<f64>,
    time_column: Option<String>,
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
                    time_column: w.time_column,
                })
            }
            Source::Positions => {
                unused(
                    "speed",
                    "positions",
                    &[
                        ("table", w.table.is_some()),
                        ("column", w.column.is_some()),
                        ("unit", w.unit.is_some()),
                        ("time_column", w.time_column.is_some()),
                    ],
                )?;
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

pub(super) fn default_max_lag() -> f64 {
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
            None => {
                let mut given: Vec<&str> = self.keys().map(String::as_str).take(8).collect();
                if self.len() > given.len() {
                    given.push("...");
                }
                Err(Error::File(format!("{name}: the recipe names this file, but it was not given (given: {})", given.join(", "))))
            }
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
    /// What the time policies did, over all tables: rows merged into another of the same
    /// time (`mean`), rows dropped (`drop`), rows put back in time order (`sort`).
    #[serde(default)]
    pub time_fixes: TimeFixes,
}
