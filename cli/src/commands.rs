//! One function per command: read the files, call core, print (text or `--json`).

use crate::input::{open_input, read_checked, read_log, read_logs, read_named, scored_logs, stem_of, time_order, Input};
use crate::{expand_recipes, fail, import_recipe, is_stdin, output, print_json, settings, shell_quoted, shown, write_stdout, Failure};
use gyrodrift::{battery, calibration, gyrodometry, hdr, tune, DriveLog};
use std::path::{Path, PathBuf};

/// Prints `value` as JSON, or the text table `text` makes.
fn emit<T: serde::Serialize>(json: bool, value: &T, text: impl FnOnce() -> String) -> Result<(), Failure> {
    if json {
        return print_json(value);
    }
    write_stdout(&text())
}

/// Writes a log to a file, or to stdout when no file is given.
fn write_log(log: &DriveLog, out: Option<&Path>) -> Result<(), Failure> {
    match out {
        Some(path) => {
            let f = std::fs::File::create(path).map_err(|e| Failure(format!("{}: cannot create: {}", path.display(), e)))?;
            log.write_csv(f).map_err(|e| fail(path, e))
        }
        None => log.write_csv(std::io::stdout().lock()).map_err(|e| Failure(format!("standard output: cannot write: {e}"))),
    }
}

/// Logs named by their `# name:` or file stem, as core's batch functions take them.
fn named(logs: &[(String, DriveLog)]) -> Vec<(String, &DriveLog)> {
    logs.iter().map(|(n, l)| (n.clone(), l)).collect()
}

/// Runs `one` on every part of a log and prints: one result as before; the parts of a
/// split log as a JSON array, or their tables one after another under their names.
fn per_part<T: serde::Serialize>(
    log: &Path,
    parts: &[DriveLog],
    json: bool,
    mut one: impl FnMut(usize, &DriveLog) -> gyrodrift::Result<T>,
    text: impl Fn(&T) -> String,
) -> Result<(), Failure> {
    let results = parts.iter().enumerate().map(|(i, p)| one(i, p).map_err(|e| fail(log, e))).collect::<Result<Vec<T>, _>>()?;
    per_log(parts, &results, json, |i| text(&results[i]))
}

/// Prints the results of a file's logs: one as before; several (`--joined split`) as a JSON
/// array, or their tables one after another under their names, as `per_part` prints parts.
fn per_log<T: serde::Serialize>(logs: &[DriveLog], results: &[T], json: bool, text: impl Fn(usize) -> String) -> Result<(), Failure> {
    match results {
        [only] => emit(json, only, || text(0)),
        all => emit(json, &all, || {
            let name = |p: &DriveLog| p.meta.name.clone().unwrap_or_default();
            logs.iter().enumerate().map(|(i, p)| format!("== {} ==\n{}", name(p), text(i))).collect::<Vec<_>>().join("\n")
        }),
    }
}

/// The trace file of part `i` (the second part of `t.csv` goes to `t.part2.csv`).
fn part_path(path: &Path, i: usize) -> PathBuf {
    if i == 0 {
        return path.to_path_buf();
    }
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let ext = path.extension().map(|e| format!(".{}", e.to_string_lossy())).unwrap_or_default();
    path.with_file_name(format!("{stem}.part{}{ext}", i + 1))
}

/// What `hdr` and `pipeline` print for a drive: its scores, or, for a drive without a
/// reference heading (no GPS course), why it is not scored and the estimator's own figures.
#[derive(serde::Serialize)]
#[serde(untagged)]
pub enum Outcome<R, S> {
    Scored(R),
    Unscored {
        not_scored: String,
        #[serde(flatten)]
        summary: S,
    },
}

/// A run's scores, or its summary where the drive has no reference to score against (any
/// other failure to score stays an error).
fn outcome<R, S>(drive: &DriveLog, result: gyrodrift::Result<R>, summary: S) -> gyrodrift::Result<Outcome<R, S>> {
    match result {
        Ok(r) => Ok(Outcome::Scored(r)),
        Err(e) if !drive.has_reference() => Ok(Outcome::Unscored { not_scored: e.to_string(), summary }),
        Err(e) => Err(e),
    }
}

