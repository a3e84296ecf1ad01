//! Positions to local east/north, course and speed from positions, integration,
//! interpolation and the clock alignment of two rate series.

use super::*;

/// Local east/north (m) of positions, relative to the first valid one.
pub(super) fn local_en(spec: &PositionsSpec, t: &Table) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let need = match spec.kind {
        PositionKind::Ecef => 3,
        PositionKind::Nmea => 4,
        _ => 2,
    };
    if spec.columns.len() != need {
        return Err(recipe_err("positions.columns", format!("{:?} positions need {need} columns", spec.kind)));
    }
    let c: Vec<&[f64]> = spec.columns.iter().map(|n| t.col(n, "positions")).collect::<Result<_>>()?;
    // NMEA's positions in decimal degrees, then as latlon.
    let degrees: [Vec<f64>; 2];
    let (kind, c, need) = if spec.kind == PositionKind::Nmea {
        degrees = [nmea_degrees(c[0], c[1]), nmea_degrees(c[2], c[3])];
        (PositionKind::Latlon, vec![degrees[0].as_slice(), degrees[1].as_slice()], 2)
    } else {
        (spec.kind, c, need)
    };
    let mut time = Vec::new();
    let (mut e, mut nn) = (Vec::new(), Vec::new());
    let first = (0..t.time_s.len()).find(|&i| (0..need).all(|j| c[j][i].is_finite()));
    let Some(i0) = first else {
        return Err(Error::data(format!("{}: no complete position", t.file)));
    };
    // WGS84
    const A: f64 = 6_378_137.0;
    const E2: f64 = 6.694_379_990_14e-3;
    let (lat0, lon0) = match kind {
        PositionKind::Latlon => (c[0][i0].to_radians(), c[1][i0].to_radians()),
        PositionKind::Ecef => {
            let (x, y, z) = (c[0][i0], c[1][i0], c[2][i0]);
            let p = (x * x + y * y).sqrt();
            let mut lat = libm::atan2(z, p * (1.0 - E2));
            for _ in 0..5 {
                let s = libm::sin(lat);
                let n = A / (1.0 - E2 * s * s).sqrt();
                lat = libm::atan2(z + E2 * n * s, p);
            }
            (lat, libm::atan2(y, x))
        }
        _ => (0.0, 0.0),
    };
    let s2 = libm::sin(lat0) * libm::sin(lat0);
    let r_n = A / (1.0 - E2 * s2).sqrt(); // prime vertical
    let r_m = A * (1.0 - E2) / libm::pow(1.0 - E2 * s2, 1.5); // meridional
    for i in 0..t.time_s.len() {
        if !(0..need).all(|j| c[j][i].is_finite()) {
            continue;
        }
        let (de, dn) = match kind {
            // (NMEA's positions are latlon here, converted above.)
            PositionKind::Latlon | PositionKind::Nmea => {
                ((c[1][i].to_radians() - lon0) * r_n * libm::cos(lat0), (c[0][i].to_radians() - lat0) * r_m)
            }
            PositionKind::Utm | PositionKind::Enu => (c[0][i] - c[0][i0], c[1][i] - c[1][i0]),
            PositionKind::Ecef => {
                let d = [c[0][i] - c[0][i0], c[1][i] - c[1][i0], c[2][i] - c[2][i0]];
                let (sl, cl, so, co) = (libm::sin(lat0), libm::cos(lat0), libm::sin(lon0), libm::cos(lon0));
                (-so * d[0] + co * d[1], -sl * co * d[0] - sl * so * d[1] + cl * d[2])
            }
        };
        time.push(t.time_s[i]);
        e.push(de);
        nn.push(dn);
    }
    Ok((time, e, nn))
}

/// NMEA's `ddmm.mmmm` (or `dddmm.mmmm`) with its hemisphere (+1 for N or E, -1 for S or W,
/// as an NMEA table reads the letters) in signed decimal degrees: 4220.2340 N = 42.33723.
pub(super) fn nmea_degrees(ddmm: &[f64], hemisphere: &[f64]) -> Vec<f64> {
    ddmm.iter()
        .zip(hemisphere)
        .map(|(&v, &h)| {
            let d = (v / 100.0).trunc();
            h * (d + (v - 100.0 * d) / 60.0)
        })
        .collect()
}

/// Course over ground (deg, clockwise from north) between positions at least
/// `min_distance_m` apart, stamped at the segment's middle; segments slower than
/// `min_speed_mps` restart the anchor without a sample.
pub fn course_from_positions(
    time_s: &[f64],
    east_m: &[f64],
    north_m: &[f64],
    min_distance_m: f64,
    min_speed_mps: f64,
) -> (Vec<f64>, Vec<f64>) {
    let (mut ts, mut course) = (Vec::new(), Vec::new());
    let mut a = 0usize;
    for i in 1..time_s.len() {
        let (de, dn) = (east_m[i] - east_m[a], north_m[i] - north_m[a]);
        let d = (de * de + dn * dn).sqrt();
        if d >= min_distance_m {
            let dt = time_s[i] - time_s[a];
            if d / dt >= min_speed_mps {
                ts.push(0.5 * (time_s[i] + time_s[a]));
                course.push(libm::atan2(de, dn).to_degrees());
            }
            a = i;
        } else if time_s[i] - time_s[a] > min_distance_m / min_speed_mps.max(1e-3) {
            // Too slow to reach the distance at the minimum speed: restart here.
            a = i;
        }
    }
    (ts, course)
}

