//! Gyrodometry (Borenstein & Feng, seed 001): odometry heading increments, replaced by
//! the gyro's while the two disagree by more than a threshold (bumps, slip).
//! Streaming estimator plus a batch run scored with the shared metrics (methods.md detail 7).

use crate::error::{Error, Result};
use crate::log::{Column, DriveLog};
use crate::metrics::{self, Reference};
use crate::preprocess;
use serde::{Deserialize, Serialize};

/// Settings of Gyrodometry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GyrodometryOptions {
    /// Threshold rate; per interval thres_i = thres_rate * T_i (0.125 deg per 0.1 s).
    #[serde(alias = "thres_rate")]
    pub thres_rate_dps: f64,
    /// Wheelbase b, m; None = the log's `# wheelbase_m:`.
    #[serde(alias = "wheelbase")]
    pub wheelbase_m: Option<f64>,
    /// Static-bias window, s; None = the log's `# bias_s:` or 20 s.
    pub bias_s: Option<f64>,
}

impl Default for GyrodometryOptions {
    fn default() -> Self {
        GyrodometryOptions { thres_rate_dps: 1.25, wheelbase_m: None, bias_s: None }
    }
}

impl crate::options::Settings for GyrodometryOptions {
    /// Threshold rate, wheelbase (a vehicle's, 5 cm to 50 m) and static-bias window.
    fn validate(&self) -> Result<()> {
        let t = self.thres_rate_dps;
        if !(t.is_finite() && (0.0..=1000.0).contains(&t)) {
            return Err(Error::param("thres_rate", format!("{t} is not a rate in [0, 1000] deg/s")));
        }
        if let Some(b) = self.wheelbase_m {
            if !(b.is_finite() && (0.05..=50.0).contains(&b)) {
                return Err(Error::param("wheelbase_m", format!("{b} is not a wheelbase in [0.05, 50] m")));
            }
        }
        crate::options::check_bias_s(self.bias_s)
    }
}

/// One step of Gyrodometry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GyrodometryOutput {
    pub time_s: f64,
    /// Odometry-only heading, deg.
    pub heading_odo_deg: f64,
    /// Gyro-only heading (eps0 removed), deg.
    pub heading_gyro_deg: f64,
    /// Gyrodometry heading, deg.
    pub heading_deg: f64,
    /// Whether this interval used the gyro increment.
    pub used_gyro: bool,
}

/// The streaming Gyrodometry estimator.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone)]
pub struct Gyrodometry {
    wheelbase_m: f64,
    thres_rate_dps: f64,
    eps0_dps: f64,
    last: Option<(f64, f64, f64)>,
    odo: f64,
    gyro: f64,
    fused: f64,
}

/// Odometry heading increment (seed 001): (dR - dL) / b, rad -> deg.
#[inline]
pub fn odo_increment_deg(d_left_m: f64, d_right_m: f64, wheelbase_m: f64) -> f64 {
    ((d_right_m - d_left_m) / wheelbase_m).to_degrees()
}

impl Gyrodometry {
    pub fn new(wheelbase_m: f64, thres_rate_dps: f64, eps0_dps: f64) -> Result<Self> {
        if !(wheelbase_m.is_finite() && wheelbase_m > 0.0) {
            return Err(Error::param("wheelbase_m", format!("{wheelbase_m} is not a length > 0 m")));
        }
        if !(thres_rate_dps.is_finite() && thres_rate_dps >= 0.0) {
            return Err(Error::param("thres_rate", format!("{thres_rate_dps} is not a rate >= 0 deg/s")));
        }
        if !eps0_dps.is_finite() {
            return Err(Error::param("eps0", "the static bias must be finite"));
        }
        Ok(Gyrodometry { wheelbase_m, thres_rate_dps, eps0_dps, last: None, odo: 0.0, gyro: 0.0, fused: 0.0 })
    }

    /// Feeds one row: time, raw gyro rate, cumulative left and right wheel travel.
    pub fn update(&mut self, time_s: f64, rate_raw_dps: f64, odo_left_m: f64, odo_right_m: f64) -> Result<GyrodometryOutput> {
        if !(time_s.is_finite() && rate_raw_dps.is_finite() && odo_left_m.is_finite() && odo_right_m.is_finite()) {
            return Err(Error::data(format!("Gyrodometry update at {time_s} s: a value is not finite")));
        }
        let mut used_gyro = false;
        if let Some((t, l, r)) = self.last {
            let dt = time_s - t;
            if !(dt > 0.0) {
                return Err(Error::data(format!("Gyrodometry update: time {time_s} s is not after the previous {t} s")));
            }
            let d_odo = odo_increment_deg(odo_left_m - l, odo_right_m - r, self.wheelbase_m);
            let d_gyro = (rate_raw_dps - self.eps0_dps) * dt;
            let thres = self.thres_rate_dps * dt;
            used_gyro = (d_gyro - d_odo).abs() > thres;
            self.odo += d_odo;
            self.gyro += d_gyro;
            self.fused += if used_gyro { d_gyro } else { d_odo };
        }
        self.last = Some((time_s, odo_left_m, odo_right_m));
        Ok(GyrodometryOutput { time_s, heading_odo_deg: self.odo, heading_gyro_deg: self.gyro, heading_deg: self.fused, used_gyro })
    }
}

