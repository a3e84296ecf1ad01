//! A v1 log as a spreadsheet saves it where the decimal mark is a comma: cells separated by
//! `;` (or a tab, or `|`) and numbers like `0,25`. The native fronts read it as the
//! comma-separated log it stands for. Outside `#` lines the separator becomes a comma and a
//! comma a decimal point, byte for byte, so an error names the same line and column as in
//! the file. A comma-separated log (the format as written) passes through untouched.

use std::io::{self, Read};

/// Bytes read before the first one is given, to find the header row and its separator.
const HEAD_BYTES: usize = 64 * 1024;

/// Where the next byte stands in its line: the separator is mapped only in table rows.
#[derive(Clone, Copy, PartialEq)]
enum LineState {
    /// At the line's start or after spaces: a `#` makes it a metadata line.
    Start,
    Comment,
    Row,
}

/// `inner` read as a comma-separated v1 log (see the module's doc).
pub struct CommaSeparated<R> {
    inner: R,
    head: Option<Vec<u8>>,
    at: usize,
    /// The file's separator when it is not a comma (`None`: bytes pass through).
    separator: Option<u8>,
    state: LineState,
}

/// Wraps `inner`; nothing is read until the first `read`.
pub fn comma_separated<R: Read>(inner: R) -> CommaSeparated<R> {
    CommaSeparated { inner, head: None, at: 0, separator: None, state: LineState::Start }
}

/// The separator of a v1 header row that is not comma-separated: the most frequent of `;`,
/// tab and `|` in the first line that is neither blank nor `#`, when that line names
/// `time_s` and holds no comma.
fn separator_of(head: &[u8]) -> Option<u8> {
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let line = head.split(|&b| b == b'\n').find(|l| {
        let t = l.trim_ascii();
        !t.is_empty() && t[0] != b'#'
    })?;
    if line.contains(&b',') || !line.windows(6).any(|w| w == b"time_s") {
        return None;
    }
    [b';', b'\t', b'|'].into_iter().map(|d| (line.iter().filter(|&&b| b == d).count(), d)).filter(|&(n, _)| n > 0).max().map(|(_, d)| d)
}

impl<R: Read> CommaSeparated<R> {
    /// Reads the head (up to [`HEAD_BYTES`] or the end) and finds the separator.
    fn fill_head(&mut self) -> io::Result<()> {
        let mut head = Vec::with_capacity(HEAD_BYTES);
        (&mut self.inner).take(HEAD_BYTES as u64).read_to_end(&mut head)?;
        self.separator = separator_of(&head);
        let bom = if head.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
        self.map(&mut head[bom..]);
        self.head = Some(head);
        Ok(())
    }

    /// Maps bytes in place (see the module's doc), carrying the line state across calls.
    fn map(&mut self, bytes: &mut [u8]) {
        let Some(sep) = self.separator else { return };
        for b in bytes {
            self.state = match (self.state, *b) {
                (_, b'\n') => LineState::Start,
                (LineState::Start, b'#') => LineState::Comment,
                (LineState::Start, b' ' | b'\r') => LineState::Start,
                (LineState::Comment, _) => LineState::Comment,
                _ => {
                    if *b == sep {
                        *b = b',';
                    } else if *b == b',' {
                        *b = b'.';
                    }
                    LineState::Row
                }
            };
        }
    }
}

impl<R: Read> Read for CommaSeparated<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        if self.head.is_none() {
            self.fill_head()?;
        }
        if let Some(head) = &self.head {
            if self.at < head.len() {
                let n = (head.len() - self.at).min(buf.len());
                buf[..n].copy_from_slice(&head[self.at..self.at + n]);
                self.at += n;
                return Ok(n);
            }
        }
        let n = self.inner.read(buf)?;
        self.map(&mut buf[..n]);
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::Column;

    fn read_all(bytes: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        comma_separated(bytes).read_to_end(&mut out).unwrap();
        out
    }

    /// A reader that gives one byte per read, so the line state crosses every boundary.
    struct Trickle<'a>(&'a [u8]);
    impl Read for Trickle<'_> {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            let Some((&b, rest)) = self.0.split_first() else { return Ok(0) };
            if buf.is_empty() {
                return Ok(0);
            }
            buf[0] = b;
            self.0 = rest;
            Ok(1)
        }
    }

    #[test]
    fn a_semicolon_log_with_decimal_commas_reads_as_the_comma_log() {
        let eu = "\u{feff}# name: Fahrt, Teil 1\r\n# bias_s: 2,5x\r\ntime_s;gyro_dps;ref_heading_deg\r\n0;0,5;\r\n0,1;-1,25;10,5\r\n";
        let us = "\u{feff}# name: Fahrt, Teil 1\r\n# bias_s: 2,5x\r\ntime_s,gyro_dps,ref_heading_deg\r\n0,0.5,\r\n0.1,-1.25,10.5\r\n";
        assert_eq!(String::from_utf8(read_all(eu.as_bytes())).unwrap(), us);
        // The metadata line keeps its commas (a name may hold one); a tab and `|` too.
        for sep in ["\t", "|"] {
            let text = "time_s;gyro_dps\n0;1,5\n".replace(';', sep);
            assert_eq!(read_all(text.as_bytes()), b"time_s,gyro_dps\n0,1.5\n");
        }
        // Past the head, byte by byte, as the head.
        let rows: String = (0..20_000).map(|i| format!("{i},5;-0,{i}\n")).collect();
        let long = format!("# name: a, b\ntime_s;gyro_dps\n{rows}");
        let mut out = Vec::new();
        comma_separated(Trickle(long.as_bytes())).read_to_end(&mut out).unwrap();
        assert_eq!(out, format!("# name: a, b\ntime_s,gyro_dps\n{}", rows.replace(',', ".").replace(';', ",")).into_bytes());
    }

    #[test]
    fn a_comma_log_and_other_files_pass_through_untouched() {
        for text in [
            "# a; b\ntime_s,gyro_dps\n0,1\n",
            "time_s;gyro_dps,x\n0;1\n", // a comma in the header: the format as written
            "t;gyro_dps\n0;1,5\n",      // no time_s: not a v1 log; its error stays its own
            "time_s\n0,5\n",            // one column: no separator to tell
            "",
            "# only a comment; here\n",
        ] {
            assert_eq!(read_all(text.as_bytes()), text.as_bytes(), "{text}");
        }
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
}
