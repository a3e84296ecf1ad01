//! A log assembled from columns in pieces (a worker's parse handed to the page a chunk per
//! task), checked as the parser checks while it grows, so finishing costs nothing.

use super::{Column, DriveLog, LogMeta};
use crate::error::{Error, Result};

/// Builds a `DriveLog` from chunks of columns; `DriveLog::from_columns` is one chunk.
#[derive(Debug)]
pub struct LogBuilder {
    log: DriveLog,
    present: Vec<Column>,
    rows: usize,
}

impl LogBuilder {
    /// A builder for these columns (time_s among them, none twice), with room for
    /// `rows_hint` rows.
    pub fn new(meta: LogMeta, columns: &[Column], rows_hint: usize) -> Result<LogBuilder> {
        let mut log = DriveLog { meta, ..DriveLog::default() };
        for &c in columns {
            if log.columns[c.index()].is_some() {
                return Err(Error::File(format!("duplicate column {}", c.name())));
            }
            log.columns[c.index()] = Some(Vec::with_capacity(rows_hint));
        }
        if log.columns[Column::TimeS.index()].is_none() {
            return Err(Error::missing("time_s", "every log needs it"));
        }
        log.line.reserve(rows_hint);
        let present = Column::ALL.iter().copied().filter(|c| log.columns[c.index()].is_some()).collect();
        Ok(LogBuilder { log, present, rows: 0 })
    }

    /// The rows so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Appends rows: every column of the builder, each as long as time_s; `line` gives
    /// each row's line in the file (another length: numbered as if from line 2 on). Checked
    /// as the parser checks (finite, in the physical range, time strictly increasing); on an
    /// error nothing of this chunk is kept.
    pub fn append(&mut self, line: Vec<u64>, columns: Vec<(Column, Vec<f64>)>) -> Result<()> {
        let refs: Vec<(Column, &[f64])> = columns.iter().map(|(c, v)| (*c, v.as_slice())).collect();
        let lines = self.check(&line, &refs)?;
        for (c, mut v) in columns {
            let col = self.log.columns[c.index()].as_mut().expect("checked");
            // moved in when it would not fit the room reserved (one log in one chunk)
            if col.is_empty() && col.capacity() < v.len() {
                *col = v;
            } else {
                col.append(&mut v);
            }
        }
        if self.log.line.is_empty() && self.log.line.capacity() < lines.len() {
            self.log.line = lines;
        } else {
            self.log.line.extend(lines);
        }
        self.rows = self.log.line.len();
        Ok(())
    }

    /// The rows' lines, once the chunk meets every rule.
    fn check(&self, line: &[u64], columns: &[(Column, &[f64])]) -> Result<Vec<u64>> {
        let find = |c: Column| columns.iter().find(|(k, _)| *k == c).map(|(_, v)| *v);
        for (c, _) in columns {
            if !self.present.contains(c) {
                return Err(Error::File(format!("column {} is not in the log's header", c.name())));
            }
        }
        let t = find(Column::TimeS).ok_or_else(|| Error::missing("time_s", "every log needs it"))?;
        let n = t.len();
        let lines: Vec<u64> = if line.len() == n { line.to_vec() } else { (0..n as u64).map(|i| self.rows as u64 + i + 2).collect() };
        for &c in &self.present {
            let v = find(c).ok_or_else(|| Error::missing(c.name(), "every log needs it"))?;
            if v.len() != n {
                return Err(Error::File(format!("column {} has {} values, time_s has {n}", c.name(), v.len())));
            }
            check_range(c, v, &lines)?;
        }
        let mut prev = self.log.time_s().last().copied().unwrap_or(f64::NEG_INFINITY);
        for (i, &ti) in t.iter().enumerate() {
            if ti.is_nan() || !(ti > prev) {
                return Err(Error::Cell {
                    line: lines[i],
                    column: "time_s".into(),
                    message: "time must be present and strictly increase".into(),
                });
            }
            prev = ti;
        }
        Ok(lines)
    }

    /// The log (at least one row).
    pub fn finish(self) -> Result<DriveLog> {
        if self.rows == 0 {
            return Err(Error::File("no data rows".into()));
        }
        Ok(self.log)
    }
}

