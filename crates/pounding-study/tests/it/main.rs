//! Integration tests of `pounding-study`: one test binary, one module per subject.

mod messages;
mod plan;
mod schemas;
mod store;