pub fn hdr(log: &Path, resample: bool, set: &[String], json: bool, trace: Option<&Path>, input: Input) -> Result<(), Failure> {
    let opts = hdr::HdrOptions { resample, ..settings(set)? };
    let parts = read_checked(log, input, opts.bias_s)?;
    let mut trace_err = None;
    let mut one = |i: usize, drive: &DriveLog| {
        let run = hdr::run(drive, &opts)?;
        write_part(trace, i, &mut trace_err, |f| run.trace.write_csv(f));
        let summary = run.summary(drive.duration_min());
        outcome(drive, run.result, summary)
    };
    let printed = per_part(log, &parts, json, &mut one, |r| match r {
        Outcome::Scored(r) => output::hdr_table(log, &opts, r),
        Outcome::Unscored { not_scored, summary } => output::hdr_unscored(log, not_scored, summary, trace.is_some()),
    });
    trace_err.map_or(printed, Err)
}

/// `files`: the trace and the track CSV to write, if asked for.
pub fn pipeline(log: &Path, set: &[String], json: bool, files: [Option<&Path>; 2], input: Input) -> Result<(), Failure> {
    let params: gyrodrift::pipeline::PipelineParams = settings(set)?;
    let parts = read_checked(log, input, params.bias_s)?;
    let [trace, track] = files;
    let mut trace_err = None;
    let mut one = |i: usize, drive: &DriveLog| {
        let run = gyrodrift::pipeline::run(drive, &params)?;
        write_part(trace, i, &mut trace_err, |f| run.trace.write_csv(f));
        if track.is_some() {
            // Computed before the file is created: a log without a speed leaves no empty file.
            match gyrodrift::track::Tracks::of(drive, &params) {
                Ok(paths) => write_part(track, i, &mut trace_err, |f| paths.write_csv(f)),
                Err(e) => _ = trace_err.get_or_insert(fail(log, e)),
            }
        }
        let summary = run.summary(drive.duration_min());
        outcome(drive, run.result, summary)
    };
    let printed = per_part(log, &parts, json, &mut one, |r| match r {
        Outcome::Scored(r) => output::pipeline_table(log, r),
        Outcome::Unscored { not_scored, summary } => output::pipeline_unscored(log, not_scored, summary, trace.is_some()),
    });
    trace_err.map_or(printed, Err)
}

/// Writes part `i`'s file (a trace, a track) when one was asked for; the first failure is
/// kept in `err` (the results are still printed).
fn write_part(file: Option<&Path>, i: usize, err: &mut Option<Failure>, write: impl FnOnce(std::fs::File) -> gyrodrift::Result<()>) {
    let Some(path) = file.map(|f| part_path(f, i)) else { return };
    let written = std::fs::File::create(&path)
        .map_err(|e| Failure(format!("{}: cannot create: {}", path.display(), e)))
        .and_then(|f| write(f).map_err(|e| fail(&path, e)));
    if let Err(e) = written {
        err.get_or_insert(e);
    }
}

pub fn gyrodometry(log: &Path, set: &[String], json: bool, input: Input) -> Result<(), Failure> {
    let opts: gyrodometry::GyrodometryOptions = settings(set)?;
    let parts = read_checked(log, input, opts.bias_s)?;
    per_part(log, &parts, json, |_, d| gyrodometry::run(d, &opts).and_then(|r| r.result), |r| output::gyrodometry_table(log, r))
}

/// `calibrate`: the error model of a turntable session (of each, with `--joined split`).
pub fn calibrate(log: &Path, set: &[String], json: bool, input: Input) -> Result<(), Failure> {
    let opts: calibration::CalibrationOptions = settings(set)?;
    let sessions = read_named(log, input)?;
    let runs = sessions.iter().map(|d| calibration::run(d, &opts).map_err(|e| fail(log, e))).collect::<Result<Vec<_>, _>>()?;
    let results: Vec<_> = runs.iter().map(|r| &r.result).collect();
    per_log(&sessions, &results, json, |i| output::calibration_table(log, &runs[i]))
}

/// `report --compare`: every method side by side, HDR tuned on `tune_on` when given.
pub fn compare(files: &[PathBuf], set: &[String], json: bool, csv: bool, tune_on: &[PathBuf], input: Input) -> Result<(), Failure> {
    let params: gyrodrift::pipeline::PipelineParams = settings(set)?;
    let tuned = if tune_on.is_empty() {
        None
    } else {
        let train = scored_logs(tune_on, input, None)?;
        let prepared = tune::prepare_all(&named(&train), &hdr::HdrOptions::default()).map_err(|e| Failure(e.to_string()))?;
        Some(tune::tune(&prepared, &tune::TuneOptions::default()).map_err(|e| Failure(e.to_string()))?.recommended)
    };
    let logs = scored_logs(files, input, params.bias_s)?;
    let c = gyrodrift::compare::compare(&named(&logs), &params, tuned).map_err(|e| Failure(e.to_string()))?;
    if csv {
        return write_stdout(&c.to_csv());
    }
    emit(json, &c, || c.to_markdown())
}

