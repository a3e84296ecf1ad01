//! A file given where a v1 drive log was expected that is a logger's raw export one of the
//! presets reads: which preset, and which files (it and those beside it in its folder) to
//! import, so a front can answer the parse error with the import that makes a v1 log of it.

use super::{detect, sniff, ImportSummary, Recipe, Sniffed, SNIFF_BYTES};
use crate::error::{Error, Result};
use crate::log::DriveLog;
use std::io::Read;
use std::path::{Path, PathBuf};

/// The preset that reads a raw export, and the files to give it.
#[derive(Debug, Clone, PartialEq)]
pub struct ImportHint {
    pub preset: &'static str,
    pub title: &'static str,
    /// The folder of the recording.
    pub folder: PathBuf,
    /// The file given and those beside it that the preset uses, in the preset's order.
    pub files: Vec<PathBuf>,
}

/// A file the v1 parser refused for its time column (`e`: no column named `time_s`, or a
/// `time_s` cell that is not a number) whose table the import's draft reads: a logger's own
/// table (time in ms, date-times), for which a front names the draft (`gyrodrift import
/// FILE --print-recipe`). For a `time_s` cell only when the draft reads that time as a date
/// or time of day, so a v1 log with one bad time further down gets no such hint.
pub fn draft_reads_refused(path: &Path, e: &Error) -> bool {
    let e = match e {
        Error::In { source, .. } => source.as_ref(),
        e => e,
    };
    match e {
        Error::Line { .. } if crate::log::accept::Refusal::of(e) == Some(crate::log::accept::Refusal::Foreign) => draft_reads(path, false),
        Error::Cell { .. } if crate::log::is_bad_time_cell(e) => draft_reads(path, true),
        _ => false,
    }
}

/// Whether the import's draft reads the file (no preset does); with `dates`, only when it
/// reads the file's time as a date or time of day (a `time_s` of date-times).
pub fn draft_reads(path: &Path, dates: bool) -> bool {
    match super::draft_for_paths(&[path.to_path_buf()]) {
        Ok(Some(d)) => !dates || d.recipe_json["table"][0]["time"].get("format").is_some(),
        _ => false,
    }
}

/// The head of a file: its first `SNIFF_BYTES`, what detection and drafts read.
pub(super) fn read_head(p: &Path) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    std::fs::File::open(p)?.take(SNIFF_BYTES as u64).read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// The head of a file, sniffed (None when it cannot be read or is not a table).
fn head(p: &Path) -> Option<Sniffed> {
    sniff(&p.file_name()?.to_string_lossy(), &read_head(p).ok()?).ok()
}

/// The folders of `files`, each once, in the order they first appear.
fn folders_of(files: &[PathBuf]) -> Vec<&Path> {
    let mut folders: Vec<&Path> = Vec::new();
    for p in files {
        let dir = folder_of(p);
        if !folders.contains(&dir) {
            folders.push(dir);
        }
    }
    folders
}

/// A head with a `time_s` column: a v1 log (broken, when it failed to read), not a raw export.
fn names_time_s(h: &Sniffed) -> bool {
    h.header.iter().any(|c| c == "time_s")
}

/// The folder a file is in ("." for a bare name).
fn folder_of(path: &Path) -> &Path {
    path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

/// The files of a folder, sorted, hidden ones (`.DS_Store`) left out (None when it cannot
/// be read).
pub(super) fn files_in(dir: &Path) -> Option<Vec<PathBuf>> {
    let visible = |p: &PathBuf| p.is_file() && !p.file_name().is_some_and(|n| n.to_string_lossy().starts_with('.'));
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir).ok()?.filter_map(|e| e.ok().map(|e| e.path())).filter(visible).collect();
    files.sort();
    Some(files)
}

/// The folders in `dir` (sorted, hidden ones left out): where a folder of recordings keeps
/// each of its recordings.
pub(super) fn folders_in(dir: &Path) -> Vec<String> {
    let visible = |p: &PathBuf| p.is_dir() && !p.file_name().is_some_and(|n| n.to_string_lossy().starts_with('.'));
    let Ok(entries) = std::fs::read_dir(dir) else { return Vec::new() };
    let mut names: Vec<String> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(visible)
        .filter_map(|p| Some(p.file_name()?.to_string_lossy().into_owned()))
        .collect();
    names.sort();
    names
}

