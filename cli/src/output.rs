//! Human-readable tables with units. Formatting only: every number comes from core.

use gyrodrift::allan::{AllanConfidence, AllanResult};
use gyrodrift::calibration::CalibrationRun;
use gyrodrift::gyrodometry::GyrodometryResult;
use gyrodrift::hdr::{HdrOptions, HdrResult};
use std::fmt::Write;
use std::path::Path;

pub fn hdr_table(path: &Path, o: &HdrOptions, r: &HdrResult) -> String {
    let p = &o.params;
    let mut s = String::new();
    let _ = writeln!(s, "{}: HDR, {:.1} min, {}", crate::shown(path), r.duration_min, if r.resampled { "1 Hz blocks" } else { "raw rows" });
    let _ =
        writeln!(s, "  parameters   i_c {} deg/s, tau {} s, theta_w {} deg/s, c1 {}, c2 {}", p.i_c_dps, p.tau_s, p.theta_w_dps, p.c1, p.c2);
    let _ = writeln!(s, "               {:>12} {:>18}", "E_psi (deg)", "NE_psi (deg/min)");
    let _ = writeln!(s, "  without HDR  {:>12.2} {:>18.3}", r.E_psi_raw_deg, r.NE_psi_raw_deg_per_min);
    let _ = writeln!(s, "  with HDR     {:>12.2} {:>18.3}", r.E_psi_hdr_deg, r.NE_psi_hdr_deg_per_min);
    let _ = writeln!(s, "  improvement  {:.2}x", r.improvement);
    let _ = writeln!(
        s,
        "  static bias eps0 {:.4} deg/s; {} estimator samples; {} scored reference samples",
        r.eps0_dps, r.n_processed, r.n_samples
    );
    s
}

/// Where an unscored run's headings are: the trace file, or how to ask for one.
fn trace_hint(traced: bool) -> &'static str {
    if traced {
        "per sample in the trace file"
    } else {
        "per sample with --trace FILE"
    }
}

/// HDR on a drive without a reference heading: why nothing is scored, and the estimator's figures.
pub fn hdr_unscored(path: &Path, why: &str, s: &gyrodrift::hdr::HdrSummary, traced: bool) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}: HDR, {:.1} min, not scored: {why}", crate::shown(path), s.duration_min);
    let _ = writeln!(out, "  heading turned (from 0 at the start; {})", trace_hint(traced));
    let _ = writeln!(out, "    without HDR  {:>10.2} deg", s.heading_change_raw_deg);
    let _ = writeln!(out, "    with HDR     {:>10.2} deg", s.heading_change_hdr_deg);
    let _ = writeln!(
        out,
        "  static bias eps0 {:.4} deg/s; drift estimate -I at the end {:.4} deg/s; {} estimator samples",
        s.eps0_dps, s.final_drift_estimate_dps, s.n_processed
    );
    out
}

pub fn gyrodometry_table(path: &Path, r: &GyrodometryResult) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}: Gyrodometry, {:.2} min, wheelbase {} m, threshold {} deg/s",
        crate::shown(path),
        r.duration_min,
        r.wheelbase_m,
        r.thres_rate_dps
    );
    let _ = writeln!(s, "                {:>12} {:>18} {:>16}", "E_psi (deg)", "NE_psi (deg/min)", "final err (deg)");
    for (name, e, ne, f) in [
        ("odometry", r.E_psi_odo_deg, r.NE_psi_odo_deg_per_min, r.final_err_odo_deg),
        ("gyro", r.E_psi_gyro_deg, r.NE_psi_gyro_deg_per_min, r.final_err_gyro_deg),
        ("gyrodometry", r.E_psi_gyrodometry_deg, r.NE_psi_gyrodometry_deg_per_min, r.final_err_gyrodometry_deg),
    ] {
        let _ = writeln!(s, "  {name:<13} {e:>12.3} {ne:>18.3} {f:>16.3}");
    }
    let _ = writeln!(
        s,
        "  gyro used in {} intervals; eps0 {:.4} deg/s; {} scored reference samples",
        r.n_gyro_intervals, r.eps0_dps, r.n_samples
    );
    s
}

