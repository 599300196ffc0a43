//! A study file (TOML): a base scenario and axes, expanded into the scenarios of a sweep.
//!
//! ```toml
//! scenario = "two-sdof.toml"          # the base scenario, relative to the study file
//! [axes]
//! record = ["el-centro-1940", "records/*.AT2"]   # built-ins, files, folders (every file in it), globs
//! scale = [0.5, 1.0, 2.0]             # ground_motion.scale
//! contact.0.gap = [0.005, 0.01, 0.02] # any scenario key, by dotted path (list entries from 0)
//! "contact.0.model" = ["papi", "hertzdamp"]
//! ```
//!
//! The axes combine as their Cartesian product (the last axis varies fastest), or, with `[[run]]` entries in
//! place of `[axes]`, as an explicit list: each entry sets the keys it names.

use crate::input::{read_text_file, ScenarioFile, SCENARIO_FILE_LIMIT};
use crate::InputError;
use serde_json::{Map, Value};
use std::path::{Path, PathBuf};

/// One axis of a study: a name (`record`, `scale` or a dotted scenario key) and its values.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// `record`, `scale` or the dotted key path.
    pub name: String,
    /// The values, as written (a record's value is its source: a built-in's name or a file's path).
    pub values: Vec<Value>,
}

/// One scenario of a study.
#[derive(Clone, Debug, PartialEq)]
pub struct Variant {
    /// The scenario.
    pub value: Value,
    /// The value of each axis (in [`Study::axes`] order), as shown in `runs.csv`.
    pub coords: Vec<String>,
}

/// A study read from its file. Its runs are made on demand ([`Study::scenario`]), so that a study of
/// millions of runs starts at once and holds no more than its definition.
#[derive(Clone, Debug)]
pub struct Study {
    /// The study file.
    pub path: PathBuf,
    /// The base scenario file.
    pub base: PathBuf,
    /// The axes (for an explicit list: every key any entry sets).
    pub axes: Vec<Axis>,
    runs: Runs,
}

/// How a study's runs are made.
#[derive(Clone, Debug)]
enum Runs {
    /// The Cartesian product of the axes over the base scenario (the last axis varying fastest).
    Product { base: Value, len: usize },
    /// An explicit list of `[[run]]` entries.
    List(Vec<Variant>),
}

/// Largest number of runs in one study.
pub const MAX_RUNS: usize = 10_000_000;

fn err(path: &Path, msg: impl std::fmt::Display) -> InputError {
    InputError::new(format!("{}: {msg}", path.display()))
}

/// `table` with nested tables flattened into dotted keys (`contact.0.gap = [...]` is written as nested
/// tables by TOML). A leaf is anything but a table.
fn flatten(prefix: &str, table: &Map<String, Value>, out: &mut Vec<(String, Value)>) {
    for (k, v) in table {
        let key = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        match v {
            Value::Object(t) => flatten(&key, t, out),
            other => out.push((key, other.clone())),
        }
    }
}

/// Where each axis of the study text's `[axes]` is written (the byte offset of its value), by dotted name.
fn written_order(text: &str) -> std::collections::HashMap<String, usize> {
    fn walk(
        prefix: &str,
        item: &toml_edit::Item,
        out: &mut std::collections::HashMap<String, usize>,
    ) {
        // Tables, dotted or inline, hold axes; anything else is one.
        let entries: Vec<(&str, &toml_edit::Item)> = match item.as_table_like() {
            Some(t) => t.iter().collect(),
            None => {
                if let Some(span) = item.span() {
                    out.insert(prefix.to_string(), span.start);
                }
                return;
            }
        };
        for (k, v) in entries {
            let key = if prefix.is_empty() {
                k.to_string()
            } else {
                format!("{prefix}.{k}")
            };
            walk(&key, v, out);
        }
    }
    let mut out = std::collections::HashMap::new();
    if let Ok(doc) = toml_edit::ImDocument::parse(text) {
        if let Some(axes) = doc.as_item().get("axes") {
            walk("", axes, &mut out);
        }
    }
    out
}

