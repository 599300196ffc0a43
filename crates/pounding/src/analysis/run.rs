//! A pounding run: the row as a system of the engine, its recorders, and the results they kept.

use super::histories::HistoryRecorder;
use super::impacts::Impacts;
use super::model::Model;
use super::peaks::{DevicePeaks, Peak, Peaks};
use super::recorders::Recorders;
use super::{
    BuildingResponse, ColumnResponse, DeviceResponse, EnergyBalance, FoundationResponse, Histories,
    Layer, LineResponse, PlanResponse, Results, Scenario, SiteResponse, Statistics,
};
use crate::engine::{self, Outcome, Settings};
use crate::Error;
use std::ops::ControlFlow;

/// How far a run has got, for progress reports.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Time reached, s.
    pub t: f64,
    /// Duration of the analysis, s.
    pub duration: f64,
    /// Impacts so far.
    pub impacts: usize,
}

/// What a run keeps, and how much work it may do.
#[derive(Clone, Debug, PartialEq)]
pub struct RunOptions {
    /// Keep the time histories at the output interval (otherwise [`Results::histories`] is empty and a run
    /// keeps only its peaks, impacts and energies).
    pub histories: bool,
    /// Largest work of the run, in integration steps times (states + 8) ([`crate::limits::step_budget`]);
    /// [`crate::limits::MAX_WORK`] (about 5 s) by default. A study may lower it to skip runs that would
    /// crawl, or raise it for a run it knows to be long.
    pub max_work: f64,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            histories: true,
            max_work: crate::limits::MAX_WORK,
        }
    }
}

impl RunOptions {
    /// Only peaks, impacts and energies, with the default work budget.
    pub fn summary_only() -> Self {
        Self {
            histories: false,
            ..Self::default()
        }
    }
}

impl Scenario {
    /// Runs the analysis, keeping the histories.
    pub fn run(&self) -> Result<Results, Error> {
        run(self, &RunOptions::default(), &mut |_| {
            ControlFlow::Continue(())
        })
    }

