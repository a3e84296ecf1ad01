//! Recipes for the loggers people use, picked from the files' names and header rows: a user
//! drops what the app wrote and gets a v1 log, or is told which preset came closest and
//! which column it missed. Each preset lists its files (roles) by the columns they must
//! have; its recipe is built from the columns actually found.

use super::sniff::Sniffed;
use super::*;
use crate::log::DriveLog;
use serde_json::{json, Value};
use std::io::Read;

/// One file a preset reads.
struct Role {
    id: &'static str,
    /// File stems (lower case) the role accepts; empty = any name.
    stems: &'static [&'static str],
    /// Columns the header must have (patterns as for [`Sniffed::find`]).
    columns: &'static [&'static str],
    required: bool,
}

/// One logger's layout.
struct Preset {
    id: &'static str,
    title: &'static str,
    roles: &'static [Role],
    build: fn(&Found) -> Value,
}

/// The files matched to a preset's roles.
pub struct Found<'a> {
    files: BTreeMap<&'static str, &'a Sniffed>,
}

impl Found<'_> {
    fn has(&self, role: &str) -> bool {
        self.files.contains_key(role)
    }
    /// A column of a matched role's file (the actual name behind a pattern).
    fn col(&self, role: &str, pattern: &str) -> Option<String> {
        self.files.get(role).and_then(|s| s.find(pattern)).map(str::to_string)
    }
    /// Three columns, or None when one is missing.
    fn cols3(&self, role: &str, p: [&str; 3]) -> Option<[String; 3]> {
        Some([self.col(role, p[0])?, self.col(role, p[1])?, self.col(role, p[2])?])
    }
    fn table(&self, role: &str, time: Value) -> Value {
        json!({ "id": role, "file": self.files[role].name, "time": time })
    }
}

