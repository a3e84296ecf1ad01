//! The one tabular reader of the crate: CSV (quotes, CRLF, a UTF-8 byte-order mark, spaces
//! around fields trimmed) or whitespace-separated text, streamed row by row with the line
//! number of each row. The v1 log parser and the recipe import both read through it, so a
//! file's bytes are checked, and its errors worded, in one place.

use crate::error::{Error, Result};
use std::io::{BufRead, BufReader, Read};

/// How a line splits into fields.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Split {
    /// Comma-separated (the `csv` crate: quotes allowed).
    Csv,
    /// Separated by this ASCII byte (`;`, tab, `|`), quotes allowed.
    Delimited(u8),
    /// Runs of spaces or tabs.
    Whitespace,
}

/// Caps on what a reader will take, so a wrong file (`/dev/zero`, a binary, a log far larger
/// than memory) is an error early instead of an out-of-memory abort.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Total bytes of the file.
    pub max_bytes: u64,
    /// Bytes of one line.
    pub max_line_bytes: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits { max_bytes: 4 << 30, max_line_bytes: 1 << 20 }
    }
}

/// A reader that fails once the file or one line passes its cap.
struct Capped<R> {
    inner: R,
    limits: Limits,
    total: u64,
    line: u64,
}

impl<R: Read> Read for Capped<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.total += n as u64;
        if self.total > self.limits.max_bytes {
            let msg = format!("the file is larger than {} bytes; split it or raise the limit", self.limits.max_bytes);
            return Err(std::io::Error::new(std::io::ErrorKind::InvalidData, msg));
        }
        // Only the bytes after the chunk's last line break extend the current line.
        self.line = match buf[..n].iter().rposition(|&b| b == b'\n') {
            Some(i) => (n - i - 1) as u64,
            None => self.line + n as u64,
        };
        if self.line > self.limits.max_line_bytes {
            let msg = format!("a line is longer than {} bytes: not a text table (or raise the limit)", self.limits.max_line_bytes);
            return Err(std::io::Error::new(std::io::ErrorKind::InvalidData, msg));
        }
        Ok(n)
    }
}

/// One data row: its 1-based line in the file, the bytes read up to it (for progress), and
/// its fields. Rows whose fields are all empty are never passed.
pub struct Row<'a> {
    pub line: u64,
    pub byte: u64,
    pub fields: &'a [&'a str],
}

/// Reads `reader` row by row. The first `skip_lines` lines are skipped unread; then each
/// line goes to `preamble` (as text) until it returns false: that line and every later one
/// are rows (`preamble` takes comment or metadata lines before a header). Errors name the
/// line, counted from `lines_before` (the file's lines before the reader's first, as for a
/// log joined on after another); `row` may return its own.
pub fn read_rows(
    reader: impl Read,
    lines_before: u64,
    split: Split,
    skip_lines: usize,
    limits: Limits,
    preamble: &mut dyn FnMut(u64, &str) -> Result<bool>,
    row: &mut dyn FnMut(Row) -> Result<()>,
) -> Result<()> {
    let mut reader = BufReader::with_capacity(1 << 16, Capped { inner: reader, limits, total: 0, line: 0 });
    let mut raw = Vec::new();
    let mut line_no: u64 = lines_before;
    let mut byte: u64 = 0;
    for _ in 0..skip_lines {
        raw.clear();
        let n = reader.read_until(b'\n', &mut raw)?;
        if n == 0 {
            return Err(Error::File("the file ends within the skipped lines".into()));
        }
        line_no += 1;
        byte += n as u64;
    }
    // The preamble, line by line; `first` is the first line of the table, if any.
    let first = loop {
        raw.clear();
        let n = reader.read_until(b'\n', &mut raw)?;
        if n == 0 {
            return Ok(());
        }
        line_no += 1;
        let at_start = line_no == lines_before + 1;
        if at_start && raw.starts_with(b"\xEF\xBB\xBF") {
            raw.drain(..3);
        }
        if let Some(message) = not_text_message(&raw).filter(|_| at_start) {
            return Err(Error::Line { line: line_no, message: message.into() });
        }
        let text = std::str::from_utf8(&raw).map_err(|_| Error::Line { line: line_no, message: "not valid UTF-8 text".into() })?;
        if !preamble(line_no, text)? {
            break std::mem::take(&mut raw);
        }
        byte += n as u64;
    };
    let before = line_no - 1;
    let rest = std::io::Cursor::new(first).chain(reader);
    match split {
        Split::Whitespace => whitespace_rows(rest, before, byte, row),
        Split::Csv => csv_rows(rest, b',', before, byte, row),
        Split::Delimited(d) => csv_rows(rest, d, before, byte, row),
    }
}

