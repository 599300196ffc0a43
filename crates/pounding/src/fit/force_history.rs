//! A contact law fitted to the measured force history of one impact (a drop or a pendulum test: the
//! effective mass and the impact velocity known): stiffness, exponent, and damping (`e`, a material
//! damping constant, or Thornton's yield pressure), with the touch time, by least squares on the force
//! (docs/contact-models.md section 2.8).

use super::least_squares::{minimise, Solution};
use super::restitution::{chi_for, speed_for};
use super::{Estimate, Fit};
use crate::contact::{ContactOptions, Model, Restitution};
use crate::impact::{force_at, ImpactOptions, ImpactSetup};
use crate::Error;

/// What a force-history fit holds and what it varies.
#[derive(Clone, Debug, PartialEq)]
pub struct HistorySetup {
    /// The model and its fixed options (damping rule, `alpha`, reading, tension; `thornton`'s radius); its
    /// stiffness, exponent and damping are fitted, so their values here are ignored.
    pub options: ContactOptions,
    /// Effective mass of the impact, kg (`m1 m2 / (m1 + m2)`).
    pub mass: f64,
    /// Impact velocity, m/s.
    pub v_i: f64,
    /// Hold the exponent at this value instead of fitting it (a model with a fixed exponent always holds
    /// its own).
    pub exponent: Option<f64>,
    /// Fit a material damping constant `D/K` (s/m; the Hunt–Crossley family) instead of `e`.
    pub damping_constant: bool,
}

/// A force-history fit: its parameters, and the fitted force at the data's times.
#[derive(Clone, Debug, PartialEq)]
pub struct HistoryFit {
    /// Parameters: `stiffness` (N/m^n), `exponent` (if fitted), the damping (`e`, `damping_constant` in
    /// s/m or `yield_pressure` in Pa; none for an elastic law) and `touch_time` (s, on the data's clock).
    pub fit: Fit,
    /// The fitted force at each data time, N.
    pub force: Vec<f64>,
    /// The fitted force on a fine grid over the data's time span, for a figure: times (s, the data's clock)
    /// and forces (N).
    pub curve: (Vec<f64>, Vec<f64>),
}

/// How the damping enters the parameter vector.
#[derive(Clone, Copy, PartialEq)]
enum Damping {
    /// An elastic law: none.
    None,
    /// `e`, as `logit(e)` (0 < e < 1).
    E,
    /// A material damping constant, as `ln c`.
    Constant,
    /// Thornton's yield pressure, as `ln p_y`.
    YieldPressure,
}

/// Where each fitted quantity sits in the parameter vector `x`: `ln k`, `ln n` (unless held), the damping
/// (unless elastic), and the touch time as its shift from the first estimate, in contact durations.
struct Layout<'s> {
    setup: &'s HistorySetup,
    /// The exponent held, if it is.
    fixed_n: Option<f64>,
    damping: Damping,
    start: Start,
}