/// The paper's Table II over the drives.
pub fn report(
    files: &[PathBuf],
    set: &[String],
    resample: bool,
    json: bool,
    markdown: bool,
    csv: bool,
    input: Input,
) -> Result<(), Failure> {
    let opts = hdr::HdrOptions { resample, ..settings(set)? };
    let logs = scored_logs(files, input, opts.bias_s)?;
    let report = gyrodrift::report::Report::build(&named(&logs), &opts).map_err(|e| Failure(e.to_string()))?;
    if csv {
        return write_stdout(&report.to_csv());
    }
    emit(json, &report, || if markdown { report.to_markdown() } else { report.to_text() })
}

pub fn tune(train: &[PathBuf], test: &[PathBuf], json: bool, markdown: bool, input: Input) -> Result<(), Failure> {
    let opts = hdr::HdrOptions::default();
    let prep = |paths: &[PathBuf]| -> Result<Vec<tune::PreparedDrive>, Failure> {
        tune::prepare_all(&named(&scored_logs(paths, input, opts.bias_s)?), &opts).map_err(|e| Failure(e.to_string()))
    };
    let (train_p, test_p) = (prep(train)?, prep(test)?);
    let rep = tune::tune_and_report(&train_p, &test_p, &tune::TuneOptions::default()).map_err(|e| Failure(e.to_string()))?;
    emit(json, &rep, || output::tune_text(&rep, markdown))
}

pub fn simulate(req: &gyrodrift::sim::SimRequest, out: Option<&Path>) -> Result<(), Failure> {
    let log = gyrodrift::sim::simulate(req).map_err(|e| Failure(e.to_string()))?;
    write_log(&log, out)
}

/// `inject`: the log with these gyro errors added to its yaw rate, as a v1 log.
pub fn inject(log: &Path, errors: &gyrodrift::sim::GyroErrors, out: Option<&Path>, input: Input) -> Result<(), Failure> {
    let drive = read_log(log, input)?;
    let with = gyrodrift::sim::inject(&drive, errors).map_err(|e| fail(log, e))?;
    write_log(&with, out)
}

/// Every shipped sample log under `out` (`realisation` > 0: the same set with other seeds).
pub fn samples(out: &Path, realisation: u64) -> Result<(), Failure> {
    for s in gyrodrift::sim::samples::SAMPLE_LOGS {
        let path = out.join(s.path);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(|e| Failure(format!("{}: {e}", dir.display())))?;
        }
        let log = gyrodrift::sim::simulate(&s.realisation(realisation)).map_err(|e| Failure(e.to_string()))?;
        write_log(&log, Some(&path))?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

/// The recorded drives `roads` measures: recipes, the user's own v1 logs, the input policy.
pub struct RoadsInput<'a> {
    pub recipes: &'a [PathBuf],
    pub logs: &'a [PathBuf],
    pub data: Option<&'a Path>,
    pub input: Input,
}

/// `roads`: road statistics of recorded drives (the shipped recipes' when none is given)
/// against the simulator's (issue 13); drives without a speed column are named and left out.
pub fn roads(given: RoadsInput, json: bool, plot: Option<&Path>) -> Result<(), Failure> {
    let shipped = [PathBuf::from("sample-logs/recipes")];
    let recipes = if given.recipes.is_empty() && given.logs.is_empty() { &shipped[..] } else { given.recipes };
    let mut logs = Vec::new();
    for r in expand_recipes(recipes)? {
        let (log, _) = import_recipe(&r, given.data, false)?;
        logs.push((r.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(), log));
    }
    logs.extend(read_logs(given.logs, given.input, None)?);
    let c = gyrodrift::sim::roads::compare(&named(&logs)).map_err(|e| Failure(e.to_string()))?;
    for name in &c.skipped {
        eprintln!("{name}: left out: no speed column, so no block is known to be moving");
    }
    if let Some(p) = plot {
        crate::roads_plot::draw(&c, p).map_err(Failure)?;
    }
    emit(json, &c, || c.to_markdown())
}

/// The battery's simulated drives: their length, and which draw of the scoring bases.
pub struct SimDraw {
    pub minutes: f64,
    pub draw: u64,
}

