//! `gyrodrift import` on small files with known content (units, signs, ISO time, projection
//! on gravity, course from positions, wheel-speed odometry), its errors, and the pipeline
//! and the method comparison on the result.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn dir(name: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&p);
    std::fs::create_dir_all(&p).unwrap();
    p
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gyrodrift")).args(args).output().unwrap()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// 10 Hz phone-like IMU (ISO time, rad/s, clockwise positive on one axis) and 1 Hz GPS
/// (bearing clockwise from north, speed): 30 s standing, then a right turn of 2 deg/s.
fn phone_like(d: &Path) {
    let mut imu = String::from("time,w\n");
    for i in 0..600 {
        let t = i as f64 / 10.0;
        // + a bias step of 0.1 deg/s after the lead-in, so the methods have drift to reduce
        let cw_dps: f64 = if t >= 30.0 { 2.1 } else { 0.0 };
        let secs = 5 + i / 10; // starts 2023-08-06 10:48:05-04:00
        imu.push_str(&format!("2023-08-06 10:{}:{:02}.{}-04:00,{}\n", 48 + secs / 60, secs % 60, i % 10, cw_dps.to_radians()));
    }
    std::fs::write(d.join("imu.csv"), imu).unwrap();
    let mut gps = String::from("time,speed,bearing\n");
    for k in 0..60 {
        let t = k as f64;
        let (v, b) = if t >= 30.0 { (8.0, (t - 30.0) * 2.0) } else { (0.0, 0.0) };
        gps.push_str(&format!("2023-08-06 10:{}:{:02}-04:00,{v},{b}\n", 48 + (5 + k) / 60, (5 + k) % 60));
    }
    std::fs::write(d.join("gps.csv"), gps).unwrap();
    std::fs::write(
        d.join("r.toml"),
        r#"name = "phone"
bias_s = 10
[[table]]
id = "imu"
file = "imu.csv"
time = { column = "time", format = "iso8601" }
[[table]]
id = "gps"
file = "gps.csv"
time = { column = "time", format = "iso8601" }
[yaw_rate]
table = "imu"
column = "w"
unit = "rad/s"
positive = "cw"
[heading]
source = "column"
table = "gps"
column = "bearing"
unit = "deg"
positive = "cw"
speed_column = "speed"
min_speed_mps = 5.0
[speed]
source = "column"
table = "gps"
column = "speed"
unit = "m/s"
"#,
    )
    .unwrap();
}

fn parse(p: &Path) -> gyrodrift::DriveLog {
    gyrodrift::parse_log(std::fs::File::open(p).unwrap()).unwrap()
}

