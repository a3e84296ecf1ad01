//! `gyrodrift`: the command-line front of the gyrodrift core. It reads files, parses
//! options, calls core and prints; every number comes from core.

mod args;
mod batch;
mod commands;
mod input;
mod oom;
mod output;
mod parquet_out;
mod roads_plot;

#[global_allocator]
static ALLOC: oom::Graceful = oom::Graceful;

use args::*;
use clap::Parser;
use gyrodrift::log::accept::{JoinedLogs, TimeOrder};
use gyrodrift::sim::{GyroErrors, SimKind, SimRequest};
use gyrodrift::{battery, DriveLog, Error};
use input::TIME_ORDER;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// An error for the user: `file: message`, exit code 2.
struct Failure(String);

fn fail(path: &Path, e: Error) -> Failure {
    Failure(format!("{}: {}", shown(path), e))
}

/// `-` given for a log: the log on standard input (`gyrodrift import drive.zip | gyrodrift
/// pipeline -`), as the commands write theirs to standard output.
fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// A log's path as messages name it ("standard input" for `-`).
fn shown(path: &Path) -> String {
    if is_stdin(path) {
        "standard input".into()
    } else {
        path.display().to_string()
    }
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
    let files: Vec<String> = h.files.iter().map(|p| shell_quoted(p)).collect();
    format!(
        "it looks like {what} of {} (import preset {}): `gyrodrift import {} --out drive.csv` makes a v1 drive log of it",
        h.title,
        h.preset,
        files.join(" ")
    )
}

/// A path as a shell command names it: in single quotes when it has a space.
fn shell_quoted(p: &Path) -> String {
    match p.display().to_string() {
        s if s.contains(char::is_whitespace) => format!("'{s}'"),
        s => s,
    }
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
    let time_order = match cli.time_order {
        TimeOrderArg::Error => TimeOrder::Error,
        TimeOrderArg::Fix => TimeOrder::Fix,
    };
    let _ = TIME_ORDER.set(time_order);
    let joined = match cli.joined {
        JoinedArg::Error => JoinedLogs::Error,
        JoinedArg::Split => JoinedLogs::Split,
    };
    let input = input::Input { gaps, ignore_check: cli.ignore_check, time_order, joined };
    match cli.cmd {
        Cmd::Hdr { log, no_resample, set, json, trace } => c::hdr(&log, !no_resample, &set, json, trace.as_deref(), input),
        Cmd::Pipeline { log, set, json, trace, track } => c::pipeline(&log, &set, json, [trace.as_deref(), track.as_deref()], input),
        Cmd::Gyrodometry { log, set, json } => c::gyrodometry(&log, &set, json, input),
        Cmd::Calibrate { log, set, json } => c::calibrate(&log, &set, json, input),
        Cmd::Report { batch: BatchArgs { dir: Some(dir), jobs, out, import, recipe, fail_on_error }, set, json, .. }
        | Cmd::Compare { batch: BatchArgs { dir: Some(dir), jobs, out, import, recipe, fail_on_error }, set, json, .. } => {
            let opts = gyrodrift::fleet::FleetOptions { input, pipeline: settings(&set)? };
            let recipe = recipe.map(|r| gyrodrift::import::read_recipe(&r)).transpose().map_err(|e| Failure(e.to_string()))?;
            batch::run(&dir, batch::Batch { jobs, out: out.as_deref(), import, recipe: recipe.as_ref(), fail_on_error }, &opts, json)
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
            Some(errors) => c::inject(&log, &errors, out.as_deref(), input),
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
            None => c::import_detected(&files, print_recipe, out.as_deref(), json, input),
        },
        Cmd::Allan { log, json } => c::allan(&log, json, input),
        Cmd::Check { logs, json } => c::check(&logs, json, input),
        Cmd::Split { log, out_dir } => c::split(&log, out_dir.as_deref()),
        Cmd::Roads { recipes, logs, data, json, plot } => {
            c::roads(c::RoadsInput { recipes: &recipes, logs: &logs, data: data.as_deref(), input }, json, plot.as_deref())
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
