//! How every front takes a log before scoring it: what `check` finds is said (warnings),
//! a log with an error finding (time not in seconds, heading in radians, gyro in another
//! unit or clockwise) is refused unless asked to run it anyway, since every figure from it
//! would be absurd, and the gap policy splits it into parts scored as drives of their own.
//! One place, so the CLI, the fleet batch and the Python package refuse and split the same
//! logs.

use super::gaps::{split_at_gaps, GapPolicy, MIN_PART_S};
pub use super::refusal::Refusal;
use super::DriveLog;
use crate::check::{check, Finding, Severity};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// What to do with a log that has gaps, and whether a check error refuses it.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct InputPolicy {
    pub gaps: GapPolicy,
    /// Run a log even when `check` finds an error in it.
    pub ignore_check: bool,
    /// A v1 log whose time repeats or steps back a little: refused, or put in time order.
    pub time_order: TimeOrder,
    /// A file of several v1 logs joined on: refused naming the line, or each log a drive.
    pub joined: JoinedLogs,
}

/// What to do with a file of several v1 logs joined on (`cat a.csv b.csv`, a logger
/// appending each session to one file).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JoinedLogs {
    /// An error naming the second log's first line (the default: the file is not one log).
    #[default]
    Error,
    /// Each log read as a drive of its own ([`parse_joined`]), said in a warning.
    Split,
}

/// What to do with a v1 log whose time repeats or steps back by at most 1 s (a logger
/// writing a sample twice, or a row late).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TimeOrder {
    /// An error naming the line (the default: the log is not what it says).
    #[default]
    Error,
    /// Rows of one time merged by their mean, rows up to 1 s late sorted in, as the import's
    /// default time policies do (`parse_log_in_time_order`); said in a warning.
    Fix,
}

/// Parses a v1 log file as the native fronts read one (`log::dialect`: as a spreadsheet
/// saved it, a last line cut short dropped, Windows-1252 text, a second log joined on
/// refused naming its first line), by the time-order policy:
/// the log, and what was done to read it ("its last line, cut short (...), dropped; time
/// order: 1 rows of a repeated time merged"; None when nothing).
pub fn parse_by<R: std::io::Read>(reader: R, order: TimeOrder) -> Result<(DriveLog, Option<String>)> {
    let (log, fixes, read) = read_v1(reader, order)?;
    let said: Vec<String> = read.into_iter().chain((!fixes.is_empty()).then(|| format!("time order: {fixes}"))).collect();
    Ok((log, (!said.is_empty()).then(|| said.join("; "))))
}

/// A v1 log read as the dashboard's worker reads one it was asked to fix: as [`parse_by`]
/// with `Fix`, and what was done in the words the page shows ("1 rows of a repeated time
/// merged; its last line, cut short (...), dropped"; "" when nothing).
pub fn parse_fixing<R: std::io::Read>(reader: R) -> Result<(DriveLog, String)> {
    let (log, fixes, read) = read_v1(reader, TimeOrder::Fix)?;
    let said: Vec<String> = Some(fixes).filter(|s| !s.is_empty()).into_iter().chain(read).collect();
    Ok((log, said.join("; ")))
}

/// A v1 log read through `log::dialect` by the time-order policy: the log, what putting its
/// time in order did ("" when nothing or `Error`) and what reading the file did.
fn read_v1<R: std::io::Read>(reader: R, order: TimeOrder) -> Result<(DriveLog, String, Vec<String>)> {
    let mut reader = super::dialect::v1_reader(reader, true);
    let parsed = read_one(&mut reader, order);
    let (log, fixes) = reader.refuse_joined(parsed)?;
    Ok((log, fixes, reader.said()))
}

/// The log `reader` gives, by the time-order policy, and what putting its time in order did.
fn read_one<R: std::io::Read>(reader: &mut super::dialect::V1Reader<R>, order: TimeOrder) -> Result<(DriveLog, String)> {
    match order {
        TimeOrder::Error => super::parse_log(reader).map(|log| (log, String::new())),
        TimeOrder::Fix => super::parse_log_in_time_order(reader, Default::default()).map(|(log, fixes)| (log, fixes.to_text())),
    }
}

