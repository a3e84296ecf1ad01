//! The log registry: parsed logs held in wasm memory, named, passed to every method.

use crate::convert::*;
use crate::JsResult;
use gyrodrift::DriveLog;
use js_sys::{Array, Float64Array, Object, Reflect};
use std::cell::{Cell, RefCell};
use std::rc::Rc;

thread_local! {
    /// Live logs by id (a short list: a Vec beats a HashMap here in code size and speed).
    static LOGS: RefCell<Vec<(u32, Rc<DriveLog>)>> = const { RefCell::new(Vec::new()) };
    static NEXT_ID: Cell<u32> = const { Cell::new(1) };
}
use wasm_bindgen::prelude::*;

/// A parsed drive log. Pass it to the functions below as often as needed; `free()` it (or
/// let the garbage collector do so) when done.
#[wasm_bindgen]
pub struct Log {
    id: u32,
    pub(crate) log: Rc<DriveLog>,
    pub(crate) name: String,
    /// HDR's last preparation of this log (samples, reference), reused while the lead-in
    /// and blocks stay the same: a slider step re-runs only the method.
    pub(crate) hdr_prepared: RefCell<Option<Rc<gyrodrift::hdr::Prepared>>>,
}

impl Drop for Log {
    fn drop(&mut self) {
        let id = self.id;
        LOGS.with(|m| m.borrow_mut().retain(|(k, _)| *k != id));
    }
}

impl Log {
    /// HDR's preparation for these options: the cached one when it fits, else a new one.
    pub(crate) fn hdr_prepared(&self, opts: &gyrodrift::hdr::HdrOptions) -> gyrodrift::Result<Rc<gyrodrift::hdr::Prepared>> {
        if let Some(p) = self.hdr_prepared.borrow().as_ref().filter(|p| p.fits(opts)) {
            return Ok(p.clone());
        }
        let p = Rc::new(gyrodrift::hdr::prepare(&self.log, opts)?);
        *self.hdr_prepared.borrow_mut() = Some(p.clone());
        Ok(p)
    }

    pub(crate) fn new(log: DriveLog) -> Log {
        let id = NEXT_ID.with(|n| {
            let id = n.get();
            n.set(id.wrapping_add(1).max(1));
            id
        });
        let log = Rc::new(log);
        LOGS.with(|m| m.borrow_mut().push((id, log.clone())));
        let name = log.meta.name.clone().unwrap_or_default();
        Log { id, log, name, hdr_prepared: RefCell::new(None) }
    }

    /// The logs of a JS array of `Log` objects, with their names, without taking them. One
    /// `check` finds an error in (core's `refusal`: time not in seconds, heading in radians,
    /// gyro in another unit or clockwise) is refused, as the CLI refuses it, unless
    /// `ignore_check`.
    pub(crate) fn from_array(value: &JsValue, what: &str, ignore_check: Option<bool>) -> JsResult<Vec<(String, Rc<DriveLog>)>> {
        if value.is_undefined() || value.is_null() {
            return Ok(Vec::new());
        }
        let arr: &Array = value.dyn_ref().ok_or_else(|| err(format!("{what}: expected an array of Log")))?;
        let mut out = Vec::with_capacity(arr.length() as usize);
        for (i, item) in arr.iter().enumerate() {
            let id = Reflect::get(&item, &JsValue::from_str("id"))
                .ok()
                .and_then(|v| v.as_f64())
                .ok_or_else(|| err(format!("{what}[{i}]: not a Log")))?;
            let name = Reflect::get(&item, &JsValue::from_str("name")).ok().and_then(|v| v.as_string());
            let log = LOGS
                .with(|m| m.borrow().iter().find(|(k, _)| *k == id as u32).map(|(_, l)| l.clone()))
                .ok_or_else(|| err(format!("{what}[{i}]: this Log was freed")))?;
            let name = name.filter(|n| !n.is_empty()).unwrap_or_else(|| format!("log {}", i + 1));
            if ignore_check != Some(true) {
                if let Some(r) = gyrodrift::log::accept::refusal(&log) {
                    let message = format!("{name}: {}", gyrodrift::log::accept::check_refused(&r, "ignore_check = true"));
                    return Err(check_refusal(&name, message));
                }
            }
            out.push((name, log));
        }
        Ok(out)
    }
}

