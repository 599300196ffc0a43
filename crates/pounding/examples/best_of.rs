//! Best-of-N wall time of whole runs, for comparing two builds of the library in one session on a noisy
//! machine: build this example in each tree (`cargo build --release --example best_of -p pounding`), run the
//! two binaries in turn a few times (`best_of 10`), and compare the smallest times. Prints one line per case:
//! name, best time (s), accepted steps. `best_of N PREFIX` runs only the cases whose name starts with PREFIX;
//! `SUMMARY_ONLY=1` runs without histories. Used for the cost of the step budgets (docs/performance.md).
use pounding::analysis::{Building, RunOptions, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::element::StoreyLaw;
use pounding::ground_motion::Record;
use pounding::structure::ShearBuilding;
use std::time::Instant;

fn building(name: &str, n: usize, m: f64, k: f64, law: Option<StoreyLaw>) -> Building {
    let mut s = ShearBuilding::new(vec![m; n], vec![k; n], vec![3.0; n], 0.05).unwrap();
    if let Some(l) = law {
        s = s.with_storey_laws(vec![l; n]).unwrap();
    }
    Building {
        name: name.into(),
        structure: s,
    }
}

fn pair(n: usize, model: Model, k_c: f64, law: Option<StoreyLaw>) -> Scenario {
    let (kl, kr) = (7.8957e7 * n as f64, 1.9739e7 * n as f64);
    let c = ContactModel::new(model, k_c, 0.65).unwrap();
    Scenario::new(
        vec![
            building("L", n, 5e5, kl, law),
            building("R", n, 5e5, kr, law),
        ],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_link("L", "R", 0.02, &c, None)
    .unwrap()
}

fn main() {
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    let bil = StoreyLaw::bilinear(2e5, 0.05).ok();
    let bw = StoreyLaw::bouc_wen(2e5, 0.05, 2.0, 0.5, 0.5).ok();
    let cases = [
        ("two_sdof/papi", pair(1, Model::Papi, 2e9, None)),
        ("two_sdof/hooke", pair(1, Model::Hooke, 2e9, None)),
        ("two_sdof/hertzdamp", pair(1, Model::Hertzdamp, 2e10, None)),
        ("storeys_10/papi", pair(10, Model::Papi, 2e9, None)),
        ("sdof/bilinear", pair(1, Model::Papi, 2e9, bil)),
        ("mdof_5/bilinear", pair(5, Model::Papi, 2e9, bil)),
        ("mdof_5/bouc-wen", pair(5, Model::Papi, 2e9, bw)),
    ];
    let only = std::env::args().nth(2);
    let summary = std::env::var("SUMMARY_ONLY").is_ok();
    let opts = if summary {
        RunOptions::summary_only()
    } else {
        RunOptions::default()
    };
    for (name, s) in &cases {
        if only.as_deref().is_some_and(|o| !name.starts_with(o)) {
            continue;
        }
        let mut best = f64::INFINITY;
        let mut steps = 0;
        for _ in 0..reps {
            let t = Instant::now();
            let r = s
                .run_with_options(&opts, &mut |_| std::ops::ControlFlow::Continue(()))
                .unwrap();
            best = best.min(t.elapsed().as_secs_f64());
            steps = r.statistics.steps;
        }
        println!("{name} {best:.6e} {steps}");
    }
}