#[test]
fn import_converts_units_signs_and_time_and_merges_on_time() {
    let d = dir("import-phone");
    phone_like(&d);
    let out = d.join("drive.csv");
    let o = run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&out), "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sum: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(sum["n_gyro"], 600);
    assert_eq!(sum["n_reference"], 30, "bearing kept only above 5 m/s");
    // 2023-08-06 14:48:05 UTC
    assert_eq!(sum["start_time_s"], 1_691_333_285.0);
    let log = parse(&out);
    use gyrodrift::Column::*;
    let (t, g, r, v) = (log.time_s(), log.column(GyroDps).unwrap(), log.column(RefHeadingDeg).unwrap(), log.column(SpeedMps).unwrap());
    assert_eq!(log.len(), 600, "GPS stamps fall on IMU rows: merged, not added");
    assert_eq!(t[0], 0.0);
    assert!((t[1] - 0.1).abs() < 1e-6);
    let i = 350; // t = 35 s: turning right at 2 deg/s (+0.1 bias) = -2.1 deg/s CCW; bearing 10 -> ref -10
    assert!((g[i] + 2.1).abs() < 1e-12, "{}", g[i]);
    assert!((r[i] + 10.0).abs() < 1e-12, "{}", r[i]);
    assert_eq!(v[i], 8.0);
    assert!(r[355].is_nan(), "reference only at its own times");
    assert!((v[355] - 8.0).abs() < 1e-12, "speed interpolated onto every row");
    assert_eq!(log.meta.bias_s, Some(10.0));
    // The pipeline and HDR run on it: 0.1 deg/s of drift over 30 s -> raw E_psi ~ 0.1 * 15.
    let o = run(&["pipeline", s(&out), "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let p: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let e_raw = p["E_psi_raw_deg"].as_f64().unwrap();
    assert!((1.0..2.0).contains(&e_raw), "{p}");
}

#[test]
fn pipeline_json_has_the_issue_keys() {
    let d = dir("import-keys");
    phone_like(&d);
    let out = d.join("drive.csv");
    assert!(run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&out)]).status.success());
    let o = run(&["pipeline", s(&out), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for k in [
        "E_psi_raw_deg",
        "E_psi_hdr_deg",
        "E_psi_pipeline_deg",
        "NE_psi_raw_deg_per_min",
        "NE_psi_hdr_deg_per_min",
        "NE_psi_pipeline_deg_per_min",
        "improvement_pipeline",
        "duration_min",
    ] {
        assert!(v[k].is_number(), "{k} missing in {v}");
    }
    let e_raw = v["E_psi_raw_deg"].as_f64().unwrap();
    let e_pipe = v["E_psi_pipeline_deg"].as_f64().unwrap();
    // serde_json's default float parser is not correctly rounded: compare to 1e-12.
    assert!((v["improvement_pipeline"].as_f64().unwrap() / (e_raw / e_pipe) - 1.0).abs() < 1e-12);
    assert!(v["NE_psi_pipeline_smoothed_deg_per_min"].is_number());
    let o = run(&["pipeline", s(&out), "--set", "road_gate_dps=-1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("road_gate_dps"));
    let o = run(&["report", "--compare", s(&out), s(&out)]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success() && text.contains("| phone |") && text.contains("**Mean of 2**"), "{text}");
}

#[test]
fn projection_on_gravity_positions_course_and_wheel_odometry() {
    let d = dir("import-proj");
    // Tilted mount: up = (0, 0.6, 0.8) in the sensor frame; the vehicle turns left at
    // 3 deg/s after 10 s, so the gyro reads 3 * up; it drives east at 10 m/s on a
    // lat/lon track, wheel speeds differ by (3 deg/s in rad) * track 1.5 m.
    let (mut imu, mut gps) = (String::from("t,gx,gy,gz,ax,ay,az\n"), String::from("t,lat,lon,vl,vr\n"));
    for i in 0..400 {
        let t = i as f64 * 0.05;
        let w = if t >= 10.0 { 3.0 } else { 0.0 };
        imu.push_str(&format!("{t},{},{},{},{},{},{}\n", 0.0, 0.6 * w, 0.8 * w, 0.0, 0.6 * 9.81, 0.8 * 9.81));
    }
    for k in 0..20 {
        let t = k as f64;
        let lon = 10.0 + (10.0 * t) / (6_378_137.0 * 50f64.to_radians().cos()) * 180.0 / std::f64::consts::PI;
        let dv = if t >= 10.0 { 3f64.to_radians() * 1.5 / 2.0 } else { 0.0 };
        gps.push_str(&format!("{t},50.0,{lon},{},{}\n", 10.0 - dv, 10.0 + dv));
    }
    std::fs::write(d.join("imu.csv"), imu).unwrap();
    std::fs::write(d.join("gps.csv"), gps).unwrap();
    std::fs::write(
        d.join("r.toml"),
        r#"bias_s = 5
[[table]]
id = "imu"
file = "imu.csv"
time = { column = "t" }
[[table]]
id = "gps"
file = "gps.csv"
time = { column = "t" }
[yaw_rate]
table = "imu"
axes = ["gx", "gy", "gz"]
gravity = { axes = ["ax", "ay", "az"], first_s = 5 }
unit = "deg/s"
positive = "ccw"
[positions]
table = "gps"
kind = "latlon"
columns = ["lat", "lon"]
[heading]
source = "positions"
min_distance_m = 5.0
[odometry]
table = "gps"
left = ["vl"]
right = ["vr"]
kind = "speed"
unit = "m/s"
track_m = 1.5
"#,
    )
    .unwrap();
    let out = d.join("x.csv");
    let o = run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&out), "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sum: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!((sum["up"][1].as_f64().unwrap() - 0.6).abs() < 1e-9 && (sum["up"][2].as_f64().unwrap() - 0.8).abs() < 1e-9);
    let log = parse(&out);
    use gyrodrift::Column::*;
    let g = log.column(GyroDps).unwrap();
    let t = log.time_s();
    let i = t.iter().position(|&x| x >= 12.0).unwrap();
    assert!((g[i] - 3.0).abs() < 1e-9, "projected rate {}", g[i]);
    // Course 90 deg (east) -> ref -90 (CCW convention), at segment middles 0.5, 1.5, ...
    let r = log.column(RefHeadingDeg).unwrap();
    let refs: Vec<(f64, f64)> = t.iter().zip(r).filter(|(_, v)| v.is_finite()).map(|(&t, &v)| (t, v)).collect();
    assert_eq!(refs.len(), 19);
    assert!((refs[0].0 - 0.5).abs() < 1e-9);
    assert!(refs.iter().all(|(_, v)| (v + 90.0).abs() < 0.01), "{refs:?}");
    // Wheel odometry: (dR - dL) / track over the turn = 3 deg/s.
    assert_eq!(log.meta.wheelbase_m, Some(1.5));
    let o = run(&["gyrodometry", s(&out), "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn bad_recipes_and_files_exit_2_naming_what_is_wrong() {
    let d = dir("import-bad");
    phone_like(&d);
    let base = std::fs::read_to_string(d.join("r.toml")).unwrap();
    let cases: Vec<(String, &str)> = vec![
        (base.replace("column = \"w\"", "column = \"w_y\""), "missing column w_y"),
        (base.replace("unit = \"rad/s\"", "unit = \"rad\""), "not a rate unit"),
        (base.replace("file = \"gps.csv\"", "file = \"nope.csv\""), "nope.csv: cannot open"),
        (base.replace("table = \"imu\"\ncolumn", "table = \"imux\"\ncolumn"), "no [[table]] with id \"imux\""),
        (base.replace("positive = \"cw\"\n[heading]", "[heading]"), "missing field `positive`"),
        (base.replace("format = \"iso8601\" }\n[[table]]", "format = \"iso8601\", colour = 1 }\n[[table]]"), "unknown field `colour`"),
        (
            base.replace(
                "source = \"column\"\ntable = \"gps\"\ncolumn = \"bearing\"",
                "source = \"positions\"\ntable = \"gps\"\ncolumn = \"bearing\"",
            ),
            "heading: `table` is not used with source = \"positions\"",
        ),
        (base.replace("column = \"bearing\"\n", ""), "heading: source = \"column\" needs `column`"),
    ];
    for (i, (text, want)) in cases.iter().enumerate() {
        let r = d.join(format!("bad{i}.toml"));
        std::fs::write(&r, text).unwrap();
        let o = run(&["import", "--recipe", s(&r), "--out", s(&d.join("o.csv"))]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "case {i}: {err}");
        assert!(err.contains(want), "case {i}: want {want:?} in {err:?}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // A bad cell names file, line and column; a time that goes back too.
    let imu = std::fs::read_to_string(d.join("imu.csv")).unwrap();
    std::fs::write(d.join("imu.csv"), imu.replacen(",0\n", ",zero\n", 1)).unwrap();
    let o = run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&d.join("o.csv"))]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("imu.csv: line 2, column w: \"zero\" is not a number"), "{err}");
    let lines: Vec<&str> = imu.lines().collect();
    let mut swapped = lines.clone();
    swapped.swap(5, 6);
    std::fs::write(d.join("imu.csv"), swapped.join("\n")).unwrap();
    // By default a row a little late is put in time order, and the summary says so ...
    let o = run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&d.join("o.csv"))]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && err.contains("1 late rows put in time order"), "{err}");
    // ... and with backward = "error" it names the line.
    let strict = base.replacen(
        "time = { column = \"time\", format = \"iso8601\" }",
        "time = { column = \"time\", format = \"iso8601\", backward = \"error\" }",
        1,
    );
    std::fs::write(d.join("r.toml"), strict).unwrap();
    let o = run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&d.join("o.csv"))]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("imu.csv: line 7, column time") && err.contains("goes back"), "{err}");
    std::fs::write(d.join("r.toml"), &base).unwrap();
    std::fs::write(d.join("imu.csv"), "").unwrap();
    let o = run(&["import", "--recipe", s(&d.join("r.toml")), "--out", s(&d.join("o.csv"))]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("empty file"), "{}", String::from_utf8_lossy(&o.stderr));
}

