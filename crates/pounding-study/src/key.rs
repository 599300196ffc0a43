//! The key of a run: a hash of its scenario in canonical form, so that the same run is recognised whatever
//! spelled it (a TOML file, a Python dict, a study's axis) and from whatever folder.

use serde_json::Value;

/// FNV-1a over 128 bits (offset basis and prime of the FNV specification): stable across platforms and
/// versions, which the key of a stored run must be. Not cryptographic: keys name runs, they guard nothing.
pub fn fnv1a_128(bytes: &[u8]) -> u128 {
    const OFFSET: u128 = 0x6c62272e07bb014262b821756295c58d;
    const PRIME: u128 = (1 << 88) + 0x13b;
    bytes
        .iter()
        .fold(OFFSET, |h, b| (h ^ u128::from(*b)).wrapping_mul(PRIME))
}

/// The identity of a list of runs: the hash of their keys, in order, in hexadecimal.
pub fn keys_id<S: AsRef<str>>(keys: &[S]) -> String {
    let joined: Vec<&str> = keys.iter().map(AsRef::as_ref).collect();
    format!("{:032x}", fnv1a_128(joined.join("\n").as_bytes()))
}

/// `value` as compact JSON with every object's keys sorted: the same text for the same content.
pub fn canonical(value: &Value) -> String {
    let mut out = String::new();
    write(value, &mut out);
    out
}

fn write(v: &Value, out: &mut String) {
    match v {
        Value::Object(m) => {
            let mut keys: Vec<&String> = m.keys().collect();
            keys.sort();
            out.push('{');
            for (i, k) in keys.into_iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push_str(&Value::String(k.clone()).to_string());
                out.push(':');
                write(&m[k], out);
            }
            out.push('}');
        }
        Value::Array(a) => {
            out.push('[');
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write(x, out);
            }
            out.push(']');
        }
        other => out.push_str(&other.to_string()),
    }
}

/// The key of `value`: 32 hexadecimal digits.
pub fn key_of(value: &Value) -> String {
    format!("{:032x}", fnv1a_128(canonical(value).as_bytes()))
}

/// The identity of a study from its definition `def` (its base, its axes or runs): `def-` and the hash of its
/// canonical form, with the folder `dir` (the study file's) taken out of every path, so that the identity
/// holds when the folder moves.
pub fn definition_id(def: &Value, dir: Option<&std::path::Path>) -> String {
    let mut text = canonical(def);
    if let Some(dir) = dir.filter(|d| !d.as_os_str().is_empty()) {
        let quoted = Value::String(format!("{}/", dir.display())).to_string();
        text = text.replace(&quoted[1..quoted.len() - 1], "");
    }
    format!("def-{:032x}", fnv1a_128(text.as_bytes()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_128_matches_the_published_test_vectors() {
        // FNV test suite (Fowler, Noll, Vo): FNV-1a 128 of "" is the offset basis, of "a" the value below.
        assert_eq!(fnv1a_128(b""), 0x6c62272e07bb014262b821756295c58d);
        assert_eq!(fnv1a_128(b"a"), 0xd228cb696f1a8caf78912b704e4a8964);
    }

    #[test]
    fn canonical_form_ignores_key_order() {
        let a: Value = serde_json::from_str(r#"{"b": 1, "a": {"y": [1, 2], "x": "s"}}"#).unwrap();
        let b: Value = serde_json::from_str(r#"{"a": {"x": "s", "y": [1, 2]}, "b": 1}"#).unwrap();
        assert_eq!(canonical(&a), r#"{"a":{"x":"s","y":[1,2]},"b":1}"#);
        assert_eq!(key_of(&a), key_of(&b));
    }
}
