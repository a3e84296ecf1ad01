//! WebAssembly bindings of gyrodrift. Thin: they translate types (option objects in,
//! plain result objects and Float64Array series out) and errors (every core error becomes a
//! thrown JS `Error` with the same message the CLI prints). No science here, and no panic:
//! every fallible call returns `Result`. One file per concern: conversions, the log
//! registry, batch methods, streaming estimators, views for drawing, import, plotting,
//! TypeScript types.

// A build with only some features (scripts/lib.sh builds the parts) leaves helpers unused.
#![cfg_attr(
    not(all(feature = "core", feature = "import", feature = "plot", feature = "tune", feature = "sim", feature = "live")),
    allow(dead_code, unused_imports)
)]

use wasm_bindgen::prelude::*;

#[cfg(feature = "core")]
mod batch;
mod convert;
#[cfg(feature = "import")]
mod import;
#[cfg(feature = "core")]
mod log;
#[cfg(feature = "core")]
mod log_builder;
#[cfg(feature = "plot")]
mod plot;
#[cfg(feature = "core")]
mod streaming;
#[cfg(feature = "live")]
mod streaming_pipeline;
mod types;
#[cfg(feature = "core")]
mod view;

#[cfg(feature = "core")]
pub use batch::*;
#[cfg(feature = "import")]
pub use import::*;
#[cfg(feature = "core")]
pub use log::Log;
#[cfg(feature = "core")]
pub use log_builder::*;
#[cfg(feature = "core")]
pub use streaming::*;
#[cfg(feature = "live")]
pub use streaming_pipeline::*;
#[cfg(feature = "core")]
pub use view::reduce_series;

type JsResult<T> = Result<T, JsValue>;
