//! The wasm bindings under Node (wasm-bindgen-test): streaming = batch, bad input throws an
//! Error with line and column and the module keeps working, options take defaults, wrong
//! types and unknown fields are named. Run: cargo test -p gyrodrift-wasm --target wasm32-unknown-unknown --tests
#![cfg(target_arch = "wasm32")]

use gyrodrift_wasm::*;
use js_sys::{Array, Float64Array, Object, Reflect};
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

const RURAL: &str = include_str!("../../sample-logs/train/rural-1.csv");
const ROBOT: &str = include_str!("../../sample-logs/robot/straight.csv");

fn get(obj: &JsValue, key: &str) -> JsValue {
    Reflect::get(obj, &JsValue::from_str(key)).unwrap()
}

fn num(obj: &JsValue, key: &str) -> f64 {
    get(obj, key).as_f64().unwrap_or_else(|| panic!("{key} is not a number"))
}

fn obj(pairs: &[(&str, JsValue)]) -> JsValue {
    let o = Object::new();
    for (k, v) in pairs {
        Reflect::set(&o, &JsValue::from_str(k), v).unwrap();
    }
    o.into()
}

fn message(e: JsValue) -> String {
    let e: js_sys::Error = e.dyn_into().expect("a JS Error");
    e.message().into()
}

/// The same numbers as the native core computes on the same text (core is linked in too).
#[wasm_bindgen_test]
fn hdr_matches_core_bit_for_bit() {
    let log = Log::parse(JsValue::from_str(RURAL)).unwrap();
    let r = hdr(&log, JsValue::UNDEFINED).unwrap();
    let native = gyrodrift::hdr::run(&gyrodrift::parse_log_str(RURAL).unwrap(), &Default::default()).unwrap().result.unwrap();
    assert_eq!(num(&r, "E_psi_hdr_deg").to_bits(), native.E_psi_hdr_deg.to_bits());
    assert_eq!(num(&r, "E_psi_raw_deg").to_bits(), native.E_psi_raw_deg.to_bits());
    assert_eq!(get(&r, "resampled").as_bool(), Some(true));
    assert!(num(&r, "improvement") > 1.0);
}

#[wasm_bindgen_test]
fn streaming_equals_batch() {
    let log = Log::parse(JsValue::from_str(RURAL)).unwrap();
    let run = run_hdr(&log, obj(&[("resample", JsValue::FALSE)]), None).unwrap();
    let trace = get(&run, "trace");
    let t: Float64Array = get(&trace, "time_s").dyn_into().unwrap();
    let batch: Float64Array = get(&trace, "heading_hdr_deg").dyn_into().unwrap();
    let raw: Float64Array = get(&trace, "rate_raw_dps").dyn_into().unwrap();
    let eps0 = num(&run, "eps0_dps");
    let mut est = HdrEstimator::new(JsValue::UNDEFINED, eps0).unwrap();
    let shift = batch.get_index(0);
    for i in 0..t.length() {
        let h = est.update(t.get_index(i), raw.get_index(i)).unwrap();
        assert_eq!((h + shift).to_bits(), batch.get_index(i).to_bits(), "sample {i}");
    }
    // updateMany continues the same state
    let mut est2 = HdrEstimator::new(JsValue::UNDEFINED, eps0).unwrap();
    let all = est2.update_many(&t.to_vec(), &raw.to_vec()).unwrap();
    assert_eq!(all.get_index(t.length() - 1).to_bits(), est.heading_deg().to_bits());
    assert!(est.state().unwrap().is_object());
}