/// The recorded drives given to the battery: shipped-style recipes, the user's own v1 logs
/// (read, checked and split at gaps as every command reads a log), and the input policy.
pub struct BatteryInput<'a> {
    pub recipes: &'a [PathBuf],
    pub logs: &'a [PathBuf],
    pub data: Option<&'a Path>,
    pub input: Input,
}

/// The battery's bases: the recipes' drives (named by their recipe's stem), the logs given
/// (added bases, named by `# name:` or file stem) and the simulated drives.
fn battery_bases(given: BatteryInput, sim: SimDraw) -> Result<Vec<battery::Base>, Failure> {
    let SimDraw { minutes, draw } = sim;
    if !(minutes.is_finite() && minutes > 1.0 && minutes <= 600.0) {
        return Err(Failure(format!("--minutes {minutes}: expected a length in (1, 600] min")));
    }
    let mut bases = Vec::new();
    for r in expand_recipes(given.recipes)? {
        let (log, _) = import_recipe(&r, given.data, false)?;
        let stem = r.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        bases.push(battery::recorded_base(&stem, log));
    }
    for path in given.logs {
        for part in read_checked(path, given.input, None)? {
            let name = part.meta.name.clone().unwrap_or_default();
            bases.push(battery::added_base(&name, part).map_err(|e| fail(path, e))?);
        }
    }
    bases.extend(battery::simulated_bases_drawn(minutes, draw));
    Ok(bases)
}

/// One battery case's log ("BASE / PROFILE") to a file or stdout.
pub fn battery_case(given: BatteryInput, sim: SimDraw, case: &str, out: Option<&Path>) -> Result<(), Failure> {
    let bases = battery_bases(given, sim)?;
    let log = battery::case_log(&bases, &battery::profiles(), case).map_err(|e| Failure(e.to_string()))?;
    write_log(&log, out)
}

/// The robustness battery on the recipes' drives, the logs given and the simulated ones.
pub fn battery(given: BatteryInput, split: battery::Split, sim: SimDraw, cases: bool, set: &[String], json: bool) -> Result<(), Failure> {
    if !given.logs.is_empty() && split == battery::Split::Training {
        return Err(Failure("--logs with --split training: the drives you add are scoring bases, so none of their cases would run".into()));
    }
    let params: gyrodrift::pipeline::PipelineParams = settings(set)?;
    let bases = battery_bases(given, sim)?;
    let tuned = battery::tune_hdr(&bases).map_err(|e| Failure(e.to_string()))?;
    eprintln!(
        "HDR tuned on the {} training bases: cross-validated NE_psi {:.4} (Table III {:.4}) -> {}",
        bases.iter().filter(|b| b.training).count(),
        tuned.cv.as_ref().map_or(f64::NAN, |c| c.cv_tuned_deg_per_min),
        tuned.cv.as_ref().map_or(f64::NAN, |c| c.cv_table_iii_deg_per_min),
        if tuned.recommended_is_tuned { "tuned parameters used" } else { "Table III used (tuning does not generalise)" }
    );
    let peer = battery::TunedHdr::from_result(&tuned);
    let b = battery::run(&bases, &battery::profiles(), split, &params, Some(&peer)).map_err(|e| Failure(e.to_string()))?;
    emit(json, &b, || b.to_markdown(cases))
}

/// A recorded log by its recipe: the v1 log to a file or stdout, the summary to stderr (or
/// as JSON on stdout).
pub fn import(recipe: &Path, data: Option<&Path>, allow_outside: bool, out: Option<&Path>, json: bool) -> Result<(), Failure> {
    let (log, summary) = import_recipe(recipe, data, allow_outside)?;
    if out.is_some() || !json {
        write_log(&log, out)?;
    }
    if json {
        print_json(&summary)
    } else {
        eprintln!("{}", output::import_line(recipe, &summary));
        Ok(())
    }
}