/// The logs `reader` gives, cut where the clock resets (time back by more than 1 s: a logger
/// restarted without writing a new header), each put in time order by the policy: the log,
/// what that did, and for a part after a reset the latest time before it. A named log cut
/// so is named "name (1)", "name (2)", ...
fn read_restarts<R: std::io::Read>(
    reader: &mut super::dialect::V1Reader<R>,
    order: TimeOrder,
    lines_before: u64,
) -> Result<Vec<(DriveLog, String, Option<f64>)>> {
    let mut log = super::parse::parse_log_unordered(reader, order == TimeOrder::Error, lines_before)?;
    let (mut latest, mut cuts) = (f64::NEG_INFINITY, Vec::new());
    for (i, &x) in log.time_s().iter().enumerate() {
        if crate::import::is_clock_reset(latest, x) {
            cuts.push((i, latest));
            latest = x;
        }
        latest = latest.max(x);
    }
    let mut parts: Vec<(DriveLog, Option<f64>)> = cuts.iter().rev().map(|&(i, after)| (log.split_off(i), Some(after))).collect();
    parts.push((log, None));
    parts.reverse();
    let n = parts.len();
    let in_order = |(k, (mut part, after)): (usize, (DriveLog, Option<f64>))| {
        part.meta.name = part.meta.name.take().map(|name| stem_in_file(&name, k, n));
        let (part, fixes) = match order {
            TimeOrder::Error => super::parse::strictly_increasing(&part).map(|_| (part, String::new()))?,
            TimeOrder::Fix => super::parse::in_time_order(part).map(|(l, f)| (l, f.to_text()))?,
        };
        Ok((part, fixes, after))
    };
    parts.into_iter().enumerate().map(in_order).collect()
}

