//! Fleet batches: one flat row per drive (every method's E_psi and NE_psi, or the error that
//! stopped it), and the paper's Table II over a fleet. The CLI's `report --dir`, the Python
//! package and its Dask job all make their rows here, so a drive scores the same whichever
//! front ran it. A drive that fails is a row with its message, never a failed batch.

use crate::error::Result;
use crate::eval::{col, standard_methods, MethodScore, Prepared};
use crate::log::accept::{accept, InputPolicy};
use crate::log::DriveLog;
use crate::metrics::quantile;
use crate::pipeline::{PipelineParams, PipelineSummary};
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use std::io::Read;

mod hints;
pub use hints::{refusal_hints, ForeignReading, RefusalHint, Remedy};

/// What a batch does with each log: the input policy (gaps, check errors) and the pipeline's
/// settings (the other methods run with their defaults: Table-III HDR, Fusion's offset, ZARU).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FleetOptions {
    pub input: InputPolicy,
    pub pipeline: PipelineParams,
}

impl crate::options::Settings for FleetOptions {
    /// The pipeline's settings (the input policy has no ranges).
    fn validate(&self) -> Result<()> {
        self.pipeline.validate()
    }
}

/// The methods of a fleet row, in column order: (column stem, label).
pub const METHODS: [(&str, &str); 6] = [
    ("raw", "raw"),
    ("hdr", "HDR Table III"),
    ("fusion_offset", "Fusion offset"),
    ("zaru", "ZARU"),
    ("pipeline", "pipeline"),
    ("pipeline_smoothed", "smoothed (offline)"),
];

/// One drive, or one part of a drive split at a gap, or a file that could not be scored.
/// Flat, so it maps to one Parquet or DataFrame row; scores are None on an error row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DriveRow {
    /// The file (or drive key) the row came from.
    pub file: String,
    /// 1-based part of a log split at gaps; 1 without gaps.
    pub part: u32,
    pub parts: u32,
    /// `# name:` or the file stem, with "(part i of n)" for a split log.
    pub name: String,
    pub rows: u64,
    pub duration_min: Option<f64>,
    /// What the still flags came from: speed, odometry, gyro or none.
    pub still_source: Option<String>,
    /// Static bias over the lead-in, deg/s.
    pub static_bias_dps: Option<f64>,
    /// How far the gyro's bias moved between the standings the speed or the wheels show:
    /// the rate of the standing furthest from the first, less the first's (medians, as
    /// `check`'s `stop_bias_dps` and its `bias_drift` finding), deg/s; None with fewer than
    /// two standings.
    pub stop_bias_drift_dps: Option<f64>,
    pub e_psi_raw_deg: Option<f64>,
    pub ne_psi_raw_deg_per_min: Option<f64>,
    pub e_psi_hdr_deg: Option<f64>,
    pub ne_psi_hdr_deg_per_min: Option<f64>,
    pub e_psi_fusion_offset_deg: Option<f64>,
    pub ne_psi_fusion_offset_deg_per_min: Option<f64>,
    pub e_psi_zaru_deg: Option<f64>,
    pub ne_psi_zaru_deg_per_min: Option<f64>,
    pub e_psi_pipeline_deg: Option<f64>,
    pub ne_psi_pipeline_deg_per_min: Option<f64>,
    pub e_psi_pipeline_smoothed_deg: Option<f64>,
    pub ne_psi_pipeline_smoothed_deg_per_min: Option<f64>,
    /// The pipeline's own figures at the end of the drive, scored or not (a drive without
    /// a reference has only these): heading turned, causal with its sigma and smoothed, deg;
    /// final bias and its sigma, deg/s; time whose stop evidence was used, s.
    pub pipeline_heading_change_deg: Option<f64>,
    pub pipeline_heading_change_sigma_deg: Option<f64>,
    pub pipeline_heading_change_smoothed_deg: Option<f64>,
    pub pipeline_final_bias_dps: Option<f64>,
    pub pipeline_final_bias_sigma_dps: Option<f64>,
    pub pipeline_stop_s: Option<f64>,
    /// The check's warnings and what splitting did, "; "-separated (empty when none).
    pub warnings: String,
    /// Why a drive without a reference heading has no scores (not an error: the
    /// pipeline's figures are there).
    pub not_scored: Option<String>,
    /// Why this file or part has no scores.
    pub error: Option<String>,
    /// Where another reading mends the file's refusal, its kind (core's
    /// `log::accept::Refusal` code: "time_order", "clock_reset", "joined", "cut_row",
    /// "foreign" for a table without `time_s` (a logger's own export: an import reads it), or
    /// "check" for a unit or sign mistake), so a fleet's failures are sorted by the option
    /// that reads them; None otherwise.
    pub error_code: Option<String>,
}