/// Per-row series of a batch run (headings aligned to the reference when there is one).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GyrodometryTrace {
    pub time_s: Vec<f64>,
    pub heading_odo_deg: Vec<f64>,
    pub heading_gyro_deg: Vec<f64>,
    pub heading_gyrodometry_deg: Vec<f64>,
    pub used_gyro: Vec<bool>,
}

impl GyrodometryTrace {
    /// The series of the wasm `runGyrodometry` and Python's `run_gyrodometry`.
    pub fn columns(&self) -> [(&'static str, crate::series::Column<'_>); 5] {
        use crate::series::{values, Column};
        [
            ("time_s", values(&self.time_s)),
            ("heading_odo_deg", values(&self.heading_odo_deg)),
            ("heading_gyro_deg", values(&self.heading_gyro_deg)),
            ("heading_gyrodometry_deg", values(&self.heading_gyrodometry_deg)),
            ("used_gyro", Column::Flags(&self.used_gyro)),
        ]
    }
}

/// The Result keys of methods.md for `gyrodometry`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct GyrodometryResult {
    pub E_psi_odo_deg: f64,
    pub E_psi_gyro_deg: f64,
    pub E_psi_gyrodometry_deg: f64,
    pub NE_psi_odo_deg_per_min: f64,
    pub NE_psi_gyro_deg_per_min: f64,
    pub NE_psi_gyrodometry_deg_per_min: f64,
    pub final_err_odo_deg: f64,
    pub final_err_gyro_deg: f64,
    pub final_err_gyrodometry_deg: f64,
    pub n_gyro_intervals: usize,
    pub n_samples: usize,
    pub eps0_dps: f64,
    pub duration_min: f64,
    pub wheelbase_m: f64,
    pub thres_rate_dps: f64,
}

#[derive(Debug, Clone)]
pub struct GyrodometryRun {
    pub eps0_dps: f64,
    pub trace: GyrodometryTrace,
    pub result: Result<GyrodometryResult>,
}

/// Runs Gyrodometry on the rows that have gyro and both wheel values, from row 0.
pub fn run(log: &DriveLog, opts: &GyrodometryOptions) -> Result<GyrodometryRun> {
    crate::options::Settings::validate(opts)?;
    log.check_span()?;
    let wheelbase_m = opts
        .wheelbase_m
        .or(log.meta.wheelbase_m)
        .ok_or_else(|| Error::param("wheelbase_m", "missing: give it as an option or as `# wheelbase_m:` in the log"))?;
    crate::options::Settings::validate(&GyrodometryOptions { wheelbase_m: Some(wheelbase_m), ..*opts })?;
    let gyro = log.require(Column::GyroDps, "needed by Gyrodometry")?;
    let left = log.require(Column::OdoLeftM, "needed by Gyrodometry")?;
    let right = log.require(Column::OdoRightM, "needed by Gyrodometry")?;
    let eps0 = preprocess::static_bias_dps(log.time_s(), gyro, log.bias_s(opts.bias_s))?;
    let mut est = Gyrodometry::new(wheelbase_m, opts.thres_rate_dps, eps0)?;
    let mut tr = GyrodometryTrace::default();
    let mut n_gyro = 0;
    for (i, &t) in log.time_s().iter().enumerate() {
        let (g, l, r) = (gyro[i], left[i], right[i]);
        if g.is_nan() || l.is_nan() || r.is_nan() {
            continue;
        }
        let o = est.update(t, g, l, r)?;
        n_gyro += o.used_gyro as usize;
        tr.time_s.push(t);
        tr.heading_odo_deg.push(o.heading_odo_deg);
        tr.heading_gyro_deg.push(o.heading_gyro_deg);
        tr.heading_gyrodometry_deg.push(o.heading_deg);
        tr.used_gyro.push(o.used_gyro);
    }
    if tr.time_s.is_empty() {
        return Err(Error::data("no row has gyro_dps, odo_left_m and odo_right_m all present"));
    }
    let result = Reference::from_log(log).and_then(|reference| {
        let odo = metrics::score(&tr.time_s, &tr.heading_odo_deg, &reference)?;
        let gy = metrics::score(&tr.time_s, &tr.heading_gyro_deg, &reference)?;
        let fu = metrics::score(&tr.time_s, &tr.heading_gyrodometry_deg, &reference)?;
        tr.heading_odo_deg.iter_mut().for_each(|p| *p += odo.shift_deg);
        tr.heading_gyro_deg.iter_mut().for_each(|p| *p += gy.shift_deg);
        tr.heading_gyrodometry_deg.iter_mut().for_each(|p| *p += fu.shift_deg);
        let d = log.duration_min();
        Ok(GyrodometryResult {
            E_psi_odo_deg: odo.e_psi_deg,
            E_psi_gyro_deg: gy.e_psi_deg,
            E_psi_gyrodometry_deg: fu.e_psi_deg,
            NE_psi_odo_deg_per_min: metrics::ne_psi(odo.e_psi_deg, d),
            NE_psi_gyro_deg_per_min: metrics::ne_psi(gy.e_psi_deg, d),
            NE_psi_gyrodometry_deg_per_min: metrics::ne_psi(fu.e_psi_deg, d),
            final_err_odo_deg: odo.final_err_deg,
            final_err_gyro_deg: gy.final_err_deg,
            final_err_gyrodometry_deg: fu.final_err_deg,
            n_gyro_intervals: n_gyro,
            n_samples: fu.n_samples,
            eps0_dps: eps0,
            duration_min: d,
            wheelbase_m,
            thres_rate_dps: opts.thres_rate_dps,
        })
    });
    Ok(GyrodometryRun { eps0_dps: eps0, trace: tr, result })
}

