//! `report --dir DIR`: every `*.csv` log under a folder (recursive), scored in parallel
//! (rayon, `--jobs N`) with a progress bar on a terminal. Each drive is a row of core's
//! `fleet` (a file that fails is a row with its error; the rest go on); the rows go to
//! `--out` (Parquet, CSV or JSON by extension), the fleet's Table II to stdout. With
//! `--import`, a logger's raw exports among them are imported and scored, a drive per
//! recording (core's `import::recordings`); with `--recipe`, the files one recipe reads
//! (`import::recipe_recordings`).

use crate::{print_json, write_stdout, Failure};
use gyrodrift::fleet::{self, DriveRow, FleetOptions};
use gyrodrift::import::Recipe;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// At most this many folders of failed files are looked at for an import hint.
const MAX_HINT_FOLDERS: usize = 20;

/// Every `*.csv` and `*.csv.gz` file under `dir` (and `*.zip`, a logger's zipped export,
/// with `zips`; files ending as a recipe's tables do, with `recipe`), sorted, links
/// followed; unreadable entries are errors.
pub fn collect_logs(dir: &Path, zips: bool, recipe: Option<&Recipe>) -> Result<Vec<PathBuf>, Failure> {
    let ends = recipe.map(Recipe::file_endings).unwrap_or_default();
    if !dir.is_dir() {
        return Err(Failure(format!("{}: not a folder", dir.display())));
    }
    let mut files = Vec::new();
    for entry in walkdir::WalkDir::new(dir).follow_links(true) {
        let e = entry.map_err(|e| Failure(format!("{}: {e}", dir.display())))?;
        let name = e.file_name().to_string_lossy().to_ascii_lowercase();
        let is_csv = name.ends_with(".csv")
            || name.ends_with(".csv.gz")
            || zips && name.ends_with(".zip")
            || ends.iter().any(|x| name.ends_with(x.as_str()));
        if e.file_type().is_file() && is_csv {
            files.push(e.into_path());
        }
    }
    files.sort();
    if files.is_empty() {
        return Err(Failure(format!("{}: no *.csv logs in this folder or below", dir.display())));
    }
    Ok(files)
}

/// One file's rows: opened here, read and scored by core.
fn score_file(path: &Path, opts: &FleetOptions) -> Vec<DriveRow> {
    fleet::score_opened(path, gyrodrift::log::file::open_log(path), opts)
}

/// How the folder is scored: threads, where the rows go, whether raw exports are imported.
pub struct Batch<'a> {
    pub jobs: usize,
    pub out: Option<&'a Path>,
    pub import: bool,
    /// Files that are not v1 logs are read by this recipe (`--recipe`).
    pub recipe: Option<&'a Recipe>,
    /// Exit 1 when a file could not be scored (`--fail-on-error`).
    pub fail_on_error: bool,
}

/// Scores the files on `jobs` threads (0 = one per core), in file order.
pub fn score_files(files: &[PathBuf], jobs: usize, opts: &FleetOptions) -> Result<Vec<DriveRow>, Failure> {
    score_units(files, jobs, |p| score_file(p, opts))
}

/// Scores each unit (a file, a recording) on `jobs` threads, in order, with a progress bar.
fn score_units<T: Sync>(units: &[T], jobs: usize, score: impl Fn(&T) -> Vec<DriveRow> + Sync) -> Result<Vec<DriveRow>, Failure> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(jobs).build().map_err(|e| Failure(format!("--jobs {jobs}: {e}")))?;
    let bar = indicatif::ProgressBar::new(units.len() as u64).with_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} logs, {elapsed} elapsed, about {eta} left")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let rows: Vec<Vec<DriveRow>> = pool.install(|| {
        units
            .par_iter()
            .map(|p| {
                let r = score(p);
                bar.inc(1);
                r
            })
            .collect()
    });
    bar.finish_and_clear();
    Ok(rows.into_iter().flatten().collect())
}

/// Writes the rows by the file's extension: .parquet, .csv or .json.
fn write_rows(out: &Path, rows: &[DriveRow]) -> Result<(), Failure> {
    let ext = out.extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    let create = || std::fs::File::create(out).map_err(|e| Failure(format!("{}: cannot create: {e}", out.display())));
    let written = match ext.as_str() {
        "parquet" => crate::parquet_out::write(create()?, rows).map_err(|e| e.to_string()),
        "csv" => std::fs::write(out, fleet::rows_to_csv(rows)).map_err(|e| e.to_string()),
        "json" => serde_json::to_writer(std::io::BufWriter::new(create()?), rows).map_err(|e| e.to_string()),
        _ => return Err(Failure(format!("{}: --out takes a .parquet, .csv or .json file", out.display()))),
    };
    written.map_err(|e| Failure(format!("{}: cannot write: {e}", out.display())))
}

