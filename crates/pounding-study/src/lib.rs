//! What the `pounding` command line and the Python package share, around the library's physics: scenarios read
//! from files or given as JSON values (Python dicts), the summary of a run, and studies: many scenarios (a base
//! and axes by dotted key path), run in parallel on threads, with a resumable SQLite store.
//!
//! The library (`pounding`) reads no files; this crate does, and never does physics.

pub mod fit;
pub mod format;
pub mod headline;
pub mod ida;
pub mod input;
pub mod key;
pub mod schema;
pub mod separation;
pub mod shape;
pub mod store;
pub mod study;
pub mod summary;
pub mod sweep;
pub mod tables;

/// `msg` as one line of at most `max` characters, as every error is shown: control characters (a newline in
/// an axis name, a tab in a record's name) written as escapes, and a message longer than `max` cut with
/// ` ...` (a last resort: messages quote long values shortened where they are made).
pub fn one_line(msg: &str, max: usize) -> String {
    let mut out = String::with_capacity(msg.len().min(max));
    // Long names, lists and numbers written out in full are shortened first, keeping the rest whole.
    for c in pounding::words::compact(msg.trim_end()).chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    if out.chars().count() > max {
        out = out.chars().take(max.saturating_sub(4)).collect();
        out.push_str(" ...");
    }
    out
}

/// Bad input: one line that names the file and line (or the key's dotted path), the value and what is allowed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputError(pub String);

impl InputError {
    /// An error with this message.
    pub fn new(msg: impl Into<String>) -> Self {
        InputError(msg.into())
    }
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InputError {}

#[cfg(test)]
mod tests {
    #[test]
    fn one_line_escapes_control_characters_and_caps_the_length() {
        assert_eq!(
            super::one_line("axis \"a\nb\" names no key\n", 80),
            "axis \"a\\nb\" names no key"
        );
        let long = "x".repeat(400);
        let cut = super::one_line(&long, 292);
        assert_eq!(cut.chars().count(), 292);
        assert!(cut.ends_with(" ..."));
    }
}