/// A live Gyrodometry estimator and its last output, saved and resumed (`snapshot`): the
/// settings checked as a new estimator's.
#[cfg(feature = "snapshot")]
impl crate::snapshot::Resumable for (Gyrodometry, Option<GyrodometryOutput>) {
    const KIND: &'static str = "GyrodometryEstimator";
    fn restored(self) -> Result<Self> {
        Gyrodometry::new(self.0.wheelbase_m, self.0.thres_rate_dps, self.0.eps0_dps)?;
        Ok(self)
    }
}
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odo_increment_hand_worked() {
        // right wheel 0.01 m more over b = 0.5 m: 0.02 rad = 1.1459.. deg, CCW positive
        let d = odo_increment_deg(0.0, 0.01, 0.5);
        assert!((d - 0.02f64.to_degrees()).abs() < 1e-12);
        assert!(odo_increment_deg(0.01, 0.0, 0.5) < 0.0);
    }

    #[test]
    fn switches_to_gyro_only_when_they_disagree() {
        // b = 1 m, thres 1.25 deg/s, T = 0.1 s -> thres 0.125 deg.
        let mut g = Gyrodometry::new(1.0, 1.25, 0.0).unwrap();
        g.update(0.0, 0.0, 0.0, 0.0).unwrap();
        // odometry says 0.0 deg, gyro says 1 deg/s * 0.1 = 0.1 deg: |0.1| <= 0.125 -> odometry
        let o = g.update(0.1, 1.0, 0.0, 0.0).unwrap();
        assert!(!o.used_gyro);
        assert_eq!(o.heading_deg, 0.0);
        // a bump: odometry jumps by 0.01 m on the right wheel = 0.573 deg, gyro says 0 -> gyro used
        let o = g.update(0.2, 0.0, 0.0, 0.01).unwrap();
        assert!(o.used_gyro);
        assert!((o.heading_deg - 0.0).abs() < 1e-15);
        assert!((o.heading_odo_deg - 0.01f64.to_degrees()).abs() < 1e-12);
        assert!((o.heading_gyro_deg - 0.1).abs() < 1e-15);
    }

    #[test]
    fn bad_settings_are_errors() {
        assert!(Gyrodometry::new(0.0, 1.25, 0.0).is_err());
        assert!(Gyrodometry::new(f64::NAN, 1.25, 0.0).is_err());
        assert!(Gyrodometry::new(0.5, -1.0, 0.0).is_err());
    }

    #[test]
    fn missing_wheelbase_is_an_error() {
        let log = crate::log::parse_log_str("time_s,gyro_dps,odo_left_m,odo_right_m,ref_heading_deg\n0,0,0,0,0\n1,0,0,0,0\n").unwrap();
        let e = run(&log, &GyrodometryOptions::default()).unwrap_err();
        assert!(e.to_string().contains("wheelbase_m"), "{e}");
        let ok = run(&log, &GyrodometryOptions { wheelbase_m: Some(0.5), bias_s: Some(0.0), ..Default::default() });
        assert!(ok.is_ok());
    }
}
