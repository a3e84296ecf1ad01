//! A v1 log file as other programs and crashes leave it, read as the log it stands for:
//! - saved by a spreadsheet where the decimal mark is a comma: cells separated by `;` (or
//!   a tab, or `|`) and numbers like `0,25`. Outside `#` lines the separator becomes a
//!   comma and a comma a decimal point, byte for byte, so an error names the same line and
//!   column as in the file;
//! - opened and saved by a spreadsheet in any locale: its `#` metadata lines padded with
//!   separators to the header's width (`# bias_s: 20,,,,`), or quoted when they hold one
//!   (`"# description: a, b",,,,`), or an Excel `sep=;` line first: read as written;
//! - with its last line cut short (a logger stopped mid-write: no line end, fewer cells
//!   than the header): that line can be dropped, and [`V1Reader::cut_last_line`] says so;
//! - in Windows-1252 rather than UTF-8 (Excel's "CSV" on Windows, with a `ü` in a name or
//!   a note): lines that are not UTF-8 are read as Windows-1252 (WHATWG's table), which
//!   [`V1Reader::said`] says;
//! - with a second log joined on (`cat a.csv b.csv`, or a logger appending each session to
//!   one file): the reader ends before the first `#` line after the header, or the header
//!   row found again, and
//!   [`V1Reader::joined_at`] names it, so the fronts refuse the file naming that line, not
//!   as a row with too few cells; [`V1Reader::into_rest`] gives the rest to read on
//!   (`accept::parse_joined`, the CLI's `split`).
//!
//! A comma-separated log that ends cleanly (the format as written) passes through untouched.

use std::io::{self, Read};

/// Bytes held at a time; the first fill finds the header row and its separator.
const BUF_BYTES: usize = 64 * 1024;

/// Where the next byte stands in its line: the separator is mapped only in table rows.
#[derive(Clone, Copy, PartialEq)]
enum LineState {
    /// At the line's start or after spaces: a `#` makes it a metadata line.
    Start,
    Comment,
    Row,
}

/// A last line dropped for being cut short: its cells and the header's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CutLine {
    pub fields: usize,
    pub header_fields: usize,
}

impl CutLine {
    /// What was done, as the fronts say it.
    pub fn to_text(self) -> String {
        format!("its last line, cut short ({} of {} cells, no line end), dropped", self.fields, self.header_fields)
    }
}

/// `inner` read as a comma-separated v1 log (see the module's doc).
pub struct V1Reader<R> {
    inner: R,
    buf: Vec<u8>,
    /// Bytes `[start, ready)` may be given; `[ready, buf.len())` are held back (a line not
    /// yet ended, which may be the last, cut short).
    start: usize,
    ready: usize,
    filled: bool,
    eof: bool,
    drop_cut: bool,
    /// The file's separator when it is not a comma (`None`: no mapping).
    separator: Option<u8>,
    /// Cells of the header row, once found, and the row as written (without its line end):
    /// found again after the rows, it starts a second log.
    header_fields: Option<usize>,
    header_row: Vec<u8>,
    state: LineState,
    cut: Option<CutLine>,
    windows_1252: bool,
    /// Lines given before `buf[0]`, counted until a second log is found, and whether
    /// `buf[0]` starts a line (not after a line longer than the buffer, given in parts).
    lines_before: u64,
    line_start: bool,
    joined: Option<Joined>,
}

/// A `#` line after a log's header, a second log's metadata, or the header row again, a
/// second log's header (two logs joined into one file).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Joined {
    /// Its 1-based line in the file.
    pub line: u64,
    /// The line, trimmed and shortened to 60 characters.
    pub text: String,
}

/// What the refusal of a file with a second log joined on says (`accept::Refusal::of`).
pub(crate) const JOINED_REFUSAL: &str = "a second log joined on?";

impl Joined {
    /// The refusal the fronts give for such a file.
    pub fn to_error(&self) -> crate::error::Error {
        let message = if self.text.starts_with('#') {
            format!(
                "a '#' line after the rows (\"{}\"): {JOINED_REFUSAL} A log's '#' lines come before its header; split the file before this line",
                self.text
            )
        } else {
            format!("the header row again after the rows (\"{}\"): {JOINED_REFUSAL} Split the file before this line", self.text)
        };
        crate::error::Error::Line { line: self.line, message }
    }
}

