//! How the commands read their logs: standard input or a file (gzip-compressed too), by
//! the time-order and joined-logs policies, a refusal naming the option or command that
//! reads the log; and the checked parts each scoring command runs on (core's `accept`).

use crate::{fail, hint_text, import_hint, is_stdin, shell_quoted, shown, Failure};
use gyrodrift::log::accept::{accept, stem_in_file, InputPolicy, Refusal, TimeOrder};
use gyrodrift::{DriveLog, Error};
use std::path::{Path, PathBuf};

/// The `--time-order` policy every log is read by (set once, before any is read).
pub(crate) static TIME_ORDER: std::sync::OnceLock<TimeOrder> = std::sync::OnceLock::new();

/// The `--time-order` policy.
pub(crate) fn time_order() -> TimeOrder {
    TIME_ORDER.get().copied().unwrap_or_default()
}

/// Every log of a file by the input policy (core's `parse_by_policy`): one, or with
/// `--joined split` each log joined on; what reading each did is said on stderr, and a
/// refusal names the option or command that reads the log (or the import, for a logger's
/// export).
pub(crate) fn read_all(path: &Path, input: InputPolicy) -> Result<Vec<DriveLog>, Failure> {
    let logs = gyrodrift::log::accept::parse_by_policy(open_input(path)?, input).map_err(|e| {
        let mut f = read_failure(path, e);
        if let Some(hint) = import_hint(path).filter(|_| !is_stdin(path)) {
            f.0 += &format!("; {hint}");
        }
        f
    })?;
    let said = |(log, s): (DriveLog, Option<String>)| {
        if let Some(s) = s {
            eprintln!("{}: {s}", shown(path));
        }
        log
    };
    Ok(logs.into_iter().map(said).collect())
}

/// A log's refusal with the option or command that reads it: `--time-order fix` for a time
/// that repeats, `split` for logs joined on or a clock reset, the import's draft for a
/// logger's own table.
pub(crate) fn read_failure(path: &Path, e: Error) -> Failure {
    let refusal = Refusal::of(&e);
    let out_of_order = refusal == Some(Refusal::TimeOrder);
    let reset = refusal == Some(Refusal::ClockReset);
    let joined = refusal == Some(Refusal::Joined) || reset;
    let drafted = !out_of_order && !joined && !is_stdin(path) && gyrodrift::import::draft_reads_refused(path, &e);
    let mut f = fail(path, e);
    if joined {
        let out = if is_stdin(path) { " --out-dir DIR" } else { "" };
        let p = shell_quoted(path);
        let each = if reset { "each part (a logger restarted?)" } else { "each log in it" };
        f.0 += &format!("; `gyrodrift split {p}{out}` writes {each} as a file of its own (the scoring commands take `--joined split`)");
    } else if out_of_order {
        f.0 += "; `--time-order fix` merges repeated times and sorts rows up to 1 s late in";
    } else if drafted {
        // A logger's own table (time in ms, date-times, another name): the import reads it.
        let p = shell_quoted(path);
        f.0 += &format!("; if it is a logger's table, `gyrodrift import {p} --print-recipe` drafts a recipe from its column names");
    }
    f
}

/// The one log of a file, by the `--time-order` policy, for a command that writes one log
/// (`inject`, `import`): a file of several joined on refused, with `--joined split` too,
/// naming the command that writes each.
pub(crate) fn read_log(path: &Path, input: InputPolicy) -> Result<DriveLog, Failure> {
    let mut logs = read_all(path, input)?;
    if logs.len() > 1 {
        let p = shell_quoted(path);
        return Err(Failure(format!(
            "{}: {} logs joined in the file; this command writes one log: `gyrodrift split {p}` writes each as a file of its own",
            shown(path),
            logs.len()
        )));
    }
    logs.pop().ok_or_else(|| Failure(format!("{}: no log", shown(path))))
}

/// Every log of a file as `read_all` gives them, an unnamed one named by the file's stem (and
/// its number, for a file of several read with `--joined split`): for the commands that take
/// a log as it is (no check, no gap split), such as `allan` and `calibrate`.
pub(crate) fn read_named(path: &Path, input: InputPolicy) -> Result<Vec<DriveLog>, Failure> {
    let mut logs = read_all(path, input)?;
    let (stem, n) = (stem_of(path), logs.len());
    for (k, log) in logs.iter_mut().enumerate() {
        log.meta.name.get_or_insert_with(|| stem_in_file(&stem, k, n));
    }
    Ok(logs)
}

