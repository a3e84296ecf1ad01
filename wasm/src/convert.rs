//! Conversions between JS values and core types: errors, option objects, result objects,
//! typed arrays.

use crate::JsResult;
use js_sys::{Float64Array, Object, Reflect, Uint8Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A JS `Error` with the message.
pub(crate) fn err(msg: impl std::fmt::Display) -> JsValue {
    js_sys::Error::new(&msg.to_string()).into()
}

/// Options from JS: undefined/null = all defaults; otherwise read by core's one schema
/// (`options::from_json`: the structs' serde with their aliases, then their `validate`),
/// which names an unknown or mistyped field. JSON has no NaN, so a non-finite number is
/// refused here, by name, before the conversion could turn it into "absent".
pub(crate) fn options<T: gyrodrift::options::Settings>(what: &str, value: JsValue) -> JsResult<T> {
    if value.is_undefined() || value.is_null() {
        return Ok(T::default());
    }
    let obj: &Object = value.dyn_ref().filter(|_| value.is_object()).ok_or_else(|| err(format!("{what} options: expected an object")))?;
    reject_non_finite(what, obj, "")?;
    let json: serde_json::Value =
        serde_wasm_bindgen::from_value(value.clone()).map_err(|e| err(format!("{what} options: {}", js_message(e))))?;
    gyrodrift::options::from_json(json).map_err(|e| err(format!("{what} options: {e}")))
}

/// An error naming the first non-finite number of an options object (one level of nesting).
pub(crate) fn reject_non_finite(what: &str, obj: &Object, prefix: &str) -> JsResult<()> {
    for key in Object::keys(obj).iter() {
        let name = format!("{prefix}{}", key.as_string().unwrap_or_default());
        let v = Reflect::get(obj, &key).unwrap_or(JsValue::UNDEFINED);
        if let Some(x) = v.as_f64() {
            if !x.is_finite() {
                return Err(err(format!("{what} options: {name}: {x} is not a finite number")));
            }
        } else if let (Some(inner), true) = (v.dyn_ref::<Object>(), prefix.is_empty() && v.is_object()) {
            reject_non_finite(what, inner, &format!("{name}."))?;
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

/// A JS object of named Float64Array series (a trace, a reference, error series).
pub(crate) fn series(fields: &[(&str, &[f64])]) -> JsResult<Object> {
    let out = Object::new();
    for (name, v) in fields {
        set(&out, name, &f64s(v))?;
    }
    Ok(out)
}