/// A view reduces the series to what a chart draws; the metrics stay those of every sample;
/// a bad view is an error, not a panic.
#[wasm_bindgen_test]
fn a_view_reduces_the_trace_not_the_metrics() {
    let log = Log::parse(JsValue::from_str(RURAL)).unwrap();
    let opts = || obj(&[("resample", JsValue::FALSE)]);
    let full = run_hdr(&log, opts(), None).unwrap();
    let view = obj(&[("columns", JsValue::from_f64(20.0))]);
    let small = run_hdr(&log, opts(), Some(view)).unwrap();
    let len = |run: &JsValue, key: &str| get(&get(run, "trace"), key).dyn_into::<Float64Array>().unwrap().length();
    assert!(len(&small, "time_s") < len(&full, "time_s") / 4, "{} of {}", len(&small, "time_s"), len(&full, "time_s"));
    assert_eq!(len(&small, "time_s"), len(&small, "heading_hdr_deg"));
    let e = |run: &JsValue| num(&get(run, "result"), "E_psi_hdr_deg");
    assert_eq!(e(&small).to_bits(), e(&full).to_bits());
    // The reduced heading keeps the full one's extremes.
    let h = |run: &JsValue| get(&get(run, "trace"), "heading_hdr_deg").dyn_into::<Float64Array>().unwrap().to_vec();
    let max = |v: Vec<f64>| v.into_iter().fold(f64::MIN, f64::max);
    assert_eq!(max(h(&small)), max(h(&full)));
    for bad in [
        obj(&[("columns", JsValue::from_f64(0.0))]),
        obj(&[("columns", JsValue::from_f64(10.0)), ("x_range", Array::of2(&JsValue::from_f64(5.0), &JsValue::from_f64(1.0)).into())]),
    ] {
        assert!(message(run_hdr(&log, opts(), Some(bad)).err().unwrap()).contains("view."));
    }
}

#[wasm_bindgen_test]
fn bad_input_throws_with_line_and_column_and_module_keeps_working() {
    let e = Log::parse(JsValue::from_str("time_s,gyro_dps\n0,1\n0.1,1.2.3\n")).err().unwrap();
    assert_eq!(message(e), "line 3, column gyro_dps: \"1.2.3\" is not a number");
    let e = Log::parse(JsValue::from_str("")).err().unwrap();
    assert_eq!(message(e), "empty file: no header row");
    let e = Log::parse(JsValue::from_str("time_s,gyro_dps\n0,1\n0,1\n")).err().unwrap();
    assert!(message(e).contains("line 3, column time_s"));
    let e = Log::from_bytes(js_sys::Uint8Array::from(&b"time_s,gyro_dps\n0,\xff\n"[..]).into()).err().unwrap();
    assert!(message(e).contains("line 2"));
    let mut est = HdrEstimator::new(JsValue::UNDEFINED, 0.0).unwrap();
    est.update(1.0, 0.0).unwrap();
    assert!(est.update(1.0, 0.0).is_err());
    assert!(est.update(2.0, f64::NAN).is_err());
    let noref = Log::parse(JsValue::from_str("time_s,gyro_dps,ref_heading_deg\n0,1,\n1,1,\n")).unwrap();
    let e = hdr(&noref, JsValue::UNDEFINED).err().unwrap();
    assert!(message(e).contains("no valid reference heading"));
    let run = run_hdr(&noref, JsValue::UNDEFINED, None).unwrap();
    assert!(get(&run, "result").is_null());
    assert!(get(&run, "error").as_string().unwrap().contains("reference"));
    let e = gyrodometry(&Log::parse(JsValue::from_str(RURAL)).unwrap(), JsValue::UNDEFINED).err().unwrap();
    let m = message(e);
    assert!(m.contains("wheelbase_m"), "{m}");
    // after all of that the module still works
    let log = Log::parse(JsValue::from_str(RURAL)).unwrap();
    assert!(num(&hdr(&log, JsValue::UNDEFINED).unwrap(), "E_psi_hdr_deg") > 0.0);
}

#[wasm_bindgen_test]
fn options_default_and_name_bad_fields() {
    let log = Log::parse(JsValue::from_str(RURAL)).unwrap();
    let a = hdr(&log, JsValue::UNDEFINED).unwrap();
    let b = hdr(&log, obj(&[("tau_s", JsValue::from_f64(0.75))])).unwrap();
    assert_eq!(num(&a, "E_psi_hdr_deg"), num(&b, "E_psi_hdr_deg"));
    let c = hdr(&log, obj(&[("i_c", JsValue::from_f64(0.003))])).unwrap();
    assert_ne!(num(&a, "E_psi_hdr_deg"), num(&c, "E_psi_hdr_deg"));
    let e = hdr(&log, obj(&[("tau_s", JsValue::from_str("fast"))])).err().unwrap();
    let m = message(e);
    assert!(m.starts_with("hdr options: parameter tau_s: invalid type"), "{m}");
    let e = hdr(&log, obj(&[("taus", JsValue::from_f64(1.0))])).err().unwrap();
    assert!(message(e).contains("unknown field `taus`"));
    let e = hdr(&log, obj(&[("tau_s", JsValue::from_f64(-1.0))])).err().unwrap();
    assert_eq!(message(e), "hdr options: parameter tau: -1.0 is not a time in [0, 3600] s");
    // NaN would become "absent" in the conversion: refused by name instead.
    let e = hdr(&log, obj(&[("bias_s", JsValue::from_f64(f64::NAN))])).err().unwrap();
    assert_eq!(message(e), "hdr options: bias_s: NaN is not a finite number");
    let e = pipeline(&log, obj(&[("still", obj(&[("still_speed_mps", JsValue::from_f64(f64::INFINITY))]))])).err().unwrap();
    assert_eq!(message(e), "pipeline options: still.still_speed_mps: inf is not a finite number");
}

