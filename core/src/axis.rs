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

/// The smallest and largest finite value, or None when there is none.
pub fn finite_range(vals: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in vals.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    (lo <= hi).then_some((lo, hi))
}

/// A value axis' range for these values: their span padded by 5 % each side (none on a log
/// axis, whose values are already exponents), one either side of a single value, 0..1 with
/// no finite value.
pub fn value_range(vals: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    match finite_range(vals) {
        Some((a, b)) if b > a => {
            let pad = if log { 0.0 } else { (b - a) * 0.05 };
            (a - pad, b + pad)
        }
        Some((a, _)) => (a - 1.0, a + 1.0),
        None => (0.0, 1.0),
    }
}

/// Equal axes (a track in metres): x and y ranges that draw one unit the same length across
/// and up on a plot area of `w_px` by `h_px`. Centred on `view` = (x centre, y centre, units
/// per pixel) when given (a zoomed or panned view), else fitting `extent` = (x0, x1, y0, y1)
/// with 5 % to spare on its tighter axis.
pub fn equal_ranges(extent: [f64; 4], w_px: f64, h_px: f64, view: Option<[f64; 3]>) -> [f64; 4] {
    let (w, h) = (w_px.max(1.0), h_px.max(1.0));
    let [x0, x1, y0, y1] = extent;
    let [xc, yc, per_px] = match view {
        Some(v) if v.iter().all(|a| a.is_finite()) && v[2] > 0.0 => v,
        _ => [(x0 + x1) / 2.0, (y0 + y1) / 2.0, ((x1 - x0) / w).max((y1 - y0) / h).max(1e-9) * 1.05],
    };
    let (half_x, half_y) = (per_px * w / 2.0, per_px * h / 2.0);
    [xc - half_x, xc + half_x, yc - half_y, yc + half_y]
}

/// The intervals of x where a 0/1 mask is on (from the first x on to the first x off, or
/// the last x), gaps narrower than `min_gap` merged: the shaded stretches of a chart.
pub fn mask_intervals(x: &[f64], mask: &[f64], min_gap: f64) -> Vec<(f64, f64)> {
    let n = x.len().min(mask.len());
    let mut intervals: Vec<(f64, f64)> = Vec::new();
    let mut start: Option<f64> = None;
    for i in 0..=n {
        let on = i < n && mask[i] > 0.5;
        match (on, start) {
            (true, None) => start = Some(x[i]),
            (false, Some(s0)) => {
                let e = if i < n { x[i] } else { x[n - 1] };
                match intervals.last_mut() {
                    Some(last) if s0 - last.1 < min_gap => last.1 = e,
                    _ => intervals.push((s0, e)),
                }
                start = None;
            }
            _ => {}
        }
    }
    intervals
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_ranges_fit_the_extent_or_keep_the_view() {
        // 100 m by 50 m on 200 x 200 px: x limits, 0.5 m/px x 1.05 = 0.525 m/px, 105 m each way.
        let r = equal_ranges([0.0, 100.0, 0.0, 50.0], 200.0, 200.0, None);
        for (a, b) in r.iter().zip([-2.5, 102.5, -27.5, 77.5]) {
            assert!((a - b).abs() < 1e-9, "{r:?}");
        }
        // A view centred on (10, 20) at 2 m/px on 100 x 50 px: 200 m across, 100 m up.
        assert_eq!(equal_ranges([0.0, 1.0, 0.0, 1.0], 100.0, 50.0, Some([10.0, 20.0, 2.0])), [-90.0, 110.0, -30.0, 70.0]);
        // An unusable view (zero scale) falls back to the extent; a point still gets a span.
        let f = equal_ranges([0.0, 4.0, 0.0, 2.0], 4.0, 2.0, Some([0.0, 0.0, 0.0]));
        for (a, b) in f.iter().zip([-0.1, 4.1, -0.05, 2.05]) {
            assert!((a - b).abs() < 1e-12, "{f:?}");
        }
        let p = equal_ranges([3.0, 3.0, 5.0, 5.0], 10.0, 10.0, None);
        assert!(p[1] > p[0] && p[3] > p[2] && (p[0] + p[1]) / 2.0 == 3.0);
    }

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

    #[test]
    fn value_range_pads_by_5_percent_hand_worked() {
        assert_eq!(value_range([1.0, f64::NAN, 3.0].into_iter(), false), (0.9, 3.1));
        assert_eq!(value_range([1.0, 3.0].into_iter(), true), (1.0, 3.0));
        assert_eq!(value_range([2.0, 2.0].into_iter(), false), (1.0, 3.0));
        assert_eq!(value_range([f64::NAN].into_iter(), false), (0.0, 1.0));
        assert_eq!(finite_range(std::iter::empty()), None);
    }

    #[test]
    fn mask_intervals_hand_worked() {
        let x = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];
        // On at 1-2, off at 3, on 4-5, off 6, on 7 (to the end).
        let m = [0.0, 1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
        assert_eq!(mask_intervals(&x, &m, 0.5), vec![(1.0, 3.0), (4.0, 6.0), (7.0, 7.0)]);
        // Gaps of 1 (3 to 4, 6 to 7) under min_gap 1.5 merge all three.
        assert_eq!(mask_intervals(&x, &m, 1.5), vec![(1.0, 7.0)]);
        assert!(mask_intervals(&x, &[0.0; 8], 1.0).is_empty());
    }
}
