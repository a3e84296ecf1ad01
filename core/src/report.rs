//! The HDR paper's Table II for any set of drives: per drive its duration, E_psi and NE_psi
//! without and with HDR, the improvement; the average row with the improvement's standard
//! deviation (sample, n - 1, as the paper's 7.75 and 3.44).

use crate::error::{Error, Result};
use crate::hdr::{self, HdrOptions};
use crate::log::DriveLog;
use crate::metrics::mean_std;
use serde::{Deserialize, Serialize};

/// One drive's row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ReportRow {
    pub name: String,
    pub duration_min: f64,
    pub E_psi_raw_deg: f64,
    pub NE_psi_raw_deg_per_min: f64,
    pub E_psi_hdr_deg: f64,
    pub NE_psi_hdr_deg_per_min: f64,
    pub improvement: f64,
}

/// The table with its average row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct Report {
    pub rows: Vec<ReportRow>,
    pub total_duration_min: f64,
    pub mean_E_psi_raw_deg: f64,
    pub mean_NE_psi_raw_deg_per_min: f64,
    pub mean_E_psi_hdr_deg: f64,
    pub mean_NE_psi_hdr_deg_per_min: f64,
    pub mean_improvement: f64,
    /// Sample standard deviation of the improvement (the paper's sigma-hat).
    pub std_improvement: f64,
}

impl ReportRow {
    /// The row's numbers in column order: duration, E_psi and NE_psi raw, with HDR, improvement.
    fn values(&self) -> [f64; 6] {
        [
            self.duration_min,
            self.E_psi_raw_deg,
            self.NE_psi_raw_deg_per_min,
            self.E_psi_hdr_deg,
            self.NE_psi_hdr_deg_per_min,
            self.improvement,
        ]
    }

    pub fn from_result(name: &str, r: &hdr::HdrResult) -> Self {
        ReportRow {
            name: name.to_string(),
            duration_min: r.duration_min,
            E_psi_raw_deg: r.E_psi_raw_deg,
            NE_psi_raw_deg_per_min: r.NE_psi_raw_deg_per_min,
            E_psi_hdr_deg: r.E_psi_hdr_deg,
            NE_psi_hdr_deg_per_min: r.NE_psi_hdr_deg_per_min,
            improvement: r.improvement,
        }
    }
}

impl Report {
    /// The average row over the given rows.
    pub fn from_rows(rows: Vec<ReportRow>) -> Result<Report> {
        if rows.is_empty() {
            return Err(Error::data("no drives to report on"));
        }
        let col = |f: fn(&ReportRow) -> f64| -> Vec<f64> { rows.iter().map(f).collect() };
        let (mean_improvement, std_improvement) = mean_std(&col(|r| r.improvement));
        Ok(Report {
            total_duration_min: col(|r| r.duration_min).iter().sum(),
            mean_E_psi_raw_deg: mean_std(&col(|r| r.E_psi_raw_deg)).0,
            mean_NE_psi_raw_deg_per_min: mean_std(&col(|r| r.NE_psi_raw_deg_per_min)).0,
            mean_E_psi_hdr_deg: mean_std(&col(|r| r.E_psi_hdr_deg)).0,
            mean_NE_psi_hdr_deg_per_min: mean_std(&col(|r| r.NE_psi_hdr_deg_per_min)).0,
            mean_improvement,
            std_improvement,
            rows,
        })
    }

    /// Runs HDR with the same options on every drive and tabulates (errors name the drive).
    pub fn build(drives: &[(String, &DriveLog)], opts: &HdrOptions) -> Result<Report> {
        let mut rows = Vec::with_capacity(drives.len());
        for (name, log) in drives {
            let r = hdr::run(log, opts).and_then(|run| run.result).map_err(|e| e.within(name))?;
            rows.push(ReportRow::from_result(name, &r));
        }
        Report::from_rows(rows)
    }

    /// The average row's numbers in column order (total duration, then the means).
    fn mean_values(&self) -> [f64; 6] {
        [
            self.total_duration_min,
            self.mean_E_psi_raw_deg,
            self.mean_NE_psi_raw_deg_per_min,
            self.mean_E_psi_hdr_deg,
            self.mean_NE_psi_hdr_deg_per_min,
            self.mean_improvement,
        ]
    }

    /// The table as Markdown, laid out like the paper's Table II.
    pub fn to_markdown(&self) -> String {
        let mut s = String::from(
            "| Drive | Duration (min) | E_psi without HDR (deg) | NE_psi without HDR (deg/min) | E_psi with HDR (deg) | NE_psi with HDR (deg/min) | Improvement |\n\
             |---|---:|---:|---:|---:|---:|---:|\n",
        );
        for r in &self.rows {
            let [d, er, nr, eh, nh, imp] = r.values();
            s.push_str(&format!("| {} | {d:.1} | {er:.1} | {nr:.2} | {eh:.1} | {nh:.2} | {imp:.1}x |\n", r.name));
        }
        let ([d, er, nr, eh, nh, imp], sd) = (self.mean_values(), self.std_improvement);
        let n = self.rows.len();
        s.push_str(&format!(
            "| **Average of {n}** | {d:.1} total | {er:.1} | {nr:.2} | {eh:.1} | {nh:.2} | {imp:.1}x (sigma = {sd:.2}) |\n"
        ));
        s
    }

