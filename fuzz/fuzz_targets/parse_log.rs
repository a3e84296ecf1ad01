//! Any bytes through the CSV v1 parser and, when they parse, through every method:
//! errors are fine, a panic is a bug.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(log) = gyrodrift::parse_log(data) {
        let _ = gyrodrift::hdr::run(&log, &Default::default());
        let _ = gyrodrift::hdr::run(&log, &gyrodrift::hdr::HdrOptions { resample: false, ..Default::default() });
        let _ = gyrodrift::gyrodometry::run(&log, &gyrodrift::gyrodometry::GyrodometryOptions { wheelbase_m: Some(0.5), ..Default::default() });
        let _ = gyrodrift::calibration::run(&log, &gyrodrift::calibration::CalibrationOptions { p: 1, q: 1, bias_s: Some(1.0) });
        let _ = gyrodrift::allan::run(&log);
        let _ = gyrodrift::pipeline::run(&log, &Default::default());
        let _ = gyrodrift::compare::compare(&[("fuzz".into(), &log)], &Default::default(), None);
    }
});