/// Every log of a file that holds several joined on (`cat a.csv b.csv`, a logger appending
/// each session to one file, or restarting its clock without a new header), each read as
/// [`parse_by`] reads a file of its own, with what was done to read it and the line it starts
/// on. An error names the file's line. A second log with no rows (a `#` note after the last
/// row) is none: said on the log before it.
pub fn parse_joined<'a, R: std::io::Read + 'a>(reader: R, order: TimeOrder) -> Result<Vec<(DriveLog, Option<String>, u64)>> {
    let mut out: Vec<(DriveLog, Option<String>, u64)> = Vec::new();
    let (mut rest, mut first_line): (Box<dyn std::io::Read + 'a>, u64) = (Box::new(reader), 1);
    loop {
        let mut reader = super::dialect::v1_reader(rest, true).after_lines(first_line - 1);
        let parts = match (read_restarts(&mut reader, order, first_line - 1), out.last_mut()) {
            (Ok(read), _) => read,
            // Comments alone after the last log's rows: not a log.
            (Err(Error::File(m)), Some(last)) if m.starts_with("empty file") => {
                let note = format!("the '#' lines from line {first_line} on, with no rows after them, ignored");
                last.1 = Some(last.1.take().map_or(note.clone(), |s| format!("{s}; {note}")));
                return Ok(out);
            }
            (Err(Error::File(m)), Some(_)) => return Err(Error::File(m).within(&format!("the log from line {first_line}"))),
            (Err(e), _) => return Err(e),
        };
        let read = reader.said();
        for (log, fixes, reset_after) in parts {
            let (line, reset) = match (reset_after, log.line.first(), log.time_s().first()) {
                (Some(after), Some(&l), Some(t)) => {
                    (l, Some(format!("its clock reset on this line (time {t} after {after}): read on as a log of its own")))
                }
                _ => (first_line, None),
            };
            let fixes = (!fixes.is_empty()).then(|| format!("time order: {fixes}"));
            let said: Vec<String> = reset.into_iter().chain(read.iter().cloned()).chain(fixes).collect();
            out.push((log, (!said.is_empty()).then(|| said.join("; ")), line));
        }
        match reader.into_rest() {
            Some((joined, r)) => (rest, first_line) = (Box::new(r), joined.line),
            None => return Ok(out),
        }
    }
}

/// A v1 log file's logs by the input policy's time order and joined-logs rule: one, as
/// [`parse_by`] reads it; or, with [`JoinedLogs::Split`], each log joined on, what reading it
/// did then naming which it is and its first line.
pub fn parse_by_policy<R: std::io::Read>(reader: R, policy: InputPolicy) -> Result<Vec<(DriveLog, Option<String>)>> {
    if policy.joined == JoinedLogs::Error {
        return parse_by(reader, policy.time_order).map(|read| vec![read]);
    }
    let logs = parse_joined(reader, policy.time_order)?;
    let n = logs.len();
    let said = |k: usize, line: u64, s: Option<String>| {
        let at = format!("log {} of {n} joined in the file, from line {line}", k + 1);
        if n == 1 {
            s
        } else {
            Some(s.map_or(at.clone(), |s| format!("{at}; {s}")))
        }
    };
    Ok(logs.into_iter().enumerate().map(|(k, (log, s, line))| (log, said(k, line, s))).collect())
}

/// The name of log `k` of `n` read from one file, should it have no `# name:`: the file's
/// stem, with its number when the file held several joined on ("drive (2)").
pub fn stem_in_file(stem: &str, k: usize, n: usize) -> String {
    if n > 1 {
        format!("{stem} ({})", k + 1)
    } else {
        stem.to_string()
    }
}

/// A log taken: its parts (one without gaps), the check's warnings and what splitting did.
#[derive(Debug, Clone)]
pub struct Accepted {
    pub parts: Vec<DriveLog>,
    /// One line per finding that is not informational (`warning [code]: message; fix: ...`).
    /// Gap findings are not repeated here: `split` says what the policy did with them.
    pub warnings: Vec<String>,
    /// What splitting at gaps did, or None without gaps.
    pub split: Option<String>,
}

/// Checks, refuses or splits `log` (named `name` when it has no `# name:`). `bias_s` is the
/// static-bias window the method will use (the later parts get the first part's bias removed).
pub fn accept(mut log: DriveLog, name: &str, policy: InputPolicy, bias_s: Option<f64>) -> Result<Accepted> {
    let mut warnings = Vec::new();
    for f in check(&log).findings.iter().filter(|f| f.severity != Severity::Info && f.code != "gap") {
        let line = said(f);
        if f.severity == Severity::Error && !policy.ignore_check {
            return Err(Error::data(check_refused(&line, "--ignore-check")));
        }
        warnings.push(line);
    }
    log.meta.name.get_or_insert_with(|| name.to_string());
    let bias_s = log.bias_s(bias_s);
    let s = split_at_gaps(log, policy.gaps, bias_s)?;
    if s.parts.is_empty() {
        return Err(Error::data(format!("every part between its gaps is shorter than {MIN_PART_S} s")));
    }
    let split = s.summary();
    Ok(Accepted { parts: s.parts, warnings, split })
}

/// What a refusal of a log with a check error says after the finding (`Refusal::of`).
pub(super) const CHECK_REFUSED: &str = "(refused: its results would be absurd;";

/// The refusal of a log with a check error, `said` the finding as [`refusal`] gives it,
/// `run_anyway` the front's words for the option that runs it anyway: one text for the CLI,
/// the wasm tables and Python's.
pub fn check_refused(said: &str, run_anyway: &str) -> String {
    format!("{said} {CHECK_REFUSED} {run_anyway} runs it anyway)")
}

/// A finding as the fronts say it: "check: <severity> [<code>]: <message>; fix: <fix>".
fn said(f: &Finding) -> String {
    let fix = f.fix.as_deref().map(|x| format!("; fix: {x}")).unwrap_or_default();
    format!("check: {} [{}]: {}{fix}", f.severity.name(), f.code, f.message)
}

/// Why `accept` would refuse this log (its first check error, said as `accept` says it), or
/// None: for fronts that take logs already parsed (the wasm and Python tables), which refuse
/// the same logs as the CLI unless asked to run them anyway.
pub fn refusal(log: &DriveLog) -> Option<String> {
    check(log).findings.iter().find(|f| f.severity == Severity::Error).map(said)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::parse_log_str;

    fn drive(rows: impl Iterator<Item = (f64, f64)>) -> DriveLog {
        let mut s = String::from("time_s,gyro_dps,heading_ref_deg\n");
        for (t, h) in rows {
            s.push_str(&format!("{t},0.1,{h}\n"));
        }
        parse_log_str(&s).unwrap()
    }

    #[test]
    fn a_clean_log_is_one_part_named_by_the_caller() {
        let a = accept(drive((0..200).map(|i| (i as f64, 0.0))), "stem", InputPolicy::default(), None).unwrap();
        assert_eq!(a.parts.len(), 1);
        assert_eq!(a.parts[0].meta.name.as_deref(), Some("stem"));
        assert!(a.split.is_none());
    }

    #[test]
    fn a_gap_splits_or_refuses() {
        let rows = (0..100).map(|i| (i as f64, 0.0)).chain((0..100).map(|i| (300.0 + i as f64, 0.0)));
        let log = drive(rows);
        let a = accept(log.clone(), "g", InputPolicy::default(), None).unwrap();
        assert_eq!(a.parts.len(), 2);
        assert!(a.split.unwrap().contains("split at 1 gap"));
        let e = accept(log, "g", InputPolicy { gaps: GapPolicy::Error, ..Default::default() }, None).unwrap_err();
        assert!(e.to_string().contains("gap of 201.0 s"), "{e}");
    }

    #[test]
    fn a_check_error_refuses_unless_ignored() {
        let p = concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/city-1.csv");
        let mut log = crate::log::parse_log(std::fs::File::open(p).unwrap()).unwrap();
        // A clockwise gyro: every rate negated.
        log.column_mut(crate::log::Column::GyroDps).unwrap().iter_mut().for_each(|v| *v = -*v);
        let e = accept(log.clone(), "cw", InputPolicy::default(), None).unwrap_err();
        assert!(e.to_string().contains("[gyro_sign]") && e.to_string().contains("refused"), "{e}");
        assert_eq!(Refusal::of(&e), Some(Refusal::Check));
        // A message that names a check without being its refusal is none.
        assert_eq!(Refusal::of(&Error::data("check: error [gyro_sign]: a note")), None);
        let r = refusal(&log).unwrap();
        assert!(r.starts_with("check: error [gyro_sign]") && e.to_string().starts_with(&r), "{r}");
        assert_eq!(refusal(&drive((0..200).map(|i| (i as f64, 0.0)))), None);
        let a = accept(log, "cw", InputPolicy { ignore_check: true, ..Default::default() }, None).unwrap();
        assert!(a.warnings.iter().any(|w| w.starts_with("check: error [gyro_sign]")), "{:?}", a.warnings);
    }

    /// Two logs joined (a BOM and CRLF lines in the first, as a spreadsheet saves): both,
    /// each with its own metadata and the line it starts on; `parse_by` refuses the file,
    /// and the refusal is the one `Refusal::of` knows as joined.
    #[test]
    fn joined_logs_are_read_each_as_a_log_of_its_own() {
        let first = "\u{feff}# name: City 1\r\n# bias_s: 20\r\ntime_s,gyro_dps\r\n0,1\r\n1,2\r\n";
        let second = "# name: City 2\n# bias_s: 5\ntime_s,gyro_dps\n0,3\n";
        let text = format!("{first}{second}");
        let logs = parse_joined(text.as_bytes(), TimeOrder::Error).unwrap();
        let got: Vec<_> =
            logs.iter().map(|(l, said, line)| (l.meta.name.clone().unwrap(), l.meta.bias_s, l.len(), said.clone(), *line)).collect();
        assert_eq!(got, [("City 1".into(), Some(20.0), 2, None, 1), ("City 2".into(), Some(5.0), 1, None, 6)]);
        assert_eq!(logs[1].0.column(crate::log::Column::GyroDps).unwrap(), &[3.0]);
        let e = parse_by(text.as_bytes(), TimeOrder::Error).unwrap_err();
        assert!(Refusal::of(&e) == Some(Refusal::Joined) && e.to_string().starts_with("line 6:"), "{e}");
        assert_eq!(Refusal::of(&Error::Line { line: 6, message: "a bad row".into() }), None);
        // Three logs: the third starts where the second's line count says.
        let three = format!("{text}{second}");
        let lines: Vec<u64> = parse_joined(three.as_bytes(), TimeOrder::Error).unwrap().iter().map(|x| x.2).collect();
        assert_eq!(lines, [1, 6, 10]);
    }

    /// A bad cell in a later log names the file's line; one with a header and no rows is an
    /// error naming where it starts; `#` lines alone after the last rows are a note, not a
    /// log; a `;` log with decimal commas joined to another reads both.
    #[test]
    fn a_joined_log_is_read_or_refused_naming_the_files_lines() {
        let text = "time_s,gyro_dps\n0,1\n# name: b\ntime_s,gyro_dps\n0,1\n1,x\n";
        let e = parse_joined(text.as_bytes(), TimeOrder::Error).unwrap_err().to_string();
        assert!(e.starts_with("line 6, column gyro_dps"), "{e}");
        let e = parse_joined(&b"time_s,gyro_dps\n0,1\n# name: b\ntime_s,gyro_dps\n"[..], TimeOrder::Error).unwrap_err().to_string();
        assert!(e.starts_with("the log from line 3: no data rows: the file has a header (line 4)"), "{e}");
        // A row late in the second log: its line and the line of the row before, the file's.
        let late = "time_s,gyro_dps\n0,1\n# name: b\ntime_s,gyro_dps\n1,1\n0.5,1\n";
        let e = parse_joined(late.as_bytes(), TimeOrder::Error).unwrap_err().to_string();
        assert!(e.starts_with("line 6, column time_s: time 0.5 goes back from 1 on line 5:"), "{e}");
        // A third log: its start and a late row in it, counted on from the second's.
        let third = format!("{late}\n# name: c\ntime_s,gyro_dps\n0,1\n2,1\n1.5,1\n");
        let logs = parse_joined(third.as_bytes(), TimeOrder::Fix).unwrap();
        assert_eq!(logs.iter().map(|l| l.2).collect::<Vec<_>>(), [1, 3, 8]);
        assert_eq!(logs[2].0.line, [10, 12, 11]);
        let e = parse_joined(third.as_bytes(), TimeOrder::Error).unwrap_err().to_string();
        assert!(e.starts_with("line 6,"), "{e}");
        let e = parse_joined(third.replace("1,1\n0.5", "0.5,1\n1").as_bytes(), TimeOrder::Error).unwrap_err().to_string();
        assert!(e.starts_with("line 12, column time_s: time 1.5 goes back from 2 on line 11:"), "{e}");
        // A bad time cell quoting "on line 2" is quoted as it is.
        let quoted = "time_s,gyro_dps\n0,1\n# name: b\ntime_s,gyro_dps\non line 2,1\n";
        let e = parse_joined(quoted.as_bytes(), TimeOrder::Error).unwrap_err().to_string();
        assert!(e.starts_with("line 5, column time_s: \"on line 2\""), "{e}");
        let logs = parse_joined(&b"time_s,gyro_dps\n0,1\n1,2\n# stopped by the user\n"[..], TimeOrder::Fix).unwrap();
        assert_eq!(logs.len(), 1);
        assert_eq!(logs[0].1.as_deref(), Some("the '#' lines from line 4 on, with no rows after them, ignored"));
        let rows: String = (0..30_000).map(|i| format!("{i};0,5\n")).collect();
        let semi = format!("# name: a\ntime_s;gyro_dps\n{rows}# name: b\ntime_s;gyro_dps\n0;1,5\n");
        let logs = parse_joined(semi.as_bytes(), TimeOrder::Error).unwrap();
        assert_eq!((logs[0].0.len(), logs[1].0.len(), logs[1].2), (30_000, 1, 30_003));
        assert_eq!(logs[1].0.column(crate::log::Column::GyroDps).unwrap(), &[1.5]);
    }

    /// A second log that starts with its header row alone (a logger appending each session
    /// with a header, no metadata), or with a byte-order mark (`cat` of two files Excel
    /// saved): refused naming that line as a second log, not a cell that is not a number;
    /// read on, each log is the log alone.
    #[test]
    fn a_header_row_again_or_a_byte_order_mark_starts_a_second_log() {
        let first = "# name: a\ntime_s,gyro_dps\n0,1\n1,2\n";
        for (second, text) in [
            ("time_s,gyro_dps\r\n5,3\n6,4\n", "the header row again after the rows (\"time_s,gyro_dps\")"),
            ("\u{feff}# name: b\ntime_s,gyro_dps\n5,3\n6,4\n", "a '#' line after the rows (\"# name: b\")"),
            ("\u{feff}time_s,gyro_dps\n5,3\n6,4\n", "the header row again after the rows (\"time_s,gyro_dps\")"),
        ] {
            let joined = format!("{first}{second}");
            let e = parse_by(joined.as_bytes(), TimeOrder::Error).unwrap_err();
            assert!(
                Refusal::of(&e) == Some(Refusal::Joined) && e.to_string().starts_with(&format!("line 5: {text}: a second log joined on?")),
                "{e}"
            );
            let logs = parse_joined(joined.as_bytes(), TimeOrder::Error).unwrap();
            let alone = parse_by(second.as_bytes(), TimeOrder::Error).unwrap().0;
            assert_eq!((logs.len(), logs[1].2, logs[1].0.meta.name.clone()), (2, 5, alone.meta.name.clone()));
            assert_eq!(logs[1].0.column(crate::log::Column::GyroDps).unwrap(), alone.column(crate::log::Column::GyroDps).unwrap());
        }
        // A row that starts with the header's text is no header.
        let logs = parse_joined(&b"time_s,gyro_dps\n0,1\ntime_s,gyro_dps,x\n"[..], TimeOrder::Error);
        assert!(logs.is_err_and(|e| e.to_string().starts_with("line 3: row has 3 fields")));
    }

    /// A logger that restarted its clock without a new header (time back by more than 1 s):
    /// refused naming the line as a clock reset, which no time-order fix mends; read as joined
    /// logs, each part is a log of its own named by its number, its lines the file's, the
    /// second's rows as they were; a step back of 1 s or less within a part is the time-order
    /// policy's, as in a file of its own.
    #[test]
    fn a_clock_reset_is_refused_or_read_as_logs_of_their_own() {
        let text = "# name: a\n# bias_s: 2\ntime_s,gyro_dps\n0,1\n1,2\n2,3\n0,4\n0.5,5\n1,6\n";
        for order in [TimeOrder::Error, TimeOrder::Fix] {
            let e = parse_by(text.as_bytes(), order).unwrap_err();
            assert_eq!(Refusal::of(&e), Some(Refusal::ClockReset), "{e}");
            assert!(e.to_string().starts_with("line 7, column time_s: time 0 goes back"), "{e}");
        }
        let logs = parse_joined(text.as_bytes(), TimeOrder::Error).unwrap();
        let got: Vec<_> =
            logs.iter().map(|(l, _, line)| (l.meta.name.clone().unwrap(), l.meta.bias_s, l.len(), *line, l.line.clone())).collect();
        assert_eq!(got, [("a (1)".into(), Some(2.0), 3, 1, vec![4, 5, 6]), ("a (2)".into(), Some(2.0), 3, 7, vec![7, 8, 9])]);
        assert_eq!(logs[1].0.column(crate::log::Column::GyroDps).unwrap(), &[4.0, 5.0, 6.0]);
        assert_eq!(logs[1].1.as_deref(), Some("its clock reset on this line (time 0 after 2): read on as a log of its own"));
        assert_eq!(logs[0].1, None);
        let by_policy = parse_by_policy(text.as_bytes(), InputPolicy { joined: JoinedLogs::Split, ..Default::default() }).unwrap();
        assert!(by_policy[1].1.as_deref().unwrap().starts_with("log 2 of 2 joined in the file, from line 7; its clock reset"));
        // A row 0.5 s late in the second part: refused as in a file of its own, or sorted in.
        let late = format!("{text}0.5,7\n");
        let e = parse_joined(late.as_bytes(), TimeOrder::Error).unwrap_err();
        assert!(
            Refusal::of(&e) == Some(Refusal::TimeOrder)
                && e.to_string().starts_with("line 10, column time_s: time 0.5 goes back from 1 on line 9"),
            "{e}"
        );
        let fixed = parse_joined(late.as_bytes(), TimeOrder::Fix).unwrap();
        assert_eq!(fixed[1].0.len(), 3);
        assert!(fixed[1].1.as_deref().unwrap().contains("; time order: "), "{:?}", fixed[1].1);
        // A bad cell after the late row: the late row, the first in the file, is named (before,
        // the part was read whole and then put in order, so the cell was named first).
        let late_then_bad = format!("{late}2,x\n");
        let e = parse_joined(late_then_bad.as_bytes(), TimeOrder::Error).unwrap_err();
        assert!(Refusal::of(&e) == Some(Refusal::TimeOrder) && e.to_string().starts_with("line 10, column time_s"), "{e}");
        let e = parse_joined(late_then_bad.as_bytes(), TimeOrder::Fix).unwrap_err();
        assert!(e.to_string().starts_with("line 11, column gyro_dps"), "{e}");
        // A second log joined on after a reset: three logs, lines as in the file.
        let three = format!("{text}# name: b\ntime_s,gyro_dps\n0,1\n");
        let lines: Vec<u64> = parse_joined(three.as_bytes(), TimeOrder::Error).unwrap().iter().map(|x| x.2).collect();
        assert_eq!(lines, [1, 7, 10]);
    }

    /// Two logs a spreadsheet saved with `;` and decimal commas, their metadata padded to the
    /// header's width, joined: the second, starting past the first read's buffer, is read with
    /// its own separator and padding as the log alone is (before, its `# bias_s: 20;` was
    /// refused as not a number).
    #[test]
    fn joined_spreadsheet_logs_with_padded_metadata_read_as_each_alone() {
        let log = |name: &str, n: usize| {
            let rows: String = (0..n).map(|i| format!("{i};0,{}\n", i % 10)).collect();
            format!("# name: {name};\n# bias_s: 20;\ntime_s;gyro_dps\n{rows}")
        };
        let (a, b) = (log("a", 20_000), log("b", 3));
        let logs = parse_joined(format!("{a}{b}").as_bytes(), TimeOrder::Error).unwrap();
        let alone = parse_joined(b.as_bytes(), TimeOrder::Error).unwrap();
        assert_eq!(logs.len(), 2);
        assert_eq!((logs[0].0.len(), logs[0].0.meta.bias_s, logs[1].2), (20_000, Some(20.0), 20_004));
        assert_eq!((logs[1].0.meta.name.as_deref(), logs[1].0.meta.bias_s), (Some("b"), Some(20.0)));
        assert_eq!(logs[1].0.column(crate::log::Column::GyroDps).unwrap(), alone[0].0.column(crate::log::Column::GyroDps).unwrap());
        assert_eq!(logs[1].0.column(crate::log::Column::GyroDps).unwrap(), &[0.0, 0.1, 0.2]);
    }
}
