//! Ground-motion records: uniform-step accelerations in m/s^2, parsed from text (PEER AT2, two-column
//! time/acceleration, one value per line), the built-in 1940 El Centro N-S record, and peak ground
//! acceleration, velocity and displacement.
//!
//! The library reads text, never files: the caller passes the file's contents to [`Record::read`], which
//! detects the format ([`Format::detect`]: AT2 by its header, whatever the file's name) and takes the units
//! an AT2 header states (`ACCELERATION TIME SERIES IN UNITS OF G`) unless told otherwise, refusing units
//! that contradict the header. Units names (`g`, `m/s2`, `cm/s2`, `gal`, ...) are read by [`Units::parse`].

mod builtin;
pub mod coherency;
pub mod conditional;
mod format;
mod pair;
pub mod parse;
mod record;
pub mod spectrum;
pub mod synthetic;

pub use builtin::Builtin;
pub use format::{Format, ParseError, Units};
pub use pair::{on_one_grid, turned};
pub use record::{Peaks, Record, RecordError};
