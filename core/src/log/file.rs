//! A log file as the native fronts open it: a gzip-compressed log (`drive.csv.gz`, as
//! fleets store them) reads through a decoder, so the CLI, Python and the fleet batch read
//! it as the plain file, errors naming its lines as they are once decompressed (and
//! `accept::parse_by` reads it through `log::dialect`).

use std::path::Path;

/// The name a log file gives a log without `# name:`: its file name without `.gz`, then
/// without its extension ("drive.csv.gz" -> "drive", "drive.csv" -> "drive").
pub fn log_stem(path: &Path) -> String {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let name = match name.len().checked_sub(3) {
        Some(cut) if name.is_char_boundary(cut) && name[cut..].eq_ignore_ascii_case(".gz") => &name[..cut],
        _ => &name,
    };
    Path::new(name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default()
}

/// `reader` for `parse_log`, gunzipped when it starts as gzip does (every member of a
/// multi-member stream, as `cat a.gz b.gz` makes), else as it is. (`accept::parse_by` then
/// reads a spreadsheet's `;` and decimal commas, and drops a last line cut short.)
#[cfg(feature = "zip")]
pub fn decompressed<'a, R: std::io::BufRead + Send + 'a>(mut reader: R) -> std::io::Result<Box<dyn std::io::Read + Send + 'a>> {
    if crate::table::is_gzip(reader.fill_buf()?) {
        Ok(Box::new(Gunzip(flate2::bufread::MultiGzDecoder::new(reader))))
    } else {
        Ok(Box::new(reader))
    }
}

/// The decoder, its errors said as what they mean for the file.
#[cfg(feature = "zip")]
struct Gunzip<R>(flate2::bufread::MultiGzDecoder<R>);

#[cfg(feature = "zip")]
impl<R: std::io::BufRead> std::io::Read for Gunzip<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        self.0.read(buf).map_err(|e| std::io::Error::new(e.kind(), format!("a damaged or cut gzip file ({e})")))
    }
}

/// Opens the log file at `path` for `parse_log`: buffered, and gunzipped when it is gzip.
#[cfg(feature = "zip")]
pub fn open_log(path: &Path) -> std::io::Result<Box<dyn std::io::Read + Send>> {
    decompressed(std::io::BufReader::new(std::fs::File::open(path)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_log_is_named_by_its_file_without_gz_and_extension() {
        for (path, stem) in
            [("a/drive.csv.gz", "drive"), ("drive.csv", "drive"), ("Drive.CSV.GZ", "Drive"), ("x.gz", "x"), ("gz", "gz"), ("é.gz", "é")]
        {
            assert_eq!(log_stem(Path::new(path)), stem, "{path}");
        }
    }

    /// A gzipped log parses as the plain one (two members as one stream); a plain file
    /// reads as it is; a damaged stream is an I/O error, never a panic.
    #[cfg(feature = "zip")]
    #[test]
    fn a_gzipped_log_reads_as_the_plain_one() {
        use std::io::Write;
        let text = "time_s,gyro_dps\n0,1\n1,2\n2,3\n";
        let gz = |s: &str| {
            let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
            e.write_all(s.as_bytes()).unwrap();
            e.finish().unwrap()
        };
        let read = |b: &[u8]| crate::parse_log(decompressed(b).unwrap());
        let plain = read(text.as_bytes()).unwrap();
        assert_eq!(read(&gz(text)).unwrap().column(crate::Column::GyroDps), plain.column(crate::Column::GyroDps));
        let two = [gz("time_s,gyro_dps\n0,1\n"), gz("1,2\n2,3\n")].concat();
        assert_eq!(read(&two).unwrap().len(), 3);
        let mut cut = gz(text);
        cut.truncate(cut.len() / 2);
        let e = read(&cut).unwrap_err().to_string();
        assert!(e.contains("a damaged or cut gzip file"), "{e}");
        let e = read(&gz("time_s,gyro_dps\n0,1\n1,x\n")).unwrap_err().to_string();
        assert!(e.contains("line 3, column gyro_dps"), "{e}");
    }
}
