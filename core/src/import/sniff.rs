//! What the first bytes of a raw file say about its table: the separator, a decimal comma,
//! the lines before the header, and the header's column names. Detection of a logger's
//! preset works from this alone, so a caller passes only the head of each file.

use super::*;

/// Bytes of a file's head that detection reads (the caller may pass more; the rest is ignored).
pub const SNIFF_BYTES: usize = 64 * 1024;

/// One file's dialect and header.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sniffed {
    /// The file's name as the caller knows it (a recipe's `file`).
    pub name: String,
    pub delimiter: char,
    pub decimal_comma: bool,
    /// Lines before the header (comments, `sep=,`).
    pub skip_lines: usize,
    /// Column names, trimmed, quotes removed.
    pub header: Vec<String>,
}

impl Sniffed {
    /// The file name without folders and extension, lower case (`Gyroscope.csv` -> `gyroscope`).
    pub fn stem(&self) -> String {
        let base = self.name.rsplit(['/', '\\']).next().unwrap_or(&self.name);
        let stem = base.rsplit_once('.').map_or(base, |(s, _)| s);
        stem.to_ascii_lowercase()
    }

    /// A drive log v1 already (its header after the `#` lines has `time_s` and `gyro_dps`):
    /// it opens as it is, no import needed; one saved with `;` and decimal commas through
    /// `log::dialect`.
    pub fn is_drive_log(&self) -> bool {
        self.find("time_s").is_some() && self.find("gyro_dps").is_some()
    }

    /// A recipe table's dialect fields (JSON) as sniffed: the separator, a decimal comma,
    /// the lines before the header; the defaults left out.
    pub(super) fn set_dialect(&self, table: &mut serde_json::Value) {
        if self.delimiter != ',' {
            table["delimiter"] = serde_json::json!(self.delimiter.to_string());
        }
        if self.decimal_comma {
            table["decimal_comma"] = serde_json::json!(true);
        }
        if self.skip_lines > 0 {
            table["skip_lines"] = serde_json::json!(self.skip_lines);
        }
    }

    /// The first header column matching `pattern`: a name, `*suffix` (ends with), or several
    /// such alternatives separated by `|`.
    pub fn find(&self, pattern: &str) -> Option<&str> {
        pattern.split('|').find_map(|p| match p.strip_prefix('*') {
            Some(suffix) => self.header.iter().find(|h| h.ends_with(suffix)).map(String::as_str),
            None => self.header.iter().find(|h| *h == p).map(String::as_str),
        })
    }
}

/// Reads the head of a file: an error names the file when it is not a text table.
pub fn sniff(name: &str, head: &[u8]) -> Result<Sniffed> {
    let head = &head[..head.len().min(SNIFF_BYTES)];
    let at = |m: &str| Error::File(format!("{name}: {m}"));
    if let Some(m) = crate::table::not_text_message(head) {
        return Err(at(m));
    }
    let text = match std::str::from_utf8(head) {
        Ok(t) => t,
        // The head may end inside a character; anything earlier is an encoding error.
        Err(e) if e.error_len().is_none() => std::str::from_utf8(&head[..e.valid_up_to()]).unwrap_or(""),
        Err(e) => return Err(at(&format!("not UTF-8 text (byte {})", e.valid_up_to() + 1))),
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text.split('\n').map(|l| l.trim_end_matches('\r'));
    let mut skip_lines = 0;
    let header_line = loop {
        match lines.next() {
            None => return Err(at("no header row (the file is empty or only comments)")),
            Some(l) if l.trim().is_empty() || l.starts_with('#') || l.starts_with("sep=") => skip_lines += 1,
            Some(l) => break l,
        }
    };
    let delimiter = [',', ';', '\t', '|'].into_iter().max_by_key(|&d| (count_outside_quotes(header_line, d), d == ',')).unwrap_or(',');
    let delimiter = if count_outside_quotes(header_line, delimiter) == 0 { ',' } else { delimiter };
    let header = split_line(header_line, delimiter);
    if header.iter().all(|h| h.is_empty()) {
        return Err(at("the header row is empty"));
    }
    // A decimal comma: a field like "0,25" in the first rows of a table not separated by commas.
    let decimal_comma = delimiter != ',' && lines.take(20).any(|l| split_line(l, delimiter).iter().any(|f| is_comma_number(f)));
    Ok(Sniffed { name: name.to_string(), delimiter, decimal_comma, skip_lines, header })
}

/// The heads (name, bytes) of a recording's files sniffed: the text tables, and the names of
/// the files that are not (a binary file beside the logger's tables, an empty one, a
/// Markdown document), left out; the first one's error when none is a table.
pub fn sniff_tables<'a>(heads: impl IntoIterator<Item = (&'a str, &'a [u8])>) -> Result<(Vec<Sniffed>, Vec<String>)> {
    let (mut tables, mut others, mut first) = (Vec::new(), Vec::new(), None);
    for (name, head) in heads {
        // Prose beside the tables (a README, a SOURCE.md) would read as a table of its first line's words.
        let markdown = name.to_ascii_lowercase().ends_with(".md");
        match if markdown { Err(Error::File(format!("{name}: a Markdown document, not a table"))) } else { sniff(name, head) } {
            Ok(s) => tables.push(s),
            Err(e) => {
                others.push(name.to_string());
                first.get_or_insert(e);
            }
        }
    }
    match first {
        Some(e) if tables.is_empty() => Err(e),
        _ => Ok((tables, others)),
    }
}

