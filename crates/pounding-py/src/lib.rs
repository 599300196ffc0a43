//! The extension module `pounding._pounding`: thin bindings over `pounding-study` (scenarios, runs, sweeps,
//! the store). The Python package `pounding` (python/pounding) wraps it in numpy arrays and dicts; scenarios
//! cross as JSON text, so that a dict is validated by exactly the schema a TOML file is.

use pounding::analysis::{Results, RunOptions, Scenario};
use pounding_study::input::{dict_message, from_value, parse_value, Loaded, ScenarioFile};
use pounding_study::store::{Finished, Store, StoreError};
use pounding_study::summary::RunSummary;
use pounding_study::sweep::{self, Prepared, Progress};
use pounding_study::tables::ImpactRow;
use pyo3::create_exception;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyDict, PyList};
use serde_json::Value;
use std::io::Write as _;
use std::ops::ControlFlow;
use std::path::Path;

create_exception!(
    _pounding,
    InputError,
    PyValueError,
    "Bad input: the one-line message the command line gives (file and line, or the key's dotted path; the value; what is allowed)."
);

/// InputError with the one line the command line would print.
fn input_err(msg: impl Into<String>) -> PyErr {
    InputError::new_err(pounding_study::one_line(&msg.into(), 299))
}

fn store_err(e: StoreError) -> PyErr {
    match e {
        StoreError::Mismatch(m) => input_err(m),
        StoreError::Io(m) => PyOSError::new_err(m),
    }
}

/// A typed result (a summary, a separation or IDA report) as compact JSON text.
fn json_text(v: &impl serde::Serialize) -> PyResult<String> {
    serde_json::to_string(v).map_err(|e| input_err(format!("result: {e}")))
}

/// The error of a function's keyword arguments read as one set of parameters: `key: message`, or the
/// message alone when it names its key already (`units = "gg" is not allowed: ...`).
fn keyword_err((key, msg): (Option<String>, String)) -> PyErr {
    match key {
        Some(k) if msg.starts_with(&format!("{k}: {k} = ")) => input_err(&msg[k.len() + 2..]),
        k => input_err(dict_message(k, msg)),
    }
}

/// At most 64 characters of `s`, for a message.
fn short(s: &str) -> String {
    match s.char_indices().nth(64) {
        Some((i, _)) => format!("{}...", &s[..i]),
        None => s.to_string(),
    }
}

/// The scenario file at `path` as JSON text, a relative record `file` made absolute.
#[pyfunction]
fn load_scenario(path: &str) -> PyResult<String> {
    let file = ScenarioFile::read(Path::new(path)).map_err(|e| input_err(e.0))?;
    let mut value = file.value;
    for at in pounding_study::input::record_files(&value) {
        if let Some(Value::String(f)) = value.pointer_mut(&at) {
            if let Ok(abs) = std::path::absolute(f.as_str()) {
                *f = abs.to_string_lossy().into_owned();
            }
        }
    }
    Ok(value.to_string())
}

/// The scenario given as JSON text (`label` says where it came from) or read from `path`.
fn loaded(scenario: Option<&str>, path: Option<&str>) -> PyResult<Loaded> {
    match (scenario, path) {
        (_, Some(p)) => ScenarioFile::read(Path::new(p))
            .and_then(|f| f.load())
            .map_err(|e| input_err(e.0)),
        (Some(text), None) => {
            let value: Value = serde_json::from_str(text)
                .map_err(|e| input_err(format!("scenario: not a JSON object: {e}")))?;
            from_value(&value, "<dict>").map_err(|(k, m)| input_err(dict_message(k, m)))
        }
        (None, None) => Err(input_err("scenario: give a dict or a path")),
    }
}

/// f64 values as a bytearray (little-endian), for `numpy.frombuffer` without a further copy.
fn bytes<'py>(py: Python<'py>, xs: impl Iterator<Item = f64>) -> Bound<'py, PyByteArray> {
    let v: Vec<u8> = xs.flat_map(f64::to_le_bytes).collect();
    PyByteArray::new(py, &v)
}

/// `cols[c][k]` as samples x columns, row-major.
fn matrix<'py>(py: Python<'py>, cols: &[Vec<f64>], n: usize) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item(
        "data",
        bytes(py, (0..n).flat_map(|k| cols.iter().map(move |c| c[k]))),
    )?;
    d.set_item("shape", (n, cols.len()))?;
    Ok(d)
}

