//! Import of recorded logs in any tabular format into the canonical v1 log, driven by a
//! declarative recipe: which files, which columns, units, sign or axis (or projection onto
//! gravity), time format, and how the reference heading, speed and wheel travel are
//! obtained. Tables are merged on time: every gyro row and every reference sample becomes a
//! row; speed, temperature and wheel travel are interpolated onto the rows; the reference
//! heading is never resampled (methods.md, detail 2).
//!
//! Transcendental functions come from `libm`, so the wasm package imports bit-identically.
//! Core reads the files through [`Files`] (any `Read`); the recipe arrives deserialized
//! (the CLI reads TOML, the wasm package takes a JS object), so core knows no file system.

mod geo;
mod presets;
mod recipe;
mod sniff;
mod table;
mod time;
mod units;

pub use geo::*;
pub use presets::{detect, presets, Detection};
pub use recipe::*;
pub use sniff::{sniff, Sniffed, SNIFF_BYTES};
pub use time::*;
pub use units::parse_iso8601;

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
    let wanted = wanted_columns(recipe)?;

    let mut tables = BTreeMap::new();
    for spec in &recipe.tables {
        if tables.contains_key(&spec.id) {
            return Err(recipe_err("table.id", format!("\"{}\" is used twice", spec.id)));
        }
        let t = read_table(spec, &wanted[&spec.id], files)?;
        tables.insert(spec.id.clone(), t);
    }

    let (mut gyro_t, gyro_v, up) = yaw_rate(&recipe.yaw_rate, &tables, "yaw_rate")?;
    let mut align_offset = None;
    if let Some(a) = &recipe.align {
        let (rt, rv, _) = yaw_rate(&a.rate, &tables, "align.rate")?;
        let lag = best_lag_s(&gyro_t, &gyro_v, &rt, &rv, a.max_lag_s)?;
        gyro_t.iter_mut().for_each(|t| *t += lag);
        align_offset = Some(lag);
    }
    check_clocks(recipe, &tables, &gyro_t)?;

    // Reference heading, deg CCW (time, value).
    let mut positions = None;
    if let Some(p) = &recipe.positions {
        let t = tables.get(&p.table).ok_or_else(|| recipe_err("positions.table", format!("no table \"{}\"", p.table)))?;
        positions = Some(local_en(p, t)?);
    }
    let (ref_t, ref_v) = reference_heading(recipe, &tables, positions.as_ref())?;
    let speed = speed_series(recipe, &tables, positions.as_ref())?;
    let odo = odometry_series(recipe, &tables)?;
    let temp = temperature_series(recipe, &tables)?;

    let (g0, g1) = (gyro_t[0], gyro_t[gyro_t.len() - 1]);
    let merged = merge_rows(&gyro_t, &gyro_v, &ref_t, &ref_v);
    let times: Vec<f64> = merged.iter().map(|r| r.0).collect();
    let mut data: Vec<(Column, Vec<f64>)> = vec![(Column::GyroDps, merged.iter().map(|r| r.1).collect())];
    if recipe.heading.is_some() {
        data.push((Column::RefHeadingDeg, merged.iter().map(|r| r.2).collect()));
    }
    if let Some((ts, vs)) = &speed {
        data.push((Column::SpeedMps, interpolate(ts, vs, &times)));
    }
    if let Some((ts, l, r)) = &odo {
        data.push((Column::OdoLeftM, interpolate(ts, l, &times)));
        data.push((Column::OdoRightM, interpolate(ts, r, &times)));
    }
    if let Some((ts, vs)) = &temp {
        data.push((Column::TempC, interpolate(ts, vs, &times)));
    }
    let start = g0;
    let mut columns = vec![(Column::TimeS, times.iter().map(|t| t - start).collect::<Vec<f64>>())];
    columns.extend(data);
    if let Some([a, b]) = recipe.span_s {
        let keep: Vec<bool> = columns[0].1.iter().map(|&t| t >= a && t <= b).collect();
        for (_, v) in columns.iter_mut() {
            let mut k = keep.iter();
            v.retain(|_| *k.next().unwrap_or(&false));
        }
        if columns[0].1.is_empty() {
            return Err(Error::data(format!("span_s [{a}, {b}] keeps no rows: the log spans {} s", g1 - g0)));
        }
    }
    // Equal times after the shift to 0 are impossible (the shift is exact for distinct
    // doubles only up to rounding): merge rows that collapse.
    let (columns, _) = dedup_rows(columns);
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

