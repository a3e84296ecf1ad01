//! Every method side by side on the same drives and the same metric code (through
//! `eval`): raw integration, Table-III HDR, HDR tuned on training drives (optional), the
//! pipeline (causal and smoothed), and its two peers (x-io Fusion offset, ZARU at stops).

use crate::error::{Error, Result};
use crate::eval::{col, standard_methods, Prepared};
use crate::hdr::HdrParams;
use crate::log::DriveLog;
use crate::pipeline::PipelineParams;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// One drive: NE_psi (deg/min) of every method.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CompareRow {
    pub name: String,
    pub duration_min: f64,
    pub raw: f64,
    pub hdr_table_iii: f64,
    /// HDR with the tuned parameters (None without training drives).
    pub hdr_tuned: Option<f64>,
    pub pipeline: f64,
    /// The pipeline's offline smoothed mode (non-causal; not in the "best" column).
    pub pipeline_smoothed: f64,
    pub fusion_offset: f64,
    pub zaru: f64,
}

impl CompareRow {
    /// The pipeline beats raw integration and Table-III HDR on this drive.
    pub fn pipeline_beats_raw_and_hdr(&self) -> bool {
        self.pipeline < self.raw && self.pipeline < self.hdr_table_iii
    }
}

/// The table with its mean row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Compare {
    pub rows: Vec<CompareRow>,
    pub mean: CompareRow,
    /// The tuned HDR parameters, when tuned.
    pub tuned_params: Option<HdrParams>,
}

/// One drive's row: the log prepared once, every method scored on it.
pub fn compare_row(name: &str, log: &DriveLog, params: &PipelineParams, tuned: Option<HdrParams>) -> Result<CompareRow> {
    let prep = Prepared::new(log, params.bias_s, &params.still)?;
    let s = prep.score_all(&standard_methods(params, tuned))?;
    let ne = |i: usize| s[i].ne_psi_deg_per_min;
    Ok(CompareRow {
        name: name.to_string(),
        duration_min: prep.duration_min,
        raw: ne(col::RAW),
        hdr_table_iii: ne(col::HDR_TABLE_III),
        hdr_tuned: tuned.map(|_| ne(col::HDR_TUNED)),
        pipeline: ne(col::PIPELINE),
        pipeline_smoothed: ne(col::SMOOTHED),
        fusion_offset: ne(col::FUSION_OFFSET),
        zaru: ne(col::ZARU),
    })
}

/// NE_psi of every method on each drive; `tuned` = HDR parameters for the tuned column.
pub fn compare(drives: &[(String, &DriveLog)], params: &PipelineParams, tuned: Option<HdrParams>) -> Result<Compare> {
    if drives.is_empty() {
        return Err(Error::data("no drives to compare"));
    }
    params.validate()?;
    let rows =
        drives.iter().map(|(name, log)| compare_row(name, log, params, tuned).map_err(|e| e.within(name))).collect::<Result<Vec<_>>>()?;
    let n = rows.len() as f64;
    let mean = |f: fn(&CompareRow) -> f64| rows.iter().map(f).sum::<f64>() / n;
    let mean_row = CompareRow {
        name: format!("Mean of {}", rows.len()),
        duration_min: rows.iter().map(|r| r.duration_min).sum(),
        raw: mean(|r| r.raw),
        hdr_table_iii: mean(|r| r.hdr_table_iii),
        hdr_tuned: tuned.map(|_| mean(|r| r.hdr_tuned.unwrap_or(f64::NAN))),
        pipeline: mean(|r| r.pipeline),
        pipeline_smoothed: mean(|r| r.pipeline_smoothed),
        fusion_offset: mean(|r| r.fusion_offset),
        zaru: mean(|r| r.zaru),
    };
    Ok(Compare { rows, mean: mean_row, tuned_params: tuned })
}

impl Compare {
    /// Drives where the pipeline beats both raw integration and Table-III HDR.
    pub fn n_pipeline_wins(&self) -> usize {
        self.rows.iter().filter(|r| r.pipeline_beats_raw_and_hdr()).count()
    }