impl Layout<'_> {
    /// Parameters.
    fn len(&self) -> usize {
        2 + usize::from(self.fixed_n.is_none()) + usize::from(self.damping != Damping::None)
    }

    /// The index of the damping parameter.
    fn damping_at(&self) -> usize {
        1 + usize::from(self.fixed_n.is_none())
    }

    fn exponent(&self, x: &[f64]) -> f64 {
        self.fixed_n.unwrap_or_else(|| x[1].exp())
    }

    fn touch(&self, x: &[f64]) -> f64 {
        self.start.touch + x[self.len() - 1] * self.start.duration
    }

    /// Where the fit starts: the elastic stiffness of the peak force, the model's exponent, the damping of
    /// the impulse's `e`, the first touch estimate.
    fn x0(&self) -> Vec<f64> {
        let (m, v) = (self.setup.mass, self.setup.v_i);
        let n0 = self
            .fixed_n
            .unwrap_or(self.setup.options.model.info().default_n);
        let k0 = self.start.peak.powf(n0 + 1.0) / ((n0 + 1.0) * 0.5 * m * v * v).powf(n0);
        let e0 = self.start.e;
        let mut x0 = vec![k0.ln()];
        if self.fixed_n.is_none() {
            x0.push(n0.ln());
        }
        match self.damping {
            Damping::None => {}
            Damping::E => x0.push((e0 / (1.0 - e0)).ln()),
            Damping::Constant => x0.push((chi_for(e0).unwrap_or(1.0) / v).ln()),
            Damping::YieldPressure => {
                let r = self.setup.options.radius.unwrap_or(f64::NAN);
                x0.push(yield_pressure_for(e0, k0, r, m, v).ln());
            }
        }
        x0.push(0.0);
        x0
    }

    /// The model's force (N) at `times` (the data's clock) for parameters `x`.
    fn force(&self, x: &[f64], times: &[f64]) -> Result<Vec<f64>, Error> {
        let (m, v) = (self.setup.mass, self.setup.v_i);
        let mut o = self.setup.options.clone();
        let info = o.model.info();
        o.exponent = (!info.n_fixed).then(|| self.exponent(x));
        let d = x[self.damping_at()];
        match self.damping {
            Damping::E => o.e = Restitution::Constant(1.0 / (1.0 + (-d).exp())),
            Damping::Constant => o.e = Restitution::DampingConstant(d.exp()),
            Damping::YieldPressure => o.yield_pressure = Some(d.exp()),
            Damping::None => {}
        }
        let spec = o.build(x[0].exp()).map_err(|e| match e {
            crate::contact::OptionError::Value(v) => v,
            other => Error::Choice {
                name: "model",
                value: o.model.to_string(),
                allowed: other.message(|k| k.to_string()),
            },
        })?;
        let (law, _) = spec.prepare()?.law(m, v)?;
        let t0 = self.touch(x);
        let shifted: Vec<f64> = times.iter().map(|t| t - t0).collect();
        force_at(
            &law,
            spec.tension(),
            &ImpactSetup::relative(m, v),
            &ImpactOptions::default(),
            &shifted,
        )
    }

    /// The estimates of `s`, in the parameters' own units, their standard errors by their derivatives.
    fn estimates(&self, s: &Solution) -> Vec<Estimate> {
        let (x, se) = (&s.x, |j: usize| s.std_error(j));
        let (k, n) = (x[0].exp(), self.exponent(x));
        let mut est = vec![Estimate::new(
            "stiffness",
            k,
            k * se(0),
            crate::words::stiffness_unit(n),
        )];
        if self.fixed_n.is_none() {
            est.push(Estimate::new("exponent", n, n * se(1), ""));
        }
        let j = self.damping_at();
        let y = x[j].exp();
        match self.damping {
            Damping::None => {}
            Damping::E => {
                let e = 1.0 / (1.0 + (-x[j]).exp());
                est.push(Estimate::new("e", e, e * (1.0 - e) * se(j), ""));
            }
            Damping::Constant => est.push(Estimate::new("damping_constant", y, y * se(j), "s/m")),
            Damping::YieldPressure => est.push(Estimate::new("yield_pressure", y, y * se(j), "Pa")),
        }
        let last = self.len() - 1;
        est.push(Estimate::new(
            "touch_time",
            self.touch(x),
            se(last) * self.start.duration,
            "s",
        ));
        est
    }
}