impl DriveRow {
    /// A row that says why `file` has no scores.
    pub fn failed(file: &str, message: impl Into<String>) -> DriveRow {
        DriveRow { error: Some(message.into()), ..DriveRow::blank(file) }
    }

    /// A row that says why `file` was refused, with the refusal's kind where it has one.
    pub fn refused(file: &str, e: &crate::Error) -> DriveRow {
        let error_code = crate::log::accept::Refusal::of(e).map(|r| r.code().to_string());
        DriveRow { error_code, ..DriveRow::failed(file, e.to_string()) }
    }

    /// A row of `file` with nothing in it yet.
    fn blank(file: &str) -> DriveRow {
        DriveRow {
            file: file.to_string(),
            part: 1,
            parts: 1,
            name: file.to_string(),
            rows: 0,
            duration_min: None,
            still_source: None,
            static_bias_dps: None,
            stop_bias_drift_dps: None,
            e_psi_raw_deg: None,
            ne_psi_raw_deg_per_min: None,
            e_psi_hdr_deg: None,
            ne_psi_hdr_deg_per_min: None,
            e_psi_fusion_offset_deg: None,
            ne_psi_fusion_offset_deg_per_min: None,
            e_psi_zaru_deg: None,
            ne_psi_zaru_deg_per_min: None,
            e_psi_pipeline_deg: None,
            ne_psi_pipeline_deg_per_min: None,
            e_psi_pipeline_smoothed_deg: None,
            ne_psi_pipeline_smoothed_deg_per_min: None,
            pipeline_heading_change_deg: None,
            pipeline_heading_change_sigma_deg: None,
            pipeline_heading_change_smoothed_deg: None,
            pipeline_final_bias_dps: None,
            pipeline_final_bias_sigma_dps: None,
            pipeline_stop_s: None,
            warnings: String::new(),
            not_scored: None,
            error: None,
            error_code: None,
        }
    }

    /// (E_psi, NE_psi) of method `i` of [`METHODS`].
    pub fn score(&self, i: usize) -> (Option<f64>, Option<f64>) {
        match i {
            0 => (self.e_psi_raw_deg, self.ne_psi_raw_deg_per_min),
            1 => (self.e_psi_hdr_deg, self.ne_psi_hdr_deg_per_min),
            2 => (self.e_psi_fusion_offset_deg, self.ne_psi_fusion_offset_deg_per_min),
            3 => (self.e_psi_zaru_deg, self.ne_psi_zaru_deg_per_min),
            4 => (self.e_psi_pipeline_deg, self.ne_psi_pipeline_deg_per_min),
            5 => (self.e_psi_pipeline_smoothed_deg, self.ne_psi_pipeline_smoothed_deg_per_min),
            _ => (None, None),
        }
    }