pub fn calibration_table(path: &Path, run: &CalibrationRun) -> String {
    let r = &run.result;
    let mut s = String::new();
    let _ = writeln!(s, "{}: calibration, p = {}, q = {}, {} data sets", crate::shown(path), r.p, r.q, r.n_sets);
    let _ = writeln!(s, "  static bias w_s {:.5} deg/s; after compensation w_s* {:.5} deg/s", r.w_s_dps, r.w_s_star_dps);
    let _ = writeln!(s, "  set-level fit residual RMS {:.5} deg/s", r.fit_residual_rms_dps);
    let _ = writeln!(s, "                     {:>16} {:>18} {:>18}", "residual RMS", "360-deg err max", "360-deg err RMS");
    let _ = writeln!(s, "                     {:>16} {:>18} {:>18}", "(deg/s)", "(deg)", "(deg)");
    let _ = writeln!(
        s,
        "  static bias only   {:>16.5} {:>18.3} {:>18.3}",
        r.residual_rms_static_only_dps, r.turn360_err_static_only_max_deg, r.turn360_err_static_only_rms_deg
    );
    let _ = writeln!(
        s,
        "  compensated        {:>16.5} {:>18.3} {:>18.3}",
        r.residual_rms_compensated_dps, r.turn360_err_compensated_max_deg, r.turn360_err_compensated_rms_deg
    );
    let _ = writeln!(s, "  coefficients C[j][k] of T^j w_g^k:");
    for (j, row) in r.c.iter().enumerate() {
        let cells: Vec<String> = row.iter().map(|c| format!("{c:>13.5e}")).collect();
        let _ = writeln!(s, "    T^{j}: {}", cells.join(" "));
    }
    s
}

pub fn allan_table(path: &Path, r: &AllanResult, c: &AllanConfidence) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}: Allan deviation, T0 = {} s", crate::shown(path), trim(r.T0_s));
    let _ = writeln!(s, "  angle random walk   {:.5} deg/sqrt(s) = {:.4} deg/sqrt(h)", r.arw_deg_per_sqrt_s, r.arw_deg_per_sqrt_h);
    let _ = writeln!(
        s,
        "  bias instability    {:.6} deg/s = {:.3} deg/h (minimum at tau = {} s)",
        r.bias_instability_dps,
        r.bias_instability_dph,
        trim(r.tau_at_min_s)
    );
    let _ = writeln!(
        s,
        "  68 % band           {:.6} to {:.6} deg/s; the minimum could lie anywhere in tau {} to {} s",
        c.bias_instability_low_dps,
        c.bias_instability_high_dps,
        trim(c.tau_min_range_s[0]),
        trim(c.tau_min_range_s[1])
    );
    let _ = writeln!(
        s,
        "  tightest bound      adev {:.6} deg/s at tau = {} s (bias instability {:.6} deg/s)",
        c.adev_tightest_dps,
        trim(c.tau_tightest_s),
        c.adev_tightest_dps / 0.664
    );
    let _ = writeln!(s, "  {:>10} {:>14} {:>14} {:>14}", "tau (s)", "adev (deg/s)", "68 % low", "68 % high");
    for (i, (t, a)) in r.tau_s.iter().zip(&r.adev_dps).enumerate() {
        let _ = writeln!(s, "  {:>10} {a:>14.6} {:>14.6} {:>14.6}", trim(*t), c.adev_low_dps[i], c.adev_high_dps[i]);
    }
    s
}

/// A number with at most 6 decimals and no trailing zeros (0.30000000000000004 -> 0.3).
fn trim(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

pub fn tune_text(rep: &gyrodrift::tune::TuneReport, markdown: bool) -> String {
    let p = &rep.result.params;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Tuned HDR parameters ({} evaluations): mean NE_psi over the training drives {:.4} -> {:.4} deg/min",
        rep.result.n_evaluations, rep.result.objective_start_deg_per_min, rep.result.objective_tuned_deg_per_min
    );
    let t = gyrodrift::hdr::HdrParams::table_iii();
    let _ = writeln!(s, "  {:<8} {:>12} {:>12}", "", "Table III", "tuned");
    for (name, a, b, unit) in [
        ("i_c", t.i_c_dps, p.i_c_dps, "deg/s"),
        ("tau", t.tau_s, p.tau_s, "s"),
        ("theta_w", t.theta_w_dps, p.theta_w_dps, "deg/s"),
        ("c1", t.c1, p.c1, ""),
        ("c2", t.c2, p.c2, ""),
    ] {
        let _ = writeln!(s, "  {name:<8} {a:>12.4} {b:>12.4} {unit}");
    }
    if let Some(cv) = &rep.result.cv {
        let _ = writeln!(
            s,
            "Leave-one-drive-out cross-validation over {} drives: mean held-out NE_psi {:.4} deg/min with Table III, {:.4} with parameters tuned on the other drives.",
            cv.folds.len(), cv.cv_table_iii_deg_per_min, cv.cv_tuned_deg_per_min
        );
    }
    if rep.result.recommended_is_tuned {
        let _ = writeln!(s, "Recommended: the tuned parameters.");
    } else {
        let _ = writeln!(
            s,
            "Recommended: Table III. The tuned parameters do worse on drives they were not tuned on; they are shown, not recommended."
        );
    }
    let table = |r: &gyrodrift::report::Report| if markdown { r.to_markdown() } else { r.to_text() };
    let sets = [("Training drives", Some(&rep.train)), ("Test drives", rep.test.as_ref())];
    for (title, cmp) in sets {
        if let Some(c) = cmp {
            let _ = writeln!(s, "\n{title}, Table III parameters:\n{}", table(&c.table_iii));
            let _ = writeln!(s, "{title}, tuned parameters:\n{}", table(&c.tuned));
        }
    }
    s
}