/// A log file's bytes as the commands read them: standard input for `-` (once), a
/// gzip-compressed file as the plain one; a folder is answered with what reads it.
pub(crate) fn open_input(path: &Path) -> Result<Box<dyn std::io::Read>, Failure> {
    if is_stdin(path) {
        // Standard input can be read once: `-` given twice would be an empty second log.
        static READ: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);
        if READ.swap(true, std::sync::atomic::Ordering::SeqCst) {
            return Err(Failure("-: standard input is given twice; it can be read once".into()));
        }
        let stdin = gyrodrift::log::file::decompressed(std::io::BufReader::new(std::io::stdin()));
        return Ok(Box::new(stdin.map_err(|e| fail(path, Error::from(e)))?));
    }
    if path.is_dir() {
        let what = match gyrodrift::import::folder_hint(path) {
            Some(h) => hint_text(&h, "a recording"),
            None => format!("to score every log in it: `gyrodrift report --dir {}`", path.display()),
        };
        return Err(Failure(format!("{}: a folder, not a log file; {what}", path.display())));
    }
    if is_parquet(path) {
        return Err(Failure(format!(
            "{}: a Parquet file, not a CSV log: Python's `gyrodrift.read_log` reads one drive's Parquet file, `python -m gyrodrift.fleet` a dataset of them",
            path.display()
        )));
    }
    // A gzip-compressed log (drive.csv.gz) reads as the plain file.
    let file = gyrodrift::log::file::open_log(path).map_err(|e| Failure(format!("{}: cannot open: {}", path.display(), e)))?;
    Ok(Box::new(file))
}

/// Whether the file starts as a Parquet file does (`PAR1`), which core names only as binary.
fn is_parquet(path: &Path) -> bool {
    let mut head = [0u8; 4];
    std::fs::File::open(path).and_then(|mut f| std::io::Read::read_exact(&mut f, &mut head)).is_ok() && &head == b"PAR1"
}

/// What names a log read from `path` that has no `# name:`: the file's stem ("stdin" for `-`).
pub(crate) fn stem_of(path: &Path) -> String {
    if is_stdin(path) {
        "stdin".to_string()
    } else {
        gyrodrift::log::file::log_stem(path)
    }
}

/// How the commands take their input logs: the gap policy, and whether a log `check` finds
/// an error in (a unit or sign mistake) is refused (the default) or run anyway.
pub(crate) type Input = InputPolicy;

/// Reads a log and takes it as core's `accept` does: what `check` finds is printed to
/// stderr (a line each), a log with a check error is refused unless `--ignore-check`, and
/// the gap policy gives the parts to score, each a drive of its own, named by `# name:` or
/// the file stem; the split is said on stderr.
/// With `--joined split`, each log of a file of several joined on, an unnamed one named by
/// the stem and its number.
pub(crate) fn read_checked(path: &Path, input: Input, bias_s: Option<f64>) -> Result<Vec<DriveLog>, Failure> {
    let logs = read_all(path, input)?;
    let (stem, n) = (stem_of(path), logs.len());
    let mut parts = Vec::new();
    for (k, drive) in logs.into_iter().enumerate() {
        let a = accept(drive, &stem_in_file(&stem, k, n), input, bias_s).map_err(|e| fail(path, e))?;
        for line in a.warnings.iter().chain(&a.split) {
            eprintln!("{}: {line}", shown(path));
        }
        parts.extend(a.parts);
    }
    Ok(parts)
}

/// Reads many logs (checked and split as `read_checked`), with their names.
pub(crate) fn read_logs(paths: &[PathBuf], input: Input, bias_s: Option<f64>) -> Result<Vec<(String, DriveLog)>, Failure> {
    let mut out = Vec::new();
    for p in paths {
        for part in read_checked(p, input, bias_s)? {
            out.push((part.meta.name.clone().unwrap_or_default(), part));
        }
    }
    Ok(out)
}

/// The logs a table scores: those with a reference heading. A drive without one is named on
/// stderr and left out, as the dashboard's Report leaves it out (its heading is `pipeline`'s
/// and `hdr`'s unscored summary); none left is an error.
pub(crate) fn scored_logs(paths: &[PathBuf], input: Input, bias_s: Option<f64>) -> Result<Vec<(String, DriveLog)>, Failure> {
    let mut logs = read_logs(paths, input, bias_s)?;
    let n = logs.len();
    logs.retain(|(name, log)| {
        let keep = log.has_reference();
        if !keep {
            eprintln!("{name}: not scored: no reference heading (ref_heading_deg absent or empty)");
        }
        keep
    });
    if logs.is_empty() && n > 0 {
        return Err(Failure("no drive has a reference heading to score against".into()));
    }
    Ok(logs)
}
