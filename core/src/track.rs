//! Dead-reckoned paths for the Track view: speed integrated along a heading trace, in
//! metres on a local plane (x along heading 0, y along heading 90 deg, CCW positive).

use crate::error::{Error, Result};
use crate::eval::{Method, Prepared};
use crate::hdr::HdrParams;
use crate::log::{Column, DriveLog};
use crate::metrics::{interp_at, score, Reference};
use crate::pipeline::PipelineParams;
use serde::{Deserialize, Serialize};

/// A path in metres.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Path {
    pub x_m: Vec<f64>,
    pub y_m: Vec<f64>,
}

impl Path {
    /// The path for drawing `columns` pixels across its larger extent: points under half a
    /// pixel from the last kept one dropped (`decimate::path`). A path that still has more
    /// than `max_points` (a long drive winding over the same pixels many times) is reduced
    /// with a proportionally larger step, so drawing stays bounded.
    pub fn for_drawing(&self, columns: usize, max_points: usize) -> Path {
        let ext = |v: &[f64]| {
            let (lo, hi) = v.iter().filter(|x| x.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| (l.min(x), h.max(x)));
            if hi > lo {
                hi - lo
            } else {
                0.0
            }
        };
        let mut step = ext(&self.x_m).max(ext(&self.y_m)) / (2.0 * columns.max(1) as f64);
        loop {
            let (x_m, y_m) = crate::decimate::path(&self.x_m, &self.y_m, step);
            if x_m.len() <= max_points.max(2) || !(step > 0.0) {
                return Path { x_m, y_m };
            }
            step *= 1.5 * x_m.len() as f64 / max_points.max(2) as f64;
        }
    }
}

/// Heading of a trace at time t (held at the ends), looked up from `*j`, the index of the
/// last trace sample at or before the previous (earlier) t: rows come in time order, so the
/// index only moves forward (one pass over the trace, not a search per row).
fn heading_at(time_s: &[f64], psi_deg: &[f64], t: f64, j: &mut usize) -> f64 {
    if t <= time_s[0] {
        return psi_deg[0];
    }
    while *j + 1 < time_s.len() && time_s[*j + 1] <= t {
        *j += 1;
    }
    interp_at(time_s, psi_deg, *j, t)
}

/// Integrates the log's speed along a heading trace: x += v dt cos(psi), y += v dt sin(psi),
/// at every row with a speed (rectangle rule, the speed and heading at the row's end).
pub fn dead_reckon(log: &DriveLog, time_s: &[f64], psi_deg: &[f64]) -> Result<Path> {
    let speed = log.require(Column::SpeedMps, "needed for the track")?;
    if time_s.is_empty() || time_s.len() != psi_deg.len() {
        return Err(Error::data("the heading trace is empty"));
    }
    let mut p = Path::default();
    let (mut x, mut y) = (0.0, 0.0);
    let mut last_t: Option<f64> = None;
    let mut j = 0;
    for (&t, &v) in log.time_s().iter().zip(speed) {
        if v.is_nan() {
            continue;
        }
        if let Some(t0) = last_t {
            let h = heading_at(time_s, psi_deg, t, &mut j).to_radians();
            x += v * (t - t0) * libm::cos(h);
            y += v * (t - t0) * libm::sin(h);
        }
        last_t = Some(t);
        p.x_m.push(x);
        p.y_m.push(y);
    }
    Ok(p)
}

/// The path integrated along the (unwrapped) reference heading.
pub fn reference_path(log: &DriveLog) -> Result<Path> {
    let r = Reference::from_log(log)?;
    dead_reckon(log, &r.time_s, &r.heading_deg)
}

/// Every method's dead-reckoned path on one table, at the log's rows with a speed: raw
/// integration, Table-III HDR, the pipeline causal and smoothed (each heading aligned to the
/// reference as its score aligns it, or from 0 deg without one), and the reference's own
/// path where there is one. The CLI's `pipeline --track` and Python's `pipeline_track`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tracks {
    /// The rows with a speed, s.
    pub time_s: Vec<f64>,
    /// Method names (`raw`, `hdr`, `pipeline`, `smoothed`, `reference`) and their paths.
    pub paths: Vec<(&'static str, Path)>,
}

