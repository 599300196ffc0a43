//! Contact laws fitted to measurements, as the command line (`pounding fit`) and Python (`pounding.fit`) ask
//! them: data read from two-column text, the fit chosen by the model's name, and one report with the
//! parameters under their scenario key names, their standard errors, the residual, the lines to paste into
//! a scenario, and the fitted curve for a figure. The fitting is the library's (`pounding::fit`).

use crate::format::fmt_sig;
use pounding::contact::{ContactOptions, Formula, Model, Restitution};
use pounding::fit::force_history::{yield_pressure_of, HistorySetup};
use pounding::fit::{restitution, Estimate, Fit};
use serde::Serialize;
use serde_json::{Map, Value};

/// Pairs of numbers from text: one row per line, two numbers separated by a comma, spaces or tabs; blank
/// lines and everything from `#` are skipped, and so is a first line that is not numbers (a header). The
/// error names the line and says what is allowed.
pub fn pairs(text: &str) -> Result<Vec<(f64, f64)>, String> {
    let mut rows = Vec::new();
    let mut first = true;
    for (k, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|f| !f.is_empty())
            .collect();
        let numbers: Vec<Option<f64>> = fields.iter().map(|f| f.parse().ok()).collect();
        let header = first && numbers.iter().all(Option::is_none);
        first = false;
        if header {
            continue;
        }
        match numbers[..] {
            [Some(a), Some(b)] => rows.push((a, b)),
            _ => {
                return Err(format!(
                    "line {} {:?} is not allowed: two numbers separated by a comma or spaces",
                    k + 1,
                    cut(line)
                ))
            }
        }
    }
    Ok(rows)
}

/// A line of a file, for a message: its first 60 characters.
fn cut(line: &str) -> String {
    match line.char_indices().nth(60) {
        Some((i, _)) => format!("{}...", &line[..i]),
        None => line.to_string(),
    }
}

/// What a restitution fit fits: a model's parameter, or the table itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RestitutionLaw {
    /// A contact model: the Hunt–Crossley family its material damping constant, `thornton` its yield
    /// velocity, any other damped model one constant `e`.
    Model(Model),
    /// The table `e(v_i)`, smoothed.
    Table,
}

impl RestitutionLaw {
    /// `table`, or a model's name (the message lists what is allowed).
    pub fn parse(name: &str) -> Result<Self, String> {
        if name == "table" {
            return Ok(Self::Table);
        }
        use pounding::names::Named;
        Model::parse_name(name)
            .map(Self::Model)
            .map_err(|m| format!("{m}, or table"))
    }
}

/// Thornton's spheres, to turn a fitted yield velocity into their yield pressure.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Spheres {
    /// Radius, m.
    pub radius: f64,
    /// Hertz stiffness `(4/3) E* sqrt(R)`, N/m^1.5.
    pub stiffness: f64,
    /// Effective mass of the tests' impacts, kg.
    pub mass: f64,
}

/// What `pounding fit` found: parameters under their scenario key names, their standard errors, the
/// residual, and the lines to paste.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FitReport {
    /// `restitution` or `force-history`.
    pub kind: &'static str,
    /// The model fitted (`table` for a table).
    pub model: String,
    /// Data points used.
    pub points: usize,
    /// The fitted parameters by scenario key (a table as `{"table": [[v_i, e], ...]}`).
    pub parameters: Map<String, Value>,
    /// Their standard errors, by the same keys (a table: one per row; null where the data leave none).
    pub std_errors: Map<String, Value>,
    /// Their units, by the same keys (empty: dimensionless).
    pub units: Map<String, Value>,
    /// What else the fit found that is not a scenario key: `yield_velocity` (m/s), `touch_time` (s, on the
    /// data's clock), with `{"value", "std_error", "unit"}`.
    pub also: Map<String, Value>,
    /// Root mean square of the residuals, in `residual_unit`.
    pub rms_residual: f64,
    /// The unit of the residual: empty for `e`, `N` for a force.
    pub residual_unit: &'static str,
    /// `sqrt(sum r^2 / sum y^2)`, dimensionless.
    pub normalised_residual: f64,
    /// Lines to paste into a scenario's `[[contact]]`.
    pub scenario: Vec<String>,
    /// The fitted curve, for a figure: `e` against `v_i` (m/s), or the force (N) against time (s).
    #[serde(skip)]
    pub curve: (Vec<f64>, Vec<f64>),
}

