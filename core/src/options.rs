//! Settings by name, one schema: serde reads every settings struct (short names declared
//! once, as `alias` on its fields) and each struct checks itself once ([`Settings::validate`]).
//! The CLI's `--set key=value` pairs and the wasm package's option objects both come here.

use crate::error::{Error, Result};
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::{Map, Value};

/// A settings struct: serde with defaults and unknown fields denied, and one validation.
pub trait Settings: Serialize + DeserializeOwned + Default {
    /// Every setting finite and in its range.
    fn validate(&self) -> Result<()>;
}

/// A static-bias window (the `bias_s` of every method): None, or a time >= 0 s.
pub fn check_bias_s(bias_s: Option<f64>) -> Result<()> {
    match bias_s {
        Some(b) if !(b.is_finite() && b >= 0.0) => Err(Error::param("bias_s", format!("{b} is not a time >= 0 s"))),
        _ => Ok(()),
    }
}

/// Settings from a JSON object (missing fields take their defaults), validated. An unknown
/// field or a value of the wrong type is an error naming the field.
pub fn from_json<T: Settings>(value: Value) -> Result<T> {
    // The generic part is the parse alone; the rest is written once for every settings
    // struct (it was instantiated for each: 5 KB of the browser's size-budgeted module).
    let parse = |v: Value| serde_json::from_value::<T>(v).map_err(|e| e.to_string());
    let mut out = None;
    checked_object(value, &mut |v| parse(v).map(|t| out = Some(t)))?;
    let t = out.unwrap_or_default();
    t.validate()?;
    Ok(t)
}

/// Parses `value` (null: the defaults, left to the caller) with `parse`; on failure names
/// the field: the first one that fails on its own.
fn checked_object(value: Value, parse: &mut dyn FnMut(Value) -> std::result::Result<(), String>) -> Result<()> {
    let obj = match value {
        Value::Null => return Ok(()),
        Value::Object(o) => o,
        other => return Err(Error::param("options", format!("expected an object, not {other}"))),
    };
    let Err(e) = parse(Value::Object(obj.clone())) else { return Ok(()) };
    for (k, v) in &obj {
        // Inserted, not collected: a collect into the map sorts, code the size-capped wasm
        // module would carry for this alone.
        let mut one = Map::new();
        one.insert(k.clone(), v.clone());
        if let Err(e1) = parse(Value::Object(one)) {
            return Err(Error::param(k, e1));
        }
    }
    Err(Error::param("options", e))
}

/// A pair's value as JSON: a whole number as an integer (so integer settings take it), any
/// other finite number as it is.
fn number(key: &str, v: f64) -> Result<Value> {
    if v.fract() == 0.0 && v.abs() < 9e15 {
        Ok(Value::from(v as i64))
    } else {
        serde_json::Number::from_f64(v).map(Value::Number).ok_or_else(|| Error::param(key, format!("{v} is not a finite number")))
    }
}

/// Settings from `key=value` pairs on top of the defaults (the CLI's `--set`): a key is a
/// field name or its alias; a key that names a field of a nested settings struct (the
/// pipeline's still thresholds) goes to that struct. Validated.
pub fn from_pairs<T: Settings>(pairs: &[(String, f64)]) -> Result<T> {
    let defaults = serde_json::to_value(T::default()).map_err(|e| Error::param("options", e.to_string()))?;
    let mut obj = Map::new();
    for (k, v) in pairs {
        let num = number(k, *v)?;
        let nested = defaults.as_object().and_then(|d| {
            d.iter().find(|(_, inner)| !d.contains_key(k.as_str()) && inner.as_object().is_some_and(|i| i.contains_key(k.as_str())))
        });
        match nested {
            Some((name, _)) => {
                let inner = obj.entry(name.clone()).or_insert_with(|| Value::Object(Map::new()));
                if let Value::Object(m) = inner {
                    m.insert(k.clone(), num);
                }
            }
            None => {
                obj.insert(k.clone(), num);
            }
        }
    }
    from_json(Value::Object(obj))
}

