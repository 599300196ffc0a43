//! The study store: one SQLite file holding every finished run of one study, committed as it finishes, so that
//! an interrupted sweep resumes where it stopped and never repeats or loses a finished run.
//!
//! Tables:
//! - `runs(key TEXT PRIMARY KEY, idx INTEGER, status TEXT, summary TEXT, error TEXT, seconds REAL,
//!   finished TEXT, digest TEXT)`: `key` the run's hash ([`crate::key`]), `idx` its position in the study
//!   (from 0), `status` `ok` or `error`, `summary` the run's summary as compact JSON text (`summary.json`'s
//!   content without its `units`, the same for every run: [`crate::summary::RunSummary::to_row`]; rows
//!   written before 2026-11-27 hold them too; NULL for an error), `error` the one-line message (NULL if
//!   ok), `seconds` the run's wall time (s),
//!   `finished` the UTC time it was committed, `digest` the FNV-1a-128 hash of key, status and summary or
//!   message ([`digest`]): a row whose digest does not match (a flipped bit, an edited or swapped summary) is
//!   not trusted, and its run is run again.
//! - `study(name TEXT PRIMARY KEY, value TEXT)`: `id` (the hash of the study's run keys, in order), `runs`
//!   (their number), `format` (this layout's version), `created`, `units` (the summaries' units, as JSON:
//!   `summary.json`'s `units`).
//!
//! A store of layout `pounding-study-1` (without digests) is brought to this layout when opened: its rows get
//! their digests, in the transaction that changes its format. A store of layout `pounding-study-2` (rows with
//! their units) gets its `units` row and this layout's name; its rows read as they are.

use rusqlite::{params, Connection, OpenFlags, OptionalExtension};
use std::collections::HashSet;
use std::path::Path;

/// Version of the store's layout: rows without the units (`pounding-study-3`, 2026-11-27). A version an
/// older program does not know is refused by it with its layout named, instead of every row it cannot read
/// being run again.
pub const FORMAT: &str = "pounding-study-3";

/// The layout whose rows hold the units, read as it is and brought to [`FORMAT`] when opened.
const FORMAT_2: &str = "pounding-study-2";

/// The layout before digests, read and brought to [`FORMAT`] when opened.
const FORMAT_1: &str = "pounding-study-1";

/// One finished run.
#[derive(Clone, Debug, PartialEq)]
pub struct Finished {
    /// The run's key.
    pub key: String,
    /// Its position in the study.
    pub index: usize,
    /// The summary as JSON text, or the one-line error message.
    pub outcome: Outcome,
    /// Wall time of the run, s.
    pub seconds: f64,
}

/// A run's outcome as stored: the summary's JSON text, or the one-line error message.
pub type Outcome = Result<String, String>;

/// One stored row as read back.
#[derive(Clone, Debug, PartialEq)]
pub struct Stored {
    /// The run's key.
    pub key: String,
    /// What the row says the run gave.
    pub outcome: Outcome,
    /// Whether the row is what was committed: a known status, its text present, its digest matching. A row
    /// that is not is not to be trusted.
    pub intact: bool,
}

/// The digest of a stored run: FNV-1a-128 over its key, status and text (the summary or the message), in
/// hexadecimal. It ties a summary to its run, so that a damaged or moved summary is found.
pub fn digest(key: &str, outcome: &Outcome) -> String {
    let (status, text) = match outcome {
        Ok(s) => ("ok", s),
        Err(e) => ("error", e),
    };
    let mut bytes = Vec::with_capacity(key.len() + text.len() + 8);
    for part in [key, status, text] {
        bytes.extend_from_slice(part.as_bytes());
        bytes.push(0);
    }
    format!("{:032x}", crate::key::fnv1a_128(&bytes))
}

/// How a study meets the store at a path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fit {
    /// No store yet (or an empty one): it is created.
    New,
    /// The store of this study.
    Same,
    /// The store of an earlier study whose every stored run is a run of this one (new axis values, records
    /// or levels): it grows into this study's, keeping them.
    Grows {
        /// Runs stored, kept.
        stored: usize,
        /// Runs of the earlier study.
        of: usize,
    },
}

