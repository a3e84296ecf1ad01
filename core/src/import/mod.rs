//! Import of recorded logs in any tabular format into the canonical v1 log, driven by a
//! declarative recipe: which files, which columns, units, sign or axis (or projection onto
//! gravity), time format, and how the reference heading, speed and wheel travel are
//! obtained. Tables are merged on time: every gyro row and every reference sample becomes a
//! row; speed, temperature and wheel travel are interpolated onto the rows; the reference
//! heading is never resampled (methods.md, detail 2).
//!
//! Transcendental functions come from `libm`, so the wasm package imports bit-identically.
//! Core reads the files through [`Files`] (any `Read`) and the recipe from its text (TOML
//! or JSON, `recipe_text`), so the import knows no file system; the `fs` feature adds the
//! native fronts' shared file access (a recipe file, its tables confined to the data folder).

#[cfg(feature = "zip")]
mod archive;
mod channels;
mod draft;
mod geo;
mod gpx;
mod guess;
#[cfg(feature = "fs")]
mod hint;
mod merge;
mod presets;
mod recipe;
mod recipe_text;
mod sniff;
mod table;
mod time;
mod units;

#[cfg(feature = "zip")]
pub use archive::{detect_and_import_unzipped, detect_unzipped, import_unzipped, is_zip, unzip_all, unzip_heads, MAX_UNZIPPED_BYTES};
pub use draft::{draft_recipe, Draft};
pub use geo::*;
pub use guess::{column_guesses, guess_columns, ColumnReading, ColumnRef, FileGuess, Guesses, LatLon};
#[cfg(feature = "fs")]
pub use hint::{
    draft_reads, draft_reads_refused, folder_hint, folder_hints, import_hint, import_recording, recipe_recordings, recordings, ImportHint,
    Recording,
};
pub use presets::{detect, detect_and_import, presets, Detection};
pub use recipe::*;
pub use recipe_text::*;
pub use sniff::{is_drive_log_head, sniff, sniff_tables, Sniffed, SNIFF_BYTES};
pub use time::*;
pub use units::{parse_iso8601, parse_time_of_day};

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog, LogMeta};
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use std::io::Read;
use table::*;
use units::*;

/// Positions in local metres: (time, east, north).
type Positions = (Vec<f64>, Vec<f64>, Vec<f64>);
/// Wheel travel in metres: (time, left, right).
type WheelTravel = (Vec<f64>, Vec<f64>, Vec<f64>);

/// Runs a recipe: reads the tables, derives the channels, merges on time.
pub fn import(recipe: &Recipe, files: &mut dyn Files) -> Result<(DriveLog, ImportSummary)> {
    recipe.validate()?;
    if recipe.tables.is_empty() {
        return Err(recipe_err("table", "at least one [[table]] is needed"));
    }
    let tables = read_tables(recipe, files)?;

    let (mut gyro_t, gyro_v, up) = yaw_rate(&recipe.yaw_rate, &tables, "yaw_rate")?;
    let mut align_offset = None;
    if let Some(a) = &recipe.align {
        let (rt, rv, _) = yaw_rate(&a.rate, &tables, "align.rate")?;
        let lag = best_lag_s(&gyro_t, &gyro_v, &rt, &rv, a.max_lag_s)?;
        gyro_t.iter_mut().for_each(|t| *t += lag);
        align_offset = Some(lag);
    }
    check_clocks(recipe, &tables, &gyro_t)?;
    let ch = channels::channels(recipe, &tables)?;
    let columns = merge::columns(recipe, &gyro_t, &gyro_v, &ch)?;
    let start = gyro_t[0];
    let mut meta = LogMeta {
        name: recipe.name.clone(),
        description: recipe.description.clone(),
        bias_s: recipe.bias_s,
        wheelbase_m: recipe.odometry.as_ref().map(|o| o.track_m),
        ..LogMeta::default()
    };
    meta.other.insert("source_start_time_s".into(), format!("{start}"));
    if let Some(lag) = align_offset {
        meta.other.insert("align_offset_s".into(), format!("{lag}"));
    }
    // Cells past physical ranges (a wrong unit or scale in the recipe) are refused as the
    // parser refuses them; the line is the imported log's row.
    let log =
        DriveLog::from_columns(meta, Vec::new(), columns).map_err(|e| e.within("the imported log (check the recipe's unit and scale)"))?;
    let finite = |c: Column| log.column(c).map_or(0, |v| v.iter().filter(|x| x.is_finite()).count());
    let n_reference = finite(Column::RefHeadingDeg);
    let summary = ImportSummary {
        n_rows: log.len(),
        n_gyro: finite(Column::GyroDps),
        n_reference,
        duration_min: log.duration_min(),
        up,
        align_offset_s: align_offset,
        start_time_s: start,
        time_fixes: time_fixes(&tables),
    };
    Ok((log, summary))
}

