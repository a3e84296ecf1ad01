//! The CLI's robustness battery: its goals, the scoring bases drawn afresh, a case written
//! as a log, the profiles on a user's own log.

mod common;

use common::*;

/// `battery` on its simulated half alone (3 min drives, training split): the summary's
/// goals as JSON, each verdict agreeing with the counts it is measured from, and the
/// good-gyro goal absent (no recorded Pixel drive was given).
#[test]
fn battery_reports_the_goals_it_measures() {
    let out = run(&["battery", "--minutes", "3", "--split", "training", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["scoring"].is_null());
    let s = &v["training"];
    let goals = s["goals"].as_array().unwrap();
    let names: Vec<&str> = goals.iter().map(|g| g["goal"].as_str().unwrap()).collect();
    assert_eq!(names.len(), 5, "{names:?}");
    assert!(names.iter().all(|n| !n.contains("Pixel")), "{names:?}");
    let n = s["n_cases"].as_f64().unwrap();
    assert_eq!(goals[1]["measured"].as_f64(), s["n_over_2x"].as_f64());
    assert_eq!(goals[1]["holds"].as_bool(), Some(s["n_over_2x"].as_u64() == Some(0)));
    assert_eq!(goals[2]["measured"].as_f64(), Some(s["n_within"].as_f64().unwrap() / n));
    assert_eq!(goals[4]["measured"].as_f64(), s["n_worse_than_raw"].as_f64());
    let text = String::from_utf8(run(&["battery", "--minutes", "3", "--split", "training"]).stdout).unwrap();
    assert!(text.contains("| training | no case worse than 2x the best other + 0.05 |"), "{text}");
}

/// `battery --draw K`: the simulated scoring bases drawn afresh (seeds 101-106 + 1000 K),
/// the training bases as they were.
#[test]
fn battery_draws_the_simulated_scoring_bases_afresh() {
    let out = run(&["battery", "--minutes", "2", "--split", "all", "--draw", "2", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let cases = v["cases"].as_array().unwrap();
    let bases = |training: bool| {
        let mut b: Vec<&str> =
            cases.iter().filter(|c| c["training"].as_bool() == Some(training)).map(|c| c["base"].as_str().unwrap()).collect();
        b.dedup();
        b
    };
    assert!(bases(false).contains(&"sim-city-mems-2101") && !bases(false).contains(&"sim-city-mems-101"), "{:?}", bases(false));
    assert!(bases(true).contains(&"sim-city-crs03-1"), "{:?}", bases(true));
}

/// `battery --write-case`: one case's log, which `compare` scores as the battery did (raw,
/// Table-III HDR, Fusion, ZARU, pipeline, smoothed: the battery's first six columns); an
/// unknown case exits 2 (the CLI's code for an error) with the names it knows.
#[test]
fn battery_writes_a_case_that_scores_as_the_battery_did() {
    let case = "sim-city-crs03-1 / bias +0.5";
    let out = run(&["battery", "--minutes", "2", "--split", "training", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let row = v["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| format!("{} / {}", c["base"].as_str().unwrap(), c["profile"].as_str().unwrap()) == case)
        .unwrap();
    let dir = std::env::temp_dir().join(format!("gyrodrift-case-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("case.csv");
    let w = run(&["battery", "--minutes", "2", "--write-case", case, "--out", file.to_str().unwrap()]);
    assert!(w.status.success(), "{}", String::from_utf8_lossy(&w.stderr));
    let c: serde_json::Value = serde_json::from_slice(&run(&["compare", "--json", file.to_str().unwrap()]).stdout).unwrap();
    let r = &c["rows"][0];
    assert_eq!(r["name"].as_str(), Some(case));
    let keys = ["raw", "hdr_table_iii", "fusion_offset", "zaru", "pipeline", "pipeline_smoothed"];
    for (i, k) in keys.iter().enumerate() {
        assert_eq!(r[k].as_f64(), row["ne_psi"][i].as_f64(), "{k}");
    }
    let bad = run(&["battery", "--minutes", "2", "--write-case", "sim-city-crs03-1 / bias +9"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("the profiles are as-is"), "{}", String::from_utf8_lossy(&bad.stderr));
    std::fs::remove_dir_all(&dir).ok();
}

/// `battery --logs`: the user's own v1 log becomes a scoring base (whatever its name), run
/// with every error profile and summarised apart as "added"; a log without a reference
/// heading, or two logs of one name, exit 2 naming the problem.
#[test]
fn battery_runs_the_profiles_on_a_users_own_log() {
    let p = write("battery-own.csv", &drive_csv());
    let out = run(&["battery", "--minutes", "2", "--split", "scoring", "--json", "--logs", p.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mine: Vec<&serde_json::Value> = v["cases"].as_array().unwrap().iter().filter(|c| c["base"] == "test drive").collect();
    assert!(mine.len() > 20 && mine.iter().all(|c| c["training"] == false), "{}", mine.len());
    assert_eq!(v["added"]["n_cases"].as_u64(), Some(mine.len() as u64));
    let text = String::from_utf8(run(&["battery", "--minutes", "2", "--split", "scoring", "--logs", p.to_str().unwrap()]).stdout).unwrap();
    assert!(text.contains(&format!("| added ({}) |", mine.len())), "{text}");

    let no_ref = write("battery-noref.csv", "time_s,gyro_dps\n0,0.1\n1,0.1\n2,0.1\n");
    let bad = run(&["battery", "--minutes", "2", "--logs", no_ref.to_str().unwrap()]);
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(err.contains("battery-noref.csv") && err.contains("ref_heading_deg"), "{err}");
    let twice = run(&["battery", "--minutes", "2", "--logs", p.to_str().unwrap(), p.to_str().unwrap()]);
    assert_eq!(twice.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&twice.stderr).contains("two battery bases are named \"test drive\""));
    let training = run(&["battery", "--minutes", "2", "--split", "training", "--logs", p.to_str().unwrap()]);
    assert_eq!(training.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&training.stderr).contains("the drives you add are scoring bases"));
}
