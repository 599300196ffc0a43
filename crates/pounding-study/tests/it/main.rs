//! Integration tests of `pounding-study`: one test binary, one module per subject.

mod messages;
mod names;
mod plan;
mod schemas;
mod store;