/// A recipe is data: its files resolve inside --data; `..`, absolute paths and links out of
/// the folder are refused before the file is read (its content never reaches the message).
#[test]
fn recipe_files_are_confined_to_the_data_folder() {
    let d = dir("confined");
    let data = d.join("data");
    std::fs::create_dir_all(data.join("sub")).unwrap();
    std::fs::write(data.join("sub/a.csv"), "t,w\n0,1\n1,2\n").unwrap();
    let secret = d.join("secret.csv");
    std::fs::write(&secret, "t,w\nSECRET,1\n").unwrap();
    let link = data.join("link.csv");
    let _ = std::fs::remove_file(&link);
    #[cfg(unix)]
    std::os::unix::fs::symlink(&secret, &link).unwrap();
    let recipe = |file: &str| {
        let r = d.join("r.toml");
        let text = format!(
            "bias_s = 0\n[[table]]\nid = \"a\"\nfile = \"{file}\"\ntime = {{ column = \"t\" }}\n[yaw_rate]\ntable = \"a\"\ncolumn = \"w\"\nunit = \"deg/s\"\npositive = \"ccw\"\n"
        );
        std::fs::write(&r, text).unwrap();
        r
    };
    let out = d.join("o.csv");
    for bad in ["../secret.csv", secret.to_str().unwrap(), "link.csv", "sub/../../secret.csv"] {
        let o = run(&["import", "--recipe", s(&recipe(bad)), "--data", s(&data), "--out", s(&out)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{bad}: {err}");
        assert!(err.contains("refused") && !err.contains("SECRET"), "{bad}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    let o = run(&["import", "--recipe", s(&recipe("sub/a.csv")), "--data", s(&data), "--out", s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = run(&["import", "--recipe", s(&recipe("../secret.csv")), "--data", s(&data), "--out", s(&out), "--allow-outside"]);
    assert_eq!(o.status.code(), Some(2), "read on request, then a cell error");
    assert!(String::from_utf8_lossy(&o.stderr).contains("line 2, column t"));
}

fn wild(name: &str) -> Vec<String> {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild").join(name);
    let mut v: Vec<String> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path().display().to_string()).collect();
    v.sort();
    v
}

/// A logger's sample export (`sample-logs/wild/NAME`) copied into `to`, as an unzipped export.
fn copy_wild(name: &str, to: &Path) {
    for f in wild(name) {
        std::fs::copy(&f, to.join(PathBuf::from(&f).file_name().unwrap())).unwrap();
    }
}

/// Without --recipe: the preset is detected and named; its recipe printed as TOML imports
/// the same log through --recipe; files that fit no preset get the closest one's gap.
#[test]
fn import_without_recipe_detects_says_and_prints_a_reusable_recipe() {
    let d = dir("detect");
    let files = wild("sensor-logger");
    let mut args = vec!["import"];
    args.extend(files.iter().map(String::as_str));
    let direct = d.join("direct.csv");
    let o = run(&[args.as_slice(), &["--out", s(&direct)]].concat());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("detected preset sensor-logger") && err.contains("not used: Accelerometer.csv, Metadata.csv"), "{err}");
    let o = run(&[args.as_slice(), &["--print-recipe"]].concat());
    assert!(o.status.success());
    let recipe = d.join("r.toml");
    std::fs::write(&recipe, &o.stdout).unwrap();
    let folder = PathBuf::from(&files[0]).parent().unwrap().to_path_buf();
    let via = d.join("via.csv");
    let o = run(&["import", "--recipe", s(&recipe), "--data", s(&folder), "--out", s(&via)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(parse(&direct).time_s(), parse(&via).time_s());
    assert_eq!(parse(&direct).columns().len(), parse(&via).columns().len());

    // A file no preset reads: an error with the closest preset and the missing column.
    let odd = d.join("Gyroscope.csv");
    std::fs::write(&odd, "time,seconds_elapsed,x,y\n0,0,1,2\n").unwrap();
    let o = run(&["import", s(&odd)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "{err}");
    assert!(err.contains("closest preset is sensor-logger") && err.contains("lacks the column z"), "{err}");
    // Neither files nor a recipe, or both: a usage error naming the arguments.
    for o in [run(&["import"]), run(&["import", s(&odd), "--recipe", s(&recipe)])] {
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.contains("Usage") && err.contains("--recipe"), "{err}");
    }
}

/// A logger's zipped export: imported as it is and named by the archive; its printed
/// recipe says where its data is (the zip, or the files' folder) in a command that runs as
/// printed, and that recipe on the zip gives the same log.
#[test]
fn a_zipped_export_imports_and_its_recipe_reads_the_zip_again() {
    use std::io::Write;
    let d = dir("zipped export");
    let zip = d.join("Drive 2026-11-27.zip");
    let mut w = zip::ZipWriter::new(std::fs::File::create(&zip).unwrap());
    for f in wild("sensor-logger") {
        let name = format!("Drive/{}", PathBuf::from(&f).file_name().unwrap().to_string_lossy());
        w.start_file(name, zip::write::SimpleFileOptions::default()).unwrap();
        w.write_all(&std::fs::read(&f).unwrap()).unwrap();
    }
    w.finish().unwrap();
    let direct = d.join("direct.csv");
    let o = run(&["import", s(&zip), "--out", s(&direct)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("Drive 2026-11-27.zip: 1000 rows"), "{err}");
    assert_eq!(parse(&direct).meta.name.as_deref(), Some("Drive 2026-11-27"));
    let o = run(&["import", s(&zip), "--print-recipe"]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let first = text.lines().next().unwrap();
    assert_eq!(first, format!("# gyrodrift import --recipe THIS.toml --data '{}' (preset sensor-logger)", zip.display()));
    assert!(text.contains("name = \"Drive 2026-11-27\""), "{text}");
    let recipe = d.join("r.toml");
    std::fs::write(&recipe, &text).unwrap();
    let via = d.join("via.csv");
    let o = run(&["import", "--recipe", s(&recipe), "--data", s(&zip), "--out", s(&via)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read(&via).unwrap(), std::fs::read(&direct).unwrap());
    // Files from one folder: that folder.
    let files = wild("sensor-logger");
    let o = run(&[&["import", "--print-recipe"], files.iter().map(String::as_str).collect::<Vec<_>>().as_slice()].concat());
    let folder = PathBuf::from(&files[0]).parent().unwrap().display().to_string();
    assert!(String::from_utf8_lossy(&o.stdout).starts_with(&format!("# gyrodrift import --recipe THIS.toml --data {folder} (")));
}

/// A logger's export folder (unzipped) given alone: its files imported (hidden ones left
/// out), the log and the printed recipe named by the folder, the recipe's `--data` the
/// folder; a folder among files, or an empty one, is an error saying so.
#[test]
fn a_folder_imports_as_its_files_named_by_the_folder() {
    let d = dir("folder export");
    let folder = d.join("Drive 2026-11-27");
    std::fs::create_dir_all(&folder).unwrap();
    copy_wild("sensor-logger", &folder);
    std::fs::write(folder.join(".DS_Store"), b"\x00\x01bin").unwrap();
    let (from_folder, from_files) = (d.join("folder.csv"), d.join("files.csv"));
    let o = run(&["import", s(&folder), "--out", s(&from_folder)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("Drive 2026-11-27: 1000 rows"), "{err}");
    let files = wild("sensor-logger");
    let o = run(&[&["import", "--out", s(&from_files)], files.iter().map(String::as_str).collect::<Vec<_>>().as_slice()].concat());
    assert!(o.status.success());
    let (a, b) = (parse(&from_folder), parse(&from_files));
    assert_eq!(a.meta.name.as_deref(), Some("Drive 2026-11-27"));
    assert_eq!((a.time_s(), a.column(gyrodrift::Column::GyroDps)), (b.time_s(), b.column(gyrodrift::Column::GyroDps)));
    let o = run(&["import", s(&folder), "--print-recipe"]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(text.starts_with(&format!("# gyrodrift import --recipe THIS.toml --data '{}' (", folder.display())), "{text}");
    assert!(text.contains("name = \"Drive 2026-11-27\""), "{text}");
    let o = run(&["import", s(&folder), &files[0]]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("a folder among files: give the folder alone, or its files"));
    let empty = d.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let o = run(&["import", s(&empty)]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("empty: no files in this folder to import"));
}

/// A logger's folder with a README.md and a photo beside its tables imports, both named as
/// not used; a folder of recordings (a SOURCE.md and one folder per recording) is answered
/// with the folders to import alone, and no draft recipe is made of its prose.
#[test]
fn prose_and_binaries_beside_the_tables_are_left_out_and_a_folder_of_recordings_names_its_folders() {
    let d = dir("folder of recordings");
    let trip = d.join("trip 1");
    std::fs::create_dir_all(&trip).unwrap();
    copy_wild("sensor-logger", &trip);
    std::fs::write(trip.join("README.md"), "Phone on the dashboard, screen up, recorded with Sensor Logger, 10 minutes.\n").unwrap();
    std::fs::write(trip.join("photo.jpg"), b"\xff\xd8\xff\xe0\x00\x10JFIF\x00").unwrap();
    let out = dir("folder of recordings out").join("trip.csv");
    let o = run(&["import", s(&trip), "--out", s(&out)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("not used: Accelerometer.csv, Metadata.csv, README.md, photo.jpg") && err.contains("trip 1: 1000 rows"), "{err}");
    std::fs::create_dir_all(d.join("trip 2")).unwrap();
    std::fs::write(d.join("SOURCE.md"), "Two drives, one per folder, recorded with Sensor Logger, phone on the dashboard.\n").unwrap();
    let o = run(&["import", s(&d)]);
    assert_eq!(o.status.code(), Some(2));
    let want = format!(
        "SOURCE.md: a Markdown document, not a table. Its folders may each hold a recording, to import alone: trip 1, trip 2 (gyrodrift import {})",
        trip.display()
    );
    assert_eq!(String::from_utf8_lossy(&o.stderr).trim_end(), want);
    let o = run(&["import", s(&d), "--print-recipe"]);
    assert_eq!((o.status.code(), o.stdout.is_empty()), (Some(2), true), "{}", String::from_utf8_lossy(&o.stdout));
}

/// A logger's raw export given to a method: the error names the file and line, and the
/// import command that makes a v1 log of it, with the files beside it that the preset uses;
/// a table no preset reads gets the error alone.
#[test]
fn a_raw_export_given_to_a_method_is_answered_with_the_import_command() {
    let px4 = wild("px4");
    let o = run(&["pipeline", &px4[0]]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("line 1: missing required column time_s"), "{err}");
    assert!(err.contains("(import preset px4): `gyrodrift import"), "{err}");
    assert!(px4.iter().all(|f| err.contains(f.as_str())), "both files: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    let d = dir("no-preset");
    let odd = d.join("table.csv");
    std::fs::write(&odd, "a,b\n1,2\n").unwrap();
    let o = run(&["hdr", s(&odd)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("missing required column time_s") && !err.contains("import preset"), "{err}");
}

/// A folder given to a method: one line saying so, with the import command when a preset
/// reads the recording in it, else the folder batch.
#[test]
fn a_folder_given_to_a_method_is_answered_with_the_import_or_the_batch() {
    let phyphox = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild/phyphox");
    let o = run(&["pipeline", s(&phyphox)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("a folder, not a log file") && err.contains("(import preset phyphox): `gyrodrift import"), "{err}");
    assert!(wild("phyphox").iter().all(|f| err.contains(f.as_str())), "every file: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    let train = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/train");
    let o = run(&["hdr", s(&train)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("a folder, not a log file; to score every log in it: `gyrodrift report --dir"), "{err}");
}

/// A logger's own CSV that no preset reads: the import's error offers a draft, and the draft
/// `--print-recipe` writes from the column names imports it as written (City 1 with ms time,
/// the course clockwise and the speed in km/h: HDR as on the log itself, the course kept
/// above the draft's 5 m/s).
#[test]
fn files_no_preset_reads_get_a_draft_recipe_from_their_column_names() {
    let d = dir("draft");
    let v1 = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/train/city-1.csv");
    let mut mine = String::from("stamp_ms,gyro_z_dps,course,speed_kmh\n");
    for line in std::fs::read_to_string(&v1).unwrap().lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let num = |s: &str| s.parse::<f64>().ok();
        let course = num(f[3]).map_or(String::new(), |h| (-h).to_string());
        mine.push_str(&format!("{},{},{course},{}\n", num(f[0]).unwrap() * 1000.0, f[1], num(f[4]).unwrap() * 3.6));
    }
    let file = d.join("my-logger.csv");
    std::fs::write(&file, mine).unwrap();
    let o = run(&["import", s(&file)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.contains("--print-recipe drafts one from the column names"), "{err}");
    let o = run(&["import", s(&file), "--print-recipe"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(text.contains("#   yaw_rate: my-logger.csv column \"gyro_z_dps\", deg/s") && text.contains("unit = \"km/h\""), "{text}");
    let recipe = d.join("draft.toml");
    std::fs::write(&recipe, text.as_bytes()).unwrap();
    let imported = d.join("imported.csv");
    let o = run(&["import", "--recipe", s(&recipe), "--data", s(&d), "--out", s(&imported)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let hdr = |p: &Path| -> serde_json::Value {
        let o = run(&["hdr", s(p), "--set", "bias_s=20", "--json"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let (a, b) = (hdr(&v1)["E_psi_hdr_deg"].as_f64().unwrap(), hdr(&imported)["E_psi_hdr_deg"].as_f64().unwrap());
    assert!((a - b).abs() < 0.5, "{a} vs {b}");
}
