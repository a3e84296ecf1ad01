//! `gyrodrift`: the command-line front of the gyrodrift core. It reads files, parses
//! options, calls core and prints; every number comes from core.

mod output;

use clap::{Parser, Subcommand};
use gyrodrift::{calibration, gyrodometry, hdr, DriveLog, Error};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "gyrodrift", version, about = "Heading from a cheap yaw-rate gyro: HDR, Gyrodometry, calibration")]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Heuristic Drift Reduction on a drive log, scored against its reference heading.
    Hdr {
        log: PathBuf,
        /// Run on the raw rows instead of the paper's 1 Hz blocks.
        #[arg(long)]
        no_resample: bool,
        /// Parameter: i_c, tau, theta_w, c1, c2, bias_s (e.g. --set tau=1.0).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print one JSON object with the Result keys.
        #[arg(long)]
        json: bool,
        /// Write the per-sample heading trace (CSV) to this file.
        #[arg(long, value_name = "FILE")]
        trace: Option<PathBuf>,
    },
    /// The recommended drift-reduction pipeline (beyond the paper) against raw, Table-III HDR
    /// and two peers (x-io Fusion offset, zero-rate update at stops).
    Pipeline {
        log: PathBuf,
        /// Setting: min_still_s, gate_dps, road_sigma_dps, bias_walk_dps_per_sqrt_s, bias_s, ...
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        json: bool,
    },
    /// Gyrodometry on a robot log with wheel travel.
    Gyrodometry {
        log: PathBuf,
        /// Parameter: thres_rate, wheelbase_m, bias_s.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        json: bool,
    },
    /// Fit the rate x temperature error model to a turntable session.
    Calibrate {
        log: PathBuf,
        /// Parameter: p, q, bias_s.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        json: bool,
    },
    /// The HDR paper's Table II for any set of drives.
    Report {
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// Parameter: i_c, tau, theta_w, c1, c2, bias_s.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        no_resample: bool,
        #[arg(long, conflicts_with = "markdown")]
        json: bool,
        #[arg(long)]
        markdown: bool,
        /// Every method side by side (raw, HDR, pipeline, peers) instead of Table II, as
        /// Markdown (or --json); the pipeline always runs on the 1 Hz blocks.
        #[arg(long, conflicts_with = "no_resample")]
        compare: bool,
        /// With --compare: tune HDR on these training drives for a "HDR tuned" column.
        #[arg(long, num_args = 1.., requires = "compare")]
        tune_on: Vec<PathBuf>,
    },
    /// The robustness battery: recorded and simulated drives with gyro error classes added;
    /// every method scored; training and scoring cases reported apart.
    Battery {
        /// Recipes of recorded drives (a folder's *.toml or files); none = simulated only.
        #[arg(long, num_args = 1..)]
        recipes: Vec<PathBuf>,
        /// Folder the recipes' files are in (default: each recipe's folder).
        #[arg(long)]
        data: Option<PathBuf>,
        /// training (where choices are made), scoring (only looked at), or all.
        #[arg(long, default_value = "all")]
        split: String,
        /// Length of each simulated drive, min.
        #[arg(long, default_value_t = 20.0)]
        minutes: f64,
        /// Print every case, not only the summaries.
        #[arg(long)]
        cases: bool,
        /// Pipeline setting (as for `pipeline`).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        json: bool,
    },
    /// Tune the five HDR parameters on training drives; report Table III vs tuned.
    Tune {
        #[arg(long, num_args = 1.., required = true)]
        train: Vec<PathBuf>,
        #[arg(long, num_args = 1..)]
        test: Vec<PathBuf>,
        #[arg(long, conflicts_with = "markdown")]
        json: bool,
        #[arg(long)]
        markdown: bool,
    },
    /// Simulate a log with known truth: drive, robot, turntable or static.
    Simulate {
        #[arg(value_enum)]
        kind: SimKindArg,
        /// Drive: city, downtown, suburbs, rural, highway, mixed. Robot: straight, turns.
        #[arg(long)]
        scenario: Option<String>,
        /// Length in minutes (drive 20, robot 2.33, static 120 by default).
        #[arg(long)]
        minutes: Option<f64>,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Written as `# name:` in the log.
        #[arg(long)]
        name: Option<String>,
        /// Output file (stdout when absent).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Write every shipped sample log (bit-identical for the same version) under a folder.
    Samples {
        #[arg(long, default_value = "sample-logs")]
        out: PathBuf,
    },
    /// Import a recorded log in any format into a v1 drive log, by a recipe (TOML or JSON).
    Import {
        #[arg(long)]
        recipe: PathBuf,
        /// Folder the recipe's `file` paths are relative to (default: the recipe's folder).
        #[arg(long)]
        data: Option<PathBuf>,
        /// Output file (stdout when absent).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Print what was imported (rows, reference samples, up vector, clock offset) as JSON.
        #[arg(long)]
        json: bool,
    },
    /// Overlapping Allan deviation of a (static) gyro log.
    Allan {
        log: PathBuf,
        #[arg(long)]
        json: bool,
    },
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum SimKindArg {
    Drive,
    Robot,
    Turntable,
    Static,
}

/// An error for the user: `file: message`, exit code 2.
struct Failure(String);

fn fail(path: &Path, e: Error) -> Failure {
    Failure(format!("{}: {}", path.display(), e))
}

fn read_log(path: &Path) -> Result<DriveLog, Failure> {
    let file = std::fs::File::open(path).map_err(|e| Failure(format!("{}: cannot open: {}", path.display(), e)))?;
    gyrodrift::parse_log(file).map_err(|e| fail(path, e))
}

/// Reads many logs, each named by its `# name:` or its file stem.
fn read_logs(paths: &[PathBuf]) -> Result<Vec<(String, DriveLog)>, Failure> {
    paths
        .iter()
        .map(|p| {
            let log = read_log(p)?;
            let stem = p.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            Ok((log.meta.name.clone().unwrap_or(stem), log))
        })
        .collect()
}

/// Splits `key=value` and parses the value as a number.
fn parse_set(s: &str) -> Result<(String, f64), Failure> {
    let (k, v) = s.split_once('=').ok_or_else(|| Failure(format!("--set {s}: expected KEY=VALUE")))?;
    let value: f64 = v.trim().parse().map_err(|_| Failure(format!("--set {s}: \"{v}\" is not a number")))?;
    Ok((k.trim().to_string(), value))
}

/// Settings from the `--set` pairs on top of the defaults, through core's one schema.
fn settings<T: gyrodrift::options::Settings>(sets: &[String]) -> Result<T, Failure> {
    let pairs = sets.iter().map(|s| parse_set(s)).collect::<Result<Vec<_>, _>>()?;
    gyrodrift::options::from_pairs(&pairs).map_err(|e| Failure(format!("--set: {e}")))
}

/// Reads a recipe (TOML, or JSON by extension) and imports its files from `data` (default:
/// the recipe's folder).
fn import_recipe(recipe: &Path, data: Option<&Path>) -> Result<(DriveLog, gyrodrift::import::ImportSummary), Failure> {
    let text = std::fs::read_to_string(recipe).map_err(|e| Failure(format!("{}: cannot read: {e}", recipe.display())))?;
    let parsed: gyrodrift::import::Recipe = if recipe.extension().is_some_and(|e| e == "json") {
        serde_json::from_str(&text).map_err(|e| Failure(format!("{}: {e}", recipe.display())))?
    } else {
        toml::from_str(&text).map_err(|e| Failure(format!("{}: {e}", recipe.display())))?
    };
    let root = data.map(Path::to_path_buf).unwrap_or_else(|| recipe.parent().map(Path::to_path_buf).unwrap_or_default());
    let mut files = |name: &str| -> gyrodrift::Result<Box<dyn std::io::Read>> {
        let path = root.join(name);
        std::fs::File::open(&path)
            .map(|f| Box::new(f) as Box<dyn std::io::Read>)
            .map_err(|e| Error::File(format!("{}: cannot open: {e}", path.display())))
    };
    gyrodrift::import::import(&parsed, &mut files).map_err(|e| fail(recipe, e))
}

/// Recipe paths: files as given, folders as their *.toml files (sorted).
fn expand_recipes(paths: &[PathBuf]) -> Result<Vec<PathBuf>, Failure> {
    let mut out = Vec::new();
    for p in paths {
        if p.is_dir() {
            let rd = std::fs::read_dir(p).map_err(|e| Failure(format!("{}: cannot list: {e}", p.display())))?;
            let mut v: Vec<PathBuf> =
                rd.filter_map(|e| e.ok().map(|e| e.path())).filter(|f| f.extension().is_some_and(|x| x == "toml")).collect();
            v.sort();
            out.extend(v);
        } else {
            out.push(p.clone());
        }
    }
    Ok(out)
}

fn print_json<T: serde::Serialize>(value: &T) -> Result<(), Failure> {
    let text = serde_json::to_string_pretty(value).map_err(|e| Failure(format!("JSON: {e}")))?;
    println!("{text}");
    Ok(())
}

fn run(cli: Cli) -> Result<(), Failure> {
    match cli.cmd {
        Cmd::Hdr { log, no_resample, set, json, trace } => {
            let opts = hdr::HdrOptions { resample: !no_resample, ..settings(&set)? };
            let drive = read_log(&log)?;
            let run = hdr::run(&drive, &opts).map_err(|e| fail(&log, e))?;
            if let Some(path) = trace {
                let f = std::fs::File::create(&path).map_err(|e| Failure(format!("{}: cannot create: {}", path.display(), e)))?;
                run.trace.write_csv(f).map_err(|e| fail(&path, e))?;
            }
            let result = run.result.map_err(|e| fail(&log, e))?;
            if json {
                print_json(&result)
            } else {
                print!("{}", output::hdr_table(&log, &opts, &result));
                Ok(())
            }
        }
        Cmd::Pipeline { log, set, json } => {
            let params: gyrodrift::pipeline::PipelineParams = settings(&set)?;
            let drive = read_log(&log)?;
            let run = gyrodrift::pipeline::run(&drive, &params).map_err(|e| fail(&log, e))?;
            let result = run.result.map_err(|e| fail(&log, e))?;
            if json {
                print_json(&result)
            } else {
                print!("{}", output::pipeline_table(&log, &result));
                Ok(())
            }
        }
        Cmd::Gyrodometry { log, set, json } => {
            let opts: gyrodometry::GyrodometryOptions = settings(&set)?;
            let drive = read_log(&log)?;
            let run = gyrodometry::run(&drive, &opts).map_err(|e| fail(&log, e))?;
            let result = run.result.map_err(|e| fail(&log, e))?;
            if json {
                print_json(&result)
            } else {
                print!("{}", output::gyrodometry_table(&log, &result));
                Ok(())
            }
        }
        Cmd::Calibrate { log, set, json } => {
            let opts: calibration::CalibrationOptions = settings(&set)?;
            let drive = read_log(&log)?;
            let run = calibration::run(&drive, &opts).map_err(|e| fail(&log, e))?;
            if json {
                print_json(&run.result)
            } else {
                print!("{}", output::calibration_table(&log, &run));
                Ok(())
            }
        }
        Cmd::Report { files, set, no_resample: _, json, markdown: _, compare: true, tune_on } => {
            let params: gyrodrift::pipeline::PipelineParams = settings(&set)?;
            let tuned = if tune_on.is_empty() {
                None
            } else {
                use gyrodrift::tune;
                let train = read_logs(&tune_on)?;
                let refs: Vec<(String, &DriveLog)> = train.iter().map(|(n, l)| (n.clone(), l)).collect();
                let prepared = tune::prepare_all(&refs, &hdr::HdrOptions::default()).map_err(|e| Failure(e.to_string()))?;
                Some(tune::tune(&prepared, &tune::TuneOptions::default()).map_err(|e| Failure(e.to_string()))?.recommended)
            };
            let logs = read_logs(&files)?;
            let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), l)).collect();
            let c = gyrodrift::compare::compare(&named, &params, tuned).map_err(|e| Failure(e.to_string()))?;
            if json {
                print_json(&c)
            } else {
                print!("{}", c.to_markdown());
                Ok(())
            }
        }
        Cmd::Report { files, set, no_resample, json, markdown, .. } => {
            let opts = hdr::HdrOptions { resample: !no_resample, ..settings(&set)? };
            let logs = read_logs(&files)?;
            let named: Vec<(String, &DriveLog)> = logs.iter().map(|(n, l)| (n.clone(), l)).collect();
            let report = gyrodrift::report::Report::build(&named, &opts).map_err(|e| Failure(e.to_string()))?;
            if json {
                print_json(&report)
            } else {
                print!("{}", if markdown { report.to_markdown() } else { report.to_text() });
                Ok(())
            }
        }
        Cmd::Tune { train, test, json, markdown } => {
            use gyrodrift::tune;
            let opts = hdr::HdrOptions::default();
            let train_logs = read_logs(&train)?;
            let test_logs = read_logs(&test)?;
            let prep = |v: &[(String, DriveLog)]| -> Result<Vec<tune::PreparedDrive>, Failure> {
                let refs: Vec<(String, &DriveLog)> = v.iter().map(|(n, l)| (n.clone(), l)).collect();
                tune::prepare_all(&refs, &opts).map_err(|e| Failure(e.to_string()))
            };
            let train_p = prep(&train_logs)?;
            let test_p = prep(&test_logs)?;
            let rep = tune::tune_and_report(&train_p, &test_p, &tune::TuneOptions::default()).map_err(|e| Failure(e.to_string()))?;
            if json {
                return print_json(&rep);
            }
            print!("{}", output::tune_text(&rep, markdown));
            Ok(())
        }
        Cmd::Simulate { kind, scenario, minutes, seed, name, out } => {
            use gyrodrift::sim::{SimKind, SimRequest};
            let kind = match kind {
                SimKindArg::Drive => SimKind::Drive,
                SimKindArg::Robot => SimKind::Robot,
                SimKindArg::Turntable => SimKind::Turntable,
                SimKindArg::Static => SimKind::Static,
            };
            let req = SimRequest { kind, scenario, minutes, seed, name };
            let log = gyrodrift::sim::simulate(&req).map_err(|e| Failure(e.to_string()))?;
            match out {
                Some(path) => {
                    let f = std::fs::File::create(&path).map_err(|e| Failure(format!("{}: cannot create: {}", path.display(), e)))?;
                    log.write_csv(f).map_err(|e| fail(&path, e))
                }
                None => log.write_csv(std::io::stdout().lock()).map_err(|e| Failure(e.to_string())),
            }
        }
        Cmd::Samples { out } => {
            for s in gyrodrift::sim::samples::SAMPLE_LOGS {
                let path = out.join(s.path);
                if let Some(dir) = path.parent() {
                    std::fs::create_dir_all(dir).map_err(|e| Failure(format!("{}: {e}", dir.display())))?;
                }
                let log = gyrodrift::sim::simulate(&s.request()).map_err(|e| Failure(e.to_string()))?;
                let f = std::fs::File::create(&path).map_err(|e| Failure(format!("{}: cannot create: {}", path.display(), e)))?;
                log.write_csv(f).map_err(|e| fail(&path, e))?;
                eprintln!("wrote {}", path.display());
            }
            Ok(())
        }
        Cmd::Battery { recipes, data, split, minutes, cases, set, json } => {
            use gyrodrift::battery;
            let params: gyrodrift::pipeline::PipelineParams = settings(&set)?;
            let split = match split.as_str() {
                "training" => battery::Split::Training,
                "scoring" => battery::Split::Scoring,
                "all" => battery::Split::All,
                other => return Err(Failure(format!("--split {other}: expected training, scoring or all"))),
            };
            if !(minutes.is_finite() && minutes > 1.0 && minutes <= 600.0) {
                return Err(Failure(format!("--minutes {minutes}: expected a length in (1, 600] min")));
            }
            let mut bases = Vec::new();
            for r in expand_recipes(&recipes)? {
                let (log, _) = import_recipe(&r, data.as_deref())?;
                let stem = r.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
                bases.push(battery::recorded_base(&stem, log));
            }
            bases.extend(battery::simulated_bases(minutes));
            let tuned = battery::tune_hdr(&bases).map_err(|e| Failure(e.to_string()))?;
            eprintln!(
                "HDR tuned on the {} training bases: cross-validated NE_psi {:.4} (Table III {:.4}) -> {}",
                bases.iter().filter(|b| b.training).count(),
                tuned.cv.as_ref().map_or(f64::NAN, |c| c.cv_tuned_deg_per_min),
                tuned.cv.as_ref().map_or(f64::NAN, |c| c.cv_table_iii_deg_per_min),
                if tuned.recommended_is_tuned { "tuned parameters used" } else { "Table III used (tuning does not generalise)" }
            );
            let b =
                battery::run(&bases, &battery::profiles(), split, &params, Some(tuned.recommended)).map_err(|e| Failure(e.to_string()))?;
            if json {
                print_json(&b)
            } else {
                print!("{}", b.to_markdown(cases));
                Ok(())
            }
        }
        Cmd::Import { recipe, data, out, json } => {
            let (log, summary) = import_recipe(&recipe, data.as_deref())?;
            match &out {
                Some(path) => {
                    let f = std::fs::File::create(path).map_err(|e| Failure(format!("{}: cannot create: {}", path.display(), e)))?;
                    log.write_csv(f).map_err(|e| fail(path, e))?;
                }
                None if !json => log.write_csv(std::io::stdout().lock()).map_err(|e| Failure(e.to_string()))?,
                None => {}
            }
            if json {
                print_json(&summary)?;
            } else {
                eprintln!("{}", output::import_line(&recipe, &summary));
            }
            Ok(())
        }
        Cmd::Allan { log, json } => {
            let drive = read_log(&log)?;
            let result = gyrodrift::allan::run(&drive).map_err(|e| fail(&log, e))?;
            if json {
                print_json(&result)
            } else {
                print!("{}", output::allan_table(&log, &result));
                Ok(())
            }
        }
    }
}

fn main() -> ExitCode {
    // A closed pipe (`gyrodrift allan LOG | head -1`) ends the command quietly with SIGPIPE,
    // as other Unix tools do, instead of a panic inside print!.
    #[cfg(unix)]
    // SAFETY: restoring the default disposition of one signal before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure(msg)) => {
            eprintln!("{msg}");
            ExitCode::from(2)
        }
    }
}
