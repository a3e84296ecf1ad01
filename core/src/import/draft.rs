//! A draft recipe for files no preset reads, guessed from their column names and first
//! rows: each file's time and its format, the yaw rate (one axis) and its unit, the
//! reference heading (a course column, a GPX track's positions, or latitude and longitude)
//! and the speed. A draft is a starting point to check and edit (`gyrodrift import FILES
//! --print-recipe`), never imported unseen: names say little about signs and axes, and
//! `check` then says what is off.

use super::sniff::{first_row, Sniffed};
use super::*;
use serde_json::{json, Value};

/// A draft recipe and, per guess, what it was read from.
#[derive(Debug, Clone)]
pub struct Draft {
    pub recipe_json: Value,
    /// One line per guess ("yaw_rate: gyro.csv column gz, rad/s: ..."), for the user to check.
    pub guesses: Vec<String>,
}

/// `name` in lower case contains `a`, then later `b` (a regex `a.*b`).
fn then(name: &str, a: &str, b: &str) -> bool {
    name.find(a).is_some_and(|i| name[i + a.len()..].contains(b))
}

/// `name` has `word` as a whole token (letters and digits around it are other words).
fn word(name: &str, word: &str) -> bool {
    name.match_indices(word).any(|(i, _)| {
        let before = name[..i].chars().next_back();
        let after = name[i + word.len()..].chars().next();
        !before.is_some_and(char::is_alphanumeric) && !after.is_some_and(char::is_alphanumeric)
    })
}

/// The time format or unit a time column's value (its first row's) or name suggests.
fn time_of(name: &str, value: &str) -> Value {
    let n = name.to_lowercase();
    if parse_iso8601(value).is_some() {
        json!({ "column": name, "format": "iso8601" })
    } else if (value.contains(':') && parse_time_of_day(value).is_some())
        || n.contains("time_of_day")
        || n.contains("timeofday")
        || n.contains("hhmmss")
        || n.contains("clock")
    {
        json!({ "column": name, "format": "time_of_day" })
    } else if n.contains("iso") || n.contains("date") || n.contains("utc") {
        json!({ "column": name, "format": "iso8601" })
    } else {
        let unit = match () {
            _ if word(&n, "ns") || n.contains("_ns") || n.contains("nanos") => "ns",
            _ if word(&n, "us") || n.contains("_us") || n.contains("micros") => "us",
            _ if word(&n, "ms") || n.contains("_ms") || n.contains("millis") => "ms",
            _ => "s",
        };
        json!({ "column": name, "unit": unit })
    }
}

/// A file's time column: the first whose name says time or stamp, else one named like a time
/// in seconds (`t`, `t_...`, `..._s`), else the first column.
fn time_column(s: &Sniffed) -> &str {
    let named = |h: &&String| {
        let n = h.to_lowercase();
        n.contains("time") || n.contains("stamp")
    };
    let like = |h: &&String| {
        let n = h.to_lowercase();
        n == "t" || n.starts_with("t_") || n.ends_with("_s")
    };
    s.header.iter().find(named).or_else(|| s.header.iter().find(like)).or(s.header.first()).map_or("", String::as_str)
}

/// A GPX file (by its name): a track read whole, not a table of columns.
fn is_gpx(s: &Sniffed) -> bool {
    s.name.to_lowercase().ends_with(".gpx")
}

/// The first column, over every file, that `fits` and is not the file's time: (file index, name).
fn find(files: &[Sniffed], fits: impl Fn(&str) -> bool) -> Option<(usize, String)> {
    files.iter().enumerate().filter(|(_, s)| !is_gpx(s)).find_map(|(i, s)| {
        let time = time_column(s);
        s.header.iter().find(|h| h.as_str() != time && fits(&h.to_lowercase())).map(|h| (i, h.clone()))
    })
}