/// The impacts as columns: the rows of impacts.csv ([`ImpactRow`]) turned into lists (`e_asked` and `e_post`
/// NaN where the impact has none, the floor 0 on a wall's side).
fn impacts<'py>(py: Python<'py>, s: &Scenario, r: &Results) -> PyResult<Bound<'py, PyDict>> {
    let rows = ImpactRow::all(s, r);
    let d = PyDict::new(py);
    let num = |f: fn(&ImpactRow) -> f64| -> Vec<f64> { rows.iter().map(f).collect() };
    let floor = |f: fn(&ImpactRow) -> Option<usize>| -> Vec<usize> {
        rows.iter().map(|i| f(i).unwrap_or(0)).collect()
    };
    d.set_item("time_s", num(|i| i.time_s))?;
    d.set_item(
        "contact",
        rows.iter().map(|i| i.contact.as_str()).collect::<Vec<_>>(),
    )?;
    d.set_item("floor_left", floor(|i| i.floor_left))?;
    d.set_item("floor_right", floor(|i| i.floor_right))?;
    d.set_item(
        "layer",
        rows.iter().map(|i| i.layer.name()).collect::<Vec<_>>(),
    )?;
    d.set_item("v_i_m_per_s", num(|i| i.v_i_m_per_s))?;
    d.set_item("e_asked", num(|i| i.e_asked.unwrap_or(f64::NAN)))?;
    d.set_item("e_post", num(|i| i.e_post.unwrap_or(f64::NAN)))?;
    d.set_item("peak_force_N", num(|i| i.peak_force_n))?;
    d.set_item("time_of_peak_force_s", num(|i| i.time_of_peak_force_s))?;
    d.set_item("duration_s", num(|i| i.duration_s))?;
    d.set_item("dissipated_energy_J", num(|i| i.dissipated_energy_j))?;
    d.set_item("max_penetration_m", num(|i| i.max_penetration_m))?;
    d.set_item("ended", rows.iter().map(|i| i.ended).collect::<Vec<_>>())?;
    d.set_item(
        "resting",
        rows.iter().map(|i| i.resting).collect::<Vec<_>>(),
    )?;
    // Between buildings in plan, the point at rest; NaN in one line.
    d.set_item("point_x_m", num(|i| i.point_x_m.unwrap_or(f64::NAN)))?;
    d.set_item("point_y_m", num(|i| i.point_y_m.unwrap_or(f64::NAN)))?;
    Ok(d)
}

/// The histories: time and ground acceleration; per building, floor displacements, absolute accelerations and
/// storey shears (samples x floors); per site (contact or wall), the force of each level (samples x levels)
/// and its levels; per device, the force of each floor pair; energies.
fn histories<'py>(py: Python<'py>, s: &Scenario, r: &Results) -> PyResult<Bound<'py, PyDict>> {
    let h = &r.histories;
    let n = h.t.len();
    let d = PyDict::new(py);
    d.set_item("time", bytes(py, h.t.iter().copied()))?;
    d.set_item(
        "ground_acceleration",
        bytes(py, h.ground_acceleration.iter().copied()),
    )?;
    for (key, group) in [
        ("displacement", &h.displacement),
        ("absolute_acceleration", &h.absolute_acceleration),
        ("storey_shear", &h.storey_shear),
    ] {
        let g = PyDict::new(py);
        for (b, cols) in s.buildings().iter().zip(group) {
            g.set_item(&b.name, matrix(py, cols, n)?)?;
        }
        d.set_item(key, g)?;
    }
    // Buildings in plan: their mass centres along y and their rotations; the ground along y.
    for (key, group) in [
        ("displacement_y", &h.displacement_y),
        ("rotation", &h.rotation),
    ] {
        let g = PyDict::new(py);
        for (b, cols) in s.buildings().iter().zip(group) {
            if b.structure.plan().is_some() {
                g.set_item(&b.name, matrix(py, cols, n)?)?;
            }
        }
        d.set_item(key, g)?;
    }
    d.set_item(
        "ground_acceleration_y",
        bytes(py, h.ground_acceleration_y.iter().copied()),
    )?;
    // Buildings on a foundation: its sway and rocking (samples x 2).
    let g = PyDict::new(py);
    for (b, cols) in s.buildings().iter().zip(&h.foundation) {
        if b.structure.foundation().is_some() {
            g.set_item(&b.name, matrix(py, cols, n)?)?;
        }
    }
    d.set_item("foundation", g)?;
    // Every site alike (contacts and walls): its force per level, and its levels as (left, right) floors,
    // None on a wall's side.
    let (f, levels) = (PyDict::new(py), PyDict::new(py));
    for (site, cols) in s.sites().iter().zip(&h.site_force) {
        f.set_item(&site.name, matrix(py, cols, n)?)?;
        let lv: Vec<(Option<usize>, Option<usize>)> =
            site.levels.iter().map(|l| (l.left, l.right)).collect();
        levels.set_item(&site.name, lv)?;
    }
    d.set_item("site_force", f)?;
    d.set_item("site_levels", levels)?;
    let (df, dfl) = (PyDict::new(py), PyDict::new(py));
    for (dv, cols) in s.devices().iter().zip(&h.device_force) {
        df.set_item(&dv.name, matrix(py, cols, n)?)?;
        dfl.set_item(&dv.name, dv.floors.clone())?;
    }
    d.set_item("device_force", df)?;
    d.set_item("device_floors", dfl)?;
    let e = PyDict::new(py);
    for (c, name) in [
        "input",
        "kinetic",
        "strain",
        "structural_damping",
        "hysteretic",
        "contact",
    ]
    .iter()
    .enumerate()
    {
        e.set_item(*name, bytes(py, h.energy[c].iter().copied()))?;
    }
    d.set_item("energy", e)?;
    Ok(d)
}

