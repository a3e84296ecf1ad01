//! `report --dir`: a folder of logs scored in parallel; a bad file is a row with its error
//! while the rest are scored; the rows go to Parquet, CSV or JSON.

use std::path::PathBuf;
use std::process::Command;

/// A folder of logs of its own per test (tests run in parallel).
fn fleet_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("day2")).unwrap();
    let samples = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs");
    std::fs::copy(samples.join("train/city-1.csv"), dir.join("city-1.csv")).unwrap();
    std::fs::copy(samples.join("test/highway-3.csv"), dir.join("day2/highway-3.csv")).unwrap();
    std::fs::write(dir.join("day2/broken.csv"), "time_s,gyro_dps,ref_heading_deg\n0,0.1,0\n1,abc,0\n").unwrap();
    std::fs::write(dir.join("notes.txt"), "not a log").unwrap();
    dir
}

fn report_dir(dir: &PathBuf, extra: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_gyrodrift")).arg("report").arg("--dir").arg(dir).args(extra).output().unwrap()
}

#[test]
fn a_folder_is_scored_with_a_bad_file_as_an_error_row() {
    let dir = fleet_dir("fleet-a");
    let csv = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-rows.csv");
    let o = report_dir(&dir, &["--jobs", "2", "--out", csv.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(stdout.starts_with("3 files, 2 drives scored"), "{stdout}");
    assert!(stdout.contains("| HDR Table III | 2 |"), "{stdout}");
    assert!(stderr.contains("broken.csv: line 3, column gyro_dps"), "{stderr}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "{text}");
    // Sorted by path: city-1, day2/broken, day2/highway-3.
    assert!(lines[1].contains("city-1.csv,1,1,City 1,"), "{}", lines[1]);
    assert!(
        lines[2].contains("broken.csv") && lines[2].ends_with("\"line 3, column gyro_dps: \"\"abc\"\" is not a number\","),
        "{}",
        lines[2]
    );
    assert!(lines[3].contains("Highway 3"), "{}", lines[3]);
}

/// Files refused for what an option reads (a time that repeats, logs joined on, a clock
/// reset) or runs anyway (a unit or sign mistake `check` finds) are error rows with the
/// refusal's kind in `error_code`, and the option is named once for them all; with the
/// options given, each is scored.
#[test]
fn refusals_an_option_reads_are_counted_by_kind_and_name_the_option_once() {
    let dir = fleet_dir("fleet-kinds");
    let city = std::fs::read_to_string(dir.join("city-1.csv")).unwrap();
    let (head, rows) = city.split_at(city.find("time_s,").unwrap());
    let rows: Vec<&str> = rows.lines().collect();
    let repeated = format!("{head}{}\n{}\n{}\n", rows[..3].join("\n"), rows[2], rows[3..].join("\n"));
    std::fs::write(dir.join("repeat.csv"), repeated).unwrap();
    std::fs::write(dir.join("joined.csv"), format!("{city}{city}")).unwrap();
    std::fs::write(dir.join("reset.csv"), format!("{city}{}\n", rows[1..].join("\n"))).unwrap();
    // A clockwise gyro: every rate negated (the gyro is the second column).
    let cw: Vec<String> = city
        .lines()
        .map(|l| match l.split_once(',') {
            Some((t, rest)) if !l.starts_with('#') && !l.starts_with("time_s") => {
                let (g, more) = rest.split_once(',').unwrap();
                format!("{t},{},{more}", -g.parse::<f64>().unwrap())
            }
            _ => l.to_string(),
        })
        .collect();
    std::fs::write(dir.join("cw.csv"), cw.join("\n") + "\n").unwrap();
    let json = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-kinds.json");
    let o = report_dir(&dir, &["--out", json.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let code = |file: &str| {
        let r = v.as_array().unwrap().iter().find(|r| r["file"].as_str().unwrap().ends_with(file)).unwrap();
        r["error_code"].as_str().map(str::to_string)
    };
    let got: Vec<Option<String>> = ["repeat.csv", "joined.csv", "reset.csv", "cw.csv", "broken.csv", "city-1.csv"].map(code).into();
    let want = ["time_order", "joined", "clock_reset", "check"].map(|c| Some(c.to_string()));
    assert_eq!(got, [&want[..], &[None, None]].concat());
    let hint = |s: &str| stderr.matches(s).count();
    assert_eq!(
        hint("1 file refused for a time that repeats or steps back by at most 1 s: `--time-order fix` puts it in order"),
        1,
        "{stderr}"
    );
    assert_eq!(hint("2 files refused for a second log joined on or a clock reset: `--joined split`"), 1, "{stderr}");
    assert_eq!(hint("1 file refused for a unit or sign mistake check found: `gyrodrift check FILE` names each fix"), 1, "{stderr}");
    let o = report_dir(&dir, &["--time-order", "fix", "--joined", "split", "--ignore-check"]);
    let (stdout, stderr) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(stdout.starts_with("7 files, 8 drives scored") && !stderr.contains("refused for"), "{stdout}{stderr}");
}

/// A CI job's exit: 1 with --fail-on-error when a file is an error row (the rows written
/// all the same), 0 when every file is scored; a fleet job's 0 without the flag (above).
#[test]
fn fail_on_error_exits_1_after_writing_every_row() {
    let dir = fleet_dir("fleet-fail");
    let csv = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-fail-rows.csv");
    let o = report_dir(&dir, &["--fail-on-error", "--out", csv.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("1 of 3 rows are errors (--fail-on-error)"), "{stderr}");
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("3 files, 2 drives scored"));
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 4);
    std::fs::remove_file(dir.join("day2/broken.csv")).unwrap();
    let o = report_dir(&dir, &["--fail-on-error"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn one_job_and_two_give_the_same_rows_as_json_and_parquet() {
    let dir = fleet_dir("fleet-b");
    let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let (a, b) = (tmp.join("fleet-1.json"), tmp.join("fleet-2.json"));
    assert!(report_dir(&dir, &["--jobs", "1", "--out", a.to_str().unwrap()]).status.success());
    assert!(report_dir(&dir, &["--jobs", "2", "--out", b.to_str().unwrap()]).status.success());
    let rows: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&a).unwrap()).unwrap();
    assert_eq!(rows, serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&b).unwrap()).unwrap());
    assert_eq!(rows.as_array().unwrap().len(), 3);
    assert!(rows[0]["ne_psi_hdr_deg_per_min"].as_f64().unwrap() > 0.0);
    assert!(rows[1]["ne_psi_hdr_deg_per_min"].is_null());
    let pq = tmp.join("fleet.parquet");
    assert!(report_dir(&dir, &["--out", pq.to_str().unwrap()]).status.success());
    assert_eq!(&std::fs::read(&pq).unwrap()[..4], b"PAR1");
}

#[test]
fn bad_batch_arguments_exit_2() {
    let dir = fleet_dir("fleet-c");
    let o = report_dir(&dir, &["--out", "/tmp/rows.xlsx"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--out takes a .parquet, .csv or .json file"));
    let empty = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-empty");
    std::fs::create_dir_all(&empty).unwrap();
    let o = report_dir(&empty, &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no *.csv logs"));
    let o = report_dir(&dir.join("city-1.csv"), &[]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("not a folder"));
}

#[test]
fn compare_over_a_folder_is_the_same_batch_and_table_options_do_not_mix_with_it() {
    let dir = fleet_dir("fleet-d");
    let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let (a, b) = (tmp.join("fleet-d-compare.json"), tmp.join("fleet-d-report.json"));
    let run = |cmd: &str, out: &PathBuf| {
        Command::new(env!("CARGO_BIN_EXE_gyrodrift")).args([cmd, "--dir"]).arg(&dir).arg("--out").arg(out).output().unwrap()
    };
    assert!(run("compare", &a).status.success());
    assert!(run("report", &b).status.success());
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    for extra in [["report", "--markdown"], ["report", "--csv"], ["compare", "--csv"], ["report", "--no-resample"]] {
        let o = Command::new(env!("CARGO_BIN_EXE_gyrodrift")).arg(extra[0]).arg("--dir").arg(&dir).arg(extra[1]).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("cannot be used with"), "{extra:?}");
    }
}

/// A folder of a logger's raw exports: every file an error row, and one import hint per
/// recording folder (not one per file), naming the preset and the command.
#[test]
fn a_folder_of_raw_exports_gets_one_import_hint_per_recording() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild");
    let o = report_dir(&dir, &[]);
    assert!(o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    let hints: Vec<&str> = err.lines().filter(|l| l.contains("it looks like a recording of")).collect();
    assert_eq!(hints.len(), 5, "{err}");
    let sl = hints.iter().find(|l| l.contains("(import preset sensor-logger)")).unwrap();
    assert!(sl.contains("sensor-logger: ") && sl.contains("gyrodrift import ") && sl.contains("Gyroscope.csv"), "{sl}");
}

/// A logger's zipped export (as Sensor Logger shares one) in a fleet folder: with --import
/// a drive of its own, scored as the import of its files; a zip no preset reads an error
/// row saying what it is; without --import zips are not looked at.
#[test]
fn with_import_a_zipped_export_is_a_drive_of_its_own() {
    use std::io::Write;
    let dir = fleet_dir("zipped");
    let sl = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild/sensor-logger");
    let zip = |path: PathBuf, entries: &[(&str, Vec<u8>)]| {
        let mut w = zip::ZipWriter::new(std::fs::File::create(path).unwrap());
        for (name, bytes) in entries {
            w.start_file(*name, zip::write::SimpleFileOptions::default()).unwrap();
            w.write_all(bytes).unwrap();
        }
        w.finish().unwrap();
    };
    let files = ["Gyroscope.csv", "Gravity.csv", "Location.csv", "Metadata.csv"];
    let entries: Vec<(String, Vec<u8>)> = files.iter().map(|f| (format!("Drive/{f}"), std::fs::read(sl.join(f)).unwrap())).collect();
    let refs: Vec<(&str, Vec<u8>)> = entries.iter().map(|(n, b)| (n.as_str(), b.clone())).collect();
    zip(dir.join("day2/drive.zip"), &refs);
    zip(dir.join("other.zip"), &[("readme.txt", b"hello".to_vec())]);
    let json = dir.join("rows.json");
    let o = report_dir(&dir, &["--import", "--out", json.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(stderr.contains("importing 1 recording(s) of raw exports (1 files)"), "{stderr}");
    let rows: Vec<serde_json::Value> = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let drive = rows.iter().find(|r| r["file"].as_str().unwrap().ends_with("drive.zip")).unwrap();
    assert_eq!(drive["name"], "drive", "named by its archive, as a folder names its recording");
    assert!(drive["error"].is_null(), "{drive}");
    let other = rows.iter().find(|r| r["file"].as_str().unwrap().ends_with("other.zip")).unwrap();
    assert!(other["error"].as_str().unwrap().contains("a ZIP archive, not a text table"), "{other}");
    // The import of the files themselves scores the same.
    let out = dir.join("drive.csv");
    let args: Vec<PathBuf> = files[..3].iter().map(|f| sl.join(f)).collect();
    let i = Command::new(env!("CARGO_BIN_EXE_gyrodrift")).arg("import").args(&args).arg("--out").arg(&out).output().unwrap();
    assert!(i.status.success());
    let h = Command::new(env!("CARGO_BIN_EXE_gyrodrift")).args(["hdr", "--json"]).arg(&out).output().unwrap();
    let hdr: serde_json::Value = serde_json::from_slice(&h.stdout).unwrap();
    assert_eq!(drive["e_psi_hdr_deg"], hdr["E_psi_hdr_deg"]);
    // Without --import: the zips are not logs, and not looked at.
    let o = report_dir(&dir, &["--json"]);
    assert!(!String::from_utf8_lossy(&o.stderr).contains(".zip"));
}

/// With --import the raw exports are scored instead: a drive per recording (a folder of
/// several files named by the folder, a one-file export by its file), no error rows, each
/// as its log imported by `gyrodrift import` scores.
#[test]
fn with_import_a_folder_of_raw_exports_is_scored_a_drive_per_recording() {
    let wild = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild");
    let json = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("wild-rows.json");
    let o = report_dir(&wild, &["--import", "--out", json.to_str().unwrap()]);
    let (stdout, stderr) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{stderr}");
    assert!(stdout.starts_with("5 files, 5 drives scored") && stdout.contains("0 errors"), "{stdout}");
    assert!(stderr.contains("importing 5 recording(s) of raw exports (13 files)") && !stderr.contains("it looks like"), "{stderr}");
    let rows: Vec<serde_json::Value> = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let mut names: Vec<&str> = rows.iter().map(|r| r["name"].as_str().unwrap()).collect();
    names.sort();
    assert_eq!(names, ["SensorLog.csv (SensorLog)", "phyphox", "px4", "ros", "sensor-logger"]);
    // The Sensor Logger folder scores as its imported log does.
    let one = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("wild-imported");
    let _ = std::fs::remove_dir_all(&one);
    std::fs::create_dir_all(&one).unwrap();
    let sl = wild.join("sensor-logger");
    let files: Vec<PathBuf> = ["Gyroscope.csv", "Gravity.csv", "Location.csv"].iter().map(|f| sl.join(f)).collect();
    let imp =
        Command::new(env!("CARGO_BIN_EXE_gyrodrift")).arg("import").args(&files).arg("--out").arg(one.join("sl.csv")).output().unwrap();
    assert!(imp.status.success(), "{}", String::from_utf8_lossy(&imp.stderr));
    let json1 = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("wild-one.json");
    assert!(report_dir(&one, &["--out", json1.to_str().unwrap()]).status.success());
    let want: Vec<serde_json::Value> = serde_json::from_str(&std::fs::read_to_string(&json1).unwrap()).unwrap();
    let got = rows.iter().find(|r| r["name"] == "sensor-logger").unwrap();
    for k in ["e_psi_raw_deg", "e_psi_hdr_deg", "e_psi_pipeline_deg", "rows"] {
        assert_eq!(got[k], want[0][k], "{k}");
    }
}

/// Gzip-compressed logs (`drive.csv.gz`, as fleets store them) are logs of the folder too:
/// scored as the plain file, named by the file without `.csv.gz`; a damaged one is an error
/// row saying so; and one given to a method reads alike.
#[test]
fn gzipped_logs_are_scored_as_the_plain_files() {
    use std::io::Write;
    let dir = fleet_dir("fleet-gz");
    let gz = |from: PathBuf, to: PathBuf, keep: usize| {
        let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
        let text = std::fs::read_to_string(&from).unwrap();
        // Without its `# name:`, so the row is named by the file.
        let unnamed: String = text.lines().filter(|l| !l.starts_with("# name:")).map(|l| format!("{l}\n")).collect();
        e.write_all(unnamed.as_bytes()).unwrap();
        let bytes = e.finish().unwrap();
        std::fs::write(to, &bytes[..keep.min(bytes.len())]).unwrap();
    };
    let plain = dir.join("city-1.csv");
    gz(plain.clone(), dir.join("day2/city-1z.csv.gz"), usize::MAX);
    gz(plain.clone(), dir.join("cut.csv.gz"), 300);
    let json = dir.join("rows.json");
    let o = report_dir(&dir, &["--out", json.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows: Vec<serde_json::Value> = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let row = |end: &str| rows.iter().find(|r| r["file"].as_str().unwrap().ends_with(end)).unwrap().clone();
    let (z, p, cut) = (row("city-1z.csv.gz"), row("/city-1.csv"), row("cut.csv.gz"));
    assert_eq!(z["name"], "city-1z");
    assert!(z["error"].is_null(), "{z}");
    for key in ["rows", "e_psi_raw_deg", "e_psi_hdr_deg", "e_psi_pipeline_deg"] {
        assert_eq!(z[key], p[key], "{key}");
    }
    assert!(cut["error"].as_str().unwrap().contains("a damaged or cut gzip file"), "{cut}");
    let h = |f: &PathBuf| Command::new(env!("CARGO_BIN_EXE_gyrodrift")).args(["hdr", "--json"]).arg(f).output().unwrap().stdout;
    assert_eq!(h(&dir.join("day2/city-1z.csv.gz")), h(&plain));
}

/// With --recipe a fleet of one logger no preset knows is scored: a recipe of one table reads
/// each of its files whatever its name (.txt files too, as the recipe's table ends), a recipe
/// of several tables each folder holding the files it names; each drive named by its file or
/// folder and scored as `gyrodrift import --recipe` of it scores; v1 logs beside them as logs.
#[test]
fn with_recipe_a_fleet_of_ones_own_logger_is_scored_a_drive_per_recording() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-recipe");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("week2")).unwrap();
    let samples = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs");
    // City 1 and Highway 3 as a logger of our own writes them: ms, deg/s, a clockwise course, km/h.
    let mine = |v1: &str| -> String {
        let mut out = String::from("stamp_ms;gyro_z_dps;course;speed_kmh\n");
        for line in std::fs::read_to_string(samples.join(v1)).unwrap().lines().filter(|l| !l.starts_with('#')).skip(1) {
            let f: Vec<&str> = line.split(',').collect();
            let num = |s: &str| s.parse::<f64>().ok();
            let course = num(f[3]).map_or(String::new(), |h| (-h).to_string());
            out.push_str(&format!("{};{};{course};{}\n", num(f[0]).unwrap() * 1000.0, f[1], num(f[4]).unwrap() * 3.6));
        }
        out
    };
    std::fs::write(dir.join("monday.txt"), mine("train/city-1.csv")).unwrap();
    std::fs::write(dir.join("week2/tuesday.txt"), mine("test/highway-3.csv")).unwrap();
    std::fs::copy(samples.join("train/city-2.csv"), dir.join("city-2.csv")).unwrap();
    // A broken v1 log keeps its own error; a file ending otherwise is not read.
    std::fs::write(dir.join("week2/broken.csv"), "time_s,gyro_dps,ref_heading_deg\n0,0.1,0\n1,abc,0\n").unwrap();
    std::fs::write(dir.join("week2/notes.csv"), "a,b\n1,2\n").unwrap();
    let recipe = dir.join("mine.toml");
    std::fs::write(
        &recipe,
        "bias_s = 20\n[[table]]\nid = \"log\"\nfile = \"drive.txt\"\ndelimiter = \";\"\ntime = { column = \"stamp_ms\", unit = \"ms\" }\n\
         [yaw_rate]\ntable = \"log\"\ncolumn = \"gyro_z_dps\"\nunit = \"deg/s\"\npositive = \"ccw\"\n\
         [heading]\nsource = \"column\"\ntable = \"log\"\ncolumn = \"course\"\nunit = \"deg\"\npositive = \"cw\"\n\
         [speed]\nsource = \"column\"\ntable = \"log\"\ncolumn = \"speed_kmh\"\nunit = \"km/h\"\n",
    )
    .unwrap();
    let json = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-recipe-rows.json");
    let o = report_dir(&dir, &["--recipe", recipe.to_str().unwrap(), "--out", json.to_str().unwrap()]);
    let (stdout, stderr) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{stderr}");
    assert!(stderr.contains("importing 2 recording(s) by the recipe (2 files)"), "{stderr}");
    assert!(stdout.starts_with("5 files, 3 drives scored") && stdout.contains("2 errors"), "{stdout}");
    assert!(stderr.contains("broken.csv: line 3, column gyro_dps"), "{stderr}");
    let rows: Vec<serde_json::Value> = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let mut names: Vec<&str> = rows.iter().filter(|r| r["error"].is_null()).map(|r| r["name"].as_str().unwrap()).collect();
    names.sort();
    assert_eq!(names, ["City 2", "monday", "tuesday"]);
    // Each as its own import scores.
    let run = |args: &[&str]| Command::new(env!("CARGO_BIN_EXE_gyrodrift")).args(args).output().unwrap();
    let one = dir.join("one");
    std::fs::create_dir_all(&one).unwrap();
    std::fs::copy(dir.join("week2/tuesday.txt"), one.join("drive.txt")).unwrap();
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-recipe-tuesday.csv");
    let i = run(&["import", "--recipe", recipe.to_str().unwrap(), "--data", one.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(i.status.success(), "{}", String::from_utf8_lossy(&i.stderr));
    let hdr: serde_json::Value = serde_json::from_slice(&run(&["hdr", "--json", out.to_str().unwrap()]).stdout).unwrap();
    let tuesday = rows.iter().find(|r| r["name"] == "tuesday").unwrap();
    assert_eq!(tuesday["e_psi_hdr_deg"], hdr["E_psi_hdr_deg"]);
    // A recipe of two tables: a folder holding both files is one recording (its other files
    // part of it), named by the folder.
    let two = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-recipe-two");
    let _ = std::fs::remove_dir_all(&two);
    std::fs::create_dir_all(two.join("car-7")).unwrap();
    let text = mine("train/city-1.csv");
    let (mut gyro, mut gps) = (String::from("t;w\n"), String::from("t;cog\n"));
    for line in text.lines().skip(1) {
        let f: Vec<&str> = line.split(';').collect();
        gyro.push_str(&format!("{};{}\n", f[0], f[1]));
        if !f[2].is_empty() && f[3].parse::<f64>().unwrap() > 18.0 {
            gps.push_str(&format!("{};{}\n", f[0], f[2]));
        }
    }
    std::fs::write(two.join("car-7/gyro.csv"), gyro).unwrap();
    std::fs::write(two.join("car-7/gps.csv"), gps).unwrap();
    std::fs::write(two.join("car-7/notes.csv"), "a,b\n1,2\n").unwrap();
    let recipe2 = two.join("two.json");
    std::fs::write(
        &recipe2,
        r#"{"bias_s": 20, "table": [{"id": "g", "file": "gyro.csv", "delimiter": ";", "time": {"column": "t", "unit": "ms"}},
            {"id": "p", "file": "gps.csv", "delimiter": ";", "time": {"column": "t", "unit": "ms"}}],
            "yaw_rate": {"table": "g", "column": "w", "unit": "deg/s", "positive": "ccw"},
            "heading": {"source": "column", "table": "p", "column": "cog", "unit": "deg", "positive": "cw"}}"#,
    )
    .unwrap();
    let o = report_dir(&two, &["--recipe", recipe2.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // Its notes.csv is part of the recording, not an error.
    assert_eq!((summary["scored"].as_u64(), summary["errors"].as_u64()), (Some(1), Some(0)), "{summary}");
    // The same recipe written for one recording under its data root (its files named with
    // their folder, as `import --recipe --data` takes them) reads every folder holding them,
    // with the same figures.
    let rows = |recipe: &PathBuf| {
        let out = two.join("rows.json");
        let o = report_dir(&two, &["--recipe", recipe.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
        v.as_array().unwrap().iter().map(|r| (r["name"].clone(), r["e_psi_pipeline_deg"].clone())).collect::<Vec<_>>()
    };
    let rooted = two.join("rooted.json");
    let text = std::fs::read_to_string(&recipe2)
        .unwrap()
        .replace("\"gyro.csv\"", "\"car-1/gyro.csv\"")
        .replace("\"gps.csv\"", "\"car-1/gps.csv\"");
    std::fs::write(&rooted, text).unwrap();
    let want = rows(&recipe2);
    assert!(want.len() == 1 && want[0].1.is_number(), "{want:?}");
    assert_eq!(rows(&rooted), want);
}

/// Files that are not v1 logs (no time_s column) are error rows of kind "foreign", and the
/// way that reads them is named once, by how the job read them: `--import` for the loggers
/// it knows; with it, a recipe for the files no preset reads; with a recipe, another one.
#[test]
fn tables_that_are_not_logs_are_counted_and_name_the_import_once() {
    let dir = fleet_dir("fleet-foreign");
    let wild = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild/sensorlog/SensorLog.csv");
    std::fs::create_dir_all(dir.join("phone")).unwrap();
    std::fs::copy(wild, dir.join("phone/SensorLog.csv")).unwrap();
    std::fs::write(dir.join("mine.csv"), "PacketCounter,SampleTimeFine,Gyr_Z\n1,1000,0.5\n2,2000,0.5\n").unwrap();
    let json = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fleet-foreign.json");
    let o = report_dir(&dir, &["--out", json.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let codes: Vec<(String, Option<String>)> = v
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["error"].is_string())
        .map(|r| (r["file"].as_str().unwrap().rsplit('/').next().unwrap().to_string(), r["error_code"].as_str().map(str::to_string)))
        .collect();
    let foreign = Some("foreign".to_string());
    assert!(codes.contains(&("mine.csv".into(), foreign.clone())) && codes.contains(&("SensorLog.csv".into(), foreign)), "{codes:?}");
    assert!(codes.contains(&("broken.csv".into(), None)), "{codes:?}");
    let hint = |s: &str, extra: &[&str]| {
        let err = String::from_utf8(report_dir(&dir, extra).stderr).unwrap();
        assert_eq!(err.matches(s).count(), 1, "{err}");
        assert_eq!(err.matches("(no time_s column)").count(), 1, "{err}");
    };
    hint("2 files are not v1 logs (no time_s column): `--import` reads the exports of the loggers it knows", &[]);
    hint("1 file is not a v1 log (no time_s column) and no logger preset reads it: `--recipe R`", &["--import"]);
    let recipe = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/recipes/neu-vn100-circle.toml");
    hint("and the recipe does not read them: another recipe", &["--recipe", recipe.to_str().unwrap()]);
}