pub fn import_line(recipe: &Path, s: &gyrodrift::import::ImportSummary) -> String {
    let mut out = format!(
        "{}: {} rows ({} gyro, {} reference headings), {:.1} min",
        recipe.display(),
        s.n_rows,
        s.n_gyro,
        s.n_reference,
        s.duration_min
    );
    if let Some(u) = s.up {
        let _ = write!(out, ", up = ({:.3}, {:.3}, {:.3})", u[0], u[1], u[2]);
    }
    if let Some(l) = s.align_offset_s {
        let _ = write!(out, ", gyro clock shifted by {l:+.2} s");
    }
    let fixed = s.time_fixes.to_text();
    if !fixed.is_empty() {
        let _ = write!(out, ", {fixed}");
    }
    out
}

pub fn pipeline_table(path: &Path, r: &gyrodrift::pipeline::PipelineResult) -> String {
    let mut s = String::new();
    let _ =
        writeln!(s, "{}: {:.1} min, stops from {} ({:.0} s counted)", crate::shown(path), r.duration_min, r.still_source.name(), r.stop_s);
    let _ = writeln!(s, "                    {:>12} {:>18} {:>12}", "E_psi (deg)", "NE_psi (deg/min)", "vs raw");
    for (name, e, ne) in [
        ("raw", r.E_psi_raw_deg, r.NE_psi_raw_deg_per_min),
        ("HDR (Table III)", r.E_psi_hdr_deg, r.NE_psi_hdr_deg_per_min),
        ("Fusion offset", r.E_psi_fusion_offset_deg, r.NE_psi_fusion_offset_deg_per_min),
        ("ZARU at stops", r.E_psi_zaru_deg, r.NE_psi_zaru_deg_per_min),
        ("pipeline", r.E_psi_pipeline_deg, r.NE_psi_pipeline_deg_per_min),
        ("smoothed (offline)", r.E_psi_pipeline_smoothed_deg, r.NE_psi_pipeline_smoothed_deg_per_min),
    ] {
        let _ = writeln!(s, "  {name:<18} {e:>11.2} {ne:>18.3} {:>11.2}x", r.E_psi_raw_deg / e);
    }
    let _ = writeln!(s, "  final bias {:.4} +- {:.4} deg/s", r.final_bias_dps, r.final_bias_sigma_dps);
    s
}

/// The pipeline on a drive without a reference heading: why nothing is scored, and the
/// estimator's figures at the end.
pub fn pipeline_unscored(path: &Path, why: &str, s: &gyrodrift::pipeline::PipelineSummary, traced: bool) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}: {:.1} min, stops from {} ({:.0} s counted)",
        crate::shown(path),
        s.duration_min,
        s.still_source.name(),
        s.stop_s
    );
    let _ = writeln!(out, "  not scored: {why}");
    let _ = writeln!(out, "  heading turned (from 0 at the start; {})", trace_hint(traced));
    let _ = writeln!(out, "    pipeline            {:>10.2} +- {:.2} deg", s.heading_change_deg, s.heading_change_sigma_deg);
    let _ = writeln!(out, "    smoothed (offline)  {:>10.2} deg", s.heading_change_smoothed_deg);
    let _ = writeln!(out, "  final bias {:.4} +- {:.4} deg/s", s.final_bias_dps, s.final_bias_sigma_dps);
    out
}