    fn set_scores(&mut self, s: &[MethodScore]) {
        let get = |c: usize| (Some(s[c].e_psi_deg), Some(s[c].ne_psi_deg_per_min));
        (self.e_psi_raw_deg, self.ne_psi_raw_deg_per_min) = get(col::RAW);
        (self.e_psi_hdr_deg, self.ne_psi_hdr_deg_per_min) = get(col::HDR_TABLE_III);
        (self.e_psi_fusion_offset_deg, self.ne_psi_fusion_offset_deg_per_min) = get(col::FUSION_OFFSET);
        (self.e_psi_zaru_deg, self.ne_psi_zaru_deg_per_min) = get(col::ZARU);
        (self.e_psi_pipeline_deg, self.ne_psi_pipeline_deg_per_min) = get(col::PIPELINE);
        (self.e_psi_pipeline_smoothed_deg, self.ne_psi_pipeline_smoothed_deg_per_min) = get(col::SMOOTHED);
    }

    fn set_summary(&mut self, s: &PipelineSummary) {
        self.pipeline_heading_change_deg = Some(s.heading_change_deg);
        self.pipeline_heading_change_sigma_deg = Some(s.heading_change_sigma_deg);
        self.pipeline_heading_change_smoothed_deg = Some(s.heading_change_smoothed_deg);
        self.pipeline_final_bias_dps = Some(s.final_bias_dps);
        self.pipeline_final_bias_sigma_dps = Some(s.final_bias_sigma_dps);
        self.pipeline_stop_s = Some(s.stop_s);
    }

    /// The pipeline's summary columns in [`CSV_HEADER`] order.
    fn summary_cells(&self) -> [Option<f64>; 6] {
        [
            self.pipeline_heading_change_deg,
            self.pipeline_heading_change_sigma_deg,
            self.pipeline_heading_change_smoothed_deg,
            self.pipeline_final_bias_dps,
            self.pipeline_final_bias_sigma_dps,
            self.pipeline_stop_s,
        ]
    }
}

/// Scores one part: the log prepared once, the pipeline run once (its summary), every
/// method on it; a part without a reference heading keeps the summary, `not_scored`.
fn score_part(row: &mut DriveRow, part: &DriveLog, params: &PipelineParams) -> Result<()> {
    let prep = Prepared::new(part, params.bias_s, &params.still)?;
    row.duration_min = Some(prep.duration_min);
    row.static_bias_dps = Some(prep.eps0_dps);
    row.still_source = Some(prep.blocks.source.name().to_string());
    let stops = crate::check::drift::standings(&prep.blocks);
    row.stop_bias_drift_dps = crate::check::drift::furthest(&stops).filter(|_| stops.len() > 1).map(|(a, b)| b.1 - a.1);
    let trace = prep.pipeline_trace(params)?;
    row.set_summary(&trace.summary(prep.blocks.source, trace.stop_s(), prep.duration_min));
    // The pipeline's two columns from the run just made, not a second one.
    let methods = standard_methods(params, None);
    let scores = prep.score_all(&methods[..col::PIPELINE]).and_then(|mut s| {
        s.extend(prep.score_trace(&trace)?);
        Ok(s)
    });
    match scores {
        Ok(scores) => row.set_scores(&scores),
        // As the CLI's `pipeline` and `hdr`: no reference value at all is not an error.
        Err(e) if !part.has_reference() => row.not_scored = Some(e.to_string()),
        Err(e) => return Err(e),
    }
    Ok(())
}

/// Every part of a parsed log as rows (`file` labels them; `stem` names a log without
/// `# name:`). A log the input policy refuses is one error row; a part that fails is an error
/// row beside the parts that scored.
pub fn score_log(file: &str, stem: &str, log: DriveLog, opts: &FleetOptions) -> Vec<DriveRow> {
    if let Err(e) = opts.pipeline.validate() {
        return vec![DriveRow::failed(file, e.to_string())];
    }
    let accepted = match accept(log, stem, opts.input, opts.pipeline.bias_s) {
        Ok(a) => a,
        Err(e) => return vec![DriveRow::refused(file, &e)],
    };
    let warnings = accepted.warnings.iter().chain(&accepted.split).cloned().collect::<Vec<_>>().join("; ");
    let n = accepted.parts.len() as u32;
    let mut rows = Vec::with_capacity(accepted.parts.len());
    for (i, part) in accepted.parts.iter().enumerate() {
        let mut row = DriveRow::blank(file);
        row.part = i as u32 + 1;
        row.parts = n;
        row.name = part.meta.name.clone().unwrap_or_else(|| stem.to_string());
        row.rows = part.len() as u64;
        row.warnings = warnings.clone();
        if let Err(e) = score_part(&mut row, part, &opts.pipeline) {
            row.error = Some(e.to_string());
        }
        rows.push(row);
    }
    rows
}

