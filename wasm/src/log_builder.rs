//! A log handed over in pieces (a big log parsed in a worker): the page copies one chunk
//! per task, so no single task holds it for the whole copy. The checks are core's.

use crate::convert::*;
use crate::log::{read_columns, ColumnData, Log};
use crate::JsResult;
use wasm_bindgen::prelude::*;

/// Builds a `Log` from chunks of `toColumns()` data: `new LogBuilder(firstChunk, rows)`
/// (its meta and columns make the log's), `append(chunk)` for the rest, then `finish()`.
#[wasm_bindgen]
pub struct LogBuilder {
    inner: Option<gyrodrift::log::LogBuilder>,
}

#[wasm_bindgen]
impl LogBuilder {
    /// A builder with the first chunk's meta and columns (`time_s` among them), room for
    /// `rows` rows, and the first chunk's rows.
    #[wasm_bindgen(constructor)]
    pub fn new(#[wasm_bindgen(unchecked_param_type = "LogColumns")] first: JsValue, rows: f64) -> JsResult<LogBuilder> {
        let ColumnData { meta, line, cols } = read_columns(&first);
        let names: Vec<gyrodrift::Column> = cols.iter().map(|c| c.0).collect();
        let hint = if rows.is_finite() && rows >= 0.0 { rows.min(1e9) as usize } else { 0 };
        let mut b = gyrodrift::log::LogBuilder::new(meta, &names, hint).map_err(err)?;
        b.append(line, cols).map_err(err)?;
        Ok(LogBuilder { inner: Some(b) })
    }

    /// Appends a chunk `{ line?, columns }` holding every column of the log; a chunk that
    /// breaks a rule is refused whole (the error names its line and column) and the
    /// builder stays as it was.
    pub fn append(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Omit<LogColumns, \"meta\"> | LogColumns")] chunk: JsValue,
    ) -> JsResult<()> {
        let b = self.inner.as_mut().ok_or_else(|| err("LogBuilder: already finished"))?;
        let ColumnData { line, cols, .. } = read_columns(&chunk);
        b.append(line, cols).map_err(err)
    }

    /// The log (the builder is spent).
    pub fn finish(&mut self) -> JsResult<Log> {
        let b = self.inner.take().ok_or_else(|| err("LogBuilder: already finished"))?;
        b.finish().map(Log::new).map_err(err)
    }
}
