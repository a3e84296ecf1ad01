//! What raw columns are, read from their names and first values: each file's time column
//! and, for every column, the time format and the rate, speed and angle units its name (or
//! value) says; then the columns that read as the yaw rate, three gyro and three
//! accelerometer axes, a course, latitude and longitude, a speed and a temperature. The
//! draft recipe (`draft.rs`) and the dashboard's column mapper both start from these, so a
//! raw file is read one way wherever it is opened.

use super::sniff::{first_rows, sniff, Sniffed};
use super::units::{parse_iso8601, parse_time_of_day};
use crate::error::Result;
use serde::Serialize;

/// A column of one of the files: its index among them and its name.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ColumnRef {
    pub file: usize,
    pub column: String,
}

/// What one column's name (and first value) says, read as each kind it could be.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ColumnReading {
    pub name: String,
    /// As a time: "s", "ms", "us", "ns" (a unit) or "iso8601", "time_of_day" (a format).
    pub time: &'static str,
    /// As a rate: "rad/s" or "deg/s" (rad/s when the name says no unit: phones and ROS).
    pub rate_unit: &'static str,
    /// As a speed: "m/s", "km/h", "mph" or "kn".
    pub speed_unit: &'static str,
    /// As a heading: "deg" or "rad".
    pub angle_unit: &'static str,
}

/// One file: its name, whether it is a GPX track or an NMEA log (read as tracks, not by
/// their columns), its time column and the reading of each column.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FileGuess {
    pub name: String,
    pub gpx: bool,
    /// An NMEA log's sentence to read: its RMC (course and speed), else its GGA (positions).
    pub nmea: Option<String>,
    pub time_column: String,
    pub columns: Vec<ColumnReading>,
}

/// Latitude and longitude columns of one file, in degrees.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LatLon {
    pub file: usize,
    pub lat: String,
    pub lon: String,
}

/// The columns each role is guessed to be, by name; `None` where no column reads so.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Guesses {
    pub files: Vec<FileGuess>,
    /// A z axis or a yaw rate by name, else any gyro or rate.
    pub yaw_rate: Option<ColumnRef>,
    /// Gyro x, y, z, all in one file (for a yaw rate projected on gravity).
    pub gyro_axes: Option<Vec<ColumnRef>>,
    /// Accelerometer (or gravity) x, y, z, all in one file.
    pub accel_axes: Option<Vec<ColumnRef>>,
    /// The yaw rate is better read as the gyro axes projected on the accelerometer's up
    /// (both triads found, the yaw-rate guess one of the gyro axes): right in any mounting,
    /// where one axis is the yaw rate only when it points up.
    pub yaw_from_axes: bool,
    /// A course, bearing or heading column (never the yaw rate's).
    pub course: Option<ColumnRef>,
    pub lat_lon: Option<LatLon>,
    pub speed: Option<ColumnRef>,
    pub temperature: Option<ColumnRef>,
}

/// `name` in lower case contains `a`, then later `b` (a regex `a.*b`).
pub(super) fn then(name: &str, a: &str, b: &str) -> bool {
    name.find(a).is_some_and(|i| name[i + a.len()..].contains(b))
}

/// `name` has `word` as a whole token (letters and digits around it are other words).
pub(super) fn word(name: &str, word: &str) -> bool {
    name.match_indices(word).any(|(i, _)| {
        let before = name[..i].chars().next_back();
        let after = name[i + word.len()..].chars().next();
        !before.is_some_and(char::is_alphanumeric) && !after.is_some_and(char::is_alphanumeric)
    })
}

/// The time format or unit a time column's value (its first row's) or name suggests.
pub fn time_reading(name: &str, value: &str) -> &'static str {
    let n = name.to_lowercase();
    let clock = ["time_of_day", "timeofday", "hhmmss", "clock"];
    if parse_iso8601(value).is_some() {
        "iso8601"
    } else if (value.contains(':') && parse_time_of_day(value).is_some()) || clock.iter().any(|w| n.contains(w)) {
        "time_of_day"
    } else if n.contains("iso") || n.contains("date") || n.contains("utc") {
        "iso8601"
    } else if word(&n, "ns") || n.contains("_ns") || n.contains("nanos") {
        "ns"
    } else if word(&n, "us") || n.contains("_us") || n.contains("micros") || n.contains('µ') {
        "us"
    } else if word(&n, "ms") || n.contains("_ms") || n.contains("millis") {
        "ms"
    } else {
        "s"
    }
}

/// Rows of the head a time column's step is read from.
const STEP_ROWS: usize = 21;

