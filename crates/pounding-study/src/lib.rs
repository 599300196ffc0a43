//! What the `pounding` command line and the Python package share, around the library's physics: scenarios read
//! from files or given as JSON values (Python dicts), the summary of a run, and studies: many scenarios (a base
//! and axes by dotted key path), run in parallel on threads, with a resumable SQLite store.
//!
//! The library (`pounding`) reads no files; this crate does, and never does physics.

pub mod format;
pub mod headline;
pub mod ida;
pub mod input;
pub mod key;
pub mod schema;
pub mod separation;
pub mod store;
pub mod study;
pub mod summary;
pub mod sweep;
pub mod tables;

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
