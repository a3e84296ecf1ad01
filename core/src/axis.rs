//! Axis helpers for drawing: the unit a time axis reads in, chosen by the span shown, so a
//! 60-hour log reads in hours and a 3-minute one in seconds.

/// A unit of time for an axis: its name and how many seconds it holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeUnit {
    pub name: &'static str,
    pub seconds: f64,
}

/// The unit for a time axis spanning `span_s` seconds: seconds below 10 min, minutes below
/// 10 h, hours above (labels stay under about 600 and above about 10 in every unit).
pub fn time_unit(span_s: f64) -> TimeUnit {
    if !(span_s >= 600.0) {
        TimeUnit { name: "s", seconds: 1.0 }
    } else if span_s < 36_000.0 {
        TimeUnit { name: "min", seconds: 60.0 }
    } else {
        TimeUnit { name: "h", seconds: 3600.0 }
    }
}

/// Tick positions at round values on [lo, hi]: multiples of a step of 1, 2 or 5 times a
/// power of ten, the smallest such step giving at most `max_count` ticks.
pub fn ticks(lo: f64, hi: f64, max_count: usize) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) || max_count == 0 {
        return Vec::new();
    }
    let raw = (hi - lo) / max_count as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|&s| (hi / s).floor() - (lo / s).ceil() < max_count as f64)
        .unwrap_or(10.0 * mag);
    let (first, last) = ((lo / step).ceil() as i64, (hi / step).floor() as i64);
    // Each tick as an integer times the step (no accumulated round-off), -0 as 0.
    (first..=last).map(|k| k as f64 * step).map(|v| if v == 0.0 { 0.0 } else { v }).collect()
}

/// Ticks of a log axis given in log10 units: the whole decades inside, or, when fewer than
/// two fit, round values of the exponent.
pub fn log_ticks(lo_log10: f64, hi_log10: f64, max_count: usize) -> Vec<f64> {
    if !(lo_log10.is_finite() && hi_log10.is_finite()) {
        return Vec::new();
    }
    let (a, b) = (lo_log10.ceil(), hi_log10.floor());
    if b - a < 1.0 {
        return ticks(lo_log10, hi_log10, max_count);
    }
    // Whole decades, every 1, 2, 5, ... of them.
    let t = ticks(a, b, max_count);
    if t.iter().all(|v| v.fract() == 0.0) {
        t
    } else {
        (a as i64..=b as i64).map(|d| d as f64).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_at_one_two_five() {
        assert_eq!(ticks(0.0, 10.0, 11), vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0]);
        assert_eq!(ticks(0.0, 10.0, 10), vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0], "at most max_count");
        assert_eq!(ticks(0.0, 19.4, 10), vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0]);
        assert_eq!(ticks(-163.0, 142.0, 10), vec![-150.0, -100.0, -50.0, 0.0, 50.0, 100.0]);
        assert_eq!(ticks(-1.9, 1.9, 10), vec![-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5]);
        // Round values with no round-off: 0.1 steps are k * 0.1.
        let t = ticks(0.05, 0.62, 10);
        assert_eq!(t, vec![0.1, 0.2, 0.30000000000000004, 0.4, 0.5, 0.6000000000000001]);
        assert!(ticks(1.0, 1.0, 10).is_empty() && ticks(0.0, f64::NAN, 10).is_empty());
        for (lo, hi) in [(0.0, 1e-3), (-7.3e5, 2.2e6), (3.0, 3.0001)] {
            let t = ticks(lo, hi, 10);
            assert!((2..=10).contains(&t.len()), "{lo}..{hi}: {t:?}");
        }
    }

    #[test]
    fn log_ticks_on_decades() {
        // tau 0.07 .. 980 s: decades 0.1 .. 100
        assert_eq!(log_ticks(0.07f64.log10(), 980f64.log10(), 12), vec![-1.0, 0.0, 1.0, 2.0]);
        // Within one decade: round exponents.
        assert_eq!(log_ticks(0.1, 0.9, 5), vec![0.2, 0.4, 0.6000000000000001, 0.8]);
        // Many decades: every 1, 2 or 5 of them.
        assert_eq!(log_ticks(0.0, 20.0, 10), vec![0.0, 5.0, 10.0, 15.0, 20.0]);
        assert_eq!(log_ticks(0.0, 3.0, 12), vec![0.0, 1.0, 2.0, 3.0]);
    }

    #[test]
    fn unit_by_span() {
        assert_eq!(time_unit(180.0).name, "s");
        assert_eq!(time_unit(599.9).name, "s");
        assert_eq!(time_unit(600.0), TimeUnit { name: "min", seconds: 60.0 });
        assert_eq!(time_unit(22.0 * 60.0).name, "min");
        assert_eq!(time_unit(9.9 * 3600.0).name, "min");
        assert_eq!(time_unit(60.0 * 3600.0), TimeUnit { name: "h", seconds: 3600.0 });
        // Nothing sensible to span: seconds.
        assert_eq!(time_unit(f64::NAN).name, "s");
        assert_eq!(time_unit(-5.0).name, "s");
    }
}
