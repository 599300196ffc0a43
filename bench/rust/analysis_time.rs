//! Times the analysis alone of scenario files, as `pounding run` does it (`Scenario::run_with`, histories
//! at `output_dt` in memory, no files): for each file, the median and the best of `--repeat` runs in this
//! process after one warm-up run, printed as one JSON line per file. `bench/run/bench.py` runs it beside the
//! whole command, in one session, and builds it against an older commit too.
//!
//!     cargo run --release --manifest-path bench/rust/Cargo.toml --bin analysis-time -- [--repeat N]
//!         [--stepping] [--summary-only] FILE...
//!
//! `--summary-only` runs as a study's runs do (`RunOptions::summary_only`: no histories, the summary alone).
//! `--stepping` runs every scenario with `[analysis] propagation = "stepping"` (the adaptive stepper
//! throughout) instead of its own setting: the same binary times both ways.

use std::ops::ControlFlow;
use std::time::Instant;

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut repeat = 20;
    if let Some(i) = args.iter().position(|a| a == "--repeat") {
        repeat = args[i + 1].parse().expect("--repeat N");
        args.drain(i..i + 2);
    }
    let stepping = args.iter().any(|a| a == "--stepping");
    args.retain(|a| a != "--stepping");
    let summary_only = args.iter().any(|a| a == "--summary-only");
    args.retain(|a| a != "--summary-only");
    let options = if summary_only {
        pounding::analysis::RunOptions::summary_only()
    } else {
        pounding::analysis::RunOptions::default()
    };
    for file in &args {
        let loaded = pounding_study::input::ScenarioFile::read(std::path::Path::new(file))
            .and_then(|f| f.load())
            .unwrap_or_else(|e| panic!("{file}: {e:?}"));
        let s = &if stepping {
            loaded
                .scenario
                .clone()
                .with_propagation(pounding::engine::Propagation::Stepping)
        } else {
            loaded.scenario.clone()
        };
        let mut steps = 0;
        let mut times = Vec::with_capacity(repeat);
        for k in 0..=repeat {
            let t0 = Instant::now();
            let r = s
                .run_with_options(&options, &mut |_| ControlFlow::Continue(()))
                .expect("the analysis runs");
            let dt = t0.elapsed().as_secs_f64();
            steps = r.statistics.steps;
            if k > 0 {
                times.push(dt);
            }
            std::hint::black_box(r);
        }
        times.sort_by(f64::total_cmp);
        println!(
            "{{\"file\": {file:?}, \"median_s\": {}, \"best_s\": {}, \"steps\": {steps}}}",
            times[times.len() / 2],
            times[0]
        );
    }
}
