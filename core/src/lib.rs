//! gyrodrift: a cheap yaw-rate gyro turned into a usable heading source, with the three
//! methods of the University of Michigan mobile-robotics lab read exactly as
//! `shared/spec/methods.md` fixes them:
//!
//! - [`hdr`]: Heuristic Drift Reduction (Borenstein & Ojeda), streaming, Eqs. 7-14;
//! - [`gyrodometry`]: odometry heading replaced by the gyro's while they disagree (Borenstein & Feng);
//! - [`calibration`]: static bias, rate x temperature error model, compensation (Ojeda, Chung & Borenstein);
//! - [`allan`]: overlapping Allan deviation, ARW and bias instability;
//! - [`metrics`]: E_psi, NE_psi and improvement against a reference heading;
//! - [`log`]: the drive-log CSV v1, parsed streaming from any `Read`;
//! - [`import`]: recorded logs in any tabular format to v1, by a declarative recipe;
//! - [`pipeline`]: the recommended drift reduction beyond the paper (bias Kalman filter with
//!   zero-rate updates at stops and HDR's straight-road heuristic as weak evidence), with
//!   [`still`] detection and the [`peers`] it is compared with.
//!
//! Pure Rust: no I/O beyond `Read`/`Write`, no wasm or browser types; errors, never panics,
//! on bad input.

// NaN-rejecting comparisons (`!(x > 0.0)`) are intended throughout: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Numeric loops over several parallel arrays read clearer with an index.
#![allow(clippy::needless_range_loop)]

pub mod allan;
pub mod axis;
pub mod battery;
pub mod calibration;
pub mod check;
pub mod compare;
pub mod decimate;
pub mod error;
pub mod eval;
pub mod export;
pub mod fleet;
pub mod gyrodometry;
pub mod hdr;
pub mod import;
pub mod line;
pub mod log;
pub mod metrics;
pub mod options;
pub mod peers;
pub mod pipeline;
pub mod preprocess;
pub mod report;
pub mod series;
pub mod sim;
#[cfg(feature = "snapshot")]
pub mod snapshot;
pub mod still;
pub mod table;
pub mod track;
pub mod tune;

pub use error::{Error, Result};
pub use log::{parse_log, parse_log_str, Column, DriveLog, LogKind, LogMeta};
