use super::*;
use crate::compare::compare_row;
use crate::log::Column;

fn city() -> (String, DriveLog) {
    let p = concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/city-1.csv");
    (p.to_string(), crate::log::parse_log(std::fs::File::open(p).unwrap()).unwrap())
}

#[test]
fn a_drive_row_holds_the_comparisons_scores() {
    let (p, log) = city();
    let opts = FleetOptions::default();
    let want = compare_row("city-1", &log, &opts.pipeline, None).unwrap();
    let rows = score_log(&p, "city-1", log, &opts);
    assert_eq!(rows.len(), 1);
    let r = &rows[0];
    assert_eq!(r.error, None);
    assert_eq!((r.part, r.parts, r.name.as_str()), (1, 1, "City 1"));
    assert_eq!(r.ne_psi_raw_deg_per_min, Some(want.raw));
    assert_eq!(r.ne_psi_hdr_deg_per_min, Some(want.hdr_table_iii));
    assert_eq!(r.ne_psi_pipeline_deg_per_min, Some(want.pipeline));
    assert_eq!(r.ne_psi_pipeline_smoothed_deg_per_min, Some(want.pipeline_smoothed));
    assert_eq!(r.ne_psi_fusion_offset_deg_per_min, Some(want.fusion_offset));
    assert_eq!(r.ne_psi_zaru_deg_per_min, Some(want.zaru));
    assert_eq!(r.still_source.as_deref(), Some("speed"));
    // The bias's move between standings is check's: City 1's CRS03-like gyro warms 0.16 deg/s.
    let check = crate::check::check(&city().1);
    let (first, far) = crate::check::drift::furthest(&check.stop_bias_dps).unwrap();
    assert!(check.stop_bias_dps.len() > 1 && (far.1 - first.1 - 0.16).abs() < 0.01, "{:?}", check.stop_bias_dps);
    assert_eq!(r.stop_bias_drift_dps, Some(far.1 - first.1));
    // NE_psi is E_psi per minute of the drive.
    let (e, ne) = r.score(1);
    assert!((e.unwrap() / r.duration_min.unwrap() - ne.unwrap()).abs() < 1e-9);
}

/// A drive without a reference heading (no GPS course): not an error but `not_scored`, with
/// the pipeline's own figures, the CLI's `pipeline` summary; a scored drive has them too.
#[test]
fn a_drive_without_a_reference_has_the_pipelines_figures_and_no_scores() {
    let (p, log) = city();
    let opts = FleetOptions::default();
    let kept: Vec<(Column, Vec<f64>)> =
        log.columns().into_iter().filter(|(c, _)| *c != Column::RefHeadingDeg).map(|(c, v)| (c, v.to_vec())).collect();
    let blind = DriveLog::from_columns(log.meta.clone(), vec![0; log.len()], kept).unwrap();
    for (drive, scored) in [(&log, true), (&blind, false)] {
        let want = crate::pipeline::run(drive, &opts.pipeline).unwrap().summary(drive.duration_min());
        let rows = score_log(&p, "city-1", drive.clone(), &opts);
        let r = &rows[0];
        assert_eq!(r.error, None);
        assert_eq!(r.not_scored.is_none(), scored, "{:?}", r.not_scored);
        assert_eq!(r.ne_psi_pipeline_deg_per_min.is_some(), scored);
        let want_cells = [
            want.heading_change_deg,
            want.heading_change_sigma_deg,
            want.heading_change_smoothed_deg,
            want.final_bias_dps,
            want.final_bias_sigma_dps,
            want.stop_s,
        ];
        // Equal but for rounding: the scored run's headings are shifted to the reference.
        for (got, want) in r.summary_cells().iter().zip(want_cells) {
            assert!((got.unwrap() - want).abs() < 1e-9, "{:?} against {want_cells:?}", r.summary_cells());
        }
        assert!(want.stop_s > 60.0 && want.heading_change_deg.abs() > 10.0, "{want:?}");
    }
    let rows = score_log("blind.csv", "blind", blind, &opts);
    assert!(rows[0].not_scored.as_deref().unwrap().contains("ref_heading_deg"), "{:?}", rows[0].not_scored);
    let s = summarize(&[rows, score_log(&p, "city-1", log, &opts)].concat());
    assert_eq!((s.scored, s.not_scored, s.errors), (1, 1, 0));
    assert!(s.to_markdown().starts_with("2 files, 1 drives scored (0.3 h), 1 not scored (no reference), 0 errors"), "{}", s.to_markdown());
}