/// Runs one scenario (JSON text, or the file at `path`) with the GIL released; returns a dict with
/// `summary` (JSON text), `impacts` (columns) and `histories` (or None). Ctrl-C stops it (KeyboardInterrupt).
#[pyfunction]
#[pyo3(signature = (scenario=None, path=None, histories=true))]
fn run<'py>(
    py: Python<'py>,
    scenario: Option<&str>,
    path: Option<&str>,
    histories: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let loaded = loaded(scenario, path)?;
    let options = RunOptions {
        histories,
        ..RunOptions::default()
    };
    let mut interrupted = None;
    let results = py.allow_threads(|| {
        let mut go_on = ctrl_c(&mut interrupted);
        loaded.scenario.run_with_options(&options, &mut |_| go_on())
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let results = results.map_err(|e| input_err(format!("analysis failed: {e}")))?;
    let summary = RunSummary::new(&loaded, &results).map_err(input_err)?;
    let out = PyDict::new(py);
    out.set_item("summary", json_text(&summary)?)?;
    out.set_item("impacts", impacts(py, &loaded.scenario, &results)?)?;
    if histories {
        out.set_item(
            "histories",
            self::histories(py, &loaded.scenario, &results)?,
        )?;
    } else {
        out.set_item("histories", py.None())?;
    }
    Ok(out)
}

/// Parses and keys the scenarios (JSON texts, with labels) on `workers` threads, the GIL released.
fn prepare(
    py: Python<'_>,
    scenarios: Vec<String>,
    labels: Vec<String>,
    workers: usize,
) -> Vec<Prepared> {
    py.allow_threads(|| {
        let values = scenarios
            .into_iter()
            .zip(labels)
            .map(|(s, l)| (serde_json::from_str(&s).unwrap_or(Value::Null), l))
            .collect();
        sweep::prepare(values, workers)
    })
}

/// The keys of the scenarios and the study's id: `(keys, id)`.
#[pyfunction]
fn keys(py: Python<'_>, scenarios: Vec<String>) -> (Vec<String>, String) {
    let n = scenarios.len();
    let p = prepare(py, scenarios, vec![String::new(); n], 1);
    let id = sweep::study_id(&p);
    (p.into_iter().map(|p| p.key).collect(), id)
}

/// A callback for long work on this (the calling) thread with the GIL released: Ctrl-C reaches Python only
/// with the GIL, so it takes the GIL and looks for a signal at most every 0.1 s; a KeyboardInterrupt is kept
/// in `interrupted` and the work told to stop.
fn ctrl_c(interrupted: &mut Option<PyErr>) -> impl FnMut() -> ControlFlow<()> + '_ {
    let mut last = std::time::Instant::now();
    move || {
        if last.elapsed().as_secs_f64() < 0.1 {
            return ControlFlow::Continue(());
        }
        last = std::time::Instant::now();
        match Python::with_gil(|py| py.check_signals()) {
            Ok(()) => ControlFlow::Continue(()),
            Err(e) => {
                *interrupted = Some(e);
                ControlFlow::Break(())
            }
        }
    }
}