/// A v1 log's bytes parsed, `progress(bytes read)` now and then. With the import's code (the
/// worker's module and Node's), a log as a spreadsheet saved it (`;` and decimal commas,
/// metadata lines padded or quoted, Windows-1252 text) reads as the log, and one with a second
/// log joined on is refused naming that log's first line (core's `log::dialect`; a last line
/// cut short still refused); the size-budgeted page module reads the format as written.
pub(crate) fn parse_v1(bytes: &[u8], progress: &mut dyn FnMut(u64)) -> gyrodrift::Result<gyrodrift::DriveLog> {
    #[cfg(feature = "import")]
    {
        let mut reader = gyrodrift::log::dialect::comma_separated(bytes);
        let parsed = gyrodrift::log::parse_log_progress(&mut reader, Default::default(), progress);
        reader.refuse_joined(parsed)
    }
    #[cfg(not(feature = "import"))]
    gyrodrift::log::parse_log_progress(bytes, Default::default(), progress)
}

/// [`parse_v1`] without progress. The page module calls the parser's own entry: 36 bytes
/// smaller gzipped than through `parse_v1`'s closure (BENCHMARKS.md).
fn parse_v1_whole(bytes: &[u8]) -> gyrodrift::Result<gyrodrift::DriveLog> {
    #[cfg(feature = "import")]
    return parse_v1(bytes, &mut |_| {});
    #[cfg(not(feature = "import"))]
    gyrodrift::parse_log(bytes)
}

#[wasm_bindgen]
impl Log {
    /// Parses CSV v1 text; a bad file throws an Error naming line and column. The `full`
    /// module and Node's also read a log as a spreadsheet saved it (`;` or tabs and decimal
    /// commas, metadata lines padded or quoted, Windows-1252 text).
    pub fn parse(#[wasm_bindgen(unchecked_param_type = "string")] text: JsValue) -> JsResult<Log> {
        let text = js_string(&text, "Log.parse(text)")?;
        parse_v1_whole(text.as_bytes()).map(Log::new).map_err(refusal)
    }

    /// Parses CSV v1 bytes (e.g. from a File's arrayBuffer()); a spreadsheet's log as
    /// `parse` says.
    #[wasm_bindgen(js_name = fromBytes)]
    pub fn from_bytes(#[wasm_bindgen(unchecked_param_type = "Uint8Array | ArrayBuffer")] bytes: JsValue) -> JsResult<Log> {
        let bytes = js_bytes(&bytes, "Log.fromBytes(bytes)")?;
        parse_v1_whole(&bytes).map(Log::new).map_err(refusal)
    }

    /// Parses CSV v1 bytes, calling `progress(fraction)` now and then (for a Web Worker
    /// parsing a large file).
    #[wasm_bindgen(js_name = fromBytesWithProgress)]
    pub fn from_bytes_with_progress(
        #[wasm_bindgen(unchecked_param_type = "Uint8Array | ArrayBuffer")] bytes: JsValue,
        progress: &js_sys::Function,
    ) -> JsResult<Log> {
        let bytes = js_bytes(&bytes, "Log.fromBytesWithProgress(bytes)")?;
        let total = bytes.len().max(1) as f64;
        let mut cb = |b: u64| {
            let _ = progress.call1(&JsValue::NULL, &JsValue::from_f64(b as f64 / total));
        };
        parse_v1(&bytes, &mut cb).map(Log::new).map_err(refusal)
    }

    /// The parsed log as plain data `{ meta, line, columns: { name: Float64Array } }`,
    /// whose buffers can be transferred from a worker; `Log.fromColumns` takes it back.
    #[wasm_bindgen(js_name = toColumns, unchecked_return_type = "LogColumns")]
    pub fn to_columns(&self) -> JsResult<JsValue> {
        let out = Object::new();
        set(&out, "meta", &to_js(&self.log.meta)?)?;
        let lines: Vec<f64> = self.log.line.iter().map(|&l| l as f64).collect();
        set(&out, "line", &f64s(&lines))?;
        let cols = Object::new();
        for (c, v) in self.log.columns() {
            set(&cols, c.name(), &f64s(v))?;
        }
        set(&out, "columns", &cols)?;
        Ok(out.into())
    }

    /// A log from `toColumns()` data, checked as the parser checks.
    #[wasm_bindgen(js_name = fromColumns)]
    pub fn from_columns(#[wasm_bindgen(unchecked_param_type = "LogColumns")] data: JsValue) -> JsResult<Log> {
        let ColumnData { meta, line, cols } = read_columns(&data);
        DriveLog::from_columns(meta, line, cols).map(Log::new).map_err(err)
    }

    /// An identifier, used when a Log is passed inside an array.
    #[wasm_bindgen(getter)]
    pub fn id(&self) -> u32 {
        self.id
    }