#[test]
fn a_bad_file_is_a_row_with_its_line_and_column() {
    let text = "time_s,gyro_dps,heading_ref_deg\n0,0.1,0\n1,abc,0\n";
    let rows = score_reader("bad.csv", "bad", text.as_bytes(), &FleetOptions::default());
    assert_eq!(rows.len(), 1);
    let e = rows[0].error.as_deref().unwrap();
    assert!(e.contains("line 3") && e.contains("gyro_dps"), "{e}");
    assert_eq!(rows[0].ne_psi_raw_deg_per_min, None);
}

#[test]
fn a_log_with_a_gap_gives_a_row_per_part() {
    let (p, mut log) = city();
    log.retain_rows(|t| !(300.0..360.0).contains(&t));
    let rows = score_log(&p, "city-1", log, &FleetOptions::default());
    assert_eq!(rows.len(), 2);
    assert_eq!((rows[1].part, rows[1].parts), (2, 2));
    assert!(rows[0].warnings.contains("split at 1 gap"), "{}", rows[0].warnings);
    assert!(rows.iter().all(|r| r.error.is_none() && r.ne_psi_hdr_deg_per_min.is_some()));
}

/// Two logs joined in one file: one error row naming the line by default; with the input
/// policy's `joined: "split"` a row each, scored as the log alone, the second unnamed one
/// named by the stem and its number, each saying which log it is.
#[test]
fn joined_logs_are_an_error_row_or_a_row_each_by_the_policy() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/city-1.csv")).unwrap();
    let unnamed: String = text.lines().filter(|l| !l.starts_with("# name:")).map(|l| format!("{l}\n")).collect();
    let joined = format!("{text}{unnamed}");
    let refused = score_reader("j.csv", "j", joined.as_bytes(), &FleetOptions::default());
    assert_eq!(refused.len(), 1);
    assert!(refused[0].error.as_deref().unwrap().contains("a second log joined on?"), "{:?}", refused[0].error);
    assert_eq!(refused[0].error_code.as_deref(), Some("joined"));
    let opts: FleetOptions = serde_json::from_str(r#"{"input": {"joined": "split"}}"#).unwrap();
    let rows = score_reader("j.csv", "j", joined.as_bytes(), &opts);
    let alone = score_reader("c.csv", "c", text.as_bytes(), &FleetOptions::default());
    assert_eq!(rows.iter().map(|r| r.name.as_str()).collect::<Vec<_>>(), ["City 1", "j (2)"]);
    let line = text.lines().count() + 1;
    assert!(rows[0].warnings.starts_with("log 1 of 2 joined in the file, from line 1"), "{}", rows[0].warnings);
    assert!(rows[1].warnings.starts_with(&format!("log 2 of 2 joined in the file, from line {line}")), "{}", rows[1].warnings);
    for r in &rows {
        assert_eq!((r.error.as_deref(), r.ne_psi_pipeline_deg_per_min), (None, alone[0].ne_psi_pipeline_deg_per_min));
    }
}

#[test]
fn the_summary_averages_scored_rows_and_counts_errors() {
    let row = |file: &str, raw: f64, hdr: f64| {
        let mut r = DriveRow::blank(file);
        r.duration_min = Some(30.0);
        for i in 0..METHODS.len() {
            let v = if i == 1 { hdr } else { raw };
            r.set_scores_for_test(i, v * 30.0, v);
        }
        r
    };
    let rows = vec![row("a", 1.0, 0.5), row("b", 3.0, 0.1), DriveRow::failed("c", "line 2: bad")];
    let s = summarize(&rows);
    assert_eq!((s.files, s.scored, s.errors), (3, 2, 1));
    assert!((s.hours - 1.0).abs() < 1e-12);
    let hdr = &s.methods[1];
    assert!((hdr.mean_ne_psi_deg_per_min - 0.3).abs() < 1e-12);
    assert!((hdr.mean_e_psi_deg - 9.0).abs() < 1e-12);
    assert_eq!(hdr.better_than_raw, 2);
    assert_eq!(s.methods[0].better_than_raw, 0);
    assert!(s.to_markdown().contains("| HDR Table III | 2 | 9.000 | 0.3000 |"), "{}", s.to_markdown());
}