/// Fits `setup`'s model to the force history `data` (`(t` s, `F` N) pairs, any clock: the touch time is
/// fitted too). At least 5 samples, times finite and distinct, forces finite, some of them positive.
pub fn force_history(data: &[(f64, f64)], setup: &HistorySetup) -> Result<HistoryFit, Error> {
    let data = checked(data)?;
    let info = setup.options.model.info();
    crate::error::check("mass", setup.mass, setup.mass > 0.0, "mass > 0 (kg)")?;
    crate::error::check("v_i", setup.v_i, setup.v_i > 0.0, "v_i > 0 (m/s)")?;
    let layout = Layout {
        setup,
        fixed_n: if info.n_fixed {
            Some(info.default_n)
        } else {
            setup.exponent
        },
        damping: match (info.model, setup.damping_constant, info.model.is_damped()) {
            (Model::Thornton, ..) => Damping::YieldPressure,
            (_, true, _) => Damping::Constant,
            (_, false, true) => Damping::E,
            (_, false, false) => Damping::None,
        },
        start: Start::of(&data, setup.mass, setup.v_i),
    };
    let times: Vec<f64> = data.iter().map(|d| d.0).collect();
    let measured: Vec<f64> = data.iter().map(|d| d.1).collect();
    let peak = layout.start.peak;
    // Residuals in units of the peak force, so that the solver's tests are scale-free.
    let residuals = |x: &[f64], out: &mut [f64]| -> Result<(), Error> {
        let f = layout.force(x, &times)?;
        for ((o, f), y) in out.iter_mut().zip(f).zip(&measured) {
            *o = (f - y) / peak;
        }
        Ok(())
    };
    // The elastic estimate of the stiffness from the peak force, mass and velocity: a start outside the range
    // of f64 means inputs in the wrong units (a mass in grams, a force in kN).
    if !layout.x0().iter().all(|x| x.is_finite()) {
        return Err(Error::Choice {
            name: "data",
            value: format!(
                "a peak force of {} N with mass {} kg and v_i {} m/s",
                crate::words::number(peak),
                crate::words::number(setup.mass),
                crate::words::number(setup.v_i)
            ),
            allowed: "inputs whose elastic stiffness estimate F^(n+1) / ((n+1) m v^2 / 2)^n is a finite number > 0 (check the units: N, kg, m/s)".into(),
        });
    }
    let x_best = search(&layout, &residuals, data.len())?;
    let scales = vec![1.0; layout.len()];
    let s = minimise(residuals, &x_best, &scales, data.len(), "data")?;
    let force = layout.force(&s.x, &times)?;
    let (first, last) = (times[0], times[times.len() - 1]);
    let grid: Vec<f64> = (0..=600)
        .map(|j| first + (last - first) * f64::from(j) / 600.0)
        .collect();
    let curve = (grid.clone(), layout.force(&s.x, &grid)?);
    let residuals: Vec<f64> = force.iter().zip(&measured).map(|(f, y)| f - y).collect();
    Ok(HistoryFit {
        fit: Fit::new(
            layout.estimates(&s),
            &residuals,
            measured.iter().copied(),
            s.iterations,
        ),
        force,
        curve,
    })
}

/// Where the full fit starts. A law whose force jumps at touch or at the end (a dashpot) makes the
/// residual jump as either crosses a sample, and a wrong stiffness puts the end many samples away: descent
/// alone stops at such a jump. So a coarse grid of stiffnesses (a factor 4 either way) and touch times
/// (across the bracket) is searched first; from its three best points the other parameters are fitted with
/// the touch held, and the best of these is returned.
fn search<F>(layout: &Layout, residuals: &F, m: usize) -> Result<Vec<f64>, Error>
where
    F: Fn(&[f64], &mut [f64]) -> Result<(), Error>,
{
    let (x0, p) = (layout.x0(), layout.len());
    let start = &layout.start;
    let mut sq = vec![0.0; m];
    let mut grid: Vec<(f64, f64, f64)> = Vec::new();
    for j in -8..=8 {
        for touch in start.touches() {
            let mut x = x0.clone();
            x[0] += f64::from(j) * 0.25 * std::f64::consts::LN_2;
            x[p - 1] = (touch - start.touch) / start.duration;
            if residuals(&x, &mut sq).is_ok() {
                let rss: f64 = sq.iter().map(|r| r * r).sum();
                if rss.is_finite() {
                    grid.push((rss, x[0], x[p - 1]));
                }
            }
        }
    }
    grid.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best: Option<(f64, Vec<f64>)> = None;
    let mut failure = None;
    for &(_, ln_k, x_t) in grid.iter().take(3) {
        let mut xs = x0[..p - 1].to_vec();
        xs[0] = ln_k;
        let held = minimise(
            |xr, out| {
                let mut x = xr.to_vec();
                x.push(x_t);
                residuals(&x, out)
            },
            &xs,
            &vec![1.0; p - 1],
            m,
            "data",
        );
        match held {
            Ok(h) if best.as_ref().is_none_or(|b| h.rss < b.0) => {
                let mut x = h.x;
                x.push(x_t);
                best = Some((h.rss, x));
            }
            Ok(_) => {}
            Err(e) => failure = Some(e),
        }
    }
    match (best, failure) {
        (Some(b), _) => Ok(b.1),
        (None, Some(e)) => Err(e),
        (None, None) => Ok(x0),
    }
}

