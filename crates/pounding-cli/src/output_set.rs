//! A run's output folder, written as a whole. Files go into a fresh hidden folder beside the target; when all
//! are written, one rename puts the folder in place of the target, and an fsync of the parent makes that
//! rename durable. A kill leaves either the earlier folder or the new one, never a mix, and no temporary file
//! inside the target. A marker file lists the run's data files with their sizes and hashes, so that
//! `pounding report` can refuse a folder whose files do not come from one run (or whose data a power loss
//! kept from the disk: the files are not fsynced one by one, which cost more than formatting them), and so
//! that an existing folder is replaced only if a run wrote it.

use crate::error::CliError;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Name of the marker file of a run's output folder.
pub const MARKER: &str = ".pounding-run";

/// Prefix of the temporary folders, beside the target.
const TMP_PREFIX: &str = ".pounding-tmp-";

/// First line of a marker whose hashes are [`WordHash`]es.
const MARKER_V2: &str = "pounding run output v2";

/// First line of the markers written before version 2, whose hashes are [`fnv1a`]s (still read).
const MARKER_V1: &str = "pounding run output";

/// FNV-1a, 64 bits, byte by byte: the hash of markers before version 2.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(*b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// A hash of 8-byte words (the last one padded with zeros; the size is listed beside it), eight times faster
/// than [`fnv1a`]: each step is a bijection of the running value, so a file that differs from the listed one
/// in any single word always hashes differently. Enough to tell one run's file from another's, not a defence
/// against forgery. Fed in pieces of any length, as a buffered writer hands them on.
#[derive(Clone, Copy)]
struct WordHash {
    h: u64,
    /// Bytes of an incomplete word, and how many.
    tail: [u8; 8],
    len: usize,
}

impl WordHash {
    fn new() -> Self {
        Self {
            h: 0xcbf2_9ce4_8422_2325,
            tail: [0; 8],
            len: 0,
        }
    }

    fn step(&mut self, w: [u8; 8]) {
        self.h =
            (self.h.rotate_left(5) ^ u64::from_le_bytes(w)).wrapping_mul(0x517c_c1b7_2722_0a95);
    }

    fn update(&mut self, mut bytes: &[u8]) {
        if self.len > 0 {
            let n = (8 - self.len).min(bytes.len());
            self.tail[self.len..self.len + n].copy_from_slice(&bytes[..n]);
            self.len += n;
            bytes = &bytes[n..];
            if self.len < 8 {
                return;
            }
            self.step(self.tail);
            self.len = 0;
        }
        let mut words = bytes.chunks_exact(8);
        for w in &mut words {
            let mut word = [0u8; 8];
            word.copy_from_slice(w);
            self.step(word);
        }
        let rest = words.remainder();
        self.tail[..rest.len()].copy_from_slice(rest);
        self.len = rest.len();
    }

    fn finish(mut self) -> u64 {
        if self.len > 0 {
            self.tail[self.len..].fill(0);
            self.step(self.tail);
        }
        self.h
    }

    fn of(bytes: &[u8]) -> u64 {
        let mut h = Self::new();
        h.update(bytes);
        h.finish()
    }
}

/// A data file of the set being written: bytes go to the file through a buffer, and are counted and hashed
/// on their way for the marker. [`OutputSet::finish`] lists it.
pub struct DataFile {
    out: std::io::BufWriter<Counted>,
    name: String,
}

/// The file under the buffer, with the size and hash of what reached it.
struct Counted {
    file: std::fs::File,
    size: usize,
    hash: WordHash,
}

impl Write for Counted {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let n = self.file.write(buf)?;
        self.size += n;
        self.hash.update(&buf[..n]);
        Ok(n)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.file.flush()
    }
}

impl Write for DataFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.out.write(buf)
    }

    fn write_all(&mut self, buf: &[u8]) -> std::io::Result<()> {
        self.out.write_all(buf)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.out.flush()
    }
}

