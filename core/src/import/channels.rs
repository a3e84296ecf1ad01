//! The channels of the log besides the yaw rate, each from its table: the reference
//! heading (a column, or the course of positions), speed, wheel travel, temperature; a slow
//! sensor logged in fast rows gives one sample per own time.

use super::table::Table;
use super::*;

/// Every channel the recipe asks for, as (time, value) series on the tables' clock.
pub(super) struct Channels {
    /// Reference heading, deg counter-clockwise, never resampled.
    pub(super) reference: (Vec<f64>, Vec<f64>),
    pub(super) speed: Option<(Vec<f64>, Vec<f64>)>,
    pub(super) odometry: Option<WheelTravel>,
    pub(super) temperature: Option<(Vec<f64>, Vec<f64>)>,
}

/// The recipe's channels from the read tables.
pub(super) fn channels(recipe: &Recipe, tables: &BTreeMap<String, Table>) -> Result<Channels> {
    let mut positions = None;
    if let Some(p) = &recipe.positions {
        let t = tables.get(&p.table).ok_or_else(|| recipe_err("positions.table", format!("no table \"{}\"", p.table)))?;
        positions = Some(local_en(p, t)?);
    }
    Ok(Channels {
        reference: reference_heading(recipe, tables, positions.as_ref())?,
        speed: speed_series(recipe, tables, positions.as_ref())?,
        odometry: odometry_series(recipe, tables)?,
        temperature: temperature_series(recipe, tables)?,
    })
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