impl FitReport {
    fn new(kind: &'static str, model: String, fit: &Fit, residual_unit: &'static str) -> Self {
        Self {
            kind,
            model,
            points: fit.points,
            parameters: Map::new(),
            std_errors: Map::new(),
            units: Map::new(),
            also: Map::new(),
            rms_residual: fit.rms_residual,
            residual_unit,
            normalised_residual: fit.normalised_residual,
            scenario: Vec::new(),
            curve: (Vec::new(), Vec::new()),
        }
    }

    /// Adds `e` as a scenario parameter (and its line to paste, with the standard error beside it).
    fn parameter(&mut self, e: &Estimate) {
        self.parameters.insert(e.key.into(), number(e.value));
        self.std_errors.insert(e.key.into(), number(e.std_error));
        self.units.insert(e.key.into(), Value::from(e.unit.clone()));
        let unit = if e.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", e.unit)
        };
        self.scenario.push(format!(
            "{} = {}   # +- {}{unit} (standard error)",
            e.key,
            fmt_sig(e.value, 6),
            fmt_sig(e.std_error, 2)
        ));
    }

    /// Adds `e` as a finding that is not a scenario key.
    fn also(&mut self, e: &Estimate) {
        self.also.insert(
            e.key.into(),
            serde_json::json!({"value": number(e.value), "std_error": number(e.std_error), "unit": e.unit}),
        );
    }
}

/// A finite number as JSON, or null.
fn number(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

/// What a restitution fit is asked.
#[derive(Clone, Debug, PartialEq)]
pub struct RestitutionRequest {
    /// What to fit.
    pub law: RestitutionLaw,
    /// A table: at most this many rows.
    pub rows: Option<usize>,
    /// A table: non-increasing in `v_i`.
    pub monotone: bool,
    /// Thornton: the spheres' radius, m.
    pub radius: Option<f64>,
    /// Thornton: their Hertz stiffness, N/m^1.5.
    pub k: Option<f64>,
    /// Thornton: the mass of the moving body in the tests, kg.
    pub m1: Option<f64>,
    /// Thornton: the mass of the body at rest, kg (infinite: a rigid slab).
    pub m2: f64,
}

impl RestitutionRequest {
    /// The request checked: table options only with a table, Thornton's spheres (all three or none) only
    /// with thornton. Errors name the option (`rows`, `radius`, `k`, `m1`).
    fn spheres(&self) -> Result<Option<Spheres>, pounding::Error> {
        let refuse = |name: &'static str, value: String, allowed: &str| {
            Err(pounding::Error::Choice {
                name,
                value,
                allowed: allowed.to_string(),
            })
        };
        if self.law != RestitutionLaw::Table {
            if let Some(r) = self.rows {
                return refuse(
                    "rows",
                    r.to_string(),
                    "with model table only: rows of the table",
                );
            }
            if self.monotone {
                return refuse("monotone", "true".into(), "with model table only");
            }
        }
        let thornton = self.law == RestitutionLaw::Model(Model::Thornton);
        match (self.radius, self.k, self.m1) {
            (None, None, None) => Ok(None),
            (r, k, m) if !thornton => {
                let (name, v) = [("radius", r), ("k", k), ("m1", m)]
                    .into_iter()
                    .find_map(|(n, v)| v.map(|v| (n, v)))
                    .unwrap_or(("radius", 0.0));
                refuse(
                    name,
                    fmt_sig(v, 6),
                    "with model thornton only: radius, k and m1 turn its yield velocity into a yield pressure",
                )
            }
            (Some(radius), Some(stiffness), Some(m1)) => {
                let bodies = pounding::impact::TwoBodies::new(m1, self.m2, 1.0)?;
                let check = |name, x: f64, allowed| {
                    if x.is_finite() && x > 0.0 {
                        Ok(x)
                    } else {
                        Err(pounding::Error::Parameter {
                            name,
                            value: x,
                            allowed,
                        })
                    }
                };
                Ok(Some(Spheres {
                    radius: check("radius", radius, "radius > 0 (m)")?,
                    stiffness: check("k", stiffness, "k > 0 (N/m^1.5)")?,
                    mass: bodies.effective_mass(),
                }))
            }
            (r, k, _) => {
                let missing = if r.is_none() {
                    "radius"
                } else if k.is_none() {
                    "k"
                } else {
                    "m1"
                };
                refuse(
                    missing,
                    "missing".into(),
                    "radius, k and m1 go together: the spheres' radius (m), Hertz stiffness (N/m^1.5) and the tests' mass (kg)",
                )
            }
        }
    }
}

