use super::*;
use crate::log::Column;

fn read_all(bytes: &[u8], drop_cut: bool) -> (Vec<u8>, Option<CutLine>) {
    let mut out = Vec::new();
    let mut r = v1_reader(bytes, drop_cut);
    r.read_to_end(&mut out).unwrap();
    (out, r.cut_last_line())
}

/// A reader that gives at most `n` bytes per read, so the line state and the held-back
/// line cross every boundary.
struct Trickle<'a>(&'a [u8], usize);
impl Read for Trickle<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.1.min(buf.len()).min(self.0.len());
        buf[..n].copy_from_slice(&self.0[..n]);
        self.0 = &self.0[n..];
        Ok(n)
    }
}

#[test]
fn a_semicolon_log_with_decimal_commas_reads_as_the_comma_log() {
    let eu = "\u{feff}# name: Fahrt, Teil 1\r\n# bias_s: 2,5x\r\ntime_s;gyro_dps;ref_heading_deg\r\n0;0,5;\r\n0,1;-1,25;10,5\r\n";
    let us = "\u{feff}# name: Fahrt, Teil 1\r\n# bias_s: 2,5x\r\ntime_s,gyro_dps,ref_heading_deg\r\n0,0.5,\r\n0.1,-1.25,10.5\r\n";
    assert_eq!(String::from_utf8(read_all(eu.as_bytes(), true).0).unwrap(), us);
    // The metadata line keeps its commas (a name may hold one); a tab and `|` too.
    for sep in ["\t", "|"] {
        let text = "time_s;gyro_dps\n0;1,5\n".replace(';', sep);
        assert_eq!(read_all(text.as_bytes(), true).0, b"time_s,gyro_dps\n0,1.5\n");
    }
    // Past the first buffer, in reads of 1 and 7 bytes, as in one.
    let rows: String = (0..20_000).map(|i| format!("{i},5;-0,{i}\n")).collect();
    let long = format!("# name: a, b\ntime_s;gyro_dps\n{rows}");
    let want = format!("# name: a, b\ntime_s,gyro_dps\n{}", rows.replace(',', ".").replace(';', ","));
    for step in [1, 7, 1 << 20] {
        let mut out = Vec::new();
        v1_reader(Trickle(long.as_bytes(), step), true).read_to_end(&mut out).unwrap();
        assert!(out == want.as_bytes(), "reads of {step} bytes");
    }
}

#[test]
fn a_comma_log_and_other_files_pass_through_untouched() {
    for text in [
        "# a; b\ntime_s,gyro_dps\n0,1\n",
        "time_s,gyro_dps\n0,1\n1,2", // a last line without its end, whole
        "time_s;gyro_dps,x\n0;1\n",  // a comma in the header: the format as written
        "t;gyro_dps\n0;1,5\n",       // no time_s: not a v1 log; its error stays its own
        "time_s\n0,5\n",             // one column: no separator to tell
        "time_s,gyro_dps",           // a header alone
        "",
        "# only a comment; here\n",
    ] {
        assert_eq!(read_all(text.as_bytes(), true), (text.as_bytes().to_vec(), None), "{text}");
    }
}

#[test]
fn a_last_line_cut_short_is_dropped_and_said_only_when_asked() {
    let cut = "# name: x\ntime_s,gyro_dps,speed_mps\n0,1,2\n1,2,3\n2,3";
    let (out, said) = read_all(cut.as_bytes(), true);
    assert_eq!(out, b"# name: x\ntime_s,gyro_dps,speed_mps\n0,1,2\n1,2,3\n");
    assert_eq!(said, Some(CutLine { fields: 2, header_fields: 3 }));
    assert_eq!(said.unwrap().to_text(), "its last line, cut short (2 of 3 cells, no line end), dropped");
    assert_eq!(read_all(cut.as_bytes(), false), (cut.as_bytes().to_vec(), None));
    // Cut in a `;` log, over many reads: the same.
    let eu = "time_s;gyro_dps;speed_mps\r\n0;1,5;2\r\n1;2,5;3\r\n2;3,";
    let mut out = Vec::new();
    let mut r = v1_reader(Trickle(eu.as_bytes(), 3), true);
    r.read_to_end(&mut out).unwrap();
    assert_eq!(
        (out, r.cut_last_line()),
        (b"time_s,gyro_dps,speed_mps\r\n0,1.5,2\r\n1,2.5,3\r\n".to_vec(), Some(CutLine { fields: 2, header_fields: 3 }))
    );
    // A line cut in the middle of the file is the parser's to refuse; a whole last line
    // without its end or a header alone is kept; a last `#` line is not cut (it ends the log,
    // below).
    for text in ["time_s,gyro_dps\n0\n1,2\n", "time_s,gyro_dps,x\n"] {
        assert_eq!(read_all(text.as_bytes(), true), (text.as_bytes().to_vec(), None), "{text}");
    }
    assert_eq!(read_all(b"time_s,gyro_dps\n0,1\n# end", true), (b"time_s,gyro_dps\n0,1\n".to_vec(), None));
}

