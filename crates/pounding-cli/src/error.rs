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

/// A map of errors for one impact set up by `options` (flag and value): scales outside
/// [`pounding::impact::SCALE_RANGE`] are said in the words of those options (`--m1 1e300, --m2 inf, --v 1 and
/// --k 1e9 are not allowed together: ...`), `with` saying how they make the mass `m` and the velocity `v`;
/// any other error as usual.
pub fn impact_scales<'a>(
    options: &'a [(&'a str, f64)],
    with: &'a str,
) -> impl Fn(pounding::Error) -> CliError + 'a {
    move |e| match e {
        pounding::Error::ScaleOutOfRange { .. } => {
            let shown: Vec<String> = options
                .iter()
                .map(|(name, v)| format!("--{name} {}", as_typed(*v)))
                .collect();
            let given = match shown.split_last() {
                Some((last, [])) => last.clone(),
                Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
                None => "the options".into(),
            };
            input(format!(
                "{given} are not allowed together: {with}, {}",
                pounding::impact::scales_allowed("m", "v")
            ))
        }
        other => other.into(),
    }
}

/// `x` as one would type it: its shortest text, in scientific notation from 1e6 on and under 1e-3 (`1e9`,
/// `3e10`, `2400`, `0.5`, `inf`).
fn as_typed(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-3..1e6).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Text given to an option as one would type it: as it is when short and plain (`--records kobe`), quoted
/// (and cut, over 64 characters) when it holds spaces, quotes or control characters or is long.
pub fn as_typed_text(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars().count() <= 64
        && !s
            .chars()
            .any(|c| c.is_whitespace() || c.is_control() || c == '"' || c == '\'');
    if plain {
        s.to_string()
    } else {
        pounding::words::quoted(s, 64)
    }
}
