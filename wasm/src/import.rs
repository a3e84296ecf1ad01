//! Import of recorded files by a recipe.

use crate::convert::*;
use crate::log::Log;
use crate::JsResult;
use gyrodrift::import;
use js_sys::{Object, Reflect, Uint8Array};
use std::collections::BTreeMap;
use wasm_bindgen::prelude::*;

/// Imports recorded files by a recipe (the same object as the CLI's TOML/JSON recipe):
/// `files` maps each recipe `file` name to its bytes (a ZIP archive gives the files inside). Returns `{ log, summary }`; a bad
/// recipe or file throws an Error naming the file, line and column.
#[wasm_bindgen(js_name = importLog, unchecked_return_type = "ImportResult")]
pub fn import_log(
    #[wasm_bindgen(unchecked_param_type = "Recipe")] recipe: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Record<string, Uint8Array>")] files: JsValue,
) -> JsResult<JsValue> {
    // Through JSON, so unknown (misspelled) fields are refused as the CLI refuses them.
    let recipe: gyrodrift::import::Recipe = serde_json::from_value(js_json("recipe", &recipe)?).map_err(|e| err(format!("recipe: {e}")))?;
    let (log, summary) = import::import_unzipped(&recipe, raw_files(&files)?).map_err(err)?;
    let out = Object::new();
    set(&out, "log", &JsValue::from(Log::new(log)))?;
    set(&out, "summary", &to_js(&summary)?)?;
    Ok(out.into())
}

/// A v1 log whose time repeats or steps back by at most 1 s, put in time order (core's
/// `parse_log_in_time_order`: rows of one time merged by their mean, rows up to 1 s late
/// sorted in), or whose last line a logger cut short (dropped): `{ log, fixed }`, `fixed`
/// saying what was done ("" when nothing). A clock reset (more than 1 s back) throws,
/// naming the line. `Log.fromBytes` refuses such a log.
#[wasm_bindgen(js_name = logInTimeOrder, unchecked_return_type = "{ log: Log; fixed: string }")]
pub fn log_in_time_order(#[wasm_bindgen(unchecked_param_type = "Uint8Array | ArrayBuffer")] bytes: JsValue) -> JsResult<JsValue> {
    let bytes = js_bytes(&bytes, "logInTimeOrder(bytes)")?;
    let (log, fixed) = gyrodrift::log::accept::parse_fixing(&bytes[..]).map_err(refusal)?;
    let out = Object::new();
    set(&out, "log", &JsValue::from(Log::new(log)))?;
    set(&out, "fixed", &JsValue::from_str(&fixed))?;
    Ok(out.into())
}

/// Each log of a file that holds several joined on (`cat a.csv b.csv`, a logger appending
/// each session; core's `log::accept::parse_joined`, as the CLI's `split`), its time put in
/// order as by `logInTimeOrder`: `[{ log, fixed, line }]`, `line` where it starts in the file.
/// The other parsers refuse such a file, naming the second log's first line.
#[wasm_bindgen(js_name = logsJoined, unchecked_return_type = "{ log: Log; fixed: string; line: number }[]")]
pub fn logs_joined(#[wasm_bindgen(unchecked_param_type = "Uint8Array | ArrayBuffer")] bytes: JsValue) -> JsResult<JsValue> {
    let bytes = js_bytes(&bytes, "logsJoined(bytes)")?;
    let logs = gyrodrift::log::accept::parse_joined(&bytes[..], gyrodrift::log::accept::TimeOrder::Fix).map_err(refusal)?;
    let out = js_sys::Array::new();
    for (log, fixed, line) in logs {
        let o = Object::new();
        set(&o, "log", &JsValue::from(Log::new(log)))?;
        set(&o, "fixed", &JsValue::from_str(&fixed.unwrap_or_default()))?;
        set(&o, "line", &JsValue::from_f64(line as f64))?;
        out.push(&o);
    }
    Ok(out.into())
}