/// Speed (m/s) from positions: distance to the last position at least `window_s` earlier.
pub fn speed_from_positions(time_s: &[f64], east_m: &[f64], north_m: &[f64], window_s: f64) -> (Vec<f64>, Vec<f64>) {
    let (mut ts, mut v) = (Vec::new(), Vec::new());
    let mut k = 0usize;
    for i in 0..time_s.len() {
        while k + 1 < i && time_s[k + 1] <= time_s[i] - window_s {
            k += 1;
        }
        let dt = time_s[i] - time_s[k];
        if i > k && dt >= window_s {
            let (de, dn) = (east_m[i] - east_m[k], north_m[i] - north_m[k]);
            ts.push(time_s[i]);
            v.push((de * de + dn * dn).sqrt() / dt);
        }
    }
    (ts, v)
}

/// Cumulative travel (m) from speeds (m/s) by the trapezoid rule; empty cells are skipped.
pub fn integrate_speed(time_s: &[f64], speed_mps: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(time_s.len());
    let mut acc = 0.0;
    let mut prev: Option<(f64, f64)> = None;
    for (&t, &v) in time_s.iter().zip(speed_mps) {
        if v.is_finite() {
            if let Some((tp, vp)) = prev {
                acc += 0.5 * (v + vp) * (t - tp);
            }
            prev = Some((t, v));
            out.push(acc);
        } else {
            out.push(f64::NAN);
        }
    }
    out
}

/// Linear interpolation of the finite samples (ts, vs) at each of the increasing times
/// `at` (the metrics' rule, `metrics::interp_at`); NaN outside their span.
pub fn interpolate(ts: &[f64], vs: &[f64], at: &[f64]) -> Vec<f64> {
    let (pt, pv): (Vec<f64>, Vec<f64>) = ts.iter().zip(vs).filter(|(_, v)| v.is_finite()).map(|(&t, &v)| (t, v)).unzip();
    let mut j = 0usize;
    at.iter()
        .map(|&t| match (pt.first(), pt.last()) {
            (Some(&a), Some(&b)) if t >= a && t <= b => {
                while j + 1 < pt.len() && pt[j + 1] <= t {
                    j += 1;
                }
                crate::metrics::interp_at(&pt, &pv, j, t)
            }
            _ => f64::NAN,
        })
        .collect()
}

/// Means of (ts, vs) in bins of `dt` from `t0`, NaN where a bin is empty.
pub(super) fn bin_means(ts: &[f64], vs: &[f64], t0: f64, dt: f64, n: usize) -> Vec<f64> {
    let mut sum = vec![0.0; n];
    let mut cnt = vec![0usize; n];
    for (&t, &v) in ts.iter().zip(vs) {
        let k = ((t - t0) / dt).floor();
        if v.is_finite() && k >= 0.0 && (k as usize) < n {
            sum[k as usize] += v;
            cnt[k as usize] += 1;
        }
    }
    sum.iter().zip(&cnt).map(|(&s, &c)| if c > 0 { s / c as f64 } else { f64::NAN }).collect()
}

/// The lag (s) to add to series a's times so that it best matches series b: the maximum
/// of the normalised cross-correlation on a 20 Hz grid, refined by a parabola.
pub fn best_lag_s(ta: &[f64], a: &[f64], tb: &[f64], b: &[f64], max_lag_s: f64) -> Result<f64> {
    const DT: f64 = 0.05;
    let (Some(&b0), Some(&b1)) = (tb.first(), tb.last()) else {
        return Err(Error::data("alignment: the reference rate is empty"));
    };
    if !(max_lag_s.is_finite() && max_lag_s > 0.0 && max_lag_s <= 600.0) {
        return Err(recipe_err("align.max_lag_s", format!("{max_lag_s} is not a lag in (0, 600] s")));
    }
    // 20 Hz bins over the reference: a span of days means a wrong time unit, not a drive.
    if !(b1 - b0 <= 86_400.0) {
        return Err(Error::data(format!("alignment: the reference rate spans {} s (over a day): check the time units", b1 - b0)));
    }
    let n = ((b1 - b0) / DT).floor() as usize + 1;
    let gb = bin_means(tb, b, b0, DT, n);
    let max_k = (max_lag_s / DT).round() as i64;
    let mut best = (f64::NEG_INFINITY, 0i64);
    let mut scores = BTreeMap::new();
    for k in -max_k..=max_k {
        let shifted: Vec<f64> = ta.iter().map(|&t| t + k as f64 * DT).collect();
        let ga = bin_means(&shifted, a, b0, DT, n);
        let (mut sab, mut saa, mut sbb, mut sa, mut sb, mut m) = (0.0, 0.0, 0.0, 0.0, 0.0, 0usize);
        for (x, y) in ga.iter().zip(&gb) {
            if x.is_finite() && y.is_finite() {
                sab += x * y;
                saa += x * x;
                sbb += y * y;
                sa += x;
                sb += y;
                m += 1;
            }
        }
        if m < 100 {
            continue;
        }
        let mf = m as f64;
        let cov = sab - sa * sb / mf;
        let den = ((saa - sa * sa / mf) * (sbb - sb * sb / mf)).sqrt();
        let r = if den > 0.0 { cov / den } else { 0.0 };
        scores.insert(k, r);
        if r > best.0 {
            best = (r, k);
        }
    }
    if !best.0.is_finite() {
        return Err(Error::data("alignment: the gyro and the reference rate do not overlap by 5 s at any lag"));
    }
    let k = best.1;
    let (ym, y0, yp) = (scores.get(&(k - 1)), Some(best.0), scores.get(&(k + 1)));
    let frac = match (ym, y0, yp) {
        (Some(&ym), Some(y0), Some(&yp)) if ym - 2.0 * y0 + yp < 0.0 => 0.5 * (ym - yp) / (ym - 2.0 * y0 + yp),
        _ => 0.0,
    };
    Ok((k as f64 + frac) * DT)
}