const fn role(id: &'static str, stems: &'static [&'static str], columns: &'static [&'static str], required: bool) -> Role {
    Role { id, stems, columns, required }
}

static PRESETS: &[Preset] = &[
    Preset {
        id: "sensorlog",
        title: "SensorLog (iOS)",
        roles: &[role(
            "log",
            &[],
            &["gyroTimestamp_sinceReboot(s)", "gyroRotationX(rad/s)", "gyroRotationY(rad/s)", "gyroRotationZ(rad/s)"],
            true,
        )],
        build: sensorlog,
    },
    Preset {
        id: "sensor-logger",
        title: "Sensor Logger (Android, iOS), CSV export",
        roles: &[
            role("gyro", &["gyroscope", "gyroscopeuncalibrated"], &["seconds_elapsed", "x", "y", "z"], true),
            role("gravity", &["gravity", "totalacceleration"], &["seconds_elapsed", "x", "y", "z"], false),
            role("location", &["location", "locationgps"], &["seconds_elapsed", "speed", "bearing"], false),
        ],
        build: sensor_logger,
    },
    Preset {
        id: "sensor-logger-1s",
        title: "Sensor Logger resampled to 1 s (the Pixel 6a drives' imu.csv + gps.csv)",
        roles: &[
            role("imu", &[], &["time", "a_x", "a_y", "a_z", "w_x", "w_y", "w_z"], true),
            role("gps", &[], &["time", "speed", "bearing"], false),
        ],
        build: sensor_logger_1s,
    },
    Preset {
        id: "phyphox",
        title: "phyphox, CSV export (any separator and decimal mark)",
        roles: &[
            role("gyro", &[], &["Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)"], true),
            role("acc", &[], &["Time (s)", "Acceleration x (m/s^2)", "Acceleration y (m/s^2)", "Acceleration z (m/s^2)"], false),
            role("location", &[], &["Time (s)", "Velocity (m/s)", "Direction (°)"], false),
        ],
        build: phyphox,
    },
    Preset {
        id: "comma2k19",
        title: "comma2k19 segment as CSV (imu.csv, can.csv, live_gnss_ublox.csv)",
        roles: &[
            role("imu", &[], &["t_boot_s", "gyro_fwd_rad_s", "gyro_right_rad_s", "gyro_down_rad_s"], true),
            role("gnss", &[], &["t_boot_s", "bearing_deg", "speed_m_s"], false),
            role("can", &[], &["t_boot_s", "speed_m_s", "wheel_rl_m_s", "wheel_rr_m_s"], false),
        ],
        build: comma2k19,
    },
    Preset {
        id: "px4",
        title: "PX4 ulog as CSV (ulog2csv: *_sensor_combined_0.csv, *_vehicle_gps_position_0.csv)",
        roles: &[
            role("imu", &[], &["timestamp", "gyro_rad[0]", "gyro_rad[1]", "gyro_rad[2]"], true),
            role("gps", &[], &["timestamp", "vel_m_s", "cog_rad"], false),
        ],
        build: px4,
    },
    Preset {
        id: "ros",
        title: "ROS 1/2 sensor_msgs/Imu as CSV (rostopic echo -p, ros2 bag tools, bagpy, PlotJuggler)",
        roles: &[
            role("imu", &[], &[ROS_TIME, "*angular_velocity.z|*angular_velocity/z"], true),
            role("fix", &[], &[ROS_TIME, "*latitude", "*longitude"], false),
        ],
        build: ros,
    },
];

const ROS_TIME: &str = "%time|__time|Time|rosbagTimestamp";

/// The time spec of a ROS CSV: `%time` and `rosbagTimestamp` are ns, `__time` and `Time` s.
fn ros_time(s: &Sniffed) -> Value {
    let c = s.find(ROS_TIME).unwrap_or("Time").to_string();
    let unit = if c == "%time" || c == "rosbagTimestamp" { "ns" } else { "s" };
    json!({ "column": c, "unit": unit })
}

/// A yaw rate: three axes projected on the gravity of `grav` (its table or the gyro's),
/// or the z axis alone when no gravity was found.
fn rate3(f: &Found, gyro: &str, axes: [&str; 3], unit: &str, grav: Option<(&str, [&str; 3], [i8; 3])>) -> Value {
    let g = grav.and_then(|(role, p, signs)| Some((role, f.cols3(role, p)?, signs)));
    match (f.cols3(gyro, axes), g) {
        (Some(a), Some((role, ga, signs))) => {
            let mut grav = json!({ "axes": ga, "signs": signs, "first_s": 10 });
            if role != gyro {
                grav["table"] = json!(role);
            }
            json!({ "table": gyro, "axes": a, "gravity": grav, "unit": unit, "positive": "ccw" })
        }
        _ => json!({ "table": gyro, "column": f.col(gyro, axes[2]), "unit": unit, "positive": "ccw" }),
    }
}

fn heading_column(table: &str, column: Option<String>, unit: &str, speed: Option<String>, min_speed: f64) -> Value {
    json!({ "source": "column", "table": table, "column": column, "unit": unit, "positive": "cw",
            "speed_column": speed, "min_speed_mps": min_speed })
}

fn sensorlog(f: &Found) -> Value {
    // CoreMotion's gravity (and the accelerometer at rest) points down, in G: signs -1 give up.
    let grav = if f.col("log", "motionGravityX(G)").is_some() {
        Some(("log", ["motionGravityX(G)", "motionGravityY(G)", "motionGravityZ(G)"], [-1, -1, -1]))
    } else {
        Some(("log", ["accelerometerAccelerationX(G)", "accelerometerAccelerationY(G)", "accelerometerAccelerationZ(G)"], [-1, -1, -1]))
    };
    let mut r = json!({
        "tables": [f.table("log", json!({ "column": "gyroTimestamp_sinceReboot(s)", "unit": "s" }))],
        "yaw_rate": rate3(f, "log", ["gyroRotationX(rad/s)", "gyroRotationY(rad/s)", "gyroRotationZ(rad/s)"], "rad/s", grav),
    });
    // Location columns repeat the last fix on every row: one sample per fix, by its own time.
    let fix_time = f.col("log", "locationTimestamp_since1970(s)");
    if let (Some(course), Some(_)) = (f.col("log", "locationCourse(°)"), &fix_time) {
        let mut h = heading_column("log", Some(course), "deg", f.col("log", "locationSpeed(m/s)"), 5.0);
        h["time_column"] = json!(fix_time);
        r["heading"] = h;
    }
    if let (Some(speed), Some(_)) = (f.col("log", "locationSpeed(m/s)"), &fix_time) {
        r["speed"] = json!({ "source": "column", "table": "log", "column": speed, "unit": "m/s", "time_column": fix_time });
    }
    r
}

fn sensor_logger(f: &Found) -> Value {
    let time = json!({ "column": "seconds_elapsed", "unit": "s" });
    let mut tables = vec![f.table("gyro", time.clone())];
    // Android's gravity and total acceleration read +g along up.
    let grav = f.has("gravity").then_some(("gravity", ["x", "y", "z"], [1, 1, 1]));
    if f.has("gravity") {
        tables.push(f.table("gravity", time.clone()));
    }
    let mut r = json!({ "yaw_rate": rate3(f, "gyro", ["x", "y", "z"], "rad/s", grav) });
    if f.has("location") {
        tables.push(f.table("location", time));
        r["heading"] = heading_column("location", f.col("location", "bearing"), "deg", f.col("location", "speed"), 5.0);
        r["speed"] = json!({ "source": "column", "table": "location", "column": "speed", "unit": "m/s" });
    }
    r["tables"] = json!(tables);
    r
}

fn sensor_logger_1s(f: &Found) -> Value {
    let time = json!({ "column": "time", "format": "iso8601" });
    let mut tables = vec![f.table("imu", time.clone())];
    // The repository that made this layout negated gyro y and accel z: the signs undo that.
    let mut rate = rate3(f, "imu", ["w_x", "w_y", "w_z"], "rad/s", Some(("imu", ["a_x", "a_y", "a_z"], [1, 1, -1])));
    rate["signs"] = json!([1, -1, 1]);
    let mut r = json!({ "bias_s": 0, "yaw_rate": rate });
    if f.has("gps") {
        tables.push(f.table("gps", time));
        r["heading"] = heading_column("gps", Some("bearing".into()), "deg", Some("speed".into()), 5.0);
        r["speed"] = json!({ "source": "column", "table": "gps", "column": "speed", "unit": "m/s" });
    }
    r["tables"] = json!(tables);
    r
}

fn phyphox(f: &Found) -> Value {
    let time = json!({ "column": "Time (s)", "unit": "s" });
    let mut tables = vec![f.table("gyro", time.clone())];
    let grav = f.has("acc").then_some(("acc", ["Acceleration x (m/s^2)", "Acceleration y (m/s^2)", "Acceleration z (m/s^2)"], [1, 1, 1]));
    if f.has("acc") {
        tables.push(f.table("acc", time.clone()));
    }
    let axes = ["Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)"];
    let mut r = json!({ "yaw_rate": rate3(f, "gyro", axes, "rad/s", grav) });
    if f.has("location") {
        tables.push(f.table("location", time));
        r["heading"] = heading_column("location", Some("Direction (°)".into()), "deg", Some("Velocity (m/s)".into()), 5.0);
        r["speed"] = json!({ "source": "column", "table": "location", "column": "Velocity (m/s)", "unit": "m/s" });
    }
    r["tables"] = json!(tables);
    r
}

fn comma2k19(f: &Found) -> Value {
    let time = json!({ "column": "t_boot_s", "unit": "s" });
    let mut tables = vec![f.table("imu", time.clone())];
    let acc = ["acc_fwd_m_s2", "acc_right_m_s2", "acc_down_m_s2"];
    let axes = ["gyro_fwd_rad_s", "gyro_right_rad_s", "gyro_down_rad_s"];
    let mut rate = rate3(f, "imu", axes, "rad/s", Some(("imu", acc, [1, 1, 1])));
    if rate.get("column").is_some() {
        rate["positive"] = json!("cw"); // the down axis alone
    }
    let mut r = json!({ "bias_s": 0, "yaw_rate": rate });
    if f.has("gnss") {
        tables.push(f.table("gnss", time.clone()));
        r["heading"] = heading_column("gnss", Some("bearing_deg".into()), "deg", Some("speed_m_s".into()), 5.0);
    }
    if f.has("can") {
        tables.push(f.table("can", time));
        r["speed"] = json!({ "source": "column", "table": "can", "column": "speed_m_s", "unit": "m/s" });
        r["odometry"] = json!({ "table": "can", "left": ["wheel_rl_m_s"], "right": ["wheel_rr_m_s"], "kind": "speed",
                                "unit": "m/s", "track_m": 1.6 });
    } else if f.has("gnss") {
        r["speed"] = json!({ "source": "column", "table": "gnss", "column": "speed_m_s", "unit": "m/s" });
    }
    r["tables"] = json!(tables);
    r
}

fn px4(f: &Found) -> Value {
    let time = json!({ "column": "timestamp", "unit": "us" });
    let mut tables = vec![f.table("imu", time.clone())];
    // FRD body axes; the accelerometer reads the specific force (up at rest): projecting on
    // it turns the z-down gyro into counter-clockwise positive.
    let acc = ["accelerometer_m_s2[0]", "accelerometer_m_s2[1]", "accelerometer_m_s2[2]"];
    let mut rate = rate3(f, "imu", ["gyro_rad[0]", "gyro_rad[1]", "gyro_rad[2]"], "rad/s", Some(("imu", acc, [1, 1, 1])));
    if rate.get("column").is_some() {
        rate["positive"] = json!("cw");
    }
    let mut r = json!({ "yaw_rate": rate });
    if f.has("gps") {
        tables.push(f.table("gps", time));
        r["heading"] = heading_column("gps", Some("cog_rad".into()), "rad", Some("vel_m_s".into()), 2.0);
        r["speed"] = json!({ "source": "column", "table": "gps", "column": "vel_m_s", "unit": "m/s" });
    }
    r["tables"] = json!(tables);
    r
}

fn ros(f: &Found) -> Value {
    let mut tables = vec![f.table("imu", ros_time(f.files["imu"]))];
    // REP 103: the accelerometer reads +g along up at rest.
    let p = |axis: &str| format!("*linear_acceleration.{axis}|*linear_acceleration/{axis}");
    let w = |axis: &str| format!("*angular_velocity.{axis}|*angular_velocity/{axis}");
    let (px, py, pz, wx, wy, wz) = (p("x"), p("y"), p("z"), w("x"), w("y"), w("z"));
    let mut r = json!({ "yaw_rate": rate3(f, "imu", [&wx, &wy, &wz], "rad/s", Some(("imu", [&px, &py, &pz], [1, 1, 1]))) });
    if f.has("fix") {
        tables.push(f.table("fix", ros_time(f.files["fix"])));
        r["positions"] = json!({ "table": "fix", "kind": "latlon", "columns": [f.col("fix", "*latitude"), f.col("fix", "*longitude")] });
        r["heading"] = json!({ "source": "positions" });
        r["speed"] = json!({ "source": "positions" });
    }
    r["tables"] = json!(tables);
    r
}

/// The preset picked for a set of files, and its recipe.
#[derive(Debug, Clone)]
pub struct Detection {
    pub preset: &'static str,
    pub title: &'static str,
    /// The recipe as data (to show, save as TOML or JSON, and edit).
    pub recipe_json: Value,
    pub recipe: Recipe,
    /// (role, file) of each file used.
    pub used: Vec<(&'static str, String)>,
    /// Files no role took.
    pub ignored: Vec<String>,
}

impl Detection {
    /// Names the recording (an archive's or a folder's name) in the recipe, so the log it
    /// imports, and the recipe saved and run again, carry that name.
    pub fn name(&mut self, name: &str) {
        self.recipe_json["name"] = Value::String(name.to_string());
        self.recipe.name = Some(name.to_string());
    }
}

/// The preset ids and titles, for help texts.
pub fn presets() -> Vec<(&'static str, &'static str)> {
    PRESETS.iter().map(|p| (p.id, p.title)).collect()
}

fn role_fits(r: &Role, s: &Sniffed) -> bool {
    (r.stems.is_empty() || r.stems.contains(&s.stem().as_str())) && r.columns.iter().all(|c| s.find(c).is_some())
}

/// Picks the preset whose roles the files fill best (every required role, then the most
/// optional ones), and builds its recipe. Without a fit, the error names the closest
/// preset and what its first file lacked.
pub fn detect(files: &[Sniffed]) -> Result<Detection> {
    if files.is_empty() {
        return Err(Error::File("no files to detect a logger from".into()));
    }
    let mut best: Option<(usize, &Preset, Found)> = None;
    for p in PRESETS {
        let mut found = Found { files: BTreeMap::new() };
        for r in p.roles {
            let taken: Vec<&str> = found.files.values().map(|s| s.name.as_str()).collect();
            if let Some(s) = files.iter().find(|s| !taken.contains(&s.name.as_str()) && role_fits(r, s)) {
                found.files.insert(r.id, s);
            }
        }
        if p.roles.iter().any(|r| r.required && !found.has(r.id)) {
            continue;
        }
        if best.as_ref().is_none_or(|(n, _, _)| found.files.len() > *n) {
            best = Some((found.files.len(), p, found));
        }
    }
    let Some((_, p, found)) = best else { return Err(no_fit(files)) };
    let mut v = (p.build)(&found);
    let first = found.files.get(p.roles[0].id).map(|s| s.name.clone()).unwrap_or_default();
    v["name"] =
        json!(format!("{} ({})", first.rsplit(['/', '\\']).next().unwrap_or(&first), p.title.split(" (").next().unwrap_or(p.title)));
    v["description"] = json!(format!("imported by the {} preset", p.id));
    // The dialect of each file, as sniffed.
    let tables = v.as_object_mut().and_then(|o| o.remove("tables")).unwrap_or(json!([]));
    v["table"] = tables;
    for t in v["table"].as_array_mut().into_iter().flatten() {
        let Some(s) = files.iter().find(|s| Some(s.name.as_str()) == t["file"].as_str()) else { continue };
        s.set_dialect(t);
    }
    strip_nulls(&mut v);
    let recipe: Recipe = serde_json::from_value(v.clone()).map_err(|e| recipe_err(&format!("preset {}", p.id), e.to_string()))?;
    let used: Vec<(&'static str, String)> = p.roles.iter().filter_map(|r| found.files.get(r.id).map(|s| (r.id, s.name.clone()))).collect();
    let ignored = files.iter().filter(|s| !used.iter().any(|(_, n)| *n == s.name)).map(|s| s.name.clone()).collect();
    Ok(Detection { preset: p.id, title: p.title, recipe_json: v, recipe, used, ignored })
}

fn strip_nulls(v: &mut Value) {
    match v {
        Value::Object(o) => {
            o.retain(|_, x| !x.is_null());
            o.values_mut().for_each(strip_nulls);
        }
        Value::Array(a) => a.iter_mut().for_each(strip_nulls),
        _ => {}
    }
}

/// Why no preset fits: the closest preset's first role against the file nearest to it, or
/// the file with the most columns.
fn no_fit(files: &[Sniffed]) -> Error {
    let mut best: Option<(usize, String)> = None;
    for p in PRESETS {
        let r = &p.roles[0];
        for s in files {
            let have = r.columns.iter().filter(|c| s.find(c).is_some()).count();
            let name_ok = r.stems.is_empty() || r.stems.contains(&s.stem().as_str());
            let score = have + usize::from(name_ok && !r.stems.is_empty());
            if have > 0 && best.as_ref().is_none_or(|(b, _)| score > *b) {
                let missing: Vec<&str> =
                    r.columns.iter().filter(|c| s.find(c).is_none()).map(|c| c.split('|').next().unwrap_or(c)).collect();
                let why = if missing.is_empty() {
                    format!("its file name would be one of {}", r.stems.iter().map(|x| format!("{x}.csv")).collect::<Vec<_>>().join(", "))
                } else {
                    format!("it lacks the column{} {}", if missing.len() > 1 { "s" } else { "" }, missing.join(", "))
                };
                best = Some((score, format!("{}: closest preset is {} ({}), but {why}", s.name, p.id, p.title)));
            }
        }
    }
    let names: Vec<&str> = PRESETS.iter().map(|p| p.id).collect();
    let header = |s: &Sniffed| s.header.iter().take(8).cloned().collect::<Vec<_>>().join(", ");
    // The file with the most columns (the first of them) stands for the recording.
    let widest = files.iter().rev().max_by_key(|s| s.header.len()).unwrap_or(&files[0]);
    Error::File(match best {
        Some((_, m)) => format!("no logger preset fits these files. {m}. Write a recipe (sample-logs/recipes/README.md)"),
        None => format!(
            "no logger preset ({}) recognises {} (header: {}). Write a recipe (sample-logs/recipes/README.md)",
            names.join(", "),
            widest.name,
            header(widest)
        ),
    })
}

/// Detection and import of raw files by name through `files` (each opened once for its
/// head, then again by the import): what `gyrodrift import FILE...` and the Python
/// `import_files` do.
pub fn detect_and_import(names: &[String], files: &mut dyn Files) -> Result<(Detection, DriveLog, ImportSummary)> {
    let mut heads = Vec::with_capacity(names.len());
    for name in names {
        let mut head = Vec::new();
        files.open(name)?.take(super::sniff::SNIFF_BYTES as u64).read_to_end(&mut head).map_err(|e| Error::File(format!("{name}: {e}")))?;
        heads.push((name.as_str(), head));
    }
    let (sniffed, others) = super::sniff::sniff_tables(heads.iter().map(|(n, h)| (*n, h.as_slice())))?;
    let mut d = detect(&sniffed)?;
    d.ignored.extend(others);
    let (log, summary) = import(&d.recipe, files)?;
    Ok((d, log, summary))
}
