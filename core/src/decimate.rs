//! Min/max decimation for drawing: a series reduced to at most four points per pixel
//! column (first, min, max, last, in time order), so a 1 h 10 Hz log and a 10 M-sample log
//! redraw alike and no peak is lost.

/// Reduces (x, y) inside [x0, x1] to at most 4 points per column of `columns` columns.
/// The samples just outside the window are kept so lines run to the edges. NaN y values
/// break nothing: they are skipped.
pub fn min_max(x: &[f64], y: &[f64], x0: f64, x1: f64, columns: usize) -> (Vec<f64>, Vec<f64>) {
    shared_indices(x, &[y], x0, x1, columns).into_iter().filter(|&i| !y[i].is_nan()).map(|i| (x[i], y[i])).unzip()
}

/// The samples to draw of several series sharing one x (a trace's columns): in each of
/// `columns` pixel columns of [x0, x1], the first and last sample where some series has a
/// value and each series' minimum and maximum, in order and once (a column where every
/// series is NaN keeps nothing); the samples just outside the window are kept so lines run
/// to the edges. Every series sampled at these indices keeps its extremes per column, and
/// the series still share their x. When the window holds at most 4 samples per column, every
/// sample in it is kept.
pub fn shared_indices(x: &[f64], ys: &[&[f64]], x0: f64, x1: f64, columns: usize) -> Vec<usize> {
    let n = ys.iter().fold(x.len(), |n, y| n.min(y.len()));
    if n == 0 || columns == 0 || !(x1 > x0) {
        return Vec::new();
    }
    let start = x[..n].partition_point(|&v| v < x0).saturating_sub(1);
    let end = (x[..n].partition_point(|&v| v <= x1) + 1).min(n);
    if end - start <= 4 * columns {
        return (start..end).collect();
    }
    let scale = columns as f64 / (x1 - x0);
    let mut out = Vec::with_capacity(columns * (2 + 2 * ys.len()));
    let mut picked = Vec::with_capacity(2 + 2 * ys.len());
    let mut i = start;
    while i < end {
        let col = ((x[i] - x0) * scale).floor();
        let first = i;
        while i < end && ((x[i] - x0) * scale).floor() == col {
            i += 1;
        }
        picked.clear();
        let valued = |k: &usize| ys.iter().any(|y| !y[*k].is_nan());
        match ((first..i).find(valued), (first..i).rev().find(valued)) {
            (Some(a), Some(b)) => picked.extend([a, b]),
            _ => continue,
        }
        for y in ys {
            let (mut lo, mut hi) = (usize::MAX, usize::MAX);
            for (k, &v) in y[first..i].iter().enumerate() {
                if v.is_nan() {
                    continue;
                }
                if lo == usize::MAX || v < y[first + lo] {
                    lo = k;
                }
                if hi == usize::MAX || v > y[first + hi] {
                    hi = k;
                }
            }
            if lo != usize::MAX {
                picked.extend([first + lo, first + hi]);
            }
        }
        picked.sort_unstable();
        picked.dedup();
        out.extend_from_slice(&picked);
    }
    out
}

/// The values of `y` at `indices`.
pub fn take(y: &[f64], indices: &[usize]) -> Vec<f64> {
    indices.iter().map(|&i| y.get(i).copied().unwrap_or(f64::NAN)).collect()
}

/// Reduces a path (x, y) to the points at least `min_step` (same unit) from the last kept
/// point, plus the last one: no point of the path is farther than `min_step` from the drawn
/// polyline's vertices, so at a scale where `min_step` is under a pixel it draws the same. NaN
/// points are skipped.
pub fn path(x: &[f64], y: &[f64], min_step: f64) -> (Vec<f64>, Vec<f64>) {
    let n = x.len().min(y.len());
    let (mut ox, mut oy) = (Vec::new(), Vec::new());
    let step2 = if min_step > 0.0 { min_step * min_step } else { 0.0 };
    let mut last = None;
    for i in 0..n {
        let (px, py) = (x[i], y[i]);
        if px.is_nan() || py.is_nan() {
            continue;
        }
        let keep = match ox.last().zip(oy.last()) {
            None => true,
            Some((&lx, &ly)) => (px - lx) * (px - lx) + (py - ly) * (py - ly) >= step2,
        };
        if keep {
            ox.push(px);
            oy.push(py);
            last = None;
        } else {
            last = Some((px, py));
        }
    }
    if let Some((px, py)) = last {
        ox.push(px);
        oy.push(py);
    }
    (ox, oy)
}

