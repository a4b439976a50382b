//! What a sweep's command line changes in its recipe, by the scenario file's names: any
//! parameter of the table ([`PARAMETERS`]), the step `dt`, the `duration`, and the area's
//! `side`; one value for every scenario ([`set`]) or a grid of values ([`Grid`]), each of its
//! points a group of the sweep.
//!
//! A value is read as the scenario file reads it (the parameters through the same
//! deserialiser), and the recipe is then checked by [`Recipe::check`], so that a value is
//! refused with the file reader's message.

use super::recipe::{Family, Recipe};
use crate::error::Error;
use crate::params::{Params, PARAMETERS};
use serde_json::Value;
use std::collections::BTreeMap;

/// The names a sweep sets besides the parameters of the table.
pub const RECIPE_NAMES: [&str; 3] = ["dt", "duration", "side"];

/// At most this many values on one axis of a grid.
pub const MAX_AXIS: usize = 1_000;

/// At most this many points in a grid (the product of its axes).
pub const MAX_POINTS: usize = 10_000;

/// Values by name, in the order of the names (a grid point, or the values set for every
/// scenario).
pub type Values = BTreeMap<String, Value>;

/// The JSON value `text` stands for on a command line: `none` or `null` for none, a number as
/// a number (an `f64`), other JSON as itself (`true`, `"paper"`), anything else as a string (a
/// mode such as `paper`, or text that the setting then refuses as the file reader would).
#[must_use]
pub fn value_of(text: &str) -> Value {
    let text = text.trim();
    if text == "none" || text == "null" {
        return Value::Null;
    }
    match serde_json::from_str::<Value>(text) {
        Ok(Value::Number(n)) => n.as_f64().map_or(Value::Null, Value::from),
        Ok(v) => v,
        Err(_) => Value::String(text.to_owned()),
    }
}

/// `name=value` for each of `values`, joined by `sep`: a string as written, `none` for a null
/// (how a command line gives them, and how messages and file names show a grid point).
#[must_use]
pub fn label(values: &Values, sep: &str) -> String {
    let text = |v: &Value| match v {
        Value::String(s) => s.clone(),
        Value::Null => "none".into(),
        v => v.to_string(),
    };
    let parts: Vec<String> = values
        .iter()
        .map(|(k, v)| format!("{k}={}", text(v)))
        .collect();
    parts.join(sep)
}

/// Sets `name` (a parameter of the table, `dt`, `duration` or `side`) of `recipe` to `value`.
///
/// # Errors
/// A name that is none of these, or a value of the wrong type, with the scenario file reader's
/// message (`params.k_a: invalid type: string "x", expected f64`); the formation family has no
/// `side`. Ranges are checked by [`Recipe::check`].
pub fn set(recipe: &mut Recipe, name: &str, value: &Value) -> Result<(), Error> {
    if PARAMETERS.iter().any(|p| p.name == name) {
        let mut params = serde_json::to_value(recipe.params).map_err(|e| Error::Parse {
            field: "params".into(),
            message: e.to_string(),
        })?;
        if let Some(map) = params.as_object_mut() {
            map.insert(name.to_owned(), value.clone());
        }
        recipe.params =
            serde_path_to_error::deserialize::<_, Params>(params).map_err(|e| Error::Parse {
                field: format!("params.{}", e.path()),
                message: e.into_inner().to_string(),
            })?;
        return Ok(());
    }
    let number = || {
        serde_json::from_value::<f64>(value.clone()).map_err(|e| Error::Parse {
            field: name.to_owned(),
            message: e.to_string(),
        })
    };
    match name {
        "dt" => recipe.dt = number()?,
        "duration" => recipe.duration = number()?,
        "side" if recipe.family == Family::Formation => {
            return Err(Error::Invalid {
                field: "side".into(),
                message: "the formation family has no area: its slots are placed from the spacing"
                    .into(),
            })
        }
        "side" => recipe.side = number()?,
        _ => {
            let names: Vec<String> = PARAMETERS
                .iter()
                .map(|p| p.name)
                .chain(RECIPE_NAMES)
                .map(|n| format!("`{n}`"))
                .collect();
            return Err(Error::Parse {
                field: name.to_owned(),
                message: format!(
                    "not a parameter of a sweep, expected one of {}",
                    names.join(", ")
                ),
            });
        }
    }
    Ok(())
}

