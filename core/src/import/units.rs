//! Units, recipe errors and ISO 8601 times.

use super::*;

pub(super) fn recipe_err(field: &str, message: impl Into<String>) -> Error {
    Error::Param { name: format!("recipe {field}"), message: message.into() }
}

/// Factor from `unit` to deg/s.
pub(super) fn rate_unit(unit: &str, field: &str) -> Result<f64> {
    Ok(match unit {
        "deg/s" | "dps" => 1.0,
        "rad/s" => 180.0 / std::f64::consts::PI,
        "mrad/s" => 0.18 / std::f64::consts::PI,
        "deg/h" => 1.0 / 3600.0,
        // Raw counts: `scale` converts them to deg/s.
        "counts" => 1.0,
        _ => return Err(recipe_err(field, format!("unit \"{unit}\" is not a rate unit (deg/s, rad/s, mrad/s, deg/h, counts)"))),
    })
}

pub(super) fn angle_unit(unit: &str, field: &str) -> Result<f64> {
    Ok(match unit {
        "deg" => 1.0,
        "rad" => 180.0 / std::f64::consts::PI,
        _ => return Err(recipe_err(field, format!("unit \"{unit}\" is not an angle unit (deg, rad)"))),
    })
}

pub(super) fn speed_unit(unit: &str, field: &str) -> Result<f64> {
    Ok(match unit {
        "m/s" => 1.0,
        "km/h" => 1.0 / 3.6,
        "mph" => 0.44704,
        // The knot of NMEA's RMC and VTG sentences: one nautical mile (1852 m) per hour.
        "kn" | "knots" => 1852.0 / 3600.0,
        _ => return Err(recipe_err(field, format!("unit \"{unit}\" is not a speed unit (m/s, km/h, mph, kn)"))),
    })
}

pub(super) fn time_unit(unit: &str) -> Result<f64> {
    Ok(match unit {
        "s" => 1.0,
        "ms" => 1e-3,
        "us" => 1e-6,
        "ns" => 1e-9,
        _ => return Err(recipe_err("table.time.unit", format!("\"{unit}\" is not a time unit (s, ms, us, ns)"))),
    })
}

/// Parses a time of day into seconds since midnight: `hh:mm:ss[.fff]` (the hour may have
/// one digit), `hh:mm:ss:fff` (the fraction after a colon, as some phone apps write it) or
/// NMEA's `hhmmss[.sss]`, each with an optional `Z`. Loggers write these without a date;
/// The import's time policies (`time.rs`) count the days as the time passes midnight.
pub fn parse_time_of_day(s: &str) -> Option<f64> {
    let s = s.trim();
    let s = s.strip_suffix(['Z', 'z']).unwrap_or(s);
    let digits = |t: &str, n: std::ops::RangeInclusive<usize>| n.contains(&t.len()) && t.bytes().all(|c| c.is_ascii_digit());
    // The fraction of a second, when written (after a point, or after a third colon).
    let (h, m, sec, frac) = match s.split(':').collect::<Vec<_>>()[..] {
        [h, m, sec] => match sec.split_once('.') {
            Some((sec, frac)) => (h, m, sec, Some(frac)),
            None => (h, m, sec, None),
        },
        [h, m, sec, frac] => (h, m, sec, Some(frac)),
        [hms] => {
            let (whole, frac) = hms.split_once('.').map_or((hms, None), |(w, f)| (w, Some(f)));
            // Six ASCII digits before the slicing (a multi-byte character is no digit).
            if whole.len() != 6 || !whole.bytes().all(|c| c.is_ascii_digit()) {
                return None;
            }
            (&whole[..2], &whole[2..4], &whole[4..], frac)
        }
        _ => return None,
    };
    if !(digits(h, 1..=2) && digits(m, 2..=2) && digits(sec, 2..=2) && frac.is_none_or(|f| digits(f, 1..=9))) {
        return None;
    }
    let (h, m, sec): (u32, u32, u32) = (h.parse().ok()?, m.parse().ok()?, sec.parse().ok()?);
    if h > 23 || m > 59 || sec > 60 {
        return None;
    }
    let frac = match frac {
        Some(f) => format!("0.{f}").parse::<f64>().ok()?,
        None => 0.0,
    };
    Some(f64::from(h * 3600 + m * 60 + sec) + frac)
}

/// Parses an ISO 8601 date-time (`YYYY-MM-DD[T ]hh:mm:ss[.fff][Z|±hh:mm]`) into seconds
/// since 1970-01-01 UTC; no offset means UTC.
pub fn parse_iso8601(s: &str) -> Option<f64> {
    let s = s.trim();
    let b = s.as_bytes();
    if b.len() < 19 || b[4] != b'-' || b[7] != b'-' || !(b[10] == b'T' || b[10] == b' ') || b[13] != b':' || b[16] != b':' {
        return None;
    }
    let num = |r: std::ops::Range<usize>| -> Option<i64> {
        let t = s.get(r)?;
        if t.bytes().all(|c| c.is_ascii_digit()) {
            t.parse().ok()
        } else {
            None
        }
    };
    let (y, mo, d) = (num(0..4)?, num(5..7)?, num(8..10)?);
    let (h, mi) = (num(11..13)?, num(14..16)?);
    if !(1..=12).contains(&mo) || !(1..=31).contains(&d) || h > 23 || mi > 59 {
        return None;
    }
    // Seconds with an optional fraction, then the zone.
    let rest = &s[17..];
    let end = rest.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(rest.len());
    let sec: f64 = rest[..end].parse().ok()?;
    if !(0.0..61.0).contains(&sec) {
        return None;
    }
    let zone = &rest[end..];
    let offset_s = match zone {
        "" | "Z" => 0,
        z if (z.starts_with('+') || z.starts_with('-')) && (z.len() == 6 || z.len() == 5 || z.len() == 3) => {
            let sign = if z.starts_with('-') { -1 } else { 1 };
            let digits: String = z[1..].chars().filter(|c| *c != ':').collect();
            if digits.len() != 4 && digits.len() != 2 || !digits.bytes().all(|c| c.is_ascii_digit()) {
                return None;
            }
            let zh: i64 = digits[..2].parse().ok()?;
            let zm: i64 = if digits.len() == 4 { digits[2..].parse().ok()? } else { 0 };
            sign * (zh * 3600 + zm * 60)
        }
        _ => return None,
    };
    // Days from civil (H. Hinnant's algorithm).
    let y2 = if mo <= 2 { y - 1 } else { y };
    let era = y2.div_euclid(400);
    let yoe = y2 - era * 400;
    let mp = (mo + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    let days = era * 146_097 + doe - 719_468;
    Some((days * 86_400 + h * 3600 + mi * 60 - offset_s) as f64 + sec)
}