/// Error rows another reading mends (or `ignore_check` runs) are counted by kind; a refusal
/// without one (a bad cell) and a failure that is not a refusal are errors only.
#[test]
fn the_summary_counts_refusals_by_kind() {
    let refusal = |text: &str| crate::log::accept::parse_by(text.as_bytes(), crate::log::accept::TimeOrder::Error).unwrap_err();
    let rows = vec![
        DriveRow::refused("a", &refusal("time_s\n0\n0\n")),
        DriveRow::refused("b", &refusal("time_s\n0\n1\n# name: b\ntime_s\n0\n")),
        DriveRow::refused("c", &refusal("time_s\n0\n1\n1\n")),
        DriveRow::refused("d", &refusal("time_s,gyro_dps\n0,x\n")),
        DriveRow::failed("e", "cannot open: no such file"),
    ];
    let codes: Vec<Option<&str>> = rows.iter().map(|r| r.error_code.as_deref()).collect();
    assert_eq!(codes, [Some("time_order"), Some("joined"), Some("time_order"), None, None]);
    // A log check refuses (a clockwise gyro): "check".
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/city-1.csv")).unwrap();
    let mut log = crate::log::parse_log_str(&text).unwrap();
    log.column_mut(crate::log::Column::GyroDps).unwrap().iter_mut().for_each(|v| *v = -*v);
    let cw = score_log("cw.csv", "cw", log, &FleetOptions::default());
    assert_eq!(cw[0].error_code.as_deref(), Some("check"), "{:?}", cw[0].error);
    let s = summarize(&[rows, cw].concat());
    assert_eq!(s.errors, 6);
    let by: Vec<(&str, usize)> = s.errors_by_code.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    assert_eq!(by, [("check", 1), ("joined", 1), ("time_order", 2)]);
}

/// A fleet where every file failed scores +0 h, not "-0.0 h" (an empty float sum is -0).
#[test]
fn a_fleet_with_nothing_scored_says_zero_hours() {
    let s = summarize(&[DriveRow::failed("a", "line 2: bad")]);
    assert_eq!((s.files, s.scored, s.errors), (1, 0, 1));
    assert!(s.hours == 0.0 && s.hours.is_sign_positive(), "{}", s.hours);
    assert!(s.to_markdown().starts_with("1 files, 0 drives scored (0.0 h), 1 errors"), "{}", s.to_markdown());
}

#[test]
fn csv_rows_have_the_header_and_quote_messages() {
    let rows = vec![DriveRow::failed("a,b.csv", "line 3, column gyro_dps: \"x\" is not a number")];
    let csv = rows_to_csv(&rows);
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(CSV_HEADER));
    let line = lines.next().unwrap();
    assert!(line.starts_with("\"a,b.csv\",1,1,\"a,b.csv\",0,,,"), "{line}");
    assert!(line.ends_with(",\"line 3, column gyro_dps: \"\"x\"\" is not a number\","), "{line}");
    assert_eq!(CSV_HEADER.split(',').count(), 31);
    // The header names are the JSON keys, in the struct's order.
    let json = serde_json::to_value(&rows[0]).unwrap();
    let keys: Vec<&str> = json.as_object().unwrap().keys().map(|k| k.as_str()).collect();
    let mut header: Vec<&str> = CSV_HEADER.split(',').collect();
    header.sort_unstable();
    let mut sorted = keys.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, header);
}

impl DriveRow {
    fn set_scores_for_test(&mut self, i: usize, e: f64, ne: f64) {
        let slot = match i {
            0 => (&mut self.e_psi_raw_deg, &mut self.ne_psi_raw_deg_per_min),
            1 => (&mut self.e_psi_hdr_deg, &mut self.ne_psi_hdr_deg_per_min),
            2 => (&mut self.e_psi_fusion_offset_deg, &mut self.ne_psi_fusion_offset_deg_per_min),
            3 => (&mut self.e_psi_zaru_deg, &mut self.ne_psi_zaru_deg_per_min),
            4 => (&mut self.e_psi_pipeline_deg, &mut self.ne_psi_pipeline_deg_per_min),
            _ => (&mut self.e_psi_pipeline_smoothed_deg, &mut self.ne_psi_pipeline_smoothed_deg_per_min),
        };
        *slot.0 = Some(e);
        *slot.1 = Some(ne);
    }
}

#[test]
fn an_opened_file_is_named_by_its_stem_and_one_that_failed_to_open_is_an_error_row() {
    let p = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/robot/square.csv"));
    let rows = score_opened(p, std::fs::File::open(p), &FleetOptions::default());
    assert_eq!(rows[0].file, p.display().to_string());
    let missing = std::path::Path::new("/nonexistent/drive-7.csv");
    let rows = score_opened(missing, std::fs::File::open(missing), &FleetOptions::default());
    assert!(rows[0].error.as_deref().unwrap().starts_with("cannot open: "), "{:?}", rows[0].error);
    assert_eq!(rows[0].file, "/nonexistent/drive-7.csv");
}

#[test]
fn fleet_options_refuse_a_misspelled_field_and_a_bad_setting() {
    use crate::options::from_json;
    assert!(from_json::<FleetOptions>(serde_json::json!({"pipelin": {}})).unwrap_err().to_string().contains("unknown field"));
    assert!(from_json::<FleetOptions>(serde_json::json!({"pipeline": {"min_still_s": -1}})).is_err());
    let o: FleetOptions = from_json(serde_json::json!({"input": {"gaps": "error"}})).unwrap();
    assert_eq!(o.input.gaps, crate::log::gaps::GapPolicy::Error);
}