/// Wraps `inner`, mapping a spreadsheet's dialect; with `drop_cut`, a last line cut short is
/// dropped (else it reaches the parser, which refuses it naming its line). Nothing is read
/// until the first `read`.
pub fn v1_reader<R: Read>(inner: R, drop_cut: bool) -> V1Reader<R> {
    V1Reader {
        inner,
        buf: Vec::new(),
        start: 0,
        ready: 0,
        filled: false,
        eof: false,
        drop_cut,
        separator: None,
        header_fields: None,
        header_row: Vec::new(),
        state: LineState::Start,
        cut: None,
        windows_1252: false,
        lines_before: 0,
        line_start: true,
        joined: None,
    }
}

/// Windows-1252's characters for bytes 0x80-0x9F (WHATWG's index; the five it leaves
/// undefined map to the C1 controls of the same value, as browsers decode them).
const WINDOWS_1252_80: [char; 32] = [
    '\u{20AC}', '\u{81}', '\u{201A}', '\u{192}', '\u{201E}', '\u{2026}', '\u{2020}', '\u{2021}', '\u{2C6}', '\u{2030}', '\u{160}',
    '\u{2039}', '\u{152}', '\u{8D}', '\u{17D}', '\u{8F}', '\u{90}', '\u{2018}', '\u{2019}', '\u{201C}', '\u{201D}', '\u{2022}', '\u{2013}',
    '\u{2014}', '\u{2DC}', '\u{2122}', '\u{161}', '\u{203A}', '\u{153}', '\u{9D}', '\u{17E}', '\u{178}',
];

/// Bytes read as Windows-1252, as UTF-8.
fn from_windows_1252(bytes: &[u8]) -> Vec<u8> {
    let text: String = bytes
        .iter()
        .map(|&b| match b {
            0x80..=0x9F => WINDOWS_1252_80[usize::from(b - 0x80)],
            _ => char::from(b),
        })
        .collect();
    text.into_bytes()
}

/// `inner` with a spreadsheet's dialect mapped, a cut last line left to the parser.
pub fn comma_separated<R: Read>(inner: R) -> V1Reader<R> {
    v1_reader(inner, false)
}

/// A line before the header: blank, `#` metadata, a spreadsheet's quoted `"#...` cell, or
/// Excel's `sep=;`.
fn is_preamble(line: &[u8]) -> bool {
    let t = line.trim_ascii();
    t.is_empty() || t[0] == b'#' || t.starts_with(b"\"#") || t.starts_with(b"sep=")
}

/// Where the header row of a head starts (after a byte-order mark), and the row.
fn header_line(head: &[u8]) -> Option<(usize, &[u8])> {
    let mut at = if head.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
    for line in head[at..].split(|&b| b == b'\n') {
        if !is_preamble(line) {
            return Some((at, line));
        }
        at += line.len() + 1;
    }
    None
}

/// A metadata line as a spreadsheet saves it, back as written: its cell unquoted (`"# a, b"`
/// -> `# a, b`, `""` -> `"`), the separators it was padded with to the header's width
/// (`# bias_s: 20;;;;`) dropped, `sep=;` blank. Its line end is kept, so lines keep their
/// numbers.
fn metadata_line(line: &[u8], sep: u8, pad: usize) -> Vec<u8> {
    let (body, end) = match line.strip_suffix(b"\r") {
        Some(b) => (b, &b"\r"[..]),
        None => (line, &b""[..]),
    };
    let t = body.trim_ascii_start();
    let mut out = if t.starts_with(b"sep=") {
        Vec::new()
    } else if let Some(quoted) = t.strip_prefix(b"\"") {
        // The cell up to its closing quote; what follows is padding.
        let mut cell = Vec::with_capacity(quoted.len());
        let mut bytes = quoted.iter().peekable();
        while let Some(&b) = bytes.next() {
            if b == b'"' && bytes.next_if_eq(&&b'"').is_none() {
                break;
            }
            cell.push(b);
        }
        cell
    } else {
        let run = body.iter().rev().take_while(|&&b| b == sep).count();
        body[..body.len() - if pad > 0 && run == pad { run } else { 0 }].to_vec()
    };
    out.extend_from_slice(end);
    out
}

/// The separator of a v1 header row that is not comma-separated: the most frequent of `;`,
/// tab and `|`, when the row names `time_s` and holds no comma.
fn separator_of(line: &[u8]) -> Option<u8> {
    if line.contains(&b',') || !line.windows(6).any(|w| w == b"time_s") {
        return None;
    }
    [b';', b'\t', b'|'].into_iter().map(|d| (line.iter().filter(|&&b| b == d).count(), d)).filter(|&(n, _)| n > 0).max().map(|(_, d)| d)
}