fn speed_unit_of(n: &str) -> &'static str {
    match () {
        _ if n.contains("kmh") || n.contains("km/h") || n.contains("kph") => "km/h",
        _ if n.contains("mph") => "mph",
        _ if n.contains("knot") || word(n, "kn") || n.contains("kts") => "kn",
        _ => "m/s",
    }
}

/// A draft recipe for files (name, the head of its bytes) from their column names and
/// first rows, or an error when a file is not a text table or no column reads as a yaw rate.
pub fn draft_recipe(heads: &[(String, Vec<u8>)]) -> Result<Draft> {
    let files: Vec<Sniffed> = heads.iter().map(|(name, head)| sniff(name, head)).collect::<Result<_>>()?;
    draft_sniffed(&files, heads)
}

/// [`draft_recipe`] of heads already sniffed (`files`, in the order of `heads`).
pub(super) fn draft_sniffed(files: &[Sniffed], heads: &[(String, Vec<u8>)]) -> Result<Draft> {
    let rows: Vec<Vec<String>> = files.iter().zip(heads).map(|(s, (_, head))| first_row(s, head)).collect();
    draft_from(files, &rows)
}

/// What the draft has so far: the recipe, the guesses, the files (indices) it reads.
struct Drafting<'a> {
    files: &'a [Sniffed],
    r: Value,
    guesses: Vec<String>,
    used: Vec<usize>,
}

fn table(i: usize) -> String {
    format!("t{i}")
}

