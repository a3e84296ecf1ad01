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
fn time_of_day_hand_worked() {
    assert_eq!(parse_time_of_day("00:00:00"), Some(0.0));
    assert_eq!(parse_time_of_day("13:05:09"), Some(13.0 * 3600.0 + 5.0 * 60.0 + 9.0));
    assert_eq!(parse_time_of_day("9:05:09.25"), Some(9.0 * 3600.0 + 309.25));
    // a fraction after a colon, as some phone apps write it: 250 = .250 s
    assert_eq!(parse_time_of_day("13:05:09:250"), Some(47_109.25));
    // NMEA's hhmmss.ss, and a trailing Z (UTC)
    assert_eq!(parse_time_of_day("130509.25"), Some(47_109.25));
    assert_eq!(parse_time_of_day("235959Z"), Some(86_399.0));
    assert_eq!(parse_time_of_day(" 23:59:60.5 "), Some(86_400.5), "a leap second");
    for bad in [
        "",
        "24:00:00",
        "12:60:00",
        "12:5:00",
        "12:05",
        "1305.25",
        "12:05:09.",
        "12:05:09.x",
        "2023-08-06 12:05:09",
        "-1:00:00",
        "12:05:09:1:2",
        "1é345",
        "12345é",
    ] {
        assert_eq!(parse_time_of_day(bad), None, "{bad}");
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

#[test]
fn a_rate_past_the_physical_range_is_refused_as_the_parser_refuses_it() {
    // 1e3 rad/s = 57 296 deg/s: a wrong unit in the recipe, found by the fuzz loop as a NaN pipeline
    let a: String = (0..40).map(|i| format!("{i},{}\n", if i == 20 { 1000.0 } else { 0.01 * (i % 3) as f64 })).collect();
    let b: String = (0..40).map(|i| format!("{i} {} 0\n", 5 * i)).collect();
    let mut files = BTreeMap::new();
    files.insert("a.csv".to_string(), format!("t,w\n{a}").into_bytes());
    files.insert("b.txt".to_string(), b.into_bytes());
    let mut r = recipe();
    r.align = None;
    let e = import(&r, &mut files).unwrap_err().to_string();
    assert!(e.contains("the imported log") && e.contains("column gyro_dps") && e.contains("outside the physical range"), "{e}");
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

    /// Arbitrary text as a time of day, an ISO 8601 time, or a time column of either
    /// format: a time or None (an error naming the line), never a panic.
    #[test]
    fn time_texts_never_panic(text in "\\PC{0,14}", digits in "[0-9:.Zé ]{0,14}") {
        for t in [&text, &digits] {
            let _ = (parse_time_of_day(t), parse_iso8601(t));
        }
        let csv = format!("t,w\n{digits},1\n{text},2\n");
        let _ = import(&one_table(r#", "format": "time_of_day""#), &mut files(&csv));
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

#[test]
fn recipe_is_checked_before_any_file_is_opened() {
    let mut opened = 0;
    let mut files = |_: &str| -> Result<Box<dyn std::io::Read>> {
        opened += 1;
        Ok(Box::new(&b"t,w\n0,1\n"[..]))
    };
    type Spoil = fn(&mut Recipe);
    let cases: [(&str, Spoil); 6] = [
        ("recipe name", |r| r.name = Some("x\n# bias_s: 0".into())),
        ("recipe description", |r| r.description = Some("a\rb".into())),
        ("recipe bias_s", |r| r.bias_s = Some(f64::NAN)),
        ("recipe table a offset_s", |r| r.tables[0].offset_s = f64::INFINITY),
        ("recipe table a time", |r| r.tables[0].time.period_s = Some(0.1)),
        ("recipe span_s", |r| r.span_s = Some([5.0, 1.0])),
    ];
    for (field, spoil) in cases {
        let mut r = recipe();
        spoil(&mut r);
        let e = import(&r, &mut files).unwrap_err();
        assert!(matches!(&e, Error::Param { name, .. } if name == field), "{field}: {e}");
    }
    assert_eq!(opened, 0);
}

#[test]
fn a_line_break_in_metadata_is_never_written() {
    let mut log = crate::log::parse_log_str("time_s,gyro_dps\n0,1\n1,1\n").unwrap();
    log.meta.name = Some("x\n# bias_s: 0".into());
    let mut out = Vec::new();
    assert!(log.write_csv(&mut out).is_err());
    assert!(out.is_empty());
}

/// A one-table recipe over `a.csv` (t, w in deg/s) with the given time policies.
fn one_table(policies: &str) -> Recipe {
    let text = format!(
        r#"{{"table": [{{"id": "a", "file": "a.csv", "time": {{"column": "t"{policies}}}}}],
            "yaw_rate": {{"table": "a", "column": "w", "unit": "deg/s", "positive": "ccw"}}}}"#
    );
    serde_json::from_str(&text).unwrap()
}

fn files(csv: &str) -> BTreeMap<String, Vec<u8>> {
    BTreeMap::from([("a.csv".to_string(), csv.as_bytes().to_vec())])
}

#[test]
fn time_policies_merge_repeats_and_sort_late_rows_by_default() {
    // line 4 repeats t = 1 (w 3 and 5: mean 4); line 6 (t = 2.5) comes after t = 3
    let csv = "t,w\n0,1\n1,3\n1,5\n3,7\n2.5,9\n4,11\n";
    let (log, s) = import(&one_table(""), &mut files(csv)).unwrap();
    assert_eq!(log.time_s(), &[0.0, 1.0, 2.5, 3.0, 4.0]);
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 4.0, 9.0, 7.0, 11.0]);
    assert_eq!(s.time_fixes, TimeFixes { merged_duplicates: 1, sorted_backward: 1, ..Default::default() });
    // drop: the first of a repeat is kept, the late row is dropped
    let (log, s) = import(&one_table(r#", "duplicates": "drop", "backward": "drop""#), &mut files(csv)).unwrap();
    assert_eq!(log.time_s(), &[0.0, 1.0, 3.0, 4.0]);
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 3.0, 7.0, 11.0]);
    assert_eq!(s.time_fixes, TimeFixes { dropped_duplicates: 1, dropped_backward: 1, ..Default::default() });
    // in-order files are untouched
    let (_, s) = import(&one_table(""), &mut files("t,w\n0,1\n1,2\n")).unwrap();
    assert_eq!(s.time_fixes, TimeFixes::default());
}

#[test]
fn time_policies_error_and_a_clock_reset_name_the_line() {
    let csv = "t,w\n0,1\n1,3\n1,5\n3,7\n2.5,9\n";
    let e = import(&one_table(r#", "duplicates": "error""#), &mut files(csv)).unwrap_err().to_string();
    assert!(e.contains("line 4, column t") && e.contains("repeats"), "{e}");
    let e = import(&one_table(r#", "backward": "error""#), &mut files(csv)).unwrap_err().to_string();
    assert!(e.contains("line 6, column t") && e.contains("goes back"), "{e}");
    // 10 s back is past max_backward_s (1 s): a clock reset, whatever the policy
    let e = import(&one_table(""), &mut files("t,w\n0,1\n20,2\n10,3\n")).unwrap_err().to_string();
    assert!(e.contains("line 4") && e.contains("clock reset"), "{e}");
    let e = import(&one_table(r#", "max_backward_s": -1"#), &mut files("t,w\n0,1\n")).unwrap_err().to_string();
    assert!(e.contains("max_backward_s"), "{e}");
}

#[test]
fn a_slow_sensor_in_fast_rows_gives_one_sample_per_own_time_at_that_time() {
    // 10 Hz rows; the location (course, its own clock 1000 s ahead) updates once a second
    // and reaches the rows 0.3 s late (first written at x.3), repeated on every row after.
    let mut csv = String::from("t,w,course,loc_t\n");
    for i in 0..50 {
        let t = i as f64 / 10.0;
        let k = ((t - 0.3) / 1.0).floor().max(0.0); // the latest fix written so far
        csv.push_str(&format!("{t},0,{},{}\n", 10.0 * k, 1000.0 + k));
    }
    let text = r#"{"table": [{"id": "a", "file": "a.csv", "time": {"column": "t"}}],
        "yaw_rate": {"table": "a", "column": "w", "unit": "deg/s", "positive": "ccw"},
        "heading": {"source": "column", "table": "a", "column": "course", "unit": "deg", "positive": "ccw", "time_column": "loc_t"}}"#;
    let recipe: Recipe = serde_json::from_str(text).unwrap();
    let (log, s) = import(&recipe, &mut files(&csv)).unwrap();
    assert_eq!(s.n_reference, 5, "one sample per fix, not one per row");
    let stamped = reference_samples(&log);
    // fix k is stamped at its own time k on the rows' clock (1000 s removed by the smallest
    // delay, which is the 0 s of the first rows), not 0.3 s late; values 0, 10, ... deg
    for (k, &(t, v)) in stamped.iter().enumerate() {
        assert!((t - k as f64).abs() < 1e-9 && (v - 10.0 * k as f64).abs() < 1e-9, "{stamped:?}");
    }
    // a time_column with source = positions is refused by name
    let bad = r#"{"source": "positions", "time_column": "x"}"#;
    assert!(serde_json::from_str::<HeadingSpec>(bad).unwrap_err().to_string().contains("time_column"));
}

#[test]
fn the_heading_gate_reads_its_speed_column_in_its_unit() {
    // 18 km/h = 5 m/s: with speed_unit km/h the rows at 20 km/h pass a 5 m/s gate, those at
    // 10 km/h do not; read as m/s, all of them would.
    let csv = "t,w,course,v\n0,0,10,10\n1,0,11,20\n2,0,12,20\n3,0,13,10\n";
    let mut r = one_table("");
    r.heading = serde_json::from_value(serde_json::json!({ "source": "column", "table": "a", "column": "course", "unit": "deg",
        "positive": "cw", "speed_column": "v", "speed_unit": "km/h", "min_speed_mps": 5.0 }))
    .unwrap();
    let (log, s) = import(&r, &mut files(csv)).unwrap();
    assert_eq!(s.n_reference, 2);
    let refs: Vec<f64> = log.column(Column::RefHeadingDeg).unwrap().iter().copied().filter(|x| x.is_finite()).collect();
    assert_eq!(refs, [-11.0, -12.0]);
    r.heading = serde_json::from_value(serde_json::json!({ "source": "column", "table": "a", "column": "course", "unit": "deg",
        "positive": "cw", "speed_column": "v", "speed_unit": "furlong/fortnight", "min_speed_mps": 5.0 }))
    .unwrap();
    assert!(import(&r, &mut files(csv)).unwrap_err().to_string().contains("heading.speed_unit"));
}

#[test]
fn an_nmea_rmc_log_and_a_time_of_day_pass_midnight() {
    // A GPS logger's $GPRMC sentences (time hhmmss.ss, speed in knots, course cw) and a
    // gyro's CSV stamped with the time of day, both across midnight; one invalid fix (V)
    // with its course and speed empty.
    let rmc = |t: &str, ok: &str, kn: &str, course: &str| format!("$GPRMC,{t},{ok},4220.2340,N,07105.3704,W,{kn},{course},241123,,,A*00\n");
    let mut gps = String::new();
    for (t, ok, kn, course) in [("235958.00", "A", "10.0", "80.0"), ("235959.00", "A", "10.0", "90.0"), ("000000.00", "V", "", "")] {
        gps.push_str(&rmc(t, ok, kn, course));
    }
    gps.push_str("$GPGGA,000000.00,4220.2340,N,07105.3704,W,1,09,1.2,16.6,M,-33.8,M,,0000*55\n");
    gps.push_str(&rmc("000001.00", "A", "20.0", "100.0"));
    // The row of 23:59:59.5 is written late, after midnight's: sorted in on its own day.
    let gyro = "time,w\n23:59:58.0,1\n23:59:58.5,2\n23:59:59.0,3\n00:00:00.0,5\n23:59:59.5,4\n00:00:00.5,6\n00:00:01.0,7\n";
    let text = r#"{"table": [{"id": "imu", "file": "imu.csv", "time": {"column": "time", "format": "time_of_day"}},
            {"id": "gps", "file": "gps.nmea", "format": "nmea", "record": "$GPRMC",
             "columns": ["tag", "time", "status", "lat", "ns", "lon", "ew", "kn", "course", "date", "mv", "mv_ew", "mode"],
             "time": {"column": "time", "format": "time_of_day"}}],
        "yaw_rate": {"table": "imu", "column": "w", "unit": "deg/s", "positive": "ccw"},
        "heading": {"source": "column", "table": "gps", "column": "course", "unit": "deg", "positive": "cw",
                    "speed_column": "kn", "speed_unit": "kn", "min_speed_mps": 1.0},
        "speed": {"source": "column", "table": "gps", "column": "kn", "unit": "kn"}}"#;
    let recipe: Recipe = serde_json::from_str(text).unwrap();
    let mut files = BTreeMap::from([("imu.csv".to_string(), gyro.as_bytes().to_vec()), ("gps.nmea".to_string(), gps.into_bytes())]);
    let (log, s) = import(&recipe, &mut files).unwrap();
    // 23:59:58 is the start; midnight passes without a clock reset: 0.5 s steps throughout
    assert_eq!(log.time_s(), &[0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]);
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    // three valid fixes at 0, 1 and 3 s (courses 80, 90, 100 cw: -80, -90, -100 ccw)
    assert_eq!(s.n_reference, 3);
    let stamped = reference_samples(&log);
    assert_eq!(stamped, [(0.0, -80.0), (1.0, -90.0), (3.0, -100.0)]);
    // 10 kn = 5.144 m/s; 20 kn = 10.289 m/s
    let v = log.column(Column::SpeedMps).unwrap();
    assert!((v[0] - 10.0 * 1852.0 / 3600.0).abs() < 1e-12 && (v[6] - 20.0 * 1852.0 / 3600.0).abs() < 1e-12, "{v:?}");
    // a multi-GNSS receiver's talker ($GNRMC): the record that matched nothing is named
    // with what the rows start with
    let gn = String::from_utf8(files["gps.nmea"].clone()).unwrap().replace("$GPRMC", "$GNRMC");
    let mut gn_files = files.clone();
    gn_files.insert("gps.nmea".to_string(), gn.into_bytes());
    let e = import(&recipe, &mut gn_files).unwrap_err().to_string();
    assert!(e.contains("no row starts with record \"$GPRMC\" (rows start with \"$GNRMC\", \"$GPGGA\")"), "{e}");
    // read as seconds, the time of day is refused naming the format that reads it
    let secs = recipe_text_seconds(text);
    let e = import(&secs, &mut files).unwrap_err().to_string();
    assert!(e.contains("imu.csv: line 2, column time") && e.contains("time.format = \"time_of_day\""), "{e}");
    // The two files drafted: the NMEA log's RMC sentences give the course and the speed, the
    // same reference samples and speeds as the recipe above (its gate 3 m/s, below 10 kn).
    // (The gyro's column named as a rate, which "w" alone does not say.)
    let mut dfiles = files.clone();
    dfiles.insert("imu.csv".to_string(), gyro.replace("time,w", "time,yaw_rate_dps").into_bytes());
    let heads: Vec<(String, Vec<u8>)> = dfiles.iter().map(|(n, b)| (n.clone(), b.clone())).collect();
    let draft = draft_recipe(&heads).unwrap();
    let r = &draft.recipe_json;
    assert_eq!((r["table"][0]["format"].as_str(), r["table"][0]["record"].as_str()), (Some("nmea"), Some("$GPRMC")), "{r}");
    assert_eq!(r["table"][1]["time"], serde_json::json!({ "column": "time", "format": "time_of_day" }));
    assert!(draft.guesses.iter().any(|g| g.contains("gps.nmea's $GPRMC sentences")), "{:?}", draft.guesses);
    let drafted: Recipe = serde_json::from_value(r.clone()).unwrap();
    let (dlog, ds) = import(&drafted, &mut dfiles).unwrap();
    assert_eq!((ds.n_reference, reference_samples(&dlog)), (3, stamped));
    assert_eq!(dlog.column(Column::SpeedMps), log.column(Column::SpeedMps));
    // A log of GGA sentences alone: the course between its positions.
    let gga = "$GPGGA,000000.00,4220.2340,N,07105.3704,W,1,09,1.2,16.6,M,-33.8,M,,0000*55\n";
    let r = draft_recipe(&[heads[1].clone(), ("fix.nmea".to_string(), gga.as_bytes().to_vec())]).unwrap().recipe_json;
    assert_eq!(r["positions"], serde_json::json!({ "table": "t1", "kind": "nmea", "columns": ["lat", "ns", "lon", "ew"] }));
    assert_eq!((r["table"][1]["record"].as_str(), r["heading"]["source"].as_str()), (Some("$GPGGA"), Some("positions")));
}

/// The recipe with its time_of_day formats removed (times read as seconds).
fn recipe_text_seconds(text: &str) -> Recipe {
    serde_json::from_str(&text.replace(r#", "format": "time_of_day""#, "")).unwrap()
}

#[test]
fn a_draft_recipe_reads_the_columns_by_name_and_imports() {
    // A logger's own CSV: ms time, a gyro z in deg/s, a course, a speed in km/h, a temperature.
    let csv = "stamp_ms,acc_z,gyro_z_dps,course,speed_kmh,temp\n0,9.8,1.0,,0,20\n1000,9.8,2.0,10,36,20\n2000,9.8,3.0,20,3.6,21\n";
    let head = |name: &str, text: &str| (name.to_string(), text.as_bytes().to_vec());
    let draft = draft_recipe(&[head("my-logger.csv", csv)]).unwrap();
    let r = &draft.recipe_json;
    assert_eq!(r["table"][0]["time"], serde_json::json!({ "column": "stamp_ms", "unit": "ms" }));
    assert_eq!(r["yaw_rate"]["column"], "gyro_z_dps");
    assert_eq!(r["yaw_rate"]["unit"], "deg/s");
    assert_eq!(r["heading"]["column"], "course");
    assert_eq!(r["heading"]["speed_unit"], "km/h");
    assert_eq!(r["speed"]["unit"], "km/h");
    assert_eq!(r["temperature"]["column"], "temp");
    assert!(draft.guesses.iter().any(|g| g.starts_with("yaw_rate: my-logger.csv column \"gyro_z_dps\", deg/s")), "{:?}", draft.guesses);
    let recipe: Recipe = serde_json::from_value(r.clone()).unwrap();
    let mut files = BTreeMap::from([("my-logger.csv".to_string(), csv.as_bytes().to_vec())]);
    let (log, s) = import(&recipe, &mut files).unwrap();
    assert_eq!(log.time_s(), &[0.0, 1.0, 2.0]);
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 2.0, 3.0]);
    // 36 km/h = 10 m/s passes the 5 m/s gate (course 10 cw = -10), 3.6 km/h does not
    assert_eq!(s.n_reference, 1);
    assert_eq!(log.column(Column::SpeedMps).unwrap(), &[0.0, 10.0, 1.0]);
    // positions when there is no course; a time of day by its name; rad/s by default
    let d2 = draft_recipe(&[head("b.csv", "clock,wz,latitude,longitude\n")]).unwrap().recipe_json;
    assert_eq!(d2["table"][0]["time"]["format"], "time_of_day");
    assert_eq!((d2["yaw_rate"]["column"].as_str(), d2["yaw_rate"]["unit"].as_str()), (Some("wz"), Some("rad/s")));
    assert_eq!(d2["positions"]["columns"], serde_json::json!(["latitude", "longitude"]));
    // a GPX track beside the gyro: the heading and speed from its positions; the gyro's
    // time read as ISO 8601 from its first row (its name says nothing), or a time of day
    let g = head("drive.gpx", "<?xml version=\"1.0\"?>\n<gpx version=\"1.1\"><trk><trkseg>\n");
    let d3 = draft_recipe(&[head("imu.csv", "time,gyro_z\n2026-11-27T10:00:00.1Z,0.5\n"), g]).unwrap().recipe_json;
    assert_eq!(d3["table"][0]["time"], serde_json::json!({ "column": "time", "format": "iso8601" }));
    let d4 = draft_recipe(&[head("imu.csv", "# app 1.0\ntime;gyro_z\n\n10:00:00.125;0,5\n")]).unwrap().recipe_json;
    assert_eq!(d4["table"][0]["time"], serde_json::json!({ "column": "time", "format": "time_of_day" }));
    assert_eq!(d3["table"][1], serde_json::json!({ "id": "t1", "file": "drive.gpx", "format": "gpx" }));
    assert_eq!(d3["positions"], serde_json::json!({ "table": "t1", "kind": "latlon", "columns": ["lat", "lon"] }));
    assert_eq!((d3["heading"]["source"].as_str(), d3["speed"]["source"].as_str()), (Some("positions"), Some("positions")));
    // a rate in rad/s named "..._s" before the time column is not taken for the time
    let d5 = draft_recipe(&[head("d.csv", "gyro_z_rad_s,timestamp\n0.1,5\n")]).unwrap().recipe_json;
    assert_eq!((d5["table"][0]["time"]["column"].as_str(), d5["yaw_rate"]["column"].as_str()), (Some("timestamp"), Some("gyro_z_rad_s")));
    // a drive log's own reference column (a v1 log saved with `;`): counter-clockwise, not
    // a course, and not gated again by speed
    let v1 = "time_s;gyro_dps;ref_heading_deg;speed_mps\n0;1,5;;0\n1;1,5;10;10\n";
    let d6 = draft_recipe(&[head("v1.csv", v1)]).unwrap().recipe_json;
    assert_eq!(
        d6["heading"],
        serde_json::json!({ "source": "column", "table": "t0", "column": "ref_heading_deg", "unit": "deg", "positive": "ccw" })
    );
    // no yaw rate by name: an error naming the headers
    let e = draft_recipe(&[head("c.csv", "t,a,b\n")]).unwrap_err().to_string();
    assert!(e.contains("no column reads as a yaw rate") && e.contains("c.csv: t, a, b"), "{e}");
}

#[test]
fn a_draft_reads_three_gyro_axes_on_the_accelerometers_up_so_any_mounting_turns_the_right_way() {
    // An IMU mounted x forward, y right, z down (the VN-100's frame): a left turn of 0.2 rad/s
    // reads -0.2 on its z axis, the accelerometer -g on z. A second file holds the gravity
    // of a phone logger that writes it apart.
    let imu = "time,gyro_x,gyro_y,gyro_z,accel_x,accel_y,accel_z\n0,0,0,-0.2,0,0,-9.81\n1,0,0,-0.2,0,0,-9.81\n2,0,0,-0.2,0,0,-9.81\n";
    let draft = draft_recipe(&[("imu.csv".to_string(), imu.as_bytes().to_vec())]).unwrap();
    let r = &draft.recipe_json;
    assert_eq!(r["yaw_rate"]["axes"], serde_json::json!(["gyro_x", "gyro_y", "gyro_z"]));
    assert_eq!(r["yaw_rate"]["gravity"], serde_json::json!({ "axes": ["accel_x", "accel_y", "accel_z"], "first_s": 10 }));
    assert!(
        draft.guesses.iter().any(|g| g.contains("projected on the up of imu.csv columns accel_x, accel_y, accel_z")),
        "{:?}",
        draft.guesses
    );
    let recipe: Recipe = serde_json::from_value(r.clone()).unwrap();
    let mut files = BTreeMap::from([("imu.csv".to_string(), imu.as_bytes().to_vec())]);
    let (log, _) = import(&recipe, &mut files).unwrap();
    for w in log.column(Column::GyroDps).unwrap() {
        assert!((w - 0.2f64.to_degrees()).abs() < 1e-9, "{w}: a left turn is counter-clockwise positive");
    }
    // The accelerometer in its own file: the gravity names its table, which the draft reads.
    let gyro = "time,gyro_x,gyro_y,gyro_z\n0,0,0,-0.2\n";
    let grav = "time,gravity_x,gravity_y,gravity_z\n0,0,0,-9.81\n";
    let heads = [("gyro.csv".to_string(), gyro.as_bytes().to_vec()), ("gravity.csv".to_string(), grav.as_bytes().to_vec())];
    let r = draft_recipe(&heads).unwrap().recipe_json;
    assert_eq!((r["yaw_rate"]["table"].as_str(), r["yaw_rate"]["gravity"]["table"].as_str()), (Some("t0"), Some("t1")));
    assert_eq!(r["table"].as_array().map(Vec::len), Some(2));
    // Without an accelerometer, the z axis alone.
    let r = draft_recipe(&heads[..1]).unwrap().recipe_json;
    assert_eq!(r["yaw_rate"]["column"], "gyro_z");
}

/// Without the `gpx` feature (the size-budgeted wasm module's build) a GPX table is refused
/// by name.
#[cfg(not(feature = "gpx"))]
#[test]
fn a_gpx_table_without_the_feature_is_refused_by_name() {
    let text = r#"{"table": [{"id": "trk", "file": "drive.gpx", "format": "gpx"}],
        "yaw_rate": {"table": "trk", "column": "lat", "unit": "deg/s", "positive": "ccw"}}"#;
    let mut files = BTreeMap::from([("drive.gpx".to_string(), b"<gpx/>".to_vec())]);
    let e = import(&serde_json::from_str(text).unwrap(), &mut files).unwrap_err().to_string();
    assert!(e.contains("table trk") && e.contains("reads no GPX"), "{e}");
}

#[cfg(feature = "gpx")]
#[test]
fn a_gpx_track_gives_the_heading_from_its_positions() {
    // A recorded track (GPX 1.1): 8.3 m/s east for 3 s, then north; a gyro in ISO time.
    let mut gpx = String::from(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<gpx version="1.1" creator="test" xmlns="http://www.topografix.com/GPX/1/1"><trk><name>drive</name><trkseg>"#,
    );
    let pts = [(42.0, 11.0), (42.0, 11.0001), (42.0, 11.0002), (42.0, 11.0003), (42.0001, 11.0003), (42.0002, 11.0003)];
    for (k, (lat, lon)) in pts.iter().enumerate() {
        gpx.push_str(&format!(r#"<trkpt lat="{lat}" lon="{lon}"><ele>100</ele><time>2026-11-27T10:00:0{k}Z</time></trkpt>"#));
    }
    gpx.push_str("</trkseg></trk></gpx>\n");
    let mut gyro = String::from("time,w\n");
    for i in 0..=50 {
        gyro.push_str(&format!("2026-11-27 10:00:0{}.{}Z,{}\n", i / 10, i % 10, if i == 35 { 90.0 } else { 0.0 }));
    }
    let text = r#"{"table": [{"id": "imu", "file": "imu.csv", "time": {"column": "time", "format": "iso8601"}},
            {"id": "trk", "file": "drive.gpx", "format": "gpx"}],
        "yaw_rate": {"table": "imu", "column": "w", "unit": "deg/s", "positive": "ccw"},
        "positions": {"table": "trk", "kind": "latlon", "columns": ["lat", "lon"]},
        "heading": {"source": "positions"}, "speed": {"source": "positions"}}"#;
    let recipe: Recipe = serde_json::from_str(text).unwrap();
    let mut files = BTreeMap::from([("imu.csv".to_string(), gyro.into_bytes()), ("drive.gpx".to_string(), gpx.into_bytes())]);
    let (log, s) = import(&recipe, &mut files).unwrap();
    let stamped = reference_samples(&log);
    assert_eq!(s.n_reference, 5, "{stamped:?}");
    assert_east_then_north(&stamped);
    // 0.0001 deg of longitude at 42 deg north: about 8.3 m/s
    let v = log.column(Column::SpeedMps).unwrap();
    assert!((v[10] - 8.27).abs() < 0.05, "{}", v[10]);
    // a column a GPX table does not have, a point without a time, a file that is not GPX
    let bad = text.replace(r#""columns": ["lat", "lon"]"#, r#""columns": ["lat", "long"]"#);
    let e = import(&serde_json::from_str(&bad).unwrap(), &mut files).unwrap_err().to_string();
    assert!(e.contains("long") && e.contains("a GPX table has: lat, lon, ele, speed"), "{e}");
    let g = String::from_utf8(files["drive.gpx"].clone()).unwrap().replacen("<time>2026-11-27T10:00:02Z</time>", "", 1);
    files.insert("drive.gpx".into(), g.into_bytes());
    let e = import(&recipe, &mut files).unwrap_err().to_string();
    assert!(e.contains("drive.gpx") && e.contains("track point 3: no <time>"), "{e}");
    files.insert("drive.gpx".into(), b"time,lat,lon\n".to_vec());
    let e = import(&recipe, &mut files).unwrap_err().to_string();
    assert!(e.contains("drive.gpx: not a GPX file"), "{e}");
}

#[test]
fn nmea_positions_read_ddmm_and_their_hemisphere() {
    // The NEU VN-100 drive's $GPGGA 4220.2340,N,07105.3704,W beside its own decimal columns
    // (42.33723333333333, -71.08950666666667; real-logs/neu-vn100-car/first_test).
    let d = geo::nmea_degrees(&[4220.2340, 07105.3704, 3330.0], &[1.0, -1.0, -1.0]);
    assert!((d[0] - 42.33723333333333).abs() < 1e-12 && (d[1] + 71.08950666666667).abs() < 1e-12, "{d:?}");
    assert!((d[2] + 33.5).abs() < 1e-12, "30 minutes south: {}", d[2]);
    // A GGA-only log (no course): east at about 8.3 m/s for 3 s, then north; the course from
    // the positions, read as ddmm.mmmm with their N/S and E/W.
    let mut gps = String::new();
    let pts = [
        ("4200.0000", "01100.0000"),
        ("4200.0000", "01100.0060"),
        ("4200.0000", "01100.0120"),
        ("4200.0000", "01100.0180"),
        ("4200.0060", "01100.0180"),
        ("4200.0120", "01100.0180"),
    ];
    for (k, (lat, lon)) in pts.iter().enumerate() {
        gps.push_str(&format!("$GPGGA,10000{k}.00,{lat},N,{lon},E,1,09,1.2,16.6,M,-33.8,M,,0000*55\n"));
    }
    let mut gyro = String::from("time,w\n");
    for i in 0..=50 {
        gyro.push_str(&format!("10:00:0{}.{},0\n", i / 10, i % 10));
    }
    let text = r#"{"table": [{"id": "imu", "file": "imu.csv", "time": {"column": "time", "format": "time_of_day"}},
            {"id": "gps", "file": "gps.nmea", "format": "nmea", "record": "$GPGGA",
             "columns": ["tag", "time", "lat", "ns", "lon", "ew", "fix", "sats", "hdop", "alt", "m", "geoid", "m2", "age", "station"],
             "time": {"column": "time", "format": "time_of_day"}}],
        "yaw_rate": {"table": "imu", "column": "w", "unit": "deg/s", "positive": "ccw"},
        "positions": {"table": "gps", "kind": "nmea", "columns": ["lat", "ns", "lon", "ew"]},
        "heading": {"source": "positions"}, "speed": {"source": "positions"}}"#;
    let recipe: Recipe = serde_json::from_str(text).unwrap();
    let mut files = BTreeMap::from([("imu.csv".to_string(), gyro.into_bytes()), ("gps.nmea".to_string(), gps.into_bytes())]);
    let (log, s) = import(&recipe, &mut files).unwrap();
    let stamped = reference_samples(&log);
    assert_eq!(s.n_reference, 5, "{stamped:?}");
    assert_east_then_north(&stamped);
    // nmea positions need their four columns
    let bad = text.replace(r#"["lat", "ns", "lon", "ew"]"#, r#"["lat", "lon"]"#);
    let e = import(&serde_json::from_str(&bad).unwrap(), &mut files).unwrap_err().to_string();
    assert!(e.contains("positions need 4 columns"), "{e}");
}

/// The log's reference samples: (time, heading) where the heading is given.
fn reference_samples(log: &crate::log::DriveLog) -> Vec<(f64, f64)> {
    let r = log.column(Column::RefHeadingDeg).unwrap();
    log.time_s().iter().zip(r).filter(|(_, v)| v.is_finite()).map(|(t, v)| (*t, *v)).collect()
}

/// Courses from positions driven east for 3 s, then north, a point a second: stamped at the
/// segments' middles, east (90 cw = -90 ccw) at 0.5, 1.5, 2.5 s, then north (0).
fn assert_east_then_north(stamped: &[(f64, f64)]) {
    for (k, &(t, h)) in stamped.iter().enumerate() {
        let want = if k < 3 { -90.0 } else { 0.0 };
        assert!((t - (k as f64 + 0.5)).abs() < 1e-9 && (h - want).abs() < 0.1, "{stamped:?}");
    }
}