#[test]
fn a_second_log_joined_on_ends_the_first_and_is_refused_naming_its_line() {
    let first = "\u{feff}# name: City 1\r\n# bias_s: 20\r\ntime_s,gyro_dps\r\n0,1\r\n1,2\r\n";
    let second = "# name: City 2, part 2\r\n# bias_s: 20\r\ntime_s,gyro_dps\r\n0,1\r\n";
    let joined = format!("{first}{second}");
    let mut r = v1_reader(joined.as_bytes(), true);
    let parsed = crate::parse_log(&mut r);
    assert_eq!(parsed.as_ref().map(|l| l.len()).ok(), Some(2), "the first log alone parses");
    assert_eq!(r.joined_at(), Some(&Joined { line: 6, text: "# name: City 2, part 2".into() }));
    let e = r.refuse_joined(parsed).unwrap_err().to_string();
    assert!(e.starts_with("line 6: a '#' line after the rows (\"# name: City 2, part 2\"): a second log joined on?"), "{e}");
    // Far into the file, in a `;` log (a comma-decimal spreadsheet), over reads of any size:
    // the line counted across the buffers.
    let rows: String = (0..30_000).map(|i| format!("{i};0,5\n")).collect();
    let long = format!("# name: a\ntime_s;gyro_dps\n{rows}# name: b\ntime_s;gyro_dps\n0;1\n");
    for step in [1, 4093, 1 << 20] {
        let mut r = v1_reader(Trickle(long.as_bytes(), step), true);
        let parsed = crate::parse_log(&mut r);
        assert_eq!(parsed.as_ref().map(|l| l.len()).ok(), Some(30_000), "reads of {step} bytes");
        assert_eq!(r.joined_at().map(|j| j.line), Some(30_003), "reads of {step} bytes");
    }
    // The header alone, then a second log: refused for the join, not for having no rows.
    let mut r = v1_reader(&b"time_s,gyro_dps\n# name: b\ntime_s,gyro_dps\n0,1\n"[..], true);
    let parsed = crate::parse_log(&mut r);
    assert!(r.refuse_joined(parsed).unwrap_err().to_string().starts_with("line 2: a '#' line"));
    // A bad row before the join is the error; a `#` inside a row or a metadata line is none.
    let mut r = v1_reader(&b"time_s,gyro_dps\n0,x\n# name: b\n"[..], true);
    let parsed = crate::parse_log(&mut r);
    assert!(r.refuse_joined(parsed).unwrap_err().to_string().starts_with("line 2, column gyro_dps"));
    let mut r = v1_reader(&b"# a\n# b\ntime_s,note\n0,#1\n1, #2\n"[..], true);
    let parsed = crate::parse_log(&mut r);
    assert_eq!((r.refuse_joined(parsed).map(|l| l.len()).ok(), r.joined_at()), (Some(2), None));
}

#[test]
fn the_log_parses_and_errors_name_the_files_line_and_column() {
    let log = crate::parse_log(comma_separated("# bias_s: 1\ntime_s;gyro_dps\n0;0,5\n0,5;-1,25\n".as_bytes())).unwrap();
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[0.5, -1.25]);
    assert_eq!(log.column(Column::TimeS).unwrap(), &[0.0, 0.5]);
    assert_eq!(log.meta.bias_s, Some(1.0));
    let e = crate::parse_log(comma_separated("# x\ntime_s;gyro_dps\n0;0,5\n1;1,2,3\n".as_bytes())).unwrap_err().to_string();
    assert!(e.contains("line 4") && e.contains("gyro_dps"), "{e}");
}