/// A one-line progress report on stderr: `runs 1234/10000, 3 failed, 12.3 s, about 4 s left`.
fn show(p: &Progress, end: bool) {
    let rate = p.done as f64 / p.elapsed.max(1e-9);
    let left = if p.done > 0 {
        format!(", about {:.0} s left", (p.todo - p.done) as f64 / rate)
    } else {
        String::new()
    };
    let mut err = std::io::stderr().lock();
    let _ = write!(
        err,
        "\rpounding sweep: {}/{} runs, {} failed, {} from the store, {:.1} s{}   ",
        p.done, p.todo, p.failed, p.skipped, p.elapsed, left
    );
    if end {
        let _ = writeln!(err);
    }
}

/// A sweep's progress callback: the line on stderr if `progress`, and Ctrl-C, which reaches Python only with
/// the GIL, looked for at every report (the error is kept in `interrupted` and the sweep stops).
fn reporter(
    progress: bool,
    interrupted: &mut Option<PyErr>,
) -> impl FnMut(Progress) -> ControlFlow<()> + '_ {
    move |p: Progress| {
        if progress {
            show(&p, false);
        }
        match Python::with_gil(|py| py.check_signals()) {
            Ok(()) => ControlFlow::Continue(()),
            Err(e) => {
                *interrupted = Some(e);
                ControlFlow::Break(())
            }
        }
    }
}

