//! The log's rows: the gyro and reference samples merged on one time line, the other
//! channels interpolated onto it, times from the first gyro sample, the span kept.

use super::channels::Channels;
use super::*;

/// The log's columns (time from `start`, the first gyro sample), span applied.
pub(super) fn columns(recipe: &Recipe, gyro_t: &[f64], gyro_v: &[f64], ch: &Channels) -> Result<Vec<(Column, Vec<f64>)>> {
    let (ref_t, ref_v) = &ch.reference;
    let (g0, g1) = (gyro_t[0], gyro_t[gyro_t.len() - 1]);
    let merged = merge_rows(gyro_t, gyro_v, ref_t, ref_v);
    let times: Vec<f64> = merged.iter().map(|r| r.0).collect();
    let mut columns = vec![(Column::TimeS, times.iter().map(|t| t - g0).collect::<Vec<f64>>())];
    columns.push((Column::GyroDps, merged.iter().map(|r| r.1).collect()));
    if recipe.heading.is_some() {
        columns.push((Column::RefHeadingDeg, merged.iter().map(|r| r.2).collect()));
    }
    if let Some((ts, vs)) = &ch.speed {
        columns.push((Column::SpeedMps, interpolate(ts, vs, &times)));
    }
    if let Some((ts, l, r)) = &ch.odometry {
        columns.push((Column::OdoLeftM, interpolate(ts, l, &times)));
        columns.push((Column::OdoRightM, interpolate(ts, r, &times)));
    }
    if let Some((ts, vs)) = &ch.temperature {
        columns.push((Column::TempC, interpolate(ts, vs, &times)));
    }
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
    Ok(dedup_rows(columns).0)
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
