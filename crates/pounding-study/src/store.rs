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

/// An open study store, held by this process alone (an OS lock on the file `<store>.lock` beside it, released
/// when the store is dropped or the process ends, however it ends).
pub struct Store {
    conn: Connection,
    _lock: std::fs::File,
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
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(".lock");
    path.with_file_name(name)
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
        let unreadable = |e: rusqlite::Error| {
            if is_content(&e) {
                mismatch(format!("is not an SQLite database ({e})"))
            } else {
                StoreError::Io(format!("study store {shown} cannot be read: {e}"))
            }
        };
        let conn = Connection::open_with_flags(path, OpenFlags::SQLITE_OPEN_READ_ONLY)
            .map_err(unreadable)?;
        // An empty database (a file just created by a reader, or by `touch`) is a new store.
        let tables: i64 = conn
            .query_row("SELECT count(*) FROM sqlite_master", [], |r| r.get(0))
            .map_err(unreadable)?;
        if tables == 0 {
            return Ok(());
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
            return Ok(());
        }
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

    /// Opens (or creates) the store of study `id` with `runs` runs at `path`: takes its lock (another process
    /// holding it is refused at once), checks it ([`Store::check`]), and creates its tables and study rows in
    /// one transaction, so that a kill leaves no store without its study.
    pub fn open(path: &Path, id: &str, runs: usize) -> Result<Store, StoreError> {
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
        Self::check(path, id, runs)?;
        let mut conn = Connection::open(path).map_err(io(path))?;
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
                 finished TEXT NOT NULL
             );",
        )
        .map_err(io(path))?;
        tx.execute(
            "INSERT OR IGNORE INTO study (name, value) VALUES ('format', ?1), ('id', ?2), ('runs', ?3), ('created', datetime('now'))",
            params![FORMAT, id, runs.to_string()],
        )
        .map_err(io(path))?;
        tx.commit().map_err(io(path))?;
        Ok(Store { conn, _lock: lock })
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

#[cfg(test)]
mod tests {
    use super::*;

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
        let first = Store::open(&path, "a", 2).unwrap();
        // Another study, or the same one: refused while the first holds the store.
        for id in ["b", "a"] {
            match Store::open(&path, id, 2) {
                Err(StoreError::Mismatch(m)) => assert!(m.contains("in use"), "{m}"),
                Err(e) => panic!("{e}"),
                Ok(_) => panic!("two holders of one store"),
            }
        }
        drop(first);
        assert!(Store::open(&path, "a", 2).is_ok());
        assert!(
            matches!(Store::open(&path, "b", 2), Err(StoreError::Mismatch(m)) if m.contains("different study"))
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_store_killed_while_it_was_created_is_taken_as_new() {
        // What a kill between the tables and the study rows left before they were one transaction.
        let dir = scratch("half");
        let path = dir.join("study.sqlite");
        let conn = Connection::open(&path).unwrap();
        conn.execute_batch(
            "CREATE TABLE study (name TEXT PRIMARY KEY, value TEXT NOT NULL);
             CREATE TABLE runs (key TEXT PRIMARY KEY, idx INTEGER NOT NULL, status TEXT NOT NULL,
                 summary TEXT, error TEXT, seconds REAL NOT NULL, finished TEXT NOT NULL);",
        )
        .unwrap();
        drop(conn);
        assert_eq!(Store::check(&path, "a", 1), Ok(()));
        let mut s = Store::open(&path, "a", 1).unwrap();
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
            Store::check(&path, "b", 1),
            Err(StoreError::Mismatch(_))
        ));
        let s = Store::open(&path, "a", 1).unwrap();
        assert_eq!(
            s.all().unwrap(),
            vec![("k".to_string(), Err("failed".to_string()))]
        );
        drop(s);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_file_that_is_no_database_is_bad_input() {
        let dir = scratch("junk");
        let path = dir.join("study.sqlite");
        std::fs::write(&path, vec![7u8; 4096]).unwrap();
        assert!(
            matches!(Store::check(&path, "a", 1), Err(StoreError::Mismatch(m)) if m.contains("not an SQLite database"))
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
