//! Batch methods over a parsed log: HDR, Gyrodometry, calibration, Allan, report, tune,
//! simulate, the pipeline and the comparison; one file per family.

pub(crate) use crate::convert::*;
pub(crate) use crate::log::Log;
pub(crate) use crate::view::{columns_object, reduced, View};
pub(crate) use crate::JsResult;
pub(crate) use gyrodrift::hdr::{self, HdrOptions, HdrParams};
pub(crate) use gyrodrift::{allan, calibration, gyrodometry, report, sim, tune, DriveLog};
pub(crate) use js_sys::Object;
pub(crate) use serde::Serialize;
pub(crate) use std::rc::Rc;
pub(crate) use wasm_bindgen::prelude::*;

/// `{ result, error }` of a batch run: the Result keys, or why there are none.
pub(crate) fn result_object<T: Serialize>(result: &gyrodrift::Result<T>) -> JsResult<Object> {
    let out = Object::new();
    let (r, e) = match result {
        Ok(r) => (to_js(r)?, JsValue::NULL),
        Err(e) => (JsValue::NULL, JsValue::from_str(&e.to_string())),
    };
    set(&out, "result", &r)?;
    set(&out, "error", &e)?;
    Ok(out)
}

/// `{ result, error, eps0_dps }` of a batch run with a static bias.
pub(crate) fn run_object<T: Serialize>(result: &gyrodrift::Result<T>, eps0_dps: f64) -> JsResult<Object> {
    let out = result_object(result)?;
    set(&out, "eps0_dps", &JsValue::from_f64(eps0_dps))?;
    Ok(out)
}

mod fleet;
mod hdr_runs;
mod methods;
mod pipeline;
mod settings;
mod util;

pub use fleet::*;
pub use hdr_runs::*;
pub use methods::*;
pub use pipeline::*;
pub use settings::*;
pub use util::*;