impl Tracks {
    /// The paths of `log` with the pipeline's settings (Table-III HDR with its `bias_s`).
    pub fn of(log: &DriveLog, params: &PipelineParams) -> Result<Tracks> {
        params.validate()?;
        let speed = log.require(Column::SpeedMps, "needed for the track")?;
        let prep = Prepared::new(log, params.bias_s, &params.still)?;
        let reference = prep.reference().ok();
        let trace = prep.pipeline_trace(params)?;
        let (t_blocks, raw) = prep.heading(&Method::Raw)?;
        let (_, hdr) = prep.heading(&Method::Hdr(HdrParams::default()))?;
        let headings = [
            ("raw", &t_blocks, raw),
            ("hdr", &t_blocks, hdr),
            ("pipeline", &trace.time_s, trace.heading_deg),
            ("smoothed", &trace.time_s, trace.heading_smoothed_deg),
        ];
        let mut paths = Vec::with_capacity(5);
        for (name, t, mut psi) in headings {
            if let Some(r) = reference {
                let shift = score(t, &psi, r)?.shift_deg;
                psi.iter_mut().for_each(|p| *p += shift);
            }
            paths.push((name, dead_reckon(log, t, &psi)?));
        }
        if let Some(r) = reference {
            paths.push(("reference", dead_reckon(log, &r.time_s, &r.heading_deg)?));
        }
        let time_s = log.time_s().iter().zip(speed).filter(|(_, v)| !v.is_nan()).map(|(&t, _)| t).collect();
        Ok(Tracks { time_s, paths })
    }

