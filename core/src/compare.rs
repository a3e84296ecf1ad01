//! Every method side by side on the same drives and the same metric code: raw integration,
//! Table-III HDR, HDR tuned on training drives (optional), the pipeline, and its two peers
//! (x-io Fusion offset, ZARU at stops). NE_psi per drive, means, and which goals hold.

use crate::error::{Error, Result};
use crate::hdr::{self, HdrOptions, HdrParams};
use crate::log::DriveLog;
use crate::pipeline::{self, PipelineParams};
use crate::report::prefix;
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

/// NE_psi of every method on each drive; `tuned` = HDR parameters for the tuned column.
pub fn compare(drives: &[(String, &DriveLog)], params: &PipelineParams, tuned: Option<HdrParams>) -> Result<Compare> {
    if drives.is_empty() {
        return Err(Error::data("no drives to compare"));
    }
    let mut rows = Vec::with_capacity(drives.len());
    for (name, log) in drives {
        let at = |e: Error| prefix(name, e);
        let r = pipeline::run(log, params).map_err(at)?.result.map_err(at)?;
        let hdr_tuned = match tuned {
            Some(p) => {
                let opts = HdrOptions { params: p, bias_s: params.bias_s, ..Default::default() };
                Some(hdr::run(log, &opts).map_err(at)?.result.map_err(at)?.NE_psi_hdr_deg_per_min)
            }
            None => None,
        };
        rows.push(CompareRow {
            name: name.clone(),
            duration_min: r.duration_min,
            raw: r.NE_psi_raw_deg_per_min,
            hdr_table_iii: r.NE_psi_hdr_deg_per_min,
            hdr_tuned,
            pipeline: r.NE_psi_pipeline_deg_per_min,
            fusion_offset: r.NE_psi_fusion_offset_deg_per_min,
            zaru: r.NE_psi_zaru_deg_per_min,
        });
    }
    let n = rows.len() as f64;
    let mean = |f: fn(&CompareRow) -> f64| rows.iter().map(f).sum::<f64>() / n;
    let mean_row = CompareRow {
        name: format!("Mean of {}", rows.len()),
        duration_min: rows.iter().map(|r| r.duration_min).sum(),
        raw: mean(|r| r.raw),
        hdr_table_iii: mean(|r| r.hdr_table_iii),
        hdr_tuned: tuned.map(|_| mean(|r| r.hdr_tuned.unwrap_or(f64::NAN))),
        pipeline: mean(|r| r.pipeline),
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
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        let tuned = self.tuned_params.is_some();
        let _ = write!(s, "| Drive | Duration (min) | raw | HDR Table III |");
        if tuned {
            let _ = write!(s, " HDR tuned |");
        }
        let _ = writeln!(s, " Fusion offset | ZARU at stops | **pipeline** | pipeline beats raw and HDR |");
        let _ = write!(s, "|---|---:|---:|---:|");
        if tuned {
            let _ = write!(s, "---:|");
        }
        let _ = writeln!(s, "---:|---:|---:|:---:|");
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
            let _ = writeln!(s, " {verdict} |");
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{simulate, SimKind, SimRequest};

    #[test]
    fn compare_matches_the_single_runs_and_means() {
        let a = simulate(&SimRequest { kind: SimKind::Drive, scenario: Some("city".into()), minutes: Some(4.0), seed: 3, name: None }).unwrap();
        let b = simulate(&SimRequest { kind: SimKind::Drive, scenario: Some("highway".into()), minutes: Some(4.0), seed: 4, name: None }).unwrap();
        let p = PipelineParams::default();
        let c = compare(&[("a".into(), &a), ("b".into(), &b)], &p, Some(HdrParams { i_c_dps: 0.01, ..Default::default() })).unwrap();
        let ra = pipeline::run(&a, &p).unwrap().result.unwrap();
        assert_eq!(c.rows[0].pipeline, ra.NE_psi_pipeline_deg_per_min);
        assert_eq!(c.rows[0].zaru, ra.NE_psi_zaru_deg_per_min);
        assert_eq!(c.mean.raw, (c.rows[0].raw + c.rows[1].raw) / 2.0);
        let md = c.to_markdown();
        assert!(md.contains("| a | 4.0 |") && md.contains("**Mean of 2**") && md.contains("HDR tuned"));
        assert!(compare(&[], &p, None).is_err());
    }
}
