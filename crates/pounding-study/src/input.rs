//! Scenarios and records from files and from JSON values (Python dicts, a study's variants): read, parsed into
//! the library's [`ScenarioDoc`] and validated once, with one-line messages that say where (the file and line,
//! or the key's dotted path).

use crate::InputError;
use pounding::analysis::Scenario;
use pounding::ground_motion::{Format, Record, RecordError};
use pounding::scenario::{RecordSpec, ScenarioDoc};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Largest record file read, bytes (1e7 samples at 25 characters each).
pub const RECORD_FILE_LIMIT: u64 = 256 << 20;

/// Largest scenario (or study) file read, bytes.
pub const SCENARIO_FILE_LIMIT: u64 = 16 << 20;

/// Largest table of test data read (`--e-table`, `pounding fit`'s data), bytes: as a record file.
pub const DATA_FILE_LIMIT: u64 = RECORD_FILE_LIMIT;

/// The text of a regular file of at most `limit` bytes; anything else (a FIFO or a device, which could block or
/// never end; a file too large; text that is not UTF-8) is a one-line message naming `what`.
pub fn read_text_file(path: &Path, what: &str, limit: u64) -> Result<String, String> {
    use std::io::Read;
    let shown = path.display();
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot read {what} {shown}: {e}"))?;
    if !meta.is_file() {
        return Err(format!(
            "cannot read {what} {shown}: not a regular file (a folder, device or pipe)"
        ));
    }
    if meta.len() > limit {
        return Err(format!(
            "{what} {shown} has {} bytes; allowed: at most {} MiB",
            meta.len(),
            limit >> 20
        ));
    }
    let mut text = String::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(limit + 1).read_to_string(&mut text))
        .map_err(|e| format!("cannot read {what} {shown}: {e}"))?;
    if text.len() as u64 > limit {
        return Err(format!("{what} {shown} is larger than {} MiB", limit >> 20));
    }
    Ok(text)
}

/// Writes `contents` to `path` atomically: a temporary file in the same folder, flushed, then renamed.
pub fn write_atomic(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    write_atomic_with(path, |w| w.write_all(contents))
}

