use super::*;

fn err(text: &str) -> String {
    parse_log_str(text).unwrap_err().to_string()
}

#[test]
fn parses_metadata_free_order_unknown_and_empty_cells() {
    let text = "# name: City 1\n# wheelbase_m: 0.5\n# bias_s: 10\n# vehicle: Forester\n\
                gyro_dps,extra,time_s\n1.5,x,0.0\n,y,0.1\n-2,z,0.2\n";
    let log = parse_log_str(text).unwrap();
    assert_eq!(log.meta.name.as_deref(), Some("City 1"));
    assert_eq!(log.meta.wheelbase_m, Some(0.5));
    assert_eq!(log.meta.bias_s, Some(10.0));
    assert_eq!(log.meta.other.get("vehicle").map(String::as_str), Some("Forester"));
    assert_eq!(log.time_s(), &[0.0, 0.1, 0.2]);
    let g = log.column(Column::GyroDps).unwrap();
    assert_eq!(g[0], 1.5);
    assert!(g[1].is_nan());
    assert_eq!(g[2], -2.0);
    assert_eq!(log.line, vec![6, 7, 8]);
    assert!(!log.has(Column::RefHeadingDeg));
}

#[test]
fn crlf_bom_and_spaces() {
    let log = parse_log_str("\u{feff}time_s , gyro_dps\r\n0, 1\r\n1 ,2\r\n").unwrap();
    assert_eq!(log.time_s(), &[0.0, 1.0]);
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 2.0]);
}

#[test]
fn empty_file_and_header_only() {
    assert_eq!(err(""), "empty file: no header row");
    assert_eq!(err("# name: x\n\n"), "empty file: no header row");
    assert!(err("time_s,gyro_dps\n").contains("no data rows"));
}

#[test]
fn missing_and_duplicate_columns() {
    let e = err("gyro_dps\n1\n");
    assert!(e.contains("line 1") && e.contains("missing required column time_s"), "{e}");
    let e = err("time_s,gyro_dps,gyro_dps\n0,1,1\n");
    assert_eq!(e, "line 1: duplicate column gyro_dps (fields 2 and 3)");
}

#[test]
fn bad_cells_name_line_and_column() {
    let e = err("# name: a\ntime_s,gyro_dps\n0,1\n1,1.2.3\n");
    assert_eq!(e, "line 4, column gyro_dps: \"1.2.3\" is not a number");
    let e = err("time_s,gyro_dps\n0,NaN\n");
    assert_eq!(e, "line 2, column gyro_dps: \"NaN\" is not a finite number");
    let e = err("time_s,gyro_dps\n0,1\n1,inf\n");
    assert_eq!(e, "line 3, column gyro_dps: \"inf\" is not a finite number");
    let e = err("time_s,gyro_dps\n,1\n");
    assert_eq!(e, "line 2, column time_s: empty, but every row needs a time");
}

#[test]
fn non_increasing_time_names_both_lines() {
    let e = err("time_s,gyro_dps\n0,1\n1,1\n1,1\n");
    assert_eq!(e, "line 4, column time_s: time 1 repeats 1 on line 3: time must strictly increase");
    let e = err("time_s,gyro_dps\n0,1\n2,1\n1.5,1\n");
    assert!(e.starts_with("line 4, column time_s: time 1.5 goes back from 2 on line 3"), "{e}");
}

#[test]
fn truncated_last_line() {
    let e = err("time_s,gyro_dps,temp_c\n0,1,20\n0.1,1");
    assert_eq!(e, "line 3: row has 2 fields, the header has 3 (truncated row?)");
}

#[test]
fn bad_metadata() {
    let e = err("# wheelbase_m: wide\ntime_s\n0\n");
    assert_eq!(e, "line 1: metadata wheelbase_m: \"wide\" is not a number >= 0");
    let e = err("# bias_s: -3\ntime_s\n0\n");
    assert!(e.contains("line 1") && e.contains("bias_s"));
}

#[test]
fn row_limit_is_an_error_not_an_abort() {
    let text = "time_s\n0\n1\n2\n";
    let e = parse_log_with(text.as_bytes(), ParseOptions { max_rows: 2, ..Default::default() }).unwrap_err();
    assert!(e.to_string().contains("too many rows"), "{e}");
}

#[test]
fn invalid_utf8_is_an_error() {
    let e = parse_log(&b"time_s,gyro_dps\n0,\xff\n"[..]).unwrap_err().to_string();
    assert!(e.contains("line 2"), "{e}");
}

#[test]
fn write_then_parse_round_trips() {
    let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]);
    log.meta.name = Some("t".into());
    log.meta.bias_s = Some(5.0);
    log.push_row(&[(Column::TimeS, 0.0), (Column::GyroDps, 0.1 + 0.2)]);
    log.push_row(&[(Column::TimeS, 0.1), (Column::RefHeadingDeg, -12.5)]);
    let mut buf = Vec::new();
    log.write_csv(&mut buf).unwrap();
    let back = parse_log(&buf[..]).unwrap();
    assert_eq!(back.meta, log.meta);
    assert_eq!(back.time_s(), log.time_s());
    assert_eq!(back.column(Column::GyroDps).unwrap()[0], 0.1 + 0.2);
    assert!(back.column(Column::GyroDps).unwrap()[1].is_nan());
    assert_eq!(back.column(Column::RefHeadingDeg).unwrap()[1], -12.5);
}

