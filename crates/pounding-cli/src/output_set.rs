//! A run's output folder, written as a whole. Files go into a fresh hidden folder beside the target; when all
//! are written (and flushed), one rename puts the folder in place of the target. A kill leaves either the
//! earlier folder or the new one, never a mix, and no temporary file inside the target. A marker file lists
//! the run's data files with their sizes and hashes, so that `pounding report` can refuse a folder whose files
//! do not come from one run, and so that an existing folder is replaced only if a run wrote it.

use crate::error::CliError;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Name of the marker file of a run's output folder.
pub const MARKER: &str = ".pounding-run";

/// Prefix of the temporary folders, beside the target.
const TMP_PREFIX: &str = ".pounding-tmp-";

/// FNV-1a, 64 bits: enough to tell one run's file from another's (not a defence against forgery).
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(*b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// The folder a run's files are written into before they appear at the target.
pub struct OutputSet {
    target: PathBuf,
    tmp: PathBuf,
    /// Data files recorded in the marker: name, size, hash.
    listed: Vec<(String, usize, u64)>,
    done: bool,
}

fn io(what: &str, path: &Path, e: std::io::Error) -> CliError {
    CliError::Io(format!("cannot {what} {}: {e}", path.display()))
}

impl OutputSet {
    /// Checks that `target` may be written: absent, empty, or an earlier run's folder.
    pub fn check(target: &Path) -> Result<(), CliError> {
        if target.exists() {
            if !target.is_dir() {
                return Err(CliError::Input(format!(
                    "--out {} is a file; give a folder (it is created if missing)",
                    target.display()
                )));
            }
            let empty = std::fs::read_dir(target)
                .map_err(|e| io("read", target, e))?
                .next()
                .is_none();
            if !empty && !target.join(MARKER).is_file() {
                return Err(CliError::Input(format!(
                    "--out {} exists and is not the output folder of an earlier run (no {MARKER} in it): give a new or empty folder",
                    target.display()
                )));
            }
        }
        Ok(())
    }

    /// Checks `target` again and creates the temporary folder beside it. Nothing is written at the target yet.
    pub fn begin(target: &Path) -> Result<Self, CliError> {
        Self::check(target)?;
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(|e| io("create", &parent, e))?;
        remove_stale(&parent);
        let nonce = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.subsec_nanos());
        let tmp = parent.join(format!("{TMP_PREFIX}{}-{nonce}", std::process::id()));
        std::fs::create_dir(&tmp).map_err(|e| io("create", &tmp, e))?;
        Ok(Self {
            target: target.to_path_buf(),
            tmp,
            listed: Vec::new(),
            done: false,
        })
    }

    /// The folder being written (where `RunData::load` reads the data files back for figures and report).
    pub fn dir(&self) -> &Path {
        &self.tmp
    }

    /// Writes one file and flushes it to disk.
    pub fn write(&self, name: &str, bytes: &[u8]) -> Result<(), CliError> {
        let p = self.tmp.join(name);
        let mut f = std::fs::File::create(&p).map_err(|e| io("write", &p, e))?;
        f.write_all(bytes)
            .and_then(|_| f.sync_all())
            .map_err(|e| io("write", &p, e))
    }

    /// Writes a data file and lists it in the marker.
    pub fn write_data(&mut self, name: &str, bytes: &[u8]) -> Result<(), CliError> {
        self.write(name, bytes)?;
        self.listed
            .push((name.to_string(), bytes.len(), fnv1a(bytes)));
        Ok(())
    }

    /// Writes the marker and puts the folder in place of the target, replacing an earlier run's folder.
    pub fn commit(mut self) -> Result<(), CliError> {
        let mut marker = String::from("pounding run output\n");
        for (name, size, hash) in &self.listed {
            marker.push_str(&format!("{name} {size} {hash:016x}\n"));
        }
        self.write(MARKER, marker.as_bytes())?;
        if self.target.exists() {
            // An earlier run's folder (checked in `begin`): moved aside, then removed.
            let old = self.tmp.with_extension("old");
            std::fs::rename(&self.target, &old).map_err(|e| io("replace", &self.target, e))?;
            if let Err(e) = std::fs::rename(&self.tmp, &self.target) {
                let _ = std::fs::rename(&old, &self.target);
                return Err(io("replace", &self.target, e));
            }
            let _ = std::fs::remove_dir_all(&old);
        } else {
            std::fs::rename(&self.tmp, &self.target).map_err(|e| io("create", &self.target, e))?;
        }
        self.done = true;
        Ok(())
    }
}

impl Drop for OutputSet {
    fn drop(&mut self) {
        if !self.done {
            let _ = std::fs::remove_dir_all(&self.tmp);
        }
    }
}

/// Removes temporary folders left in `parent` by runs that were killed (their process is gone).
fn remove_stale(parent: &Path) {
    let Ok(entries) = std::fs::read_dir(parent) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some(rest) = name.strip_prefix(TMP_PREFIX) else {
            continue;
        };
        let pid = rest.split(['-', '.']).next().unwrap_or("");
        let alive = Path::new("/proc").join(pid).exists() || !Path::new("/proc/self").exists();
        if !alive && pid.parse::<u32>().is_ok() {
            let _ = std::fs::remove_dir_all(e.path());
        }
    }
}

/// Checks that the data files of `dir` are those its marker lists (one run's files); an error says which
/// file differs.
pub fn verify(dir: &Path) -> Result<(), String> {
    let marker = std::fs::read_to_string(dir.join(MARKER)).map_err(|_| {
        format!("no {MARKER}: not an output folder of `pounding run` (or one written before version 0.1 kept a marker)")
    })?;
    for line in marker.lines().skip(1) {
        let mut parts = line.split(' ');
        let (Some(name), Some(size), Some(hash)) = (parts.next(), parts.next(), parts.next())
        else {
            return Err(format!("{MARKER}: malformed line {line:?}"));
        };
        let bytes = std::fs::read(dir.join(name))
            .map_err(|e| format!("{name}, listed in {MARKER}, cannot be read: {e}"))?;
        if bytes.len().to_string() != size || format!("{:016x}", fnv1a(&bytes)) != hash {
            return Err(format!(
                "{name} is not the file this run wrote (its size or content changed): the folder mixes files of different runs"
            ));
        }
    }
    Ok(())
}