/// For files that failed to read as v1 logs (a fleet folder of a logger's raw exports): one
/// hint per folder whose files a preset reads, in the order the folders first appear, at
/// most `max_folders` folders looked at (each reads the heads of at most 64 files).
pub fn folder_hints(failed: &[PathBuf], max_folders: usize) -> Vec<ImportHint> {
    let mut folders = folders_of(failed);
    folders.truncate(max_folders);
    folders.into_iter().filter_map(folder_hint).collect()
}

/// For a folder given where a log was expected: the preset that reads the files in it (at
/// most 64 looked at), when one does and none of them is a v1 log; else None.
pub fn folder_hint(dir: &Path) -> Option<ImportHint> {
    let sniffed: Vec<Sniffed> = files_in(dir)?.iter().take(64).filter_map(|p| head(p)).collect();
    if sniffed.iter().any(names_time_s) {
        return None;
    }
    hint(dir, &sniffed)
}

/// One recording of a logger's raw export in a fleet folder: the files a preset reads
/// together, named by the file (an export of one file) or the folder (of several).
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    pub preset: &'static str,
    pub label: PathBuf,
    /// The files the preset uses, in its order.
    pub files: Vec<PathBuf>,
    /// Files of the recording's folder the preset does not use (a Sensor Logger folder's
    /// accelerometer and metadata files): part of it, not logs that failed.
    pub ignored: Vec<PathBuf>,
}

/// The recordings among files that failed to read as v1 logs (`report --dir --import`),
/// folder by folder in the order they first appear: in each, the preset detected from its
/// failed files takes the files it uses as one recording, again on the files left, until
/// none is detected (a Sensor Logger folder is one recording of three files, a folder of
/// SensorLog exports one per file). A recording of one file is named by it, of several by
/// the folder, which also takes the folder's files no preset read (`ignored`). Other files
/// are left out.
pub fn recordings(failed: &[PathBuf]) -> Vec<Recording> {
    let folders = folders_of(failed);
    let mut out = Vec::new();
    for dir in folders {
        // A zipped recording is one of its own (`import_paths` unzips it).
        for p in failed.iter().filter(|p| folder_of(p) == dir && super::starts_as_zip(p)) {
            if let Some(h) = zip_hint(p) {
                out.push(Recording { preset: h.preset, label: p.clone(), files: h.files, ignored: Vec::new() });
            }
        }
        let mut left: Vec<(&PathBuf, Sniffed)> = failed
            .iter()
            .filter(|p| folder_of(p) == dir)
            .filter_map(|p| head(p).map(|h| (p, h)))
            .filter(|(_, h)| !names_time_s(h))
            .collect();
        while !left.is_empty() {
            let heads: Vec<Sniffed> = left.iter().map(|(_, h)| h.clone()).collect();
            let Ok(d) = detect(&heads) else { break };
            let used: Vec<&str> = d.used.iter().map(|(_, f)| f.as_str()).collect();
            let files: Vec<PathBuf> = used.iter().map(|f| dir.join(f)).collect();
            let label = match files.as_slice() {
                [one] => one.clone(),
                _ => dir.to_path_buf(),
            };
            let before = left.len();
            left.retain(|(p, _)| !p.file_name().is_some_and(|n| used.contains(&n.to_string_lossy().as_ref())));
            if left.len() == before {
                break; // a detection that uses none of them (never expected): no endless loop
            }
            out.push(Recording { preset: d.preset, label, files, ignored: Vec::new() });
        }
        if let Some(r) =
            out.iter_mut().rev().take_while(|r| r.files.first().is_some_and(|f| folder_of(f) == dir)).find(|r| r.files.len() > 1)
        {
            r.ignored = left.into_iter().map(|(p, _)| p.clone()).collect();
        }
    }
    out
}

