//! A recipe as text: TOML (the shipped recipes, `gyrodrift import --recipe`) or JSON (the
//! object the wasm and Python packages take), read and written in one place so every front
//! refuses the same unknown fields with the same message. With the `fs` feature, the
//! native fronts' file access: a recipe read from disk, its files confined to the data
//! folder.

use super::Recipe;
use crate::error::{Error, Result};

/// A recipe from TOML text, checked (unknown or misspelled fields refused).
pub fn recipe_from_toml(text: &str) -> Result<Recipe> {
    serde_json::from_value(recipe_value_from_toml(text)?).map_err(|e| Error::Data(format!("recipe: {e}")))
}

/// A recipe from JSON text, checked.
pub fn recipe_from_json(text: &str) -> Result<Recipe> {
    serde_json::from_str(text).map_err(|e| Error::Data(format!("recipe: {e}")))
}

/// A recipe from TOML text as the JSON object the packages take, checked as a recipe.
pub fn recipe_value_from_toml(text: &str) -> Result<serde_json::Value> {
    let v: serde_json::Value = toml::from_str(text).map_err(|e| Error::Data(format!("recipe: {e}")))?;
    check_value(&v)?;
    Ok(v)
}

/// A recipe (the JSON object) as TOML text, checked as a recipe first.
pub fn recipe_value_to_toml(v: &serde_json::Value) -> Result<String> {
    check_value(v)?;
    toml::to_string(v).map_err(|e| Error::Data(format!("recipe as TOML: {e}")))
}

fn check_value(v: &serde_json::Value) -> Result<()> {
    serde_json::from_value::<Recipe>(v.clone()).map(|_| ()).map_err(|e| Error::Data(format!("recipe: {e}")))
}

#[cfg(feature = "fs")]
pub use files::*;

#[cfg(feature = "fs")]
mod files {
    use super::super::{import, ImportSummary};
    use super::*;
    use crate::log::DriveLog;
    use std::path::{Component, Path, PathBuf};

    /// Reads a recipe file: JSON by its extension, TOML otherwise. Errors name the file.
    pub fn read_recipe(path: &Path) -> Result<Recipe> {
        let named = |e: Error| Error::In { name: path.display().to_string(), source: Box::new(e) };
        let text = std::fs::read_to_string(path).map_err(|e| named(Error::File(format!("cannot read: {e}"))))?;
        if path.extension().is_some_and(|e| e == "json") { recipe_from_json(&text) } else { recipe_from_toml(&text) }.map_err(named)
    }

    /// A recipe's table file, confined to the data folder: a relative path with no `..`,
    /// and, after links are followed, still inside the folder (unless `allow_outside`).
    /// Checked before the file is opened, so a refused file is never read.
    pub fn confined(root: &Path, name: &str, allow_outside: bool) -> Result<PathBuf> {
        let refuse = |why: &str| {
            Error::File(format!(
                "{name}: refused: {why} (the recipe's files must lie inside the data folder; the CLI's --allow-outside permits it)"
            ))
        };
        let rel = Path::new(name);
        let path = root.join(rel);
        if allow_outside {
            return Ok(path);
        }
        if rel.is_absolute() || rel.components().any(|c| !matches!(c, Component::Normal(_) | Component::CurDir)) {
            return Err(refuse("not a plain relative path"));
        }
        let base = std::fs::canonicalize(root).map_err(|e| Error::File(format!("{}: cannot open the data folder: {e}", root.display())))?;
        match std::fs::canonicalize(&path) {
            Ok(real) if !real.starts_with(&base) => Err(refuse("a link leads out of the data folder")),
            Ok(real) => Ok(real),
            Err(e) => Err(Error::File(format!("{}: cannot open: {e}", path.display()))),
        }
    }

