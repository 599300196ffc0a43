//! Whole runs from bytes: rows of one to three buildings of one to four storeys (linear, bilinear or
//! Bouc–Wen), any contact model between neighbours, gap 0 included, El Centro scaled, under a small work
//! budget. A run ends in finite results, or in a one-line error that is a refusal or the budget; never a
//! panic, a chatter or a non-finite result.
#![no_main]

use libfuzzer_sys::fuzz_target;
use pounding::analysis::{Building, RunOptions, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::element::StoreyLaw;
use pounding::ground_motion::Record;
use pounding::structure::ShearBuilding;
use pounding::Error;
use std::ops::ControlFlow;

/// Numbers in [0, 1) read two bytes at a time (0 once the input runs out).
struct Reader<'a>(&'a [u8]);

impl Reader<'_> {
    fn unit(&mut self) -> f64 {
        let v = match self.0 {
            [a, b, rest @ ..] => {
                let v = u16::from_le_bytes([*a, *b]);
                self.0 = rest;
                v
            }
            _ => 0,
        };
        v as f64 / 65536.0
    }
    /// 10^x for x in [lo, hi).
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(lo + (hi - lo) * self.unit())
    }
    fn index(&mut self, n: usize) -> usize {
        ((self.unit() * n as f64) as usize).min(n - 1)
    }
}

fn scenario(r: &mut Reader) -> Result<Scenario, Error> {
    let mut buildings = Vec::new();
    for i in 0..1 + r.index(3) {
        let n = 1 + r.index(4);
        let (mut m, mut k, mut laws) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..n {
            let (mi, ki) = (r.log(0.0, 8.0), r.log(3.0, 12.0));
            let f_y = ki * r.log(-5.0, 0.0);
            let a = 0.6 * r.unit();
            laws.push(match r.index(3) {
                0 => StoreyLaw::Linear,
                1 => StoreyLaw::bilinear(f_y, a)?,
                _ => {
                    let beta = r.unit();
                    StoreyLaw::bouc_wen(f_y, a, 1.0 + 4.0 * r.unit(), beta, 1.0 - beta)?
                }
            });
            m.push(mi);
            k.push(ki);
        }
        let structure =
            ShearBuilding::new(m, k, vec![3.0; n], 0.3 * r.unit())?.with_storey_laws(laws)?;
        buildings.push(Building {
            name: format!("b{i}"),
            structure,
        });
    }
    let count = buildings.len();
    let record = Record::el_centro_1940().scaled(r.log(-3.0, 1.5))?;
    let mut s = Scenario::new(buildings, record)?.with_duration(0.05 + 2.0 * r.unit())?;
    let models: Vec<Model> = Model::all().collect();
    for i in 0..count - 1 {
        let model = models[r.index(models.len())];
        let c = ContactModel::new(model, r.log(3.0, 15.0), 0.001 + 0.999 * r.unit())?;
        let gap = if r.unit() < 0.3 {
            0.0
        } else {
            r.log(-9.0, 1.0)
        };
        s = s.with_link(&format!("b{i}"), &format!("b{}", i + 1), gap, &c, None)?;
    }
    Ok(s)
}

fuzz_target!(|data: &[u8]| {
    let mut r = Reader(data);
    let s = match scenario(&mut r) {
        Ok(s) => s,
        Err(e) => {
            assert_eq!(e.to_string().lines().count(), 1, "{e}");
            return;
        }
    };
    let opts = RunOptions {
        max_work: 2e6,
        ..RunOptions::default()
    };
    match s.run_with_options(&opts, &mut |_| ControlFlow::Continue(())) {
        Ok(res) => {
            assert!(res.first_non_finite().is_none());
            assert!(res.energy.relative_error.is_finite());
        }
        Err(e @ (Error::StepBudget { .. } | Error::Parameter { .. } | Error::Choice { .. })) => {
            assert_eq!(e.to_string().lines().count(), 1, "{e}");
        }
        Err(e) => panic!("{e:?}"),
    }
});