#[wasm_bindgen_test]
fn every_method_returns_result_keys() {
    let robot = Log::parse(JsValue::from_str(ROBOT)).unwrap();
    let g = gyrodometry(&robot, JsValue::UNDEFINED).unwrap();
    assert!(num(&g, "E_psi_gyrodometry_deg") < num(&g, "E_psi_odo_deg"));
    let sim_tt = simulate(obj(&[("kind", "turntable".into()), ("seed", JsValue::from_f64(3.0))])).unwrap();
    let c = calibrate(&sim_tt, JsValue::UNDEFINED).unwrap();
    assert!(num(&c, "residual_rms_compensated_dps") < num(&c, "residual_rms_static_only_dps"));
    assert!(Array::is_array(&get(&c, "C")));
    let st = simulate(obj(&[("kind", "static".into()), ("minutes", JsValue::from_f64(10.0))])).unwrap();
    let a = allan(&st).unwrap();
    assert!(get(&a, "adev_dps").is_instance_of::<Float64Array>());
    assert!(num(&a, "arw_deg_per_sqrt_s") > 0.0);
    let d1 = Log::parse(JsValue::from_str(RURAL)).unwrap();
    let d2 = simulate(obj(&[("scenario", "city".into()), ("minutes", JsValue::from_f64(6.0)), ("name", "Sim".into())])).unwrap();
    let logs = Array::of2(&JsValue::from(d1), &JsValue::from(d2));
    let rep = report(logs.clone().into(), JsValue::UNDEFINED, None).unwrap();
    let rows: Array = get(&rep, "rows").dyn_into().unwrap();
    assert_eq!(rows.length(), 2);
    assert_eq!(get(&rows.get(1), "name").as_string().as_deref(), Some("Sim"));
    let t = tune(
        logs.into(),
        JsValue::UNDEFINED,
        obj(&[("max_iters", JsValue::from_f64(20.0)), ("restarts", JsValue::from_f64(0.0))]),
        None,
        None,
    )
    .unwrap();
    let res = get(&t, "result");
    assert!(num(&res, "objective_tuned_deg_per_min") <= num(&res, "objective_start_deg_per_min"));
}

#[wasm_bindgen_test]
fn simulate_matches_the_shipped_sample_log() {
    let s = gyrodrift::sim::samples::SAMPLE_LOGS.iter().find(|s| s.path == "robot/straight.csv").unwrap();
    let req = obj(&[
        ("kind", "robot".into()),
        ("scenario", "straight".into()),
        ("minutes", JsValue::from_f64(s.minutes.unwrap())),
        ("seed", JsValue::from_f64(s.seed as f64)),
        ("name", s.name.into()),
    ]);
    let log = simulate(req).unwrap();
    assert_eq!(log.to_csv().unwrap(), ROBOT, "wasm simulation differs from the native sample log");
}