    /// Runs the analysis, telling `progress` how far it has got (for progress bars) each time the run advances
    /// 0.5 % of its duration and at least every 256 steps (so that a run that crawls can be cancelled
    /// promptly); `progress` returns `ControlFlow::Break(())` to cancel the run ([`Error::Cancelled`]).
    pub fn run_with(
        &self,
        progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<Results, Error> {
        run(self, &RunOptions::default(), progress)
    }

    /// Runs the analysis with `options` (for example without histories, for studies of many runs). Every run
    /// has a step budget ([`crate::limits::step_budget`]): a run that would exceed it is refused before it
    /// starts, or stopped, with [`Error::StepBudget`].
    pub fn run_with_options(
        &self,
        options: &RunOptions,
        progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<Results, Error> {
        run(self, options, progress)
    }
}

/// The values of `peaks`.
fn values(peaks: &[Peak]) -> Vec<f64> {
    peaks.iter().map(|p| p.value).collect()
}

/// The times of `peaks`, s.
fn times(peaks: &[Peak]) -> Vec<f64> {
    peaks.iter().map(|p| p.time).collect()
}

/// Histories of `s` fit in memory (they are refused before any work otherwise).
fn check_histories(s: &Scenario) -> Result<(), Error> {
    if s.output_samples() > crate::limits::MAX_OUTPUT_SAMPLES {
        return Err(Error::Parameter {
            name: "output_dt",
            value: s.output_dt(),
            allowed: "at most 1e7 output samples over the duration (limits::MAX_OUTPUT_SAMPLES; raise output_dt)",
        });
    }
    let floors: usize = s.buildings().iter().map(|b| b.structure.storeys()).sum();
    // A floor in plan has two more histories (along y, rotation), and a ground along y one.
    let plan_floors: usize = s
        .buildings()
        .iter()
        .map(|b| b.structure.plan().map_or(0, |p| p.floors()))
        .sum();
    let contacts: usize = s.sites().iter().map(|l| l.levels.len()).sum::<usize>()
        + s.devices().iter().map(|d| d.floors.len()).sum::<usize>();
    let columns =
        2 + 3 * floors + 2 * plan_floors + usize::from(s.record_y().is_some()) + contacts + 6;
    if s.output_samples().saturating_mul(columns) > crate::limits::MAX_HISTORY_VALUES {
        return Err(Error::Parameter {
            name: "output_dt",
            value: s.output_dt(),
            allowed: "at most 1e7 history values, output samples times columns (3 per floor, 1 per contact, 8 more) (limits::MAX_HISTORY_VALUES; raise output_dt)",
        });
    }
    Ok(())
}

/// The step budget of a run of `dim` states, checked against what the scenario will need at least: an
/// explicit step resolves the highest natural frequency, so a run needs at least about `w_max t_end / 3`
/// steps (Dormand–Prince is stable to `h w` of about 3.3), and every sample of the record ends a step.
fn budget(s: &Scenario, dim: usize, max_work: f64) -> Result<usize, Error> {
    let budget = crate::limits::step_budget(dim, max_work);
    let t_end = s.duration();
    let w_max = s
        .buildings()
        .iter()
        .flat_map(
            |b| match (b.structure.plan(), b.structure.flexible_modes()) {
                (Some(p), _) => p.modes().omega.iter().copied(),
                (None, Some(m)) => m.omega.iter().copied(),
                (None, None) => b.structure.modes().omega.iter().copied(),
            },
        )
        .fold(0.0, f64::max);
    if w_max * t_end / 3.0 > budget as f64 {
        return Err(Error::StepBudget {
            allowed: budget as f64,
            reason: format!(
                "the highest natural frequency, {:e} Hz, needs about {:e} steps over {t_end:e} s: check the masses and stiffnesses",
                w_max / (2.0 * std::f64::consts::PI),
                w_max * t_end / 3.0
            ),
        });
    }
    let samples = (s.record().npts() as f64).min(t_end / s.record().dt());
    if samples > budget as f64 {
        return Err(Error::StepBudget {
            allowed: budget as f64,
            reason: format!(
                "the record has {samples:e} samples within {t_end:e} s, and every sample ends a step: shorten the duration or the record"
            ),
        });
    }
    Ok(budget)
}

fn run(
    s: &Scenario,
    opts: &RunOptions,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<Results, Error> {
    if opts.histories {
        check_histories(s)?;
    }
    let mut model = Model::new(s);
    let (atol, h0) = model.tolerances(s, s.tolerance());
    let t_end = s.duration();
    let histories = opts.histories.then(|| {
        let storeys: Vec<usize> = s
            .buildings()
            .iter()
            .map(|b| b.structure.storeys())
            .collect();
        let plans: Vec<usize> = s
            .buildings()
            .iter()
            .map(|b| b.structure.plan().map_or(0, |p| p.floors()))
            .collect();
        let grounded: Vec<usize> = s
            .buildings()
            .iter()
            .map(|b| 2 * usize::from(b.structure.foundation().is_some()))
            .collect();
        let sites: Vec<usize> = s.sites().iter().map(|l| l.levels.len()).collect();
        let devices: Vec<usize> = s.devices().iter().map(|d| d.floors.len()).collect();
        HistoryRecorder::new(
            &model,
            &super::histories::Counts {
                storeys: &storeys,
                plans: &plans,
                grounded: &grounded,
                sites: &sites,
                devices: &devices,
            },
            s.output_samples(),
            s.output_dt(),
            t_end,
        )
    });
    let mut rec = Recorders::new(
        Peaks::new(&model),
        Impacts::new(&model, opts.histories),
        DevicePeaks::new(&model),
        histories,
        progress,
        t_end,
    );
    let dim = model.system.layout().dim();
    let budget = budget(s, dim, opts.max_work)?;
    let settings = Settings {
        t_end,
        rtol: s.tolerance(),
        atol,
        h0,
        max_steps: budget,
        propagation: s.propagation(),
    };
    let out = engine::run(
        &mut model.system,
        (0.0, &vec![0.0; dim]),
        &settings,
        &mut rec,
    )?;
    match out.ending {
        engine::Ending::StepBudget => {
            return Err(Error::StepBudget {
                allowed: budget as f64,
                reason: format!(
                    "it had reached t = {:e} s of {t_end:e} s, with {} events: impacts or yielding too stiff or too frequent to resolve",
                    out.t, out.events
                ),
            })
        }
        engine::Ending::Cancelled => return Err(Error::Cancelled { t: out.t }),
        engine::Ending::Time | engine::Ending::Stopped => {}
    }
    let results = results(s, &model, rec, &out);
    match results.first_non_finite() {
        Some(what) => Err(Error::NotFinite { what }),
        None => Ok(results),
    }
}

/// What the recorders kept, and the state at the end, as results.
fn results(s: &Scenario, model: &Model, mut rec: Recorders, out: &Outcome) -> Results {
    let sys = &model.system;
    let y = &out.y;
    let (impacts, impact_loops) = rec.impacts.finish(sys, out.t, y);
    let sites = (0..s.sites().len())
        .map(|site| site_totals(s, model, &rec, &impacts, site, y))
        .collect();
    let devices = (0..s.devices().len())
        .map(|di| {
            let ks: Vec<usize> = (0..model.devices.len())
                .filter(|&k| model.devices[k].device == di)
                .collect();
            let per = |v: &[f64]| ks.iter().map(|&k| v[k]).collect::<Vec<f64>>();
            DeviceResponse {
                peak_force: per(&rec.devices.force),
                max_closing: per(&rec.devices.closing),
                max_opening: per(&rec.devices.opening),
            }
        })
        .collect();
    let balance = &rec.balance;
    Results {
        buildings: building_responses(s, model, &rec.peaks, y),
        sites,
        devices,
        impacts,
        energy: EnergyBalance {
            end: sys.energies(y),
            relative_error: if balance.scale > 0.0 {
                balance.worst / balance.scale
            } else {
                0.0
            },
        },
        histories: rec
            .histories
            .map(|h| Histories {
                impact_loops,
                ..h.hist
            })
            .unwrap_or_default(),
        statistics: Statistics {
            steps: out.steps,
            rejected: out.rejected,
            events: out.events,
        },
    }
}

/// The peak response of every building, and its state at the end `y`.
fn building_responses(
    s: &Scenario,
    model: &Model,
    peaks: &Peaks,
    y: &[f64],
) -> Vec<BuildingResponse> {
    let sys = &model.system;
    let l = sys.layout();
    // Each line element's index among the plans' lines ([`Peaks::line_drift`]).
    let mut line_at = vec![usize::MAX; sys.elements().len()];
    for (k, &e) in model.lines.iter().enumerate() {
        line_at[e] = k;
    }
    let mut corner = 0;
    s.buildings()
        .iter()
        .enumerate()
        .map(|(b, bd)| {
            let st = &bd.structure;
            let o = model.offsets[b];
            let n = st.storeys();
            let r = o..o + n;
            let drift_at = |i: usize| model.storeys[i].drift(i, y, 0);
            let elements = |j: usize| model.storey_elements(b, j);
            let hysteretic = |e: usize| {
                let (x, _) = sys.deformation(e, y);
                sys.elements()[e].energy(x, &y[l.block(e)]).hysteretic
            };
            let plan = st.plan().map(|p| {
                let pr = plan_response(model, peaks, y, (b, p), corner, &line_at, &hysteretic);
                corner += 4 * n;
                pr
            });
            let ductility = match &plan {
                None => st
                    .storey_laws()
                    .iter()
                    .zip(st.stiffnesses())
                    .zip(&peaks.drift[r.clone()])
                    .map(|((law, k), d)| law.yield_force().map(|fy| d / (fy / k)))
                    .collect(),
                // The largest of any line of the storey.
                Some(pr) => (0..n)
                    .map(|j| {
                        pr.lines
                            .iter()
                            .filter_map(|line| line.ductility[j])
                            .reduce(f64::max)
                    })
                    .collect(),
            };
            BuildingResponse {
                peak_displacement: values(&peaks.displacement[r.clone()]),
                time_of_peak_displacement: times(&peaks.displacement[r.clone()]),
                peak_drift: peaks.drift[r.clone()].to_vec(),
                peak_absolute_acceleration: values(&peaks.acceleration[r.clone()]),
                time_of_peak_absolute_acceleration: times(&peaks.acceleration[r.clone()]),
                peak_storey_shear: peaks.shear[r.clone()].to_vec(),
                residual_displacement: r.clone().map(|i| y[l.u(i)]).collect(),
                residual_drift: r.clone().map(drift_at).collect(),
                ductility,
                hysteretic_energy: (0..n).map(|j| elements(j).map(hysteretic).sum()).collect(),
                plan,
                foundation: st.foundation().map(|_| {
                    // The foundation's sway and rocking follow the floors (Model: on_foundation).
                    let (uf, th) = (o + n, o + n + 1);
                    FoundationResponse {
                        peak_sway: peaks.displacement[uf].value,
                        peak_rocking: peaks.displacement[th].value,
                        peak_soil_force: peaks.shear[uf],
                        peak_soil_moment: peaks.shear[th],
                        residual_sway: y[l.u(uf)],
                        residual_rocking: y[l.u(th)],
                    }
                }),
            }
        })
        .collect()
}

/// The response of building `b` in plan `p` beyond its mass centres' along x; its corners' peaks start at
/// `corner` in [`Peaks::corner`].
fn plan_response(
    model: &Model,
    peaks: &Peaks,
    y: &[f64],
    (b, p): (usize, &crate::structure::Plan),
    corner: usize,
    line_at: &[usize],
    hysteretic: &dyn Fn(usize) -> f64,
) -> PlanResponse {
    use crate::structure::PlanDof;
    let l = model.system.layout();
    let o = model.offsets[b];
    let n = p.floors();
    let at = |d: PlanDof| (1..=n).map(move |f| o + p.dof(f, d));
    let peak = |d: PlanDof, v: &[f64]| at(d).map(|i| v[i]).collect::<Vec<f64>>();
    let disp: Vec<f64> = values(&peaks.displacement);
    // Per floor: along x the edges at y_min and y_max, along y those at x_min and x_max (Model::corners);
    // corners counterclockwise from (x_min, y_min).
    let corners: Vec<[(f64, f64); 4]> = (0..n)
        .map(|f| {
            let e = |j: usize| peaks.corner[corner + 4 * f + j].value;
            [(e(0), e(2)), (e(0), e(3)), (e(1), e(3)), (e(1), e(2))]
        })
        .collect();
    let ratio = |c: f64, m: f64| (m > 0.0).then_some(c / m);
    let torsional_amplification = (0..n)
        .map(|f| {
            let (cx, cy) = corners[f]
                .iter()
                .fold((0.0f64, 0.0f64), |a, c| (a.0.max(c.0), a.1.max(c.1)));
            let (mx, my) = (
                disp[o + p.dof(f + 1, PlanDof::X)],
                disp[o + p.dof(f + 1, PlanDof::Y)],
            );
            (ratio(cx, mx), ratio(cy, my))
        })
        .collect();
    let lines = (0..p.lines().len())
        .map(|li| {
            let line = &p.lines()[li];
            let es: Vec<usize> = (0..n)
                .map(|j| model.storey_elements(b, j).start + li)
                .collect();
            LineResponse {
                peak_drift: es.iter().map(|&e| peaks.line_drift[line_at[e]]).collect(),
                ductility: es
                    .iter()
                    .enumerate()
                    .map(|(j, &e)| {
                        line.laws[j]
                            .yield_force()
                            .map(|fy| peaks.line_drift[line_at[e]] / (fy / line.stiffnesses[j]))
                    })
                    .collect(),
                hysteretic_energy: es.iter().map(|&e| hysteretic(e)).collect(),
            }
        })
        .collect();
    PlanResponse {
        peak_displacement_y: peak(PlanDof::Y, &disp),
        peak_rotation: peak(PlanDof::Rotation, &disp),
        peak_drift_y: peak(PlanDof::Y, &peaks.drift),
        peak_twist: peak(PlanDof::Rotation, &peaks.drift),
        peak_storey_shear_y: peak(PlanDof::Y, &peaks.shear),
        peak_torque: peak(PlanDof::Rotation, &peaks.shear),
        peak_corner: corners,
        torsional_amplification,
        residual_displacement_y: at(PlanDof::Y).map(|i| y[l.u(i)]).collect(),
        residual_rotation: at(PlanDof::Rotation).map(|i| y[l.u(i)]).collect(),
        lines,
    }
}

/// Totals of contact site `site`: its impacts, the work of its elements, its closings and openings per level
/// (a bumper's two elements share their level), and its largest force.
fn site_totals(
    s: &Scenario,
    model: &Model,
    rec: &Recorders,
    impacts: &[super::Impact],
    site: usize,
    y: &[f64],
) -> SiteResponse {
    let mine = impacts.iter().filter(|i| i.site == site);
    let ks: Vec<usize> = (0..model.contacts.len())
        .filter(|&k| model.contacts[k].site == site)
        .collect();
    let first: Vec<usize> = ks
        .iter()
        .copied()
        .filter(|&k| model.contacts[k].layer != Layer::Consumed)
        .collect();
    let per = |v: &[f64]| first.iter().map(|&k| v[k]).collect::<Vec<f64>>();
    let max_opening = per(&rec.impacts.max_opening);
    let pair_peak = ks
        .iter()
        .map(|&k| rec.impacts.pair_peak[rec.impacts.pair[k]])
        .fold(0.0, f64::max);
    SiteResponse {
        impacts: mine.clone().filter(|i| i.layer != Layer::Consumed).count(),
        consumed: mine.clone().filter(|i| i.layer == Layer::Consumed).count(),
        peak_force: mine.clone().map(|i| i.peak_force).fold(pair_peak, f64::max),
        dissipated_energy: ks
            .iter()
            .map(|&k| super::impacts::dissipated(&model.system, model.contacts[k].element, y))
            .sum(),
        max_penetration: mine.map(|i| i.max_penetration).fold(0.0, f64::max),
        max_closing: per(&rec.impacts.max_closing),
        peak_ends: first
            .iter()
            .map(|&k| {
                rec.impacts
                    .end_peaks_of(&model.system, &rec.peaks.displacement, k)
            })
            .collect(),
        column: model
            .columns
            .iter()
            .position(|c| c.site == site)
            .and_then(|ci| {
                let col = s.sites()[site].column.as_ref()?.struck?;
                // The force at the point, and the end forces with the column's drift: the storey's bending
                // of it and the load at the point.
                let [f, v1, v2, m1, m2] = rec.peaks.column[ci];
                let (shear, moment) = ((v1, v2), (m1, m2));
                Some(ColumnResponse {
                    peak_force: f,
                    peak_shear: shear,
                    peak_moment: moment,
                    shear_exceeded: col.shear_capacity.map(|cap| shear.0.max(shear.1) > cap),
                    moment_exceeded: col.moment_capacity.map(|cap| moment.0.max(moment.1) > cap),
                })
            }),
        unseated: s.sites()[site]
            .seat
            .map(|seat| max_opening.iter().any(|&o| o > seat)),
        max_opening,
    }
}
