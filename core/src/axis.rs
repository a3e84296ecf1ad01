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

#[cfg(test)]
mod tests {
    use super::*;

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