/// Every table of the recipe, with the columns the recipe uses.
fn read_tables(recipe: &Recipe, files: &mut dyn Files) -> Result<BTreeMap<String, Table>> {
    let wanted = wanted_columns(recipe)?;
    let mut tables = BTreeMap::new();
    for spec in &recipe.tables {
        if tables.contains_key(&spec.id) {
            return Err(recipe_err("table.id", format!("\"{}\" is used twice", spec.id)));
        }
        let t = read_table(spec, &wanted[&spec.id], files)?;
        tables.insert(spec.id.clone(), t);
    }
    Ok(tables)
}

/// The time policies' counts summed over the tables.
fn time_fixes(tables: &BTreeMap<String, Table>) -> TimeFixes {
    tables.values().fold(TimeFixes::default(), |a, t| TimeFixes {
        merged_duplicates: a.merged_duplicates + t.fixes.merged_duplicates,
        dropped_duplicates: a.dropped_duplicates + t.fixes.dropped_duplicates,
        sorted_backward: a.sorted_backward + t.fixes.sorted_backward,
        dropped_backward: a.dropped_backward + t.fixes.dropped_backward,
    })
}

/// Which columns each table must provide, from every section that names a table.
fn wanted_columns(recipe: &Recipe) -> Result<BTreeMap<String, BTreeSet<String>>> {
    let mut wanted: BTreeMap<String, BTreeSet<String>> = recipe.tables.iter().map(|t| (t.id.clone(), BTreeSet::new())).collect();
    let mut want = |table: &str, cols: &[&String], field: &str| -> Result<()> {
        let set =
            wanted.get_mut(table).ok_or_else(|| recipe_err(&format!("{field}.table"), format!("no [[table]] with id \"{table}\"")))?;
        set.extend(cols.iter().map(|c| (*c).clone()));
        Ok(())
    };
    // A rate's own columns, and its gravity axes (in the gravity's table when it has one).
    let mut want_rate = |r: &RateSpec, field: &str| -> Result<()> {
        let mut v: Vec<&String> = r.column.iter().collect();
        v.extend(r.axes.iter().flatten());
        if let Some(g) = &r.gravity {
            match &g.table {
                Some(t) => want(t, &g.axes.iter().collect::<Vec<_>>(), &format!("{field}.gravity"))?,
                None => v.extend(g.axes.iter()),
            }
        }
        want(&r.table, &v, field)
    };
    want_rate(&recipe.yaw_rate, "yaw_rate")?;
    if let Some(a) = &recipe.align {
        want_rate(&a.rate, "align.rate")?;
    }
    if let Some(p) = &recipe.positions {
        want(&p.table, &p.columns.iter().collect::<Vec<_>>(), "positions")?;
    }
    match &recipe.heading {
        Some(HeadingSpec::Column { table, column, speed_column, time_column, .. }) => {
            let mut c = vec![column];
            c.extend(speed_column.iter());
            c.extend(time_column.iter());
            want(table, &c, "heading")?;
        }
        Some(HeadingSpec::Positions { .. }) if recipe.positions.is_none() => {
            return Err(recipe_err("heading", "source = \"positions\" needs a [positions] section"));
        }
        _ => {}
    }
    match &recipe.speed {
        Some(SpeedSpec::Column { table, column, time_column, .. }) => {
            let mut c = vec![column];
            c.extend(time_column.iter());
            want(table, &c, "speed")?
        }
        Some(SpeedSpec::Positions { .. }) if recipe.positions.is_none() => {
            return Err(recipe_err("speed", "source = \"positions\" needs a [positions] section"));
        }
        _ => {}
    }
    if let Some(o) = &recipe.odometry {
        want(&o.table, &o.left.iter().chain(&o.right).collect::<Vec<_>>(), "odometry")?;
    }
    if let Some(v) = &recipe.temperature {
        want(&v.table, &[&v.column], "temperature")?;
    }
    Ok(wanted)
}

/// Tables on another clock than the gyro's (epoch seconds against seconds since boot)
/// would merge into nonsense: a table whose times do not overlap the gyro's at all is an
/// error naming both and the fix. The gravity's table only gives a mean: not checked.
fn check_clocks(recipe: &Recipe, tables: &BTreeMap<String, Table>, gyro_t: &[f64]) -> Result<()> {
    let (g0, g1) = (gyro_t[0], gyro_t[gyro_t.len() - 1]);
    let gravity = recipe.yaw_rate.gravity.as_ref().and_then(|g| g.table.as_deref());
    let align = recipe.align.as_ref().map(|a| a.rate.table.as_str());
    for (id, t) in tables {
        if *id == recipe.yaw_rate.table || Some(id.as_str()) == gravity || Some(id.as_str()) == align {
            continue;
        }
        let (a0, a1) = (t.time_s[0], t.time_s[t.time_s.len() - 1]);
        if a1 < g0 || a0 > g1 {
            return Err(recipe_err(
                &format!("table {id} time"),
                format!(
                    "{}: its times ({a0:.3} to {a1:.3} s) do not overlap the gyro's in {} ({g0:.3} to {g1:.3} s): \
                     the two files use different clocks; use the same time column in both, or give one \
                     `relative = true` or an `offset_s`",
                    t.file, tables[&recipe.yaw_rate.table].file
                ),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
