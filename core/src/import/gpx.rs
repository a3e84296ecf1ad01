//! A GPX file (a phone's or a sport watch's recorded track) as a recipe's table: its track
//! points in file order, timed by their `<time>` (s since 1970, UTC) and read by georust's
//! `gpx` crate. Columns: `lat`, `lon` (deg), `ele` (m) and `speed` (m/s, GPX 1.0 only;
//! NaN where absent). The heading then comes from the positions (`positions.kind =
//! "latlon"`), as a track has no course. A row's "line" in messages is the point's number.

use super::*;

/// The columns a GPX table has.
#[cfg(feature = "gpx")]
const GPX_COLUMNS: [&str; 4] = ["lat", "lon", "ele", "speed"];

#[cfg(feature = "gpx")]
pub(super) fn read_gpx(spec: &TableSpec, wanted: &BTreeSet<String>, files: &mut dyn Files) -> Result<Table> {
    let at = |e: Error| e.within(&spec.file);
    if let Some(c) = wanted.iter().find(|c| !GPX_COLUMNS.contains(&c.as_str())) {
        return Err(Error::missing(c, &format!("named by the recipe for table {}; a GPX table has: {}", spec.id, GPX_COLUMNS.join(", "))));
    }
    let track = ::gpx::read(std::io::BufReader::new(files.open(&spec.file)?))
        .map_err(|e| at(Error::File(format!("not a GPX file the reader accepts: {e}"))))?;
    let mut t = Table { file: spec.file.clone(), time_s: Vec::new(), line: Vec::new(), cols: BTreeMap::new(), fixes: TimeFixes::default() };
    let names: Vec<String> = wanted.iter().cloned().collect();
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
    let mut latest = f64::NEG_INFINITY;
    let points = track.tracks.iter().flat_map(|tr| tr.segments.iter()).flat_map(|s| s.points.iter());
    for (k, p) in points.enumerate() {
        let n = k as u64 + 1;
        let cell_err = |m: &str| at(Error::Cell { line: n, column: "time".into(), message: format!("track point {n}: {m}") });
        let time: ::time::OffsetDateTime = p.time.ok_or_else(|| cell_err("no <time>"))?.into();
        let time_s = time.unix_timestamp() as f64 + f64::from(time.nanosecond()) * 1e-9;
        check_step(&spec.time, time_s, t.time_s.last().copied(), latest, n, "time").map_err(at)?;
        latest = latest.max(time_s);
        let pos = p.point();
        for (c, name) in cols.iter_mut().zip(&names) {
            c.push(match name.as_str() {
                "lat" => pos.y(),
                "lon" => pos.x(),
                "ele" => p.elevation.unwrap_or(f64::NAN),
                _ => p.speed.unwrap_or(f64::NAN),
            });
        }
        t.time_s.push(time_s);
        t.line.push(n);
    }
    if t.time_s.is_empty() {
        return Err(at(Error::File(format!("table {} has no track points (<trk><trkseg><trkpt>)", spec.id))));
    }
    finish_table(spec, &mut t, names.into_iter(), cols);
    Ok(t)
}

#[cfg(not(feature = "gpx"))]
pub(super) fn read_gpx(spec: &TableSpec, _: &BTreeSet<String>, _: &mut dyn Files) -> Result<Table> {
    Err(recipe_err(&format!("table {}", spec.id), "this build reads no GPX (the gyrodrift crate's gpx feature)"))
}