impl Drafting<'_> {
    fn at(&self, i: usize, c: &str) -> String {
        format!("{} column \"{c}\"", self.files[i].name)
    }

    /// The yaw rate: a z axis or a yaw rate by name, else any gyro or rate; its unit by name.
    fn yaw_rate(&mut self) -> Result<String> {
        let files = self.files;
        let z_axis = |n: &str| then(n, "gyro", "z") || word(n, "wz") || word(n, "w_z") || then(n, "yaw", "rate") || then(n, "angular", "z");
        let any_rate = |n: &str| n.contains("gyro") || n.contains("yaw") || n.contains("rate");
        let (gi, gyro) = find(files, z_axis).or_else(|| find(files, any_rate)).ok_or_else(|| {
            let headers: Vec<String> = files.iter().map(|s| format!("{}: {}", s.name, s.header.join(", "))).collect();
            Error::File(format!(
                "no column reads as a yaw rate by its name (gyro z, yaw rate, wz) in {}; write the recipe (sample-logs/recipes/README.md)",
                headers.join("; ")
            ))
        })?;
        let g = gyro.to_lowercase();
        let (unit, why) = match () {
            _ if g.contains("rad") => ("rad/s", "the name says rad"),
            _ if g.contains("deg") || g.contains("dps") => ("deg/s", "the name says deg/s"),
            _ => ("rad/s", "no unit in the name: phones and ROS write rad/s"),
        };
        let guess = format!("yaw_rate: {}, {unit} ({why}), counter-clockwise positive (z up; `check` says if not)", self.at(gi, &gyro));
        self.guesses.push(guess);
        self.r = json!({ "name": format!("{} (draft)", files[gi].stem()), "bias_s": 0,
            "yaw_rate": { "table": table(gi), "column": gyro, "unit": unit, "positive": "ccw" } });
        self.used.push(gi);
        Ok(g)
    }

    /// The speed, then the reference heading: a course column (gated by the speed in its
    /// table), a GPX track's positions, or latitude and longitude columns.
    fn speed_and_reference(&mut self, gyro: &str) {
        let files = self.files;
        let speed = find(files, |n| {
            (n.contains("speed") || n.contains("velocity") || n.contains("vel_m") || word(n, "v")) && !n.contains("accuracy")
        });
        if let Some((si, sc)) = &speed {
            let unit = speed_unit_of(&sc.to_lowercase());
            self.guesses.push(format!("speed: {}, {unit}", self.at(*si, sc)));
            self.r["speed"] = json!({ "source": "column", "table": table(*si), "column": sc, "unit": unit });
            self.used.push(*si);
        }
        let courses = ["course", "bearing", "heading", "direction", "cog"];
        let course = find(files, |n| n != gyro && courses.iter().any(|w| n.contains(w)) && !n.contains("accuracy"));
        let lat_lon = files.iter().enumerate().filter(|(_, s)| !is_gpx(s)).find_map(|(i, s)| {
            let col = |w: &str| s.header.iter().find(|h| h.to_lowercase().contains(w)).cloned();
            Some((i, col("lat")?, col("lon")?))
        });
        if let Some((hi, hc)) = course {
            let unit = if hc.to_lowercase().contains("rad") { "rad" } else { "deg" };
            self.guesses.push(format!("heading: {}, {unit}, clockwise from north (a GPS course)", self.at(hi, &hc)));
            let mut h = json!({ "source": "column", "table": table(hi), "column": hc, "unit": unit, "positive": "cw" });
            if let Some((_, sc)) = speed.as_ref().filter(|(si, _)| *si == hi) {
                h["speed_column"] = json!(sc);
                h["speed_unit"] = json!(speed_unit_of(&sc.to_lowercase()));
                h["min_speed_mps"] = json!(5.0);
                self.guesses.push("heading: kept above 5 m/s (a course is noise at walking pace)".into());
            }
            self.r["heading"] = h;
            self.used.push(hi);
        } else if let Some(pi) = files.iter().position(is_gpx) {
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
        } else if let Some((pi, lat, lon)) = lat_lon {
            self.guesses.push(format!("heading: the course between positions, {} and \"{lon}\" in degrees", self.at(pi, &lat)));
            self.r["positions"] = json!({ "table": table(pi), "kind": "latlon", "columns": [lat, lon] });
            self.r["heading"] = json!({ "source": "positions" });
            self.used.push(pi);
        } else {
            self.guesses.push("heading: none found (no course, bearing or latitude column): nothing will be scored".into());
        }
    }

    /// One table per file the draft reads: a GPX track as it is, the others timed by their
    /// time column (format from its first row's value, else its name) in their dialect.
    fn tables(&mut self, rows: &[Vec<String>]) {
        self.used.sort_unstable();
        self.used.dedup();
        let mut tables = Vec::new();
        for &i in &self.used {
            let s = &self.files[i];
            if is_gpx(s) {
                tables.push(json!({ "id": table(i), "file": s.name, "format": "gpx" }));
                continue;
            }
            let column = time_column(s);
            let value = s.header.iter().position(|h| h == column).and_then(|j| rows[i].get(j)).map_or("", String::as_str);
            let time = time_of(column, value);
            let what = time.get("format").or(time.get("unit")).and_then(Value::as_str).unwrap_or("s");
            self.guesses.push(format!("time of {}: column \"{column}\", {what}", s.name));
            let mut t = json!({ "id": table(i), "file": s.name, "time": time });
            s.set_dialect(&mut t);
            tables.push(t);
        }
        self.r["table"] = json!(tables);
    }
}

fn draft_from(files: &[Sniffed], rows: &[Vec<String>]) -> Result<Draft> {
    let mut d = Drafting { files, r: Value::Null, guesses: Vec::new(), used: Vec::new() };
    let gyro = d.yaw_rate()?;
    d.speed_and_reference(&gyro);
    if let Some((ti, tc)) = find(files, |n| n.contains("temp")) {
        d.guesses.push(format!("temperature: {}, deg C", d.at(ti, &tc)));
        d.r["temperature"] = json!({ "table": table(ti), "column": tc, "unit": "C" });
        d.used.push(ti);
    }
    d.tables(rows);
    d.guesses.push("bias_s: 0 (set the seconds the log starts standing still, if it does)".into());
    // A draft must parse as a recipe (its units and fields the import knows).
    serde_json::from_value::<Recipe>(d.r.clone()).map_err(|e| recipe_err("draft", e.to_string()))?;
    Ok(Draft { recipe_json: d.r, guesses: d.guesses })
}