/// Runs the scenarios (JSON texts, with labels) on `workers` threads with the GIL released, committing each
/// finished run to the store at `store` if given; returns `(key, ok, summary JSON or error message)` in input
/// order. Ctrl-C stops the sweep (finished runs stay in the store) and raises KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (scenarios, labels, workers, store=None, progress=false))]
fn sweep_runs(
    py: Python<'_>,
    scenarios: Vec<String>,
    labels: Vec<String>,
    workers: usize,
    store: Option<&str>,
    progress: bool,
) -> PyResult<Vec<(String, bool, String)>> {
    let workers = sweep::check_workers("workers =", workers).map_err(input_err)?;
    let values: Vec<(Value, String)> = scenarios
        .iter()
        .zip(labels)
        .map(|(s, l)| (serde_json::from_str(s).unwrap_or(Value::Null), l))
        .collect();
    let mut st = match store {
        Some(path) => {
            // A list of scenarios is known by its runs' keys.
            let prepared = py.allow_threads(|| sweep::prepare(values.clone(), workers));
            let id = sweep::study_id(&prepared);
            let keys: Vec<String> = prepared.into_iter().map(|p| p.key).collect();
            Some(
                Store::open(Path::new(path), &id, values.len(), &|| keys.clone())
                    .map_err(store_err)?,
            )
        }
        None => None,
    };
    let mut interrupted: Option<PyErr> = None;
    let swept = py.allow_threads(|| {
        let mut report = reporter(progress, &mut interrupted);
        let r = sweep::run(
            values.len(),
            &|i| values[i].clone(),
            workers,
            &RunOptions::summary_only(),
            st.as_mut(),
            &mut report,
        );
        if progress {
            eprintln!();
        }
        r
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let swept = swept.map_err(|e| PyOSError::new_err(e.to_string()))?;
    (0..values.len())
        .map(|i| {
            let o = swept.outcome(i, st.as_ref()).map_err(store_err)?;
            Ok(match o {
                // Summaries whole, as a single run gives them (a store's rows leave out the units).
                Ok(text) => (swept.key(i), true, RunSummary::row_to_whole(&text)),
                Err(e) => (swept.key(i), false, e),
            })
        })
        .collect()
}

/// A study store opened from Python (for sweeps whose runs happen elsewhere, as on a Dask cluster).
#[pyclass(name = "Store", unsendable)]
struct PyStore {
    store: Store,
}

#[pymethods]
impl PyStore {
    /// Opens (or creates) the store at `path` of the study `id` whose runs have `keys` (in order); an earlier
    /// study's store whose every run is among them grows into this one's; InputError if it holds another
    /// study.
    #[new]
    fn new(path: &str, id: &str, keys: Vec<String>) -> PyResult<Self> {
        Ok(PyStore {
            store: Store::open(Path::new(path), id, keys.len(), &|| keys.clone())
                .map_err(store_err)?,
        })
    }

    /// Every stored run: `(key, ok, summary JSON or error message)`. A stored row that is damaged (its digest
    /// does not match) or whose summary does not read back as one is left out, so that the run is run again and replaced,
    /// as a local sweep does.
    fn finished(&self) -> PyResult<Vec<(String, bool, String)>> {
        Ok(self
            .store
            .all()
            .map_err(store_err)?
            .into_iter()
            .filter_map(|row| {
                let key = row.key.clone();
                let text = match &row.outcome {
                    Ok(s) => RunSummary::row_to_whole(s),
                    Err(s) => s.clone(),
                };
                sweep::trusted(row).map(|o| (key, o.is_ok(), text))
            })
            .collect())
    }

    /// Commits runs `(key, index, ok, summary JSON or error message, seconds)` in one transaction.
    fn commit(&mut self, runs: Vec<(String, usize, bool, String, f64)>) -> PyResult<()> {
        let runs: Vec<Finished> = runs
            .into_iter()
            .map(|(key, index, ok, text, seconds)| Finished {
                key,
                index,
                outcome: if ok {
                    Ok(RunSummary::whole_to_row(&text))
                } else {
                    Err(text)
                },
                seconds,
            })
            .collect();
        self.store.commit(&runs).map_err(store_err)
    }
}

/// The headline results of a summary (JSON text) as `(column, value)` pairs, as in runs.csv: counts as
/// integers, numbers as floats. A summary that does not read as one raises InputError naming the key.
#[pyfunction]
fn headline(py: Python<'_>, summary: &str) -> PyResult<Py<PyList>> {
    use pounding_study::headline::Cell;
    let value: Value =
        serde_json::from_str(summary).map_err(|e| input_err(format!("summary: not JSON: {e}")))?;
    // Read as RunSummary::from_json reads it, with the key that does not fit as a dotted path.
    let s: RunSummary = parse_value(&value).map_err(|(k, m)| match k {
        Some(k) if !k.is_empty() => input_err(format!("summary.{m}")),
        _ => input_err(format!("summary: {m}")),
    })?;
    let out = PyList::empty(py);
    for (k, v) in pounding_study::headline::headline(&s) {
        match v {
            Cell::Count(n) => out.append((k, n))?,
            Cell::Number(x) => out.append((k, x))?,
        }
    }
    Ok(out.unbind())
}

/// Whether `name` is a built-in record (`el-centro-1940`, `synthetic-SEED`): the library's one list.
fn is_builtin(name: &str) -> bool {
    pounding::ground_motion::Builtin::from_name(name).is_some()
}

/// The elastic spectrum of the record `source` (a built-in record's name, else a file's path, as the command
/// line decides; `format`, `dt`, `units` and `scale` as in a scenario's `[ground_motion]`) for `damping` at
/// `periods` (s): `(sd, psv, psa)` in m, m/s, m/s^2.
#[pyfunction]
#[pyo3(signature = (source, damping, periods, format=None, dt=None, units=None, scale=1.0))]
#[allow(clippy::too_many_arguments)]
fn spectrum(
    py: Python<'_>,
    source: &str,
    damping: f64,
    periods: Vec<f64>,
    format: Option<&str>,
    dt: Option<f64>,
    units: Option<&str>,
    scale: f64,
) -> PyResult<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let r = load_source(source, format, dt, units, scale)?;
    let mut interrupted = None;
    let s = py.allow_threads(|| {
        pounding::ground_motion::spectrum::spectrum_with(
            &r,
            damping,
            &periods,
            &mut ctrl_c(&mut interrupted),
        )
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let s = s.map_err(|e| input_err(e.to_string()))?;
    Ok((s.sd, s.psv, s.psa))
}

/// The record `source` (a built-in record's name, else a file's path, as the command line decides), read with
/// `format`, `dt`, `units` and `scale` as in a scenario's `[ground_motion]`.
fn load_source(
    source: &str,
    format: Option<&str>,
    dt: Option<f64>,
    units: Option<&str>,
    scale: f64,
) -> PyResult<pounding::ground_motion::Record> {
    let mut gm = serde_json::Map::new();
    let kind = if is_builtin(source) { "record" } else { "file" };
    gm.insert(kind.into(), source.into());
    if let Some(f) = format {
        gm.insert("format".into(), f.into());
    }
    if let Some(dt) = dt {
        gm.insert("dt".into(), dt.into());
    }
    if let Some(u) = units {
        gm.insert("units".into(), u.into());
    }
    gm.insert("scale".into(), scale.into());
    let doc: pounding::scenario::GroundMotionDoc =
        parse_value(&Value::Object(gm)).map_err(keyword_err)?;
    let spec = doc.spec().map_err(|e| input_err(e.message))?;
    pounding_study::input::read_record(&spec)
        .and_then(|r| {
            r.scaled(spec.scale)
                .map_err(pounding::ground_motion::RecordError::Value)
        })
        .map_err(|e| input_err(pounding_study::input::record_message(&spec, e)))
}

/// The separation report (JSON text) of a scenario (JSON text, or the file at `path`) under its record or
/// each of `records`; `aligned_factor` multiplies the rules at aligned floors.
#[pyfunction]
#[pyo3(signature = (scenario=None, path=None, records=Vec::new(), aligned_factor=None, options=None))]
fn separation(
    py: Python<'_>,
    scenario: Option<&str>,
    path: Option<&str>,
    records: Vec<String>,
    aligned_factor: Option<f64>,
    options: Option<&str>,
) -> PyResult<String> {
    let (value, label) = match (scenario, path) {
        (_, Some(p)) => {
            let file = ScenarioFile::read(Path::new(p)).map_err(|e| input_err(e.0))?;
            file.load().map_err(|e| input_err(e.0))?;
            (file.value, p.to_string())
        }
        (Some(text), None) => (
            serde_json::from_str(text)
                .map_err(|e| input_err(format!("scenario: not a JSON object: {e}")))?,
            "<dict>".to_string(),
        ),
        (None, None) => return Err(input_err("scenario: give a dict or a path")),
    };
    let doc: Value = match options {
        Some(text) => serde_json::from_str(text)
            .map_err(|e| input_err(format!("options: not a JSON object: {e}")))?,
        None => Value::Object(serde_json::Map::new()),
    };
    let options = pounding_study::separation::options_from_json(&doc, records, aligned_factor)
        .map_err(|r| input_err(pounding_study::separation::message(r)))?;
    let mut interrupted = None;
    let v = py.allow_threads(|| {
        pounding_study::separation::report_with(
            &value,
            &label,
            &options,
            &mut ctrl_c(&mut interrupted),
        )
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let v = v.map_err(|r| input_err(pounding_study::separation::message(r)))?;
    json_text(&v)
}

/// The largest `workers` a sweep or an IDA takes on this machine (16 per core).
#[pyfunction]
fn max_workers() -> usize {
    sweep::MAX_WORKERS_PER_CORE * std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// A random-number seed given from Python: a whole number from 0 to 2^64 - 1.
fn seed_of(seed: &Bound<'_, PyAny>) -> PyResult<u64> {
    seed.extract().map_err(|_| {
        input_err(format!(
            "seed = {} is not allowed: a whole number from 0 to 2^64 - 1",
            short(&seed.repr().map_or_else(|_| "?".into(), |r| r.to_string()))
        ))
    })
}

/// A synthetic record (docs/separation.md): `seed` (a whole number from 0 to 2^64 - 1) and the parameters
/// as JSON text, read as the library's [`SyntheticParams`](pounding::ground_motion::synthetic::SyntheticParams)
/// (`filter`, `wg`, `zg`, `wf`, `zf`, `duration`, `dt`, `t1`, `t2`, `decay`, `pga`; each absent one keeps its
/// default); returns `(dt, t0, accelerations)` in s and m/s^2.
#[pyfunction]
fn synthetic(seed: &Bound<'_, PyAny>, params: &str) -> PyResult<(f64, f64, Vec<f64>)> {
    use pounding::ground_motion::synthetic::SyntheticParams;
    let seed = seed_of(seed)?;
    let value: Value = serde_json::from_str(params).map_err(|e| input_err(e.to_string()))?;
    let p: SyntheticParams = parse_value(&value).map_err(keyword_err)?;
    let r = p
        .synthetic()
        .record("synthetic", seed)
        .map_err(|e| input_err(e.to_string()))?;
    Ok((r.dt(), r.t0(), r.accelerations().to_vec()))
}

/// Records at supports that lose coherence with distance (docs/structures.md): `seed`, the supports'
/// `positions` (m), the coherency model as JSON text (`{"model": "luco-wong", "alpha": ...}` or
/// `{"model": "harichandran-vanmarcke", "A", "a", "k", "f0", "b"}`, each absent one SMART-1 event 20's) and the
/// spectrum's parameters as [`synthetic`]'s, or the record `record` they are conditioned on (its `units`, and
/// the `window` of its envelope, s, and the `low_cut` of its simulated parts, Hz); returns `(dt, t0, [accelerations per support])`, s and m/s^2.
#[pyfunction]
#[pyo3(signature = (seed, positions, coherency, params, record=None, units=None, window=2.0, low_cut=0.1))]
#[allow(clippy::too_many_arguments)]
fn coherent(
    seed: &Bound<'_, PyAny>,
    positions: Vec<f64>,
    coherency: &str,
    params: &str,
    record: Option<&str>,
    units: Option<&str>,
    window: f64,
    low_cut: f64,
) -> PyResult<(f64, f64, Vec<Vec<f64>>)> {
    use pounding::ground_motion::coherency::{Coherency, Spatial};
    use pounding::ground_motion::conditional::Conditioned;
    use pounding::ground_motion::synthetic::SyntheticParams;
    let seed = seed_of(seed)?;
    let value: Value = serde_json::from_str(params).map_err(|e| input_err(e.to_string()))?;
    let p: SyntheticParams = parse_value(&value).map_err(keyword_err)?;
    if record.is_some() && value.as_object().is_some_and(|o| !o.is_empty()) {
        return Err(input_err(format!(
            "record = {} with a spectrum's parameters ({}): allowed: one or the other (the record brings its own spectrum)",
            short(record.unwrap_or_default()),
            short(&value.to_string())
        )));
    }
    let c: Value = serde_json::from_str(coherency).map_err(|e| input_err(e.to_string()))?;
    let num = |k: &str| c.get(k).and_then(Value::as_f64);
    let coherency = match c.get("model").and_then(Value::as_str) {
        Some("luco-wong") => match c.get("alpha").and_then(Value::as_f64) {
            Some(alpha) => Coherency::LucoWong { alpha },
            None => return Err(input_err(
                "alpha is required with model = \"luco-wong\": the incoherence, s/m (e.g. 2.5e-4)",
            )),
        },
        Some("harichandran-vanmarcke") => {
            Coherency::harichandran_vanmarcke(num("A"), num("a"), num("k"), num("f0"), num("b"))
        }
        other => {
            return Err(input_err(format!(
                "model = {} is not allowed: \"luco-wong\" or \"harichandran-vanmarcke\"",
                short(&format!("{other:?}"))
            )))
        }
    };
    let rs = match record {
        Some(source) => Conditioned {
            record: load_source(source, None, None, units, 1.0)?,
            coherency,
            positions,
            window,
            low_cut,
        }
        .records("support", seed),
        None => Spatial {
            synthetic: p.synthetic(),
            coherency,
            positions,
        }
        .records("support", seed),
    }
    .map_err(|e| input_err(e.to_string()))?;
    Ok((
        rs[0].dt(),
        rs[0].t0(),
        rs.iter().map(|r| r.accelerations().to_vec()).collect(),
    ))
}

/// Runs the IDA study at `study` into `out` (study.sqlite, runs.csv, fragility.csv) on `workers` threads with
/// the GIL released; returns the result as JSON text.
#[pyfunction]
#[pyo3(signature = (study, out, workers, progress=false))]
fn ida(py: Python<'_>, study: &str, out: &str, workers: usize, progress: bool) -> PyResult<String> {
    use pounding_study::ida::{run, Ida, IdaError};
    let workers = sweep::check_workers("workers =", workers).map_err(input_err)?;
    let ida = Ida::read(Path::new(study)).map_err(|e| input_err(e.0))?;
    let mut interrupted: Option<PyErr> = None;
    let r = py.allow_threads(|| {
        let mut report = reporter(progress, &mut interrupted);
        let r = run(&ida, Path::new(out), workers, &mut report);
        if progress {
            eprintln!();
        }
        r
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    match r {
        Ok(o) => json_text(&o.json),
        Err(IdaError::Input(e)) => Err(input_err(e.0)),
        Err(IdaError::Io(m)) => Err(PyOSError::new_err(m)),
        // Only Ctrl-C cancels, and it was raised above.
        Err(IdaError::Cancelled) => Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(
            "every run that finished is in the store",
        )),
    }
}

/// The pairs of `points`, or of the two-column text file at `path` (`what` names the columns in messages).
fn fit_data(
    points: Option<Vec<(f64, f64)>>,
    path: Option<&str>,
    what: &str,
) -> PyResult<Vec<(f64, f64)>> {
    match (points, path) {
        (Some(p), _) => Ok(p),
        (None, Some(path)) => {
            // As a scenario file that cannot be read: InputError (the command line's exit 2).
            let text = pounding_study::input::read_text_file(
                Path::new(path),
                "data file",
                pounding_study::input::DATA_FILE_LIMIT,
            )
            .map_err(input_err)?;
            pounding_study::fit::pairs(&text)
                .map_err(|e| input_err(format!("{path}: {e} ({what})")))
        }
        (None, None) => Err(input_err("data: give a path or pairs")),
    }
}

/// A refused fit, as one line naming the option by its keyword.
fn fit_err(e: pounding::Error) -> PyErr {
    match e {
        pounding::Error::Choice {
            name,
            value,
            allowed,
        } if value == "missing" => input_err(format!("{name} is required: {allowed}")),
        other => input_err(other.to_string()),
    }
}

/// A restitution fit (`pounding fit restitution`) of `points` or the file at `path`: the report as JSON text,
/// and the fitted curve (v_i in m/s, e).
#[pyfunction]
#[pyo3(signature = (model, points=None, path=None, rows=None, monotone=false, radius=None, k=None, m1=None, m2=f64::INFINITY))]
#[allow(clippy::too_many_arguments)]
fn fit_restitution(
    model: &str,
    points: Option<Vec<(f64, f64)>>,
    path: Option<&str>,
    rows: Option<usize>,
    monotone: bool,
    radius: Option<f64>,
    k: Option<f64>,
    m1: Option<f64>,
    m2: f64,
) -> PyResult<(String, Vec<f64>, Vec<f64>)> {
    use pounding_study::fit::{RestitutionLaw, RestitutionRequest};
    let law = RestitutionLaw::parse(model).map_err(input_err)?;
    let data = fit_data(points, path, "v_i in m/s, then e")?;
    let req = RestitutionRequest {
        law,
        rows,
        monotone,
        radius,
        k,
        m1,
        m2,
    };
    let r = pounding_study::fit::restitution(&data, &req).map_err(fit_err)?;
    Ok((json_text(&r)?, r.curve.0, r.curve.1))
}

/// A force-history fit (`pounding fit force-history`) of `data` or the file at `path`: the report as JSON
/// text, and the fitted curve (time in s, force in N).
#[pyfunction]
#[pyo3(signature = (model, m1, v, data=None, path=None, m2=f64::INFINITY, n=None, damping_constant=false, radius=None))]
#[allow(clippy::too_many_arguments)]
fn fit_force_history(
    py: Python<'_>,
    model: &str,
    m1: f64,
    v: f64,
    data: Option<Vec<(f64, f64)>>,
    path: Option<&str>,
    m2: f64,
    n: Option<f64>,
    damping_constant: bool,
    radius: Option<f64>,
) -> PyResult<(String, Vec<f64>, Vec<f64>)> {
    use pounding::names::Named;
    let model = pounding::contact::Model::parse_name(model).map_err(input_err)?;
    let data = fit_data(data, path, "time in s, then force in N")?;
    let req = pounding_study::fit::HistoryRequest {
        model,
        m1,
        m2,
        v,
        exponent: n,
        damping_constant,
        radius,
    };
    let r = py
        .allow_threads(|| pounding_study::fit::force_history(&data, &req))
        .map_err(fit_err)?;
    Ok((json_text(&r)?, r.curve.0, r.curve.1))
}

/// The extension module.
#[pymodule]
fn _pounding(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("InputError", m.py().get_type::<InputError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(load_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(keys, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_runs, m)?)?;
    m.add_function(wrap_pyfunction!(headline, m)?)?;
    m.add_function(wrap_pyfunction!(spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(separation, m)?)?;
    m.add_function(wrap_pyfunction!(synthetic, m)?)?;
    m.add_function(wrap_pyfunction!(coherent, m)?)?;
    m.add_function(wrap_pyfunction!(max_workers, m)?)?;
    m.add_function(wrap_pyfunction!(ida, m)?)?;
    m.add_function(wrap_pyfunction!(fit_restitution, m)?)?;
    m.add_function(wrap_pyfunction!(fit_force_history, m)?)?;
    m.add_class::<PyStore>()?;
    Ok(())
}
