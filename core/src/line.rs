//! A least-squares line of z on t from running sums: `check` takes a warming gyro's bias at
//! each turn from one, the pipeline tests a lead-in for a warm-up with another. One small
//! type for both, since each copy is code of its own in the size-capped wasm module.

/// Running sums of 1, t, t^2, z, t z and z^2 over the points added.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LineSums([f64; 6]);

impl LineSums {
    /// Adds the point (t, z).
    pub fn add(&mut self, t: f64, z: f64) {
        let s = &mut self.0;
        s[0] += 1.0;
        s[1] += t;
        s[2] += t * t;
        s[3] += z;
        s[4] += t * z;
        s[5] += z * z;
    }

    /// How many points were added.
    pub fn count(&self) -> f64 {
        self.0[0]
    }

    /// The means of t and z (not numbers without points).
    pub fn means(&self) -> (f64, f64) {
        let [n, t, _, z, _, _] = self.0;
        (t / n, z / n)
    }

    /// The slope, its variance from the residuals (z's units per t's unit, squared), and the
    /// spread of t about its mean (sum of squares): with fewer than two points or a single
    /// t the slope is not a number (or infinite) and the spread is 0; the variance needs
    /// three points.
    pub fn slope(&self) -> (f64, f64, f64) {
        let [n, t, tt, z, tz, zz] = self.0;
        let (sxx, sxy) = (tt - t * t / n, tz - t * z / n);
        let slope = sxy / sxx;
        (slope, (zz - z * z / n - slope * sxy) / (n - 2.0) / sxx, sxx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Four points (0, 0), (1, 1), (2, 1), (3, 2): sxx = 14 - 36/4 = 5, sxy = 9 - 6 x 4/4 =
    /// 3, syy = 6 - 16/4 = 2; slope 3/5 = 0.6, residual variance (2 - 0.6 x 3)/2 = 0.1, the
    /// slope's variance 0.1/5 = 0.02; means 1.5 and 1. One point: no slope, no spread.
    #[test]
    fn a_line_hand_worked() {
        let mut s = LineSums::default();
        for (t, z) in [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, 2.0)] {
            s.add(t, z);
        }
        let (slope, var, sxx) = s.slope();
        assert!((slope - 0.6).abs() < 1e-12 && (var - 0.02).abs() < 1e-12 && (sxx - 5.0).abs() < 1e-12, "{slope} {var} {sxx}");
        assert_eq!((s.count(), s.means()), (4.0, (1.5, 1.0)));
        let mut one = LineSums::default();
        one.add(2.0, 1.0);
        let (slope, _, sxx) = one.slope();
        assert!(slope.is_nan() && sxx == 0.0);
    }
}