/// `recipe` with every value of `values` set, checked ([`Recipe::check`]).
///
/// # Errors
/// See [`set`] and [`Recipe::check`].
pub fn with(recipe: &Recipe, values: &Values) -> Result<Recipe, Error> {
    let mut recipe = recipe.clone();
    for (name, value) in values {
        set(&mut recipe, name, value)?;
    }
    recipe.check()?;
    Ok(recipe)
}

/// One axis of a grid: a name and its values.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// The name (a parameter of the table, `dt`, `duration` or `side`).
    pub name: String,
    /// Its values, in the order given.
    pub values: Vec<Value>,
}

impl Axis {
    /// `NAME=a,b,c` (the values as [`value_of`] reads them) or `NAME=start:stop:step` (the
    /// numbers `start + k·step` up to `stop`, within a millionth of a step, each rounded to 12
    /// significant digits so that `0.1:0.5:0.1` gives 0.3 and not 0.30000000000000004).
    ///
    /// # Errors
    /// [`Error::Invalid`] for `grid` when the text is none of these, a range runs backwards or
    /// has a step that is not positive, or the axis has more than [`MAX_AXIS`] values.
    pub fn parse(text: &str) -> Result<Self, Error> {
        let bad = |message: String| Error::Invalid {
            field: "grid".into(),
            message,
        };
        let Some((name, list)) = text.split_once('=') else {
            return Err(bad(format!(
                "expected NAME=a,b,c or NAME=start:stop:step, not {text:?}"
            )));
        };
        let name = name.trim().to_owned();
        let parts: Vec<&str> = list.split(':').collect();
        let values = if parts.len() == 3 {
            let num = |t: &str| match t.trim().parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(x),
                _ => Err(bad(format!(
                    "{name}: expected start:stop:step of finite numbers, not {list:?}"
                ))),
            };
            let (start, stop, step) = (num(parts[0])?, num(parts[1])?, num(parts[2])?);
            if step <= 0.0 || stop < start {
                return Err(bad(format!(
                    "{name}: a range start:stop:step needs start ≤ stop and step > 0, not {list:?}"
                )));
            }
            let count = ((stop - start) / step + 1e-6).floor() + 1.0;
            if count > MAX_AXIS as f64 {
                return Err(bad(format!(
                    "{name}: at most {MAX_AXIS} values, not {count}"
                )));
            }
            (0..count as usize)
                .map(|k| {
                    let x = start + k as f64 * step;
                    format!("{x:.11e}")
                        .parse::<f64>()
                        .map_or(Value::Null, Value::from)
                })
                .collect()
        } else if parts.len() == 1 {
            list.split(',').map(value_of).collect::<Vec<_>>()
        } else {
            return Err(bad(format!(
                "{name}: expected a,b,c or start:stop:step, not {list:?}"
            )));
        };
        if values.len() > MAX_AXIS {
            return Err(bad(format!(
                "{name}: at most {MAX_AXIS} values, not {}",
                values.len()
            )));
        }
        Ok(Self { name, values })
    }
}