/// Whether a file's head is a drive log v1's, read as the native fronts and the worker's
/// module read one (`log::dialect`: as a spreadsheet saved it too, its metadata lines
/// padded with separators or quoted). The page's module asks [`Sniffed::is_drive_log`].
pub fn is_drive_log_head(name: &str, head: &[u8]) -> bool {
    use std::io::Read;
    let head = &head[..head.len().min(SNIFF_BYTES)];
    let mut written = Vec::with_capacity(head.len());
    crate::log::dialect::comma_separated(head).read_to_end(&mut written).is_ok() && sniff(name, &written).is_ok_and(|s| s.is_drive_log())
}

/// The first `n` data rows of a sniffed head (after its skipped lines, its header and any
/// blank or comment lines), split as the header was (the head's last may be cut short).
pub(super) fn first_rows(s: &Sniffed, head: &[u8], n: usize) -> Vec<Vec<String>> {
    let text = String::from_utf8_lossy(&head[..head.len().min(SNIFF_BYTES)]);
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let lines = text.split('\n').map(|l| l.trim_end_matches('\r')).skip(s.skip_lines + 1);
    lines.filter(|l| !l.trim().is_empty() && !l.starts_with('#')).take(n).map(|l| split_line(l, s.delimiter)).collect()
}

fn count_outside_quotes(line: &str, d: char) -> usize {
    let mut quoted = false;
    line.chars()
        .filter(|&c| {
            if c == '"' {
                quoted = !quoted;
            }
            c == d && !quoted
        })
        .count()
}

/// Fields of one line (quotes removed, trimmed); the head's last line may be cut, which is fine.
fn split_line(line: &str, d: char) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            c if c == d && !quoted => out.push(std::mem::take(&mut cur).trim().to_string()),
            c => cur.push(c),
        }
    }
    out.push(cur.trim().to_string());
    out
}

fn is_comma_number(f: &str) -> bool {
    let f = f.strip_prefix('-').unwrap_or(f);
    let Some((a, b)) = f.split_once(',') else { return false };
    let b = b.split(['e', 'E']).next().unwrap_or("");
    !a.is_empty() && !b.is_empty() && a.bytes().all(|c| c.is_ascii_digit()) && b.bytes().all(|c| c.is_ascii_digit())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dialects() {
        let s = sniff("a/Gyro.CSV", b"\xEF\xBB\xBF\"Time (s)\";\"Gyroscope z (rad/s)\"\r\n0,01;-1,5E-3\r\n").unwrap();
        assert_eq!((s.delimiter, s.decimal_comma, s.skip_lines), (';', true, 0));
        assert_eq!(s.header, ["Time (s)", "Gyroscope z (rad/s)"]);
        assert_eq!(s.stem(), "gyro");
        let s = sniff("x.tsv", b"# made by a logger\nsep=\t\nt\tw\n1.5\t2\n").unwrap();
        assert_eq!((s.delimiter, s.decimal_comma, s.skip_lines), ('\t', false, 2));
        let s = sniff("x.csv", b"time,\"a,b\",c\n1,2,3\n").unwrap();
        assert_eq!((s.delimiter, s.header.len()), (',', 3));
        assert_eq!(s.find("*,b|c"), Some("a,b"));
        assert_eq!(s.find("q|c"), Some("c"));
        // A single column has no separator: comma.
        assert_eq!(sniff("x.csv", b"gyro\n1\n").unwrap().delimiter, ',');
        assert!(sniff("d.csv", b"# name: x\ntime_s,gyro_dps\n0,1\n").unwrap().is_drive_log());
        assert!(sniff("d.csv", b"# name: x\ntime_s;gyro_dps\n0;1,5\n").unwrap().is_drive_log());
        let excel = b"# name: x,\n\"# about: a, b\",\ntime_s,gyro_dps\n0,1\n";
        assert!(!sniff("d.csv", excel).unwrap().is_drive_log() && is_drive_log_head("d.csv", excel));
        assert!(!s.is_drive_log());
    }

    #[test]
    fn refusals_name_the_file() {
        for (bytes, why) in
            [(&b"\x00\x01\x02"[..], "binary"), (b"", "no header"), (b"# only\n\n", "no header"), (b"a,\xFF\xFEb\n1,2\n", "UTF-8")]
        {
            let e = sniff("f.csv", bytes).unwrap_err().to_string();
            assert!(e.contains("f.csv") && e.contains(why), "{e}");
        }
        // A head cut inside a character is not an error.
        let cut = "t,w (°)\n1,2\n".as_bytes();
        assert!(sniff("f.csv", &cut[..6]).is_ok());
    }

    #[test]
    fn a_recordings_files_that_are_not_tables_are_left_out_and_named() {
        let heads: [(&str, &[u8]); 4] = [
            ("Gyroscope.csv", b"time,z\n0,1\n"),
            ("README.md", b"Phone on the dashboard, screen up, ten minutes.\n"),
            ("photo.jpg", b"\xff\xd8\xff\xe0\x00\x10JFIF"),
            ("Location.csv", b"time,bearing\n0,90\n"),
        ];
        let (tables, others) = sniff_tables(heads).unwrap();
        let names: Vec<&str> = tables.iter().map(|s| s.name.as_str()).collect();
        assert_eq!((names, others), (vec!["Gyroscope.csv", "Location.csv"], vec!["README.md".to_string(), "photo.jpg".to_string()]));
        // None a table: the first one's error.
        let e = sniff_tables([heads[1], heads[2]]).unwrap_err().to_string();
        assert_eq!(e, "README.md: a Markdown document, not a table");
    }
}