/// Column `j` of `rows` (empty where a row is short).
fn column_of(rows: &[Vec<String>], j: usize) -> Vec<&str> {
    rows.iter().map(|r| r.get(j).map_or("", String::as_str)).collect()
}

/// A time column's reading from its name and its first values: `time_reading` of the first,
/// and where that finds no unit (plain numbers, seconds by default) the unit whose sample
/// rate, at the median step between the values, is a logger's (0.5 Hz to 5 kHz: seconds,
/// then ms, us, ns), so a clock in microseconds (Xsens' SampleTimeFine) is not read as
/// seconds. A step of 2 to 2000 reads as ms, 2000 to 2e6 as us, beyond as ns.
pub fn time_reading_of(name: &str, values: &[&str], decimal_comma: bool) -> &'static str {
    let by_name = time_reading(name, values.first().copied().unwrap_or(""));
    let n = name.to_lowercase();
    // "s" as a word (time_s, "Time (s)"), not the s of "_stamp" or "_since".
    let says_s = word(&n, "s") || n.contains("sec");
    if by_name != "s" || says_s {
        return by_name;
    }
    let t: Vec<f64> = values.iter().filter_map(|v| super::table::number(v.trim(), decimal_comma)).collect();
    let mut steps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).filter(|d| *d > 0.0).collect();
    if steps.len() < 2 {
        return by_name;
    }
    steps.sort_by(f64::total_cmp);
    let step = steps[steps.len() / 2];
    match step {
        s if s <= 2.0 => "s",
        s if s <= 2e3 => "ms",
        s if s <= 2e6 => "us",
        _ => "ns",
    }
}

/// A rate's unit by its column name, and why.
pub fn rate_unit_of(name: &str) -> (&'static str, &'static str) {
    let n = name.to_lowercase();
    match () {
        _ if n.contains("rad") => ("rad/s", "the name says rad"),
        _ if n.contains("deg") || n.contains("dps") => ("deg/s", "the name says deg/s"),
        _ if n.starts_with("gyr_") => ("deg/s", "named as Xsens names it, Gyr_X: Xsens exports write deg/s"),
        _ => ("rad/s", "no unit in the name: phones and ROS write rad/s"),
    }
}

/// A speed's unit by its column name (m/s unless it says otherwise).
pub fn speed_unit_of(name: &str) -> &'static str {
    let n = name.to_lowercase();
    match () {
        _ if n.contains("kmh") || n.contains("km/h") || n.contains("kph") => "km/h",
        _ if n.contains("mph") => "mph",
        _ if n.contains("knot") || word(&n, "kn") || n.contains("kts") => "kn",
        _ => "m/s",
    }
}

/// A heading's unit by its column name (degrees unless it says rad).
pub fn angle_unit_of(name: &str) -> &'static str {
    if name.to_lowercase().contains("rad") {
        "rad"
    } else {
        "deg"
    }
}

/// A file's time column: the first whose name says time or stamp, else one named like a time
/// in seconds (`t`, `t_...`, `..._s`), else the first column.
fn time_column(s: &Sniffed) -> &str {
    let named = |h: &&String| {
        let n = h.to_lowercase();
        n.contains("time") || n.contains("stamp")
    };
    let like = |h: &&String| {
        let n = h.to_lowercase();
        n == "t" || n.starts_with("t_") || n.ends_with("_s")
    };
    s.header.iter().find(named).or_else(|| s.header.iter().find(like)).or(s.header.first()).map_or("", String::as_str)
}

/// A GPX file (by its name): a track read whole, not a table of columns.
fn is_gpx(s: &Sniffed) -> bool {
    s.name.to_lowercase().ends_with(".gpx")
}

/// An NMEA log: lines of `$` sentences.
fn is_nmea(s: &Sniffed) -> bool {
    s.header.first().is_some_and(|h| h.starts_with('$'))
}

/// A GPX track or an NMEA log: no column of it is a gyro's.
fn is_track(s: &Sniffed) -> bool {
    is_gpx(s) || is_nmea(s)
}

/// The sentence of an NMEA log to read, from its head's lines: the first RMC talker
/// (`$GPRMC`, `$GNRMC`: course and speed), else the first GGA (positions).
fn nmea_record(s: &Sniffed, head: &[u8]) -> Option<String> {
    if !is_nmea(s) {
        return None;
    }
    let text = String::from_utf8_lossy(head);
    let tags: Vec<&str> = text.lines().filter_map(|l| l.split(',').next()).filter(|t| t.starts_with('$') && t.len() == 6).collect();
    let first = |kind: &str| tags.iter().find(|t| t.ends_with(kind)).map(|t| t.to_string());
    first("RMC").or_else(|| first("GGA"))
}

