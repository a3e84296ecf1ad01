//! Helpers of the CLI's end-to-end tests: the binary, scratch files, a synthetic drive.
#![allow(dead_code)] // each test file uses some of them

use std::path::PathBuf;
use std::process::{Command, Output};

pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gyrodrift"))
}

pub fn write(name: &str, text: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&p, text).unwrap();
    p
}

pub fn run(args: &[&str]) -> Output {
    bin().args(args).output().unwrap()
}

/// 10 Hz drive, 10 min: 20 s still, then legs and turns; gyro = truth + 1.0 + drift.
pub fn drive_csv() -> String {
    let mut s = String::from("# name: test drive\ntime_s,gyro_dps,ref_heading_deg,speed_mps\n");
    let mut psi: f64 = 0.0;
    for i in 0..=6000 {
        let t = i as f64 / 10.0;
        let w = if t > 20.0 && (t % 60.0) > 51.0 { 10.0 } else { 0.0 };
        if i > 0 {
            psi += w * 0.1;
        }
        let bias = 1.0 + if t > 20.0 { 0.03 } else { 0.0 };
        let r = if i % 10 == 0 { format!("{}", -(-psi).rem_euclid(360.0)) } else { String::new() };
        s.push_str(&format!("{t},{},{r},10\n", w + bias));
    }
    s
}

pub fn keys(json: &str) -> Vec<String> {
    let v: serde_json::Value = serde_json::from_str(json).unwrap();
    let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
    k.sort();
    k
}

pub fn sorted(v: &[&str]) -> Vec<String> {
    let mut k: Vec<String> = v.iter().map(|s| s.to_string()).collect();
    k.sort();
    k
}

/// The column `name` of a v1 log's text (empty cells as NaN).
pub fn column(text: &str, name: &str) -> Vec<f64> {
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let i = lines.next().unwrap().split(',').position(|h| h == name).unwrap_or_else(|| panic!("no {name}"));
    lines.map(|l| l.split(',').nth(i).unwrap().parse().unwrap_or(f64::NAN)).collect()
}
