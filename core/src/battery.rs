//! The robustness battery: drift reducers judged on gyros and drives nobody tuned them to.
//! A case is a base drive (recorded, or simulated) with a gyro error profile added to its
//! yaw rate (`sim::errors`); every method runs through the one evaluation path (`eval`).
//!
//! The split into training cases (where choices may be made) and scoring cases (only
//! looked at) is fixed here by rule, before any result: a case is training only when both
//! its base and its profile are training ones. See docs/battery.md.

use crate::error::{Error, Result};
use crate::eval::{col, standard_methods, Prepared};
use crate::hdr::HdrParams;
use crate::log::DriveLog;
use crate::pipeline::PipelineParams;
use crate::sim::{errors::GyroErrors, inject, GyroSpec, Scenario};
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// Recorded drives whose recipe name is in this list are training bases; every other
/// recorded drive (including any a user adds) is scoring. Rule: alphabetical order of the
/// shipped recipes, every second one from the second on.
pub const TRAINING_RECORDED: [&str; 5] =
    ["neu-vn100-circle", "pixel6a-20230806_144805", "pixel6a-20230809_163741", "wid-car-trial02", "wid-car-trial11"];

/// One base drive.
#[derive(Debug, Clone)]
pub struct Base {
    pub name: String,
    pub log: DriveLog,
    pub training: bool,
}

/// One gyro error profile.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Profile {
    pub name: String,
    pub errors: GyroErrors,
    pub training: bool,
}

/// A recorded base; training when its name is in [`TRAINING_RECORDED`].
pub fn recorded_base(name: &str, log: DriveLog) -> Base {
    Base { name: name.to_string(), training: TRAINING_RECORDED.contains(&name), log }
}

/// Simulated bases: six scenarios with the paper's CRS03-class gyro and six with a
/// consumer MEMS gyro; seeds 1-6 train, seeds 101-106 score.
pub fn simulated_bases(minutes: f64) -> Vec<Base> {
    use Scenario::*;
    let scen = [City, Suburbs, Rural, Highway, Mixed, Downtown];
    let mut out = Vec::new();
    for (k, &(seed0, training)) in [(1u64, true), (101u64, false)].iter().enumerate() {
        for (i, &s) in scen.iter().enumerate() {
            let seed = seed0 + i as u64;
            let (spec, gyro) = if (i + k) % 2 == 0 { (GyroSpec::crs03_like(), "crs03") } else { (GyroSpec::consumer_mems(), "mems") };
            let cfg = crate::sim::DriveConfig { scenario: s, minutes, seed };
            let mut log = crate::sim::drive::simulate_drive_with(&cfg, &spec);
            let name = format!("sim-{}-{gyro}-{seed}", format!("{s:?}").to_lowercase());
            log.meta.name = Some(name.clone());
            out.push(Base { name, log, training });
        }
    }
    out
}

fn p(name: &str, training: bool, errors: GyroErrors) -> Profile {
    Profile { name: name.to_string(), errors, training }
}