/// Fits `req.law` to the `(v_i` m/s, `e)` points: a damping constant, a yield velocity (and with Thornton's
/// spheres a yield pressure), one `e`, or the table (at most `rows` rows, non-increasing if `monotone`).
pub fn restitution(
    points: &[(f64, f64)],
    req: &RestitutionRequest,
) -> Result<FitReport, pounding::Error> {
    let spheres = req.spheres()?;
    let (law, rows, monotone) = (req.law, req.rows, req.monotone);
    let v_max = points.iter().fold(0.0f64, |a, p| a.max(p.0));
    let grid: Vec<f64> = (0..=200)
        .map(|j| 1.1 * v_max * f64::from(j) / 200.0)
        .collect();
    let model = match law {
        RestitutionLaw::Table => return table(points, rows, monotone, grid),
        RestitutionLaw::Model(m) => m,
    };
    let (fit, e_of): (Fit, Box<dyn Fn(f64) -> f64>) = match model.info().formula {
        _ if !model.is_damped() && model != Model::Thornton => {
            return Err(pounding::Error::Choice {
                name: "model",
                value: model.name().into(),
                allowed: "a damped model, thornton, or table: an elastic model delivers e = 1"
                    .into(),
            })
        }
        Formula::Chi(_) => {
            let f = restitution::damping_constant(points)?;
            let c = f.estimates[0].value;
            (f, Box::new(move |v| pounding::contact::material_e(c * v)))
        }
        Formula::Thornton => {
            let f = restitution::yield_velocity(points)?;
            let v_y = f.estimates[0].value;
            (
                f,
                Box::new(move |v| pounding::contact::exact::thornton_e(v / v_y)),
            )
        }
        _ => {
            let f = restitution::constant(points)?;
            let e = f.estimates[0].value;
            (f, Box::new(move |_| e))
        }
    };
    let mut r = FitReport::new("restitution", model.name().into(), &fit, "");
    r.scenario.push(format!("model = \"{}\"", model.name()));
    let est = &fit.estimates[0];
    match (model, spheres) {
        (Model::Thornton, Some(s)) => {
            r.also(est);
            // p_y grows as v_y^(2/5) (d_y as v_y^(4/5), p_y as sqrt(d_y)).
            let p_y = yield_pressure_of(est.value, s.stiffness, s.radius, s.mass);
            let p = Estimate::new(
                "yield_pressure",
                p_y,
                0.4 * p_y * est.std_error / est.value,
                "Pa",
            );
            r.scenario
                .push(format!("radius = {}", fmt_sig(s.radius, 12)));
            r.parameter(&p);
            r.scenario.push(format!(
                "stiffness = {}\nstiffness_unit = \"N/m^1.5\"",
                fmt_sig(s.stiffness, 12)
            ));
        }
        (Model::Thornton, None) => {
            r.also(est);
            r.scenario.push(format!(
                "# yield velocity {} m/s: give the spheres' radius, Hertz stiffness and the tests' mass for the yield_pressure",
                fmt_sig(est.value, 6)
            ));
        }
        _ => r.parameter(est),
    }
    r.curve = (grid.clone(), grid.iter().map(|&v| e_of(v)).collect());
    Ok(r)
}

/// The table of the points, smoothed.
fn table(
    points: &[(f64, f64)],
    rows: Option<usize>,
    monotone: bool,
    grid: Vec<f64>,
) -> Result<FitReport, pounding::Error> {
    let (t, errors) = restitution::table(points, rows, monotone)?;
    let residuals: Vec<f64> = points.iter().map(|&(v, e)| t.at(v) - e).collect();
    let fit = Fit::new(Vec::new(), &residuals, points.iter().map(|p| p.1), 0);
    let mut r = FitReport::new("restitution", "table".into(), &fit, "");
    let rows: Vec<Value> = t
        .points()
        .iter()
        .map(|&(v, e)| Value::from(vec![number(v), number(e)]))
        .collect();
    r.parameters
        .insert("e".into(), serde_json::json!({ "table": rows }));
    r.std_errors.insert(
        "e".into(),
        Value::from(errors.iter().map(|&s| number(s)).collect::<Vec<_>>()),
    );
    r.units
        .insert("e".into(), Value::from("rows [v_i m/s, e (dimensionless)]"));
    let text: Vec<String> = t
        .points()
        .iter()
        .map(|&(v, e)| format!("[{}, {}]", fmt_sig(v, 6), fmt_sig(e, 6)))
        .collect();
    r.scenario
        .push(format!("e = {{ table = [{}] }}", text.join(", ")));
    r.curve = (grid.clone(), grid.iter().map(|&v| t.at(v)).collect());
    Ok(r)
}