    /// CSV: `time_s`, then `NAME_x_m,NAME_y_m` per path.
    pub fn write_csv<W: std::io::Write>(&self, out: W) -> Result<()> {
        use std::io::Write as _;
        let mut out = std::io::BufWriter::new(out);
        write!(out, "time_s")?;
        for (name, _) in &self.paths {
            write!(out, ",{name}_x_m,{name}_y_m")?;
        }
        writeln!(out)?;
        for (i, t) in self.time_s.iter().enumerate() {
            write!(out, "{t}")?;
            for (_, p) in &self.paths {
                write!(out, ",{},{}", p.x_m[i], p.y_m[i])?;
            }
            writeln!(out)?;
        }
        out.flush()?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_by_hand() {
        // 1 m/s, heading 0 for 10 s then 90 deg: ends near (10, 10)
        let mut log = DriveLog::with_columns(&[Column::SpeedMps]);
        for i in 0..=20 {
            log.push_row(&[(Column::TimeS, i as f64), (Column::SpeedMps, 1.0)]);
        }
        let t = [0.0, 10.0, 10.0 + 1e-9, 20.0];
        let psi = [0.0, 0.0, 90.0, 90.0];
        let p = dead_reckon(&log, &t, &psi).unwrap();
        let (x, y) = (*p.x_m.last().unwrap(), *p.y_m.last().unwrap());
        assert!((x - 10.0).abs() < 1e-6 && (y - 10.0).abs() < 1e-6, "{x} {y}");
    }

    #[test]
    fn a_long_path_is_drawn_from_a_few_points_each_under_half_a_pixel_from_the_next() {
        // 100 000 points around a circle of radius 100 m: extent 200 m, 1000 columns, so
        // points 0.1 m apart are kept: about 628 m / 0.1 m of them.
        let n = 100_000;
        let a = |i: usize| i as f64 / n as f64 * std::f64::consts::TAU;
        let p = Path { x_m: (0..=n).map(|i| 100.0 * a(i).cos()).collect(), y_m: (0..=n).map(|i| 100.0 * a(i).sin()).collect() };
        let d = p.for_drawing(1000, usize::MAX);
        assert!((6000..6400).contains(&d.x_m.len()), "{}", d.x_m.len());
        assert_eq!((d.x_m.last(), d.y_m.last()), (p.x_m.last(), p.y_m.last()));
        let gaps = d.x_m.windows(2).zip(d.y_m.windows(2)).map(|(x, y)| (x[1] - x[0]).hypot(y[1] - y[0]));
        assert!(gaps.clone().take(d.x_m.len() - 2).all(|g| (0.1..0.1 + 2.0 * std::f64::consts::PI * 100.0 / n as f64 + 1e-9).contains(&g)));
        // Capped: a coarser step until at most 1000 points remain.
        let c = p.for_drawing(1000, 1000);
        assert!((100..=1000).contains(&c.x_m.len()), "{}", c.x_m.len());
        assert_eq!((c.x_m.last(), c.y_m.last()), (p.x_m.last(), p.y_m.last()));
    }

    /// 60 s at 10 Hz with a still gyro: standing for the 20 s lead-in, then 2 m/s; a
    /// 90 deg turn (9 deg/s from 30 s to 40 s) where `turn`; the reference heading matches
    /// the gyro's where `with_ref`.
    fn drive(turn: bool, with_ref: bool) -> DriveLog {
        let cols: &[Column] =
            if with_ref { &[Column::GyroDps, Column::SpeedMps, Column::RefHeadingDeg] } else { &[Column::GyroDps, Column::SpeedMps] };
        let mut log = DriveLog::with_columns(cols);
        for i in 0..600 {
            let t = i as f64 * 0.1;
            let w = if turn && (30.0..40.0).contains(&t) { 9.0 } else { 0.0 };
            let psi = if turn { (9.0 * (t - 30.0)).clamp(0.0, 90.0) } else { 0.0 };
            let v = if t < 20.0 { 0.0 } else { 2.0 };
            log.push_row(&[(Column::TimeS, t), (Column::GyroDps, w), (Column::SpeedMps, v), (Column::RefHeadingDeg, psi)]);
        }
        log
    }

    #[test]
    fn a_straight_drive_by_hand_every_path_ends_80_m_east() {
        // The speed at each row's end times its step: 2 m/s on the 400 rows from 20 s, 80 m.
        let tr = Tracks::of(&drive(false, true), &PipelineParams::default()).unwrap();
        assert_eq!(tr.time_s.len(), 600);
        let names: Vec<_> = tr.paths.iter().map(|p| p.0).collect();
        assert_eq!(names, ["raw", "hdr", "pipeline", "smoothed", "reference"]);
        for (name, p) in &tr.paths {
            assert_eq!(p.x_m.len(), 600, "{name}");
            let (x, y) = (*p.x_m.last().unwrap(), *p.y_m.last().unwrap());
            assert!((x - 80.0).abs() < 1e-9 && y.abs() < 1e-9, "{name}: {x} {y}");
        }
        let mut csv = Vec::new();
        tr.write_csv(&mut csv).unwrap();
        let text = String::from_utf8(csv).unwrap();
        let mut lines = text.lines();
        assert_eq!(
            lines.next(),
            Some("time_s,raw_x_m,raw_y_m,hdr_x_m,hdr_y_m,pipeline_x_m,pipeline_y_m,smoothed_x_m,smoothed_y_m,reference_x_m,reference_y_m")
        );
        assert_eq!(lines.count(), 600);
    }

    #[test]
    fn the_pipeline_path_follows_its_run_heading_and_a_row_without_speed_is_skipped() {
        let mut log = drive(true, true);
        let speed = log.column_mut(Column::SpeedMps).unwrap();
        speed[450] = f64::NAN;
        let tr = Tracks::of(&log, &PipelineParams::default()).unwrap();
        assert_eq!(tr.time_s.len(), 599);
        assert!(!tr.time_s.iter().any(|&t| (t - 45.0).abs() < 1e-9));
        let run = crate::pipeline::run(&log, &PipelineParams::default()).unwrap();
        let want = dead_reckon(&log, &run.trace.time_s, &run.trace.heading_deg).unwrap();
        assert_eq!(tr.paths[2].1, want);
        // After the quarter turn the drive goes north: the reference ends well north.
        let r = &tr.paths[4].1;
        assert!(*r.y_m.last().unwrap() > 30.0, "{:?}", r.y_m.last());
    }

    #[test]
    fn without_a_reference_four_paths_from_0_deg_and_without_speed_a_clear_error() {
        let tr = Tracks::of(&drive(false, false), &PipelineParams::default()).unwrap();
        assert_eq!(tr.paths.iter().map(|p| p.0).collect::<Vec<_>>(), ["raw", "hdr", "pipeline", "smoothed"]);
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]);
        for i in 0..100 {
            log.push_row(&[(Column::TimeS, i as f64), (Column::GyroDps, 0.0), (Column::RefHeadingDeg, 0.0)]);
        }
        let e = Tracks::of(&log, &PipelineParams::default()).unwrap_err().to_string();
        assert!(e.contains("speed_mps"), "{e}");
    }
}
