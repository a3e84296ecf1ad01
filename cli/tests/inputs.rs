//! The CLI on bad input: exit 2 with one line naming file, line and column; no panic;
//! closed pipes, write errors, gaps in time, out of memory, and what `check` refuses.

mod common;

use common::*;
use std::path::PathBuf;
use std::process::Command;

#[test]
fn bad_cell_exits_2_with_file_line_column() {
    let p = write("bad.csv", "time_s,gyro_dps\n0,1\n0.1,1.2.3\n");
    let out = run(&["hdr", p.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.trim_end(), format!("{}: line 3, column gyro_dps: \"1.2.3\" is not a number", p.display()));
    assert!(out.stdout.is_empty());
}

#[test]
fn bad_inputs_exit_2_never_panic() {
    let cases: &[(&str, &str, &str)] = &[
        ("empty.csv", "", "empty file"),
        ("header.csv", "time_s,gyro_dps\n", "no data rows"),
        ("notime.csv", "gyro_dps\n1\n", "missing required column time_s"),
        ("dup.csv", "time_s,time_s\n1,1\n", "duplicate column time_s"),
        ("nan.csv", "time_s,gyro_dps\n0,nan\n", "line 2, column gyro_dps"),
        ("back.csv", "time_s,gyro_dps\n0,1\n1,1\n1,1\n", "line 4, column time_s: time 1 repeats 1 on line 3"),
        ("trunc.csv", "time_s,gyro_dps,ref_heading_deg\n0,1,0\n1,1\n2,1,0\n", "line 3: row has 2 fields"),
        // Binary files say what they are, not "missing column" with their bytes as a header.
        ("blob.csv", "\u{1}x\u{0}\u{2}\n", "line 1: a binary file (NUL bytes), not a text table"),
        ("drive.parquet", "PAR1\u{15}\u{4}\u{0}\u{0}x\n", "a Parquet file, not a CSV log: Python's `gyrodrift.read_log` reads"),
    ];
    for (name, text, want) in cases {
        let p = write(name, text);
        let out = run(&["hdr", p.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains(want) && err.starts_with(&p.display().to_string()), "{name}: {err}");
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
    }
    // A spreadsheet's "Unicode text" (UTF-16 with its byte-order mark).
    let p = write("utf16.csv", "");
    let utf16: Vec<u8> = [0xFF, 0xFE].into_iter().chain("time_s,gyro_dps\n0,1\n".bytes().flat_map(|b| [b, 0])).collect();
    std::fs::write(&p, utf16).unwrap();
    let out = run(&["hdr", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.starts_with(&format!("{}: line 1: UTF-16 text", p.display())), "{err}");
    // An empty reference column is a drive without a reference: run, not scored, exit 0.
    let p = write("noref.csv", "time_s,gyro_dps,ref_heading_deg\n0,1,\n1,1,\n");
    let out = run(&["hdr", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("not scored: no valid reference heading"));
    let out = run(&["hdr", "/nonexistent/x.csv"]);
    assert_eq!(out.status.code(), Some(2));
    let p = write("ok.csv", &drive_csv());
    let out = run(&["hdr", p.to_str().unwrap(), "--set", "tau=-1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("tau"));
    let out = run(&["hdr", p.to_str().unwrap(), "--set", "gain=1"]);
    assert_eq!(out.status.code(), Some(2));
    let out = run(&["gyrodometry", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("wheelbase_m"), "{err}");
}

/// `gyrodrift allan LOG | true`: the reader is gone before the output is written; the
/// command ends by SIGPIPE (or 0), never with a panic (exit 101).
#[cfg(unix)]
#[test]
fn a_closed_pipe_ends_quietly() {
    use std::os::unix::process::ExitStatusExt;
    use std::process::Stdio;
    let log = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/static/static-2h.csv");
    let mut child = bin().args(["allan", log.to_str().unwrap()]).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    drop(child.stdout.take()); // close the read end at once
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(out.status.success() || out.status.signal() == Some(13), "{:?}", out.status);
}

/// Output to a full device: exit 2 naming the output, never a panic.
#[cfg(target_os = "linux")]
#[test]
fn a_write_error_exits_2_naming_the_output() {
    let log = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/static/static-2h.csv");
    for args in
        [vec!["allan", log.to_str().unwrap()], vec!["allan", log.to_str().unwrap(), "--json"], vec!["simulate", "drive", "--minutes", "1"]]
    {
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let out = bin().args(&args).stdout(full).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with("standard output: cannot write") && err.lines().count() == 1, "{err}");
    }
}

/// Input that is not a log, one row, a unit mistake: exit 2 with one line, no NaN, no abort.
#[test]
fn endless_short_and_absurd_inputs_exit_2() {
    #[cfg(target_os = "linux")]
    {
        let o = run(&["hdr", "/dev/zero"]);
        assert_eq!(o.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&o.stderr).contains("a line is longer than"));
    }
    let one = write("one-row.csv", "time_s,gyro_dps,ref_heading_deg\n0,1,0\n");
    for cmd in ["hdr", "pipeline"] {
        let o = run(&[cmd, one.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{cmd}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("the log lasts 0 s"));
    }
    let big = write("big-gyro.csv", "time_s,gyro_dps\n0,1\n1,1e308\n");
    let o = run(&["hdr", big.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2));
    assert!(err.contains("line 3, column gyro_dps") && err.contains("outside the physical range"), "{err}");
    let hot = write("hot.csv", "time_s,gyro_dps,temp_c\n0,1,20\n1,1,1e6\n");
    let o = run(&["pipeline", hot.to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("line 3, column temp_c"));
    for set in ["wheelbase_m=5e-324", "thres_rate=1e300"] {
        let robot = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../sample-logs/robot/straight.csv");
        let o = run(&["gyrodometry", robot.to_str().unwrap(), "--set", set]);
        assert_eq!(o.status.code(), Some(2), "{set}");
    }
}

/// A 60 s gap: no method integrates across it. By default the log is split into drives of
/// their own (said on stderr; JSON an array of the parts); `--gaps error` exits 2 naming the line.
#[test]
fn a_gap_in_time_splits_the_log_or_is_refused() {
    let text: String = drive_csv()
        .lines()
        .filter(|l| l.split(',').next().and_then(|t| t.parse::<f64>().ok()).is_none_or(|t| !(300.0..360.0).contains(&t)))
        .map(|l| format!("{l}\n"))
        .collect();
    let p = write("gap.csv", &text);
    let whole = run(&["hdr", p.to_str().unwrap(), "--json", "--gaps", "split"]);
    assert!(whole.status.success(), "{}", String::from_utf8_lossy(&whole.stderr));
    let err = String::from_utf8_lossy(&whole.stderr);
    assert!(err.contains("split at 1 gap(s) (60.1 s at line"), "{err}");
    let v: serde_json::Value = serde_json::from_slice(&whole.stdout).unwrap();
    let parts = v.as_array().unwrap();
    assert_eq!(parts.len(), 2);
    for part in parts {
        assert!(part["E_psi_hdr_deg"].as_f64().unwrap() < 5.0, "{part}");
    }
    let refused = run(&["pipeline", p.to_str().unwrap(), "--gaps", "error"]);
    assert_eq!(refused.status.code(), Some(2));
    let msg = String::from_utf8_lossy(&refused.stderr);
    assert!(msg.contains("gap.csv: line 3003, column time_s: a gap of 60.1 s"), "{msg}");
    let report = run(&["report", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&report.stdout).unwrap();
    assert!(v.to_string().contains("test drive (part 2 of 2)"), "{v}");
}

/// A time that repeats (a logger writing a sample twice): refused by default, naming the
/// line and `--time-order fix`; with it the repeat is merged (said on stderr) and the log
/// scores as it does without the repeat, here and in `report --dir` (the row's warning).
#[test]
fn a_repeated_time_is_refused_or_merged_by_time_order() {
    let text = drive_csv();
    let lines: Vec<&str> = text.lines().collect();
    let h = lines.iter().position(|l| l.starts_with("time_s")).unwrap();
    let mut with: Vec<&str> = lines[..h + 200].to_vec();
    with.push(lines[h + 199]);
    with.extend(&lines[h + 200..]);
    let plain = write("plain.csv", &text);
    let dir = std::env::temp_dir().join(format!("gd-time-order-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("repeat.csv");
    std::fs::write(&p, with.join("\n") + "\n").unwrap();
    let refused = run(&["hdr", p.to_str().unwrap()]);
    assert_eq!(refused.status.code(), Some(2));
    let msg = String::from_utf8_lossy(&refused.stderr);
    assert!(msg.contains(&format!("line {}, column time_s: time", h + 201)) && msg.contains("`--time-order fix` merges"), "{msg}");
    let fixed = run(&["hdr", p.to_str().unwrap(), "--json", "--time-order", "fix"]);
    assert!(fixed.status.success());
    assert!(String::from_utf8_lossy(&fixed.stderr).contains("repeat.csv: time order: 1 rows of a repeated time merged"));
    assert_eq!(fixed.stdout, run(&["hdr", plain.to_str().unwrap(), "--json"]).stdout);
    let rows = dir.join("rows.csv");
    let batch = run(&["report", "--dir", dir.to_str().unwrap(), "--time-order", "fix", "--out", rows.to_str().unwrap()]);
    assert!(batch.status.success(), "{}", String::from_utf8_lossy(&batch.stderr));
    let out = std::fs::read_to_string(&rows).unwrap();
    assert!(out.contains("time order: 1 rows of a repeated time merged"), "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Out of memory (here a 60 MB address-space limit and a 16 MB log) exits 2 with one line,
/// never an abort with a backtrace (exit 134).
#[cfg(unix)]
#[test]
fn out_of_memory_exits_2_with_one_line() {
    let mut s = String::from("time_s,gyro_dps,ref_heading_deg,speed_mps\n");
    for i in 0..600_000 {
        s.push_str(&format!("{:.1},{:.3},{},10\n", i as f64 / 10.0, 0.5 + (i % 7) as f64 * 0.01, (i / 10) % 360));
    }
    let p = write("big.csv", &s);
    let cmd = format!("ulimit -v 60000; exec '{}' pipeline '{}'", env!("CARGO_BIN_EXE_gyrodrift"), p.display());
    let out = Command::new("sh").args(["-c", &cmd]).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.starts_with("gyrodrift: out of memory (a request for ") && err.lines().count() == 1, "{err}");
}

/// The test drive with a clockwise gyro: every rate negated.
fn clockwise_csv() -> String {
    drive_csv()
        .lines()
        .enumerate()
        .map(|(i, l)| {
            let mut c: Vec<String> = l.split(',').map(str::to_string).collect();
            if i > 1 {
                c[1] = format!("{}", -c[1].parse::<f64>().unwrap());
            }
            c.join(",") + "\n"
        })
        .collect()
}

/// A log `check` finds an error in (here a clockwise gyro) is refused by every method with
/// the finding and its fix, exit 2, rather than given absurd figures; `--ignore-check` runs it.
#[test]
fn a_log_check_finds_an_error_in_is_refused_unless_ignored() {
    let p = write("cw.csv", &clockwise_csv());
    for cmd in [&["hdr"][..], &["pipeline"], &["report"], &["report", "--compare"]] {
        let out = run(&[cmd, &[p.to_str().unwrap()]].concat());
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{cmd:?}: {err}");
        assert!(err.contains("check: error [gyro_sign]") && err.contains("positive = \"cw\"") && err.contains("--ignore-check"), "{err}");
    }
    let forced = run(&["hdr", p.to_str().unwrap(), "--ignore-check", "--json"]);
    assert!(forced.status.success());
    assert!(String::from_utf8_lossy(&forced.stderr).contains("check: error [gyro_sign]"));
}

/// `check` takes several logs, as a linter does: each checked and said with its file; exit 1
/// when one has an error, 2 when one cannot be read (the others checked all the same); JSON a
/// list with each `file`; with `--joined split` each log of a file of several joined on.
#[test]
fn check_takes_several_logs_and_exits_by_the_worst() {
    let good = write("check-good.csv", &drive_csv());
    let cw = write("check-cw.csv", &clockwise_csv());
    let missing = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("check-missing.csv");
    let (g, c, m) = (good.to_str().unwrap(), cw.to_str().unwrap(), missing.to_str().unwrap());
    let out = run(&["check", g]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let out = run(&["check", g, c]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.starts_with(&format!("{g}: ")) && text.contains(&format!("\n{c}: ")) && text.contains("error [gyro_sign]"), "{text}");
    let out = run(&["check", m, g, c]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains(&format!("{m}: cannot open")) && err.ends_with(&format!("1 of 3 files could not be read: {m}\n")), "{err}");
    assert!(String::from_utf8_lossy(&out.stdout).contains("error [gyro_sign]"));
    let out = run(&["check", "--json", g, c]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let files: Vec<&str> = v.as_array().unwrap().iter().map(|r| r["file"].as_str().unwrap()).collect();
    assert_eq!(files, [g, c]);
    assert!(v[1]["report"]["findings"].as_array().unwrap().iter().any(|f| f["code"] == "gyro_sign"), "{v}");
    // A file of two logs joined on: refused, or each log checked under --joined split.
    let joined = write("check-joined.csv", &format!("{}{}", drive_csv(), drive_csv()));
    let j = joined.to_str().unwrap();
    assert_eq!(run(&["check", j]).status.code(), Some(2));
    let out = run(&["check", "--joined", "split", j]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success() && text.contains(&format!("{j} (log 1 of 2): ")) && text.contains(&format!("{j} (log 2 of 2): ")),
        "{text}"
    );
}

/// `-` reads the log from standard input, so commands chain (`import | inject | pipeline -`):
/// the same numbers as the file, named "stdin" (or by its `# name:`), errors said as
/// "standard input: ..."; `-` twice is refused, as standard input can be read once.
#[test]
fn a_dash_reads_the_log_from_standard_input() {
    use std::io::Write;
    let with_stdin = |args: &[&str], input: &[u8]| {
        let mut c = bin()
            .args(args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        c.stdin.take().unwrap().write_all(input).unwrap();
        c.wait_with_output().unwrap()
    };
    let text = drive_csv();
    let p = write("stdin-drive.csv", &text);
    let from_file = run(&["pipeline", "--json", p.to_str().unwrap()]);
    let from_stdin = with_stdin(&["pipeline", "--json", "-"], text.as_bytes());
    assert!(from_stdin.status.success(), "{}", String::from_utf8_lossy(&from_stdin.stderr));
    assert_eq!(from_stdin.stdout, from_file.stdout);
    let table = with_stdin(&["hdr", "-"], text.as_bytes());
    assert!(String::from_utf8_lossy(&table.stdout).starts_with("standard input: HDR"));
    // Without a `# name:`, in a report beside a file: a row named "stdin".
    let unnamed: String = text.lines().filter(|l| !l.starts_with("# name:")).map(|l| format!("{l}\n")).collect();
    let p = write("stdin-drive.csv", &unnamed);
    let rows = with_stdin(&["report", "--json", "-", p.to_str().unwrap()], unnamed.as_bytes());
    let v: serde_json::Value = serde_json::from_slice(&rows.stdout).unwrap();
    let names: Vec<&str> = v["rows"].as_array().unwrap().iter().map(|d| d["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["stdin", "stdin-drive"], "{v}");
    // Bad or absent input: exit 2, one line naming standard input.
    for (input, want) in [(&b""[..], "standard input: empty file"), (b"time_s,gyro_dps\n0,x\n", "standard input: line 2, column gyro_dps")]
    {
        let o = with_stdin(&["hdr", "-"], input);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2));
        assert!(err.starts_with(want) && err.lines().count() == 1, "{err}");
    }
    let o = with_stdin(&["report", "-", "-"], text.as_bytes());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("standard input is given twice"));
}

/// A log a spreadsheet saved where the decimal mark is a comma (`;` between cells, `0,25`,
/// CRLF, a byte-order mark; or tabs) runs as the comma-separated log, gzipped too; a bad
/// cell in it is named by the file's line and column.
#[test]
fn a_log_saved_with_semicolons_and_decimal_commas_runs_as_the_comma_log() {
    let text = drive_csv();
    let comma = write("dialect-comma.csv", &text);
    let saved_as = |sep: &str| -> String {
        let rows = text.lines().map(|l| {
            if l.starts_with('#') {
                l.to_string()
            } else {
                l.replace(',', "\u{0}").replace('.', ",").replace('\u{0}', sep)
            }
        });
        format!("\u{feff}{}\r\n", rows.collect::<Vec<_>>().join("\r\n"))
    };
    let semi = write("dialect-semicolon.csv", &saved_as(";"));
    let tab = write("dialect-tab.tsv", &saved_as("\t"));
    let want = run(&["pipeline", "--json", comma.to_str().unwrap()]);
    assert!(want.status.success());
    for p in [&semi, &tab] {
        let got = run(&["pipeline", "--json", p.to_str().unwrap()]);
        assert!(got.status.success(), "{}", String::from_utf8_lossy(&got.stderr));
        assert_eq!(got.stdout, want.stdout, "{}", p.display());
    }
    // `import` writes it as the format is written: the comma log, byte for byte.
    let out = run(&["import", semi.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8(out.stdout).unwrap(), text);
    assert!(String::from_utf8_lossy(&out.stderr).contains("a drive log v1 already"));
    assert_eq!(run(&["import", semi.to_str().unwrap(), "--print-recipe"]).status.code(), Some(2));
    let bad = write("dialect-bad.csv", &saved_as(";").replacen("\r\n0,1;", "\r\n0,1;x", 1));
    let err = String::from_utf8(run(&["hdr", bad.to_str().unwrap()]).stderr).unwrap();
    assert!(err.contains("line 4, column gyro_dps: \"x1\" is not a number"), "{err}");
}

/// A file refused for its time column that the import's draft reads (time in ms, or
/// date-times in `time_s`) names the `import --print-recipe` command; a v1 log with one bad
/// time cell, or a table without a yaw rate, gets no such hint.
#[test]
fn a_loggers_table_refused_for_its_time_names_the_draft_recipe() {
    for (name, text, hint) in [
        ("hint-ms.csv", "time_ms,gyro_dps\n0,0.1\n100,0.2\n", true),
        ("hint-iso.csv", "time_s,gyro_dps\n2026-11-28T10:00:00.000Z,0.1\n2026-11-28T10:00:00.100Z,0.1\n", true),
        ("hint-bad-cell.csv", "time_s,gyro_dps\n0,1\nx,2\n", false),
        ("hint-no-gyro.csv", "a,b\n1,2\n", false),
    ] {
        let p = write(name, text);
        let out = run(&["hdr", p.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8(out.stderr).unwrap();
        let want = format!("`gyrodrift import {} --print-recipe` drafts a recipe", p.display());
        assert_eq!(err.contains(&want), hint, "{name}: {err}");
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        if hint {
            let draft = run(&["import", p.to_str().unwrap(), "--print-recipe"]);
            assert!(draft.status.success(), "{name}: {}", String::from_utf8_lossy(&draft.stderr));
            assert!(String::from_utf8_lossy(&draft.stdout).contains("[yaw_rate]"), "{name}");
        }
    }
}

/// A logger stopped mid-line: the last line, cut short (no line end, fewer cells than the
/// header), is dropped and said on stderr; the results are those of the log without it.
#[test]
fn a_last_line_cut_short_is_dropped_and_said() {
    let text = drive_csv();
    let whole = write("cut-whole.csv", &text);
    let cut_at = text.trim_end().rfind('\n').unwrap();
    let without = write("cut-without.csv", &text[..=cut_at]);
    let cut = write("cut-short.csv", &text[..cut_at + 6]);
    let want = run(&["pipeline", "--json", without.to_str().unwrap()]);
    let got = run(&["pipeline", "--json", cut.to_str().unwrap()]);
    assert!(got.status.success(), "{}", String::from_utf8_lossy(&got.stderr));
    assert_eq!(got.stdout, want.stdout);
    assert_ne!(got.stdout, run(&["pipeline", "--json", whole.to_str().unwrap()]).stdout);
    let err = String::from_utf8(got.stderr).unwrap();
    assert_eq!(err.lines().next().unwrap(), format!("{}: its last line, cut short (2 of 4 cells, no line end), dropped", cut.display()));
}

/// Two logs joined into one file (`cat a.csv b.csv`, a logger appending sessions): refused
/// naming the second log's first line, whatever the time-order policy, not as a short row,
/// with the command that splits it; `split` writes the two, each scoring as the log joined.
#[test]
fn two_logs_joined_are_refused_naming_the_seconds_first_line() {
    let text = drive_csv();
    let first_lines = text.lines().count();
    let joined = write("joined.csv", &format!("{text}{}", text.replace("test drive", "second drive")));
    for extra in [&[][..], &["--time-order", "fix"][..]] {
        let out = run(&[&["hdr", joined.to_str().unwrap()][..], extra].concat());
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        let want = format!(
            "{}: line {}: a '#' line after the rows (\"# name: second drive\"): a second log joined on? A log's '#' lines come before its header; split the file before this line; `gyrodrift split {}` writes each log in it as a file of its own (the scoring commands take `--joined split`)",
            joined.display(),
            first_lines + 1,
            joined.display()
        );
        assert_eq!(err.trim_end(), want);
    }
    let dir = std::env::temp_dir().join(format!("gd-split-{}", std::process::id()));
    let out = run(&["split", joined.to_str().unwrap(), "--out-dir", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let said = String::from_utf8(out.stdout).unwrap();
    let (a, b) = (dir.join("joined.1.csv"), dir.join("joined.2.csv"));
    assert!(
        said.contains(&format!("{}: from line 1,", a.display()))
            && said.contains(&format!("{}: from line {},", b.display(), first_lines + 1)),
        "{said}"
    );
    let alone = write("alone.csv", &text);
    let second = write("second.csv", &text.replace("test drive", "second drive"));
    for (part, log) in [(&a, &alone), (&b, &second)] {
        let hdr = |p: &PathBuf| run(&["hdr", "--json", p.to_str().unwrap()]).stdout;
        assert_eq!(hdr(part), hdr(log), "{}", part.display());
    }
    // --joined split: the scoring commands take each log as a drive of its own.
    let both = run(&["hdr", "--json", "--joined", "split", joined.to_str().unwrap()]);
    assert!(both.status.success(), "{}", String::from_utf8_lossy(&both.stderr));
    let each: Vec<serde_json::Value> =
        [&alone, &second].iter().map(|p| serde_json::from_slice(&run(&["hdr", "--json", p.to_str().unwrap()]).stdout).unwrap()).collect();
    assert_eq!(serde_json::from_slice::<serde_json::Value>(&both.stdout).unwrap(), serde_json::Value::from(each));
    let err = String::from_utf8(both.stderr).unwrap();
    assert!(err.contains(&format!("log 2 of 2 joined in the file, from line {}", first_lines + 1)), "{err}");
    // A row late in the second log: refused naming the option that sorts it in, as the
    // scoring commands refuse it; given, each log written.
    let late = text.replace("test drive", "second drive").replacen("\n0.5,", "\n0.35,", 1);
    let late = write("late.csv", &format!("{text}{late}"));
    let out = run(&["split", late.to_str().unwrap(), "--out-dir", dir.to_str().unwrap()]);
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.code() == Some(2) && err.contains("`--time-order fix` merges repeated times"), "{err}");
    let out = run(&["split", late.to_str().unwrap(), "--out-dir", dir.to_str().unwrap(), "--time-order", "fix"]);
    assert!(out.status.success() && dir.join("late.2.csv").exists(), "{}", String::from_utf8_lossy(&out.stderr));
    // A file of one log: nothing written.
    let out = run(&["split", alone.to_str().unwrap(), "--out-dir", dir.to_str().unwrap()]);
    assert!(String::from_utf8(out.stdout).unwrap().ends_with("one log, nothing joined on: nothing written\n"));
    assert!(!dir.join("alone.1.csv").exists());
}

/// A logger that restarted its clock without a new header: refused naming the line as a
/// clock reset, with `split` as the way on (not `--time-order fix`, which cannot mend it);
/// `--joined split` scores each part as the log it is, `split` writes them.
#[test]
fn a_clock_reset_is_refused_with_split_and_read_in_parts() {
    let text = drive_csv();
    let rows = text.lines().skip(2).collect::<Vec<_>>().join("\n");
    let reset = write("reset.csv", &format!("{text}{rows}\n"));
    let reset_line = text.lines().count() + 1;
    for extra in [&[][..], &["--time-order", "fix"][..]] {
        let out = run(&[&["hdr", reset.to_str().unwrap()][..], extra].concat());
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains(&format!("line {reset_line}, column time_s: time 0 goes back")) && err.contains("a clock reset?"), "{err}");
        assert!(
            err.contains("writes each part (a logger restarted?) as a file of its own") && !err.contains("`--time-order fix` merges"),
            "{err}"
        );
    }
    let both = run(&["hdr", "--json", "--joined", "split", reset.to_str().unwrap()]);
    assert!(both.status.success(), "{}", String::from_utf8_lossy(&both.stderr));
    let alone: serde_json::Value =
        serde_json::from_slice(&run(&["hdr", "--json", write("one.csv", &text).to_str().unwrap()]).stdout).unwrap();
    assert_eq!(serde_json::from_slice::<serde_json::Value>(&both.stdout).unwrap(), serde_json::Value::from(vec![alone.clone(), alone]));
    let err = String::from_utf8(both.stderr).unwrap();
    assert!(
        err.contains(&format!("log 2 of 2 joined in the file, from line {reset_line}; its clock reset on this line (time 0 after 600)")),
        "{err}"
    );
    let dir = std::env::temp_dir().join(format!("gd-reset-{}", std::process::id()));
    let out = run(&["split", reset.to_str().unwrap(), "--out-dir", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let second = std::fs::read_to_string(dir.join("reset.2.csv")).unwrap();
    assert!(second.starts_with("# name: test drive (2)\n"), "{second}");
}

/// A log opened and saved by a spreadsheet (Excel or LibreOffice, either locale): metadata
/// lines padded with separators to the header's width, one with a comma quoted, Excel's
/// `sep=;` first: it runs as the log, and `import` writes it back as the log.
#[test]
fn a_log_a_spreadsheet_opened_and_saved_runs_as_the_log() {
    let text = drive_csv().replace("# name: test drive\n", "# name: test drive\n# description: a, b\n# bias_s: 20\n");
    let log = write("excel-log.csv", &text);
    let saved = |sep: char, decimal: char| -> String {
        let mut out = if sep == ';' { String::from("sep=;\r\n") } else { String::new() };
        for l in text.lines() {
            let row = match l.strip_prefix('#') {
                Some(_) if l.contains(sep) => format!("\"{l}\"{sep}{sep}{sep}"),
                Some(_) => format!("{l}{sep}{sep}{sep}"),
                None => l.replace(',', &sep.to_string()).replace('.', &decimal.to_string()),
            };
            out += &format!("{row}\r\n");
        }
        out
    };
    let want = run(&["pipeline", "--json", log.to_str().unwrap()]);
    for (name, sep, decimal) in [("excel-comma.csv", ',', '.'), ("excel-semicolon.csv", ';', ',')] {
        let p = write(name, &saved(sep, decimal));
        let got = run(&["pipeline", "--json", p.to_str().unwrap()]);
        assert!(got.status.success(), "{name}: {}", String::from_utf8_lossy(&got.stderr));
        assert_eq!(got.stdout, want.stdout, "{name}");
        let back = run(&["import", p.to_str().unwrap()]);
        assert_eq!(String::from_utf8(back.stdout).unwrap(), text, "{name}");
    }
}

/// Excel's "CSV" on Windows is Windows-1252, not UTF-8: a `ü` in a name reads as `ü`, said
/// on stderr; the numbers are the UTF-8 log's.
#[test]
fn a_log_in_windows_1252_reads_and_says_so() {
    let text = drive_csv().replace("# name: test drive", "# name: Fahrt München");
    let utf8 = write("latin-utf8.csv", &text);
    let latin: Vec<u8> = text.chars().map(|c| u8::try_from(u32::from(c)).unwrap()).collect();
    let p = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("latin-1252.csv");
    std::fs::write(&p, latin).unwrap();
    let got = run(&["pipeline", "--json", p.to_str().unwrap()]);
    assert!(got.status.success(), "{}", String::from_utf8_lossy(&got.stderr));
    assert_eq!(got.stdout, run(&["pipeline", "--json", utf8.to_str().unwrap()]).stdout);
    let err = String::from_utf8(got.stderr).unwrap();
    assert!(err.starts_with(&format!("{}: its text read as Windows-1252 (it is not UTF-8)", p.display())), "{err}");
}

/// `allan` and `calibrate` take `--joined split` too: each log of a file of several gets its
/// own result (a JSON array, or the tables under their names), each as that log alone gives
/// it; without the option the file is refused naming the second log's first line.
#[test]
fn allan_and_calibrate_read_each_joined_log() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../sample-logs");
    for (cmd, file) in [("allan", "static/static-2h.csv"), ("calibrate", "turntable/session.csv")] {
        let text = std::fs::read_to_string(root.join(file)).unwrap();
        let joined = write(&format!("{cmd}-joined.csv"), &format!("{text}{text}"));
        let j = joined.to_str().unwrap();
        let refused = run(&[cmd, j]);
        assert_eq!(refused.status.code(), Some(2), "{cmd}");
        assert!(String::from_utf8(refused.stderr).unwrap().contains("a second log joined on?"), "{cmd}");
        let alone = run(&[cmd, "--json", root.join(file).to_str().unwrap()]);
        let one: serde_json::Value = serde_json::from_slice(&alone.stdout).unwrap();
        let both = run(&[cmd, "--json", "--joined", "split", j]);
        assert!(both.status.success(), "{cmd}: {}", String::from_utf8_lossy(&both.stderr));
        let got: serde_json::Value = serde_json::from_slice(&both.stdout).unwrap();
        assert_eq!(got, serde_json::Value::from(vec![one.clone(), one]), "{cmd}");
        let text_out = String::from_utf8(run(&[cmd, "--joined", "split", j]).stdout).unwrap();
        assert_eq!(text_out.matches("== ").count(), 2, "{cmd}: {text_out}");
    }
}

/// `inject` and `import` write one log: a file of several joined on is refused with
/// `--joined split` too (not read as its first log), naming the command that writes each.
#[test]
fn commands_that_write_one_log_refuse_joined_logs_naming_split() {
    let joined = write("write-one-joined.csv", &format!("{}{}", drive_csv(), drive_csv()));
    let j = joined.to_str().unwrap();
    let out = std::env::temp_dir().join(format!("gd-write-one-{}.csv", std::process::id()));
    for args in [&["inject", "--error", "bias_dps=1"][..], &["import"][..]] {
        let o = run(&[args, &["--joined", "split", j, "--out", out.to_str().unwrap()]].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(o.stderr).unwrap();
        assert!(err.contains(&format!("{j}: 2 logs joined in the file; this command writes one log: `gyrodrift split {j}`")), "{err}");
        assert!(!out.exists(), "{args:?}");
    }
}