/// What a force-history fit is asked: the model and its fixed options, the bodies, and what to hold.
#[derive(Clone, Debug, PartialEq)]
pub struct HistoryRequest {
    /// The model.
    pub model: Model,
    /// Mass of the moving body, kg.
    pub m1: f64,
    /// Mass of the body at rest, kg (infinite: a rigid wall or slab).
    pub m2: f64,
    /// Impact velocity, m/s.
    pub v: f64,
    /// Hold the exponent at this value.
    pub exponent: Option<f64>,
    /// Fit a material damping constant (s/m) instead of `e` (the Hunt–Crossley family).
    pub damping_constant: bool,
    /// Thornton's spheres' radius, m (required by it).
    pub radius: Option<f64>,
}

/// Fits `req.model` to the force history `data` (`(t` s, `F` N)).
pub fn force_history(
    data: &[(f64, f64)],
    req: &HistoryRequest,
) -> Result<FitReport, pounding::Error> {
    let mass = if req.m2.is_finite() {
        req.m1 * req.m2 / (req.m1 + req.m2)
    } else {
        req.m1
    };
    let thornton = req.model == Model::Thornton;
    if thornton && req.radius.is_none() {
        return Err(pounding::Error::Choice {
            name: "radius",
            value: "missing".into(),
            allowed: "model thornton needs its spheres' radius (m); the yield pressure is fitted"
                .into(),
        });
    }
    pounding::impact::TwoBodies::new(req.m1, req.m2, req.v)?;
    if let Some(n) = req.exponent {
        if !(n.is_finite() && n > 0.0) {
            return Err(pounding::Error::Parameter {
                name: "n",
                value: n,
                allowed: "n > 0",
            });
        }
    }
    if req.radius.is_some() && !thornton {
        return Err(pounding::Error::Choice {
            name: "radius",
            value: fmt_sig(req.radius.unwrap_or(0.0), 6),
            allowed: format!("thornton only, not {}", req.model.name()),
        });
    }
    if req.damping_constant && !matches!(req.model.info().formula, Formula::Chi(_)) {
        return Err(pounding::Error::Choice {
            name: "damping_constant",
            value: "true".into(),
            allowed: format!("with a model of the Hunt-Crossley family only (ye, hunt-crossley, herbert-mcwhannell, lee-wang, lankarani-nikravesh, gonthier, zhiying-qishao, flores, hertzdamp), not {}", req.model.name()),
        });
    }
    let mut options = ContactOptions {
        radius: req.radius,
        // A placeholder the fit replaces.
        yield_pressure: thornton.then_some(1.0),
        ..ContactOptions::new(req.model, 0.5)
    };
    if req.damping_constant {
        options.e = Restitution::DampingConstant(0.1);
    }
    if !req.model.is_damped() {
        options.e = Restitution::Constant(1.0);
    }
    let setup = HistorySetup {
        options,
        mass,
        v_i: req.v,
        exponent: req.exponent,
        damping_constant: req.damping_constant,
    };
    let h = pounding::fit::force_history(data, &setup)?;
    let mut r = FitReport::new("force-history", req.model.name().into(), &h.fit, "N");
    r.scenario.push(format!("model = \"{}\"", req.model.name()));
    if let Some(radius) = req.radius {
        r.scenario.push(format!("radius = {}", fmt_sig(radius, 12)));
    }
    let n = h
        .fit
        .get("exponent")
        .map_or(req.exponent.unwrap_or(req.model.info().default_n), |e| {
            e.value
        });
    for e in &h.fit.estimates {
        match e.key {
            "touch_time" => r.also(e),
            "stiffness" => {
                // In the unit of the exponent as its line shows it (the scenario checks they agree).
                let unit = fmt_unit(n);
                r.parameter(&Estimate {
                    unit: unit.clone(),
                    ..e.clone()
                });
                r.scenario.push(format!("stiffness_unit = \"{unit}\""));
            }
            _ => r.parameter(e),
        }
    }
    if let (Some(n), None) = (req.exponent, h.fit.get("exponent")) {
        if !req.model.info().n_fixed {
            r.scenario.push(format!("exponent = {}", fmt_sig(n, 12)));
        }
    }
    r.curve = h.curve;
    Ok(r)
}

/// The stiffness unit of exponent `n`, with `n` rounded as the scenario line shows it.
fn fmt_unit(n: f64) -> String {
    pounding::words::stiffness_unit(fmt_sig(n, 6).parse().unwrap_or(n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_skip_headers_comments_and_blank_lines() {
        let rows = pairs("v_m_per_s,e\n# a comment\n0.1, 0.8\n\n0.5\t0.65 # trailing\n").unwrap();
        assert_eq!(rows, vec![(0.1, 0.8), (0.5, 0.65)]);
        let e = pairs("0.1,0.8\n0.2,x\n").unwrap_err();
        assert!(e.starts_with("line 2 \"0.2,x\""), "{e}");
    }
}