/// The error profiles: the recorded rate as-is, and each class at training strengths and
/// at other (scoring) strengths and seeds. "cut" = no stationary lead-in.
pub fn profiles() -> Vec<Profile> {
    let e = GyroErrors::default();
    let cut = GyroErrors { cut_lead_in: true, ..e };
    vec![
        p("as-is", true, e),
        // training strengths
        p("bias +0.5", true, GyroErrors { bias_dps: 0.5, ..e }),
        p("bias -1.5 cut", true, GyroErrors { bias_dps: -1.5, ..cut }),
        p("bias +3 cut", true, GyroErrors { bias_dps: 3.0, ..cut }),
        p("warm-up +1 (300 s) cut", true, GyroErrors { warmup_dps: 1.0, warmup_tau_s: 300.0, ..cut }),
        p("walk 0.005", true, GyroErrors { walk_dps_per_sqrt_s: 0.005, seed: 11, ..e }),
        p("steps 0.1 / 600 s", true, GyroErrors { step_dps: 0.1, step_every_s: 600.0, seed: 12, ..e }),
        p("scale +2 %", true, GyroErrors { scale: 0.02, ..e }),
        p("rate-dep 1 %", true, GyroErrors { rate_dep: 0.01, ..e }),
        p("g-sens 0.05", true, GyroErrors { g_sens_dps_per_mps2: 0.05, ..e }),
        p("lsb 0.1", true, GyroErrors { lsb_dps: 0.1, ..e }),
        p("vibration 0.3 / +0.05", true, GyroErrors { vibration_noise_dps: 0.3, vibration_bias_dps: 0.05, seed: 14, ..e }),
        p(
            "cheap MEMS A cut",
            true,
            GyroErrors { bias_dps: 1.0, warmup_dps: 0.5, warmup_tau_s: 400.0, walk_dps_per_sqrt_s: 0.003, scale: 0.01, seed: 13, ..cut },
        ),
        // scoring strengths and seeds
        p("bias -0.1", false, GyroErrors { bias_dps: -0.1, ..e }),
        p("bias +0.3 cut", false, GyroErrors { bias_dps: 0.3, ..cut }),
        p("bias +1 cut", false, GyroErrors { bias_dps: 1.0, ..cut }),
        p("bias -2 cut", false, GyroErrors { bias_dps: -2.0, ..cut }),
        p("bias -3", false, GyroErrors { bias_dps: -3.0, ..e }),
        p("warm-up -0.8 (600 s)", false, GyroErrors { warmup_dps: -0.8, warmup_tau_s: 600.0, ..e }),
        p("warm-up +2 (200 s) cut", false, GyroErrors { warmup_dps: 2.0, warmup_tau_s: 200.0, ..cut }),
        p("walk 0.002", false, GyroErrors { walk_dps_per_sqrt_s: 0.002, seed: 21, ..e }),
        p("walk 0.01 cut", false, GyroErrors { walk_dps_per_sqrt_s: 0.01, seed: 22, ..cut }),
        p("steps 0.05 / 300 s", false, GyroErrors { step_dps: 0.05, step_every_s: 300.0, seed: 23, ..e }),
        p("steps 0.3 / 900 s", false, GyroErrors { step_dps: 0.3, step_every_s: 900.0, seed: 24, ..e }),
        p("scale -2 %", false, GyroErrors { scale: -0.02, ..e }),
        p("scale +5 %", false, GyroErrors { scale: 0.05, ..e }),
        p("rate-dep -1 %", false, GyroErrors { rate_dep: -0.01, ..e }),
        p("g-sens -0.1", false, GyroErrors { g_sens_dps_per_mps2: -0.1, ..e }),
        p("lsb 0.05", false, GyroErrors { lsb_dps: 0.05, ..e }),
        p("vibration 0.15 / +0.02", false, GyroErrors { vibration_noise_dps: 0.15, vibration_bias_dps: 0.02, seed: 26, ..e }),
        p("vibration 0.6 / -0.1", false, GyroErrors { vibration_noise_dps: 0.6, vibration_bias_dps: -0.1, seed: 27, ..e }),
        p(
            "cheap MEMS B cut",
            false,
            GyroErrors {
                bias_dps: -1.5,
                warmup_dps: -0.7,
                warmup_tau_s: 500.0,
                walk_dps_per_sqrt_s: 0.005,
                scale: -0.015,
                noise_dps: 0.2,
                lsb_dps: 0.07,
                seed: 25,
                ..cut
            },
        ),
    ]
}

/// HDR tuned the way a user should tune it: on the training bases as recorded, with
/// leave-one-drive-out cross-validation; `recommended` is Table III when tuning does not
/// generalise.
pub fn tune_hdr(bases: &[Base]) -> Result<crate::tune::TuneResult> {
    let named: Vec<(String, &DriveLog)> = bases.iter().filter(|b| b.training).map(|b| (b.name.clone(), &b.log)).collect();
    let prepared = crate::tune::prepare_all(&named, &Default::default())?;
    crate::tune::tune(&prepared, &Default::default())
}

/// The tuned-HDR peer: the parameters tuning recommends, and for each drive it was tuned
/// on, the parameters its cross-validation fold tuned without that drive, so no case is
/// scored with parameters fitted to its own base (that would be in-sample, not a peer).
#[derive(Debug, Clone, PartialEq)]
pub struct TunedHdr {
    pub params: HdrParams,
    pub held_out: Vec<(String, HdrParams)>,
}