#[test]
fn a_log_a_spreadsheet_opened_and_saved_reads_as_written() {
    let log = "# name: Rural 3\n# description: simulated, 16.6 min\n# bias_s: 20\ntime_s,gyro_dps,speed_mps\n0,0.025,0.02\n0.1,0.05,0\n";
    // Excel or LibreOffice, comma locale: metadata padded, the one with a comma quoted.
    let us = "# name: Rural 3,,\r\n\"# description: simulated, 16.6 min\",,\r\n# bias_s: 20,,\r\ntime_s,gyro_dps,speed_mps\r\n0,0.025,0.02\r\n0.1,0.05,0\r\n";
    // Comma-decimal locale, with Excel's `sep=;` line first and a quote in a value.
    let eu = "sep=;\r\n# name: Rural 3;;\r\n\"# description: \"\"simulated\"\"; 16.6 min\";;\r\n# bias_s: 20;;\r\ntime_s;gyro_dps;speed_mps\r\n0;0,025;0,02\r\n0,1;0,05;0\r\n";
    let want = crate::parse_log(log.as_bytes()).unwrap();
    for text in [us, eu] {
        let got = crate::parse_log(comma_separated(text.as_bytes())).unwrap();
        assert_eq!(got.column(Column::GyroDps), want.column(Column::GyroDps), "{text}");
        assert_eq!((got.meta.name.as_deref(), got.meta.bias_s), (Some("Rural 3"), Some(20.0)), "{text}");
    }
    let eu_meta = crate::parse_log(comma_separated(eu.as_bytes())).unwrap().meta;
    assert_eq!(eu_meta.description.as_deref(), Some("\"simulated\"; 16.6 min"));
    // Line numbers stay the file's: a bad cell on line 7 of the Excel file.
    let bad = eu.replace("0,1;0,05;0", "0,1;x;0");
    let e = crate::parse_log(comma_separated(bad.as_bytes())).unwrap_err().to_string();
    assert!(e.starts_with("line 7, column gyro_dps"), "{e}");
    // A value ending in separators other than the padding's count keeps them.
    let (out, _) = read_all(b"# note: a,\ntime_s,gyro_dps,x\n0,1,2\n", true);
    assert_eq!(out, b"# note: a,\ntime_s,gyro_dps,x\n0,1,2\n");
}

#[test]
fn text_that_is_not_utf8_is_read_as_windows_1252_and_said() {
    // Excel's "CSV" on Windows: a name and a note column in Windows-1252.
    let text = b"# name: Fahrt M\xfcnchen \x80 \x93x\x94\ntime_s;gyro_dps;note\n0;0,5;gr\xfcn\n1;1,5;\n";
    let mut r = v1_reader(&text[..], true);
    let log = crate::parse_log(&mut r).unwrap();
    assert_eq!(log.meta.name.as_deref(), Some("Fahrt München € \u{201C}x\u{201D}"));
    assert_eq!(log.column(Column::GyroDps).unwrap(), &[0.5, 1.5]);
    assert_eq!(r.said(), ["its text read as Windows-1252 (it is not UTF-8)"]);
    // UTF-8 stays UTF-8, a character split between reads included.
    let utf8 = "# name: Fahrt München\ntime_s,gyro_dps\n0,1\n".as_bytes();
    let mut out = Vec::new();
    let mut r = v1_reader(Trickle(utf8, 1), true);
    r.read_to_end(&mut out).unwrap();
    assert_eq!((out.as_slice(), r.said().len()), (utf8, 0));
    // Every byte has its character: the 32 of 0x80-0x9F, and Latin-1 above.
    let all: Vec<u8> = (0x80..=0xFF).collect();
    let chars: Vec<char> = String::from_utf8(from_windows_1252(&all)).unwrap().chars().collect();
    assert_eq!((chars.len(), chars[0], chars[0x1F], chars[0x20], chars[0x7F]), (128, '€', 'Ÿ', '\u{A0}', 'ÿ'));
}

#[test]
fn utf16_text_and_binary_files_are_not_read_as_windows_1252_but_said() {
    // A spreadsheet's "Unicode text" (UTF-16 with its byte-order mark) and a Parquet file:
    // NUL bytes, which no Windows-1252 text has; the parser names what they are.
    let utf16: Vec<u8> = [0xFF, 0xFE].into_iter().chain("time_s,gyro_dps\n0,1\n".bytes().flat_map(|b| [b, 0])).collect();
    let e = crate::parse_log(comma_separated(&utf16[..])).unwrap_err().to_string();
    assert!(e.starts_with("line 1: UTF-16 text"), "{e}");
    let e = crate::parse_log(comma_separated(&b"PAR1\x15\x04\x15\x10\x00\x00\x81\n"[..])).unwrap_err().to_string();
    assert_eq!(e, "line 1: a binary file (NUL bytes), not a text table");
}