/// The data sorted by time, checked: at least 5 samples, finite, distinct times, some force > 0.
fn checked(data: &[(f64, f64)]) -> Result<Vec<(f64, f64)>, Error> {
    let refuse = |value: String, allowed: &str| {
        Err(Error::Choice {
            name: "data",
            value,
            allowed: allowed.to_string(),
        })
    };
    if data.len() < 5 {
        return refuse(
            crate::words::count(data.len(), "sample", None),
            "at least 5 samples (t s, F N) of one impact's force",
        );
    }
    if let Some(k) = data
        .iter()
        .position(|d| !(d.0.is_finite() && d.1.is_finite()))
    {
        return refuse(format!("row {}", k + 1), "finite times (s) and forces (N)");
    }
    let mut d = data.to_vec();
    d.sort_by(|a, b| a.0.total_cmp(&b.0));
    if d.windows(2).any(|w| w[1].0 == w[0].0) {
        return refuse("two samples at one time".into(), "distinct times");
    }
    let above = d.iter().filter(|p| p.1 > 0.0).count();
    if above < 3 {
        return refuse(
            format!("{above} positive forces"),
            "a history with at least 3 samples in contact (force > 0)",
        );
    }
    Ok(d)
}

/// Where a fit starts, read off the data.
struct Start {
    /// Largest force, N.
    peak: f64,
    /// Time the force first exceeds 2 % of its peak, less a twentieth of the duration, s.
    touch: f64,
    /// The sample before the first above 2 % of the peak, and that first one: the touch of a law whose
    /// force jumps at touch lies between them, s.
    bracket: (f64, f64),
    /// Time above 2 % of the peak, s.
    duration: f64,
    /// `e` from the impulse, `int F dt = m v (1 + e)` (free bodies), kept within [0.05, 0.95].
    e: f64,
}

impl Start {
    /// The touch times a fit starts from: eleven across the bracket.
    fn touches(&self) -> impl Iterator<Item = f64> + '_ {
        let (a, b) = self.bracket;
        (0..11).map(move |j| a + (b - a) * (f64::from(j) + 0.5) / 11.0)
    }

    fn of(data: &[(f64, f64)], m: f64, v: f64) -> Self {
        let peak = data.iter().fold(0.0f64, |a, d| a.max(d.1));
        let above: Vec<usize> = (0..data.len())
            .filter(|&k| data[k].1 > 0.02 * peak)
            .collect();
        let (a, b) = (above[0], above[above.len() - 1]);
        let step = data[1..]
            .iter()
            .zip(data)
            .map(|(q, p)| q.0 - p.0)
            .fold(f64::INFINITY, f64::min);
        let duration = (data[b].0 - data[a].0).max(step);
        let impulse: f64 = data
            .windows(2)
            .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
            .sum();
        Start {
            peak,
            touch: data[a].0 - 0.05 * duration,
            bracket: (
                data[a.saturating_sub(1)].0.min(data[a].0 - 0.05 * duration),
                data[a].0,
            ),
            duration,
            e: (impulse / (m * v) - 1.0).clamp(0.05, 0.95),
        }
    }
}

/// The yield pressure (Pa) that makes spheres of radius `r` and Hertz stiffness `k` deliver `e` at `v`
/// with mass `m`: `v_y` from Thornton's `e(v / v_y)`, then `d_y = (5 m v_y^2 / (4 k))^(2/5)` and
/// `p_y = (2 E* / pi) sqrt(d_y / R)`, `E* = 3 k / (4 sqrt(R))` (docs/contact-models.md section 2.7).
pub fn yield_pressure_for(e: f64, k: f64, r: f64, m: f64, v: f64) -> f64 {
    yield_pressure_of(v / speed_for(e).unwrap_or(2.0), k, r, m)
}

/// The yield pressure (Pa) of spheres of radius `r` (m) and Hertz stiffness `k` (N/m^1.5) that first yield
/// at impact velocity `v_y` (m/s) with effective mass `m` (kg).
pub fn yield_pressure_of(v_y: f64, k: f64, r: f64, m: f64) -> f64 {
    let d_y = (1.25 * m * v_y * v_y / k).powf(0.4);
    let e_star = 0.75 * k / r.sqrt();
    2.0 * e_star / std::f64::consts::PI * (d_y / r).sqrt()
}
