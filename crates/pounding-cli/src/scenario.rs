//! Scenario files: read, parsed and validated by `pounding_study::input` (the schema is the library's), so the
//! command line and the Python package say the same thing about the same file.

use crate::error::CliError;
pub use pounding_study::input::Loaded;
use std::path::Path;

/// Reads and validates the scenario file at `path`: the loaded scenario and the file's text.
pub fn load(path: &Path) -> Result<(Loaded, String), CliError> {
    let file = pounding_study::input::ScenarioFile::read(path).map_err(|e| CliError::Input(e.0))?;
    let loaded = file.load().map_err(|e| CliError::Input(e.0))?;
    Ok((loaded, file.text))
}
