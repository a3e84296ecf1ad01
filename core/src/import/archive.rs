//! ZIP archives among a logger's raw files: Sensor Logger exports a recording as zipped CSV
//! files, and others are mailed or downloaded zipped. The files inside are taken out by
//! name, so the presets detect and import them as if they had been given one by one.

use super::{Detection, ImportSummary, Recipe};
use crate::error::{Error, Result};
use crate::log::DriveLog;
use std::collections::BTreeMap;
use std::io::Read;

/// The most the archives of one import may unpack to, bytes (a zip bomb stops here).
pub const MAX_UNZIPPED_BYTES: u64 = 1 << 30;

pub use crate::table::is_zip;

/// The preset that reads in-memory raw files (the wasm package's `detectImport`), a ZIP
/// archive among them as the tables inside it (`unzip_all`); with those tables. A
/// recording from one archive is named by it (`archive_stem`) in the detected recipe, so
/// the log it imports, and the recipe saved and run again, carry the archive's name.
pub fn detect_unzipped(files: BTreeMap<String, Vec<u8>>) -> Result<(Detection, BTreeMap<String, Vec<u8>>)> {
    let stem = archive_stem(&files);
    let files = unzip_all(files)?;
    let (sniffed, others) = super::sniff_tables(files.iter().map(|(n, b)| (n.as_str(), b.as_slice())))?;
    let mut d = super::detect(&sniffed)?;
    d.ignored.extend(others);
    if let Some(stem) = stem {
        d.name(&stem);
    }
    Ok((d, files))
}

/// `detect_and_import` of in-memory raw files (`gyrodrift import FILE...` when one is a
/// ZIP archive), as `detect_unzipped` detects them.
pub fn detect_and_import_unzipped(files: BTreeMap<String, Vec<u8>>) -> Result<(Detection, DriveLog, ImportSummary)> {
    let (d, mut files) = detect_unzipped(files)?;
    let (log, summary) = super::import(&d.recipe, &mut files)?;
    Ok((d, log, summary))
}

/// `import` of in-memory files by a recipe, ZIP archives among them unpacked first
/// (`unzip_all`): the wasm package's `importLog`, and a recipe whose data is an archive.
/// The recipe names the log.
pub fn import_unzipped(recipe: &Recipe, files: BTreeMap<String, Vec<u8>>) -> Result<(DriveLog, ImportSummary)> {
    let mut files = unzip_all(files)?;
    super::import(recipe, &mut files)
}

/// The name a log imported from `files` takes from its archive: the stem of the one file
/// given when it is a ZIP archive ("Drive 2026-11-27.zip" -> "Drive 2026-11-27"), as a
/// folder of raw files names its recording; None otherwise.
fn archive_stem(files: &BTreeMap<String, Vec<u8>>) -> Option<String> {
    match files.iter().next() {
        Some((name, bytes)) if files.len() == 1 && is_zip(bytes) => {
            Some(std::path::Path::new(name).file_stem().map_or_else(|| name.clone(), |s| s.to_string_lossy().into_owned()))
        }
        _ => None,
    }
}

/// `files` (name -> bytes) with every ZIP archive among them replaced by the text tables
/// inside it (`.csv`, `.tsv`, `.txt`: what the presets read; a recording's audio or images
/// are not unpacked), each named by its file name (macOS resource forks under `__MACOSX/`
/// and `._` files left out). Errors name the archive; two files of one name are refused, as two
/// given files of one name are.
pub fn unzip_all(files: BTreeMap<String, Vec<u8>>) -> Result<BTreeMap<String, Vec<u8>>> {
    if !files.values().any(|b| is_zip(b)) {
        return Ok(files);
    }
    let mut out = BTreeMap::new();
    let mut budget = MAX_UNZIPPED_BYTES;
    for (name, bytes) in files {
        let entries = if is_zip(&bytes) { unzip(&name, bytes, &mut budget)? } else { vec![(name.clone(), bytes)] };
        for (inner, b) in entries {
            if out.insert(inner.clone(), b).is_some() {
                return Err(Error::File(format!("{name}: two files are named {inner}; import one recording at a time")));
            }
        }
    }
    Ok(out)
}

/// The files of one archive, within `budget` bytes unpacked (spent as they unpack).
fn unzip(name: &str, bytes: Vec<u8>, budget: &mut u64) -> Result<Vec<(String, Vec<u8>)>> {
    tables(name, std::io::Cursor::new(bytes), budget, u64::MAX)
}

/// The head (`SNIFF_BYTES`) of each table of the archive read from `reader`, for a preset
/// to be detected from without unpacking the rest (`report --dir --import` on a fleet of
/// zipped exports reads each archive whole only to import it).
pub fn unzip_heads<R: Read + std::io::Seek>(name: &str, reader: R) -> Result<Vec<(String, Vec<u8>)>> {
    let mut budget = MAX_UNZIPPED_BYTES;
    tables(name, reader, &mut budget, super::SNIFF_BYTES as u64)
}