    /// The log's `# name:` (settable; used in reports).
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.name.clone()
    }
    #[wasm_bindgen(setter)]
    pub fn set_name(&mut self, #[wasm_bindgen(unchecked_param_type = "string")] name: JsValue) -> JsResult<()> {
        self.name = js_string(&name, "Log.name")?;
        Ok(())
    }

    /// "drive", "robot", "turntable" or "static", from the columns.
    #[wasm_bindgen(getter, unchecked_return_type = "LogKind")]
    pub fn kind(&self) -> JsResult<JsValue> {
        to_js(&self.log.kind())
    }

    /// Whether a reference heading can score it: a `ref_heading_deg` column with a value
    /// (core's rule; without one the methods run and nothing is scored).
    #[wasm_bindgen(getter, js_name = hasReference)]
    pub fn has_reference(&self) -> bool {
        self.log.has_reference()
    }

    /// Last minus first time, minutes.
    #[wasm_bindgen(getter, js_name = durationMin)]
    pub fn duration_min(&self) -> f64 {
        self.log.duration_min()
    }

    /// Number of data rows.
    #[wasm_bindgen(getter, js_name = rowCount)]
    pub fn row_count(&self) -> usize {
        self.log.len()
    }

    /// The `# key: value` metadata.
    #[wasm_bindgen(unchecked_return_type = "LogMeta")]
    pub fn meta(&self) -> JsResult<JsValue> {
        to_js(&self.log.meta)
    }

    /// The known columns present in the file, in CSV v1 order.
    pub fn columns(&self) -> Vec<String> {
        self.log.present_columns().iter().map(|c| c.name().to_string()).collect()
    }

    /// One column's cells as a Float64Array (NaN = empty cell).
    pub fn column(&self, #[wasm_bindgen(unchecked_param_type = "string")] name: JsValue) -> JsResult<Float64Array> {
        let name = js_string(&name, "Log.column(name)")?;
        let c = gyrodrift::Column::from_name(&name).ok_or_else(|| err(format!("unknown column {name}")))?;
        let v = self.log.require(c, "not in this log").map_err(err)?;
        Ok(Float64Array::from(v))
    }

    /// The log split at its gaps in time (as the CLI's `--gaps split`): `parts` are drives of
    /// their own (one part, this log's copy, when there is no gap), `summary` says what was
    /// done. `bias_s` is the static-bias window (default: the log's, else `defaultBiasS()`).
    #[wasm_bindgen(js_name = splitAtGaps, unchecked_return_type = "GapSplit")]
    pub fn split_at_gaps(&self, bias_s: Option<f64>) -> JsResult<JsValue> {
        if bias_s.is_some_and(|b| !b.is_finite()) {
            return Err(type_err("Log.splitAtGaps(bias_s): expected a finite number of seconds"));
        }
        let s = gyrodrift::log::gaps::split_at_gaps((*self.log).clone(), Default::default(), self.log.bias_s(bias_s)).map_err(err)?;
        let parts = Array::new();
        for p in s.parts.iter().cloned() {
            parts.push(&JsValue::from(Log::new(p)));
        }
        let summary = s.summary().map(|t| JsValue::from_str(&t)).unwrap_or(JsValue::NULL);
        Ok(object_of(&[
            ("parts", parts.into()),
            ("gaps", to_js(&s.gaps)?),
            ("dropped", JsValue::from(s.dropped.len() as u32)),
            ("summary", summary),
        ])?
        .into())
    }

    /// The log as CSV v1 text.
    #[wasm_bindgen(js_name = toCsv)]
    pub fn to_csv(&self) -> JsResult<String> {
        let mut buf = Vec::new();
        self.log.write_csv(&mut buf).map_err(err)?;
        String::from_utf8(buf).map_err(err)
    }
}

/// `toColumns()` data (or a chunk of it) as core's pieces.
pub(crate) struct ColumnData {
    pub meta: gyrodrift::LogMeta,
    pub line: Vec<u64>,
    /// The columns present, in core's order.
    pub cols: Vec<(gyrodrift::Column, Vec<f64>)>,
}

/// Reads `toColumns()` data (or a chunk of it): meta, lines, the present columns.
pub(crate) fn read_columns(data: &JsValue) -> ColumnData {
    let get = |o: &JsValue, k: &str| Reflect::get(o, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED);
    let meta: gyrodrift::LogMeta = serde_wasm_bindgen::from_value(get(data, "meta")).unwrap_or_default();
    let line: Vec<u64> =
        get(data, "line").dyn_into::<Float64Array>().map(|a| a.to_vec().into_iter().map(|v| v as u64).collect()).unwrap_or_default();
    let cols_obj = get(data, "columns");
    let mut cols = Vec::new();
    for c in gyrodrift::Column::ALL {
        if let Some(a) = get(&cols_obj, c.name()).dyn_ref::<Float64Array>() {
            cols.push((c, a.to_vec()));
        }
    }
    ColumnData { meta, line, cols }
}
