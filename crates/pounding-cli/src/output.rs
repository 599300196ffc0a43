//! Presentation: key-value reports printed as aligned text or as one JSON object, and numbers for people.

use serde_json::{Map, Value};

/// An ordered list of named values with units, rendered as text or JSON from the same source.
#[derive(Default)]
pub struct Report {
    rows: Vec<(String, Value, &'static str)>,
    text: Vec<Option<String>>,
}

impl Report {
    /// Adds `key = value` with `unit` (shown in text output; the JSON key carries no unit, documented).
    pub fn add(&mut self, key: &str, value: impl Into<Value>, unit: &'static str) -> &mut Self {
        self.rows.push((key.to_string(), value.into(), unit));
        self.text.push(None);
        self
    }

    /// Adds a value shown as `text` in text output and as `value` in JSON.
    pub fn add_shown(
        &mut self,
        key: &str,
        value: Value,
        text: String,
        unit: &'static str,
    ) -> &mut Self {
        self.add(key, value, unit);
        *self.text.last_mut().expect("just pushed") = Some(text);
        self
    }

    /// The report as one JSON object (keys in insertion order).
    pub fn json(&self) -> Value {
        Value::Object(
            self.rows
                .iter()
                .map(|(k, v, _)| (k.clone(), v.clone()))
                .collect::<Map<_, _>>(),
        )
    }

    /// Prints the report on stdout: JSON, or one aligned line per value.
    pub fn print(&self, json: bool) {
        if json {
            println!("{}", self.json());
            return;
        }
        let width = self.rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
        for ((k, v, unit), shown) in self.rows.iter().zip(&self.text) {
            let text = match v {
                _ if shown.is_some() => shown.clone().unwrap_or_default(),
                Value::String(s) => s.clone(),
                Value::Null => "-".to_string(),
                Value::Number(n) => match n.as_f64() {
                    Some(x) if n.is_f64() => fmt_num(x),
                    _ => n.to_string(),
                },
                other => other.to_string(),
            };
            if unit.is_empty() {
                println!("{k:width$}  {text}");
            } else {
                println!("{k:width$}  {text} {unit}");
            }
        }
    }
}

/// A finite number as JSON, or null (JSON has no infinity or NaN).
pub fn num(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

pub use pounding_study::format::{fmt_num, fmt_sig};

/// `x` with about `sig` significant digits in plain ASCII notation (no exponent, fixed decimals, at most 6), for
/// the terminal's tables; a value that rounds to zero is `0`, never `-0.000`. (The figures and the report use
/// `plot::axis::plain`, with typographic minus and powers of ten.)
pub fn fmt_table(x: f64, sig: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x == 0.0 { "0".into() } else { fmt_num(x) };
    }
    let decimals = (sig - 1 - x.abs().log10().floor() as i32).clamp(0, 6) as usize;
    let text = format!("{x:.decimals$}");
    // -0.000 reads as a sign error; a value that rounds to zero is 0.
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".into()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_twelve_significant_digits() {
        assert_eq!(fmt_num(0.65), "0.65");
        assert_eq!(fmt_num(0.6499999999873285), "0.649999999987");
        assert_eq!(fmt_num(1.0e7), "1e7");
        assert_eq!(fmt_num(9.782715214245265e6), "9.78271521425e6");
        assert_eq!(fmt_num(123.456), "123.456");
    }

    #[test]
    fn table_numbers_are_plain_and_never_negative_zero() {
        assert_eq!(fmt_table(22756.7, 4), "22757");
        assert_eq!(fmt_table(9.1524, 4), "9.152");
        assert_eq!(fmt_table(0.0399, 4), "0.03990");
        assert_eq!(fmt_table(-3.2e-10, 4), "0");
        assert_eq!(fmt_table(-0.0, 4), "0");
        assert_eq!(fmt_table(-12.345, 3), "-12.3");
    }
}