/// A polyline clipped to the rectangle [x0, x1] x [y0, y1] (a zoomed plot): the runs of it
/// inside, each crossing of the border cut where it crosses (Liang-Barsky), so a line that
/// leaves the plot ends at its edge instead of being drawn along it.
pub fn clip_polyline(pts: &[(f64, f64)], (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    // Whether the last run ends at the last point, inside.
    let mut open = false;
    if let [p] = pts {
        if (x0..=x1).contains(&p.0) && (y0..=y1).contains(&p.1) {
            runs.push(vec![*p]);
        }
    }
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        // The segment a + t (b - a), t in [0, 1], within each of the four borders.
        let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
        let mut visible = dx.is_finite() && dy.is_finite();
        for (p, q) in [(-dx, a.0 - x0), (dx, x1 - a.0), (-dy, a.1 - y0), (dy, y1 - a.1)] {
            if p == 0.0 {
                visible &= q >= 0.0;
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
        if !visible || t0 > t1 {
            open = false;
            continue;
        }
        let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
        match runs.last_mut() {
            Some(run) if open && t0 == 0.0 => run.push(at(t1)),
            _ => runs.push(vec![at(t0), at(t1)]),
        }
        open = t1 == 1.0;
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_extremes_per_column() {
        let x: Vec<f64> = (0..1000).map(|i| i as f64).collect();
        let mut y = vec![0.0; 1000];
        y[500] = 7.0;
        y[501] = -3.0;
        let (dx, dy) = min_max(&x, &y, 0.0, 999.0, 10);
        assert!(dx.len() <= 4 * 11);
        assert!(dy.contains(&7.0) && dy.contains(&-3.0));
        assert!(dx.windows(2).all(|w| w[0] < w[1]), "time order kept");
    }

    #[test]
    fn small_series_pass_through_with_edges() {
        let x = [0.0, 1.0, 2.0, 3.0];
        let y = [1.0, f64::NAN, 3.0, 4.0];
        let (dx, dy) = min_max(&x, &y, 1.5, 2.5, 100);
        assert_eq!(dx, vec![2.0, 3.0]); // sample 1 (edge) is NaN and skipped
        assert_eq!(dy, vec![3.0, 4.0]);
        assert!(min_max(&x, &y, 2.0, 1.0, 10).0.is_empty());
    }

    #[test]
    fn shared_indices_keep_every_series_extremes() {
        let x: Vec<f64> = (0..1000).map(|i| i as f64).collect();
        let mut a = vec![0.0; 1000];
        let mut b = vec![1.0; 1000];
        a[500] = 7.0;
        b[503] = -3.0;
        b[10] = f64::NAN;
        let idx = shared_indices(&x, &[&a, &b], 0.0, 999.0, 10);
        assert!(idx.windows(2).all(|w| w[0] < w[1]), "in order, once");
        assert!(idx.contains(&500) && idx.contains(&503), "{idx:?}");
        assert!(idx.len() <= 6 * 11);
        assert_eq!(take(&a, &idx).iter().cloned().fold(f64::MIN, f64::max), 7.0);
        assert_eq!(take(&b, &idx).iter().cloned().filter(|v| !v.is_nan()).fold(f64::MAX, f64::min), -3.0);
        // A small window keeps every sample, with one beyond each edge.
        assert_eq!(shared_indices(&x, &[&a], 10.5, 14.5, 10), vec![10, 11, 12, 13, 14, 15]);
        assert!(shared_indices(&x, &[&a], 5.0, 1.0, 10).is_empty());
        let t = take(&a, &[2, 5000]);
        assert_eq!(t[0], 0.0);
        assert!(t[1].is_nan(), "an index past the end reads NaN");
    }

    #[test]
    fn a_path_keeps_points_a_step_apart_and_its_end() {
        let x: Vec<f64> = (0..=10).map(|i| i as f64 * 0.1).collect();
        let y = vec![0.0; 11];
        let (px, py) = path(&x, &y, 0.25);
        // Kept: 0, 0.3 (0.2 < 0.25), 0.6, 0.9, then the last point 1.0.
        let want = [0.0, 0.3, 0.6, 0.9, 1.0];
        assert_eq!(px.len(), want.len(), "{px:?}");
        for (a, b) in px.iter().zip(want) {
            assert!((a - b).abs() < 1e-12, "{px:?}");
        }
        assert!(py.iter().all(|&v| v == 0.0));
        // A step of 0 keeps everything; NaN points are skipped; empty stays empty.
        assert_eq!(path(&x, &y, 0.0).0.len(), 11);
        assert_eq!(path(&[0.0, f64::NAN, 2.0], &[0.0, 0.0, 0.0], 1.0).0, vec![0.0, 2.0]);
        assert!(path(&[], &[], 1.0).0.is_empty());
    }

    /// Hand-worked on the unit square: in from the left, up and out through the top, along
    /// outside, back in through the right edge.
    #[test]
    fn a_polyline_is_cut_where_it_crosses_the_border() {
        let pts = [(-1.0, 0.5), (0.5, 0.5), (0.5, 2.0), (2.0, 2.0), (0.5, 0.25)];
        let runs = clip_polyline(&pts, (0.0, 1.0), (0.0, 1.0));
        assert_eq!(runs.len(), 2, "{runs:?}");
        assert_eq!(runs[0], vec![(0.0, 0.5), (0.5, 0.5), (0.5, 1.0)]);
        // (2, 2) -> (0.5, 0.25) enters through x = 1 at t = 2/3: y = 2 - 1.75 * 2/3.
        let (x, y) = runs[1][0];
        assert!((x - 1.0).abs() < 1e-12 && (y - (2.0 - 1.75 * 2.0 / 3.0)).abs() < 1e-12, "{runs:?}");
        assert_eq!(runs[1][1], (0.5, 0.25));
        // Wholly inside: one run, the points as they are; wholly outside: none.
        assert_eq!(clip_polyline(&[(0.1, 0.1), (0.9, 0.9)], (0.0, 1.0), (0.0, 1.0)), vec![vec![(0.1, 0.1), (0.9, 0.9)]]);
        assert!(clip_polyline(&[(2.0, 0.1), (3.0, 0.9)], (0.0, 1.0), (0.0, 1.0)).is_empty());
        // Through both sides of the square in one segment.
        assert_eq!(clip_polyline(&[(-1.0, 0.5), (2.0, 0.5)], (0.0, 1.0), (0.0, 1.0)), vec![vec![(0.0, 0.5), (1.0, 0.5)]]);
        // A NaN point breaks the line.
        assert_eq!(clip_polyline(&[(0.1, 0.1), (f64::NAN, 0.5), (0.9, 0.9)], (0.0, 1.0), (0.0, 1.0)).len(), 0);
        assert_eq!(clip_polyline(&[(0.5, 0.5)], (0.0, 1.0), (0.0, 1.0)), vec![vec![(0.5, 0.5)]]);
    }
}
