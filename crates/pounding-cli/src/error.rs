//! What can stop a command: bad input (exit code 2) or a failure to write output (exit code 1).

/// What can stop a command: bad input (exit code 2) or a failure to write output (exit code 1).
#[derive(Debug)]
pub enum CliError {
    /// Bad input: one line naming the parameter, the value and what is allowed.
    Input(String),
    /// An output could not be written.
    Io(String),
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