/// An open study store, held by this process alone (an OS lock on the file `<store>.lock` beside it, released
/// when the store is dropped or the process ends, however it ends).
pub struct Store {
    conn: Connection,
    path: std::path::PathBuf,
    /// The lock of the writing store; none for a reader ([`Store::reader`]).
    _lock: Option<std::fs::File>,
    /// How the study met it when opened.
    pub fit: Fit,
}

/// Why a store cannot be used: one line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StoreError {
    /// The file is not a store of this study (another study's, or not a study store at all): bad input.
    Mismatch(String),
    /// SQLite failed (I/O, a full disk).
    Io(String),
}

impl std::fmt::Display for StoreError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StoreError::Mismatch(m) | StoreError::Io(m) => f.write_str(m),
        }
    }
}

fn io(path: &Path) -> impl Fn(rusqlite::Error) -> StoreError + '_ {
    move |e| {
        let why = os_reason(path).unwrap_or_else(|| e.to_string());
        StoreError::Io(format!("study store {}: {why}", path.display()))
    }
}

/// The operating system's reason why the store at `path` (or a file beside it) cannot be written, if it
/// gives one: SQLite's own messages ("unable to open database file") do not say.
fn os_reason(path: &Path) -> Option<String> {
    let probe = |p: &Path| {
        std::fs::OpenOptions::new()
            .append(true)
            .open(p)
            .err()
            .filter(|e| e.kind() != std::io::ErrorKind::NotFound)
    };
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty());
    probe(path).map(|e| format!("{e}")).or_else(|| {
        // A file beside it cannot be created: the folder's reason.
        let test = dir?.join(format!(".pounding-probe-{}", std::process::id()));
        match std::fs::File::create(&test) {
            Ok(_) => {
                let _ = std::fs::remove_file(&test);
                None
            }
            Err(e) => Some(format!("{} cannot be written: {e}", dir?.display())),
        }
    })
}

/// Whether SQLite's error is about the file's content (not a database, corrupt), rather than about reaching
/// it (permissions, a read-only or full file system: I/O).
fn is_content(e: &rusqlite::Error) -> bool {
    matches!(
        e.sqlite_error_code(),
        Some(rusqlite::ErrorCode::NotADatabase | rusqlite::ErrorCode::DatabaseCorrupt)
    )
}

/// The lock file beside the store at `path`.
fn lock_path(path: &Path) -> std::path::PathBuf {
    companions(path).swap_remove(0)
}

/// The files SQLite and the lock may create beside the store at `path`.
fn companions(path: &Path) -> Vec<std::path::PathBuf> {
    [".lock", "-wal", "-shm", "-journal"]
        .iter()
        .map(|suffix| {
            let mut name = path.file_name().unwrap_or_default().to_os_string();
            name.push(suffix);
            path.with_file_name(name)
        })
        .collect()
}

/// Refuses a store, or a file beside it, that exists and is not a regular file: SQLite and the lock would
/// follow a symbolic link and write their files beside its target, or write into a device.
fn regular_files(path: &Path) -> Result<(), StoreError> {
    for p in std::iter::once(path.to_path_buf()).chain(companions(path)) {
        let what = match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => "a symbolic link",
            Ok(m) if !m.is_file() => "not a regular file",
            _ => continue,
        };
        return Err(StoreError::Mismatch(format!(
            "study store {} cannot be used: {} is {what}; allowed: regular files, or a new --out",
            path.display(),
            p.display()
        )));
    }
    Ok(())
}

