//! A draft recipe for files no preset reads, guessed from their column names and first
//! rows: each file's time and its format, the yaw rate (one axis, or three gyro axes
//! projected on an accelerometer's up) and its unit, the reference heading (a course
//! column, an NMEA log's RMC course or GGA positions, a GPX track's positions, or latitude
//! and longitude) and the speed. A draft is a starting point to check and edit (`gyrodrift
//! import FILES --print-recipe`), never imported unseen: names say little about signs and
//! axes, and `check` then says what is off.

use super::guess::{angle_unit_of, guess_columns, rate_unit_of, speed_unit_of, ColumnRef, Guesses};
use super::sniff::Sniffed;
use super::*;
use serde_json::{json, Value};

/// A draft recipe and, per guess, what it was read from.
#[derive(Debug, Clone)]
pub struct Draft {
    pub recipe_json: Value,
    /// One line per guess ("yaw_rate: gyro.csv column gz, rad/s: ..."), for the user to check.
    pub guesses: Vec<String>,
}

/// A draft recipe for files (name, the head of its bytes) from their column names and
/// first rows, or an error when a file is not a text table or no column reads as a yaw rate.
pub fn draft_recipe(heads: &[(String, Vec<u8>)]) -> Result<Draft> {
    let files: Vec<Sniffed> = heads.iter().map(|(name, head)| sniff(name, head)).collect::<Result<_>>()?;
    draft_sniffed(&files, heads)
}

/// [`draft_recipe`] of heads already sniffed (`files`, in the order of `heads`).
pub(super) fn draft_sniffed(files: &[Sniffed], heads: &[(String, Vec<u8>)]) -> Result<Draft> {
    draft_from(files, heads)
}

/// The fields of NMEA's RMC and GGA sentences, as a draft names them.
const RMC_FIELDS: [&str; 13] = ["tag", "time", "status", "lat", "ns", "lon", "ew", "knots", "course", "date", "mv", "mv_ew", "mode"];
const GGA_FIELDS: [&str; 15] =
    ["tag", "time", "lat", "ns", "lon", "ew", "quality", "sats", "hdop", "alt", "alt_unit", "geoid", "geoid_unit", "age", "station"];

/// What the draft has so far: the recipe, the guesses, the files (indices) it reads.
struct Drafting<'a> {
    files: &'a [Sniffed],
    g: Guesses,
    r: Value,
    guesses: Vec<String>,
    used: Vec<usize>,
}

/// The columns' names.
fn names(c: &[ColumnRef]) -> Vec<&str> {
    c.iter().map(|c| c.column.as_str()).collect()
}

fn table(i: usize) -> String {
    format!("t{i}")
}

