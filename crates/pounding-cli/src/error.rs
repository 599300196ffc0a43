//! What can stop a command: bad input (exit code 2), a failure to write output (exit code 1), runs of a
//! study that failed (exit code 3), or Ctrl-C (exit code 130).

/// What can stop a command: bad input (exit code 2), a failure to write output (exit code 1), runs of a
/// study that failed (exit code 3), or Ctrl-C (exit code 130).
#[derive(Debug)]
pub enum CliError {
    /// Bad input: one line naming the parameter, the value and what is allowed.
    Input(String),
    /// An output could not be written.
    Io(String),
    /// Ctrl-C stopped the work: what was kept.
    Interrupted(String),
    /// A study finished with failed runs: how many, and where to read why (what succeeded is written).
    Failed(String),
}

impl From<pounding::Error> for CliError {
    fn from(e: pounding::Error) -> Self {
        match e {
            pounding::Error::Parameter {
                name,
                value,
                allowed,
            } => CliError::Input(format!(
                "--{} {value} is not allowed: {allowed}",
                name.replace('_', "-")
            )),
            pounding::Error::Cancelled { t } => CliError::Interrupted(format!(
                "the run stopped at t = {t:.3} s; nothing was written"
            )),
            pounding::Error::Interrupted { what } => {
                CliError::Interrupted(format!("the {what} stopped; nothing was written"))
            }
            other => CliError::Input(other.to_string()),
        }
    }
}

/// Bad input, with this message.
pub fn input(msg: impl Into<String>) -> CliError {
    CliError::Input(msg.into())
}

/// An option as the command line spells it in messages: `--max-penetration`.
pub fn flag(key: &str) -> String {
    format!("--{key}")
}
