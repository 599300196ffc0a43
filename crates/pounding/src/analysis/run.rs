//! A pounding run: the row as a system of the engine, its recorders, and the results they kept.

use super::model::Model;
use super::record::{DevicePeaks, HistoryRecorder, Impacts, Peak, Peaks, Recorders};
use super::{
    BuildingResponse, DeviceResponse, EnergyBalance, Histories, Layer, LinkResponse, Results,
    RunOptions, Scenario, Site, Statistics,
};
use crate::element::Kind;
use crate::engine::{self, Settings};
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

/// The values of `peaks`.
fn values(peaks: &[Peak]) -> Vec<f64> {
    peaks.iter().map(|p| p.value).collect()
}

/// The times of `peaks`, s.
fn times(peaks: &[Peak]) -> Vec<f64> {
    peaks.iter().map(|p| p.time).collect()
}

pub(super) fn run(
    s: &Scenario,
    opts: &RunOptions,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<Results, Error> {
    if opts.histories && s.output_samples() > crate::limits::MAX_OUTPUT_SAMPLES {
        return Err(Error::Parameter {
            name: "output_dt",
            value: s.output_dt(),
            allowed: "at most 1e7 output samples over the duration (limits::MAX_OUTPUT_SAMPLES; raise output_dt)",
        });
    }
    let floors: usize = s.buildings().iter().map(|b| b.structure.storeys()).sum();
    let contacts: usize = s.links().iter().map(|l| l.floors.len()).sum::<usize>()
        + s.walls().iter().map(|w| w.floors.len()).sum::<usize>()
        + s.devices().iter().map(|d| d.floors.len()).sum::<usize>();
    let columns = 2 + 3 * floors + contacts + 6;
    if opts.histories
        && s.output_samples().saturating_mul(columns) > crate::limits::MAX_HISTORY_VALUES
    {
        return Err(Error::Parameter {
            name: "output_dt",
            value: s.output_dt(),
            allowed: "at most 1e7 history values, output samples times columns (3 per floor, 1 per contact, 8 more) (limits::MAX_HISTORY_VALUES; raise output_dt)",
        });
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
        let links: Vec<usize> = s.links().iter().map(|l| l.floors.len()).collect();
        let walls: Vec<usize> = s.walls().iter().map(|w| w.floors.len()).collect();
        let devices: Vec<usize> = s.devices().iter().map(|d| d.floors.len()).collect();
        HistoryRecorder::new(
            &model,
            (&storeys, &links, &walls, &devices),
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
    // The work is bounded before the run: an explicit step resolves the highest natural frequency, so a run
    // needs at least about w_max t_end / 3 steps (Dormand–Prince is stable to h w of about 3.3).
    let budget = crate::limits::step_budget(dim, opts.max_work);
    let w_max = s
        .buildings()
        .iter()
        .flat_map(|b| b.structure.modes().omega.iter().copied())
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
    // Every sample of the record within the analysis ends a step.
    let samples = (s.record().npts() as f64).min(t_end / s.record().dt());
    if samples > budget as f64 {
        return Err(Error::StepBudget {
            allowed: budget as f64,
            reason: format!(
                "the record has {samples:e} samples within {t_end:e} s, and every sample ends a step: shorten the duration or the record"
            ),
        });
    }
    let settings = Settings {
        t_end,
        rtol: s.tolerance(),
        atol,
        h0,
        max_steps: budget,
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
    let sys = &model.system;
    let y = &out.y;
    let l = sys.layout();

    let peaks = &rec.peaks;
    let buildings = s
        .buildings()
        .iter()
        .zip(model.offsets.iter().zip(&model.first_storey))
        .map(|(b, (&o, &s0))| {
            let r = o..o + b.structure.storeys();
            let storeys = s0..s0 + b.structure.storeys();
            let storey = |e: usize| match &sys.elements()[e].kind {
                Kind::Storey(st) => Some(st),
                _ => None,
            };
            let residual_drift: Vec<f64> =
                storeys.clone().map(|e| sys.deformation(e, y).0).collect();
            BuildingResponse {
                peak_displacement: values(&peaks.displacement[r.clone()]),
                time_of_peak_displacement: times(&peaks.displacement[r.clone()]),
                peak_drift: peaks.drift[r.clone()].to_vec(),
                peak_absolute_acceleration: values(&peaks.acceleration[r.clone()]),
                time_of_peak_absolute_acceleration: times(&peaks.acceleration[r.clone()]),
                peak_storey_shear: peaks.shear[r.clone()].to_vec(),
                residual_displacement: r.clone().map(|i| y[l.u(i)]).collect(),
                residual_drift,
                ductility: storeys
                    .clone()
                    .zip(&peaks.drift[r.clone()])
                    .map(|(e, d)| storey(e).and_then(|st| st.yield_drift()).map(|dy| d / dy))
                    .collect(),
                hysteretic_energy: storeys
                    .map(|e| {
                        let (x, _) = sys.deformation(e, y);
                        sys.elements()[e].energy(x, &y[l.block(e)]).hysteretic
                    })
                    .collect(),
            }
        })
        .collect();
    let (impacts, impact_loops) = rec.impacts.finish(sys, out.t, y);
    // Totals of a link or a wall: its impacts, the work of its elements, its closings and openings per
    // site (a bumper's two elements share their site), and its largest force.
    let totals = |owns: &dyn Fn(Site) -> bool, seat: Option<f64>| {
        let mine = impacts.iter().filter(|i| owns(i.site));
        let ks: Vec<usize> = (0..model.contacts.len())
            .filter(|&k| owns(model.contacts[k].site))
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
        LinkResponse {
            impacts: mine.clone().filter(|i| i.layer != Layer::Consumed).count(),
            consumed: mine.clone().filter(|i| i.layer == Layer::Consumed).count(),
            peak_force: mine.clone().map(|i| i.peak_force).fold(pair_peak, f64::max),
            dissipated_energy: ks
                .iter()
                .map(|&k| y[l.block(model.contacts[k].element).start])
                .sum(),
            max_penetration: mine.map(|i| i.max_penetration).fold(0.0, f64::max),
            max_closing: per(&rec.impacts.max_closing),
            unseated: seat.map(|s| max_opening.iter().any(|&o| o > s)),
            max_opening,
        }
    };
    let links = (0..s.links().len())
        .map(|li| {
            totals(
                &|site| matches!(site, Site::Link { link, .. } if link == li),
                s.links()[li].seat,
            )
        })
        .collect();
    let walls = (0..s.walls().len())
        .map(|wi| {
            totals(
                &|site| matches!(site, Site::Wall { wall, .. } if wall == wi),
                s.walls()[wi].seat,
            )
        })
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
    let results = Results {
        buildings,
        links,
        walls,
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
    };
    match results.first_non_finite() {
        Some(what) => Err(Error::NotFinite { what }),
        None => Ok(results),
    }
}
