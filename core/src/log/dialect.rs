//! A v1 log file as other programs and crashes leave it, read as the log it stands for:
//! - saved by a spreadsheet where the decimal mark is a comma: cells separated by `;` (or
//!   a tab, or `|`) and numbers like `0,25`. Outside `#` lines the separator becomes a
//!   comma and a comma a decimal point, byte for byte, so an error names the same line and
//!   column as in the file;
//! - with its last line cut short (a logger stopped mid-write: no line end, fewer cells
//!   than the header): that line can be dropped, and [`V1Reader::cut_last_line`] says so.
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
    /// Cells of the header row, once found.
    header_fields: Option<usize>,
    state: LineState,
    cut: Option<CutLine>,
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
        state: LineState::Start,
        cut: None,
    }
}

/// `inner` with a spreadsheet's dialect mapped, a cut last line left to the parser.
pub fn comma_separated<R: Read>(inner: R) -> V1Reader<R> {
    v1_reader(inner, false)
}

/// The header row of a head: the first line that is neither blank nor `#`.
fn header_line(head: &[u8]) -> Option<&[u8]> {
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    head.split(|&b| b == b'\n').find(|l| {
        let t = l.trim_ascii();
        !t.is_empty() && t[0] != b'#'
    })
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
    /// The last line dropped for being cut short, once the reader has reached the end.
    pub fn cut_last_line(&self) -> Option<CutLine> {
        self.cut
    }

    /// Maps bytes in place (see the module's doc), carrying the line state across calls.
    fn map(&mut self, from: usize) {
        let Some(sep) = self.separator else { return };
        for b in &mut self.buf[from..] {
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
        let want = BUF_BYTES.max(from + 4096);
        let n = (&mut self.inner).take((want - from) as u64).read_to_end(&mut self.buf)?;
        self.eof = n < want - from;
        if !self.filled {
            self.filled = true;
            if let Some(line) = header_line(&self.buf) {
                self.separator = separator_of(line);
                self.header_fields = Some(fields(line, self.separator.unwrap_or(b',')));
            }
            let bom = if self.buf.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
            self.map(bom);
        } else {
            self.map(from);
        }
        self.start = 0;
        self.ready = match self.buf.iter().rposition(|&b| b == b'\n') {
            _ if self.eof => self.end_of_file(),
            Some(i) => i + 1,
            // A line longer than the buffer: given as it is.
            None => self.buf.len(),
        };
        Ok(())
    }

    /// At the end: the bytes to give, without a last line cut short when dropping one.
    fn end_of_file(&mut self) -> usize {
        let last = self.buf.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        let line = &self.buf[last..];
        let t = line.trim_ascii();
        if self.drop_cut && !t.is_empty() && t[0] != b'#' {
            if let Some(header) = self.header_fields {
                let n = fields(line, b',');
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