impl Store {
    /// Checks, without writing anything, that the file at `path` is absent, a store of the study `id` with
    /// `runs` runs, or one that can grow into it ([`Fit`]). `keys()` gives the study's run keys in order,
    /// computed only when the identity does not settle it: a store of the first layout knew its study by the
    /// hash of its keys ([`crate::key::keys_id`]), and an earlier study's store grows when every run it
    /// stored is among them.
    pub fn check(
        path: &Path,
        id: &str,
        runs: usize,
        keys: &dyn Fn() -> Vec<String>,
    ) -> Result<Fit, StoreError> {
        regular_files(path)?;
        if !path.exists() {
            return Ok(Fit::New);
        }
        let shown = path.display();
        let mismatch = |why: String| {
            StoreError::Mismatch(format!(
                "study store {shown} {why}; allowed: a store written by this study, or a new path"
            ))
        };
        let unreadable = |e: rusqlite::Error| {
            if is_content(&e) {
                mismatch(format!("is not an SQLite database ({e})"))
            } else {
                StoreError::Io(format!(
                    "study store {shown} cannot be opened: {}",
                    os_reason(path).unwrap_or_else(|| e.to_string())
                ))
            }
        };
        let conn = Connection::open_with_flags(path, OpenFlags::SQLITE_OPEN_READ_ONLY)
            .map_err(unreadable)?;
        // An empty database (a file just created by a reader, or by `touch`) is a new store.
        let tables: i64 = conn
            .query_row("SELECT count(*) FROM sqlite_master", [], |r| r.get(0))
            .map_err(unreadable)?;
        if tables == 0 {
            return Ok(Fit::New);
        }
        let get = |name: &str| -> Result<Option<String>, rusqlite::Error> {
            conn.query_row(
                "SELECT value FROM study WHERE name = ?1",
                params![name],
                |r| r.get(0),
            )
            .optional()
        };
        let (format, stored) = match (get("format"), get("id")) {
            (Ok(f), Ok(i)) => (f, i),
            _ => {
                return Err(mismatch(
                    "is not a pounding study store (no study table)".into(),
                ))
            }
        };
        // Tables without their study rows and without runs: a store whose creation was killed before stores
        // created them in one transaction. Nothing to lose: it is taken as new.
        let stored_runs: Result<i64, _> =
            conn.query_row("SELECT count(*) FROM runs", [], |r| r.get(0));
        if format.is_none() && stored.is_none() && matches!(stored_runs, Ok(0)) {
            return Ok(Fit::New);
        }
        if !matches!(format.as_deref(), Some(FORMAT | FORMAT_2 | FORMAT_1)) {
            return Err(mismatch(format!(
                "has layout {:?}, not {FORMAT:?}",
                format.unwrap_or_default()
            )));
        }
        if stored.as_deref() == Some(id) {
            return Ok(Fit::Same);
        }
        let keys = keys();
        if format.as_deref() == Some(FORMAT_1)
            && stored.as_deref() == Some(crate::key::keys_id(&keys).as_str())
        {
            return Ok(Fit::Same);
        }
        let n = get("runs").ok().flatten().unwrap_or_default();
        let wanted: HashSet<&str> = keys.iter().map(String::as_str).collect();
        let mut st = conn.prepare("SELECT key FROM runs").map_err(unreadable)?;
        let held: Vec<String> = st
            .query_map([], |r| r.get::<_, String>(0))
            .and_then(|rows| rows.collect())
            .map_err(unreadable)?;
        if held.iter().all(|k| wanted.contains(k.as_str())) {
            return Ok(Fit::Grows {
                stored: held.len(),
                of: n.parse().unwrap_or(held.len()),
            });
        }
        Err(mismatch(format!(
            "was written by a different study ({n} runs), some of whose runs this one ({runs} runs) lacks; a store grows only into a study with all its runs"
        )))
    }

