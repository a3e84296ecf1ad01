//! What reads the files a fleet job refused, once for all of them: each refusal kind that
//! another reading mends, counted, in core's words, with the remedy as a kind that each front
//! (the CLI's `report --dir`, the Python fleet job) spells in its own options.

use serde::Serialize;
use std::collections::BTreeMap;

/// How a fleet job read the files that are not v1 logs (the hint for them differs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ForeignReading {
    /// As v1 logs only.
    AsLogs,
    /// With the logger presets' import.
    Presets,
    /// With a recipe of the user's.
    Recipe,
}

impl ForeignReading {
    /// By the job's options: a recipe reads them when given (the presets are not tried then).
    pub fn of(import_presets: bool, recipe: bool) -> Self {
        match (import_presets, recipe) {
            (_, true) => ForeignReading::Recipe,
            (true, false) => ForeignReading::Presets,
            (false, false) => ForeignReading::AsLogs,
        }
    }
}

/// What reads a kind of refused file, for a front to name in its own options.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Remedy {
    /// The time-order policy's fix (rows of one time merged, late rows sorted in).
    TimeOrderFix,
    /// The joined-logs policy's split (each log a drive of its own).
    JoinedSplit,
    /// `check` on each file, which names each fix (or running them anyway, with absurd figures).
    CheckEach,
    /// The presets' import, else a recipe (the job read the files as logs).
    ImportOrRecipe,
    /// A recipe (the presets' import read none of them).
    Recipe,
    /// Another recipe (the job's recipe read none of them).
    OtherRecipe,
}

/// One kind of refused file: how many, why, and what reads them.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct RefusalHint {
    /// Error rows of this kind (a refused file is one row).
    pub files: usize,
    /// Why, in words that follow "1 file " or "N files " (the verb agreeing with the count).
    pub why: String,
    /// The count and why together: "1 file is not a v1 log ...", "2 files refused for ...".
    pub said: String,
    pub remedy: Remedy,
}

impl RefusalHint {
    /// `why`: the words for one file and for several.
    fn new(files: usize, why: (&str, &str), remedy: Remedy) -> Self {
        let (noun, why) = if files == 1 { ("file", why.0) } else { ("files", why.1) };
        RefusalHint { files, why: why.to_string(), said: format!("{files} {noun} {why}"), remedy }
    }
}

/// The hints for a fleet's error rows counted by kind (`FleetSummary::errors_by_code`), in a
/// fixed order; none for kinds no reading mends (a cut row, a bad cell).
pub fn refusal_hints(errors_by_code: &BTreeMap<String, usize>, reading: ForeignReading) -> Vec<RefusalHint> {
    let n = |code: &str| errors_by_code.get(code).copied().unwrap_or(0);
    let same = |why| (why, why);
    let foreign_why = match reading {
        ForeignReading::AsLogs => (("is not a v1 log (no time_s column)", "are not v1 logs (no time_s column)"), Remedy::ImportOrRecipe),
        ForeignReading::Presets => (
            (
                "is not a v1 log (no time_s column) and no logger preset reads it",
                "are not v1 logs (no time_s column) and no logger preset reads them",
            ),
            Remedy::Recipe,
        ),
        ForeignReading::Recipe => (
            (
                "is not a v1 log (no time_s column) and the recipe does not read it",
                "are not v1 logs (no time_s column) and the recipe does not read them",
            ),
            Remedy::OtherRecipe,
        ),
    };
    [
        (n("time_order"), same("refused for a time that repeats or steps back by at most 1 s"), Remedy::TimeOrderFix),
        (n("joined") + n("clock_reset"), same("refused for a second log joined on or a clock reset"), Remedy::JoinedSplit),
        (n("check"), same("refused for a unit or sign mistake check found"), Remedy::CheckEach),
        (n("foreign"), foreign_why.0, foreign_why.1),
    ]
    .into_iter()
    .filter(|&(files, ..)| files > 0)
    .map(|(files, why, remedy)| RefusalHint::new(files, why, remedy))
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Joined and clock-reset rows make one hint (one option reads both); a cut row none;
    /// the foreign rows' words and remedy follow how the job read them.
    #[test]
    fn kinds_are_counted_once_each_and_foreign_files_by_the_reading() {
        let by_code: BTreeMap<String, usize> =
            [("joined", 2), ("clock_reset", 1), ("cut_row", 4), ("foreign", 3), ("time_order", 1)].map(|(c, k)| (c.to_string(), k)).into();
        let hints = refusal_hints(&by_code, ForeignReading::AsLogs);
        let got: Vec<(usize, Remedy)> = hints.iter().map(|h| (h.files, h.remedy)).collect();
        assert_eq!(got, [(1, Remedy::TimeOrderFix), (3, Remedy::JoinedSplit), (3, Remedy::ImportOrRecipe)]);
        assert_eq!(hints[2].why, "are not v1 logs (no time_s column)");
        assert_eq!(hints[2].said, "3 files are not v1 logs (no time_s column)");
        assert_eq!(hints[0].said, "1 file refused for a time that repeats or steps back by at most 1 s");
        let presets = refusal_hints(&by_code, ForeignReading::Presets);
        assert_eq!((presets[2].remedy, presets[2].why.ends_with("and no logger preset reads them")), (Remedy::Recipe, true));
        let recipe = refusal_hints(&by_code, ForeignReading::Recipe);
        assert_eq!((recipe[2].remedy, recipe[2].why.ends_with("the recipe does not read them")), (Remedy::OtherRecipe, true));
        let one: BTreeMap<String, usize> = [("foreign".to_string(), 1)].into();
        assert_eq!(
            refusal_hints(&one, ForeignReading::Presets)[0].said,
            "1 file is not a v1 log (no time_s column) and no logger preset reads it"
        );
        let check: BTreeMap<String, usize> = [("check".to_string(), 5)].into();
        assert_eq!(
            refusal_hints(&check, ForeignReading::AsLogs)[0],
            RefusalHint {
                files: 5,
                why: "refused for a unit or sign mistake check found".into(),
                said: "5 files refused for a unit or sign mistake check found".into(),
                remedy: Remedy::CheckEach
            }
        );
        assert!(refusal_hints(&BTreeMap::new(), ForeignReading::Recipe).is_empty());
        let of = [(false, false), (true, false), (false, true), (true, true)].map(|(i, r)| ForeignReading::of(i, r));
        assert_eq!(of, [ForeignReading::AsLogs, ForeignReading::Presets, ForeignReading::Recipe, ForeignReading::Recipe]);
    }
}
