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
use crate::log::{Column, DriveLog};
use crate::pipeline::PipelineParams;
use crate::sim::{errors::GyroErrors, inject, GyroSpec, Scenario};
use serde::{Deserialize, Serialize};

mod goals;
mod markdown;
mod summary;
#[cfg(test)]
mod tests;

pub use goals::{goals, GoalCheck, GOOD_GYRO_PREFIX};
pub use summary::{best_peer, summarize, Summary};

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
    /// Simulated (known truth) rather than recorded.
    pub simulated: bool,
    /// A drive the user added as a log: scoring whatever its name, and summarised apart.
    pub added: bool,
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
    Base { name: name.to_string(), training: TRAINING_RECORDED.contains(&name), simulated: false, added: false, log }
}

/// A recorded drive the user adds as a log (not by a shipped recipe): a scoring base
/// whatever its name, since no choice was made on it, with its cases summarised apart. It
/// needs the gyro and a reference heading, which every case is scored against.
pub fn added_base(name: &str, log: DriveLog) -> Result<Base> {
    log.require(Column::GyroDps, "needed by the battery")?;
    log.require(Column::RefHeadingDeg, "needed by the battery, which scores every method against it")?;
    Ok(Base { name: name.to_string(), training: false, simulated: false, added: true, log })
}

/// Every error profile on the user's own drives alone (each an [`added_base`]), without the
/// tuned-HDR peer (tuned on the battery's training bases, which these are not): how each
/// method would fare on these roads with a worse gyro. What the dashboard runs.
pub fn on_drives(drives: &[(String, &DriveLog)], params: &PipelineParams) -> Result<Battery> {
    let bases = drives.iter().map(|(n, l)| added_base(n, (*l).clone()).map_err(|e| e.within(n))).collect::<Result<Vec<Base>>>()?;
    run(&bases, &profiles(), Split::All, params, None)
}

/// Simulated bases: six scenarios with the paper's CRS03-class gyro and six with a
/// consumer MEMS gyro; seeds 1-6 train, seeds 101-106 score.
pub fn simulated_bases(minutes: f64) -> Vec<Base> {
    simulated_bases_drawn(minutes, 0)
}

/// As [`simulated_bases`], with the scoring bases drawn afresh: draw K > 0 gives them seeds
/// 101-106 + 1000 K (the same scenarios and gyro classes, other roads, drivers and gyro
/// units), never seen by any choice; the training bases stay.
pub fn simulated_bases_drawn(minutes: f64, draw: u64) -> Vec<Base> {
    use Scenario::*;
    let scen = [City, Suburbs, Rural, Highway, Mixed, Downtown];
    let mut out = Vec::new();
    for (k, &(seed0, training)) in [(1u64, true), (101 + 1000 * draw, false)].iter().enumerate() {
        for (i, &s) in scen.iter().enumerate() {
            let seed = seed0 + i as u64;
            let (spec, gyro) = if (i + k) % 2 == 0 { (GyroSpec::crs03_like(), "crs03") } else { (GyroSpec::consumer_mems(), "mems") };
            let cfg = crate::sim::DriveConfig { scenario: s, minutes, seed };
            let mut log = crate::sim::drive::simulate_drive_with(&cfg, &spec);
            let name = format!("sim-{}-{gyro}-{seed}", format!("{s:?}").to_lowercase());
            log.meta.name = Some(name.clone());
            out.push(Base { name, log, training, simulated: true, added: false });
        }
    }
    out
}

fn p(name: &str, training: bool, errors: GyroErrors) -> Profile {
    Profile { name: name.to_string(), errors, training }
}