/// The rows that carry a sample and its time: every row, or (with a slow sensor's own time
/// column) only rows where that time changes. The sensor's clock is put on the table's by
/// the smallest delay seen (a new sample appears in the first row written after it), so
/// the sample keeps its own time instead of lagging to the row's.
fn samples_of(t: &Table, time_column: Option<&str>, used_by: &str) -> Result<Vec<(usize, f64)>> {
    let Some(c) = time_column else {
        return Ok(t.time_s.iter().copied().enumerate().collect());
    };
    let own = t.col(c, used_by)?;
    let mut rows: Vec<(usize, f64)> = Vec::new();
    for (i, &o) in own.iter().enumerate() {
        if o.is_finite() && rows.last().is_none_or(|&(_, last)| o != last) {
            rows.push((i, o));
        }
    }
    let offset = rows.iter().map(|&(i, o)| t.time_s[i] - o).fold(f64::INFINITY, f64::min);
    let mut out: Vec<(usize, f64)> = rows.into_iter().map(|(i, o)| (i, o + offset)).collect();
    // a sensor clock that steps back is not a sample stream: keep increasing times only
    let mut latest = f64::NEG_INFINITY;
    out.retain(|&(_, time)| {
        let keep = time > latest;
        latest = latest.max(time);
        keep
    });
    Ok(out)
}

/// The reference heading, deg CCW: (time, value), never resampled.
fn reference_heading(recipe: &Recipe, tables: &BTreeMap<String, Table>, positions: Option<&Positions>) -> Result<(Vec<f64>, Vec<f64>)> {
    Ok(match &recipe.heading {
        None => (Vec::new(), Vec::new()),
        Some(HeadingSpec::Column { table, column, unit, positive, speed_column, speed_unit: su, min_speed_mps, time_column }) => {
            let t = &tables[table];
            let k = angle_unit(unit, "heading.unit")? * positive.factor();
            let ks = speed_unit(su.as_deref().unwrap_or("m/s"), "heading.speed_unit")?;
            let v = t.col(column, "heading")?;
            let s = match speed_column {
                Some(c) => Some(t.col(c, "heading.speed_column")?),
                None => None,
            };
            let (mut ts, mut vs) = (Vec::new(), Vec::new());
            for (i, time) in samples_of(t, time_column.as_deref(), "heading.time_column")? {
                let moving = s.is_none_or(|s| s[i] * ks >= *min_speed_mps);
                if v[i].is_finite() && moving {
                    ts.push(time);
                    vs.push(crate::metrics::wrap_diff_deg(v[i] * k));
                }
            }
            (ts, vs)
        }
        Some(HeadingSpec::Positions { min_distance_m, min_speed_mps }) => {
            if !(min_distance_m.is_finite() && *min_distance_m > 0.0 && min_speed_mps.is_finite() && *min_speed_mps >= 0.0) {
                return Err(recipe_err("heading", "min_distance_m must be > 0 and min_speed_mps >= 0"));
            }
            let (pt, e, n) = positions.ok_or_else(|| recipe_err("heading", "needs [positions]"))?;
            let (ts, course) = course_from_positions(pt, e, n, *min_distance_m, *min_speed_mps);
            (ts, course.iter().map(|c| crate::metrics::wrap_diff_deg(-c)).collect())
        }
    })
}

/// Speed in m/s on its own times, from a column or from positions.
fn speed_series(recipe: &Recipe, tables: &BTreeMap<String, Table>, positions: Option<&Positions>) -> Result<Option<(Vec<f64>, Vec<f64>)>> {
    Ok(match &recipe.speed {
        None => None,
        Some(SpeedSpec::Column { table, column, unit, time_column }) => {
            let t = &tables[table];
            let k = speed_unit(unit, "speed.unit")?;
            let v = t.col(column, "speed")?;
            let (ts, vs) =
                samples_of(t, time_column.as_deref(), "speed.time_column")?.into_iter().map(|(i, time)| (time, v[i] * k)).unzip();
            Some((ts, vs))
        }
        Some(SpeedSpec::Positions { window_s }) => {
            if !(window_s.is_finite() && *window_s > 0.0) {
                return Err(recipe_err("speed.window_s", format!("{window_s} is not a time > 0")));
            }
            let (pt, e, n) = positions.ok_or_else(|| recipe_err("speed", "needs [positions]"))?;
            Some(speed_from_positions(pt, e, n, *window_s))
        }
    })
}