/// importLog: a recipe object and in-memory files give the same log as core's import; a
/// bad recipe throws an Error naming the problem, and the module keeps working.
#[wasm_bindgen_test]
fn import_log_by_recipe_and_pipeline_match_core() {
    let imu = "t,w\n0,0.1\n0.5,0.1\n1,0.1\n1.5,0.2\n2,0.2\n2.5,0.2\n3,0.2\n";
    let gps = "t,b,v\n0,10,0\n1,10,0\n2,12,6\n3,14,6\n";
    let recipe_json = r#"{"bias_s": 1, "table": [
        {"id": "imu", "file": "imu.csv", "time": {"column": "t"}},
        {"id": "gps", "file": "gps.csv", "time": {"column": "t"}}],
      "yaw_rate": {"table": "imu", "column": "w", "unit": "deg/s", "positive": "cw"},
      "heading": {"source": "column", "table": "gps", "column": "b", "unit": "deg", "positive": "cw", "speed_column": "v", "min_speed_mps": 5},
      "speed": {"source": "column", "table": "gps", "column": "v", "unit": "m/s"}}"#;
    let recipe = js_sys::JSON::parse(recipe_json).unwrap();
    let files =
        obj(&[("imu.csv", js_sys::Uint8Array::from(imu.as_bytes()).into()), ("gps.csv", js_sys::Uint8Array::from(gps.as_bytes()).into())]);
    let out = import_log(recipe.clone(), files.clone()).unwrap();
    let log: Log = {
        // The Log inside the result object: re-import natively and compare columns.
        let native: gyrodrift::import::Recipe = serde_json::from_str(recipe_json).unwrap();
        let mut map = std::collections::BTreeMap::new();
        map.insert("imu.csv".to_string(), imu.as_bytes().to_vec());
        map.insert("gps.csv".to_string(), gps.as_bytes().to_vec());
        let (nlog, _) = gyrodrift::import::import(&native, &mut map).unwrap();
        let csv = {
            let mut v = Vec::new();
            nlog.write_csv(&mut v).unwrap();
            String::from_utf8(v).unwrap()
        };
        Log::parse(JsValue::from_str(&csv)).unwrap()
    };
    let summary = get(&out, "summary");
    assert_eq!(num(&summary, "n_gyro"), 7.0);
    assert_eq!(num(&summary, "n_reference"), 2.0);
    let wasm_log = get(&out, "log");
    let rows = get(&wasm_log, "rowCount").as_f64().unwrap();
    assert_eq!(rows, log.row_count() as f64);
    let g = log.column(JsValue::from_str("gyro_dps")).unwrap();
    assert_eq!(g.get_index(0), -0.1, "clockwise input -> counter-clockwise log");

    // Errors: a missing file, a bad unit; then the module still works.
    let e = import_log(recipe.clone(), obj(&[("imu.csv", js_sys::Uint8Array::from(imu.as_bytes()).into())])).unwrap_err();
    assert!(message(e).contains("gps.csv"));
    let bad = js_sys::JSON::parse(&recipe_json.replace("\"deg/s\"", "\"furlong\"")).unwrap();
    assert!(message(import_log(bad, files.clone()).unwrap_err()).contains("not a rate unit"));
    assert!(message(import_log(JsValue::from_str("x"), files.clone()).unwrap_err()).starts_with("recipe:"));
    assert!(import_log(recipe, files).is_ok());

    // pipeline == core, bit for bit; runPipeline has the trace; bad options are named.
    let rural = Log::parse(JsValue::from_str(RURAL)).unwrap();
    let r = pipeline(&rural, JsValue::UNDEFINED).unwrap();
    let native = gyrodrift::pipeline::run(&gyrodrift::parse_log_str(RURAL).unwrap(), &Default::default()).unwrap().result.unwrap();
    assert_eq!(num(&r, "E_psi_pipeline_deg").to_bits(), native.E_psi_pipeline_deg.to_bits());
    assert_eq!(num(&r, "E_psi_zaru_deg").to_bits(), native.E_psi_zaru_deg.to_bits());
    let run = run_pipeline(&rural, obj(&[("road_gate_dps", JsValue::from_f64(0.3))])).unwrap();
    let trace = get(&run, "trace");
    let h: Float64Array = get(&trace, "heading_deg").dyn_into().unwrap();
    assert!(h.length() > 100);
    assert_eq!(get(&run, "still_source").as_string().as_deref(), Some("speed"));
    let e = pipeline(&rural, obj(&[("gate", JsValue::from_f64(1.0))])).unwrap_err();
    assert!(message(e).contains("unknown field `gate`"));
    let c = compare(Array::of1(&JsValue::from(rural)).into(), JsValue::UNDEFINED, None).unwrap();
    assert_eq!(num(&get(&c, "mean"), "pipeline").to_bits(), native.NE_psi_pipeline_deg_per_min.to_bits());
}