/// A log file's rows, the front having opened it (core reads, it does not open files): the
/// rows are labelled by the path, a log without `# name:` is named by the file's stem, and a
/// file that could not be opened is one error row.
pub fn score_opened<R: Read>(path: &std::path::Path, opened: std::io::Result<R>, opts: &FleetOptions) -> Vec<DriveRow> {
    let label = path.display().to_string();
    let stem = crate::log::file::log_stem(path);
    match opened {
        Ok(r) => score_reader(&label, &stem, r, opts),
        Err(e) => vec![DriveRow::failed(&label, format!("cannot open: {e}"))],
    }
}

/// A log file's rows from its bytes, as fetched from an object store (gzip-compressed too):
/// labelled `file` (its URL), a log without `# name:` named by the file's stem, as
/// `score_opened` names it.
#[cfg(feature = "zip")]
pub fn score_bytes(file: &str, bytes: &[u8], opts: &FleetOptions) -> Vec<DriveRow> {
    let stem = crate::log::file::log_stem(std::path::Path::new(file));
    match crate::log::file::decompressed(bytes) {
        Ok(r) => score_reader(file, &stem, r, opts),
        Err(e) => vec![DriveRow::failed(file, format!("cannot read: {e}"))],
    }
}

/// Parses a v1 log from `reader` and scores it; a parse error is one error row naming the
/// line and column.
/// With the input policy's `joined: "split"`, a file of several logs joined on gives each
/// log's rows, an unnamed one named by the stem and its number.
pub fn score_reader<R: Read>(file: &str, stem: &str, reader: R, opts: &FleetOptions) -> Vec<DriveRow> {
    let logs = match crate::log::accept::parse_by_policy(reader, opts.input) {
        Ok(logs) => logs,
        Err(e) => return vec![DriveRow::refused(file, &e)],
    };
    let n = logs.len();
    let mut rows = Vec::new();
    for (k, (log, fixed)) in logs.into_iter().enumerate() {
        let mut these = score_log(file, &crate::log::accept::stem_in_file(stem, k, n), log, opts);
        // What reading the file fixed (time order, a cut last line) is the rows' first warning.
        if let Some(f) = fixed {
            for r in &mut these {
                r.warnings = if r.warnings.is_empty() { f.clone() } else { format!("{f}; {}", r.warnings) };
            }
        }
        rows.append(&mut these);
    }
    rows
}

/// The recordings of a logger's raw exports among the files of `rows` that failed
/// (`import::recordings`), their files' error rows taken out of `rows`: what `--import`
/// scores instead (`score_recording`).
/// With a `recipe`, the recordings it reads (`import::recipe_recordings`) instead of the
/// presets'.
#[cfg(feature = "fs")]
pub fn take_recordings(rows: &mut Vec<DriveRow>, recipe: Option<&crate::import::Recipe>) -> Vec<crate::import::Recording> {
    let failed: Vec<std::path::PathBuf> = rows.iter().filter(|r| r.error.is_some()).map(|r| std::path::PathBuf::from(&r.file)).collect();
    let recs = match recipe {
        Some(r) => crate::import::recipe_recordings(&failed, r),
        None => crate::import::recordings(&failed),
    };
    let taken: std::collections::HashSet<String> =
        recs.iter().flat_map(|r| r.files.iter().chain(&r.ignored).map(|p| p.display().to_string())).collect();
    rows.retain(|r| r.error.is_none() || !taken.contains(&r.file));
    recs
}

