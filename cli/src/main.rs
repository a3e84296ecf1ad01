//! `gyrodrift`: the command-line front of the gyrodrift core. It reads files, parses
//! options, calls core and prints; every number comes from core.

mod batch;
mod commands;
mod oom;
mod output;
mod parquet_out;
mod roads_plot;

#[global_allocator]
static ALLOC: oom::Graceful = oom::Graceful;

use clap::{Parser, Subcommand};
use gyrodrift::sim::{GyroErrors, SimKind, SimRequest};
use gyrodrift::{battery, DriveLog, Error};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "gyrodrift", version, about = "Heading from a cheap yaw-rate gyro: HDR, Gyrodometry, calibration")]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
    /// A gap in time (over 20 median steps, at least 5 s): split the log there into drives of
    /// their own (parts under 30 s dropped), or refuse it. No method integrates across one.
    #[arg(long, global = true, value_enum, default_value = "split")]
    gaps: GapsArg,
    /// Run a log even when `check` finds an error in it (ms time, radian heading, rad/s or
    /// clockwise gyro), whose results would otherwise be absurd and are refused.
    #[arg(long, global = true)]
    ignore_check: bool,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum GapsArg {
    Split,
    Error,
}

/// A folder of logs scored as a fleet batch (`report --dir`, `compare --dir`).
#[derive(clap::Args)]
struct BatchArgs {
    /// Every *.csv log under this folder (recursive), in parallel: each drive a row with
    /// every method's E_psi and NE_psi (or its error; the rest go on), the fleet's Table II
    /// printed. --set takes the pipeline's settings here.
    #[arg(long, value_name = "DIR")]
    dir: Option<PathBuf>,
    /// With --dir: threads (0 = one per core).
    #[arg(long, default_value_t = 0, requires = "dir")]
    jobs: usize,
    /// With --dir: write the per-drive rows to this .parquet, .csv or .json file.
    #[arg(long, value_name = "FILE", requires = "dir")]
    out: Option<PathBuf>,
    /// With --dir: a logger's raw exports among the files (SensorLog, Sensor Logger,
    /// phyphox, PX4 ulog2csv, ROS CSV, comma2k19) are imported by their detected preset and
    /// scored, a drive per recording (a file, or a folder of several), instead of failing.
    #[arg(long, requires = "dir")]
    import: bool,
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
        /// Setting: a field of the pipeline's settings (min_still_s, road_gate_dps,
        /// road_sigma_dps, bias_walk_max_dps_per_sqrt_s, still_speed_mps, bias_s, ...).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        json: bool,
        /// Write the per-block (1 s) trace (CSV) to this file: the causal heading and its
        /// sigma from the bias model, the smoothed heading, the bias, the stops.
        #[arg(long, value_name = "FILE")]
        trace: Option<PathBuf>,
        /// Write the dead-reckoned paths (CSV, metres east and north) to this file: the log's
        /// speed integrated along the raw, Table-III HDR, pipeline and smoothed headings and
        /// the reference's, at every row with a speed (the dashboard's Track view).
        #[arg(long, value_name = "FILE")]
        track: Option<PathBuf>,
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
        #[arg(required_unless_present = "dir", conflicts_with = "dir")]
        files: Vec<PathBuf>,
        #[command(flatten)]
        batch: BatchArgs,
        /// Parameter: i_c, tau, theta_w, c1, c2, bias_s.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long, conflicts_with = "dir")]
        no_resample: bool,
        #[arg(long, conflicts_with_all = ["markdown", "csv"])]
        json: bool,
        #[arg(long, conflicts_with_all = ["csv", "dir"])]
        markdown: bool,
        /// The table as CSV (one row per drive, then the average or mean row).
        #[arg(long, conflicts_with = "dir")]
        csv: bool,
        /// Every method side by side (raw, HDR, pipeline, peers) instead of Table II, as
        /// Markdown (or --json); the pipeline always runs on the 1 Hz blocks.
        #[arg(long, conflicts_with = "no_resample")]
        compare: bool,
        /// With --compare: tune HDR on these training drives for a "HDR tuned" column.
        #[arg(long, num_args = 1.., requires = "compare")]
        tune_on: Vec<PathBuf>,
    },
    /// Every method side by side (raw, HDR, pipeline, peers): `report --compare`; with --dir,
    /// the fleet batch over a folder.
    Compare {
        #[arg(required_unless_present = "dir", conflicts_with = "dir")]
        files: Vec<PathBuf>,
        #[command(flatten)]
        batch: BatchArgs,
        /// Setting of the pipeline (min_still_s, road_gate_dps, ...).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        #[arg(long, conflicts_with = "dir")]
        csv: bool,
        /// Tune HDR on these training drives for a "HDR tuned" column.
        #[arg(long, num_args = 1.., conflicts_with = "dir")]
        tune_on: Vec<PathBuf>,
    },
    /// The robustness battery: recorded and simulated drives with gyro error classes added;
    /// every method scored; training and scoring cases reported apart.
    Battery {
        /// Recipes of recorded drives (a folder's *.toml or files); none = simulated only.
        #[arg(long, num_args = 1..)]
        recipes: Vec<PathBuf>,
        /// Your own drives as v1 logs with a reference heading: scoring bases whatever their
        /// names, with every error profile added; their cases are also summarised apart.
        #[arg(long, num_args = 1..)]
        logs: Vec<PathBuf>,
        /// Folder the recipes' files are in (default: each recipe's folder).
        #[arg(long)]
        data: Option<PathBuf>,
        /// training (where choices are made), scoring (only looked at), or all.
        #[arg(long, value_enum, default_value = "all")]
        split: SplitArg,
        /// Length of each simulated drive, min.
        #[arg(long, default_value_t = 20.0)]
        minutes: f64,
        /// Draw the simulated scoring bases afresh: K > 0 gives them seeds 101-106 + 1000 K
        /// (other roads, drivers and gyro units; the training cases stay as they are).
        #[arg(long, default_value_t = 0)]
        draw: u64,
        /// Print every case, not only the summaries.
        #[arg(long)]
        cases: bool,
        /// Pipeline setting (as for `pipeline`).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long)]
        json: bool,
        /// Write one case's log instead ("BASE / PROFILE", as the cases are named), to open
        /// in the dashboard or run with any command. A scoring case looked at is a look.
        #[arg(long, value_name = "CASE", conflicts_with_all = ["json", "cases", "set", "split"])]
        write_case: Option<String>,
        /// With --write-case: the file (stdout when absent).
        #[arg(long, requires = "write_case")]
        out: Option<PathBuf>,
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
        #[command(flatten)]
        errors: ErrorArgs,
        /// Output file (stdout when absent).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Add gyro errors to a log's yaw rate (the robustness battery's classes: turn-on bias,
    /// warm-up, random walk, steps, scale, rate-dependent bias, g-sensitivity, vibration,
    /// noise, quantisation, no lead-in, gyro alone), to see how a method copes with a
    /// worse gyro on your own drive. The other columns are kept (cut_lead_in drops the
    /// lead-in rows, gyro_only the speed and wheel columns).
    Inject {
        log: PathBuf,
        #[command(flatten)]
        errors: ErrorArgs,
        /// Output file (stdout when absent).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Write every shipped sample log (bit-identical for the same version) under a folder.
    Samples {
        #[arg(long, default_value = "sample-logs")]
        out: PathBuf,
        /// Another realisation of the same set: every seed + 1000 x K (0 = the shipped logs).
        /// The simulator's calibration averages over realisations (docs/simulator.md).
        #[arg(long, default_value_t = 0)]
        realisation: u64,
    },
    /// Import a recorded log in any format into a v1 drive log: by a recipe (TOML or JSON),
    /// or, given the logger's files, by the preset detected from their names and headers
    /// (SensorLog, Sensor Logger, phyphox, comma2k19, PX4 ulog2csv, ROS CSV).
    #[command(group(clap::ArgGroup::new("input").required(true).args(["files", "recipe"])))]
    Import {
        /// The logger's files (without --recipe): a preset is detected from them.
        #[arg(conflicts_with_all = ["recipe", "data", "allow_outside"])]
        files: Vec<PathBuf>,
        #[arg(long)]
        recipe: Option<PathBuf>,
        /// With FILES: print the detected recipe as TOML (to save, edit and re-use with
        /// --recipe) instead of importing.
        #[arg(long, requires = "files")]
        print_recipe: bool,
        /// Folder the recipe's `file` paths are relative to (default: the recipe's folder).
        #[arg(long)]
        data: Option<PathBuf>,
        /// Let the recipe read files outside the data folder (absolute paths, `..`, links).
        #[arg(long)]
        allow_outside: bool,
        /// Output file (stdout when absent).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Print what was imported (rows, reference samples, up vector, clock offset) as JSON.
        #[arg(long)]
        json: bool,
    },
    /// Road geometry of the recorded drives (via recipes) against the simulated sample
    /// drives, per road class: yaw rate while moving, straight runs, slow curvature, curves,
    /// the yaw-rate spectrum, lane-change-like manoeuvres and loops, and their distances.
    Roads {
        #[arg(long, num_args = 1.., default_value = "sample-logs/recipes")]
        recipes: Vec<PathBuf>,
        #[arg(long)]
        data: Option<PathBuf>,
        #[arg(long)]
        json: bool,
        /// Also draw the recorded and simulated distributions and spectra per road class into this SVG
        #[arg(long)]
        plot: Option<PathBuf>,
    },
    /// What a log looks like before any method runs: rate, gaps, units and sign against the
    /// reference, bias, outliers; each finding with its fix. Exit 1 when it finds an error.
    Check {
        log: PathBuf,
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
enum SplitArg {
    Training,
    Scoring,
    All,
}

/// Gyro errors to add: a battery profile by name, settings on top.
#[derive(clap::Args)]
struct ErrorArgs {
    /// A robustness-battery error profile by name, as `battery --cases` lists them
    /// (e.g. "cheap MEMS A cut").
    #[arg(long)]
    profile: Option<String>,
    /// A gyro error setting on top (of the profile, or of none): bias_dps, warmup_dps,
    /// warmup_tau_s, walk_dps_per_sqrt_s, step_dps, step_every_s, scale, rate_dep,
    /// g_sens_dps_per_mps2, noise_dps, vibration_noise_dps, vibration_bias_dps, lsb_dps,
    /// cut_lead_in (0/1), gyro_only (0/1), seed.
    #[arg(long, value_name = "KEY=VALUE")]
    error: Vec<String>,
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
    gyrodrift::parse_log(file).map_err(|e| {
        let mut f = fail(path, e);
        if let Some(hint) = import_hint(path) {
            f.0 += &format!("; {hint}");
        }
        f
    })
}

/// For a file that is not a v1 log but a logger's raw export a preset reads (core's
/// `import_hint`): the `import` command that makes a v1 log of it, as the dashboard imports
/// such files when they are dropped on it.
fn import_hint(path: &Path) -> Option<String> {
    gyrodrift::import::import_hint(path).map(|h| hint_text(&h, "a file"))
}

/// An import hint in this front's words (`what`: a file, a recording): the `import` command
/// that makes a v1 log of it.
fn hint_text(h: &gyrodrift::import::ImportHint, what: &str) -> String {
    let quoted = |p: &PathBuf| match p.display().to_string() {
        s if s.contains(char::is_whitespace) => format!("'{s}'"),
        s => s,
    };
    let files: Vec<String> = h.files.iter().map(quoted).collect();
    format!(
        "it looks like {what} of {} (import preset {}): `gyrodrift import {} --out drive.csv` makes a v1 drive log of it",
        h.title,
        h.preset,
        files.join(" ")
    )
}

/// Splits `key=value` (given with `flag`) and parses the value as a number.
fn parse_set(flag: &str, s: &str) -> Result<(String, f64), Failure> {
    let (k, v) = s.split_once('=').ok_or_else(|| Failure(format!("{flag} {s}: expected KEY=VALUE")))?;
    let value: f64 = v.trim().parse().map_err(|_| Failure(format!("{flag} {s}: \"{v}\" is not a number")))?;
    Ok((k.trim().to_string(), value))
}

/// Settings from the `--set` pairs on top of the defaults, through core's one schema.
fn settings<T: gyrodrift::options::Settings>(sets: &[String]) -> Result<T, Failure> {
    let pairs = sets.iter().map(|s| parse_set("--set", s)).collect::<Result<Vec<_>, _>>()?;
    gyrodrift::options::from_pairs(&pairs).map_err(|e| Failure(format!("--set: {e}")))
}

/// The gyro errors of `--profile` (a battery profile by name) with the `--error` pairs on
/// top (of no errors without a profile); None when neither is given.
fn gyro_errors(profile: Option<&str>, sets: &[String]) -> Result<Option<GyroErrors>, Failure> {
    if profile.is_none() && sets.is_empty() {
        return Ok(None);
    }
    let base = match profile {
        Some(name) => battery::profile(name).map_err(|e| Failure(format!("--profile: {e}")))?.errors,
        None => GyroErrors::default(),
    };
    let pairs = sets.iter().map(|s| parse_set("--error", s)).collect::<Result<Vec<_>, _>>()?;
    gyrodrift::options::from_pairs_on(&base, &pairs).map(Some).map_err(|e| Failure(format!("--error: {e}")))
}

/// Reads a recipe (TOML, or JSON by extension) and imports its files from `data` (default:
/// the recipe's folder), confined to that folder unless `allow_outside` (core's `fs`).
fn import_recipe(recipe: &Path, data: Option<&Path>, allow_outside: bool) -> Result<(DriveLog, gyrodrift::import::ImportSummary), Failure> {
    gyrodrift::import::import_recipe_file(recipe, data, allow_outside).map_err(|e| Failure(e.to_string()))
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
    write_stdout(&format!("{text}\n"))
}

/// Writes to standard output; a write error (a full disk, `> /dev/full`) is a failure
/// naming the output, exit 2, not a panic.
fn write_stdout(text: &str) -> Result<(), Failure> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes()).and_then(|_| out.flush()).map_err(|e| Failure(format!("standard output: cannot write: {e}")))
}

fn run(cli: Cli) -> Result<(), Failure> {
    use commands as c;
    let gaps = match cli.gaps {
        GapsArg::Split => gyrodrift::log::gaps::GapPolicy::Split,
        GapsArg::Error => gyrodrift::log::gaps::GapPolicy::Error,
    };
    let input = commands::Input { gaps, ignore_check: cli.ignore_check };
    match cli.cmd {
        Cmd::Hdr { log, no_resample, set, json, trace } => c::hdr(&log, !no_resample, &set, json, trace.as_deref(), input),
        Cmd::Pipeline { log, set, json, trace, track } => c::pipeline(&log, &set, json, [trace.as_deref(), track.as_deref()], input),
        Cmd::Gyrodometry { log, set, json } => c::gyrodometry(&log, &set, json, input),
        Cmd::Calibrate { log, set, json } => c::calibrate(&log, &set, json),
        Cmd::Report { batch: BatchArgs { dir: Some(dir), jobs, out, import }, set, json, .. }
        | Cmd::Compare { batch: BatchArgs { dir: Some(dir), jobs, out, import }, set, json, .. } => {
            let opts = gyrodrift::fleet::FleetOptions { input, pipeline: settings(&set)? };
            batch::run(&dir, batch::Batch { jobs, out: out.as_deref(), import }, &opts, json)
        }
        Cmd::Compare { files, set, json, csv, tune_on, .. } => c::compare(&files, &set, json, csv, &tune_on, input),
        Cmd::Report { files, set, json, csv, compare: true, tune_on, .. } => c::compare(&files, &set, json, csv, &tune_on, input),
        Cmd::Report { files, set, no_resample, json, markdown, csv, .. } => {
            c::report(&files, &set, !no_resample, json, markdown, csv, input)
        }
        Cmd::Tune { train, test, json, markdown } => c::tune(&train, &test, json, markdown, input),
        Cmd::Simulate { kind, scenario, minutes, seed, name, errors, out } => {
            let kind = match kind {
                SimKindArg::Drive => SimKind::Drive,
                SimKindArg::Robot => SimKind::Robot,
                SimKindArg::Turntable => SimKind::Turntable,
                SimKindArg::Static => SimKind::Static,
            };
            let errors = gyro_errors(errors.profile.as_deref(), &errors.error)?;
            c::simulate(&SimRequest { kind, scenario, minutes, seed, name, errors }, out.as_deref())
        }
        Cmd::Inject { log, errors: e, out } => match gyro_errors(e.profile.as_deref(), &e.error)? {
            Some(errors) => c::inject(&log, &errors, out.as_deref()),
            None => Err(Failure("inject: name the errors to add (--profile NAME, --error KEY=VALUE or both)".into())),
        },
        Cmd::Samples { out, realisation } => c::samples(&out, realisation),
        Cmd::Battery { recipes, logs, data, minutes, draw, write_case: Some(case), out, .. } => {
            let given = c::BatteryInput { recipes: &recipes, logs: &logs, data: data.as_deref(), input };
            c::battery_case(given, c::SimDraw { minutes, draw }, &case, out.as_deref())
        }
        Cmd::Battery { recipes, logs, data, split, minutes, draw, cases, set, json, .. } => {
            let split = match split {
                SplitArg::Training => battery::Split::Training,
                SplitArg::Scoring => battery::Split::Scoring,
                SplitArg::All => battery::Split::All,
            };
            let given = c::BatteryInput { recipes: &recipes, logs: &logs, data: data.as_deref(), input };
            c::battery(given, split, c::SimDraw { minutes, draw }, cases, &set, json)
        }
        Cmd::Import { files, recipe, print_recipe, data, allow_outside, out, json } => match recipe {
            Some(recipe) => c::import(&recipe, data.as_deref(), allow_outside, out.as_deref(), json),
            None => c::import_detected(&files, print_recipe, out.as_deref(), json),
        },
        Cmd::Allan { log, json } => c::allan(&log, json),
        Cmd::Check { log, json } => c::check(&log, json),
        Cmd::Roads { recipes, data, json, plot } => c::roads(&recipes, data.as_deref(), json, plot.as_deref()),
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
