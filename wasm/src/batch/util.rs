//! Small helpers for pages: a series' value at a time, and what a file is by its first bytes.

use super::*;

/// The value of a series at time t, linearly interpolated (core's rule), NaN outside.
#[wasm_bindgen(js_name = valueAt)]
pub fn value_at(x: &[f64], y: &[f64], t: f64) -> f64 {
    gyrodrift::metrics::value_at(x, y, t)
}

/// Whether a file (its first bytes suffice) is a drive log v1 already, not a raw export.
/// The `full` module and Node's read the head as they read logs (a spreadsheet's metadata
/// lines padded or quoted, Windows-1252); the page's module as written, so it says no to a
/// head that is not UTF-8 or whose metadata a spreadsheet quoted.
#[wasm_bindgen(js_name = isDriveLog)]
pub fn is_drive_log(name: &str, head: &[u8]) -> bool {
    #[cfg(feature = "import")]
    return gyrodrift::import::is_drive_log_head(name, head);
    #[cfg(not(feature = "import"))]
    gyrodrift::import::sniff(name, head).is_ok_and(|s| s.is_drive_log())
}

/// A raw file's dialect and header from its first bytes (`{ name, delimiter, decimal_comma,
/// skip_lines, header }`), for a page that maps columns by hand; throws for a binary file.
#[wasm_bindgen(js_name = sniffFile, unchecked_return_type = "Sniffed")]
pub fn sniff_file(name: &str, head: &[u8]) -> JsResult<JsValue> {
    to_js(&gyrodrift::import::sniff(name, head).map_err(err)?)
}
