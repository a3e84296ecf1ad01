//! Conversions between JS values and core types: errors, option objects, result objects,
//! typed arrays.

use crate::JsResult;
use js_sys::{Float64Array, Object, Reflect, Uint8Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A JS `TypeError` with the message: an argument of the wrong type.
pub(crate) fn type_err(msg: impl std::fmt::Display) -> JsValue {
    js_sys::TypeError::new(&msg.to_string()).into()
}

/// A string argument, or a `TypeError` naming it (wasm-bindgen's own `&str` glue would trap
/// on a number or an object and kill the module).
pub(crate) fn js_string(v: &JsValue, what: &str) -> JsResult<String> {
    v.as_string().ok_or_else(|| type_err(format!("{what}: expected a string")))
}

/// The most bytes a log may have in the page: above it, an error before any copy.
pub(crate) const MAX_LOG_BYTES: f64 = (1u64 << 30) as f64;

/// A byte-array argument (Uint8Array or ArrayBuffer) copied into wasm memory, its size
/// checked first; a `TypeError` for anything else.
pub(crate) fn js_bytes(v: &JsValue, what: &str) -> JsResult<Vec<u8>> {
    let arr = if let Some(a) = v.dyn_ref::<js_sys::Uint8Array>() {
        a.clone()
    } else if let Some(b) = v.dyn_ref::<js_sys::ArrayBuffer>() {
        js_sys::Uint8Array::new(b)
    } else {
        return Err(type_err(format!("{what}: expected a Uint8Array or an ArrayBuffer")));
    };
    let n = arr.length() as f64;
    if n > MAX_LOG_BYTES {
        return Err(err(format!(
            "{what}: {n} bytes is more than the {} MiB a log may have here; split the log",
            MAX_LOG_BYTES / 1048576.0
        )));
    }
    Ok(arr.to_vec())
}

/// A JS `Error` with the message.
pub(crate) fn err(msg: impl std::fmt::Display) -> JsValue {
    js_sys::Error::new(&msg.to_string()).into()
}

/// A parser's refusal as a JS `Error`, its `code` the refusal's kind where another way of
/// reading mends it (core's `accept::Refusal`: "time_order", "clock_reset", "joined",
/// "cut_row", "foreign"), so the page offers that way without matching the message's words.
pub(crate) fn refusal(e: gyrodrift::Error) -> JsValue {
    let code = gyrodrift::log::accept::Refusal::of(&e).map(|r| r.code());
    let out = err(e);
    if let Some(code) = code {
        let _ = Reflect::set(&out, &"code".into(), &code.into());
    }
    out
}

/// A table's refusal of the log `name` that `check` finds an error in: a JS `Error` with
/// `code: "check"` and `log: name`, so a front offers that log's fix or `ignore_check`.
pub(crate) fn check_refusal(name: &str, message: String) -> JsValue {
    let out = err(message);
    let _ = Reflect::set(&out, &"code".into(), &gyrodrift::log::accept::Refusal::Check.code().into());
    let _ = Reflect::set(&out, &"log".into(), &name.into());
    out
}

/// Options from JS: undefined/null = all defaults; otherwise read by core's one schema
/// (`options::from_json`: the structs' serde with their aliases, then their `validate`),
/// which names an unknown or mistyped field. JSON has no NaN, so a non-finite number is
/// refused here, by name, before the conversion could turn it into "absent".
pub(crate) fn options<T: gyrodrift::options::Settings>(what: &str, value: JsValue) -> JsResult<T> {
    if value.is_undefined() || value.is_null() {
        return Ok(T::default());
    }
    let what = format!("{what} options");
    gyrodrift::options::from_json(js_json(&what, &value)?).map_err(|e| err(format!("{what}: {e}")))
}

/// A JS object as JSON, for core's serde (which, unlike serde-wasm-bindgen's struct reader,
/// sees every key, so unknown fields are refused). A non-object is a `TypeError`; a
/// non-finite number is refused by name, since JSON would turn it into "absent".
pub(crate) fn js_json(what: &str, value: &JsValue) -> JsResult<serde_json::Value> {
    let obj: &Object = value.dyn_ref().filter(|_| value.is_object()).ok_or_else(|| type_err(format!("{what}: expected an object")))?;
    reject_non_finite(what, obj, "")?;
    serde_wasm_bindgen::from_value(value.clone()).map_err(|e| err(format!("{what}: {}", js_message(e))))
}

/// An error naming the first non-finite number in an options object or recipe (at any
/// depth, arrays included), as `what: path: value`.
pub(crate) fn reject_non_finite(what: &str, obj: &Object, prefix: &str) -> JsResult<()> {
    for key in Object::keys(obj).iter() {
        let name = format!("{prefix}{}", key.as_string().unwrap_or_default());
        let v = Reflect::get(obj, &key).unwrap_or(JsValue::UNDEFINED);
        if let Some(x) = v.as_f64() {
            if !x.is_finite() {
                return Err(err(format!("{what}: {name}: {x} is not a finite number")));
            }
        } else if v.is_object() {
            if let Some(inner) = v.dyn_ref::<Object>() {
                reject_non_finite(what, inner, &format!("{name}."))?;
            }
        }
    }
    Ok(())
}

/// The message of a serde-wasm-bindgen error (a JS Error underneath).
pub(crate) fn js_message(e: serde_wasm_bindgen::Error) -> String {
    let v: JsValue = e.into();
    v.dyn_ref::<js_sys::Error>().map(|e| String::from(e.message())).unwrap_or_else(|| format!("{v:?}"))
}

/// A plain JS object (structs as objects, not Maps).
pub(crate) fn to_js<T: Serialize>(value: &T) -> JsResult<JsValue> {
    let ser = serde_wasm_bindgen::Serializer::new().serialize_maps_as_objects(true);
    value.serialize(&ser).map_err(err)
}

/// A plain JS object, or null for None.
pub(crate) fn to_js_or_null<T: Serialize>(value: &Option<T>) -> JsResult<JsValue> {
    value.as_ref().map_or(Ok(JsValue::NULL), to_js)
}

pub(crate) fn set(obj: &Object, key: &str, value: &JsValue) -> JsResult<()> {
    Reflect::set(obj, &JsValue::from_str(key), value).map(|_| ())
}

pub(crate) fn f64s(v: &[f64]) -> JsValue {
    Float64Array::from(v).into()
}

pub(crate) fn bools(v: &[bool]) -> JsValue {
    let bytes: Vec<u8> = v.iter().map(|&b| b as u8).collect();
    Uint8Array::from(&bytes[..]).into()
}

/// A JS object of named values (a trace: Float64Array series and Uint8Array flags).
pub(crate) fn object_of(fields: &[(&str, JsValue)]) -> JsResult<Object> {
    let out = Object::new();
    for (name, v) in fields {
        set(&out, name, v)?;
    }
    Ok(out)
}

/// A JS object of named Float64Array series (a trace, a reference, error series).
pub(crate) fn series(fields: &[(&str, &[f64])]) -> JsResult<Object> {
    let out = Object::new();
    for (name, v) in fields {
        set(&out, name, &f64s(v))?;
    }
    Ok(out)
}