    /// The table as CSV (names quoted as needed): one row per drive, then the average.
    /// Written by hand: the csv crate's serde writer costs the wasm package 26 KB gzipped.
    pub fn to_csv(&self) -> String {
        let mut s =
            String::from("name,duration_min,E_psi_raw_deg,NE_psi_raw_deg_per_min,E_psi_hdr_deg,NE_psi_hdr_deg_per_min,improvement\n");
        for r in &self.rows {
            s += &csv_line(&r.name, r.values().iter().map(|v| format!("{v:?}")));
        }
        let avg = format!("average of {}", self.rows.len());
        s += &csv_line(&avg, self.mean_values().iter().map(|v| format!("{v:?}")));
        s
    }

    /// The table as aligned plain text with units.
    pub fn to_text(&self) -> String {
        // Column width from the names, capped: `{:<w$}` panics for widths over 65 535, and a
        // longer name is only padded less.
        let w = self.rows.iter().map(|r| r.name.len()).max().unwrap_or(5).clamp(12, 80);
        let mut s = format!(
            "{:<w$} {:>9} {:>11} {:>13} {:>11} {:>13} {:>8}\n{:<w$} {:>9} {:>11} {:>13} {:>11} {:>13} {:>8}\n",
            "drive",
            "duration",
            "E_psi raw",
            "NE_psi raw",
            "E_psi HDR",
            "NE_psi HDR",
            "improv.",
            "",
            "(min)",
            "(deg)",
            "(deg/min)",
            "(deg)",
            "(deg/min)",
            "",
        );
        for r in &self.rows {
            let [d, er, nr, eh, nh, imp] = r.values();
            s.push_str(&format!("{:<w$} {d:>9.1} {er:>11.2} {nr:>13.3} {eh:>11.2} {nh:>13.3} {imp:>7.2}x\n", r.name));
        }
        let ([d, er, nr, eh, nh, imp], sd) = (self.mean_values(), self.std_improvement);
        let name = format!("average of {}", self.rows.len());
        s.push_str(&format!("{name:<w$} {d:>9.1} {er:>11.2} {nr:>13.3} {eh:>11.2} {nh:>13.3} {imp:>7.2}x (sigma {sd:.2})\n"));
        s
    }
}

/// One CSV field: quoted when it holds a comma, quote or line break.
pub fn csv_field(cell: &str) -> String {
    if cell.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", cell.replace('"', "\"\""))
    } else {
        cell.to_string()
    }
}

/// One CSV line: the name, then the cells, each quoted as needed.
pub fn csv_line(name: &str, cells: impl IntoIterator<Item = String>) -> String {
    let mut s = csv_field(name);
    for c in cells {
        s.push(',');
        s += &csv_field(&c);
    }
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(name: &str, imp: f64) -> ReportRow {
        ReportRow {
            name: name.into(),
            duration_min: 10.0,
            E_psi_raw_deg: imp * 2.0,
            NE_psi_raw_deg_per_min: imp * 0.2,
            E_psi_hdr_deg: 2.0,
            NE_psi_hdr_deg_per_min: 0.2,
            improvement: imp,
        }
    }

    #[test]
    fn average_row_matches_the_papers_table_ii() {
        // Table II's improvements give 9.2x with sigma-hat 7.75 (7.73 from the rounded values).
        let imps = [5.4, 3.4, 9.4, 7.7, 10.2, 29.0, 6.8, 4.4, 6.7];
        let rows = imps.iter().enumerate().map(|(i, &v)| row(&format!("d{i}"), v)).collect();
        let r = Report::from_rows(rows).unwrap();
        assert!((r.mean_improvement - 9.2222).abs() < 1e-3);
        assert!((r.std_improvement - 7.7335).abs() < 1e-3);
        assert_eq!(r.total_duration_min, 90.0);
        let md = r.to_markdown();
        assert!(md.contains("| d0 | 10.0 |") && md.contains("9.2x (sigma = 7.73)"), "{md}");
        assert!(Report::from_rows(vec![]).is_err());
    }

    #[test]
    fn csv_has_a_header_quotes_names_and_ends_with_the_average() {
        let r = Report::from_rows(vec![row("City, 1", 4.0), row("B", 6.0)]).unwrap();
        let csv = r.to_csv();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], "name,duration_min,E_psi_raw_deg,NE_psi_raw_deg_per_min,E_psi_hdr_deg,NE_psi_hdr_deg_per_min,improvement");
        assert_eq!(lines[1], "\"City, 1\",10.0,8.0,0.8,2.0,0.2,4.0");
        assert_eq!(lines[3], "average of 2,20.0,10.0,1.0,2.0,0.2,5.0");
    }
}

#[cfg(test)]
mod width_tests {
    use super::*;

    #[test]
    fn a_very_long_drive_name_does_not_panic_the_text_table() {
        let row = ReportRow {
            name: "x".repeat(70_000),
            duration_min: 1.0,
            E_psi_raw_deg: 1.0,
            NE_psi_raw_deg_per_min: 1.0,
            E_psi_hdr_deg: 0.5,
            NE_psi_hdr_deg_per_min: 0.5,
            improvement: 2.0,
        };
        let r = Report::from_rows(vec![row]).unwrap();
        assert!(r.to_text().contains(&"x".repeat(70_000)));
    }
}
