//! The one place where values cross the boundary: JS numbers to checked counts and indices,
//! JS objects or JSON text to scenarios, the core's errors to JS `Error`s, Rust values to plain
//! JS objects.

use crate::error::Error;
use crate::scenario::Scenario;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A whole number in `0..=max` from a JS number; NaN, infinities, negatives and fractions are
/// errors naming `field`.
pub(crate) fn whole(field: &str, v: f64, max: usize) -> Result<usize, JsError> {
    if v.is_finite() && v >= 0.0 && v.fract() == 0.0 && v <= max as f64 {
        Ok(v as usize)
    } else {
        Err(JsError::new(&format!(
            "{field}: must be a whole number from 0 to {max}, not {v}"
        )))
    }
}

/// A scenario from a JS object or from JSON text, parsed and validated.
///
/// An object goes through `JSON.stringify` and [`Scenario::from_json`] rather than straight
/// through serde-wasm-bindgen, whose struct deserialiser looks up the known keys only and so
/// would silently ignore a misspelt one (`{"params": {"kv": 1}}`). Objects and text thus get
/// the same checks and the same messages. JSON has no NaN or infinity: such a number arrives
/// as `null` and is reported as a type error at its field.
pub(crate) fn scenario_from_js(value: JsValue) -> Result<Scenario, Error> {
    if let Some(text) = value.as_string() {
        return Scenario::from_json(&text);
    }
    if !value.is_object() || js_sys::Array::is_array(&value) {
        return Err(Error::Parse {
            field: String::new(),
            message: "expected an object with a \"robots\" list (or its JSON text)".into(),
        });
    }
    let text = js_sys::JSON::stringify(&value)
        .ok()
        .and_then(|t| t.as_string())
        .ok_or_else(|| Error::Parse {
            field: String::new(),
            message: "the object cannot be written as JSON (a cycle, a BigInt or a function?)"
                .into(),
        })?;
    Scenario::from_json(&text)
}

/// The one conversion from the core's errors to JS `Error`s.
pub(crate) fn js_error(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

/// Serialises to a plain JS value: `None` as `null`, maps as objects.
pub(crate) fn to_js<T: Serialize + ?Sized>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&e.to_string()))
}
