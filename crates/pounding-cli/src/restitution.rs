//! What a command-line contact is asked to deliver: `--e`, `--e-table FILE` (e against the impact velocity)
//! or `--damping-constant` (a Hunt–Crossley material's D/K), one of them.

use crate::error::{input, CliError};
use crate::output::fmt_num;
use pounding::contact::{Model, Restitution, RestitutionTable};
use std::path::Path;

/// The table of `path`: one row per line, `v_i` (m/s) and `e` separated by a comma or spaces; blank lines
/// and lines from `#` are skipped, and so is a first line that is not numbers (a header).
pub fn read_e_table(path: &Path) -> Result<RestitutionTable, CliError> {
    let shown = path.display();
    // An input file that cannot be read is bad input, as a scenario or record file is (exit 2).
    let text = pounding_study::input::read_text_file(
        path,
        "--e-table",
        pounding_study::input::DATA_FILE_LIMIT,
    )
    .map_err(input)?;
    let rows = pounding_study::fit::pairs(&text)
        .map_err(|e| input(format!("--e-table {shown}: {e} (v_i in m/s, then e)")))?;
    RestitutionTable::new(rows).map_err(|e| input(format!("--e-table {shown}: {e}")))
}

/// What `model` is asked to deliver from `--e`, `--e-table` and `--damping-constant`: at most one of them;
/// an elastic model takes none (or `--e 1`), a damped one needs one.
pub fn asked(
    model: Model,
    e: Option<f64>,
    e_table: Option<&Path>,
    damping_constant: Option<f64>,
) -> Result<Restitution, CliError> {
    let given = usize::from(e.is_some())
        + usize::from(e_table.is_some())
        + usize::from(damping_constant.is_some());
    if given > 1 {
        return Err(input(
            "--e, --e-table and --damping-constant are not allowed together: give one (the e to deliver, a table of it against v_i, or a material's D/K)",
        ));
    }
    let name = model.name();
    if let Some(why) = model.asks_no_e() {
        return match (e, e_table, damping_constant) {
            (Some(e), _, _) if e != 1.0 => Err(input(format!(
                "--e {} is not allowed with model {name}: {why} (leave --e out, or choose a damped model, see pounding models)",
                fmt_num(e)
            ))),
            (_, None, None) => Ok(Restitution::Constant(1.0)),
            _ => Err(input(format!(
                "--e-table and --damping-constant are not allowed with model {name}: {why}"
            ))),
        };
    }
    match (e, e_table, damping_constant) {
        (Some(e), _, _) => Ok(Restitution::Constant(e)),
        (_, Some(path), _) => read_e_table(path).map(Restitution::Table),
        (_, _, Some(c)) => Ok(Restitution::DampingConstant(c)),
        (None, None, None) => Err(input(format!(
            "--e is required by model {name}: the coefficient of restitution it is to deliver, 0 < e <= 1 (or --e-table FILE, or --damping-constant for the Hunt-Crossley family)"
        ))),
    }
}
