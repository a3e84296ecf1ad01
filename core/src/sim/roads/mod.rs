//! Road geometry statistics that matter to drift estimators, measured the same way on recorded
//! and simulated drives so the simulator can be held against reality (issue 13): how much of
//! the moving time the yaw rate stays below HDR's theta_w, how long such "straight" runs and
//! the curves between them last, how sharp the curves are, and how far the slow (30 s) yaw
//! rate strays from zero on roads that look straight, and the yaw rate's spectrum in period
//! bands; per road class (by speed), since recorded drives are not labelled by road type.

mod compare;
pub mod events;
mod samples;
pub mod spectrum;

pub use compare::{
    cdf_points, compare, ks_distance, simulated_samples, statistic, ClassComparison, RoadComparison, RoadDistance, STATISTICS,
};
pub use samples::{road_samples, ClassedSamples, RoadClass, RoadSamples, RoadSummary};

/// Moving means faster than this, m/s; still means slower than `STILL_MPS`.
pub const MOVING_MPS: f64 = 3.0;
pub const STILL_MPS: f64 = 0.3;
/// HDR's Table-III threshold theta_w, deg/s: below it HDR calls the road straight.
pub const THETA_W_DPS: f64 = 0.564;
/// Road classes by the mean speed of the surrounding minute: urban below 14 m/s (50 km/h),
/// highway above 25 m/s (90 km/h), rural between.
pub const URBAN_MAX_MPS: f64 = 14.0;
pub const HIGHWAY_MIN_MPS: f64 = 25.0;
/// Window of the speed that classifies a block, s (centred).
pub const CLASS_WINDOW_S: usize = 60;
