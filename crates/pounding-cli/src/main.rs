//! The `pounding` command-line tool: configuration, I/O and presentation around the `pounding` library.

mod args;
mod commands;
mod describe;
mod error;
mod files;
mod interrupt;
mod output;
mod output_set;
mod plot;
mod progress;
mod records;
mod report;
mod restitution;
mod run_data;
mod scenario;

use clap::Parser;
use error::CliError;
use std::process::ExitCode;

/// The command the arguments name, as far as they name one: `pounding`, `pounding run`,
/// `pounding record spectrum`.
fn command_path() -> Vec<String> {
    use clap::CommandFactory;
    let mut cmd = args::Cli::command();
    let mut path = vec!["pounding".to_string()];
    for word in std::env::args().skip(1) {
        let Some(sub) = cmd.find_subcommand(&word).cloned() else {
            break;
        };
        path.push(word);
        cmd = sub;
    }
    path
}

fn main() -> ExitCode {
    // A reader that stops early (`pounding ... | head`) closes stdout; `println!` then panics. End quietly
    // with the status a shell expects from SIGPIPE instead.
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let msg = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .unwrap_or("");
        if msg.contains("Broken pipe") {
            std::process::exit(141);
        }
        default_hook(info);
    }));
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                print!("{e}");
                return ExitCode::SUCCESS;
            }
            if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                eprint!("{}", e.render());
                return ExitCode::from(2);
            }
            // One line: clap's first line names the option, the value and what is allowed.
            // (A missing-argument error lists the arguments on the indented lines that follow.)
            let text = e.render().to_string();
            let mut lines = text.lines();
            let mut line = lines
                .next()
                .unwrap_or("error: invalid arguments")
                .trim_end()
                .to_string();
            for more in lines.take_while(|l| l.starts_with("  ")) {
                line.push(' ');
                line.push_str(more.trim());
            }
            eprintln!("{line} (see {} --help)", command_path().join(" "));
            return ExitCode::from(2);
        }
    };
    interrupt::install();
    match commands::run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        // One line under 300 characters, whatever the message quotes.
        Err(CliError::Input(msg)) => {
            eprintln!("error: {}", pounding_study::one_line(&msg, 292));
            ExitCode::from(2)
        }
        Err(CliError::Io(msg)) => {
            eprintln!("error: {}", pounding_study::one_line(&msg, 292));
            ExitCode::from(1)
        }
        Err(CliError::Failed(msg)) => {
            eprintln!("error: {}", pounding_study::one_line(&msg, 292));
            ExitCode::from(3)
        }
        Err(CliError::Interrupted(msg)) => {
            eprintln!("interrupted: {}", pounding_study::one_line(&msg, 286));
            ExitCode::from(interrupt::EXIT_CODE)
        }
    }
}