/// The folder a run's files are written into before they appear at the target.
pub struct OutputSet {
    target: PathBuf,
    tmp: PathBuf,
    /// Data files recorded in the marker: name, size, hash (files may be written on several threads).
    listed: std::sync::Mutex<Vec<(String, usize, u64)>>,
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
            listed: Default::default(),
            done: false,
        })
    }

    /// The folder being written (where `RunData::load` reads the data files back for figures and report).
    pub fn dir(&self) -> &Path {
        &self.tmp
    }

    /// Writes one file (in one system call: `bytes` is the whole file).
    pub fn write(&self, name: &str, bytes: &[u8]) -> Result<(), CliError> {
        let p = self.tmp.join(name);
        let mut f = std::fs::File::create(&p).map_err(|e| io("write", &p, e))?;
        f.write_all(bytes).map_err(|e| io("write", &p, e))
    }

    /// Writes a data file and lists it in the marker.
    pub fn write_data(&self, name: &str, bytes: &[u8]) -> Result<(), CliError> {
        let mut f = self.create(name)?;
        f.write_all(bytes).map_err(|e| self.error(name, e))?;
        self.finish(f)
    }

    /// Creates a data file in the folder; [`Self::finish`] lists it in the marker once written.
    pub fn create(&self, name: &str) -> Result<DataFile, CliError> {
        let p = self.tmp.join(name);
        let file = std::fs::File::create(&p).map_err(|e| io("write", &p, e))?;
        let counted = Counted {
            file,
            size: 0,
            hash: WordHash::new(),
        };
        Ok(DataFile {
            out: std::io::BufWriter::with_capacity(1 << 16, counted),
            name: name.to_string(),
        })
    }

    /// The error of writing the data file `name`, with the OS's reason.
    pub fn error(&self, name: &str, e: std::io::Error) -> CliError {
        io("write", &self.tmp.join(name), e)
    }

    /// Flushes a data file and lists it, with its size and hash, in the marker.
    pub fn finish(&self, f: DataFile) -> Result<(), CliError> {
        let c = f
            .out
            .into_inner()
            .map_err(|e| self.error(&f.name, e.into_error()))?;
        let entry = (f.name, c.size, c.hash.finish());
        self.listed
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .push(entry);
        Ok(())
    }

    /// Writes the marker and puts the folder in place of the target, replacing an earlier run's folder; then
    /// makes the rename durable.
    pub fn commit(mut self) -> Result<(), CliError> {
        let mut marker = format!("{MARKER_V2}\n");
        let mut listed = std::mem::take(
            self.listed
                .get_mut()
                .unwrap_or_else(std::sync::PoisonError::into_inner),
        );
        // Files written on several threads are listed in an order that does not depend on their timing.
        listed.sort();
        for (name, size, hash) in &listed {
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
        // The rename lives in the parent folder's entries: syncing it makes the new set the one a crash keeps.
        let parent = self.tmp.parent().unwrap_or(Path::new("."));
        std::fs::File::open(parent)
            .and_then(|d| d.sync_all())
            .map_err(|e| io("sync", parent, e))
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
    let mut lines = marker.lines();
    let hash: fn(&[u8]) -> u64 = match lines.next() {
        Some(MARKER_V2) => WordHash::of,
        Some(MARKER_V1) => fnv1a,
        first => return Err(format!("{MARKER}: unknown first line {first:?}")),
    };
    for line in lines {
        let mut parts = line.split(' ');
        let (Some(name), Some(size), Some(hash_text)) = (parts.next(), parts.next(), parts.next())
        else {
            return Err(format!("{MARKER}: malformed line {line:?}"));
        };
        let bytes = std::fs::read(dir.join(name))
            .map_err(|e| format!("{name}, listed in {MARKER}, cannot be read: {e}"))?;
        if bytes.len().to_string() != size || format!("{:016x}", hash(&bytes)) != hash_text {
            return Err(format!(
                "{name} is not the file this run wrote (its size or content changed): the folder mixes files of different runs"
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_word_hash_is_the_same_in_any_pieces_and_sees_every_byte() {
        let bytes: Vec<u8> = (0..203u32).map(|i| (i * 37 % 251) as u8).collect();
        let whole = WordHash::of(&bytes);
        for cut in 0..bytes.len() {
            for cut2 in cut..bytes.len().min(cut + 11) {
                let mut h = WordHash::new();
                h.update(&bytes[..cut]);
                h.update(&bytes[cut..cut2]);
                h.update(&bytes[cut2..]);
                assert_eq!(h.finish(), whole, "pieces cut at {cut} and {cut2}");
            }
        }
        for i in 0..bytes.len() {
            let mut changed = bytes.clone();
            changed[i] ^= 1;
            assert_ne!(WordHash::of(&changed), whole, "byte {i}");
        }
    }

    #[test]
    fn folders_with_a_version_1_marker_still_verify() {
        // Published FNV-1a 64 test vectors.
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a(b"foobar"), 0x8594_4171_f739_67e8);
        let dir = std::env::temp_dir().join(format!("pounding-marker-v1-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("summary.json"), b"foobar").unwrap();
        std::fs::write(
            dir.join(MARKER),
            "pounding run output\nsummary.json 6 85944171f73967e8\n",
        )
        .unwrap();
        assert_eq!(verify(&dir), Ok(()));
        std::fs::write(dir.join("summary.json"), b"foobaz").unwrap();
        assert!(verify(&dir)
            .unwrap_err()
            .contains("summary.json is not the file"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
