//! The commands, one module each: validated inputs in, library calls, outputs out.

mod compare;
mod fit;
mod ida;
mod impact;
mod models;
mod paper;
mod record;
mod report;
mod run;
mod separation;
mod sweep;

use crate::args::Command;
use crate::error::CliError;

/// Runs one command.
pub fn run(cmd: Command) -> Result<(), CliError> {
    match cmd {
        Command::Models { json } => models::run(json),
        Command::Impact(a) => impact::impact(&a),
        Command::Calibrate(a) => impact::calibrate(&a),
        Command::Drop(a) => impact::drop(&a),
        Command::Compare(a) => compare::run(&a),
        Command::Run(a) => run::run(&a),
        Command::Sweep(a) => sweep::run(&a),
        Command::Ida(a) => ida::run(&a),
        Command::Separation(a) => separation::run(&a),
        Command::Report(a) => report::run(&a),
        Command::Record { cmd } => record::run(cmd),
        Command::Fit { cmd } => fit::run(cmd),
        Command::Paper { table } => paper::run(table),
    }
}