/// Sets the key at dotted `path` of `value` to `new`. Entries of lists must exist; a missing table on the way
/// is created (the schema then says whether its key exists).
fn set_path(value: &mut Value, path: &str, new: Value) -> Result<(), String> {
    let parts: Vec<&str> = path.split('.').collect();
    let mut cur = value;
    for (n, part) in parts.iter().enumerate() {
        let last = n + 1 == parts.len();
        cur = match cur {
            Value::Array(a) => {
                let i: usize = part
                    .parse()
                    .map_err(|_| format!("{part:?} is not an entry number of a list"))?;
                let len = a.len();
                a.get_mut(i).ok_or_else(|| {
                    format!(
                        "the base scenario has {len} entries there (numbered from 0), not {}",
                        i + 1
                    )
                })?
            }
            Value::Object(m) => {
                if last {
                    m.insert(part.to_string(), new);
                    return Ok(());
                }
                m.entry(part.to_string())
                    .or_insert_with(|| Value::Object(Map::new()))
            }
            _ => return Err(format!("{part:?} is inside a value, not a table or list")),
        };
        if last {
            *cur = new;
            return Ok(());
        }
    }
    Ok(())
}

/// Why a `record` value names no record: the value as given, and why, worded to follow the value's name
/// (`record = "kobe" is not allowed: ...` in a study, `--records kobe is not allowed: ...` on the command
/// line).
#[derive(Clone, Debug, PartialEq)]
pub struct SourceError {
    /// The value as given.
    pub given: Value,
    /// What is wrong with it and what is allowed: `is not allowed: ...`.
    pub why: String,
}

impl SourceError {
    fn new(given: &str, why: impl Into<String>) -> Self {
        Self {
            given: Value::String(given.to_string()),
            why: why.into(),
        }
    }

    /// The message with the value named `shown` (`--records kobe`).
    pub fn named(&self, shown: &str) -> String {
        format!("{shown} {}", self.why)
    }
}

impl std::fmt::Display for SourceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.given {
            Value::String(s) => write!(f, "record = {s:?} {}", self.why),
            v => write!(f, "record = {v} {}", self.why),
        }
    }
}

/// A record file's path as text; a name that is not UTF-8 (a scenario, JSON, holds only UTF-8 text) is an
/// error about `given`, the value that named it.
fn utf8_name(given: &str, f: PathBuf) -> Result<String, SourceError> {
    f.into_os_string().into_string().map_err(|os| {
        SourceError::new(
            given,
            format!("is not allowed: it names {os:?}, a file name that is not UTF-8; allowed: UTF-8 file names (rename the file)"),
        )
    })
}

/// The record sources a `record` axis value names, relative to `dir`: a built-in, a file, every file of a
/// folder, or the files a glob matches (sorted).
pub fn record_sources(dir: &Path, v: &Value) -> Result<Vec<String>, SourceError> {
    let Value::String(s) = v else {
        return Err(SourceError {
            given: v.clone(),
            why: "is not allowed: a built-in name, a file, a folder or a glob".into(),
        });
    };
    if pounding::ground_motion::Builtin::from_name(s).is_some() {
        return Ok(vec![s.clone()]);
    }
    // A suite of synthetic records: `synthetic-1..20` (both ends included).
    if let Some((a, b)) = s
        .strip_prefix("synthetic-")
        .and_then(|r| r.split_once(".."))
    {
        let (a, b): (u64, u64) = match (a.parse(), b.parse()) {
            (Ok(a), Ok(b)) if a <= b && b - a < 100_000 => (a, b),
            _ => {
                return Err(SourceError::new(
                    s,
                    "is not allowed: synthetic-FIRST..LAST with 0 <= FIRST <= LAST, at most 100000 records",
                ))
            }
        };
        return Ok((a..=b).map(|k| format!("synthetic-{k}")).collect());
    }
    let p = dir.join(s);
    if s.contains(['*', '?', '[']) {
        let pattern = p.to_string_lossy().into_owned();
        // The glob crate passes over names that are not UTF-8: the folder of a pattern whose wildcards are in
        // its last part is read for them, so that no record of a suite is left out without a word.
        if let Some(parent) = p
            .parent()
            .filter(|d| !d.to_string_lossy().contains(['*', '?', '[']))
        {
            if let Ok(entries) = std::fs::read_dir(parent) {
                for e in entries.flatten() {
                    utf8_name(s, e.path())?;
                }
            }
        }
        let mut found: Vec<String> = Vec::new();
        for f in glob::glob(&pattern)
            .map_err(|e| {
                SourceError::new(
                    s,
                    format!("is not allowed: not a valid glob ({e}); allowed: a glob, a built-in record, a file or a folder"),
                )
            })?
            .filter_map(Result::ok)
            .filter(|f| f.is_file())
        {
            found.push(utf8_name(s, f)?);
        }
        found.sort();
        if found.is_empty() {
            return Err(SourceError::new(
                s,
                "is not allowed: it matches no file; allowed: a glob that matches a file, a built-in record, a file or a folder",
            ));
        }
        return Ok(found);
    }
    if p.is_dir() {
        let mut found: Vec<String> = Vec::new();
        for f in std::fs::read_dir(&p)
            .map_err(|e| {
                SourceError::new(s, format!("is not allowed: the folder cannot be read: {e}"))
            })?
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|f| {
                f.is_file()
                    && !f
                        .file_name()
                        .is_some_and(|n| n.to_string_lossy().starts_with('.'))
            })
        {
            found.push(utf8_name(s, f)?);
        }
        found.sort();
        if found.is_empty() {
            return Err(SourceError::new(
                s,
                "is not allowed: a folder with no files; allowed: a folder of record files, a file, a glob or a built-in record",
            ));
        }
        return Ok(found);
    }
    if p.is_file() {
        return Ok(vec![p.to_string_lossy().into_owned()]);
    }
    Err(SourceError::new(
        s,
        format!(
            "is not allowed: neither a built-in record ({}), a file, a folder nor a glob that matches a file",
            pounding::ground_motion::Record::BUILTINS
        ),
    ))
}