#[test]
fn from_columns_checks_like_the_parser() {
    let log = parse_log_str("time_s,gyro_dps\n0,1\n1,\n").unwrap();
    let cols: Vec<(Column, Vec<f64>)> = log.columns().into_iter().map(|(c, v)| (c, v.to_vec())).collect();
    let back = DriveLog::from_columns(log.meta.clone(), log.line.clone(), cols).unwrap();
    assert_eq!(back.time_s(), log.time_s());
    assert_eq!(back.line, vec![2, 3]);
    let bad = DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::TimeS, vec![0.0, 0.0])]);
    assert!(bad.unwrap_err().to_string().contains("strictly increase"));
    let bad = DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::TimeS, vec![0.0, 1.0]), (Column::GyroDps, vec![1.0])]);
    assert!(bad.is_err());
    assert!(DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::GyroDps, vec![1.0])]).is_err());
    // An infinite or out-of-range cell is named by its line, a NaN (empty) cell is fine.
    let t = vec![0.0, 1.0, 2.0];
    let cols = |c: Column, v: Vec<f64>| vec![(Column::TimeS, t.clone()), (c, v)];
    let e = DriveLog::from_columns(LogMeta::default(), vec![], cols(Column::GyroDps, vec![1.0, f64::NEG_INFINITY, 2.0])).unwrap_err();
    assert_eq!(e.to_string(), "line 3, column gyro_dps: not a finite number");
    let e = DriveLog::from_columns(LogMeta::default(), vec![], cols(Column::TempC, vec![20.0, 21.0, 500.0])).unwrap_err();
    assert!(e.to_string().starts_with("line 4, column temp_c: 500.0 deg C is outside the physical range"), "{e}");
    assert!(DriveLog::from_columns(LogMeta::default(), vec![], cols(Column::TempC, vec![f64::NAN; 3])).is_ok());
    assert!(
        DriveLog::from_columns(LogMeta::default(), vec![], cols(Column::OdoLeftM, vec![1e12, 0.0, -5.0])).is_ok(),
        "no range: any finite value"
    );
}

#[test]
fn progress_is_reported_on_large_inputs() {
    let mut text = String::from("time_s\n");
    for i in 0..140_000 {
        text.push_str(&format!("{i}\n"));
    }
    let mut calls = vec![];
    parse_log_progress(text.as_bytes(), ParseOptions::default(), &mut |b| calls.push(b)).unwrap();
    assert_eq!(calls.len(), 2);
    assert!(calls[0] > 0 && calls[1] > calls[0]);
}

#[test]
fn kind_from_columns() {
    assert_eq!(DriveLog::with_columns(&[Column::GyroDps]).kind(), LogKind::Static);
    assert_eq!(DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]).kind(), LogKind::Drive);
    assert_eq!(DriveLog::with_columns(&[Column::GyroDps, Column::SpeedMps]).kind(), LogKind::Drive);
    assert_eq!(DriveLog::with_columns(&[Column::OdoLeftM, Column::OdoRightM]).kind(), LogKind::Robot);
    assert_eq!(DriveLog::with_columns(&[Column::TableRateDps]).kind(), LogKind::Turntable);
}

/// A v1 log whose time repeats or steps back a little reads in time order by the import's
/// default policies (repeats merged by their mean, late rows sorted in), counted; the strict
/// parser refuses the same text; a clock reset is an error naming its line.
#[test]
fn a_log_out_of_time_order_is_put_in_order_on_request() {
    let text = "# name: messy\ntime_s,gyro_dps,speed_mps\n0,1,\n1,2,5\n1,4,\n3,5,6\n2.5,7,7\n4,8,8\n";
    assert!(parse_log_str(text).unwrap_err().to_string().contains("line 5, column time_s: time 1 repeats 1 on line 4"));
    let (log, fixes) = parse_log_in_time_order(text.as_bytes(), ParseOptions::default()).unwrap();
    assert_eq!(log.time_s(), &[0.0, 1.0, 2.5, 3.0, 4.0]);
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 3.0, 7.0, 5.0, 8.0]);
    // The repeat's speed is the mean of its present values: 5 alone.
    assert_eq!(log.column(Column::SpeedMps).unwrap()[1], 5.0);
    assert_eq!(log.line, vec![3, 4, 7, 6, 8]);
    assert_eq!(log.meta.name.as_deref(), Some("messy"));
    assert_eq!((fixes.merged_duplicates, fixes.sorted_backward), (1, 1));
    // In order already: the strict parser's log, nothing fixed.
    let plain = "time_s,gyro_dps\n0,1\n1,2\n";
    let (log, fixes) = parse_log_in_time_order(plain.as_bytes(), ParseOptions::default()).unwrap();
    assert_eq!((log, fixes), (parse_log_str(plain).unwrap(), Default::default()));
    let reset = "time_s,gyro_dps\n0,1\n5,2\n3,3\n";
    let e = parse_log_in_time_order(reset.as_bytes(), ParseOptions::default()).unwrap_err().to_string();
    assert!(e.contains("line 4, column time_s: time 3 goes back 2.000 s from 5: a clock reset?"), "{e}");
}