/// The points of a grid: every combination of its axes' values (the last axis varies
/// fastest), each point the values of all axes.
///
/// # Errors
/// [`Error::Invalid`] for `grid` when two axes have the same name or there are more than
/// [`MAX_POINTS`] points.
pub fn points(axes: &[Axis]) -> Result<Vec<Values>, Error> {
    let bad = |message: String| Error::Invalid {
        field: "grid".into(),
        message,
    };
    for (k, a) in axes.iter().enumerate() {
        if axes[..k].iter().any(|b| b.name == a.name) {
            return Err(bad(format!("{} is given twice", a.name)));
        }
    }
    let total = axes
        .iter()
        .try_fold(1_usize, |n, a| n.checked_mul(a.values.len()))
        .filter(|&n| n <= MAX_POINTS)
        .ok_or_else(|| bad(format!("at most {MAX_POINTS} points in all")))?;
    Ok((0..total)
        .map(|mut k| {
            let mut point = Values::new();
            for a in axes.iter().rev() {
                let n = a.values.len();
                point.insert(a.name.clone(), a.values[k % n].clone());
                k /= n;
            }
            point
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    fn axis(text: &str) -> Vec<Value> {
        Axis::parse(text).expect("an axis").values
    }

    #[test]
    fn values_read_as_the_file_reads_them() {
        assert_eq!(value_of("5"), Value::from(5.0));
        assert_eq!(value_of("none"), Value::Null);
        assert_eq!(value_of("paper"), Value::from("paper"));
        assert_eq!(value_of("\"paper\""), Value::from("paper"));
        assert_eq!(value_of("true"), Value::from(true));
        // A number serde_json cannot hold stays text, which the setting refuses.
        assert_eq!(value_of("1e400"), Value::from("1e400"));
        let mut r = Recipe::default();
        set(&mut r, "k_a", &value_of("5")).unwrap();
        set(&mut r, "v_max", &value_of("2")).unwrap();
        set(&mut r, "avoidance", &value_of("paper")).unwrap();
        set(&mut r, "barrier_rate", &value_of("none")).unwrap();
        set(&mut r, "dt", &value_of("0.005")).unwrap();
        set(&mut r, "side", &value_of("60")).unwrap();
        assert_eq!(
            (
                r.params.k_a,
                r.params.v_max,
                r.params.barrier_rate,
                r.dt,
                r.side
            ),
            (5.0, Some(2.0), None, 0.005, 60.0)
        );
        assert_eq!(r.params.avoidance, crate::params::Avoidance::Paper);
        let err = |name: &str, text: &str| {
            let mut r = Recipe::default();
            set(&mut r, name, &value_of(text))
                .and_then(|()| r.check())
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err("k_a", "x"),
            "params.k_a: invalid type: string \"x\", expected f64"
        );
        assert!(
            err("k_a", "-1").starts_with("params.k_a: "),
            "{}",
            err("k_a", "-1")
        );
        assert!(err("dt", "0.5").starts_with("dt: "), "{}", err("dt", "0.5"));
        assert!(
            err("side", "0").starts_with("side: "),
            "{}",
            err("side", "0")
        );
        let unknown = err("kv", "1");
        assert!(unknown.starts_with("kv: not a parameter"), "{unknown}");
        assert!(
            unknown.contains("`k_v`") && unknown.contains("`side`"),
            "{unknown}"
        );
        let mut f = Recipe::formation();
        assert!(set(&mut f, "side", &Value::from(50.0)).is_err());
    }

    #[test]
    fn axes_are_lists_or_ranges_and_points_their_product() {
        assert_eq!(axis("k_a=5,10"), [Value::from(5.0), Value::from(10.0)]);
        // 0.1 + 2·0.1 is 0.30000000000000004 in f64: the range gives the 0.3 a person typed.
        assert_eq!(
            axis("dt=0.1:0.5:0.1"),
            [0.1, 0.2, 0.3, 0.4, 0.5].map(Value::from)
        );
        assert_eq!(axis("side=50:60:20"), [Value::from(50.0)]);
        for bad in ["k_a", "k_a=5:1:1", "k_a=1:5:0", "k_a=1:2", "k_a=0:1e9:1"] {
            assert!(Axis::parse(bad).is_err(), "{bad}");
        }
        let axes = [
            Axis::parse("k_a=5,10,20").unwrap(),
            Axis::parse("avoidance=exit,paper").unwrap(),
        ];
        let p = points(&axes).unwrap();
        assert_eq!(p.len(), 6);
        assert_eq!(p[1]["k_a"], Value::from(5.0));
        assert_eq!(p[1]["avoidance"], Value::from("paper"));
        assert_eq!(p[2]["k_a"], Value::from(10.0));
        assert!(points(&[axes[0].clone(), axes[0].clone()]).is_err());
        assert_eq!(points(&[]).unwrap(), [Values::new()]);
    }
}