/// The text tables of one archive, each by its file name and cut at `per_file` bytes,
/// within `budget` bytes unpacked (spent as they unpack).
fn tables<R: Read + std::io::Seek>(name: &str, reader: R, budget: &mut u64, per_file: u64) -> Result<Vec<(String, Vec<u8>)>> {
    let at = |m: String| Error::File(format!("{name}: {m}"));
    let mut zip = zip::ZipArchive::new(reader).map_err(|e| at(format!("not a ZIP archive that can be read ({e})")))?;
    let mut out: Vec<(String, Vec<u8>)> = Vec::new();
    for i in 0..zip.len() {
        let mut f = zip.by_index(i).map_err(|e| at(format!("file {} of the archive: {e}", i + 1)))?;
        let path = f.name().replace('\\', "/");
        let file = path.rsplit('/').next().unwrap_or_default().to_string();
        let table = [".csv", ".tsv", ".txt"].iter().any(|x| file.to_ascii_lowercase().ends_with(x));
        if f.is_dir() || !table || file.starts_with("._") || path.starts_with("__MACOSX/") {
            continue;
        }
        let mut b = Vec::new();
        f.by_ref().take((*budget).min(per_file).saturating_add(1)).read_to_end(&mut b).map_err(|e| at(format!("{path}: {e}")))?;
        if b.len() as u64 > *budget {
            return Err(at(format!("unpacks to more than {} MiB; unzip it and give the files inside", MAX_UNZIPPED_BYTES >> 20)));
        }
        b.truncate(per_file.min(usize::MAX as u64) as usize);
        *budget -= b.len() as u64;
        if out.iter().any(|(n, _)| *n == file) {
            return Err(at(format!("two files are named {file}; import one recording at a time")));
        }
        out.push((file, b));
    }
    if out.is_empty() {
        return Err(at("the archive holds no .csv, .tsv or .txt table".into()));
    }
    Ok(out)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use std::io::Write;

    /// A zip of `(path, bytes)` entries, deflated.
    pub(crate) fn zipped(entries: &[(&str, &[u8])]) -> Vec<u8> {
        let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
        let opts = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
        for (path, bytes) in entries {
            w.start_file(*path, opts).unwrap();
            w.write_all(bytes).unwrap();
        }
        w.finish().unwrap().into_inner()
    }

    /// A zipped recording's tables come out by their file names, beside the files given
    /// unzipped; folders, media and macOS resource forks are left out.
    #[test]
    fn an_archive_is_replaced_by_the_files_inside_it() {
        let z = zipped(&[
            ("Drive/Gyroscope.csv", b"time,z\n1,2\n"),
            ("__MACOSX/Drive/._Gyroscope.csv", b"x"),
            ("Drive/._x.csv", b"y"),
            ("Drive/Microphone.mp4", b"\x00\x01"),
        ]);
        let files = BTreeMap::from([("drive.zip".to_string(), z), ("notes.csv".to_string(), b"a\n".to_vec())]);
        let out = unzip_all(files).unwrap();
        assert_eq!(out.keys().collect::<Vec<_>>(), ["Gyroscope.csv", "notes.csv"]);
        assert_eq!(out["Gyroscope.csv"], b"time,z\n1,2\n");
        // No archive: the files as they were.
        let plain = BTreeMap::from([("a.csv".to_string(), b"PK".to_vec())]);
        assert_eq!(unzip_all(plain.clone()).unwrap(), plain);
        // A log from one archive is named by it; from several files, or an archive and a file, not.
        let one = BTreeMap::from([("Drive 2026-11-27.zip".to_string(), zipped(&[("a.csv", b"1")]))]);
        assert_eq!(archive_stem(&one).as_deref(), Some("Drive 2026-11-27"));
        assert_eq!(archive_stem(&plain), None);
        let mut two = one.clone();
        two.insert("b.csv".into(), b"2".to_vec());
        assert_eq!(archive_stem(&two), None);
    }

    /// Two files of one name (two recordings in one archive, or an archive's file beside
    /// the same file given), a broken archive and an empty one are errors naming the archive.
    #[test]
    fn ambiguous_broken_or_empty_archives_are_refused() {
        let two = zipped(&[("a/Gyroscope.csv", b"1"), ("b/Gyroscope.csv", b"2")]);
        let e = unzip_all(BTreeMap::from([("two.zip".to_string(), two)])).unwrap_err().to_string();
        assert!(e.contains("two.zip: two files are named Gyroscope.csv"), "{e}");
        let one = zipped(&[("Gyroscope.csv", b"1")]);
        let e = unzip_all(BTreeMap::from([("one.zip".to_string(), one), ("Gyroscope.csv".to_string(), b"2".to_vec())])).unwrap_err();
        assert!(e.to_string().contains("two files are named Gyroscope.csv"), "{e}");
        let mut cut = zipped(&[("Gyroscope.csv", b"time,z\n1,2\n")]);
        cut.truncate(20);
        let e = unzip_all(BTreeMap::from([("cut.zip".to_string(), cut)])).unwrap_err().to_string();
        assert!(e.starts_with("cut.zip: not a ZIP archive that can be read"), "{e}");
        let e = unzip_all(BTreeMap::from([("empty.zip".to_string(), zipped(&[("d/__MACOSX/", b""), ("a.jpg", b"1")]))])).unwrap_err();
        assert!(e.to_string().contains("empty.zip: the archive holds no .csv, .tsv or .txt table"), "{e}");
    }

    /// A zipped recording: the detected recipe names the log by the archive as the import
    /// does, so the recipe run again on the archive (in memory, or as the data of a recipe
    /// file: `import --recipe R --data drive.zip`) gives the same log; a table the archive
    /// lacks is an error listing what it holds.
    #[cfg(feature = "fs")]
    #[test]
    fn the_detected_recipe_reads_the_archive_again() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/wild/sensor-logger");
        let read = |f: &str| std::fs::read(dir.join(f)).unwrap();
        let z = zipped(&[
            ("Drive/Gyroscope.csv", &read("Gyroscope.csv")),
            ("Drive/Gravity.csv", &read("Gravity.csv")),
            ("Drive/Location.csv", &read("Location.csv")),
        ]);
        let csv = |l: &DriveLog| {
            let mut v = Vec::new();
            l.write_csv(&mut v).unwrap();
            v
        };
        let given = BTreeMap::from([("Drive 1.zip".to_string(), z.clone())]);
        let (d, log, _) = detect_and_import_unzipped(given.clone()).unwrap();
        assert_eq!(log.meta.name.as_deref(), Some("Drive 1"));
        assert_eq!(d.recipe_json["name"], "Drive 1");
        let again = import_unzipped(&super::super::recipe_from_json(&d.recipe_json.to_string()).unwrap(), given).unwrap().0;
        assert_eq!(csv(&again), csv(&log));
        let path = std::env::temp_dir().join(format!("gd-archive-{}.zip", std::process::id()));
        std::fs::write(&path, &z).unwrap();
        let from_file = super::super::import_from_folder(&d.recipe, &path, false);
        let mut wrong = d.recipe.clone();
        wrong.tables[0].file = "Grav.csv".into();
        let e = super::super::import_from_folder(&wrong, &path, false).unwrap_err().to_string();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(csv(&from_file.unwrap().0), csv(&log));
        assert!(
            e.contains("gd-archive-")
                && e.contains(
                    "Grav.csv: the recipe names this file, but it was not given (given: Gravity.csv, Gyroscope.csv, Location.csv)"
                ),
            "{e}"
        );
    }

    proptest::proptest! {
        /// A damaged archive (bytes changed, cut short) is an error or its files, never a
        /// panic (in wasm a panic kills the page).
        #[test]
        fn a_damaged_archive_never_panics(edits in proptest::collection::vec((0usize..4096, proptest::num::u8::ANY), 1..8), cut in 0usize..4096) {
            let mut z = zipped(&[("Drive/Gyroscope.csv", b"time,z\n1,2\n3,4\n"), ("Drive/Location.csv", &[b'x'; 300])]);
            for (i, b) in edits {
                let n = z.len();
                z[i % n] = b;
            }
            z.truncate(z.len() - cut % z.len());
            let _ = unzip_all(BTreeMap::from([("d.zip".to_string(), z)]));
        }
    }

    /// The heads of an archive's tables: each cut at SNIFF_BYTES, the same bytes the full
    /// unpacking starts with, by the same names and rules.
    #[test]
    fn the_heads_are_the_tables_cut_at_the_sniff() {
        let long = vec![b'7'; 3 * crate::import::SNIFF_BYTES];
        let z = zipped(&[("Drive/Gyroscope.csv", &long), ("Drive/Location.csv", b"time,bearing\n1,2\n"), ("Drive/a.jpg", b"x")]);
        let heads = unzip_heads("d.zip", std::io::Cursor::new(z.clone())).unwrap();
        let full = unzip_all(BTreeMap::from([("d.zip".to_string(), z)])).unwrap();
        assert_eq!(heads.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(), ["Gyroscope.csv", "Location.csv"]);
        for (n, b) in &heads {
            assert_eq!(b.len(), full[n].len().min(crate::import::SNIFF_BYTES), "{n}");
            assert!(full[n].starts_with(b), "{n}");
        }
        let two = zipped(&[("a/Gyroscope.csv", b"1"), ("b/Gyroscope.csv", b"2")]);
        let e = unzip_heads("two.zip", std::io::Cursor::new(two)).unwrap_err().to_string();
        assert!(e.contains("two.zip: two files are named Gyroscope.csv"), "{e}");
    }

    /// An archive that unpacks beyond the budget stops there, with an error (a zip bomb).
    #[test]
    fn an_archive_stops_at_its_budget() {
        let z = zipped(&[("big.csv", &vec![b'1'; 4096])]);
        let mut budget = 1000;
        let e = unzip("bomb.zip", z.clone(), &mut budget).unwrap_err().to_string();
        assert!(e.contains("bomb.zip: unpacks to more than"), "{e}");
        let mut budget = 4096;
        assert_eq!(unzip("ok.zip", z, &mut budget).unwrap()[0].1.len(), 4096);
        assert_eq!(budget, 0);
    }
}