/// Three columns of one file named alike but for the axis letter, x, y and z at one place
/// (`gyro_x`, `gyroRotationY(rad/s)`), the x one's name (in lower case) `fits`; the first
/// such over the files.
fn triad(files: &[Sniffed], fits: impl Fn(&str) -> bool) -> Option<Vec<ColumnRef>> {
    files.iter().enumerate().filter(|(_, s)| !is_track(s)).find_map(|(i, s)| {
        let lower: Vec<String> = s.header.iter().map(|h| h.to_lowercase()).collect();
        let at = |name: &str| lower.iter().position(|m| m == name);
        lower.iter().enumerate().filter(|(_, n)| fits(n)).find_map(|(x, n)| {
            n.match_indices('x').find_map(|(k, _)| {
                let with = |a: &str| at(&format!("{}{a}{}", &n[..k], &n[k + 1..]));
                let axes = [x, with("y")?, with("z")?];
                Some(axes.iter().map(|&j| ColumnRef { file: i, column: s.header[j].clone() }).collect())
            })
        })
    })
}

/// The guesses for files (name, the head of their bytes), or an error naming a file that is
/// not a text table.
pub fn column_guesses(heads: &[(String, Vec<u8>)]) -> Result<Guesses> {
    let files: Vec<Sniffed> = heads.iter().map(|(name, head)| sniff(name, head)).collect::<Result<_>>()?;
    Ok(guess_columns(&files, heads))
}