    /// Imports by `recipe`, its files read from `root` and confined to it (`confined`); a
    /// `root` that is a ZIP archive (a logger's zipped export) gives the tables inside it,
    /// by file name, as `import FILE.zip` reads them (`import_unzipped`).
    pub fn import_from_folder(recipe: &Recipe, root: &Path, allow_outside: bool) -> Result<(DriveLog, ImportSummary)> {
        if root.is_file() && starts_as_zip(root) {
            let bytes = std::fs::read(root).map_err(|e| Error::File(format!("{}: cannot open: {e}", root.display())))?;
            let name = root.file_name().map_or_else(|| root.display().to_string(), |n| n.to_string_lossy().into_owned());
            let archive = std::collections::BTreeMap::from([(name, bytes)]);
            return super::super::import_unzipped(recipe, archive)
                .map_err(|e| Error::In { name: root.display().to_string(), source: Box::new(e) });
        }
        let mut files = |name: &str| -> Result<Box<dyn std::io::Read>> {
            let path = confined(root, name, allow_outside)?;
            std::fs::File::open(&path)
                .map(|f| Box::new(std::io::BufReader::new(f)) as Box<dyn std::io::Read>)
                .map_err(|e| Error::File(format!("{}: cannot open: {e}", path.display())))
        };
        import(recipe, &mut files)
    }