/// `files` as name -> bytes, as given.
fn raw_files(files: &JsValue) -> JsResult<BTreeMap<String, Vec<u8>>> {
    let obj: &Object =
        files.dyn_ref().filter(|_| files.is_object()).ok_or_else(|| type_err("files: expected an object of name -> Uint8Array"))?;
    let mut map = BTreeMap::new();
    for key in Object::keys(obj).iter() {
        let name = key.as_string().unwrap_or_default();
        let v = Reflect::get(obj, &key)?;
        let bytes: &Uint8Array = v.dyn_ref().ok_or_else(|| err(format!("files[\"{name}\"]: expected a Uint8Array")))?;
        map.insert(name, bytes.to_vec());
    }
    Ok(map)
}

/// Which logger wrote these raw files (by their names and headers; a ZIP archive among
/// them as the tables inside it, the recipe then named by the archive): `{ preset, title,
/// recipe, used: [[role, file]], ignored }`, the recipe ready for `importLog`. Throws an
/// Error naming the closest preset and the column it lacked when none fits.
#[wasm_bindgen(js_name = detectImport, unchecked_return_type = "Detection")]
pub fn detect_import(#[wasm_bindgen(unchecked_param_type = "Record<string, Uint8Array>")] files: JsValue) -> JsResult<JsValue> {
    let (d, _) = import::detect_unzipped(raw_files(&files)?).map_err(err)?;
    let out = Object::new();
    set(&out, "preset", &d.preset.into())?;
    set(&out, "title", &d.title.into())?;
    set(&out, "recipe", &to_js(&d.recipe_json)?)?;
    set(&out, "used", &to_js(&d.used)?)?;
    set(&out, "ignored", &to_js(&d.ignored)?)?;
    Ok(out.into())
}

/// For raw files no preset reads: a draft recipe from their column names, `{ recipe,
/// guesses }` (each guess a line to check before use; core's `draft_recipe`). Throws when
/// a file is not a text table or no column reads as a yaw rate.
#[wasm_bindgen(js_name = draftRecipe, unchecked_return_type = "Draft")]
pub fn draft_recipe(#[wasm_bindgen(unchecked_param_type = "Record<string, Uint8Array>")] files: JsValue) -> JsResult<JsValue> {
    let heads: Vec<(String, Vec<u8>)> = raw_files(&files)?.into_iter().collect();
    let d = import::draft_recipe(&heads).map_err(err)?;
    let out = Object::new();
    set(&out, "recipe", &to_js(&d.recipe_json)?)?;
    set(&out, "guesses", &to_js(&d.guesses)?)?;
    Ok(out.into())
}

/// What raw files' columns are, read from their names and first rows (core's
/// `column_guesses`): each file's time column and every column's time format and units,
/// then the columns guessed for the yaw rate, three gyro and accelerometer axes, a course,
/// latitude and longitude, a speed and a temperature (each by its file's index in `files`,
/// which lists them in name order). The dashboard's column mapper starts from these.
/// Throws when a file is not a text table.
#[wasm_bindgen(js_name = columnGuesses, unchecked_return_type = "ColumnGuesses")]
pub fn column_guesses(#[wasm_bindgen(unchecked_param_type = "Record<string, Uint8Array>")] files: JsValue) -> JsResult<JsValue> {
    let heads: Vec<(String, Vec<u8>)> = raw_files(&files)?.into_iter().collect();
    to_js(&import::column_guesses(&heads).map_err(err)?)
}

/// A recipe as TOML text (the format of `sample-logs/recipes`, `gyrodrift import --recipe`),
/// checked as a recipe first (core's `recipe_value_to_toml`).
#[wasm_bindgen(js_name = recipeToToml)]
pub fn recipe_to_toml(#[wasm_bindgen(unchecked_param_type = "Recipe")] recipe: JsValue) -> JsResult<String> {
    import::recipe_value_to_toml(&js_json("recipe", &recipe)?).map_err(err)
}

/// A recipe from TOML text, checked as the CLI checks it (unknown fields refused).
#[wasm_bindgen(js_name = recipeFromToml, unchecked_return_type = "Recipe")]
pub fn recipe_from_toml(text: &str) -> JsResult<JsValue> {
    to_js(&import::recipe_value_from_toml(text).map_err(err)?)
}
