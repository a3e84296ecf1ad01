//! Any bytes as the table of a recipe, and any bytes as a recipe (JSON), through the import
//! and, when it imports, every method: errors are fine, a panic is a bug.
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::collections::BTreeMap;

const RECIPE: &str = r#"{"bias_s": 1, "table": [{"id": "p", "file": "p.csv", "time": {"column": "t"}}],
  "yaw_rate": {"table": "p", "axes": ["gx", "gy", "gz"], "gravity": {"axes": ["ax", "ay", "az"], "first_s": 1}, "unit": "rad/s", "positive": "ccw"},
  "positions": {"table": "p", "kind": "latlon", "columns": ["lat", "lon"]},
  "heading": {"source": "positions", "min_distance_m": 1}, "speed": {"source": "positions"}}"#;

fuzz_target!(|data: &[u8]| {
    // first byte 0: the bytes are a recipe over a fixed table; otherwise a table for the fixed recipe
    let (recipe, table): (Option<gyrodrift::import::Recipe>, Vec<u8>) = match data.split_first() {
        Some((0, rest)) => (serde_json::from_slice(rest).ok(), b"t,gx,gy,gz,ax,ay,az,lat,lon\n0,0,0,0.1,0,0,9.8,52.5,13.4\n1,0,0,0.1,0,0,9.8,52.50001,13.4\n2,0,0,0.1,0,0,9.8,52.50002,13.40001\n".to_vec()),
        Some((_, rest)) => (serde_json::from_str(RECIPE).ok(), rest.to_vec()),
        None => return,
    };
    let Some(recipe) = recipe else { return };
    let mut files = BTreeMap::new();
    files.insert("p.csv".to_string(), table);
    if let Ok((log, _)) = gyrodrift::import::import(&recipe, &mut files) {
        let _ = gyrodrift::check::check(&log);
        let _ = gyrodrift::log::gaps::split_at_gaps(log.clone(), Default::default(), 1.0);
        let _ = gyrodrift::hdr::run(&log, &Default::default());
        let _ = gyrodrift::pipeline::run(&log, &Default::default());
        let _ = gyrodrift::compare::compare(&[("fuzz".into(), &log)], &Default::default(), None);
    }
});