    /// Opens (or creates) the store of study `id` with `runs` runs at `path`: takes its lock (another process
    /// holding it is refused at once), checks it ([`Store::check`]), and creates its tables and study rows in
    /// one transaction, so that a kill leaves no store without its study.
    pub fn open(
        path: &Path,
        id: &str,
        runs: usize,
        keys: &dyn Fn() -> Vec<String>,
    ) -> Result<Store, StoreError> {
        let made = std::cell::OnceCell::new();
        let keys = || made.get_or_init(keys).clone();
        regular_files(path)?;
        let lp = lock_path(path);
        let lock = std::fs::OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&lp)
            .map_err(|e| StoreError::Io(format!("cannot open {}: {e}", lp.display())))?;
        match lock.try_lock() {
            Ok(()) => {}
            Err(std::fs::TryLockError::WouldBlock) => {
                return Err(StoreError::Mismatch(format!(
                    "study store {} is in use by another sweep or IDA (it holds {}); allowed: wait for it, or a new --out",
                    path.display(),
                    lp.display()
                )))
            }
            Err(std::fs::TryLockError::Error(e)) => {
                return Err(StoreError::Io(format!("cannot lock {}: {e}", lp.display())))
            }
        }
        let fit = Self::check(path, id, runs, &keys)?;
        let mut conn = Connection::open(path).map_err(io(path))?;
        // Pages of 16 KiB for a new store (no effect on an existing one): a run's row (about 2.5 KB for a
        // pair of buildings) fills a 4 KiB page alone, leaving a third of the file empty.
        conn.pragma_update(None, "page_size", 16384)
            .map_err(io(path))?;
        // WAL: a commit is durable against a killed process, and readers (pandas) never block the sweep.
        conn.pragma_update(None, "journal_mode", "WAL")
            .map_err(io(path))?;
        conn.pragma_update(None, "synchronous", "NORMAL")
            .map_err(io(path))?;
        let tx = conn
            .transaction_with_behavior(rusqlite::TransactionBehavior::Immediate)
            .map_err(io(path))?;
        tx.execute_batch(
            "CREATE TABLE IF NOT EXISTS study (name TEXT PRIMARY KEY, value TEXT NOT NULL);
             CREATE TABLE IF NOT EXISTS runs (
                 key TEXT PRIMARY KEY,
                 idx INTEGER NOT NULL,
                 status TEXT NOT NULL CHECK (status IN ('ok', 'error')),
                 summary TEXT,
                 error TEXT,
                 seconds REAL NOT NULL,
                 finished TEXT NOT NULL,
                 digest TEXT
             );",
        )
        .map_err(io(path))?;
        migrate(&tx, id).map_err(io(path))?;
        if let Fit::Grows { .. } = fit {
            grow(&tx, id, &keys()).map_err(io(path))?;
        }
        tx.execute(
            "INSERT OR IGNORE INTO study (name, value) VALUES ('format', ?1), ('id', ?2), ('runs', ?3), ('created', datetime('now')), ('units', ?4)",
            params![FORMAT, id, runs.to_string(), crate::summary::units_text()],
        )
        .map_err(io(path))?;
        tx.commit().map_err(io(path))?;
        Ok(Store {
            conn,
            path: path.to_path_buf(),
            _lock: Some(lock),
            fit,
        })
    }

    /// The keys of the runs already finished, as numbers (a key that is not hexadecimal is no run of a
    /// study's, and is left out): each parsed as it is read, so that a store of a million runs is never held
    /// as a million strings (about 90 MB more at the start of a resumed sweep).
    pub fn finished_keys(&self) -> Result<HashSet<u128>, StoreError> {
        let err = io(&self.path);
        let mut st = self.conn.prepare("SELECT key FROM runs").map_err(&err)?;
        let mut keys = HashSet::new();
        let mut rows = st.query([]).map_err(&err)?;
        while let Some(row) = rows.next().map_err(&err)? {
            let key = row.get_ref(0).map_err(&err)?;
            if let Some(k) = key
                .as_str()
                .ok()
                .and_then(|k| u128::from_str_radix(k, 16).ok())
            {
                keys.insert(k);
            }
        }
        Ok(keys)
    }

    /// Commits `runs` in one transaction (a run stored again, after its stored summary was found damaged,
    /// replaces it).
    pub fn commit(&mut self, runs: &[Finished]) -> Result<(), StoreError> {
        let path = self.path.clone();
        let err = io(&path);
        let tx = self.conn.transaction().map_err(&err)?;
        {
            let mut st = tx
                .prepare_cached(
                    "INSERT OR REPLACE INTO runs (key, idx, status, summary, error, seconds, finished, digest)
                     VALUES (?1, ?2, ?3, ?4, ?5, ?6, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'), ?7)",
                )
                .map_err(&err)?;
            for r in runs {
                let (status, summary, error) = match &r.outcome {
                    Ok(s) => ("ok", Some(s.as_str()), None),
                    Err(e) => ("error", None, Some(e.as_str())),
                };
                st.execute(params![
                    r.key,
                    r.index as i64,
                    status,
                    summary,
                    error,
                    r.seconds,
                    digest(&r.key, &r.outcome)
                ])
                .map_err(&err)?;
            }
        }
        tx.commit().map_err(&err)
    }

    /// Every stored run, in study order, each with whether it is intact ([`Stored::intact`]).
    pub fn all(&self) -> Result<Vec<Stored>, StoreError> {
        let err = io(&self.path);
        let mut st = self
            .conn
            .prepare("SELECT key, status, summary, error, digest FROM runs ORDER BY idx")
            .map_err(&err)?;
        let rows = st
            .query_map([], stored_row)
            .and_then(|rows| rows.collect::<Result<Vec<_>, _>>())
            .map_err(&err);
        rows
    }

    /// The stored run of `key`, if any.
    pub fn get(&self, key: &str) -> Result<Option<Stored>, StoreError> {
        let err = io(&self.path);
        let mut st = self
            .conn
            .prepare_cached("SELECT key, status, summary, error, digest FROM runs WHERE key = ?1")
            .map_err(&err)?;
        st.query_row(params![key], stored_row)
            .optional()
            .map_err(&err)
    }

    /// A second, read-only connection to this store (for a worker thread to look up stored runs while this
    /// one commits: the store's WAL lets readers and the writer work at once).
    pub fn reader(&self) -> Result<Store, StoreError> {
        let conn = Connection::open_with_flags(
            &self.path,
            OpenFlags::SQLITE_OPEN_READ_ONLY | OpenFlags::SQLITE_OPEN_NO_MUTEX,
        )
        .map_err(io(&self.path))?;
        Ok(Store {
            conn,
            path: self.path.clone(),
            _lock: None,
            fit: Fit::Same,
        })
    }
}