/// The error profiles: the recorded rate as-is, and each class at training strengths and
/// at other (scoring) strengths and seeds. "cut" = no stationary lead-in; "gyro-only" =
/// without the speed and wheel columns (a logger with a gyro alone: standing is judged from
/// the gyro).
pub fn profiles() -> Vec<Profile> {
    let e = GyroErrors::default();
    let cut = GyroErrors { cut_lead_in: true, ..e };
    // The gyro-only class repeats these, with the speed and wheel columns dropped.
    let go = |errors: GyroErrors| GyroErrors { gyro_only: true, ..errors };
    let vibration_a = GyroErrors { vibration_noise_dps: 0.3, vibration_bias_dps: 0.05, seed: 14, ..e };
    let vibration_b = GyroErrors { vibration_noise_dps: 0.6, vibration_bias_dps: -0.1, seed: 27, ..e };
    let warm_up_b = GyroErrors { warmup_dps: -0.8, warmup_tau_s: 600.0, ..e };
    let mems_a =
        GyroErrors { bias_dps: 1.0, warmup_dps: 0.5, warmup_tau_s: 400.0, walk_dps_per_sqrt_s: 0.003, scale: 0.01, seed: 13, ..cut };
    let mems_b = GyroErrors {
        bias_dps: -1.5,
        warmup_dps: -0.7,
        warmup_tau_s: 500.0,
        walk_dps_per_sqrt_s: 0.005,
        scale: -0.015,
        noise_dps: 0.2,
        lsb_dps: 0.07,
        seed: 25,
        ..cut
    };
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
        p("vibration 0.3 / +0.05", true, vibration_a),
        p("cheap MEMS A cut", true, mems_a),
        p("as-is gyro-only", true, go(e)),
        p("bias +0.5 gyro-only", true, go(GyroErrors { bias_dps: 0.5, ..e })),
        p("bias -1.5 cut gyro-only", true, go(GyroErrors { bias_dps: -1.5, ..cut })),
        p("vibration 0.3 / +0.05 gyro-only", true, go(vibration_a)),
        p("cheap MEMS A cut gyro-only", true, go(mems_a)),
        // scoring strengths and seeds
        p("bias -0.1", false, GyroErrors { bias_dps: -0.1, ..e }),
        p("bias +0.3 cut", false, GyroErrors { bias_dps: 0.3, ..cut }),
        p("bias +1 cut", false, GyroErrors { bias_dps: 1.0, ..cut }),
        p("bias -2 cut", false, GyroErrors { bias_dps: -2.0, ..cut }),
        p("bias -3", false, GyroErrors { bias_dps: -3.0, ..e }),
        p("warm-up -0.8 (600 s)", false, warm_up_b),
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
        p("vibration 0.6 / -0.1", false, vibration_b),
        p("cheap MEMS B cut", false, mems_b),
        p("bias -1 gyro-only", false, go(GyroErrors { bias_dps: -1.0, ..e })),
        p("bias +2 cut gyro-only", false, go(GyroErrors { bias_dps: 2.0, ..cut })),
        p("warm-up -0.8 (600 s) gyro-only", false, go(warm_up_b)),
        p("vibration 0.6 / -0.1 gyro-only", false, go(vibration_b)),
        p("cheap MEMS B cut gyro-only", false, go(mems_b)),
    ]
}

/// The profile of this name (as the battery lists them), or an error naming them all.
pub fn profile(name: &str) -> Result<Profile> {
    let all = profiles();
    let names: Vec<String> = all.iter().map(|p| format!("\"{}\"", p.name)).collect();
    all.into_iter()
        .find(|p| p.name == name.trim())
        .ok_or_else(|| Error::param("profile", format!("no battery profile \"{name}\"; the profiles are {}", names.join(", "))))
}

