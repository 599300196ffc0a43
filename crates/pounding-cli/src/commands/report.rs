//! `pounding report DIR`: the HTML report of a run's output folder, from its files alone.

use crate::args::ReportArgs;
use crate::error::CliError;
use crate::run_data::RunData;

/// `pounding report DIR [--out FILE]`.
pub fn run(a: &ReportArgs) -> Result<(), CliError> {
    if !a.dir.is_dir() {
        return Err(CliError::Input(format!(
            "{} is not a folder (give the --out folder of `pounding run`)",
            a.dir.display()
        )));
    }
    let out = a.out.clone().unwrap_or_else(|| a.dir.join("report.html"));
    if out.is_dir() {
        return Err(CliError::Input(format!(
            "--out {} is a folder; give a file name such as report.html",
            out.display()
        )));
    }
    crate::output_set::verify(&a.dir)
        .map_err(|m| CliError::Input(format!("{}: {m}", a.dir.display())))?;
    let data = RunData::load(&a.dir)?;
    let figs = crate::plot::figures::run(&data);
    let name = crate::report::write(&data, &figs, &out)?;
    println!("wrote {}", out.with_file_name(name).display());
    Ok(())
}