/// A row `(key, status, summary, error, digest)` as [`Stored`]. Read as values, not as typed columns: a
/// damaged row (a number where text belongs) is a run to run again, not a failure of the store.
fn stored_row(r: &rusqlite::Row<'_>) -> rusqlite::Result<Stored> {
    let text = |i: usize| -> rusqlite::Result<Option<String>> {
        Ok(match r.get_ref(i)? {
            rusqlite::types::ValueRef::Text(t) => Some(String::from_utf8_lossy(t).into_owned()),
            _ => None,
        })
    };
    let key = text(0)?.unwrap_or_default();
    let (outcome, present) = match text(1)?.as_deref() {
        Some("ok") => text(2)?.map_or((Ok(String::new()), false), |s| (Ok(s), true)),
        Some("error") => text(3)?.map_or((Err(String::new()), false), |e| (Err(e), true)),
        _ => (Err(String::new()), false),
    };
    let intact = present && text(4)?.as_deref() == Some(digest(&key, &outcome).as_str());
    Ok(Stored {
        key,
        outcome,
        intact,
    })
}

/// Brings a store of layout [`FORMAT_1`] (already checked to be of this study) to [`FORMAT`] inside the
/// opening transaction `tx`: a `digest` column, each row's digest from what it holds (its summaries are
/// checked when read, as before), the study's identity `id`, the new format. A store of the current layout is
/// left as it is.
/// Makes the store of an earlier study the store of study `id` whose run keys are `keys`: its identity and
/// count, and the position of each stored run in the new study.
fn grow(tx: &rusqlite::Transaction<'_>, id: &str, keys: &[String]) -> rusqlite::Result<()> {
    tx.execute("UPDATE study SET value = ?1 WHERE name = 'id'", params![id])?;
    tx.execute(
        "UPDATE study SET value = ?1 WHERE name = 'runs'",
        params![keys.len().to_string()],
    )?;
    let mut st = tx.prepare("UPDATE runs SET idx = ?2 WHERE key = ?1")?;
    for (i, k) in keys.iter().enumerate() {
        st.execute(params![k, i as i64])?;
    }
    Ok(())
}