impl TunedHdr {
    /// From a tuning run: out-of-fold parameters only where the tuned ones are recommended
    /// (when Table III is, every base gets Table III).
    pub fn from_result(r: &crate::tune::TuneResult) -> Self {
        let held_out = match (&r.cv, r.recommended_is_tuned) {
            (Some(cv), true) => cv.folds.iter().map(|f| (f.held_out.clone(), f.params)).collect(),
            _ => Vec::new(),
        };
        TunedHdr { params: r.recommended, held_out }
    }

    /// The parameters for a case on this base.
    pub fn for_base(&self, base: &str) -> HdrParams {
        self.held_out.iter().find(|(n, _)| n == base).map_or(self.params, |(_, p)| *p)
    }
}

/// The methods of the battery, in column order.
pub fn method_names(with_tuned: bool) -> Vec<&'static str> {
    let mut v = vec!["raw", "HDR Table III", "Fusion offset", "ZARU", "pipeline", "smoothed"];
    if with_tuned {
        v.push("HDR tuned (CV)");
    }
    v
}

/// Column of the recommended method and of the offline smoothed mode (never a "peer").
pub const PIPELINE: usize = col::PIPELINE;
pub const SMOOTHED: usize = col::SMOOTHED;

/// One case: NE_psi (deg/min) of every method, or why it could not run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CaseRow {
    pub base: String,
    pub profile: String,
    pub training: bool,
    pub duration_min: f64,
    pub ne_psi: Vec<f64>,
    /// pipeline / best causal peer (raw, HDR, Fusion, ZARU, tuned HDR).
    pub ratio: f64,
    /// pipeline - 1.25 best peer - 0.05 <= 0 (the "within 1.25x + 0.05").
    pub within: bool,
}

/// Summary over a set of cases.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    pub n_cases: usize,
    /// Mean NE_psi per method.
    pub mean: Vec<f64>,
    /// Pipeline mean / best other method's mean.
    pub mean_ratio: f64,
    pub n_within: usize,
    /// Cases worse than 2x the best peer + 0.05.
    pub n_over_2x: usize,
    /// Worst case: its label and its ratio to the best peer.
    pub worst: String,
    pub worst_ratio: f64,
    /// Cases where the pipeline is worse than raw integration by more than 10 %.
    pub n_worse_than_raw: usize,
    /// The goal's two counts applied to every method in turn (column order): cases within
    /// 1.25x + 0.05 of the best of the *other* causal methods, and worse than 2x + 0.05. For
    /// the pipeline these are `n_within` and `n_over_2x`; for a peer the pipeline is one
    /// of its others; the smoothed mode is measured against every causal method.
    pub each_within: Vec<usize>,
    pub each_over_2x: Vec<usize>,
}

/// Best causal method of a row other than column `j`.
fn best_other_than(ne: &[f64], j: usize) -> f64 {
    ne.iter().enumerate().filter(|(i, _)| *i != j && *i != SMOOTHED).map(|(_, v)| *v).fold(f64::INFINITY, f64::min)
}

/// The battery's result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Battery {
    pub methods: Vec<String>,
    pub cases: Vec<CaseRow>,
    pub training: Option<Summary>,
    pub scoring: Option<Summary>,
    /// Cases that could not be scored (e.g. a cut lead-in left no reference), with why.
    pub skipped: Vec<(String, String)>,
}

/// Which cases to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Split {
    Training,
    Scoring,
    All,
}

fn score_case(log: &DriveLog, params: &PipelineParams, tuned: Option<HdrParams>) -> Result<(f64, Vec<f64>)> {
    let prep = Prepared::new(log, params.bias_s, &params.still)?;
    let s = prep.score_all(&standard_methods(params, tuned))?;
    Ok((prep.duration_min, s.iter().map(|m| m.ne_psi_deg_per_min).collect()))
}

/// Best causal peer of a row (every column but the pipeline's two).
pub fn best_peer(ne: &[f64]) -> f64 {
    best_other_than(ne, PIPELINE)
}