    /// A Markdown table of NE_psi (deg/min); the best method per drive in bold.
    /// Every drive's NE_psi per method as CSV (names quoted as needed), then the mean row;
    /// `hdr_tuned` is empty when nothing was tuned.
    pub fn to_csv(&self) -> String {
        let mut s = String::from("name,duration_min,raw,hdr_table_iii,hdr_tuned,pipeline,pipeline_smoothed,fusion_offset,zaru\n");
        let num = |v: f64| format!("{v:?}");
        for r in self.rows.iter().chain(std::iter::once(&self.mean)) {
            let cells = [
                num(r.duration_min),
                num(r.raw),
                num(r.hdr_table_iii),
                r.hdr_tuned.map(num).unwrap_or_default(),
                num(r.pipeline),
                num(r.pipeline_smoothed),
                num(r.fusion_offset),
                num(r.zaru),
            ];
            s += &crate::report::csv_line(&r.name, cells);
        }
        s
    }

    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        let tuned = self.tuned_params.is_some();
        let _ = write!(s, "| Drive | Duration (min) | raw | HDR Table III |");
        if tuned {
            let _ = write!(s, " HDR tuned |");
        }
        let _ = writeln!(s, " Fusion offset | ZARU at stops | **pipeline** | pipeline beats raw and HDR | smoothed (offline) |");
        let _ = write!(s, "|---|---:|---:|---:|");
        if tuned {
            let _ = write!(s, "---:|");
        }
        let _ = writeln!(s, "---:|---:|---:|:---:|---:|");
        for (i, r) in self.rows.iter().chain(std::iter::once(&self.mean)).enumerate() {
            let mut vals = vec![r.raw, r.hdr_table_iii];
            if tuned {
                vals.push(r.hdr_tuned.unwrap_or(f64::NAN));
            }
            vals.extend([r.fusion_offset, r.zaru, r.pipeline]);
            let best = vals.iter().copied().fold(f64::INFINITY, f64::min);
            let is_mean = i == self.rows.len();
            let name = if is_mean { format!("**{}**", r.name) } else { r.name.clone() };
            let _ = write!(s, "| {name} | {:.1} |", r.duration_min);
            for v in vals {
                if v == best {
                    let _ = write!(s, " **{v:.3}** |");
                } else {
                    let _ = write!(s, " {v:.3} |");
                }
            }
            let verdict = if is_mean {
                format!("{} of {}", self.n_pipeline_wins(), self.rows.len())
            } else if r.pipeline_beats_raw_and_hdr() {
                "yes".into()
            } else {
                "no".into()
            };
            let _ = writeln!(s, " {verdict} | {:.3} |", r.pipeline_smoothed);
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{simulate, SimRequest};

    #[test]
    fn compare_matches_the_single_runs_and_means() {
        let a = simulate(&SimRequest { scenario: Some("city".into()), minutes: Some(4.0), seed: 3, ..Default::default() }).unwrap();
        let b = simulate(&SimRequest { scenario: Some("highway".into()), minutes: Some(4.0), seed: 4, ..Default::default() }).unwrap();
        let p = PipelineParams::default();
        let c = compare(&[("a".into(), &a), ("b".into(), &b)], &p, Some(HdrParams { i_c_dps: 0.01, ..Default::default() })).unwrap();
        let ra = crate::pipeline::run(&a, &p).unwrap().result.unwrap();
        assert_eq!(c.rows[0].pipeline, ra.NE_psi_pipeline_deg_per_min);
        assert_eq!(c.rows[0].zaru, ra.NE_psi_zaru_deg_per_min);
        assert_eq!(c.rows[0].pipeline_smoothed, ra.NE_psi_pipeline_smoothed_deg_per_min);
        assert_eq!(c.rows[0].hdr_table_iii, ra.NE_psi_hdr_deg_per_min);
        assert_eq!(c.mean.raw, (c.rows[0].raw + c.rows[1].raw) / 2.0);
        let md = c.to_markdown();
        assert!(md.contains("| a | 4.0 |") && md.contains("**Mean of 2**") && md.contains("HDR tuned"));
        assert!(compare(&[], &p, None).is_err());
    }
}