impl Drafting<'_> {
    fn at(&self, c: &ColumnRef) -> String {
        format!("{} column \"{}\"", self.files[c.file].name, c.column)
    }

    /// The yaw rate (one axis) and its unit by name.
    fn yaw_rate(&mut self) -> Result<()> {
        let files = self.files;
        let gyro = self.g.yaw_rate.clone().ok_or_else(|| {
            let headers: Vec<String> = files.iter().map(|s| format!("{}: {}", s.name, s.header.join(", "))).collect();
            Error::File(format!(
                "no column reads as a yaw rate by its name (gyro z, yaw rate, wz) in {}; write the recipe (sample-logs/recipes/README.md)",
                headers.join("; ")
            ))
        })?;
        let (unit, why) = rate_unit_of(&gyro.column);
        let mut y = json!({ "table": table(gyro.file), "column": gyro.column, "unit": unit, "positive": "ccw" });
        match (&self.g.gyro_axes, &self.g.accel_axes) {
            (Some(g), Some(a)) if self.g.yaw_from_axes => {
                self.guesses.push(format!(
                    "yaw_rate: {} columns {} projected on the up of {} columns {} (their mean over the first 10 s; an accelerometer reads +g up at rest, `check` says if not), so any mounting reads the yaw rate; {unit} ({why})",
                    files[g[0].file].name,
                    names(g).join(", "),
                    files[a[0].file].name,
                    names(a).join(", ")
                ));
                let mut gravity = json!({ "axes": names(a), "first_s": 10 });
                if a[0].file != g[0].file {
                    gravity["table"] = json!(table(a[0].file));
                    self.used.push(a[0].file);
                }
                y = json!({ "table": table(g[0].file), "axes": names(g), "gravity": gravity, "unit": unit, "positive": "ccw" });
            }
            _ => self
                .guesses
                .push(format!("yaw_rate: {}, {unit} ({why}), counter-clockwise positive (z up; `check` says if not)", self.at(&gyro))),
        }
        self.r = json!({ "name": format!("{} (draft)", files[gyro.file].stem()), "bias_s": 0, "yaw_rate": y });
        self.used.push(gyro.file);
        Ok(())
    }

    /// The first NMEA log whose sentence to read is of `kind` ("RMC", "GGA"), and that sentence.
    fn nmea(&self, kind: &str) -> Option<(usize, String)> {
        self.g.files.iter().enumerate().find_map(|(i, f)| f.nmea.clone().filter(|t| t.ends_with(kind)).map(|t| (i, t)))
    }

    /// The speed, then the reference heading: a course column (gated by the speed in its
    /// table), an NMEA log's RMC course, a GPX track's positions, an NMEA log's GGA
    /// positions, or latitude and longitude columns.
    fn speed_and_reference(&mut self) {
        let files = self.files;
        let speed = self.g.speed.clone();
        if let Some(sp) = &speed {
            let unit = speed_unit_of(&sp.column);
            self.guesses.push(format!("speed: {}, {unit}", self.at(sp)));
            self.r["speed"] = json!({ "source": "column", "table": table(sp.file), "column": sp.column, "unit": unit });
            self.used.push(sp.file);
        }
        if let Some(c) = self.g.course.clone().filter(|c| c.column == Column::RefHeadingDeg.name()) {
            // The v1 log's own reference column: counter-clockwise, gated already.
            self.guesses.push(format!("heading: {}, deg, counter-clockwise (a drive log's reference heading)", self.at(&c)));
            self.r["heading"] = json!({ "source": "column", "table": table(c.file), "column": c.column, "unit": "deg", "positive": "ccw" });
            self.used.push(c.file);
        } else if let Some(c) = self.g.course.clone() {
            let unit = angle_unit_of(&c.column);
            self.guesses.push(format!("heading: {}, {unit}, clockwise from north (a GPS course)", self.at(&c)));
            let mut h = json!({ "source": "column", "table": table(c.file), "column": c.column, "unit": unit, "positive": "cw" });
            if let Some(sp) = speed.as_ref().filter(|sp| sp.file == c.file) {
                h["speed_column"] = json!(sp.column);
                h["speed_unit"] = json!(speed_unit_of(&sp.column));
                h["min_speed_mps"] = json!(5.0);
                self.guesses.push("heading: kept above 5 m/s (a course is noise at walking pace)".into());
            }
            self.r["heading"] = h;
            self.used.push(c.file);
        } else if let Some((ni, tag)) = self.nmea("RMC") {
            self.guesses.push(format!(
                "heading: the course of {}'s {tag} sentences, kept above 3 m/s (its clock is the UTC time of day: so must the gyro's be)",
                files[ni].name
            ));
            self.r["heading"] = json!({ "source": "column", "table": table(ni), "column": "course", "unit": "deg", "positive": "cw",
                "speed_column": "knots", "speed_unit": "kn", "min_speed_mps": 3.0 });
            if speed.is_none() {
                self.guesses.push(format!("speed: {}'s {tag} speed, kn", files[ni].name));
                self.r["speed"] = json!({ "source": "column", "table": table(ni), "column": "knots", "unit": "kn" });
            }
            self.used.push(ni);
        } else if let Some(pi) = self.g.files.iter().position(|f| f.gpx) {
            self.guesses.push(format!(
                "heading: the course between the positions of the GPX track {} (its clock is UTC: so must the gyro's be)",
                files[pi].name
            ));
            self.r["positions"] = json!({ "table": table(pi), "kind": "latlon", "columns": ["lat", "lon"] });
            self.r["heading"] = json!({ "source": "positions" });
            if speed.is_none() {
                self.guesses.push("speed: from the GPX track's positions".into());
                self.r["speed"] = json!({ "source": "positions" });
            }
            self.used.push(pi);
        } else if let Some((ni, tag)) = self.nmea("GGA") {
            self.guesses.push(format!(
                "heading: the course between the positions of {}'s {tag} sentences (its clock is the UTC time of day: so must the gyro's be)",
                files[ni].name
            ));
            self.r["positions"] = json!({ "table": table(ni), "kind": "nmea", "columns": ["lat", "ns", "lon", "ew"] });
            self.r["heading"] = json!({ "source": "positions" });
            if speed.is_none() {
                self.guesses.push("speed: from the positions".into());
                self.r["speed"] = json!({ "source": "positions" });
            }
            self.used.push(ni);
        } else if let Some(p) = self.g.lat_lon.clone() {
            let lat = ColumnRef { file: p.file, column: p.lat.clone() };
            self.guesses.push(format!("heading: the course between positions, {} and \"{}\" in degrees", self.at(&lat), p.lon));
            self.r["positions"] = json!({ "table": table(p.file), "kind": "latlon", "columns": [p.lat, p.lon] });
            self.r["heading"] = json!({ "source": "positions" });
            self.used.push(p.file);
        } else {
            self.guesses.push("heading: none found (no course, bearing or latitude column): nothing will be scored".into());
        }
    }

    /// One table per file the draft reads: a GPX track as it is, the others timed by their
    /// time column (format from its first row's value, else its name) in their dialect.
    fn tables(&mut self) {
        self.used.sort_unstable();
        self.used.dedup();
        let mut tables = Vec::new();
        for &i in &self.used {
            let (s, f) = (&self.files[i], &self.g.files[i]);
            if f.gpx {
                tables.push(json!({ "id": table(i), "file": s.name, "format": "gpx" }));
                continue;
            }
            if let Some(tag) = &f.nmea {
                self.guesses.push(format!("time of {}: its {tag} sentences' hhmmss.ss, a time of day", s.name));
                tables.push(json!({ "id": table(i), "file": s.name, "format": "nmea", "record": tag,
                    "columns": if tag.ends_with("RMC") { &RMC_FIELDS[..] } else { &GGA_FIELDS[..] },
                    "time": { "column": "time", "format": "time_of_day" } }));
                continue;
            }
            let column = &f.time_column;
            let what = f.columns.iter().find(|c| &c.name == column).map_or("s", |c| c.time);
            let time = match what {
                "iso8601" | "time_of_day" => json!({ "column": column, "format": what }),
                unit => json!({ "column": column, "unit": unit }),
            };
            self.guesses.push(format!("time of {}: column \"{column}\", {what}", s.name));
            let mut t = json!({ "id": table(i), "file": s.name, "time": time });
            s.set_dialect(&mut t);
            tables.push(t);
        }
        self.r["table"] = json!(tables);
    }
}

fn draft_from(files: &[Sniffed], heads: &[(String, Vec<u8>)]) -> Result<Draft> {
    let g = guess_columns(files, heads);
    let mut d = Drafting { files, g, r: Value::Null, guesses: Vec::new(), used: Vec::new() };
    d.yaw_rate()?;
    d.speed_and_reference();
    if let Some(t) = d.g.temperature.clone() {
        d.guesses.push(format!("temperature: {}, deg C", d.at(&t)));
        d.r["temperature"] = json!({ "table": table(t.file), "column": t.column, "unit": "C" });
        d.used.push(t.file);
    }
    d.tables();
    d.guesses.push("bias_s: 0 (set the seconds the log starts standing still, if it does)".into());
    // A draft must parse as a recipe (its units and fields the import knows).
    serde_json::from_value::<Recipe>(d.r.clone()).map_err(|e| recipe_err("draft", e.to_string()))?;
    Ok(Draft { recipe_json: d.r, guesses: d.guesses })
}