/// For the error rows another reading mends (core's refusal kinds, counted by the
/// summary), the option that reads them, once: a front's words for core's `InputPolicy`.
fn refusal_hints(summary: &fleet::FleetSummary, batch: &Batch) -> Vec<String> {
    use fleet::{ForeignReading, Remedy};
    let reading = ForeignReading::of(batch.import, batch.recipe.is_some());
    const PRESETS: &str = "`--import` reads the exports of the loggers it knows (SensorLog, Sensor Logger, phyphox, comma2k19, PX4, ROS)";
    const CHECK: &str = "`gyrodrift check FILE` names each fix (`--ignore-check` runs them anyway, with absurd figures)";
    let own = " reads a logger of your own (sample-logs/recipes/README.md; `gyrodrift import FILE --print-recipe` drafts one from its column names)";
    let by = |remedy: Remedy| match remedy {
        Remedy::TimeOrderFix => "`--time-order fix` puts it in order".to_string(),
        Remedy::JoinedSplit => "`--joined split` scores each log as a drive of its own".to_string(),
        Remedy::CheckEach => CHECK.to_string(),
        Remedy::ImportOrRecipe => format!("{PRESETS}; `--recipe R`: a recipe{own}"),
        Remedy::Recipe => format!("`--recipe R`: a recipe{own}"),
        Remedy::OtherRecipe => format!("another recipe{own}"),
    };
    fleet::refusal_hints(&summary.errors_by_code, reading).into_iter().map(|h| format!("{}: {}", h.said, by(h.remedy))).collect()
}

/// `report --dir`: scores every log under `dir`; prints the summary (Markdown or JSON) and
/// each error row's message on stderr; writes the rows to `out`. Files that failed are rows,
/// not a failed command (exit 0): a fleet job keeps what it could score; with
/// `fail_on_error` (a CI job) they make it exit 1 once everything is written.
pub fn run(dir: &Path, batch: Batch, opts: &FleetOptions, json: bool) -> Result<(), Failure> {
    let files = collect_logs(dir, batch.import, batch.recipe)?;
    let mut rows = score_files(&files, batch.jobs, opts)?;
    if batch.import || batch.recipe.is_some() {
        // The raw exports among the failed files: each recording's files leave the error
        // rows, and the recording is scored as a drive of its own.
        let recs = fleet::take_recordings(&mut rows, batch.recipe);
        let n_files: usize = recs.iter().map(|r| r.files.len() + r.ignored.len()).sum();
        let by = if batch.recipe.is_some() { "by the recipe" } else { "of raw exports" };
        eprintln!("importing {} recording(s) {by} ({n_files} files)", recs.len());
        rows.extend(score_units(&recs, batch.jobs, |r| fleet::score_recording(r, batch.recipe, opts))?);
    }
    if let Some(out) = batch.out {
        write_rows(out, &rows)?;
    }
    for r in rows.iter().filter(|r| r.error.is_some()) {
        eprintln!("{}: {}", r.file, r.error.as_deref().unwrap_or_default());
    }
    // Folders of a logger's raw exports: the import that makes v1 logs of them, once each.
    let failed: Vec<PathBuf> = rows.iter().filter(|r| r.error.is_some()).map(|r| PathBuf::from(&r.file)).collect();
    for h in gyrodrift::import::folder_hints(&failed, MAX_HINT_FOLDERS) {
        let or = if batch.import { "" } else { "; or give report --dir --import, which imports such recordings itself" };
        eprintln!("{}: {}{or}", h.folder.display(), crate::hint_text(&h, "a recording"));
    }
    let summary = fleet::summarize(&rows);
    for line in refusal_hints(&summary, &batch) {
        eprintln!("{line}");
    }
    if json {
        print_json(&summary)?;
    } else {
        write_stdout(&summary.to_markdown())?;
    }
    let failed = rows.iter().filter(|r| r.error.is_some()).count();
    if batch.fail_on_error && failed > 0 {
        eprintln!("{failed} of {} rows are errors (--fail-on-error)", rows.len());
        std::process::exit(1);
    }
    Ok(())
}