/// Raw logger files by the detected preset: which preset and which file plays which part
/// on stderr, then as `import` (or the recipe as TOML with `print_recipe`).
pub fn import_detected(paths: &[PathBuf], print_recipe: bool, out: Option<&Path>, json: bool, input: Input) -> Result<(), Failure> {
    use gyrodrift::import;
    if let [one] = paths {
        // A drive log v1, unless its `time_s` holds date-times, which the draft reads.
        if is_drive_log_file(one) && !import::draft_reads(one, true) {
            return rewrite_drive_log(one, print_recipe, out, json, input);
        }
    }
    let (d, log, summary) = match import::import_paths(paths) {
        Ok(detected) => detected,
        Err(e) => return draft_instead(paths, print_recipe, e),
    };
    let parts: Vec<String> = d.used.iter().map(|(role, f)| format!("{role} = {f}")).collect();
    let mut note = format!("detected preset {} ({}): {}", d.preset, d.title, parts.join(", "));
    if !d.ignored.is_empty() {
        note += &format!("; not used: {}", d.ignored.join(", "));
    }
    eprintln!("{note}");
    // A recording given whole (its folder or zip): what the messages and the recipe name.
    let whole = match paths {
        [one] if one.is_dir() || import::starts_as_zip(one) => Some(one),
        _ => None,
    };
    if print_recipe {
        let text = gyrodrift::import::recipe_value_to_toml(&d.recipe_json).map_err(|e| Failure(e.to_string()))?;
        let data = whole.map_or_else(|| files_folder(paths), |w| shell_quoted(w));
        return write_stdout(&format!("# gyrodrift import --recipe THIS.toml --data {data} (preset {})\n{text}", d.preset));
    }
    if out.is_some() || !json {
        write_log(&log, out)?;
    }
    if json {
        let files: std::collections::BTreeMap<String, String> = d.used.iter().map(|(r, f)| (r.to_string(), f.clone())).collect();
        print_json(&serde_json::json!({ "preset": d.preset, "files": files, "summary": summary }))
    } else {
        // The line names what was given: the folder or zip, or the gyro's file among the files.
        let shown = whole.cloned().unwrap_or_else(|| PathBuf::from(&d.used[0].1));
        eprintln!("{}", output::import_line(&shown, &summary));
        Ok(())
    }
}

/// A file that is a drive log v1 already (gzipped or not, with commas or as a spreadsheet
/// saves it), by its head.
fn is_drive_log_file(path: &Path) -> bool {
    use std::io::Read;
    let Ok(f) = gyrodrift::log::file::open_log(path) else { return false };
    let mut head = Vec::new();
    f.take(gyrodrift::import::SNIFF_BYTES as u64).read_to_end(&mut head).is_ok()
        && gyrodrift::import::is_drive_log_head(&path.display().to_string(), &head)
}

/// `import` given a drive log v1: no preset to detect; the log is read (with `--time-order`)
/// and written as gyrodrift writes logs (commas, decimal points), so a log saved with `;`
/// and decimal commas becomes the format as written.
fn rewrite_drive_log(path: &Path, print_recipe: bool, out: Option<&Path>, json: bool, input: Input) -> Result<(), Failure> {
    if print_recipe {
        return Err(Failure(format!("{}: a drive log v1 already: it needs no recipe", path.display())));
    }
    let log = read_log(path, input)?;
    if out.is_some() || !json {
        write_log(&log, out)?;
    }
    if json {
        print_json(&serde_json::json!({ "preset": null, "drive_log": true, "rows": log.len(), "duration_min": log.duration_min() }))
    } else {
        let (p, n, min) = (path.display(), log.len(), log.duration_min());
        eprintln!("{p}: a drive log v1 already, {n} rows, {min:.1} min: written as gyrodrift writes logs");
        Ok(())
    }
}

/// Files no preset reads: with `--print-recipe` a draft recipe from their column names
/// (each guess listed as a comment to check), else the error with that hint.
fn draft_instead(paths: &[PathBuf], print_recipe: bool, e: gyrodrift::Error) -> Result<(), Failure> {
    let draft = match gyrodrift::import::draft_for_paths(paths) {
        Ok(Some(draft)) => draft,
        _ => return Err(Failure(e.to_string())),
    };
    if !print_recipe {
        return Err(Failure(format!("{e}; --print-recipe drafts one from the column names")));
    }
    let text = gyrodrift::import::recipe_value_to_toml(&draft.recipe_json).map_err(|e| Failure(e.to_string()))?;
    let data = match paths {
        [dir] if dir.is_dir() => shell_quoted(dir),
        _ => files_folder(paths),
    };
    let guesses: String = draft.guesses.iter().map(|g| format!("#   {g}\n")).collect();
    write_stdout(&format!(
        "# A draft from the column names (no logger preset reads these files): check each guess,\n\
         # then run gyrodrift import --recipe THIS.toml --data {data} and gyrodrift check on the log.\n\
         # Guessed:\n{guesses}{text}"
    ))
}

/// The folder the given files share, for the printed recipe's `--data` (quoted as the
/// import hints quote a path), else FOLDER.
fn files_folder(paths: &[PathBuf]) -> String {
    match paths {
        [first, rest @ ..] if rest.iter().all(|p| p.parent() == first.parent()) => match first.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => shell_quoted(dir),
            _ => ".".into(),
        },
        _ => "FOLDER".into(),
    }
}