/// Settings from `key=value` pairs on top of `base` (a battery profile's gyro errors, say):
/// a key is a field name (no aliases, nothing nested) and a yes/no field takes 0 or 1.
/// Validated.
pub fn from_pairs_on<T: Settings>(base: &T, pairs: &[(String, f64)]) -> Result<T> {
    let base = serde_json::to_value(base).map_err(|e| Error::param("options", e.to_string()))?;
    let mut obj = base.as_object().cloned().unwrap_or_default();
    for (k, v) in pairs {
        let value = match obj.get(k.as_str()) {
            None => {
                let known: Vec<&str> = obj.keys().map(String::as_str).collect();
                return Err(Error::param(k, format!("unknown setting; the settings are {}", known.join(", "))));
            }
            Some(Value::Bool(_)) if *v == 0.0 || *v == 1.0 => Value::Bool(*v == 1.0),
            Some(Value::Bool(_)) => return Err(Error::param(k, format!("{v} is not 0 (no) or 1 (yes)"))),
            Some(_) => number(k, *v)?,
        };
        obj.insert(k.clone(), value);
    }
    from_json(Value::Object(obj))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hdr::{HdrOptions, HdrParams};
    use crate::pipeline::PipelineParams;

    fn pairs(p: &[(&str, f64)]) -> Vec<(String, f64)> {
        p.iter().map(|(k, v)| (k.to_string(), *v)).collect()
    }

    #[test]
    fn pairs_by_alias_and_field_name_and_nested() {
        let o: HdrOptions = from_pairs(&pairs(&[("i_c", 0.01), ("tau_s", 2.0), ("bias_s", 10.0)])).unwrap();
        assert_eq!(o.params, HdrParams { i_c_dps: 0.01, tau_s: 2.0, ..HdrParams::table_iii() });
        assert_eq!(o.bias_s, Some(10.0));
        let p: PipelineParams = from_pairs(&pairs(&[("still_speed_mps", 0.5), ("forget_s", 100.0)])).unwrap();
        assert_eq!(p.still.still_speed_mps, 0.5);
        assert_eq!(p.forget_s, 100.0);
        assert_eq!(p.still.still_travel_m, PipelineParams::default().still.still_travel_m);
    }

    /// On top of a base, not the defaults: its other fields kept, a field set to its default
    /// value still set, a yes/no field by 0 or 1; an unknown key or a yes/no of 0.5 refused.
    #[test]
    fn pairs_on_a_base_hand_worked() {
        use crate::sim::GyroErrors;
        let base = GyroErrors { bias_dps: 1.5, scale: 0.02, cut_lead_in: true, ..GyroErrors::default() };
        let e: GyroErrors =
            from_pairs_on(&base, &pairs(&[("bias_dps", 0.0), ("gyro_only", 1.0), ("cut_lead_in", 0.0), ("seed", 7.0)])).unwrap();
        assert_eq!(e, GyroErrors { bias_dps: 0.0, scale: 0.02, gyro_only: true, seed: 7, ..GyroErrors::default() });
        let err = from_pairs_on(&base, &pairs(&[("bias", 1.0)])).unwrap_err();
        assert!(matches!(&err, Error::Param { name, message } if name == "bias" && message.contains("bias_dps")), "{err}");
        let err = from_pairs_on(&base, &pairs(&[("gyro_only", 0.5)])).unwrap_err();
        assert!(matches!(&err, Error::Param { name, .. } if name == "gyro_only"), "{err}");
        let err = from_pairs_on(&base, &pairs(&[("noise_dps", -1.0)])).unwrap_err();
        assert!(matches!(&err, Error::Param { name, .. } if name == "noise_dps"), "{err}");
    }

    #[test]
    fn errors_name_the_field() {
        let e = from_pairs::<HdrOptions>(&pairs(&[("gain", 1.0)])).unwrap_err();
        assert!(matches!(&e, Error::Param { name, message } if name == "gain" && message.contains("unknown field")), "{e}");
        let e = from_pairs::<HdrOptions>(&pairs(&[("bias_s", -1.0)])).unwrap_err();
        assert!(matches!(&e, Error::Param { name, .. } if name == "bias_s"), "{e}");
        let e = from_pairs::<HdrOptions>(&pairs(&[("i_c", f64::NAN)])).unwrap_err();
        assert!(matches!(&e, Error::Param { name, .. } if name == "i_c"), "{e}");
        let e = from_json::<HdrOptions>(serde_json::json!({"tau": 1.0, "c1": "x"})).unwrap_err();
        assert!(matches!(&e, Error::Param { name, .. } if name == "c1"), "{e}");
        assert!(from_json::<HdrOptions>(serde_json::json!(3)).is_err());
        assert_eq!(from_json::<HdrOptions>(Value::Null).unwrap(), HdrOptions::default());
    }
}