/// One recording of raw exports (`import::Recording`) imported by `recipe`, or by the
/// preset detected from its files, and scored as a drive labelled by its file or folder:
/// named by the import (a one-file export's file and preset; a recipe's name is the
/// recording's file stem), or by the folder when it has several files, whose first file would
/// name every folder alike. An import that fails is one error row.
#[cfg(feature = "fs")]
pub fn score_recording(rec: &crate::import::Recording, recipe: Option<&crate::import::Recipe>, opts: &FleetOptions) -> Vec<DriveRow> {
    let label = rec.label.display().to_string();
    let stem = rec.label.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let imported = match recipe {
        Some(r) => crate::import::import_recording(r, rec).map(|(log, _)| log),
        None => crate::import::import_paths(&rec.files).map(|(_, log, _)| log),
    };
    match imported {
        Ok(mut log) => {
            if recipe.is_some() || rec.files.len() > 1 {
                log.meta.name = Some(stem.clone());
            }
            score_log(&label, &stem, log, opts)
        }
        Err(e) => vec![DriveRow::failed(&label, e.to_string())],
    }
}

/// One method over the fleet.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MethodSummary {
    pub method: String,
    /// Drives (parts) scored.
    pub drives: usize,
    pub mean_e_psi_deg: f64,
    pub mean_ne_psi_deg_per_min: f64,
    pub median_ne_psi_deg_per_min: f64,
    pub p90_ne_psi_deg_per_min: f64,
    /// Drives on which this method's NE_psi is below raw integration's.
    pub better_than_raw: usize,
}

/// The paper's Table II over a fleet: every method's mean and spread of E_psi and NE_psi.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FleetSummary {
    pub files: usize,
    /// Rows scored (a split log gives one per part).
    pub scored: usize,
    /// Rows without a reference heading (the pipeline's figures, no scores).
    pub not_scored: usize,
    /// Rows with an error.
    pub errors: usize,
    /// The error rows another reading mends, counted by kind (`DriveRow::error_code`), so a
    /// front names the option once for all of them.
    pub errors_by_code: std::collections::BTreeMap<String, usize>,
    pub hours: f64,
    pub methods: Vec<MethodSummary>,
}

/// Summarises rows; methods are compared on the rows every method scored.
pub fn summarize(rows: &[DriveRow]) -> FleetSummary {
    let scored: Vec<&DriveRow> = rows.iter().filter(|r| r.error.is_none() && r.ne_psi_raw_deg_per_min.is_some()).collect();
    let mut files: Vec<&str> = rows.iter().map(|r| r.file.as_str()).collect();
    files.sort_unstable();
    files.dedup();
    let mean = |v: &[f64]| if v.is_empty() { f64::NAN } else { v.iter().sum::<f64>() / v.len() as f64 };
    let methods = METHODS
        .iter()
        .enumerate()
        .map(|(i, (_, label))| {
            let (e, ne): (Vec<f64>, Vec<f64>) = scored.iter().filter_map(|r| Some((r.score(i).0?, r.score(i).1?))).unzip();
            let better =
                scored.iter().filter(|r| matches!((r.score(i).1, r.ne_psi_raw_deg_per_min), (Some(m), Some(raw)) if m < raw)).count();
            MethodSummary {
                method: label.to_string(),
                drives: ne.len(),
                mean_e_psi_deg: mean(&e),
                mean_ne_psi_deg_per_min: mean(&ne),
                median_ne_psi_deg_per_min: quantile(&ne, 0.5),
                p90_ne_psi_deg_per_min: quantile(&ne, 0.9),
                better_than_raw: better,
            }
        })
        .collect();
    FleetSummary {
        files: files.len(),
        scored: scored.len(),
        not_scored: rows.iter().filter(|r| r.error.is_none() && r.not_scored.is_some()).count(),
        errors: rows.iter().filter(|r| r.error.is_some()).count(),
        errors_by_code: rows.iter().filter_map(|r| r.error_code.clone()).fold(Default::default(), |mut m, c| {
            *m.entry(c).or_insert(0) += 1;
            m
        }),
        // + 0: an empty float sum is -0 in Rust ("-0.0 h" when nothing scored).
        hours: (scored.iter().filter_map(|r| r.duration_min).sum::<f64>() + 0.0) / 60.0,
        methods,
    }
}

