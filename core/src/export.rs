//! What a chart shows, written out as CSV: every plotted series with the values that were
//! drawn (no interpolation), so a figure can be re-made or checked elsewhere.

use crate::report::csv_line;

/// One plotted series: its name and samples.
pub struct Series<'a> {
    pub name: &'a str,
    pub x: &'a [f64],
    pub y: &'a [f64],
}

fn cell(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        String::new()
    }
}

/// The unit of an axis label written `<quantity> (<unit>)` (the last parenthesis at the
/// end), or "" when it has none: the one reading of a label's unit for CSV columns and the
/// dashboard's tooltips.
pub fn label_unit(label: &str) -> &str {
    let l = label.trim_end();
    match (l.strip_suffix(')'), l.rfind('(')) {
        (Some(head), Some(open)) if open < head.len() => head[open + 1..].trim(),
        _ => "",
    }
}

/// Series over a shared x (time, tau): a first column `x_name` holding every x any series
/// has, in order and once, and a column per series with its value at that x, empty where it
/// has no sample there. Series must be sorted by x (time traces are); samples with a
/// non-finite x are left out.
pub fn series_csv(x_name: &str, series: &[Series]) -> String {
    let mut xs: Vec<f64> = series.iter().flat_map(|s| s.x.iter().take(s.y.len()).copied()).filter(|x| x.is_finite()).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let mut out = csv_line(x_name, series.iter().map(|s| s.name.to_string()));
    let mut at = vec![0usize; series.len()];
    for &x in &xs {
        let cells = series.iter().zip(at.iter_mut()).map(|(s, i)| {
            let n = s.x.len().min(s.y.len());
            while *i < n && !(s.x[*i] >= x) {
                *i += 1;
            }
            if *i < n && s.x[*i] == x {
                let v = s.y[*i];
                *i += 1;
                cell(v)
            } else {
                String::new()
            }
        });
        out += &csv_line(&cell(x), cells);
    }
    out
}

/// Paths (a track: x and y both data, not ordered in x): two columns per series,
/// `<name> x` and `<name> y`, row k holding each path's k-th point (empty past its end).
pub fn paths_csv(x_name: &str, y_name: &str, series: &[Series]) -> String {
    let rows = series.iter().map(|s| s.x.len().min(s.y.len())).max().unwrap_or(0);
    let names: Vec<String> = series.iter().flat_map(|s| [format!("{} {x_name}", s.name), format!("{} {y_name}", s.name)]).collect();
    let mut out = csv_line(names.first().map_or("", |n| n.as_str()), names.iter().skip(1).cloned());
    for k in 0..rows {
        let mut cells = series.iter().flat_map(|s| {
            let n = s.x.len().min(s.y.len());
            if k < n {
                [cell(s.x[k]), cell(s.y[k])]
            } else {
                [String::new(), String::new()]
            }
        });
        let first = cells.next().unwrap_or_default();
        out += &csv_line(&first, cells);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn label_unit_reads_the_last_parenthesis_at_the_end() {
        assert_eq!(label_unit("heading error (deg)"), "deg");
        assert_eq!(label_unit("rate (deg/s) "), "deg/s");
        assert_eq!(label_unit("adev (deg/s) (1-sigma band)"), "1-sigma band");
        assert_eq!(label_unit("speed ( m/s )"), "m/s");
        assert_eq!(label_unit("count"), "");
        assert_eq!(label_unit("(deg) after"), "");
        assert_eq!(label_unit(""), "");
        assert_eq!(label_unit(")"), "");
    }

    #[test]
    fn series_on_the_union_of_their_times() {
        let t = [0.0, 0.5, 1.0, 1.5, 2.0];
        let raw = [1.0, 2.0, 3.0, 4.0, 5.0];
        let ref_t = [0.0, 1.0, 2.0];
        let ref_y = [10.0, f64::NAN, 30.0];
        let csv =
            series_csv("time_s", &[Series { name: "raw (deg)", x: &t, y: &raw }, Series { name: "reference, GPS", x: &ref_t, y: &ref_y }]);
        assert_eq!(csv, "time_s,raw (deg),\"reference, GPS\"\n0,1,10\n0.5,2,\n1,3,\n1.5,4,\n2,5,30\n");
    }

    #[test]
    fn shorter_y_and_duplicate_x_are_safe() {
        let csv = series_csv("x", &[Series { name: "a", x: &[0.0, 1.0, 1.0, 2.0], y: &[1.0, 2.0, 3.0] }]);
        // x = 2 has no y: not written; the second sample at x = 1 is dropped (one row per x).
        assert_eq!(csv, "x,a\n0,1\n1,2\n");
        assert_eq!(series_csv("x", &[]), "x\n");
    }

    #[test]
    fn paths_side_by_side() {
        let csv = paths_csv(
            "east_m",
            "north_m",
            &[Series { name: "raw", x: &[0.0, 1.0], y: &[0.0, 2.0] }, Series { name: "HDR", x: &[0.5], y: &[0.25] }],
        );
        assert_eq!(csv, "raw east_m,raw north_m,HDR east_m,HDR north_m\n0,0,0.5,0.25\n1,2,,\n");
    }
}
