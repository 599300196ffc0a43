//! Summary-only runs allocate nothing per step (issue 28): the allocations a run makes on its thread do
//! not grow with its length, exact or stepped, with or without impacts (an impact's record in the results
//! is the only thing kept as it happens).

use super::buildings::building;
use pounding::analysis::{RunOptions, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::engine::Propagation;
use pounding::ground_motion::Record;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ops::ControlFlow;

/// The system allocator, counting the allocations of each thread (other tests run on other threads).
struct Counting;

thread_local! {
    static COUNT: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = COUNT.try_with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = COUNT.try_with(|c| c.set(c.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Allocations of a summary-only run of `s`, its accepted steps and its impacts.
fn allocations(s: &Scenario) -> (usize, usize, usize) {
    let options = RunOptions {
        histories: false,
        ..RunOptions::default()
    };
    let before = COUNT.with(Cell::get);
    let r = s
        .run_with_options(&options, &mut |_| ControlFlow::Continue(()))
        .unwrap();
    let after = COUNT.with(Cell::get);
    (after - before, r.statistics.steps, r.impacts.len())
}

#[test]
fn a_summary_only_run_allocates_nothing_per_step() {
    let pair = |model: Model, gap: f64| {
        let c = ContactModel::new(model, 2e9, 0.65).unwrap();
        Scenario::new(
            vec![
                building("L", &[5.0e5], &[7.8957e7], 0.05),
                building("R", &[5.0e5], &[1.9739e7], 0.05),
            ],
            Record::el_centro_1940(),
        )
        .unwrap()
        .with_link("L", "R", gap, &c, None)
        .unwrap()
    };
    for model in [
        Model::Hooke,
        Model::KelvinVoigt,
        Model::Papi,
        Model::HuntCrossley,
    ] {
        for how in [Propagation::Exact, Propagation::Stepping] {
            // 10 s and the whole record (31 s): thousands of steps more, and impacts more with a gap of 0.
            for gap in [0.0, 1.0] {
                let s = pair(model, gap).with_propagation(how);
                let (short, steps_short, impacts_short) =
                    allocations(&s.clone().with_duration(10.0).unwrap());
                let (long, steps_long, impacts_long) = allocations(&s);
                assert!(steps_long > steps_short + 500, "{steps_short} {steps_long}");
                // The impacts' records grow by doubling: a few allocations for all of them.
                let kept = impacts_long.max(1).ilog2() as usize + 1;
                println!(
                    "{model:?} {how:?} gap {gap}: {short} allocations for {steps_short} steps and \
                     {impacts_short} impacts, {long} for {steps_long} and {impacts_long}"
                );
                assert!(
                    long <= short + kept,
                    "{model:?} {how:?} gap {gap}: {short} allocations for {steps_short} steps and \
                     {impacts_short} impacts, {long} for {steps_long} and {impacts_long}"
                );
            }
        }
    }
}
