//! The study store: one SQLite file holding every finished run of one study, committed as it finishes, so that
//! an interrupted sweep resumes where it stopped and never repeats or loses a finished run.
//!
//! Tables:
//! - `runs(key TEXT PRIMARY KEY, idx INTEGER, status TEXT, summary TEXT, error TEXT, seconds REAL,
//!   finished TEXT)`: `key` the run's hash ([`crate::key`]), `idx` its position in the study (from 0),
//!   `status` `ok` or `error`, `summary` the run's summary as JSON text (`summary.json`'s content; NULL for an
//!   error), `error` the one-line message (NULL if ok), `seconds` the run's wall time (s), `finished` the UTC
//!   time it was committed.
//! - `study(name TEXT PRIMARY KEY, value TEXT)`: `id` (the hash of the study's run keys, in order), `runs`
//!   (their number), `format` (this layout's version), `created`.

use rusqlite::{params, Connection, OpenFlags, OptionalExtension};
use std::collections::HashSet;
use std::path::Path;

/// Version of the store's layout.
pub const FORMAT: &str = "pounding-study-1";

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

/// An open study store.
pub struct Store {
    conn: Connection,
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
    move |e| StoreError::Io(format!("study store {}: {e}", path.display()))
}

impl Store {
    /// Checks, without writing anything, that the file at `path` is absent or a store of the study `id`
    /// with `runs` runs.
    pub fn check(path: &Path, id: &str, runs: usize) -> Result<(), StoreError> {
        if !path.exists() {
            return Ok(());
        }
        let shown = path.display();
        let mismatch = |why: String| {
            StoreError::Mismatch(format!(
                "study store {shown} {why}; allowed: a store written by this study, or a new path"
            ))
        };
        let conn = Connection::open_with_flags(path, OpenFlags::SQLITE_OPEN_READ_ONLY)
            .map_err(|e| mismatch(format!("cannot be opened ({e})")))?;
        // An empty database (a file just created by a reader, or by `touch`) is a new store.
        let tables: Result<i64, _> =
            conn.query_row("SELECT count(*) FROM sqlite_master", [], |r| r.get(0));
        match tables {
            Ok(0) => return Ok(()),
            Ok(_) => {}
            Err(e) => return Err(mismatch(format!("is not an SQLite database ({e})"))),
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
        if format.as_deref() != Some(FORMAT) {
            return Err(mismatch(format!(
                "has layout {:?}, not {FORMAT:?}",
                format.unwrap_or_default()
            )));
        }
        if stored.as_deref() != Some(id) {
            let n = get("runs").ok().flatten().unwrap_or_default();
            return Err(mismatch(format!(
                "was written by a different study (id {}, {n} runs; this study: id {id}, {runs} runs)",
                stored.unwrap_or_default()
            )));
        }
        Ok(())
    }

    /// Opens (or creates) the store of study `id` with `runs` runs at `path`, after [`Store::check`].
    pub fn open(path: &Path, id: &str, runs: usize) -> Result<Store, StoreError> {
        Self::check(path, id, runs)?;
        let conn = Connection::open(path).map_err(io(path))?;
        // WAL: a commit is durable against a killed process, and readers (pandas) never block the sweep.
        conn.pragma_update(None, "journal_mode", "WAL")
            .map_err(io(path))?;
        conn.pragma_update(None, "synchronous", "NORMAL")
            .map_err(io(path))?;
        conn.execute_batch(
            "CREATE TABLE IF NOT EXISTS study (name TEXT PRIMARY KEY, value TEXT NOT NULL);
             CREATE TABLE IF NOT EXISTS runs (
                 key TEXT PRIMARY KEY,
                 idx INTEGER NOT NULL,
                 status TEXT NOT NULL CHECK (status IN ('ok', 'error')),
                 summary TEXT,
                 error TEXT,
                 seconds REAL NOT NULL,
                 finished TEXT NOT NULL
             );",
        )
        .map_err(io(path))?;
        conn.execute(
            "INSERT OR IGNORE INTO study (name, value) VALUES ('format', ?1), ('id', ?2), ('runs', ?3), ('created', datetime('now'))",
            params![FORMAT, id, runs.to_string()],
        )
        .map_err(io(path))?;
        Ok(Store { conn })
    }

    /// The keys of the runs already finished.
    pub fn finished_keys(&self) -> Result<HashSet<String>, StoreError> {
        let mut st = self
            .conn
            .prepare("SELECT key FROM runs")
            .map_err(|e| StoreError::Io(e.to_string()))?;
        let keys = st
            .query_map([], |r| r.get::<_, String>(0))
            .and_then(|rows| rows.collect::<Result<HashSet<_>, _>>())
            .map_err(|e| StoreError::Io(e.to_string()));
        keys
    }

    /// Commits `runs` in one transaction (a run stored again, after its stored summary was found damaged,
    /// replaces it).
    pub fn commit(&mut self, runs: &[Finished]) -> Result<(), StoreError> {
        let err = |e: rusqlite::Error| StoreError::Io(format!("study store: {e}"));
        let tx = self.conn.transaction().map_err(err)?;
        {
            let mut st = tx
                .prepare_cached(
                    "INSERT OR REPLACE INTO runs (key, idx, status, summary, error, seconds, finished)
                     VALUES (?1, ?2, ?3, ?4, ?5, ?6, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))",
                )
                .map_err(err)?;
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
                    r.seconds
                ])
                .map_err(err)?;
            }
        }
        tx.commit().map_err(err)
    }

    /// Every stored run: `(key, outcome)` with the summary's JSON text or the error message.
    pub fn all(&self) -> Result<Vec<(String, Outcome)>, StoreError> {
        let err = |e: rusqlite::Error| StoreError::Io(format!("study store: {e}"));
        let mut st = self
            .conn
            .prepare("SELECT key, status, summary, error FROM runs ORDER BY idx")
            .map_err(err)?;
        let rows = st
            .query_map([], |r| {
                let key: String = r.get(0)?;
                let status: String = r.get(1)?;
                let outcome = if status == "ok" {
                    Ok(r.get::<_, Option<String>>(2)?.unwrap_or_default())
                } else {
                    Err(r.get::<_, Option<String>>(3)?.unwrap_or_default())
                };
                Ok((key, outcome))
            })
            .and_then(|rows| rows.collect::<Result<Vec<_>, _>>())
            .map_err(err);
        rows
    }
}