/// Whether bytes start as a ZIP archive does (a local file header).
pub fn is_zip(head: &[u8]) -> bool {
    head.starts_with(b"PK\x03\x04")
}

/// Whether bytes start as a gzip stream does.
pub fn is_gzip(head: &[u8]) -> bool {
    head.starts_with(&[0x1f, 0x8b])
}

/// What a file whose head is not a text table is, for the error, rather than a header of
/// garbage: a ZIP archive or gzip (a logger's export often comes compressed), UTF-16 text (by
/// its byte-order mark), or binary (NUL bytes in its first 4 KiB: Parquet, a PX4 ULog, a ROS
/// bag). None for anything else.
pub fn not_text_message(head: &[u8]) -> Option<&'static str> {
    if is_zip(head) {
        Some("a ZIP archive, not a text table (import reads a logger's zipped export as it is)")
    } else if is_gzip(head) {
        Some("gzip-compressed, not a text table: decompress it first")
    } else if head.starts_with(b"\xFF\xFE") || head.starts_with(b"\xFE\xFF") {
        Some("UTF-16 text (a spreadsheet's \"Unicode text\"): save it as UTF-8")
    } else if head.iter().take(4096).any(|&b| b == 0) {
        Some("a binary file (NUL bytes), not a text table")
    } else {
        None
    }
}

/// Whitespace-separated rows, `before` lines and `byte0` bytes already consumed.
fn whitespace_rows(mut reader: impl BufRead, before: u64, byte0: u64, row: &mut dyn FnMut(Row) -> Result<()>) -> Result<()> {
    let (mut raw, mut line, mut byte) = (Vec::new(), before, byte0);
    loop {
        raw.clear();
        let n = reader.read_until(b'\n', &mut raw)?;
        if n == 0 {
            return Ok(());
        }
        line += 1;
        byte += n as u64;
        let text = std::str::from_utf8(&raw).map_err(|_| Error::Line { line, message: "not valid UTF-8 text".into() })?;
        let fields: Vec<&str> = text.split_whitespace().collect();
        if !fields.is_empty() {
            row(Row { line, byte, fields: &fields })?;
        }
    }
}

/// CSV rows through the `csv` crate, `before` lines and `byte0` bytes already consumed.
fn csv_rows(reader: impl Read, delimiter: u8, before: u64, byte0: u64, row: &mut dyn FnMut(Row) -> Result<()>) -> Result<()> {
    // Lines end at '\n' only (a '\r' before it is trimmed with the last field): the csv crate's
    // CRLF terminator reports the line of the record after a CRLF one short.
    let mut rdr = csv::ReaderBuilder::new()
        .delimiter(delimiter)
        .has_headers(false)
        .flexible(true)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_reader(reader);
    let mut rec = csv::StringRecord::new();
    loop {
        if !rdr.read_record(&mut rec).map_err(|e| csv_error(e, before))? {
            return Ok(());
        }
        let pos = rec.position();
        let line = before + pos.map_or(0, |p| p.line());
        // Trimmed here: the csv crate's own trimming copies the record (twice the time).
        let fields: Vec<&str> = rec.iter().map(str::trim).collect();
        if fields.iter().all(|f| f.is_empty()) {
            continue;
        }
        row(Row { line, byte: byte0 + pos.map_or(0, |p| p.byte()), fields: &fields })?;
    }
}