fn migrate(tx: &rusqlite::Transaction<'_>, id: &str) -> rusqlite::Result<()> {
    if tx.prepare("SELECT digest FROM runs LIMIT 0").is_err() {
        tx.execute_batch("ALTER TABLE runs ADD COLUMN digest TEXT")?;
    }
    let format: Option<String> = tx
        .query_row("SELECT value FROM study WHERE name = 'format'", [], |r| {
            r.get(0)
        })
        .optional()?;
    if format.as_deref() == Some(FORMAT_2) {
        // Its rows hold the units and read as they are; the study rows gain `units` in `open`.
        tx.execute(
            "UPDATE study SET value = ?1 WHERE name = 'format'",
            params![FORMAT],
        )?;
        return Ok(());
    }
    if format.as_deref() != Some(FORMAT_1) {
        return Ok(());
    }
    let rows: Vec<(String, Outcome)> = {
        let mut st = tx.prepare(
            "SELECT key, status, summary, error FROM runs WHERE typeof(key) = 'text' AND (
                 (status = 'ok' AND typeof(summary) = 'text') OR (status = 'error' AND typeof(error) = 'text'))",
        )?;
        let rows = st.query_map([], |r| {
            let key: String = r.get(0)?;
            let outcome = if r.get::<_, String>(1)? == "ok" {
                Ok(r.get(2)?)
            } else {
                Err(r.get(3)?)
            };
            Ok((key, outcome))
        })?;
        rows.collect::<Result<_, _>>()?
    };
    let mut st = tx.prepare("UPDATE runs SET digest = ?2 WHERE key = ?1")?;
    for (key, outcome) in &rows {
        st.execute(params![key, digest(key, outcome)])?;
    }
    tx.execute(
        "UPDATE study SET value = ?1 WHERE name = 'format'",
        params![FORMAT],
    )?;
    tx.execute("UPDATE study SET value = ?1 WHERE name = 'id'", params![id])?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tables of the first layout (`pounding-study-1`), before digests.
    const LAYOUT_1: &str = "CREATE TABLE study (name TEXT PRIMARY KEY, value TEXT NOT NULL);
         CREATE TABLE runs (key TEXT PRIMARY KEY, idx INTEGER NOT NULL, status TEXT NOT NULL,
             summary TEXT, error TEXT, seconds REAL NOT NULL, finished TEXT NOT NULL);";

    /// No first-layout identity.
    fn none() -> Vec<String> {
        Vec::new()
    }

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir =
            std::env::temp_dir().join(format!("pounding-store-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_second_open_of_a_store_in_use_is_refused_at_once() {
        let dir = scratch("lock");
        let path = dir.join("study.sqlite");
        let first = Store::open(&path, "a", 2, &none).unwrap();
        // Another study, or the same one: refused while the first holds the store.
        for id in ["b", "a"] {
            match Store::open(&path, id, 2, &none) {
                Err(StoreError::Mismatch(m)) => assert!(m.contains("in use"), "{m}"),
                Err(e) => panic!("{e}"),
                Ok(_) => panic!("two holders of one store"),
            }
        }
        drop(first);
        let mut a = Store::open(&path, "a", 2, &none).unwrap();
        let run = Finished {
            key: "k".into(),
            index: 0,
            outcome: Err("failed".into()),
            seconds: 0.1,
        };
        a.commit(&[run]).unwrap();
        drop(a);
        // Study b does not hold study a's run: its store is not b's to grow.
        assert!(
            matches!(Store::open(&path, "b", 2, &none), Err(StoreError::Mismatch(m)) if m.contains("different study"))
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_store_killed_while_it_was_created_is_taken_as_new() {
        // What a kill between the tables and the study rows left before they were one transaction.
        let dir = scratch("half");
        let path = dir.join("study.sqlite");
        let conn = Connection::open(&path).unwrap();
        conn.execute_batch(LAYOUT_1).unwrap();
        drop(conn);
        assert_eq!(Store::check(&path, "a", 1, &none), Ok(Fit::New));
        let mut s = Store::open(&path, "a", 1, &none).unwrap();
        let run = Finished {
            key: "k".into(),
            index: 0,
            outcome: Err("failed".into()),
            seconds: 0.1,
        };
        s.commit(std::slice::from_ref(&run)).unwrap();
        drop(s);
        // Now it is study a's, with its run.
        assert!(matches!(
            Store::check(&path, "b", 1, &none),
            Err(StoreError::Mismatch(_))
        ));
        let s = Store::open(&path, "a", 1, &none).unwrap();
        assert_eq!(
            s.all().unwrap(),
            vec![Stored {
                key: "k".into(),
                outcome: Err("failed".into()),
                intact: true
            }]
        );
        drop(s);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    fn finished(key: &str, index: usize, outcome: Outcome) -> Finished {
        Finished {
            key: key.into(),
            index,
            outcome,
            seconds: 0.5,
        }
    }

    #[test]
    fn a_row_changed_after_its_commit_is_not_intact() {
        let dir = scratch("digest");
        let path = dir.join("study.sqlite");
        let mut s = Store::open(&path, "a", 4, &none).unwrap();
        s.commit(&[
            finished("k0", 0, Ok("{\"x\":1.5}".into())),
            finished("k1", 1, Ok("{\"x\":2.5}".into())),
            finished("k2", 2, Err("failed".into())),
            finished("k3", 3, Ok("{\"x\":3.5}".into())),
        ])
        .unwrap();
        drop(s);
        let conn = Connection::open(&path).unwrap();
        // A digit changed (still valid JSON), two summaries swapped between runs, a message nulled; k3 as it was.
        conn.execute_batch(
            "UPDATE runs SET summary = '{\"x\":1.6}' WHERE key = 'k0';
             UPDATE runs SET summary = '{\"x\":1.5}' WHERE key = 'k1';
             UPDATE runs SET error = NULL WHERE key = 'k2';",
        )
        .unwrap();
        drop(conn);
        let s = Store::open(&path, "a", 4, &none).unwrap();
        let intact: Vec<(String, bool)> = s
            .all()
            .unwrap()
            .into_iter()
            .map(|r| (r.key, r.intact))
            .collect();
        assert_eq!(
            intact,
            [("k0", false), ("k1", false), ("k2", false), ("k3", true)]
                .map(|(k, i)| (k.to_string(), i))
        );
        drop(s);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_store_of_the_first_layout_gets_its_digests_when_opened() {
        let dir = scratch("layout1");
        let path = dir.join("study.sqlite");
        let conn = Connection::open(&path).unwrap();
        conn.execute_batch(LAYOUT_1).unwrap();
        // A first-layout store knew its study by the hash of its run keys.
        let legacy = || vec!["k0".to_string(), "k1".to_string()];
        conn.execute_batch(&format!(
            "INSERT INTO study VALUES ('format', 'pounding-study-1'), ('id', '{}'), ('runs', '2');
             INSERT INTO runs VALUES ('k0', 0, 'ok', '{{}}', NULL, 0.1, 'then'),
                                     ('k1', 1, 'ok', NULL, NULL, 0.1, 'then');",
            crate::key::keys_id(&legacy())
        ))
        .unwrap();
        drop(conn);
        // Known by its first-layout identity, the hash of its keys; the study's identity is now "new".
        assert!(Store::check(&path, "new", 2, &none).is_err());
        assert_eq!(Store::check(&path, "new", 2, &legacy), Ok(Fit::Same));
        let s = Store::open(&path, "new", 2, &legacy).unwrap();
        let rows = s.all().unwrap();
        assert_eq!(rows.len(), 2);
        assert!(rows[0].intact && !rows[1].intact, "{rows:?}");
        drop(s);
        let conn = Connection::open(&path).unwrap();
        let format: String = conn
            .query_row("SELECT value FROM study WHERE name = 'format'", [], |r| {
                r.get(0)
            })
            .unwrap();
        assert_eq!(format, FORMAT);
        drop(conn);
        assert_eq!(Store::check(&path, "new", 2, &none), Ok(Fit::Same));
        assert!(Store::check(&path, "a", 2, &none).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_store_of_the_second_layout_reads_as_it_is_and_gets_the_units_row() {
        let dir = scratch("layout2");
        let path = dir.join("study.sqlite");
        let mut s = Store::open(&path, "a", 2, &none).unwrap();
        let whole = r#"{"units":{"gap":"m"},"warnings":[]}"#;
        s.commit(&[finished("k0", 0, Ok(whole.into()))]).unwrap();
        drop(s);
        // As the second layout left it: its name, no units row.
        let conn = Connection::open(&path).unwrap();
        conn.execute_batch(
            "UPDATE study SET value = 'pounding-study-2' WHERE name = 'format';
             DELETE FROM study WHERE name = 'units';",
        )
        .unwrap();
        drop(conn);
        assert_eq!(Store::check(&path, "a", 2, &none), Ok(Fit::Same));
        let s = Store::open(&path, "a", 2, &none).unwrap();
        let rows = s.all().unwrap();
        assert!(
            rows[0].intact && rows[0].outcome == Ok(whole.to_string()),
            "{rows:?}"
        );
        drop(s);
        let conn = Connection::open(&path).unwrap();
        let get = |name: &str| -> String {
            conn.query_row("SELECT value FROM study WHERE name = ?1", [name], |r| {
                r.get(0)
            })
            .unwrap()
        };
        assert_eq!(get("format"), FORMAT);
        assert_eq!(get("units"), crate::summary::units_text());
        // A layout this program does not know (a later one) is refused, naming it.
        conn.execute(
            "UPDATE study SET value = 'pounding-study-9' WHERE name = 'format'",
            [],
        )
        .unwrap();
        drop(conn);
        assert!(
            matches!(Store::check(&path, "a", 2, &none), Err(StoreError::Mismatch(m)) if m.contains("pounding-study-9"))
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_store_that_is_a_link_or_beside_one_is_refused() {
        let dir = scratch("link");
        let target = dir.join("elsewhere.sqlite");
        drop(Store::open(&target, "a", 1, &none).unwrap());
        let path = dir.join("study.sqlite");
        std::os::unix::fs::symlink(&target, &path).unwrap();
        for result in [
            Store::check(&path, "a", 1, &none).err(),
            Store::open(&path, "a", 1, &none).err(),
        ] {
            assert!(
                matches!(&result, Some(StoreError::Mismatch(m)) if m.contains("is a symbolic link")),
                "{result:?}"
            );
        }
        std::fs::remove_file(&path).unwrap();
        // A lock or journal beside the store that leads elsewhere.
        std::os::unix::fs::symlink("/dev/null", dir.join("study.sqlite-wal")).unwrap();
        assert!(
            matches!(Store::open(&path, "a", 1, &none), Err(StoreError::Mismatch(m)) if m.contains("study.sqlite-wal is a symbolic link"))
        );
        assert!(!path.exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_file_that_is_no_database_is_bad_input() {
        let dir = scratch("junk");
        let path = dir.join("study.sqlite");
        std::fs::write(&path, vec![7u8; 4096]).unwrap();
        assert!(
            matches!(Store::check(&path, "a", 1, &none), Err(StoreError::Mismatch(m)) if m.contains("not an SQLite database"))
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
