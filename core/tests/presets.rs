//! Logger presets on the fixtures of `sample-logs/wild/` (made by
//! `scripts/make-wild-fixtures.py`): one 40 s drive with a known truth (0.3 deg/s gyro bias,
//! standing for 8 s, a 90 deg left turn from 20 to 28 s, course 30 -> 300 deg cw) as five
//! loggers write it. Each must be detected from its files alone and give that truth back.

use gyrodrift::import::{detect, import, sniff, Detection, ImportSummary};
use gyrodrift::log::Column;
use gyrodrift::DriveLog;
use std::path::{Path, PathBuf};

fn wild(dir: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild").join(dir);
    let mut v: Vec<PathBuf> = std::fs::read_dir(&root).unwrap().map(|e| e.unwrap().path()).collect();
    v.sort();
    v
}

fn name(p: &Path) -> String {
    p.file_name().unwrap().to_string_lossy().into_owned()
}

fn detect_and_import(paths: &[PathBuf]) -> gyrodrift::Result<(Detection, DriveLog, ImportSummary)> {
    let sniffed = paths.iter().map(|p| sniff(&name(p), &std::fs::read(p).unwrap())).collect::<gyrodrift::Result<Vec<_>>>()?;
    let d = detect(&sniffed)?;
    let mut files = |n: &str| -> gyrodrift::Result<Box<dyn std::io::Read>> {
        let p = paths.iter().find(|p| name(p) == n).expect("a detected file");
        Ok(Box::new(std::fs::File::open(p).unwrap()))
    };
    let (log, summary) = import(&d.recipe, &mut files)?;
    Ok((d, log, summary))
}

/// Mean gyro over [a, b) s from the first row, deg/s.
fn mean_rate(log: &DriveLog, a: f64, b: f64) -> f64 {
    let (t, g) = (log.time_s(), log.column(Column::GyroDps).unwrap());
    let sel: Vec<f64> = t.iter().zip(g).filter(|(x, g)| **x - t[0] >= a && **x - t[0] < b && g.is_finite()).map(|(_, g)| *g).collect();
    sel.iter().sum::<f64>() / sel.len() as f64
}

/// The first and last reference heading (deg, ccw) and how many there are.
fn reference(log: &DriveLog) -> (f64, f64, usize) {
    let r: Vec<f64> = log.column(Column::RefHeadingDeg).unwrap().iter().copied().filter(|x| x.is_finite()).collect();
    (r[0], r[r.len() - 1], r.len())
}

fn check_truth(dir: &str, preset: &str) -> (Detection, ImportSummary) {
    let (d, log, s) = detect_and_import(&wild(dir)).unwrap_or_else(|e| panic!("{dir}: {e}"));
    assert_eq!(d.preset, preset, "{dir}");
    // Bias while standing, counter-clockwise positive, deg/s.
    let bias = mean_rate(&log, 0.5, 7.5);
    assert!((bias - 0.3).abs() < 0.01, "{dir}: bias {bias}");
    // The left turn: +90 deg of rate above the bias over 20-28 s.
    let turn = (mean_rate(&log, 20.0, 28.0) - bias) * 8.0;
    assert!((turn - 90.0).abs() < 3.0, "{dir}: turn {turn}");
    // The reference sees the same left turn (course 30 -> 300 cw = -30 -> +60 ccw).
    let (first, last, _) = reference(&log);
    let change = (last - first + 540.0).rem_euclid(360.0) - 180.0;
    assert!((change - 90.0).abs() < 3.0, "{dir}: reference change {change} ({first} -> {last})");
    (d, s)
}

#[test]
fn sensorlog_one_reference_per_fix_and_time_policies_counted() {
    let (d, s) = check_truth("sensorlog", "sensorlog");
    // 1 Hz fixes repeated on 20 Hz rows: one sample per fix (speed > 5 m/s from t = 11 s).
    let (_, _, n) = reference(&detect_and_import(&wild("sensorlog")).unwrap().1);
    assert!((28..=31).contains(&n), "{n} reference samples");
    assert_eq!((s.time_fixes.merged_duplicates, s.time_fixes.sorted_backward), (1, 1));
    assert_eq!(d.used, [("log", "SensorLog.csv".to_string())]);
}

#[test]
fn sensor_logger_folder_uses_gravity_and_location_and_ignores_the_rest() {
    let (d, _) = check_truth("sensor-logger", "sensor-logger");
    let roles: Vec<&str> = d.used.iter().map(|u| u.0).collect();
    assert_eq!(roles, ["gyro", "gravity", "location"]);
    assert_eq!(d.ignored, ["Accelerometer.csv", "Metadata.csv"]);
}