impl FleetSummary {
    /// A Markdown table with a line above it saying what was scored.
    pub fn to_markdown(&self) -> String {
        let unscored = if self.not_scored > 0 { format!(", {} not scored (no reference)", self.not_scored) } else { String::new() };
        let mut s = format!(
            "{} files, {} drives scored ({:.1} h){unscored}, {} errors\n\n| method | drives | mean E_psi (deg) | mean NE_psi (deg/min) | median NE_psi | p90 NE_psi | better than raw |\n|---|---:|---:|---:|---:|---:|---:|\n",
            self.files, self.scored, self.hours, self.errors
        );
        for m in &self.methods {
            let _ = writeln!(
                s,
                "| {} | {} | {:.3} | {:.4} | {:.4} | {:.4} | {} |",
                m.method,
                m.drives,
                m.mean_e_psi_deg,
                m.mean_ne_psi_deg_per_min,
                m.median_ne_psi_deg_per_min,
                m.p90_ne_psi_deg_per_min,
                m.better_than_raw
            );
        }
        s
    }
}

/// The rows as CSV, one header row with the field names of [`DriveRow`]; an empty cell for
/// None.
pub fn rows_to_csv(rows: &[DriveRow]) -> String {
    let mut s = String::from(CSV_HEADER);
    s.push('\n');
    let num = |v: Option<f64>| v.map(|x| format!("{x:?}")).unwrap_or_default();
    for r in rows {
        let mut cells = vec![r.part.to_string(), r.parts.to_string(), r.name.clone(), r.rows.to_string()];
        cells.push(num(r.duration_min));
        cells.push(r.still_source.clone().unwrap_or_default());
        cells.push(num(r.static_bias_dps));
        cells.push(num(r.stop_bias_drift_dps));
        for i in 0..METHODS.len() {
            let (e, ne) = r.score(i);
            cells.push(num(e));
            cells.push(num(ne));
        }
        cells.extend(r.summary_cells().map(num));
        cells.push(r.warnings.clone());
        cells.push(r.not_scored.clone().unwrap_or_default());
        cells.push(r.error.clone().unwrap_or_default());
        cells.push(r.error_code.clone().unwrap_or_default());
        s.push_str(&crate::report::csv_line(&r.file, cells));
    }
    s
}

/// The header of [`rows_to_csv`]: the field names of [`DriveRow`] in order.
pub const CSV_HEADER: &str = "file,part,parts,name,rows,duration_min,still_source,static_bias_dps,stop_bias_drift_dps,\
e_psi_raw_deg,ne_psi_raw_deg_per_min,e_psi_hdr_deg,ne_psi_hdr_deg_per_min,\
e_psi_fusion_offset_deg,ne_psi_fusion_offset_deg_per_min,e_psi_zaru_deg,ne_psi_zaru_deg_per_min,\
e_psi_pipeline_deg,ne_psi_pipeline_deg_per_min,e_psi_pipeline_smoothed_deg,ne_psi_pipeline_smoothed_deg_per_min,\
pipeline_heading_change_deg,pipeline_heading_change_sigma_deg,pipeline_heading_change_smoothed_deg,\
pipeline_final_bias_dps,pipeline_final_bias_sigma_dps,pipeline_stop_s,\
warnings,not_scored,error,error_code";

#[cfg(test)]
mod tests;