/// `split`: each log joined in the file as a v1 log of its own, `STEM.K.csv` in `out_dir`
/// (the file's folder by default), a line each on stdout: where it starts, its rows and
/// length, and what reading it did. A file that reads as one log as it is (nothing joined,
/// nothing dropped) is said and nothing written.
pub fn split(path: &Path, out_dir: Option<&Path>) -> Result<(), Failure> {
    let dir = match out_dir {
        Some(d) => d.to_path_buf(),
        None if is_stdin(path) => return Err(Failure("split -: name the folder to write the logs to (--out-dir DIR)".into())),
        None => path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new(".")).to_path_buf(),
    };
    // Refused as the other commands refuse it, with the option that mends it (`--time-order
    // fix`, or the import's draft for a logger's own table).
    let logs = gyrodrift::log::accept::parse_joined(open_input(path)?, time_order()).map_err(|e| crate::input::read_failure(path, e))?;
    if let [(_, None, _)] = logs.as_slice() {
        return write_stdout(&format!("{}: one log, nothing joined on: nothing written\n", shown(path)));
    }
    std::fs::create_dir_all(&dir).map_err(|e| Failure(format!("{}: cannot create: {e}", dir.display())))?;
    let stem = stem_of(path);
    let mut text = Vec::new();
    for (k, (log, said, line)) in logs.iter().enumerate() {
        let out = dir.join(format!("{stem}.{}.csv", k + 1));
        write_log(log, Some(&out))?;
        let said = said.as_deref().map(|s| format!("; {s}")).unwrap_or_default();
        text.push(format!("{}: from line {line}, {} rows, {:.1} min{said}", out.display(), log.len(), log.duration_min()));
    }
    write_stdout(&(text.join("\n") + "\n"))
}

/// `allan`: the Allan deviation of a static log (of each, with `--joined split`).
pub fn allan(log: &Path, json: bool, input: Input) -> Result<(), Failure> {
    let logs = read_named(log, input)?;
    let runs = logs.iter().map(|d| gyrodrift::allan::run_with_confidence(d).map_err(|e| fail(log, e))).collect::<Result<Vec<_>, _>>()?;
    // --json as the bindings give it: the Result keys, and the band under `confidence`.
    let with: Vec<_> = runs.iter().map(|(result, confidence)| gyrodrift::allan::AllanWithConfidence { result, confidence }).collect();
    per_log(&logs, &with, json, |i| output::allan_table(log, &runs[i].0, &runs[i].1))
}

/// `check`: each log's findings, text or JSON (one log: its report; several: a list, each
/// with its `file`); exit 1 when one is an error (the log would give wrong results), so a
/// pipeline can stop on it. A file that cannot be read is said on stderr and the rest are
/// checked, then exit 2. With `--joined split` each log of a file of several is checked,
/// labelled "FILE (log k of n)".
pub fn check(paths: &[PathBuf], json: bool, input: Input) -> Result<(), Failure> {
    let (mut reports, mut unread) = (Vec::new(), Vec::new());
    for path in paths {
        match crate::input::read_all(path, input) {
            Ok(logs) => {
                let n = logs.len();
                for (k, drive) in logs.into_iter().enumerate() {
                    let label = if n > 1 { format!("{} (log {} of {n})", shown(path), k + 1) } else { shown(path) };
                    reports.push((label, gyrodrift::check::check(&drive)));
                }
            }
            Err(Failure(m)) if paths.len() > 1 => {
                eprintln!("{m}");
                unread.push(shown(path));
            }
            Err(f) => return Err(f),
        }
    }
    let text = || reports.iter().map(|(label, r)| format!("{label}: {}", r.to_text())).collect::<Vec<_>>().join("");
    match &reports[..] {
        [(_, r)] if paths.len() == 1 => emit(json, r, text)?,
        _ => {
            let listed: Vec<serde_json::Value> =
                reports.iter().map(|(label, r)| serde_json::json!({ "file": label, "report": r })).collect();
            emit(json, &listed, text)?
        }
    }
    if !unread.is_empty() {
        return Err(Failure(format!("{} of {} files could not be read: {}", unread.len(), paths.len(), unread.join(", "))));
    }
    if reports.iter().any(|(_, r)| r.findings.iter().any(|f| f.severity == gyrodrift::check::Severity::Error)) {
        std::process::exit(1);
    }
    Ok(())
}
