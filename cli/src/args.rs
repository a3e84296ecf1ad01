//! The command line's arguments (clap): the commands, their options and help texts.

use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "gyrodrift",
    version,
    about = "Heading from a cheap yaw-rate gyro: HDR, Gyrodometry, calibration",
    after_help = "A LOG given as `-` is read from standard input: gyrodrift import drive.zip | gyrodrift pipeline -"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) cmd: Cmd,
    /// A gap in time (over 20 median steps, at least 5 s): split the log there into drives of
    /// their own (parts under 30 s dropped), or refuse it. No method integrates across one.
    #[arg(long, global = true, value_enum, default_value = "split")]
    pub(crate) gaps: GapsArg,
    /// Run a log even when `check` finds an error in it (time not in seconds, heading in
    /// radians, gyro in another unit or clockwise), whose results would otherwise be absurd
    /// and are refused.
    #[arg(long, global = true)]
    pub(crate) ignore_check: bool,
    /// A log whose time repeats or steps back by at most 1 s (a logger writing a sample twice,
    /// or a row late): refuse it naming the line, or fix it: rows of one time merged by their
    /// mean, late rows sorted in, as `import` does (said on stderr). A larger step back (a
    /// clock reset) is refused unless `--joined split` reads each part as a log.
    #[arg(long, global = true, value_enum, default_value = "error")]
    pub(crate) time_order: TimeOrderArg,
    /// A file of several logs joined on (`cat a.csv b.csv`, a logger appending each session,
    /// or restarting its clock without a new header): refuse it naming the second log's first
    /// line, or score each log as a drive of its own (said on stderr). `split` writes them as
    /// files.
    #[arg(long, global = true, value_enum, default_value = "error")]
    pub(crate) joined: JoinedArg,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum JoinedArg {
    Error,
    Split,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum TimeOrderArg {
    Error,
    Fix,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum GapsArg {
    Split,
    Error,
}

/// A folder of logs scored as a fleet batch (`report --dir`, `compare --dir`).
#[derive(clap::Args)]
pub(crate) struct BatchArgs {
    /// Every *.csv (and *.csv.gz) log under this folder (recursive), in parallel: each drive a row with
    /// every method's E_psi and NE_psi (or its error; the rest go on), the fleet's Table II
    /// printed. --set takes the pipeline's settings here.
    #[arg(long, value_name = "DIR")]
    pub(crate) dir: Option<PathBuf>,
    /// With --dir: threads (0 = one per core).
    #[arg(long, default_value_t = 0, requires = "dir")]
    pub(crate) jobs: usize,
    /// With --dir: write the per-drive rows to this .parquet, .csv or .json file.
    #[arg(long, value_name = "FILE", requires = "dir")]
    pub(crate) out: Option<PathBuf>,
    /// With --dir: a logger's raw exports among the files (SensorLog, Sensor Logger,
    /// phyphox, PX4 ulog2csv, ROS CSV, comma2k19) are imported by their detected preset and
    /// scored, a drive per recording (a file, or a folder of several), instead of failing.
    #[arg(long, requires = "dir")]
    pub(crate) import: bool,
    /// With --dir: files that are not v1 logs are imported by this recipe (TOML or JSON;
    /// a logger of your own) and scored, a drive per recording: a folder holding the files
    /// the recipe names, or, for a recipe of one table, each such file whatever its name.
    #[arg(long, value_name = "RECIPE", requires = "dir", conflicts_with = "import")]
    pub(crate) recipe: Option<PathBuf>,
    /// With --dir: exit 1 when a file could not be scored (after every row is written and
    /// the summary printed), as a CI job wants; without it a fleet job keeps exit 0.
    #[arg(long, requires = "dir")]
    pub(crate) fail_on_error: bool,
}

/// What a command's LOG may be.
const LOG_HELP: &str = "The drive log: a v1 CSV (README, \"The drive-log CSV\"), gzipped or not, or - for standard input; a logger's raw export or its folder is answered with the import that reads it";

#[derive(Subcommand)]
pub(crate) enum Cmd {
    /// Heuristic Drift Reduction on a drive log, scored against its reference heading.
    Hdr {
        #[arg(help = LOG_HELP)]
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
        #[arg(help = LOG_HELP)]
        log: PathBuf,
        /// Setting: a field of the pipeline's settings (min_still_s, road_gate_dps,
        /// road_sigma_dps, bias_walk_max_dps_per_sqrt_s, still_speed_mps, bias_s, ...).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print the results as JSON instead of the table.
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
        #[arg(help = LOG_HELP)]
        log: PathBuf,
        /// Parameter: thres_rate, wheelbase_m, bias_s.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print the results as JSON instead of the table.
        #[arg(long)]
        json: bool,
    },
    /// Fit the rate x temperature error model to a turntable session.
    Calibrate {
        #[arg(help = LOG_HELP)]
        log: PathBuf,
        /// Parameter: p, q, bias_s.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print the results as JSON instead of the table.
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
        /// Run HDR on the raw rows instead of the paper's 1 Hz blocks.
        #[arg(long, conflicts_with = "dir")]
        no_resample: bool,
        /// Print the results as JSON instead of the table.
        #[arg(long, conflicts_with_all = ["markdown", "csv"])]
        json: bool,
        /// The table as Markdown.
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
        /// Print the results as JSON instead of the table.
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// The table as CSV (one row per drive).
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
        /// Print the results as JSON instead of the table.
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
        /// The drives to tune on (v1 logs with a reference heading), scored leave-one-out.
        #[arg(long, num_args = 1.., required = true)]
        train: Vec<PathBuf>,
        /// Drives to score Table III and the tuned parameters on, unseen by the tuning.
        #[arg(long, num_args = 1..)]
        test: Vec<PathBuf>,
        /// Print the results as JSON instead of the table.
        #[arg(long, conflicts_with = "markdown")]
        json: bool,
        /// The tables as Markdown.
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
        /// Seed of the random road, driver and gyro (the same seed, the same log).
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
        #[arg(help = LOG_HELP)]
        log: PathBuf,
        #[command(flatten)]
        errors: ErrorArgs,
        /// Output file (stdout when absent).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Write each log of a file that holds several joined on (`cat a.csv b.csv`, a logger
    /// appending each session to one file, or restarting its clock without a new header),
    /// which the other commands refuse naming the line where the second starts, as a v1 log
    /// of its own: STEM.1.csv, STEM.2.csv, ...
    Split {
        #[arg(help = LOG_HELP)]
        log: PathBuf,
        /// Folder to write them to (default: the log's own; created if missing).
        #[arg(long)]
        out_dir: Option<PathBuf>,
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
        /// The logger's files (without --recipe), their folder, or the .zip it shared: a preset is detected
        /// from them.
        #[arg(conflicts_with_all = ["recipe", "data", "allow_outside"])]
        files: Vec<PathBuf>,
        /// The recipe (TOML or JSON) that says how the files become a v1 log
        /// (sample-logs/recipes/README.md).
        #[arg(long)]
        recipe: Option<PathBuf>,
        /// With FILES: print the detected recipe as TOML (to save, edit and re-use with
        /// --recipe) instead of importing.
        #[arg(long, requires = "files")]
        print_recipe: bool,
        /// Folder the recipe's `file` paths are relative to (default: the recipe's folder),
        /// or a logger's zipped export whose tables the recipe names.
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
        /// Recipes of the recorded drives (a folder's *.toml or files); with neither this
        /// nor --logs, the shipped ones in sample-logs/recipes.
        #[arg(long, num_args = 1..)]
        recipes: Vec<PathBuf>,
        /// Your own drives as v1 logs (each with a speed column; read, checked and split at
        /// gaps as every command reads a log): their roads against the simulator's. The
        /// yaw rate is the gyro's less the median rate of its still seconds (10 or more), else
        /// as it is.
        #[arg(long, num_args = 1..)]
        logs: Vec<PathBuf>,
        /// Folder the recipes' files are in (default: each recipe's folder).
        #[arg(long)]
        data: Option<PathBuf>,
        /// Print the results as JSON instead of the table.
        #[arg(long)]
        json: bool,
        /// Also draw the recorded and simulated distributions and spectra per road class into this SVG
        #[arg(long)]
        plot: Option<PathBuf>,
    },
    /// What a log looks like before any method runs: rate, gaps, units and sign against the
    /// reference, bias, outliers; each finding with its fix. Exit 1 when it finds an error,
    /// 2 when a log cannot be read (the others are checked all the same).
    Check {
        /// The drive logs (v1 CSV, gzipped or not, or - for standard input); with `--joined
        /// split` each log of a file of several joined on (or cut at a clock reset) is checked
        #[arg(required = true, num_args = 1..)]
        logs: Vec<PathBuf>,
        /// Print the results as JSON instead of the table.
        #[arg(long)]
        json: bool,
    },
    /// Overlapping Allan deviation of a (static) gyro log.
    Allan {
        #[arg(help = LOG_HELP)]
        log: PathBuf,
        /// Print the results as JSON instead of the table.
        #[arg(long)]
        json: bool,
    },
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum SplitArg {
    Training,
    Scoring,
    All,
}

/// Gyro errors to add: a battery profile by name, settings on top.
#[derive(clap::Args)]
pub(crate) struct ErrorArgs {
    /// A robustness-battery error profile by name, as `battery --cases` lists them
    /// (e.g. "cheap MEMS A cut").
    #[arg(long)]
    pub(crate) profile: Option<String>,
    /// A gyro error setting on top (of the profile, or of none): bias_dps, warmup_dps,
    /// warmup_tau_s, walk_dps_per_sqrt_s, step_dps, step_every_s, scale, rate_dep,
    /// g_sens_dps_per_mps2, noise_dps, vibration_noise_dps, vibration_bias_dps, lsb_dps,
    /// cut_lead_in (0/1), gyro_only (0/1), seed.
    #[arg(long, value_name = "KEY=VALUE")]
    pub(crate) error: Vec<String>,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum SimKindArg {
    Drive,
    Robot,
    Turntable,
    Static,
}