/// Runs every (base, profile) case of the split.
pub fn run(bases: &[Base], profiles: &[Profile], split: Split, params: &PipelineParams, tuned: Option<&TunedHdr>) -> Result<Battery> {
    params.validate()?;
    let mut jobs = Vec::new();
    for b in bases {
        for pr in profiles {
            let training = b.training && pr.training;
            let keep = match split {
                Split::Training => training,
                Split::Scoring => !training,
                Split::All => true,
            };
            if keep {
                jobs.push((b, pr, training));
            }
        }
    }
    let run_one = |(b, pr, training): &(&Base, &Profile, bool)| -> (String, String, bool, Result<(f64, Vec<f64>)>) {
        let r = inject(&b.log, &pr.errors).and_then(|log| score_case(&log, params, tuned.map(|t| t.for_base(&b.name))));
        (b.name.clone(), pr.name.clone(), *training, r)
    };
    #[cfg(feature = "parallel")]
    let results: Vec<_> = {
        use rayon::prelude::*;
        jobs.par_iter().map(run_one).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let results: Vec<_> = jobs.iter().map(run_one).collect();
    let mut cases = Vec::new();
    let mut skipped = Vec::new();
    for (base, profile, training, r) in results {
        match r {
            Ok((duration_min, ne_psi)) => {
                let best = best_peer(&ne_psi);
                let pipe = ne_psi[PIPELINE];
                cases.push(CaseRow {
                    base,
                    profile,
                    training,
                    duration_min,
                    ratio: pipe / best,
                    within: pipe <= 1.25 * best + 0.05,
                    ne_psi,
                });
            }
            Err(e) => skipped.push((format!("{base} / {profile}"), e.to_string())),
        }
    }
    if cases.is_empty() {
        return Err(Error::data("the battery has no case that could be scored"));
    }
    let summary = |train: bool| summarize(&cases.iter().filter(|c| c.training == train).collect::<Vec<_>>());
    Ok(Battery {
        methods: method_names(tuned.is_some()).into_iter().map(String::from).collect(),
        training: summary(true),
        scoring: summary(false),
        cases,
        skipped,
    })
}

/// Means, ratios and the worst case over some cases (None if there are none).
pub fn summarize(cases: &[&CaseRow]) -> Option<Summary> {
    let first = cases.first()?;
    let m = first.ne_psi.len();
    let n = cases.len() as f64;
    let mean: Vec<f64> = (0..m).map(|j| cases.iter().map(|c| c.ne_psi[j]).sum::<f64>() / n).collect();
    let best_other = best_peer(&mean);
    let worst = cases.iter().max_by(|a, b| a.ratio.total_cmp(&b.ratio))?;
    let within = |j: usize| cases.iter().filter(|c| c.ne_psi[j] <= 1.25 * best_other_than(&c.ne_psi, j) + 0.05).count();
    let over_2x = |j: usize| cases.iter().filter(|c| c.ne_psi[j] > 2.0 * best_other_than(&c.ne_psi, j) + 0.05).count();
    Some(Summary {
        each_within: (0..m).map(within).collect(),
        each_over_2x: (0..m).map(over_2x).collect(),
        n_cases: cases.len(),
        mean_ratio: mean[PIPELINE] / best_other,
        n_within: cases.iter().filter(|c| c.within).count(),
        n_over_2x: over_2x(PIPELINE),
        worst: format!("{} / {}", worst.base, worst.profile),
        worst_ratio: worst.ratio,
        n_worse_than_raw: cases.iter().filter(|c| c.ne_psi[PIPELINE] > 1.1 * c.ne_psi[0] + 1e-9).count(),
        mean,
    })
}

impl Battery {
    /// Markdown: the two summaries, then every case (best causal method in bold).
    pub fn to_markdown(&self, cases: bool) -> String {
        let mut s = String::new();
        let head = |s: &mut String, first: &str, last: Option<&str>| {
            let _ = write!(s, "| {first} |");
            for m in self.methods.iter().map(String::as_str).chain(last) {
                let _ = write!(s, " {m} |");
            }
            let _ = writeln!(s, "\n|---|{}", "---:|".repeat(self.methods.len() + last.is_some() as usize));
        };
        let _ = writeln!(s, "Mean NE_psi (deg/min) per method; \"smoothed\" is offline (non-causal) and not a peer.\n");
        head(&mut s, "cases", Some("pipeline / best other"));
        for (label, sm) in [("training", &self.training), ("scoring", &self.scoring)] {
            if let Some(sm) = sm {
                let _ = write!(s, "| {label} ({}) |", sm.n_cases);
                for v in &sm.mean {
                    let _ = write!(s, " {v:.3} |");
                }
                let _ = writeln!(s, " {:.2}x |", sm.mean_ratio);
            }
        }
        let _ = writeln!(s);
        for (label, sm) in [("training", &self.training), ("scoring", &self.scoring)] {
            if let Some(sm) = sm {
                let _ = writeln!(
                    s,
                    "- {label}: pipeline within 1.25x best other + 0.05 on {} of {} ({:.0} %); worse than 2x + 0.05 on {}; worse than raw by > 10 % on {}; worst {:.2}x ({})",
                    sm.n_within,
                    sm.n_cases,
                    100.0 * sm.n_within as f64 / sm.n_cases as f64,
                    sm.n_over_2x,
                    sm.n_worse_than_raw,
                    sm.worst_ratio,
                    sm.worst
                );
            }
        }
        let _ = writeln!(s, "\nThe same two counts for every method against the best of its others (the pipeline is one of a peer's others; smoothed is measured against every causal method):\n");
        head(&mut s, "cases: within 1.25x + 0.05 / worse than 2x + 0.05", None);
        for (label, sm) in [("training", &self.training), ("scoring", &self.scoring)] {
            if let Some(sm) = sm {
                let _ = write!(s, "| {label} ({}) |", sm.n_cases);
                for (w, o) in sm.each_within.iter().zip(&sm.each_over_2x) {
                    let _ = write!(s, " {w} / {o} |");
                }
                let _ = writeln!(s);
            }
        }
        if !self.skipped.is_empty() {
            let _ = writeln!(s, "- skipped: {}", self.skipped.iter().map(|(c, e)| format!("{c} ({e})")).collect::<Vec<_>>().join("; "));
        }
        if cases {
            let _ = writeln!(s);
            head(&mut s, "case (T = training)", Some("pipeline / best other"));
            for c in &self.cases {
                let best = best_peer(&c.ne_psi).min(c.ne_psi[PIPELINE]);
                let _ = write!(s, "| {}{} / {} |", if c.training { "T " } else { "" }, c.base, c.profile);
                for v in &c.ne_psi {
                    if *v == best {
                        let _ = write!(s, " **{v:.3}** |");
                    } else {
                        let _ = write!(s, " {v:.3} |");
                    }
                }
                let _ = writeln!(s, " {:.2}x{} |", c.ratio, if c.within { "" } else { " !" });
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A training base is scored with its fold's parameters (tuned without it); any other
    /// base with the recommended ones; Table III recommended means Table III for every base.
    #[test]
    fn the_tuned_peer_is_out_of_fold_on_the_drives_it_was_tuned_on() {
        let t3 = HdrParams::table_iii();
        let fold = HdrParams { i_c_dps: 0.01, ..t3 };
        let all = HdrParams { i_c_dps: 0.02, ..t3 };
        let cv = crate::tune::CrossValidation {
            folds: vec![crate::tune::CvFold {
                held_out: "a".into(),
                ne_psi_table_iii_deg_per_min: 1.0,
                ne_psi_tuned_deg_per_min: 0.5,
                params: fold,
            }],
            cv_table_iii_deg_per_min: 1.0,
            cv_tuned_deg_per_min: 0.5,
        };
        let mut r = crate::tune::TuneResult {
            params: all,
            objective_start_deg_per_min: 1.0,
            objective_tuned_deg_per_min: 0.5,
            n_evaluations: 1,
            cv: Some(cv),
            recommended: all,
            recommended_is_tuned: true,
        };
        let peer = TunedHdr::from_result(&r);
        assert_eq!(peer.for_base("a"), fold);
        assert_eq!(peer.for_base("b"), all);
        r.recommended = t3;
        r.recommended_is_tuned = false;
        let peer = TunedHdr::from_result(&r);
        assert_eq!(peer.for_base("a"), t3);
        assert_eq!(peer.for_base("b"), t3);
    }

    /// A small fixed subset of the battery (simulated training bases, 10 min, five profiles)
    /// as a regression guard on the ratios the docs quote; not a timed test.
    #[test]
    fn regression_guard_on_a_fixed_subset() {
        let bases = simulated_bases(10.0).into_iter().filter(|b| b.training).collect::<Vec<_>>();
        let keep = ["as-is", "bias -1.5 cut", "bias +3 cut", "warm-up +1 (300 s) cut", "cheap MEMS A cut"];
        let profiles = profiles().into_iter().filter(|p| keep.contains(&p.name.as_str())).collect::<Vec<_>>();
        let b = run(&bases, &profiles, Split::Training, &PipelineParams::default(), None).unwrap();
        let s = b.training.as_ref().unwrap();
        eprintln!("{}", b.to_markdown(true));
        assert_eq!(s.n_cases, 30);
        assert!(b.skipped.is_empty());
        // Never diverges: with an injected error, no case worse than raw integration by more
        // than 10 % + 0.01. As recorded ("as-is") the pipeline may read the meander, sway and
        // clothoid curves of the simulated roads as bias (docs/battery.md): measured up to
        // 5.97x raw (sim-highway-mems-4, since the highway sway was fitted to the recorded
        // drives' and its size varies; 3.92x before; 1.56x on sim-city-crs03-1 before the
        // clothoids); guarded at 6.5x.
        for c in &b.cases {
            let limit = if c.profile == "as-is" { 6.5 } else { 1.1 };
            assert!(c.ne_psi[PIPELINE] <= limit * c.ne_psi[0] + 0.01, "{} / {} worse than raw: {:?}", c.base, c.profile, c.ne_psi);
        }
        // The mean beats the best other method's mean by far (measured 0.21x on the roads
        // whose sway size varies; 0.20x since the start
        // bias' prior is wide and the warm-up term independent of it; 0.39x before, since
        // stops also correct the heading; 0.46x before that).
        assert!(s.mean_ratio < 0.3, "mean ratio {}", s.mean_ratio);
        // Acquisition without a lead-in: every large-bias case within 3.5x the best peer + 0.05
        // (worst measured 2.60x, sim-city-crs03-1 / bias +3 cut, against Fusion's offset;
        // 2.75x before the sway's size varied;
        // 2.70x before stops' corrections were dated, 4.09x before the wide start prior).
        for c in b.cases.iter().filter(|c| c.profile.starts_with("bias")) {
            assert!(c.ne_psi[PIPELINE] <= 3.5 * best_peer(&c.ne_psi) + 0.05, "{} / {}: {:?}", c.base, c.profile, c.ne_psi);
        }
    }

    #[test]
    fn each_method_is_counted_against_the_best_of_its_others_hand_worked() {
        // Columns: raw, HDR, Fusion, ZARU, pipeline, smoothed.
        let row = |ne: [f64; 6]| CaseRow {
            base: "b".into(),
            profile: "p".into(),
            training: true,
            duration_min: 1.0,
            ratio: ne[PIPELINE] / best_peer(&ne),
            within: ne[PIPELINE] <= 1.25 * best_peer(&ne) + 0.05,
            ne_psi: ne.to_vec(),
        };
        // A: the pipeline (0.4) is the best causal method; raw's others' best is 0.4, so raw
        // (1.0 > 0.85) is over 2x, HDR (0.5 <= 0.55) within; smoothed against 0.4 within.
        // B: raw (0.2) best; the others' 0.29 <= 0.30 within; the pipeline 0.5 > 0.45 and
        // smoothed 0.6 over 2x.
        let (a, b) = (row([1.0, 0.5, 2.0, 3.0, 0.4, 0.1]), row([0.2, 0.29, 0.29, 0.29, 0.5, 0.6]));
        let s = summarize(&[&a, &b]).unwrap();
        assert_eq!(s.each_within, vec![1, 2, 1, 1, 1, 1]);
        assert_eq!(s.each_over_2x, vec![1, 0, 1, 1, 1, 1]);
        assert_eq!((s.each_within[PIPELINE], s.each_over_2x[PIPELINE]), (s.n_within, s.n_over_2x));
    }

    #[test]
    fn split_is_by_rule_and_profiles_have_unique_names() {
        assert!(recorded_base("wid-car-trial02", DriveLog::default()).training);
        assert!(!recorded_base("wid-car-trial10", DriveLog::default()).training);
        assert!(!recorded_base("someone-elses-drive", DriveLog::default()).training);
        let p = profiles();
        let mut names: Vec<_> = p.iter().map(|p| p.name.clone()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), p.len());
        assert!(p.iter().all(|p| p.errors.validate().is_ok()));
        let sims = simulated_bases(2.0);
        assert_eq!(sims.iter().filter(|b| b.training).count(), 6);
        assert_eq!(sims.len(), 12);
    }
}