/// Finite and in the column's physical range: one pass for the extremes; the cells are looked
/// at one by one only when one is outside, to name it.
fn check_range(c: Column, v: &[f64], lines: &[u64]) -> Result<()> {
    let (lo, hi) =
        v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| if x.is_nan() { (lo, hi) } else { (lo.min(x), hi.max(x)) });
    let all_nan = lo > hi;
    if all_nan || (lo.is_finite() && hi.is_finite() && c.physical_range().is_none_or(|(a, b, _)| a <= lo && hi <= b)) {
        return Ok(());
    }
    if let Some(i) = v.iter().position(|x| x.is_infinite()) {
        return Err(Error::Cell { line: lines[i], column: c.name().into(), message: "not a finite number".into() });
    }
    for (i, &x) in v.iter().enumerate() {
        c.check_physical(x).map_err(|message| Error::Cell { line: lines[i], column: c.name().into(), message })?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cols(t: &[f64], g: &[f64]) -> Vec<(Column, Vec<f64>)> {
        vec![(Column::TimeS, t.to_vec()), (Column::GyroDps, g.to_vec())]
    }

    #[test]
    fn chunks_make_the_same_log_as_one() {
        let t: Vec<f64> = (0..10).map(|i| i as f64 * 0.1).collect();
        let g: Vec<f64> = (0..10).map(|i| if i == 4 { f64::NAN } else { i as f64 }).collect();
        let whole =
            DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::TimeS, t.clone()), (Column::GyroDps, g.clone())]).unwrap();
        let mut b = LogBuilder::new(LogMeta::default(), &[Column::GyroDps, Column::TimeS], 10).unwrap();
        for k in [0..3, 3..7, 7..10] {
            b.append(vec![], cols(&t[k.clone()], &g[k])).unwrap();
        }
        assert_eq!(b.rows(), 10);
        let built = b.finish().unwrap();
        assert_eq!(built.line, (2..12).collect::<Vec<u64>>());
        assert_eq!(built.time_s(), whole.time_s());
        assert_eq!(format!("{:?}", built.column(Column::GyroDps)), format!("{:?}", whole.column(Column::GyroDps)));
    }

    #[test]
    fn errors_name_line_and_column_and_keep_nothing_of_the_chunk() {
        let mut b = LogBuilder::new(LogMeta::default(), &[Column::TimeS, Column::GyroDps], 0).unwrap();
        b.append(vec![10, 11], cols(&[0.0, 0.1], &[1.0, 2.0])).unwrap();
        // time going back across chunks: line of the offending row
        let e = b.append(vec![12, 13], cols(&[0.2, 0.1], &[1.0, 2.0])).unwrap_err().to_string();
        assert!(e.contains("13") && e.contains("time_s"), "{e}");
        let e = b.append(vec![12], cols(&[0.05], &[1.0])).unwrap_err().to_string();
        assert!(e.contains("12") && e.contains("strictly increase"), "{e}");
        // out of range, infinite, missing column, unknown column, unequal lengths
        let e = b.append(vec![12], cols(&[0.2], &[1e9])).unwrap_err().to_string();
        assert!(e.contains("12") && e.contains("gyro_dps"), "{e}");
        let e = b.append(vec![12], cols(&[0.2], &[f64::INFINITY])).unwrap_err().to_string();
        assert!(e.contains("not a finite number"), "{e}");
        assert!(b.append(vec![12], vec![(Column::TimeS, vec![0.2])]).unwrap_err().to_string().contains("gyro_dps"));
        assert!(b.append(vec![], vec![(Column::TimeS, vec![0.2]), (Column::GyroDps, vec![0.0]), (Column::SpeedMps, vec![0.0])]).is_err());
        assert!(b.append(vec![], cols(&[0.2, 0.3], &[1.0])).unwrap_err().to_string().contains("has 1 values"));
        // nothing of the failed chunks was kept
        assert_eq!(b.rows(), 2);
        b.append(vec![12], cols(&[0.2], &[3.0])).unwrap();
        let log = b.finish().unwrap();
        assert_eq!(log.line, vec![10, 11, 12]);
        assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 2.0, 3.0]);
    }

    #[test]
    fn a_builder_needs_time_no_duplicates_and_a_row() {
        assert!(LogBuilder::new(LogMeta::default(), &[Column::GyroDps], 0).is_err());
        assert!(LogBuilder::new(LogMeta::default(), &[Column::TimeS, Column::TimeS], 0).unwrap_err().to_string().contains("duplicate"));
        assert!(LogBuilder::new(LogMeta::default(), &[Column::TimeS], 0)
            .unwrap()
            .finish()
            .unwrap_err()
            .to_string()
            .contains("no data rows"));
    }

    #[test]
    fn the_first_chunk_moves_in_and_later_ones_append() {
        let mut b = LogBuilder::new(LogMeta::default(), &[Column::TimeS, Column::GyroDps], 0).unwrap();
        b.append(vec![], vec![(Column::TimeS, vec![0.0, 0.1]), (Column::GyroDps, vec![1.0, 2.0])]).unwrap();
        b.append(vec![7], vec![(Column::TimeS, vec![0.2]), (Column::GyroDps, vec![3.0])]).unwrap();
        assert!(b.append(vec![], vec![(Column::TimeS, vec![0.2]), (Column::GyroDps, vec![3.0])]).is_err());
        let log = b.finish().unwrap();
        assert_eq!(log.line, vec![2, 3, 7]);
        assert_eq!(log.time_s(), &[0.0, 0.1, 0.2]);
    }
}
