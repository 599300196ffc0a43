//! Ground motions named on the command line: a built-in record, or a file read as scenario files read
//! theirs.

use crate::args::RecordArgs;
use crate::error::{flag, input, CliError};
use pounding::ground_motion::{Format, Record, Units};
use pounding::scenario::FormatName;

/// Loads the ground motion `a` describes: a built-in record by name, or a file in the given format.
pub fn load_record(a: &RecordArgs) -> Result<Record, CliError> {
    load_record_from(&a.file, a.format, a.dt, a.units, a.scale)
}

/// Loads a built-in record called `source`, or the file at `source` in `format` (default: detected, AT2 by
/// its header or a `*.at2` name, time-acc otherwise), with values in `units` (default: an AT2 header's,
/// else g) multiplied by `scale`.
pub fn load_record_from(
    source: &str,
    format: Option<FormatName>,
    dt: Option<f64>,
    units: Option<Units>,
    scale: f64,
) -> Result<Record, CliError> {
    let name = flag;
    let is_file = pounding::ground_motion::Builtin::from_name(source).is_none();
    // The options are checked here, in the command line's words; reading is the scenarios' own.
    let format = match (format, dt) {
        // A built-in record carries its own format.
        _ if !is_file => None,
        (Some(FormatName::Values), Some(dt)) => Some(Format::Values { dt }),
        (Some(FormatName::Values), None) => {
            return Err(input(format!(
                "{} values needs {} (the time step, s)",
                name("format"),
                name("dt")
            )))
        }
        (Some(FormatName::At2), _) => Some(Format::At2),
        (Some(FormatName::TimeAcc), _) => Some(Format::TimeAcc),
        (None, _) => None,
    };
    if is_file && dt.is_some() && !matches!(format, Some(Format::Values { .. })) {
        return Err(input(format!(
            "{} applies to {} values only (other formats carry their time step)",
            name("dt"),
            name("format")
        )));
    }
    let spec = pounding::scenario::RecordSpec {
        source: source.to_string(),
        is_file,
        format,
        units,
        scale,
    };
    let record = pounding_study::input::read_record(&spec).map_err(|e| match e {
        pounding::ground_motion::RecordError::Value(v) => CliError::from(v),
        parse => input(pounding_study::input::record_message(&spec, parse)),
    })?;
    record.scaled(scale).map_err(CliError::from)
}