    /// A logger's raw files given by path, imported by the preset detected from them (as
    /// `detect_and_import`, which names files by their file names): `gyrodrift import
    /// FILE...`, Python's `import_files`, a fleet's recordings. A ZIP archive among them
    /// gives the files inside it (`unzip_all`). Two files of one name are refused. A folder
    /// given alone gives the files in it (an unzipped export), and names the recording.
    pub fn import_paths(paths: &[PathBuf]) -> Result<(super::super::Detection, DriveLog, ImportSummary)> {
        let (mut d, mut log, summary) = given_files(paths).and_then(|f| import_files(&f)).map_err(|e| in_folders(e, paths))?;
        if let [dir] = paths {
            let name = dir.is_dir().then(|| dir.canonicalize().ok()).flatten();
            if let Some(name) = name.and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned())) {
                d.name(&name);
                log.meta.name = Some(name);
            }
        }
        Ok((d, log, summary))
    }

    /// A folder given alone whose own files import as no recording, but which holds folders
    /// (a folder of recordings, one in each): the error, and which folders to import alone.
    fn in_folders(e: Error, paths: &[PathBuf]) -> Error {
        let [dir] = paths else { return e };
        let folders = super::super::hint::folders_in(dir);
        let Some(first) = folders.first() else { return e };
        let shown =
            if folders.len() > 6 { format!("{}, ... ({} in all)", folders[..6].join(", "), folders.len()) } else { folders.join(", ") };
        let one = dir.join(first);
        Error::File(format!("{e}. Its folders may each hold a recording, to import alone: {shown} (gyrodrift import {})", one.display()))
    }

    /// The files paths give: a folder given alone, the files in it (an unzipped export);
    /// else the paths, none of them a folder.
    fn given_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
        match paths {
            [dir] if dir.is_dir() => {
                let files = super::super::hint::files_in(dir).unwrap_or_default();
                if files.is_empty() {
                    return Err(Error::File(format!("{}: no files in this folder to import", dir.display())));
                }
                Ok(files)
            }
            _ => match paths.iter().find(|p| p.is_dir()) {
                Some(dir) => Err(Error::File(format!("{}: a folder among files: give the folder alone, or its files", dir.display()))),
                None => Ok(paths.to_vec()),
            },
        }
    }

    /// The heads (the first `SNIFF_BYTES`) of files given by path, by file name (a folder
    /// given alone: its files, as `import_paths` reads them); an error names a file that
    /// cannot be read, an empty folder or a folder among files.
    pub fn read_heads(paths: &[PathBuf]) -> Result<Vec<(String, Vec<u8>)>> {
        given_files(paths)?
            .iter()
            .map(|p| {
                let head = super::super::hint::read_head(p).map_err(|e| Error::File(format!("{}: cannot open: {e}", p.display())))?;
                Ok((file_name(p), head))
            })
            .collect()
    }

    /// A path's file name, as recipes and detection name files (the whole path without one).
    fn file_name(p: &Path) -> String {
        p.file_name().map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into_owned())
    }

    /// For files no preset reads: a draft recipe from their column names, for `gyrodrift
    /// import FILES --print-recipe`, of those that are text tables. None when a preset reads
    /// them (its recipe is the one to print) or none is a text table.
    pub fn draft_for_paths(paths: &[PathBuf]) -> Result<Option<super::super::Draft>> {
        let Ok(heads) = read_heads(paths) else { return Ok(None) };
        let Ok((sniffed, others)) = super::super::sniff_tables(heads.iter().map(|(n, h)| (n.as_str(), h.as_slice()))) else {
            return Ok(None);
        };
        // The draft reads the tables alone (a binary or a Markdown file beside them left out).
        let heads: Vec<_> = heads.into_iter().filter(|(n, _)| !others.contains(n)).collect();
        match super::super::detect(&sniffed) {
            Err(_) => super::super::draft::draft_sniffed(&sniffed, &heads).map(Some),
            Ok(_) => Ok(None),
        }
    }

    /// `import_paths` of files (no folder among them).
    fn import_files(paths: &[PathBuf]) -> Result<(super::super::Detection, DriveLog, ImportSummary)> {
        let mut by_name = std::collections::BTreeMap::new();
        let mut names = Vec::new();
        for p in paths {
            let name = file_name(p);
            if by_name.insert(name.clone(), p).is_some() {
                return Err(Error::File(format!("{}: two files are named {name}; import one recording at a time", p.display())));
            }
            names.push(name);
        }
        let open_error = |path: &Path, e: std::io::Error| Error::File(format!("{}: cannot open: {e}", path.display()));
        if paths.iter().any(|p| starts_as_zip(p)) {
            // An archive is read whole (its directory is at its end): every file in memory.
            let mut given = std::collections::BTreeMap::new();
            for (name, path) in by_name {
                given.insert(name, std::fs::read(path).map_err(|e| open_error(path, e))?);
            }
            return super::super::detect_and_import_unzipped(given);
        }
        let mut files = |name: &str| -> Result<Box<dyn std::io::Read>> {
            let path = by_name.get(name).ok_or_else(|| Error::File(format!("{name}: not among the files given")))?;
            std::fs::File::open(path)
                .map(|f| Box::new(std::io::BufReader::new(f)) as Box<dyn std::io::Read>)
                .map_err(|e| open_error(path, e))
        };
        super::super::detect_and_import(&names, &mut files)
    }

    /// Whether the file at `path` starts as a ZIP archive (false when it cannot be read).
    pub fn starts_as_zip(path: &Path) -> bool {
        let mut head = [0u8; 4];
        std::fs::File::open(path).and_then(|mut f| std::io::Read::read_exact(&mut f, &mut head)).is_ok() && super::super::is_zip(&head)
    }

    /// Imports by the recipe file at `path`, its files from `data` (default: the recipe's
    /// folder). Errors name the recipe.
    pub fn import_recipe_file(path: &Path, data: Option<&Path>, allow_outside: bool) -> Result<(DriveLog, ImportSummary)> {
        let recipe = read_recipe(path)?;
        let root = data.map(Path::to_path_buf).unwrap_or_else(|| path.parent().map(Path::to_path_buf).unwrap_or_default());
        import_from_folder(&recipe, &root, allow_outside).map_err(|e| Error::In { name: path.display().to_string(), source: Box::new(e) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = "name = \"m\"\n[[table]]\nid = \"g\"\nfile = \"g.csv\"\ntime = { column = \"t\", unit = \"s\" }\n[yaw_rate]\ntable = \"g\"\ncolumn = \"z\"\nunit = \"deg/s\"\npositive = \"ccw\"\n";

    #[test]
    fn toml_and_json_read_alike_and_round_trip() {
        let v = recipe_value_from_toml(MINIMAL).unwrap();
        let back = recipe_value_to_toml(&v).unwrap();
        assert_eq!(recipe_value_from_toml(&back).unwrap(), v);
        let json = serde_json::to_string(&v).unwrap();
        assert_eq!(recipe_from_json(&json).unwrap(), recipe_from_toml(MINIMAL).unwrap());
    }

    #[test]
    fn unknown_fields_and_bad_toml_are_refused_with_their_place() {
        let e = recipe_from_toml(&MINIMAL.replace("name = ", "colour = \"red\"\nname = ")).unwrap_err().to_string();
        assert!(e.contains("unknown field") && e.contains("colour"), "{e}");
        let e = recipe_value_from_toml("[gyro\nfile = 1").unwrap_err().to_string();
        assert!(e.starts_with("recipe: ") && e.contains("line 1"), "{e}");
        assert!(recipe_value_to_toml(&serde_json::json!({"nope": 1})).is_err());
    }
}