#[test]
fn phyphox_semicolons_and_decimal_commas() {
    let (d, _) = check_truth("phyphox", "phyphox");
    let t = &d.recipe_json["table"][0];
    assert_eq!((t["delimiter"].as_str(), t["decimal_comma"].as_bool()), (Some(";"), Some(true)));
}

#[test]
fn px4_and_ros_exports() {
    check_truth("px4", "px4");
    let (d, _) = check_truth("ros", "ros");
    assert_eq!(d.recipe_json["heading"]["source"], "positions");
}

#[test]
fn a_gyro_file_alone_imports_without_reference() {
    let gyro: Vec<PathBuf> = wild("sensor-logger").into_iter().filter(|p| name(p) == "Gyroscope.csv").collect();
    let (d, log, _) = detect_and_import(&gyro).unwrap();
    assert_eq!(d.preset, "sensor-logger");
    assert!(log.column(Column::RefHeadingDeg).is_none());
    // No gravity: the phone's z axis alone (here nearly level with the road, so small).
    assert!(d.recipe_json["yaw_rate"]["column"] == "z");
}

#[test]
fn no_fit_names_the_closest_preset_and_the_missing_column() {
    let s = sniff("drive.csv", b"time,seconds_elapsed,x,y\n0,0,1,2\n").unwrap();
    let e = detect(&[s]).unwrap_err().to_string();
    assert!(e.contains("drive.csv") && e.contains("sensor-logger") && e.contains("lacks the column z"), "{e}");
    let s = sniff("other.csv", b"alpha;beta\n1;2\n").unwrap();
    let e = detect(&[s]).unwrap_err().to_string();
    assert!(e.contains("no logger preset") && e.contains("other.csv") && e.contains("alpha, beta"), "{e}");
    assert!(detect(&[]).is_err());
}

#[test]
fn a_bad_file_in_a_detected_set_names_file_line_and_column() {
    let dir = std::env::temp_dir().join(format!("gyrodrift-presets-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut paths = Vec::new();
    for p in wild("phyphox") {
        let mut text = std::fs::read_to_string(&p).unwrap();
        if name(&p) == "Gyroscope.csv" {
            let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
            lines[41] = lines[41].replacen(';', ";abc", 1);
            text = lines.join("\n");
        }
        let q = dir.join(name(&p));
        std::fs::write(&q, text).unwrap();
        paths.push(q);
    }
    let e = detect_and_import(&paths).expect_err("a bad cell").to_string();
    assert!(e.contains("Gyroscope.csv") && e.contains("line 42") && e.contains("Gyroscope x (rad/s)"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn mixed_clocks_and_a_truncated_last_row() {
    let paths = wild("sensor-logger");
    let sniffed: Vec<_> = paths.iter().map(|p| sniff(&name(p), &std::fs::read(p).unwrap()).unwrap()).collect();
    let d = detect(&sniffed).unwrap();
    let read = |n: &str, cut: usize| -> Vec<u8> {
        let b = std::fs::read(paths.iter().find(|p| name(p) == n).unwrap()).unwrap();
        b[..b.len() - cut].to_vec()
    };
    // The location on its epoch-ns clock, the gyro on seconds since the start: refused.
    let mut v = d.recipe_json.clone();
    for t in v["table"].as_array_mut().unwrap() {
        if t["id"] == "location" {
            t["time"] = serde_json::json!({ "column": "time", "unit": "ns" });
        }
    }
    let recipe: gyrodrift::import::Recipe = serde_json::from_value(v).unwrap();
    let mut files: std::collections::BTreeMap<String, Vec<u8>> =
        ["Gyroscope.csv", "Gravity.csv", "Location.csv"].iter().map(|n| (n.to_string(), read(n, 0))).collect();
    let e = import(&recipe, &mut files).unwrap_err().to_string();
    assert!(e.contains("Location.csv") && e.contains("Gyroscope.csv") && e.contains("different clocks"), "{e}");
    // A file cut inside its last row (a logger killed mid-write): the rows before it import,
    // the cut row's missing values stay missing.
    files.insert("Gyroscope.csv".into(), read("Gyroscope.csv", 25));
    let (_, s) = import(&d.recipe, &mut files).unwrap();
    assert_eq!(s.n_gyro, 999);
}