/// Writes what `write` gives to `path` atomically, without holding it in memory: a temporary file in the
/// same folder, written through a buffer, flushed, then renamed. An error from `write` leaves no file.
pub fn write_atomic_with(
    path: &Path,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    // The rename would replace a device node or a FIFO with a file (as root, `/dev/null` itself).
    if let Ok(m) = std::fs::symlink_metadata(path) {
        if !m.is_file() && !m.file_type().is_symlink() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                "it exists and is not a regular file (a folder, a device or a FIFO); allowed: a regular file or a new path",
            ));
        }
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("output");
    remove_stale_tmp(&dir, name);
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    let result = (|| {
        let mut f = std::io::BufWriter::new(std::fs::File::create(&tmp)?);
        write(&mut f)?;
        let f = f.into_inner().map_err(|e| e.into_error())?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Removes the temporary files `.NAME.tmp-PID` that [`write_atomic`] left in `dir` when its process was
/// killed (the process is gone); those of running processes stay.
fn remove_stale_tmp(dir: &Path, name: &str) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let prefix = format!(".{name}.tmp-");
    for e in entries.flatten() {
        let file = e.file_name();
        let Some(pid) = file.to_str().and_then(|f| f.strip_prefix(&prefix)) else {
            continue;
        };
        // Only where /proc tells which processes live.
        let gone = pid.parse::<u32>().is_ok()
            && Path::new("/proc/self").exists()
            && !Path::new("/proc").join(pid).exists();
        if gone {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// The unscaled record `spec` names: a built-in, or its file read in its format (default
/// [`Format::detect`]: AT2 by its header or a `*.at2` name, else two columns) and units (default: an AT2
/// header's, else g; [`Record::read`]). Messages are one line; a library value error comes back as itself.
pub fn read_record(spec: &RecordSpec) -> Result<Record, RecordError> {
    if !spec.is_file {
        let builtin = pounding::ground_motion::Builtin::from_name(&spec.source);
        if let (Some(u), Some(b)) = (spec.units, builtin) {
            return Err(RecordError::Parse(pounding::ground_motion::ParseError {
                line: 0,
                message: b.units_refused(u),
            }));
        }
        return Record::builtin(&spec.source).ok_or_else(|| {
            RecordError::Parse(pounding::ground_motion::ParseError {
                line: 0,
                message: format!(
                    "{:?} is not a built-in record: {}",
                    spec.source,
                    Record::BUILTINS
                ),
            })
        });
    }
    let path = Path::new(&spec.source);
    let text = read_text_file(path, "record file", RECORD_FILE_LIMIT).map_err(|e| {
        RecordError::Parse(pounding::ground_motion::ParseError {
            line: 0,
            message: format!("{e} (built-in records: {})", Record::BUILTINS),
        })
    })?;
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("record");
    // Without a format, the text decides (an AT2 header), then the file's extension.
    let name = path.file_name().and_then(|s| s.to_str());
    let format = spec.format.unwrap_or_else(|| Format::detect(&text, name));
    Record::read(stem, &text, Some(format), spec.units)
}

/// A record error as one line: a parse error names the file.
pub fn record_message(spec: &RecordSpec, e: RecordError) -> String {
    match e {
        RecordError::Parse(p) if p.line == 0 => p.message,
        RecordError::Parse(p) => format!("{}: {p}", spec.source),
        RecordError::Value(v) => v.to_string(),
    }
}

/// A scenario, validated, with what a summary and a report say about where it came from.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The scenario as parsed (a record file's path resolved against the scenario's folder).
    pub doc: ScenarioDoc,
    /// The validated scenario.
    pub scenario: Scenario,
    /// Where the scenario came from: its file's path, or a label for a dict or a study's variant.
    pub label: String,
    /// The ground-motion source as given (built-in name or path).
    pub record_source: String,
}

/// A scenario file, as text and as a JSON value (for Python's `load_scenario` and for studies).
pub struct ScenarioFile {
    /// The file's path.
    pub path: PathBuf,
    /// Its text, as read.
    pub text: String,
    /// Its content as JSON, with a relative record `file` resolved against the file's folder.
    pub value: Value,
}

impl ScenarioFile {
    /// Reads the scenario file at `path`. TOML syntax errors name the line.
    pub fn read(path: &Path) -> Result<Self, InputError> {
        let text =
            read_text_file(path, "scenario file", SCENARIO_FILE_LIMIT).map_err(InputError::new)?;
        let table: toml::Table = toml::from_str(&text).map_err(|e| {
            let msg = e.message().trim().replace('\n', " ");
            match e.span() {
                Some(span) => InputError::new(format!(
                    "{}:{}: {msg}",
                    path.display(),
                    line_of(&text, span.start)
                )),
                None => InputError::new(format!("{}: {msg}", path.display())),
            }
        })?;
        // JSON, which a scenario becomes, has no NaN or infinity (they would be nulls): said here, by key.
        if let Some((key, x)) = non_finite(&table) {
            return Err(InputError::new(format!(
                "{}:{}: {} = {} is not allowed: a finite number",
                path.display(),
                key_line(&text, &key).max(1),
                shown_key(&key),
                toml_float(x)
            )));
        }
        let mut value = serde_json::to_value(table)
            .map_err(|e| InputError::new(format!("{}: {e}", path.display())))?;
        let base = path.parent().unwrap_or(Path::new("."));
        resolve_record_file(&mut value, base);
        let read = inline_matrix_files(&mut value, base).map_err(|(key, msg)| {
            let line = key_line(&text, &key).max(1);
            InputError::new(format!("{}:{line}: {msg}", path.display()))
        })?;
        let text = with_matrices_inline(text, &value, &read);
        Ok(ScenarioFile {
            path: path.to_path_buf(),
            text,
            value,
        })
    }

    /// The validated scenario; every message names the file and the line of the key it concerns.
    pub fn load(&self) -> Result<Loaded, InputError> {
        let label = self.path.display().to_string();
        from_value(&self.value, &label).map_err(|(key, msg)| {
            let line = key.as_deref().map_or(0, |k| key_line(&self.text, k)).max(1);
            match key {
                Some(_) => InputError::new(format!("{label}:{line}: {msg}")),
                None => InputError::new(format!("{label}: {msg}")),
            }
        })
    }
}

/// Where a scenario names record files: `ground_motion.file`, and `ground_motion.y.file` (the record along y);
/// each `[[support]]`'s `file` too ([`record_files`]).
pub const RECORD_FILES: [&str; 2] = ["/ground_motion/file", "/ground_motion/y/file"];

/// The JSON pointers of every record file a scenario may name: [`RECORD_FILES`] and each support's.
pub fn record_files(value: &Value) -> Vec<String> {
    let supports = value
        .pointer("/support")
        .and_then(Value::as_array)
        .map_or(0, Vec::len);
    RECORD_FILES
        .iter()
        .map(|s| s.to_string())
        .chain((0..supports).map(|i| format!("/support/{i}/file")))
        .collect()
}

/// A relative record file (`ground_motion.file`, `ground_motion.y.file`, a support's `file`) is relative to
/// `base`: rewritten so that the value runs from anywhere.
pub fn resolve_record_file(value: &mut Value, base: &Path) {
    for at in record_files(value) {
        if let Some(Value::String(f)) = value.pointer_mut(&at) {
            let p = Path::new(f.as_str());
            if p.is_relative() {
                *f = base.join(p).to_string_lossy().into_owned();
            }
        }
    }
}

/// A matrix file a scenario named: the building's index, the key and the file as given.
pub type MatrixFile = (usize, &'static str, String);

/// The keys of a building that may name a file holding a matrix.
pub const MATRIX_KEYS: [&str; 3] = ["stiffness_matrix", "damping_matrix", "mass_matrix"];

/// Every building's matrix given as a file name (`stiffness_matrix = "K.mtx"`), read (relative to `base`) and
/// put in as its rows, so that the scenario holds it and runs, or is stored, on its own. An error is
/// `(dotted key, message)`.
///
/// Returns the `(building, key, file)` it read.
pub fn inline_matrix_files(
    value: &mut Value,
    base: &Path,
) -> Result<Vec<MatrixFile>, (String, String)> {
    let mut read = Vec::new();
    let n = value
        .pointer("/building")
        .and_then(Value::as_array)
        .map_or(0, Vec::len);
    for i in 0..n {
        for key in MATRIX_KEYS {
            let Some(Value::String(f)) = value.pointer(&format!("/building/{i}/{key}")) else {
                continue;
            };
            let dotted = format!("building.{i}.{key}");
            let path = base.join(f);
            let m = read_text_file(&path, "matrix file", RECORD_FILE_LIMIT)
                .map_err(|e| (dotted.clone(), format!("{dotted}: {e}")))?;
            let m = pounding::structure::Matrix::parse(key, &m)
                .map_err(|e| (dotted.clone(), format!("{dotted}: {}: {e}", path.display())))?;
            let rows: Vec<Value> = m
                .values
                .chunks(m.n)
                .map(|r| Value::from(r.to_vec()))
                .collect();
            read.push((i, key, f.clone()));
            value["building"][i][key] = Value::Array(rows);
        }
    }
    Ok(read)
}

/// `text` with each matrix file it names (`read`, as [`inline_matrix_files`] returns) replaced by the rows in
/// `value`, the rest of the text as it was: the copy of a scenario that runs anywhere (a run's
/// `scenario.toml`, a study's stored scenario).
fn with_matrices_inline(text: String, value: &Value, read: &[MatrixFile]) -> String {
    if read.is_empty() {
        return text;
    }
    let Ok(mut doc) = text.parse::<toml_edit::DocumentMut>() else {
        return text;
    };
    for (i, key, file) in read {
        let Some(rows) = value["building"][*i][*key].as_array() else {
            continue;
        };
        let mut array = toml_edit::Array::new();
        for row in rows {
            let r: toml_edit::Array = row
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(Value::as_f64)
                .collect();
            array.push(r);
        }
        let Some(table) = doc["building"][*i].as_table_like_mut() else {
            continue;
        };
        if let Some(item) = table.get_mut(key) {
            let mut v = toml_edit::Value::Array(array);
            v.decor_mut().set_suffix(format!(
                "  # read from {file:?} when the scenario was loaded"
            ));
            *item = toml_edit::Item::Value(v);
        }
    }
    doc.to_string()
}

/// The scenario `value` parsed and validated; `label` says where it came from. An error is `(key, message)`:
/// the dotted path it concerns (if known) and one line.
pub fn from_value(value: &Value, label: &str) -> Result<Loaded, (Option<String>, String)> {
    // A matrix file named in a dict (not a file's scenario, whose files are read already): from here.
    let mut owned;
    let names_file = |b: &Value| {
        MATRIX_KEYS
            .iter()
            .any(|k| b.get(k).is_some_and(Value::is_string))
    };
    let value = if value
        .get("building")
        .and_then(Value::as_array)
        .is_some_and(|bs| bs.iter().any(names_file))
    {
        owned = value.clone();
        inline_matrix_files(&mut owned, Path::new(".")).map_err(|(k, m)| (Some(k), m))?;
        &owned
    } else {
        value
    };
    let doc = parse_doc(value)?;
    let spec = doc
        .ground_motion
        .spec()
        .map_err(|e| (Some(e.key), e.message))?;
    let load = |spec: &RecordSpec, at: &str| {
        read_record(spec)
            .and_then(|r| r.scaled(spec.scale).map_err(RecordError::Value))
            .map_err(|e| {
                let msg = record_message(spec, e);
                (Some(at.to_string()), format!("[{at}] {msg}"))
            })
    };
    let record = load(&spec, "ground_motion")?;
    let y = match doc
        .ground_motion
        .spec_y()
        .map_err(|e| (Some(e.key), e.message))?
    {
        Some(sy) => Some(load(&sy, "ground_motion.y")?),
        None => None,
    };
    let mut supports = Vec::new();
    for (i, sp) in doc
        .support_specs()
        .map_err(|e| (Some(e.key), e.message))?
        .iter()
        .enumerate()
    {
        if let Some(sp) = sp {
            supports.push(load(sp, &format!("support.{i}"))?);
        }
    }
    build(doc, (record, y, supports), label, spec.source)
}

/// Validates `doc` under `record` along x, its record along y and its supports' own records, if it has them
/// (already loaded and scaled).
pub fn build(
    doc: ScenarioDoc,
    (record, y, supports): (Record, Option<Record>, Vec<Record>),
    label: &str,
    record_source: String,
) -> Result<Loaded, (Option<String>, String)> {
    let scenario = doc
        .build_full(record, y, supports)
        .map_err(|e| (Some(e.key), e.message))?;
    Ok(Loaded {
        doc,
        scenario,
        label: label.to_string(),
        record_source,
    })
}

/// `value` as a [`ScenarioDoc`]; a shape error (an unknown key, a string for a number) names its path.
pub fn parse_doc(value: &Value) -> Result<ScenarioDoc, (Option<String>, String)> {
    if let Some(key) = crate::shape::lists_where_tables_belong(value) {
        let msg = if key.is_empty() {
            "the scenario is a list; allowed: a table of named keys (docs/scenarios.md)".to_string()
        } else {
            format!("{} is a list; allowed here: a table of named keys or a single value (docs/scenarios.md)", shown_key(&key))
        };
        return Err((Some(key), msg));
    }
    if let Some((key, x)) = tiny_number(value) {
        return Err((
            Some(key.clone()),
            format!("{} = {x:e} is not allowed: 0, or at least 1e-30 in magnitude (limits::MIN_MAGNITUDE: smaller numbers are zero for any structure and slow the analysis)", shown_key(&key)),
        ));
    }
    parse_value(value)
}

/// The dotted key of `k` inside `key` (`k` itself at the top).
pub(crate) fn dotted_child(key: &str, k: &str) -> String {
    if key.is_empty() {
        k.to_string()
    } else {
        format!("{key}.{k}")
    }
}

/// The first number of `table` that is NaN or infinite, with its dotted key. TOML has them (`nan`, `inf`),
/// JSON, which scenarios and studies become, does not: converted, they would be nulls.
pub fn non_finite(table: &toml::Table) -> Option<(String, f64)> {
    fn find(key: &str, v: &toml::Value) -> Option<(String, f64)> {
        let child = |k: &str| dotted_child(key, k);
        match v {
            toml::Value::Float(x) if !x.is_finite() => Some((key.to_string(), *x)),
            toml::Value::Table(t) => t.iter().find_map(|(k, v)| find(&child(k), v)),
            toml::Value::Array(a) => a
                .iter()
                .enumerate()
                .find_map(|(i, v)| find(&child(&i.to_string()), v)),
            _ => None,
        }
    }
    table.iter().find_map(|(k, v)| find(k, v))
}

/// A study file's `text` (read from `path`) as JSON: a TOML error, or a number that is NaN or infinite (JSON
/// has neither), is one line naming the file (and the key).
pub fn study_json(path: &Path, text: &str) -> Result<Value, InputError> {
    let err = |msg: String| InputError::new(format!("{}: {msg}", path.display()));
    let table: toml::Table =
        toml::from_str(text).map_err(|e| err(e.message().trim().replace('\n', " ")))?;
    if let Some((key, x)) = non_finite(&table) {
        return Err(err(format!(
            "{} = {} is not allowed: a finite number",
            shown_key(&key),
            toml_float(x)
        )));
    }
    serde_json::to_value(table).map_err(|e| err(e.to_string()))
}

/// A number that is not finite as TOML writes it: `nan` (`-nan`), `inf`, `-inf`.
pub fn toml_float(x: f64) -> &'static str {
    match (x.is_nan(), x.is_sign_negative()) {
        (true, false) => "nan",
        (true, true) => "-nan",
        (false, false) => "inf",
        (false, true) => "-inf",
    }
}

/// The first number of `v` that is neither 0 nor at least [`pounding::limits::MIN_MAGNITUDE`] in magnitude,
/// with its dotted key.
fn tiny_number(v: &Value) -> Option<(String, f64)> {
    /// The number and its keys, innermost first (pushed on the way out: nothing is built where none is).
    fn find(v: &Value, path: &mut Vec<String>) -> Option<f64> {
        let (k, x) = match v {
            Value::Number(n) => return n.as_f64().filter(|x| !pounding::limits::not_tiny(*x)),
            Value::Object(m) => m
                .iter()
                .find_map(|(k, v)| find(v, path).map(|x| (k.clone(), x)))?,
            Value::Array(a) => {
                let mut items = a.iter().enumerate();
                items.find_map(|(i, v)| find(v, path).map(|x| (i.to_string(), x)))?
            }
            _ => return None,
        };
        path.push(k);
        Some(x)
    }
    let mut path = Vec::new();
    let x = find(v, &mut path)?;
    path.reverse();
    Some((path.join("."), x))
}

/// `value` as a `T` (a scenario, or another set of named parameters such as Python's synthetic record's),
/// with [`parse_doc`]'s messages: a shape error names its dotted path, an unknown key gets "did you mean".
pub fn parse_value<T: serde::de::DeserializeOwned>(
    value: &Value,
) -> Result<T, (Option<String>, String)> {
    // Read plainly first (a study reads every run's scenario); only a value that fails is read again with
    // its path tracked, for the message.
    if let Ok(t) = T::deserialize(value) {
        return Ok(t);
    }
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = cut_expected(&suggest_field(&e.into_inner().to_string()));
        if path == "." || path.is_empty() {
            return (Some(String::new()), inner);
        }
        let path = dotted(&path);
        // An unknown key over 64 characters is named once, cut, by the message itself (`unknown field
        // `kkk...` (5000 characters)`): the message is put at its table, not under the key again.
        let shown = match path.rsplit_once('.') {
            Some((table, last)) if inner.starts_with("unknown field `") && too_long(last) => {
                shown_key(table)
            }
            None if inner.starts_with("unknown field `") && too_long(&path) => {
                return (Some(path), inner);
            }
            _ => shown_key(&path),
        };
        (Some(path), format!("{shown}: {inner}"))
    })
}

/// Longest part of a dotted key that messages show whole, characters (as quoted names).
const KEY_PART_MAX: usize = 64;

fn too_long(part: &str) -> bool {
    part.chars().count() > KEY_PART_MAX
}

/// The dotted `key` as messages show it: a part over 64 characters (a misspelt key pasted whole) cut as
/// quoted names are, `kkkkkkkkkkkkkkkk... (5000 characters)`.
pub fn shown_key(key: &str) -> String {
    key.split('.')
        .map(|part| {
            if too_long(part) {
                let head: String = part.chars().take(16).collect();
                format!("{head}... ({} characters)", part.chars().count())
            } else {
                part.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join(".")
}

/// Most characters of serde's list of expected names (`expected one of `a`, `b`, ...`) a message shows:
/// the rest is counted, so that the line ends with what is allowed, whole.
const EXPECTED_MAX: usize = 100;

/// serde's `..., expected one of `a`, `b`, ...` with a long list cut after its first names, with its count
/// (`..., ... (33 in all)`).
fn cut_expected(msg: &str) -> String {
    const ONE_OF: &str = ", expected one of ";
    let Some(at) = msg.find(ONE_OF) else {
        return msg.to_string();
    };
    let (head, list) = msg.split_at(at + ONE_OF.len());
    let names: Vec<&str> = list.split(", ").collect();
    let all_names = names
        .iter()
        .all(|n| n.len() >= 2 && n.starts_with('`') && n.ends_with('`'));
    if !all_names || list.len() <= EXPECTED_MAX {
        return msg.to_string();
    }
    format!("{head}{}", pounding::words::list(&names, EXPECTED_MAX))
}

/// serde's `unknown field `scael`, expected one of `record`, ..., `scale`` with `; did you mean "scale"?`
/// after the name, when one of the expected names is close.
fn suggest_field(msg: &str) -> String {
    let Some(rest) = msg.strip_prefix("unknown field `") else {
        return msg.to_string();
    };
    let Some((given, expected)) = rest.split_once('`') else {
        return msg.to_string();
    };
    let names: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
    match pounding::words::closest(given, names) {
        Some(n) => format!("unknown field `{given}` (did you mean `{n}`?){expected}"),
        None => msg.to_string(),
    }
}

/// `contact[0].gap` (serde_path_to_error's spelling) as `contact.0.gap`.
fn dotted(path: &str) -> String {
    path.replace('[', ".").replace(']', "")
}

/// A dict's message: `key: message` (the key is the dotted path, as [`shown_key`] shows it; none for the
/// whole scenario), unless the message already starts with the key or one of the tables it is in
/// (`key: ...`, `[key] ...`, `key = ...`, `key is ...`).
pub fn dict_message(key: Option<String>, msg: String) -> String {
    let Some(k) = key.filter(|k| !k.is_empty()) else {
        return msg;
    };
    let named = |p: &str| {
        let p = shown_key(p);
        [
            format!("{p}:"),
            format!("[{p}]"),
            format!("{p} = "),
            format!("{p} is "),
        ]
        .iter()
        .any(|start| msg.starts_with(start))
    };
    let mut at = k.as_str();
    loop {
        if named(at) {
            return msg;
        }
        match at.rsplit_once('.') {
            Some((table, _)) => at = table,
            None => break,
        }
    }
    format!("{}: {msg}", shown_key(&k))
}

/// 1-based line of byte `offset` of `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())]
        .bytes()
        .filter(|b| *b == b'\n')
        .count()
        + 1
}

/// The line of the key at dotted path `key` in the TOML `text`; the closest entry that exists if the key is
/// not written (a default), or the key names a list by its singular (`yield_force` of `yield_forces`).
pub fn key_line(text: &str, key: &str) -> usize {
    let Ok(doc) = toml_edit::ImDocument::parse(text) else {
        return 0;
    };
    let mut best = None;
    let mut item = doc.as_item();
    for part in key.split('.').filter(|p| !p.is_empty()) {
        let next = match part.parse::<usize>() {
            Ok(i) => item.get(i),
            Err(_) => [part.to_string(), format!("{part}s"), format!("{part}es")]
                .iter()
                .find_map(|k| item.get(k.as_str())),
        };
        let Some(next) = next else { break };
        if let Some(span) = next.span() {
            best = Some(span.start);
        }
        item = next;
    }
    best.map_or(0, |s| line_of(text, s))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_atomic_removes_what_killed_writers_left() {
        let dir = std::env::temp_dir().join(format!("pounding-atomic-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        // A process id that no process has (above the kernel's limit), and this process's own.
        let dead = dir.join(".runs.csv.tmp-4294967295");
        let alive = dir.join(format!(".other.csv.tmp-{}", std::process::id()));
        std::fs::write(&dead, "half").unwrap();
        std::fs::write(&alive, "mine").unwrap();
        write_atomic(&dir.join("runs.csv"), b"a,b\n").unwrap();
        assert_eq!(std::fs::read(dir.join("runs.csv")).unwrap(), b"a,b\n");
        assert!(!dead.exists() || !Path::new("/proc/self").exists());
        assert!(alive.exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