/// Reads sniffed files (`heads`: the files' names and heads, in the same order).
pub fn guess_columns(files: &[Sniffed], heads: &[(String, Vec<u8>)]) -> Guesses {
    let per_file = files
        .iter()
        .zip(heads)
        .map(|(s, (_, head))| (s, head, first_rows(s, head, STEP_ROWS)))
        .map(|(s, head, rows)| FileGuess {
            name: s.name.clone(),
            gpx: is_gpx(s),
            nmea: nmea_record(s, head),
            time_column: time_column(s).to_string(),
            columns: s
                .header
                .iter()
                .enumerate()
                .map(|(j, h)| ColumnReading {
                    name: h.clone(),
                    time: time_reading_of(h, &column_of(&rows, j), s.decimal_comma),
                    rate_unit: rate_unit_of(h).0,
                    speed_unit: speed_unit_of(h),
                    angle_unit: angle_unit_of(h),
                })
                .collect(),
        })
        .collect();
    // The first column, over every file, that `fits` (its name in lower case) and is not
    // the file's time.
    let find = |fits: &dyn Fn(&str) -> bool| {
        files.iter().enumerate().filter(|(_, s)| !is_track(s)).find_map(|(i, s)| {
            let time = time_column(s);
            s.header.iter().find(|h| h.as_str() != time && fits(&h.to_lowercase())).map(|h| ColumnRef { file: i, column: h.clone() })
        })
    };
    // "gyr" as well as "gyro": Xsens writes Gyr_X, Gyr_Y, Gyr_Z.
    let z_axis = |n: &str| then(n, "gyr", "z") || word(n, "wz") || word(n, "w_z") || then(n, "yaw", "rate") || then(n, "angular", "z");
    let any_rate = |n: &str| n.contains("gyr") || n.contains("yaw") || n.contains("rate");
    let yaw_rate = find(&z_axis).or_else(|| find(&any_rate));
    let gyro = yaw_rate.as_ref().map(|c| c.column.to_lowercase()).unwrap_or_default();
    let course_words = ["course", "bearing", "heading", "direction", "cog"];
    let gyro_axes = triad(files, |n| n.contains("gyr") || n.contains("angular") || n == "wx" || n == "w_x");
    let accel_axes = triad(files, |n| (n.contains("acc") || n.contains("grav") || n == "ax" || n == "a_x") && !n.contains("accuracy"));
    let yaw_from_axes = accel_axes.is_some() && gyro_axes.as_ref().is_some_and(|g| yaw_rate.as_ref().is_some_and(|y| g.contains(y)));
    Guesses {
        files: per_file,
        gyro_axes,
        accel_axes,
        yaw_from_axes,
        course: find(&|n| n != gyro && course_words.iter().any(|w| n.contains(w)) && !n.contains("accuracy")),
        lat_lon: files.iter().enumerate().filter(|(_, s)| !is_track(s)).find_map(|(i, s)| {
            let col = |w: &str| s.header.iter().find(|h| h.to_lowercase().contains(w)).cloned();
            Some(LatLon { file: i, lat: col("lat")?, lon: col("lon")? })
        }),
        speed: find(&|n| (n.contains("speed") || n.contains("velocity") || n.contains("vel_m") || word(n, "v")) && !n.contains("accuracy")),
        temperature: find(&|n| n.contains("temp")),
        yaw_rate,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guesses(files: &[(&str, &str)]) -> Guesses {
        let heads: Vec<(String, Vec<u8>)> = files.iter().map(|(n, t)| (n.to_string(), t.as_bytes().to_vec())).collect();
        column_guesses(&heads).unwrap()
    }

    fn at(file: usize, column: &str) -> ColumnRef {
        ColumnRef { file, column: column.into() }
    }

    #[test]
    fn each_column_is_read_as_every_kind_it_could_be() {
        let g = guesses(&[("p.csv", "stamp_ms,yaw_rate_dps,course_rad,speed_kmh,wall\n5,1,2,3,10:00:00.5\n")]);
        let f = &g.files[0];
        assert_eq!(f.time_column, "stamp_ms");
        let by = |c: &str| f.columns.iter().find(|r| r.name == c).unwrap().clone();
        assert_eq!(by("stamp_ms").time, "ms");
        assert_eq!(by("yaw_rate_dps").rate_unit, "deg/s");
        assert_eq!(by("course_rad").angle_unit, "rad");
        assert_eq!(by("course_rad").rate_unit, "rad/s");
        assert_eq!(by("speed_kmh").speed_unit, "km/h");
        // A time of day by its value, whatever the name.
        assert_eq!(by("wall").time, "time_of_day");
        assert_eq!((by("wall").speed_unit, by("wall").angle_unit), ("m/s", "deg"));
        assert_eq!(g.yaw_rate, Some(at(0, "yaw_rate_dps")));
        assert_eq!(g.course, Some(at(0, "course_rad")));
        assert_eq!(g.speed, Some(at(0, "speed_kmh")));
        assert_eq!((g.gyro_axes.clone(), g.lat_lon.clone(), g.temperature.clone()), (None, None, None));
    }

    #[test]
    fn time_units_and_formats_by_name_and_value() {
        for (name, value, want) in [
            ("t", "1.5", "s"),
            ("time_ns", "", "ns"),
            ("t (us)", "", "us"),
            ("time µs", "", "us"),
            ("millis", "", "ms"),
            ("utc", "", "iso8601"),
            ("time", "2026-11-27T10:00:00Z", "iso8601"),
            ("time", "235959.50", "s"),
            ("hhmmss", "235959.50", "time_of_day"),
            ("time", "23:59:59.5", "time_of_day"),
        ] {
            assert_eq!(time_reading(name, value), want, "{name} = {value}");
        }
    }

    /// Where the name says no unit, the step between the first values does: Xsens' clock in
    /// microseconds at 120 Hz (8333), a phone's milliseconds at 100 Hz (10) and at 1 Hz
    /// (1000), seconds at 100 Hz and 1 Hz; a name that says the unit, or a date, wins.
    #[test]
    fn time_units_by_the_step_where_the_name_says_none() {
        let t = |start: f64, step: f64| (0..21).map(|i| format!("{}", start + step * i as f64)).collect::<Vec<_>>();
        let of = |name: &str, v: &[String]| time_reading_of(name, &v.iter().map(String::as_str).collect::<Vec<_>>(), false);
        assert_eq!(of("SampleTimeFine", &t(848104568.0, 8333.0)), "us");
        assert_eq!(of("timestamp", &t(1.7e12, 10.0)), "ms");
        assert_eq!(of("timestamp", &t(1.7e12, 1000.0)), "ms");
        assert_eq!(of("time", &t(0.0, 0.01)), "s");
        assert_eq!(of("time", &t(1.7e9, 1.0)), "s");
        assert_eq!(of("stamp", &t(1.7e18, 1e7)), "ns");
        // The name's unit wins over the step, and a time in seconds by name stays seconds.
        assert_eq!(of("time_ms", &t(0.0, 8333.0)), "ms");
        assert_eq!(of("Time (s)", &t(0.0, 10.0)), "s");
        assert_eq!(of("seconds_elapsed", &t(0.0, 10.0)), "s");
        assert_eq!(of("time_s", &t(0.0, 10.0)), "s");
        // ... but "_stamp" says no unit.
        assert_eq!(of("time_stamp", &t(1.7e12, 10.0)), "ms");
        // Decimal commas read; too few steps, or none forward, leave the name's reading.
        let comma: Vec<String> = t(0.0, 0.01).iter().map(|v| v.replace('.', ",")).collect();
        assert_eq!(time_reading_of("zeit", &comma.iter().map(String::as_str).collect::<Vec<_>>(), true), "s");
        assert_eq!(of("time", &t(5000.0, 0.0)), "s");
        assert_eq!(of("time", &t(0.0, 8333.0)[..2]), "s");
    }

    #[test]
    fn three_axes_in_one_file_are_found_and_the_course_is_never_the_gyro() {
        let imu = "time,gyro_x,gyro_y,gyro_z,acc_x,acc_y,acc_z,temp_c\n0,1,2,3,4,5,6,7\n";
        let gps = "time,latitude,longitude,bearing,accuracy_speed,speed\n0,1,2,3,4,5\n";
        let g = guesses(&[("imu.csv", imu), ("gps.csv", gps)]);
        assert_eq!(g.yaw_rate, Some(at(0, "gyro_z")));
        assert_eq!(g.gyro_axes, Some(vec![at(0, "gyro_x"), at(0, "gyro_y"), at(0, "gyro_z")]));
        assert_eq!(g.accel_axes, Some(vec![at(0, "acc_x"), at(0, "acc_y"), at(0, "acc_z")]));
        assert!(g.yaw_from_axes);
        assert_eq!(g.temperature, Some(at(0, "temp_c")));
        assert_eq!(g.lat_lon, Some(LatLon { file: 1, lat: "latitude".into(), lon: "longitude".into() }));
        assert_eq!(g.course, Some(at(1, "bearing")));
        // "accuracy_speed" says speed but is not one.
        assert_eq!(g.speed, Some(at(1, "speed")));
        // A heading rate is the yaw rate, not the course.
        let g = guesses(&[("a.csv", "t,heading_rate,v\n0,1,2\n")]);
        assert_eq!((g.yaw_rate, g.course, g.speed), (Some(at(0, "heading_rate")), None, Some(at(0, "v"))));
        // Named as Xsens writes them (MT Manager, DOT): "Gyr", not "gyro".
        let xsens = "PacketCounter,SampleTimeFine,Euler_X,Euler_Y,Euler_Z,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z\n0,1,2,3,4,5,6,7,8,9,10\n";
        let g = guesses(&[("CAR.csv", xsens)]);
        assert_eq!((g.yaw_rate, g.yaw_from_axes), (Some(at(0, "Gyr_Z")), true));
        assert_eq!(g.gyro_axes, Some(vec![at(0, "Gyr_X"), at(0, "Gyr_Y"), at(0, "Gyr_Z")]));
        assert_eq!(g.files[0].time_column, "SampleTimeFine");
        assert_eq!(rate_unit_of("Gyr_Z").0, "deg/s");
        assert_eq!(rate_unit_of("gyro_z").0, "rad/s");
        // Axes split over two files are not a triad; the z axis is still the yaw rate.
        let g = guesses(&[("a.csv", "t,gyro_x,gyro_y\n0,1,2\n"), ("b.csv", "t,gyro_z\n0,1\n")]);
        assert_eq!((g.yaw_rate, g.gyro_axes, g.yaw_from_axes), (Some(at(1, "gyro_z")), None, false));
        // Named as CoreMotion names them (the axis letter inside the name), "y" in "gravity" no axis.
        let g = guesses(&[(
            "log.csv",
            "t,gyroRotationX(rad/s),gyroRotationY(rad/s),gyroRotationZ(rad/s),gravity_x,gravity_y,gravity_z\n0,1,2,3,4,5,6\n",
        )]);
        let names = |c: Option<Vec<ColumnRef>>| c.unwrap_or_default().into_iter().map(|c| c.column).collect::<Vec<_>>();
        assert_eq!(names(g.gyro_axes), ["gyroRotationX(rad/s)", "gyroRotationY(rad/s)", "gyroRotationZ(rad/s)"]);
        assert_eq!(names(g.accel_axes), ["gravity_x", "gravity_y", "gravity_z"]);
        assert!(g.yaw_from_axes);
        // A yaw-rate column beside the axes is read as it is.
        let g = guesses(&[("a.csv", "t,yaw_rate,gyro_x,gyro_y,gyro_z,ax,ay,az\n0,1,2,3,4,5,6,7\n")]);
        assert_eq!((g.yaw_rate, g.accel_axes.is_some(), g.yaw_from_axes), (Some(at(0, "yaw_rate")), true, false));
    }
}