/// A `csv` crate error as ours, with the file's line (`before` lines preceded the reader).
fn csv_error(e: csv::Error, before: u64) -> Error {
    let line = e.position().map(|p| p.line() + before);
    let message = match e.kind() {
        csv::ErrorKind::Io(io) => return Error::Io(crate::error::io_message(io)),
        csv::ErrorKind::Utf8 { .. } => "not valid UTF-8 text".to_string(),
        // Not raised by a flexible reader of string records (unequal lengths, seek, serde);
        // the csv crate's Display would link io::Error's (`io_message`).
        _ => "a record the CSV reader refused".to_string(),
    };
    match line {
        Some(line) => Error::Line { line, message },
        None => Error::File(message),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(text: &[u8], split: Split, skip: usize) -> Result<Vec<(u64, Vec<String>)>> {
        let mut out = Vec::new();
        let mut pre = |_: u64, t: &str| Ok(t.trim().is_empty() || t.starts_with('#'));
        read_rows(text, 0, split, skip, Limits::default(), &mut pre, &mut |r| {
            out.push((r.line, r.fields.iter().map(|s| s.to_string()).collect()));
            Ok(())
        })?;
        Ok(out)
    }

    #[test]
    fn lines_bom_quotes_comments_and_blank_rows() {
        let r = rows(b"\xEF\xBB\xBF# meta\n\na, b\r\n1,\"2,5\"\n , \n3,4\n", Split::Csv, 0).unwrap();
        let want = [(3, vec!["a", "b"]), (4, vec!["1", "2,5"]), (6, vec!["3", "4"])];
        assert_eq!(r.len(), 3);
        for ((l, f), (wl, wf)) in r.iter().zip(want) {
            assert_eq!((*l, f.iter().map(String::as_str).collect::<Vec<_>>()), (wl, wf));
        }
        let r = rows(b"skip me\n1  2\t3\n\n4 5\n", Split::Whitespace, 1).unwrap();
        assert_eq!(r, vec![(2, vec!["1".into(), "2".into(), "3".into()]), (4, vec!["4".into(), "5".into()])]);
    }

    #[test]
    fn errors_name_the_line() {
        let e = rows(b"a,b\n1,2\n\xFF,3\n", Split::Csv, 0).unwrap_err();
        assert_eq!(e, Error::Line { line: 3, message: "not valid UTF-8 text".into() });
        let e = rows(b"# \xFF\n", Split::Csv, 0).unwrap_err();
        assert_eq!(e, Error::Line { line: 1, message: "not valid UTF-8 text".into() });
        assert!(matches!(rows(b"x\n", Split::Csv, 3), Err(Error::File(_))));
        // An archive says what it is (a logger's export often comes zipped), even where its
        // first line happens to be valid UTF-8.
        let e = rows(b"PK\x03\x04\x14\x00\n\xFF", Split::Csv, 0).unwrap_err();
        assert!(matches!(e, Error::Line { line: 1, ref message } if message.starts_with("a ZIP archive, not a text table")), "{e:?}");
        let e = rows(b"\x1f\x8b\x08\x00\xFF", Split::Csv, 0).unwrap_err();
        assert!(matches!(e, Error::Line { line: 1, ref message } if message.starts_with("gzip-compressed")), "{e:?}");
        // Any other binary file (here a Parquet file's first bytes) says so, not "missing
        // column" with its bytes as the header.
        let e = rows(b"PAR1\x15\x04\x15\x10\x00\x00abc\n", Split::Csv, 0).unwrap_err();
        assert_eq!(e, Error::Line { line: 1, message: "a binary file (NUL bytes), not a text table".into() });
        let e = rows(b"\xFF\xFEt\x00,\x00g\x00\n\x00", Split::Csv, 0).unwrap_err();
        assert!(matches!(e, Error::Line { line: 1, ref message } if message.starts_with("UTF-16 text")), "{e:?}");
        assert!(rows(b"", Split::Csv, 0).unwrap().is_empty());
    }

    #[test]
    fn caps_stop_endless_or_huge_input() {
        let none = &mut |_: Row| Ok(());
        let zeros = std::io::repeat(0).take(10 << 20);
        let e = read_rows(zeros, 0, Split::Csv, 0, Limits::default(), &mut |_, _| Ok(false), none).unwrap_err();
        assert!(matches!(&e, Error::Io(m) if m.contains("a line is longer than 1048576 bytes")), "{e}");
        let small = Limits { max_bytes: 100, max_line_bytes: 1000 };
        let text = "a,b\n".repeat(100);
        let e = read_rows(text.as_bytes(), 0, Split::Whitespace, 0, small, &mut |_, _| Ok(false), none).unwrap_err();
        assert!(matches!(&e, Error::Io(m) if m.contains("larger than 100 bytes")), "{e}");
    }
}