/// Sets the ground motion of `scenario` to `source` (a built-in or a file), keeping its units, and its format
/// and time step if it already read a file.
pub fn set_record(scenario: &mut Value, source: &str) {
    let gm = scenario
        .as_object_mut()
        .map(|m| {
            m.entry("ground_motion")
                .or_insert_with(|| Value::Object(Map::new()))
        })
        .and_then(Value::as_object_mut);
    let Some(gm) = gm else { return };
    let was_file = gm.contains_key("file");
    gm.remove("record");
    gm.remove("file");
    if pounding::ground_motion::Builtin::from_name(source).is_some() {
        gm.remove("format");
        gm.remove("dt");
        gm.insert("record".into(), Value::String(source.into()));
    } else {
        if !was_file {
            gm.remove("format");
            gm.remove("dt");
        }
        gm.insert("file".into(), Value::String(source.into()));
    }
}

/// How one axis value is shown in `runs.csv`.
fn show(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// What of a value a scenario's shape check reads: its text with every number replaced by its kind (an
/// unsigned, a negative or a fractional number, and for the last whether it is too small to allow:
/// [`pounding::limits::not_tiny`]), strings and booleans and keys as they are.
fn kind(v: &Value) -> String {
    match v {
        Value::Number(n) if n.is_u64() => "u".into(),
        Value::Number(n) if n.is_i64() => "i".into(),
        Value::Number(n) => match n.as_f64().is_some_and(pounding::limits::not_tiny) {
            true => "f".into(),
            false => "t".into(),
        },
        Value::Array(a) => format!("[{}]", a.iter().map(kind).collect::<Vec<_>>().join(",")),
        Value::Object(m) => {
            let fields: Vec<String> = m
                .iter()
                .map(|(k, v)| format!("{k:?}:{}", kind(v)))
                .collect();
            format!("{{{}}}", fields.join(","))
        }
        other => other.to_string(),
    }
}

/// Applies the setting `name = v` to `scenario`.
fn apply(scenario: &mut Value, name: &str, v: &Value) -> Result<(), String> {
    match name {
        "record" => {
            set_record(scenario, v.as_str().unwrap_or_default());
            Ok(())
        }
        "scale" => set_path(scenario, "ground_motion.scale", v.clone()),
        path => set_path(scenario, path, v.clone()),
    }
}

/// The scenario keys (dotted paths) that the setting `name` writes.
fn targets(name: &str) -> Vec<&str> {
    match name {
        "record" => vec!["ground_motion.record", "ground_motion.file"],
        "scale" => vec!["ground_motion.scale"],
        path => vec![path],
    }
}

/// Refuses two settings among `names` that write one scenario key (the same key, one inside the other, or
/// `scale` beside `ground_motion.scale`): runs.csv would label rows with values that were never run. `what`
/// names where they stand (`axes`, `run 3`).
fn one_setting_per_key(path: &Path, what: &str, names: &[&str]) -> Result<(), InputError> {
    let overlap = |a: &str, b: &str| {
        a == b
            || a.strip_prefix(b).is_some_and(|r| r.starts_with('.'))
            || b.strip_prefix(a).is_some_and(|r| r.starts_with('.'))
    };
    for (i, a) in names.iter().enumerate() {
        for b in &names[..i] {
            let clash = targets(a)
                .into_iter()
                .find(|ta| targets(b).iter().any(|tb| overlap(ta, tb)));
            if let Some(key) = clash {
                return Err(err(
                    path,
                    format!(
                        "{what}: {b:?} and {a:?} both set the scenario key {key:?}; allowed: one setting per key"
                    ),
                ));
            }
        }
    }
    Ok(())
}

impl Study {
    /// Reads and expands the study file at `path`. Bad input (an axis that names no scenario key, an empty
    /// axis, a record glob that matches nothing, an unknown study key) is one line naming the file.
    pub fn read(path: &Path) -> Result<Study, InputError> {
        let text =
            read_text_file(path, "study file", SCENARIO_FILE_LIMIT).map_err(InputError::new)?;
        let top = crate::input::study_json(path, &text)?;
        let Value::Object(top) = top else {
            return Err(err(path, "not a table"));
        };
        for k in top.keys() {
            if !["scenario", "axes", "run"].contains(&k.as_str()) {
                return Err(err(
                    path,
                    format!("unknown key {k:?}; allowed: scenario, axes, run"),
                ));
            }
        }
        let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        let base = match top.get("scenario") {
            Some(Value::String(s)) => dir.join(s),
            _ => {
                return Err(err(
                    path,
                    "scenario = \"base.toml\" is required: the base scenario, relative to the study file",
                ))
            }
        };
        let base_file = ScenarioFile::read(&base)?;
        let (axes, runs) = match (top.get("axes"), top.get("run")) {
            (Some(Value::Object(a)), None) => {
                product(path, &dir, &base_file.value, a, &written_order(&text))?
            }
            (None, Some(Value::Array(runs))) => {
                let (axes, variants) = list(path, &dir, &base_file.value, runs)?;
                (axes, Runs::List(variants))
            }
            (None, None) => {
                return Err(err(
                    path,
                    "[axes] or [[run]] entries are required: what the study varies",
                ))
            }
            (Some(_), Some(_)) => return Err(err(
                path,
                "give [axes] (a Cartesian product) or [[run]] entries (an explicit list), not both",
            )),
            (Some(a), None) => {
                return Err(err(
                    path,
                    format!(
                        "axes = {} is not allowed: a table [axes] of lists of values",
                        show(a)
                    ),
                ))
            }
            (None, Some(r)) => {
                return Err(err(
                    path,
                    format!(
                        "run = {} is not allowed: [[run]] entries, tables of settings",
                        show(r)
                    ),
                ))
            }
        };
        let study = Study {
            path: path.to_path_buf(),
            base,
            axes,
            runs,
        };
        study.check_keys()?;
        Ok(study)
    }

    /// The scenarios whose keys [`Study::check_keys`] reads: for a product, the base with one axis set to
    /// each of its values in turn (axes set disjoint keys, so every run's keys are among these); for a list,
    /// every entry.
    /// Values that differ only in numbers of the same kind ([`kind`]) give the same shape errors: one
    /// probe stands for them all (a sweep of 10,000 gaps reads one scenario, not 10,000).
    fn probes(&self) -> Vec<Value> {
        let mut seen = std::collections::HashSet::new();
        match &self.runs {
            Runs::List(variants) => variants
                .iter()
                .filter(|v| seen.insert((0, kind(&v.value))))
                .map(|v| v.value.clone())
                .collect(),
            Runs::Product { base, .. } => {
                let mut out = Vec::new();
                for (a, axis) in self.axes.iter().enumerate() {
                    for v in axis.values.iter().filter(|v| seen.insert((a, kind(v)))) {
                        let mut value = base.clone();
                        if apply(&mut value, &axis.name, v).is_ok() {
                            out.push(value);
                        }
                    }
                }
                out
            }
        }
    }

    /// Every key an axis sets must be a key of the scenario schema, with a value of the right type.
    fn check_keys(&self) -> Result<(), InputError> {
        for value in self.probes() {
            if let Err((Some(k), m)) = crate::input::parse_doc(&value) {
                let axis = self.axes.iter().find(|a| {
                    a.name == k
                        || k.starts_with(&format!("{}.", a.name))
                        || a.name.starts_with(&format!("{k}."))
                });
                match axis {
                    Some(axis) if m.contains("unknown field") => {
                        return Err(err(
                            &self.path,
                            format!("axis {:?} names no scenario key: {m}", axis.name),
                        ));
                    }
                    // A value of the wrong kind (a string for a number) is the study's mistake, not a
                    // run's: refused before anything runs.
                    Some(axis) if m.contains("invalid type") => {
                        return Err(err(
                            &self.path,
                            format!("axis {:?} has a value of the wrong type: {m}", axis.name),
                        ));
                    }
                    _ => {}
                }
            }
        }
        Ok(())
    }

    /// The number of runs.
    pub fn len(&self) -> usize {
        match &self.runs {
            Runs::Product { len, .. } => *len,
            Runs::List(v) => v.len(),
        }
    }

    /// Whether the study has no runs (never, once read).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Run `i`: its scenario and label (`STUDY#i`), and the value of each axis as shown in `runs.csv`.
    pub fn variant(&self, i: usize) -> (Value, String, Vec<String>) {
        let label = format!("{}#{i}", self.path.display());
        match &self.runs {
            Runs::List(v) => (v[i].value.clone(), label, v[i].coords.clone()),
            Runs::Product { base, .. } => {
                let mut value = base.clone();
                for (axis, v) in self.picks(i) {
                    // Every value of every axis was applied to the base when the study was read.
                    let _ = apply(&mut value, &axis.name, v);
                }
                (value, label, self.coords(i))
            }
        }
    }

    /// The value of each axis of run `i` as shown in `runs.csv`: [`Self::variant`]'s, without building the
    /// run's scenario.
    pub fn coords(&self, i: usize) -> Vec<String> {
        match &self.runs {
            Runs::List(v) => v[i].coords.clone(),
            Runs::Product { .. } => self.picks(i).map(|(_, v)| show(v)).collect(),
        }
    }

    /// Each axis (in order) with its value in run `i` of a product of axes.
    fn picks(&self, i: usize) -> impl Iterator<Item = (&Axis, &Value)> {
        // The last axis varies fastest.
        let mut strides = vec![1; self.axes.len()];
        for a in (0..self.axes.len().saturating_sub(1)).rev() {
            strides[a] = strides[a + 1] * self.axes[a + 1].values.len();
        }
        self.axes
            .iter()
            .zip(strides)
            .map(move |(axis, stride)| (axis, &axis.values[(i / stride) % axis.values.len()]))
    }

    /// The same study with `contacts = "off"` in every run (`--no-contact`): its identity changes with it,
    /// so its store is another study's. Refused when an axis or a run entry sets `contacts` itself.
    pub fn without_contact(&mut self) -> Result<(), InputError> {
        if self.axes.iter().any(|a| a.name == "contacts") {
            return Err(err(
                &self.path,
                "--no-contact: the study sets \"contacts\" per run already; allowed: the option or the key, not both",
            ));
        }
        let off = |v: &mut Value| {
            if let Some(o) = v.as_object_mut() {
                o.insert("contacts".into(), Value::String("off".into()));
            }
        };
        match &mut self.runs {
            Runs::Product { base, .. } => off(base),
            Runs::List(v) => v.iter_mut().for_each(|v| off(&mut v.value)),
        }
        Ok(())
    }

    /// The study's identity: a hash of its definition (the base scenario, and the axes with their values or
    /// the list of runs), so that a store is known as this study's without making its runs.
    pub fn id(&self) -> String {
        let def = match &self.runs {
            Runs::Product { base, .. } => serde_json::json!({
                "base": base,
                "axes": self.axes.iter().map(|a| (a.name.clone(), a.values.clone())).collect::<Vec<_>>(),
            }),
            Runs::List(v) => serde_json::json!({
                "runs": v.iter().map(|v| v.value.clone()).collect::<Vec<_>>(),
            }),
        };
        crate::key::definition_id(&def, self.path.parent())
    }
}

/// The axes of `[axes]` (record sources expanded) and their Cartesian product over `base`.
fn product(
    path: &Path,
    dir: &Path,
    base: &Value,
    axes_table: &Map<String, Value>,
    order: &std::collections::HashMap<String, usize>,
) -> Result<(Vec<Axis>, Runs), InputError> {
    let mut flat = Vec::new();
    flatten("", axes_table, &mut flat);
    // In the order written: TOML groups dotted keys of one table (`contact.0.model`, then `scale`, then
    // `contact.0.gap` parse as contact.0.{model, gap}, scale).
    flat.sort_by_key(|(name, _)| order.get(name).copied().unwrap_or(usize::MAX));
    if flat.is_empty() {
        return Err(err(path, "[axes] is empty: give at least one axis"));
    }
    let names: Vec<&str> = flat.iter().map(|(n, _)| n.as_str()).collect();
    one_setting_per_key(path, "axes", &names)?;
    let mut axes = Vec::new();
    let mut total: usize = 1;
    for (name, v) in flat {
        let Value::Array(values) = v else {
            return Err(err(
                path,
                format!("axes.{name} = {v} is not allowed: a list of values"),
            ));
        };
        if values.is_empty() {
            return Err(err(
                path,
                format!("axes.{name} = [] is empty: give at least one value"),
            ));
        }
        let values = if name == "record" {
            let mut all = Vec::new();
            for v in &values {
                all.extend(
                    record_sources(dir, v)
                        .map_err(|m| err(path, format!("axes.{m}")))?
                        .into_iter()
                        .map(Value::String),
                );
            }
            all
        } else {
            // The path must exist in the base (up to a key the schema may add).
            let mut probe = base.clone();
            apply(&mut probe, &name, &values[0])
                .map_err(|m| err(path, format!("axis {name:?} names no scenario key: {m}")))?;
            values
        };
        total = total.saturating_mul(values.len());
        axes.push(Axis { name, values });
    }
    if total > MAX_RUNS {
        return Err(err(
            path,
            format!("the axes make {total} runs; allowed: at most 1e7"),
        ));
    }
    Ok((
        axes,
        Runs::Product {
            base: base.clone(),
            len: total,
        },
    ))
}

/// The explicit list of `[[run]]` entries over `base`.
fn list(
    path: &Path,
    dir: &Path,
    base: &Value,
    runs: &[Value],
) -> Result<(Vec<Axis>, Vec<Variant>), InputError> {
    if runs.is_empty() {
        return Err(err(path, "[[run]] has no entries"));
    }
    let mut names: Vec<String> = Vec::new();
    let mut entries = Vec::new();
    for (i, r) in runs.iter().enumerate() {
        let Value::Object(t) = r else {
            return Err(err(path, format!("run {i} is not a table")));
        };
        let mut flat = Vec::new();
        flatten("", t, &mut flat);
        let set: Vec<&str> = flat.iter().map(|(n, _)| n.as_str()).collect();
        one_setting_per_key(path, &format!("run {i}"), &set)?;
        for (k, _) in &flat {
            if !names.contains(k) {
                names.push(k.clone());
            }
        }
        entries.push(flat);
    }
    let mut variants = Vec::new();
    for (i, flat) in entries.iter().enumerate() {
        let mut value = base.clone();
        for (k, v) in flat {
            let v = if k == "record" {
                let s = record_sources(dir, v).map_err(|m| err(path, format!("run {i}: {m}")))?;
                if s.len() != 1 {
                    return Err(err(
                        path,
                        format!(
                            "run {i}: record = {v} names {} files; a run takes one",
                            s.len()
                        ),
                    ));
                }
                Value::String(s[0].clone())
            } else {
                v.clone()
            };
            apply(&mut value, k, &v)
                .map_err(|m| err(path, format!("run {i}: {k:?} names no scenario key: {m}")))?;
        }
        let coords = names
            .iter()
            .map(|n| {
                flat.iter()
                    .find(|(k, _)| k == n)
                    .map_or(String::new(), |(_, v)| show(v))
            })
            .collect();
        variants.push(Variant { value, coords });
    }
    let axes = names
        .into_iter()
        .map(|name| Axis {
            values: Vec::new(),
            name,
        })
        .collect();
    Ok((axes, variants))
}