/// The recordings one recipe reads among files that failed to read as v1 logs (`report
/// --dir --recipe`, a fleet of one logger no preset knows), folder by folder in the order
/// they first appear, of the files that end as the recipe's tables do and are not broken v1
/// logs (a `time_s` column: their own error stands): for a recipe of one table, each such
/// file, whatever its name, named by it; for a recipe of several, a folder holding every file
/// the recipe names (by its path in the folder, or by its name alone: `in_folder`), named by
/// the folder, its other such files part of it (`ignored`). Other files are left out.
pub fn recipe_recordings(failed: &[PathBuf], recipe: &Recipe) -> Vec<Recording> {
    let folders = folders_of(failed);
    let endings = recipe.file_endings();
    let ends_so = |p: &Path| {
        let name = p.file_name().map(|n| n.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
        endings.is_empty() || endings.iter().any(|e| name.ends_with(e.as_str()))
    };
    let broken_v1 = |p: &Path| head(p).is_some_and(|h| names_time_s(&h));
    let mut out = Vec::new();
    for dir in folders {
        let own: Vec<&PathBuf> = failed.iter().filter(|p| folder_of(p) == dir && ends_so(p) && !broken_v1(p)).collect();
        if recipe.tables.len() == 1 {
            out.extend(own.into_iter().map(|p| Recording {
                preset: "recipe",
                label: p.clone(),
                files: vec![p.clone()],
                ignored: Vec::new(),
            }));
            continue;
        }
        let named: Vec<PathBuf> = recipe.tables.iter().map(|t| in_folder(dir, &t.file)).collect();
        if !named.is_empty() && named.iter().all(|f| f.is_file()) {
            let ignored = own.into_iter().filter(|p| !named.contains(p)).cloned().collect();
            out.push(Recording { preset: "recipe", label: dir.to_path_buf(), files: named, ignored });
        }
    }
    out
}

/// Where a recipe's `file` is in a recording's folder: as named, or, where that is no file,
/// by its name alone (a recipe written for one recording under its data root, `trial02/CAR.csv`,
/// reads every folder holding a `CAR.csv`).
fn in_folder(dir: &Path, file: &str) -> PathBuf {
    let named = dir.join(file);
    match Path::new(file).file_name() {
        Some(name) if !named.is_file() => dir.join(name),
        _ => named,
    }
}

/// A recording read by `recipe`: its files from their folder, a recipe of one table reading
/// the recording's one file whatever its name, a recipe's file named with a path read where
/// `recipe_recordings` found it (`in_folder`).
pub fn import_recording(recipe: &Recipe, rec: &Recording) -> Result<(DriveLog, ImportSummary)> {
    let Some(first) = rec.files.first() else {
        return Err(Error::File(format!("{}: no files in this recording", rec.label.display())));
    };
    let mut recipe = recipe.clone();
    let dir = folder_of(first);
    if let ([table], [file]) = (recipe.tables.as_mut_slice(), rec.files.as_slice()) {
        table.file = file.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    } else {
        for table in &mut recipe.tables {
            let found = in_folder(dir, &table.file);
            if let Ok(rel) = found.strip_prefix(dir) {
                table.file = rel.to_string_lossy().into_owned();
            }
        }
    }
    super::import_from_folder(&recipe, dir, false)
}

/// For a file without a `time_s` column: the preset that reads it, with the files beside it
/// in its folder (at most 64 looked at), when one does and uses this file; else None.
pub fn import_hint(path: &Path) -> Option<ImportHint> {
    if super::starts_as_zip(path) {
        return zip_hint(path);
    }
    let me = head(path)?;
    if names_time_s(&me) {
        return None;
    }
    let dir = folder_of(path);
    let mut sniffed = vec![me];
    sniffed.extend(files_in(dir)?.iter().filter(|p| p.file_name() != path.file_name()).take(64).filter_map(|p| head(p)));
    let h = hint(dir, &sniffed)?;
    let name = path.file_name()?;
    h.files.iter().any(|f| f.file_name() == Some(name)).then_some(h)
}

/// For a ZIP archive: the preset that reads the files inside it, the archive the file to
/// give (`import_paths` unzips it).
fn zip_hint(path: &Path) -> Option<ImportHint> {
    let name = path.file_name()?.to_string_lossy().into_owned();
    let file = std::io::BufReader::new(std::fs::File::open(path).ok()?);
    let files = super::unzip_heads(&name, file).ok()?;
    let sniffed: Vec<Sniffed> = files.iter().filter_map(|(n, b)| sniff(n, b).ok()).collect();
    let d = detect(&sniffed).ok()?;
    Some(ImportHint { preset: d.preset, title: d.title, folder: folder_of(path).to_path_buf(), files: vec![path.to_path_buf()] })
}

/// The preset detected from these heads of `dir`'s files, and the files of it the preset uses.
fn hint(dir: &Path, sniffed: &[Sniffed]) -> Option<ImportHint> {
    let d = detect(sniffed).ok()?;
    Some(ImportHint {
        preset: d.preset,
        title: d.title,
        folder: dir.to_path_buf(),
        files: d.used.iter().map(|(_, f)| dir.join(f)).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A zipped recording: the preset of the files inside, the archive the file to import.
    #[test]
    fn a_zipped_raw_export_names_its_preset_and_itself() {
        let dir = std::env::temp_dir().join(format!("gyrodrift-zip-hint-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let read = |f: &str| std::fs::read(wild("sensor-logger", f)).unwrap();
        let entries = ["Gyroscope.csv", "Gravity.csv", "Location.csv"].map(|f| (format!("Drive/{f}"), read(f)));
        let refs: Vec<(&str, &[u8])> = entries.iter().map(|(n, b)| (n.as_str(), b.as_slice())).collect();
        let zip = dir.join("drive.zip");
        std::fs::write(&zip, super::super::archive::tests::zipped(&refs)).unwrap();
        let h = import_hint(&zip).unwrap();
        assert_eq!((h.preset, h.files.clone()), ("sensor-logger", vec![zip.clone()]));
        let (d, log, _) = super::super::import_paths(&[zip]).unwrap();
        assert_eq!((d.preset, log.len()), ("sensor-logger", 1000));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A recording's folder given as a whole: the preset and the files it uses; a folder of
    /// v1 logs, or one that does not exist, none.
    #[test]
    fn a_folder_of_a_raw_export_names_its_preset() {
        let h = folder_hint(&wild("phyphox", "")).unwrap();
        assert_eq!(h.preset, "phyphox");
        assert_eq!(h.files.len(), 3, "{h:?}");
        assert_eq!(folder_hint(&Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/train")), None);
        assert_eq!(folder_hint(&wild("nothing", "")), None);
    }

    /// A fleet of raw exports: the Sensor Logger folder's files one recording (the
    /// accelerometer and metadata files it does not use left out), the SensorLog file one
    /// alone, a v1 log none, in the order their folders first appear.
    #[test]
    fn failed_files_group_into_recordings() {
        let all = |dir: &str| -> Vec<PathBuf> { files_in(&wild(dir, "")).unwrap() };
        let mut failed = all("sensor-logger");
        failed.extend(all("sensorlog"));
        failed.push(Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/train/city-1.csv"));
        let r = recordings(&failed);
        let names = |v: &[PathBuf]| v.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect::<Vec<_>>();
        assert_eq!(r.len(), 2, "{r:?}");
        assert_eq!((r[0].preset, r[0].label.file_name().unwrap().to_str().unwrap()), ("sensor-logger", "sensor-logger"));
        assert_eq!(names(&r[0].files), ["Gyroscope.csv", "Gravity.csv", "Location.csv"]);
        assert_eq!(names(&r[0].ignored), ["Accelerometer.csv", "Metadata.csv"]);
        assert_eq!((r[1].preset, names(&r[1].files)), ("sensorlog", vec!["SensorLog.csv".to_string()]));
        assert_eq!(r[1].label, wild("sensorlog", "SensorLog.csv"));
        assert!(r[1].ignored.is_empty());
        assert!(recordings(&[wild("sensor-logger", "Metadata.csv")]).is_empty());
    }

    fn wild(dir: &str, file: &str) -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild").join(dir).join(file)
    }

    /// A Sensor Logger recording's gyroscope file: the preset, with the gravity and location
    /// files beside it (and not the accelerometer or metadata it does not use).
    #[test]
    fn a_raw_export_names_its_preset_and_the_files_beside_it() {
        let h = import_hint(&wild("sensor-logger", "Gyroscope.csv")).unwrap();
        assert_eq!(h.preset, "sensor-logger");
        let names: Vec<String> = h.files.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["Gyroscope.csv", "Gravity.csv", "Location.csv"]);
        // A file of the recording the preset does not use, a v1 log, a missing file: none.
        assert_eq!(import_hint(&wild("sensor-logger", "Metadata.csv")), None);
        assert_eq!(import_hint(&Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/train/city-1.csv")), None);
        assert_eq!(import_hint(&wild("sensor-logger", "nothing.csv")), None);
    }

    /// A fleet folder of raw exports: one hint per recording folder, in order, whatever file
    /// of it failed first (the accelerometer file the preset does not use included); a
    /// folder of v1 logs gives none.
    #[test]
    fn failed_files_give_one_hint_per_recording_folder() {
        let failed = [
            wild("sensor-logger", "Accelerometer.csv"),
            wild("sensor-logger", "Gyroscope.csv"),
            wild("phyphox", "Gyroscope.csv"),
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/train/city-1.csv"),
        ];
        let hints = folder_hints(&failed, 10);
        let presets: Vec<&str> = hints.iter().map(|h| h.preset).collect();
        assert_eq!(presets, ["sensor-logger", "phyphox"]);
        assert_eq!(hints[0].files.len(), 3);
        assert_eq!(folder_hints(&failed, 1).len(), 1);
    }
}