/// Wheel travel (left, right), m, on the table's times, from travel or from wheel speeds.
fn odometry_series(recipe: &Recipe, tables: &BTreeMap<String, Table>) -> Result<Option<WheelTravel>> {
    Ok(match &recipe.odometry {
        None => None,
        Some(o) => {
            if !(o.track_m.is_finite() && o.track_m > 0.0) {
                return Err(recipe_err("odometry.track_m", format!("{} is not a distance > 0", o.track_m)));
            }
            if o.left.is_empty() || o.right.is_empty() {
                return Err(recipe_err("odometry", "left and right need one column or more each"));
            }
            let t = &tables[&o.table];
            let k = match o.kind {
                OdometryKind::Speed => speed_unit(&o.unit, "odometry.unit")?,
                OdometryKind::Travel => match o.unit.as_str() {
                    "m" => 1.0,
                    "km" => 1000.0,
                    u => return Err(recipe_err("odometry.unit", format!("\"{u}\" is not a distance unit (m, km)"))),
                },
            };
            let side = |cols: &[String]| -> Result<Vec<f64>> {
                let c: Vec<&[f64]> = cols.iter().map(|n| t.col(n, "odometry")).collect::<Result<_>>()?;
                let mean: Vec<f64> = (0..t.time_s.len()).map(|i| c.iter().map(|c| c[i]).sum::<f64>() / c.len() as f64 * k).collect();
                Ok(match o.kind {
                    OdometryKind::Speed => integrate_speed(&t.time_s, &mean),
                    OdometryKind::Travel => mean,
                })
            };
            Some((t.time_s.clone(), side(&o.left)?, side(&o.right)?))
        }
    })
}

/// Temperature in deg C on the table's times.
fn temperature_series(recipe: &Recipe, tables: &BTreeMap<String, Table>) -> Result<Option<(Vec<f64>, Vec<f64>)>> {
    Ok(match &recipe.temperature {
        None => None,
        Some(v) => {
            let t = &tables[&v.table];
            let c = t.col(&v.column, "temperature")?;
            let conv: fn(f64) -> f64 = match v.unit.as_str() {
                "C" | "degC" => |x| x,
                "K" => |x| x - 273.15,
                "F" => |x| (x - 32.0) / 1.8,
                u => return Err(recipe_err("temperature.unit", format!("\"{u}\" is not a temperature unit (C, K, F)"))),
            };
            Some((t.time_s.clone(), c.iter().map(|&x| conv(x)).collect()))
        }
    })
}

/// Rows: the gyro samples and the reference samples inside the gyro's span, on one time
/// line; a gyro and a reference sample at the same time share a row. (time, gyro, heading).
fn merge_rows(gyro_t: &[f64], gyro_v: &[f64], ref_t: &[f64], ref_v: &[f64]) -> Vec<(f64, f64, f64)> {
    let (g0, g1) = (gyro_t[0], gyro_t[gyro_t.len() - 1]);
    let mut rows: Vec<(f64, f64, f64)> = gyro_t.iter().zip(gyro_v).map(|(&t, &v)| (t, v, f64::NAN)).collect();
    rows.extend(ref_t.iter().zip(ref_v).filter(|(&t, _)| t >= g0 && t <= g1).map(|(&t, &v)| (t, f64::NAN, v)));
    rows.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut merged: Vec<(f64, f64, f64)> = Vec::with_capacity(rows.len());
    for r in rows {
        match merged.last_mut() {
            Some(last) if last.0 == r.0 => {
                if r.1.is_finite() {
                    last.1 = r.1;
                }
                if r.2.is_finite() {
                    last.2 = r.2;
                }
            }
            _ => merged.push(r),
        }
    }
    merged
}

/// Merges consecutive rows whose time became equal (keeping the finite cells).
pub(super) fn dedup_rows(columns: Vec<(Column, Vec<f64>)>) -> (Vec<(Column, Vec<f64>)>, usize) {
    let t = &columns[0].1;
    let keep: Vec<usize> = (0..t.len()).filter(|&i| i + 1 == t.len() || t[i + 1] > t[i]).collect();
    if keep.len() == t.len() {
        let n = t.len();
        return (columns, n);
    }
    let n = keep.len();
    let out = columns
        .into_iter()
        .map(|(c, v)| {
            let mut w = Vec::with_capacity(n);
            let mut start = 0usize;
            for &i in &keep {
                let cell = (start..=i).rev().map(|j| v[j]).find(|x| x.is_finite()).unwrap_or(f64::NAN);
                w.push(if c == Column::TimeS { v[i] } else { cell });
                start = i + 1;
            }
            (c, w)
        })
        .collect();
    (out, n)
}

#[cfg(test)]
mod tests;