/// Cells of a line separated by `sep` (quotes respected).
fn fields(line: &[u8], sep: u8) -> usize {
    let mut quoted = false;
    1 + line
        .iter()
        .filter(|&&b| {
            quoted ^= b == b'"';
            b == sep && !quoted
        })
        .count()
}

impl<R: Read> V1Reader<R> {
    /// The reader of a log that starts after `lines_before` lines of its file (one joined on
    /// after another), so the second log it finds is named by the file's line.
    pub fn after_lines(mut self, lines_before: u64) -> Self {
        self.lines_before = lines_before;
        self
    }

    /// The last line dropped for being cut short, once the reader has reached the end.
    pub fn cut_last_line(&self) -> Option<CutLine> {
        self.cut
    }

    /// The first `#` line after the header, where the reader ended (see the module's doc).
    pub fn joined_at(&self) -> Option<&Joined> {
        self.joined.as_ref()
    }

    /// After a second log was found ([`Self::joined_at`]): where it starts, and the bytes
    /// from there on (those held, then the rest of the input), to read as a log of its own.
    pub fn into_rest(self) -> Option<(Joined, impl Read)> {
        let joined = self.joined?;
        Some((joined, io::Cursor::new(self.buf[self.ready..].to_vec()).chain(self.inner)))
    }

    /// A parse of this reader as the fronts give it: a file the reader ended at a second log
    /// is refused naming that line, unless the parse failed on a line before it.
    pub fn refuse_joined<T>(&self, parsed: crate::error::Result<T>) -> crate::error::Result<T> {
        use crate::error::Error;
        match (parsed, &self.joined) {
            (Err(e @ (Error::Line { .. } | Error::Cell { .. })), _) | (Err(e), None) => Err(e),
            (_, Some(j)) => Err(j.to_error()),
            (ok, None) => ok,
        }
    }

    /// What was done to read the file, as the fronts say it (empty when nothing): a last
    /// line cut short dropped, text read as Windows-1252.
    pub fn said(&self) -> Vec<String> {
        let latin = self.windows_1252.then(|| "its text read as Windows-1252 (it is not UTF-8)".to_string());
        self.cut.map(CutLine::to_text).into_iter().chain(latin).collect()
    }

