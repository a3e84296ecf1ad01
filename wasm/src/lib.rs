//! WebAssembly bindings of gyrodrift. Thin: they translate types (option objects in,
//! plain result objects and Float64Array series out) and errors (every core error becomes a
//! thrown JS `Error` with the same message the CLI prints). No science here, and no panic:
//! every fallible call returns `Result`. One file per concern: conversions, the log
//! registry, batch methods, streaming estimators, import, plotting, TypeScript types.

use wasm_bindgen::prelude::*;

mod batch;
mod convert;
mod import;
mod log;
mod plot;
mod streaming;
mod types;

pub use batch::*;
pub use import::*;
pub use log::Log;
pub use streaming::*;

type JsResult<T> = Result<T, JsValue>;
