//! A method's per-sample series by name. The CLI's trace CSV, the wasm package's trace
//! objects and the Python dicts all take the names and their order from the trace's
//! `columns()` (the pipeline's, HDR's, gyrodometry's): a series added to a trace reaches
//! every front under one name.

use std::borrow::Cow;

/// One named series of a trace: values, or flags (0 / 1 in a CSV).
#[derive(Debug, Clone, PartialEq)]
pub enum Column<'a> {
    Values(Cow<'a, [f64]>),
    Flags(&'a [bool]),
}

impl Column<'_> {
    /// The number of samples.
    pub fn len(&self) -> usize {
        match self {
            Column::Values(v) => v.len(),
            Column::Flags(f) => f.len(),
        }
    }

    /// True without samples.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The series as numbers: values as they are, flags as 1.0 / 0.0 (Python's arrays, a
    /// chart's reduction).
    pub fn to_f64s(&self) -> Cow<'_, [f64]> {
        match self {
            Column::Values(v) => Cow::Borrowed(v),
            Column::Flags(f) => Cow::Owned(f.iter().map(|&b| f64::from(u8::from(b))).collect()),
        }
    }
}

/// Borrowed values as a column.
pub(crate) fn values(v: &[f64]) -> Column<'_> {
    Column::Values(Cow::Borrowed(v))
}

/// Writes the columns as CSV: a header of their names, one row per sample (`{}` for values,
/// 0 / 1 for flags), as many rows as the shortest column has samples (a trace's are equal).
pub fn write_csv<W: std::io::Write>(columns: &[(&'static str, Column<'_>)], out: W) -> crate::Result<()> {
    use std::io::Write as _;
    let mut out = std::io::BufWriter::new(out);
    let names: Vec<&str> = columns.iter().map(|(n, _)| *n).collect();
    writeln!(out, "{}", names.join(","))?;
    let n = columns.iter().map(|(_, c)| c.len()).min().unwrap_or(0);
    for i in 0..n {
        for (k, (_, c)) in columns.iter().enumerate() {
            if k > 0 {
                out.write_all(b",")?;
            }
            match c {
                Column::Values(v) => write!(out, "{}", v[i])?,
                Column::Flags(f) => write!(out, "{}", u8::from(f[i]))?,
            }
        }
        out.write_all(b"\n")?;
    }
    out.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_csv_of_values_and_flags_names_each_column_once_and_writes_flags_as_0_and_1() {
        let t = [0.0, 1.5];
        let stop = [true, false];
        let cols = vec![("time_s", values(&t)), ("x", Column::Values(Cow::Owned(vec![-2.0, 0.25]))), ("stop", Column::Flags(&stop))];
        let mut out = Vec::new();
        write_csv(&cols, &mut out).unwrap();
        assert_eq!(String::from_utf8(out).unwrap(), "time_s,x,stop\n0,-2,1\n1.5,0.25,0\n");
    }

    #[test]
    fn flags_as_numbers_are_1_and_0_and_values_are_borrowed_unchanged() {
        let v = [3.5, -1.0];
        assert_eq!(&*Column::Flags(&[true, false, true]).to_f64s(), &[1.0, 0.0, 1.0]);
        assert!(matches!(values(&v).to_f64s(), Cow::Borrowed(b) if b == v));
    }

    #[test]
    fn every_trace_csv_header_is_its_columns_names() {
        let header = |write: &dyn Fn(&mut Vec<u8>) -> crate::Result<()>| {
            let mut out = Vec::new();
            write(&mut out).unwrap();
            String::from_utf8(out).unwrap().trim_end().to_string()
        };
        let names = |cols: &[(&'static str, Column<'_>)]| cols.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(",");
        let hdr = crate::hdr::HdrTrace::default();
        assert_eq!(header(&|o| hdr.write_csv(o)), names(&hdr.columns()[..3]));
        let p = crate::pipeline::PipelineTrace::default();
        assert_eq!(header(&|o| p.write_csv(o)), names(&p.columns()));
        assert!(names(&p.columns()).ends_with("bias_smoothed_dps,stop"));
    }

    #[test]
    fn no_columns_write_an_empty_header() {
        let mut out = Vec::new();
        write_csv(&[], &mut out).unwrap();
        assert_eq!(out, b"\n");
    }
}