    /// Maps `buf[from..to]` in place (see the module's doc), carrying the line state across
    /// calls. Only bytes about to be given are mapped: those held back, or after a second
    /// log's start, stay as written, so that log is read with its own separator.
    fn map(&mut self, from: usize, to: usize) {
        let Some(sep) = self.separator else { return };
        for b in &mut self.buf[from..to] {
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

    /// Refills the buffer after the held-back bytes; the first fill reads the head whole and
    /// finds the separator and the header's cells.
    fn fill(&mut self) -> io::Result<()> {
        self.buf.drain(..self.ready);
        let from = self.buf.len();
        // The held-back bytes were not mapped (see `map`).
        let mut unmapped = 0;
        let want = BUF_BYTES.max(from + 4096);
        let n = (&mut self.inner).take((want - from) as u64).read_to_end(&mut self.buf)?;
        self.eof = n < want - from;
        // Where this fill's rows start (after the header on the first fill); None: no header.
        let mut rows_from = self.header_fields.map(|_| 0);
        if !self.filled {
            self.filled = true;
            let bom = if self.buf.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
            if let Some((at, line)) = header_line(&self.buf) {
                self.header_row = line.trim_ascii_end().to_vec();
                let sep = separator_of(line);
                let cells = fields(line, sep.unwrap_or(b','));
                (self.separator, self.header_fields) = (sep, Some(cells));
                let preamble: Vec<u8> = self.buf[bom..at]
                    .split_inclusive(|&b| b == b'\n')
                    .flat_map(|l| {
                        let (text, nl) = l.strip_suffix(b"\n").map_or((l, false), |t| (t, true));
                        let mut m = metadata_line(text, sep.unwrap_or(b','), cells - 1);
                        m.extend(nl.then_some(b'\n'));
                        m
                    })
                    .collect();
                self.buf.splice(bom..at, preamble);
                rows_from = header_line(&self.buf).map(|(at, line)| at + line.len() + 1);
            }
            unmapped = bom;
        }
        self.start = 0;
        self.ready = match self.buf.iter().rposition(|&b| b == b'\n') {
            _ if self.eof => self.end_of_file(),
            Some(i) => i + 1,
            // A line longer than the buffer: given as it is.
            None => self.buf.len(),
        };
        if let Some(from) = rows_from.filter(|_| self.joined.is_none()) {
            self.end_at_joined(from);
        }
        self.map(unmapped, self.ready);
        // Not UTF-8 (a character cut at the end of a long line's part aside): Windows-1252;
        // but text has no NUL bytes, so UTF-16 or a binary file reaches the parser as it is,
        // which says what it is.
        let chunk = &self.buf[..self.ready];
        if std::str::from_utf8(chunk).is_err_and(|e| e.error_len().is_some()) && !chunk.contains(&0) {
            let text = from_windows_1252(&self.buf[..self.ready]);
            let was = std::mem::replace(&mut self.ready, text.len());
            self.buf.splice(..was, text);
            self.windows_1252 = true;
        }
        Ok(())
    }

    /// Ends the file before the first `#` line of `buf[from..ready]` (`from` at a line start),
    /// naming it; else counts the lines given.
    fn end_at_joined(&mut self, from: usize) {
        let chunk = &self.buf[..self.ready];
        let at_line_start = if from == 0 { self.line_start } else { chunk.get(from - 1) == Some(&b'\n') };
        let at = self.second_log_at(chunk, from, at_line_start);
        let Some(at) = at else {
            self.lines_before += memchr::memchr_iter(b'\n', chunk).count() as u64;
            self.line_start = chunk.last().is_none_or(|&b| b == b'\n');
            return;
        };
        let end = chunk[at..].iter().position(|&b| b == b'\n').map_or(chunk.len(), |i| at + i);
        let line = &chunk[at..end];
        let text = String::from_utf8_lossy(line.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(line).trim_ascii());
        let text = if text.chars().count() > 60 { format!("{}...", text.chars().take(60).collect::<String>()) } else { text.into_owned() };
        let line = self.lines_before + memchr::memchr_iter(b'\n', &chunk[..at]).count() as u64 + 1;
        self.joined = Some(Joined { line, text });
        (self.ready, self.eof, self.cut) = (at, true, None);
    }

    /// Where in `chunk[from..]` a second log starts: the first line that is a `#` line or the
    /// header row again, after a byte-order mark or not (`cat` of two files a spreadsheet
    /// saved); `from` is at a line start when `at_line_start`.
    fn second_log_at(&self, chunk: &[u8], from: usize, at_line_start: bool) -> Option<usize> {
        let header = &self.header_row[..];
        let starts_log = |i: usize| {
            let line = &chunk[i..];
            let line = &line[..memchr::memchr(b'\n', line).unwrap_or(line.len())];
            let line = line.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(line);
            line.first() == Some(&b'#') || (!header.is_empty() && line.trim_ascii_end() == header)
        };
        if at_line_start && from < chunk.len() && starts_log(from) {
            return Some(from);
        }
        let rest = chunk.get(from..)?;
        let find = |pattern: &[u8]| memchr::memmem::find_iter(rest, pattern).map(|i| from + i + 1).find(|&i| starts_log(i));
        let mut again = vec![b'\n'];
        again.extend_from_slice(header);
        let header_again = if header.is_empty() { None } else { find(&again) };
        [find(b"\n#"), find(b"\n\xEF\xBB\xBF"), header_again].into_iter().flatten().min()
    }

    /// At the end: the bytes to give, without a last line cut short when dropping one.
    fn end_of_file(&mut self) -> usize {
        let last = self.buf.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        let line = &self.buf[last..];
        let t = line.trim_ascii();
        if self.drop_cut && !t.is_empty() && t[0] != b'#' {
            if let Some(header) = self.header_fields {
                let n = fields(line, self.separator.unwrap_or(b','));
                if n < header && last > 0 {
                    self.cut = Some(CutLine { fields: n, header_fields: header });
                    return last;
                }
            }
        }
        self.buf.len()
    }
}

impl<R: Read> Read for V1Reader<R> {
    fn read(&mut self, out: &mut [u8]) -> io::Result<usize> {
        while self.start == self.ready {
            if self.eof {
                return Ok(0);
            }
            self.fill()?;
            if self.eof && self.start == self.ready {
                return Ok(0);
            }
        }
        let n = (self.ready - self.start).min(out.len());
        out[..n].copy_from_slice(&self.buf[self.start..self.start + n]);
        self.start += n;
        Ok(n)
    }
}

#[cfg(test)]
mod tests;