/// One case's log as the battery scores it, named "BASE / PROFILE": the base's log with the
/// profile's gyro errors added, so a case can be opened in the dashboard or run by any
/// command (its file reproduces the battery's figures: the CSV keeps every value exactly).
/// Writing out a scoring case and looking at it is a look (docs/battery.md).
pub fn case_log(bases: &[Base], profiles: &[Profile], case: &str) -> Result<DriveLog> {
    let names = |v: Vec<&str>| v.join(", ");
    let (base, profile) = case
        .split_once(" / ")
        .ok_or_else(|| Error::data(format!("battery case \"{case}\": expected \"BASE / PROFILE\" as the battery names it")))?;
    let b = bases.iter().find(|b| b.name == base.trim()).ok_or_else(|| {
        Error::data(format!(
            "battery case \"{case}\": no base \"{base}\"; the bases are {}",
            names(bases.iter().map(|b| b.name.as_str()).collect())
        ))
    })?;
    let p = profiles.iter().find(|p| p.name == profile.trim()).ok_or_else(|| {
        Error::data(format!(
            "battery case \"{case}\": no profile \"{profile}\"; the profiles are {}",
            names(profiles.iter().map(|p| p.name.as_str()).collect())
        ))
    })?;
    let mut log = inject(&b.log, &p.errors)?;
    let split = if b.training && p.training { "training" } else { "scoring" };
    log.meta.name = Some(format!("{} / {}", b.name, p.name));
    log.meta.description =
        Some(format!("robustness battery, {split} case: {} with the gyro errors of profile \"{}\" added", b.name, p.name));
    Ok(log)
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
    /// The base is simulated (the goal on simulated drives is judged on these).
    pub simulated: bool,
    pub duration_min: f64,
    pub ne_psi: Vec<f64>,
    /// pipeline / best causal peer (raw, HDR, Fusion, ZARU, tuned HDR).
    pub ratio: f64,
    /// pipeline - 1.25 best peer - 0.05 <= 0 (the "within 1.25x + 0.05").
    pub within: bool,
    /// Column of the best causal method of the case, the pipeline included (the smoothed
    /// mode is not causal); the first of equals.
    pub best: usize,
}

impl CaseRow {
    /// A scored case: its ratio to the best causal peer and the goal's band from `ne_psi`
    /// (NE_psi per method, in [`method_names`]' columns).
    pub fn new(base: String, profile: String, training: bool, simulated: bool, duration_min: f64, ne_psi: Vec<f64>) -> CaseRow {
        let (pipe, best) = (ne_psi[PIPELINE], best_peer(&ne_psi));
        let (ratio, within) = (pipe / best, pipe <= 1.25 * best + 0.05);
        CaseRow { base, profile, training, simulated, duration_min, ratio, within, best: summary::best_causal(&ne_psi), ne_psi }
    }
}

/// The battery's result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Battery {
    pub methods: Vec<String>,
    pub cases: Vec<CaseRow>,
    pub training: Option<Summary>,
    pub scoring: Option<Summary>,
    /// The cases on drives the user added as logs (a part of the scoring cases).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub added: Option<Summary>,
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

/// Runs every (base, profile) case of the split.
pub fn run(bases: &[Base], profiles: &[Profile], split: Split, params: &PipelineParams, tuned: Option<&TunedHdr>) -> Result<Battery> {
    params.validate()?;
    let mut names = std::collections::HashSet::new();
    if let Some(b) = bases.iter().find(|b| !names.insert(b.name.as_str())) {
        return Err(Error::data(format!(
            "two battery bases are named \"{}\": a case is named by its base, so rename one (`# name:` in a log)",
            b.name
        )));
    }
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
    type Scored = (String, String, bool, bool, Result<(f64, Vec<f64>)>);
    let run_one = |(b, pr, training): &(&Base, &Profile, bool)| -> Scored {
        let r = inject(&b.log, &pr.errors).and_then(|log| score_case(&log, params, tuned.map(|t| t.for_base(&b.name))));
        (b.name.clone(), pr.name.clone(), *training, b.simulated, r)
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
    for (base, profile, training, simulated, r) in results {
        match r {
            Ok((duration_min, ne_psi)) => cases.push(CaseRow::new(base, profile, training, simulated, duration_min, ne_psi)),
            Err(e) => skipped.push((format!("{base} / {profile}"), e.to_string())),
        }
    }
    if cases.is_empty() {
        return Err(Error::data("the battery has no case that could be scored"));
    }
    let summary = |train: bool| summarize(&cases.iter().filter(|c| c.training == train).collect::<Vec<_>>());
    let added: Vec<&str> = bases.iter().filter(|b| b.added).map(|b| b.name.as_str()).collect();
    let added_summary = summarize(&cases.iter().filter(|c| added.contains(&c.base.as_str())).collect::<Vec<_>>());
    Ok(Battery {
        methods: method_names(tuned.is_some()).into_iter().map(String::from).collect(),
        training: summary(true),
        scoring: summary(false),
        added: added_summary,
        cases,
        skipped,
    })
}
