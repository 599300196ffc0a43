//! A command's files: figures rendered (SVG, PNG with the `png` feature), files written into `--out` each
//! atomically, and the checks that come before any work.

use crate::args::{FigureArgs, OutArgs};
use crate::error::{input, CliError};
use crate::plot::Figure;
use pounding_study::input::write_atomic;
use std::path::Path;

/// Renders `figures` as files: SVG, and PNG too if `png` (in a build with the `png` feature).
pub fn render_figures(figures: &[Figure], png: bool) -> Result<Vec<(String, Vec<u8>)>, CliError> {
    let mut files = Vec::new();
    for f in figures {
        let svg = crate::plot::svg::render(f);
        if png {
            files.push((format!("{}.png", f.id), png_bytes(&svg, &f.id)?));
        }
        files.push((format!("{}.svg", f.id), svg.into_bytes()));
    }
    Ok(files)
}

#[cfg(feature = "png")]
fn png_bytes(svg: &str, id: &str) -> Result<Vec<u8>, CliError> {
    crate::plot::png::render(svg).map_err(|e| CliError::Io(format!("figure {id}: {e}")))
}

#[cfg(not(feature = "png"))]
fn png_bytes(_: &str, _: &str) -> Result<Vec<u8>, CliError> {
    Err(CliError::Input(NO_PNG.into()))
}

/// The message for `--png` in a build without the `png` feature.
pub const NO_PNG: &str = "--png needs PNG support, which this build leaves out: build with `--features png` \
                          (cargo run --release --features png -- ...); the SVG figures need nothing";

/// Writes `files` (name, bytes) into `dir`, created if missing, each atomically, in name order. Returns the
/// names written.
pub fn write_files(dir: &Path, mut files: Vec<(String, Vec<u8>)>) -> Result<Vec<String>, CliError> {
    use CliError;
    if dir.is_file() {
        return Err(CliError::Input(format!(
            "--out {} is a file; give a folder (it is created if missing)",
            dir.display()
        )));
    }
    files.sort_by(|a, b| a.0.cmp(&b.0));
    std::fs::create_dir_all(dir)
        .map_err(|e| CliError::Io(format!("cannot create {}: {e}", dir.display())))?;
    for (name, bytes) in &files {
        let p = dir.join(name);
        write_atomic(&p, bytes)
            .map_err(|e| CliError::Io(format!("cannot write {}: {e}", p.display())))?;
    }
    Ok(files.into_iter().map(|f| f.0).collect())
}

/// The time history of one impact as CSV with units in the header.
pub fn history_csv(h: &pounding::impact::History) -> String {
    let mut s = String::from("t_s,penetration_m,rate_m_per_s,force_N\n");
    for i in 0..h.t.len() {
        // Shortest round-trip scientific notation: exact, and compact for tiny times near touch.
        s.push_str(&format!(
            "{:e},{:e},{:e},{:e}\n",
            h.t[i], h.penetration[i], h.rate[i], h.force[i]
        ));
    }
    s
}

/// Fails early (before any work or output) if the folder `--out` cannot be made (see [`check_out_dir`]) or
/// `--png` cannot be honoured.
pub fn check_out(o: &OutArgs) -> Result<(), CliError> {
    if let Some(dir) = &o.out {
        check_out_dir(dir, false)?;
    }
    check_figures(&o.figures)
}

/// Fails early, before any work, if `dir`, the folder given as `--out`, could not be made or written: a
/// file there is bad input (exit 2); a file where a folder of its path should be, or a folder that cannot
/// be written, is an I/O failure naming `dir` with the OS's reason (exit 1). Nothing is left behind: the
/// nearest folder of the path that exists is tried with a folder made and removed at once. `beside`: the
/// output is made beside `dir` and renamed into place (a run's), so `dir`'s parent must be writable even
/// when `dir` exists.
pub fn check_out_dir(dir: &Path, beside: bool) -> Result<(), CliError> {
    use std::io::ErrorKind;
    let cannot =
        |e: std::io::Error| CliError::Io(format!("cannot create --out {}: {e}", dir.display()));
    let parent = |p: &Path| match p.parent() {
        Some(q) if !q.as_os_str().is_empty() => q.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    // The folder in which the first new folder (or file) is made.
    let mut at = match std::fs::metadata(dir) {
        Ok(m) if !m.is_dir() => {
            return Err(input(format!(
                "--out {} is a file; give a folder (it is created if missing)",
                dir.display()
            )))
        }
        Ok(_) if !beside => dir.to_path_buf(),
        Ok(_) => parent(dir),
        Err(e) if e.kind() == ErrorKind::NotFound => parent(dir),
        // A file where a folder of the path should be (`/dev/null/x`: not a directory), no permission, ...
        Err(e) => return Err(cannot(e)),
    };
    loop {
        match std::fs::metadata(&at) {
            Ok(m) if m.is_dir() => break,
            Ok(_) => return Err(cannot(ErrorKind::NotADirectory.into())),
            Err(e) if e.kind() == ErrorKind::NotFound && parent(&at) != at => at = parent(&at),
            Err(e) => return Err(cannot(e)),
        }
    }
    let nonce = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    let probe = at.join(format!(".pounding-probe-{}-{nonce}", std::process::id()));
    match std::fs::create_dir(&probe) {
        Ok(()) => {
            let _ = std::fs::remove_dir(&probe);
            Ok(())
        }
        Err(e) if e.kind() == ErrorKind::AlreadyExists => Ok(()),
        Err(e) => Err(cannot(e)),
    }
}

/// Fails early if `--png` is asked of a build without PNG support.
pub fn check_figures(f: &FigureArgs) -> Result<(), CliError> {
    if f.png && !cfg!(feature = "png") {
        return Err(input(NO_PNG));
    }
    Ok(())
}

/// Writes a command's files into `--out`, if given: `name.json` holding `json`, the `extra` files, and the
/// figures with --plots, each file atomically, all rendered before the first is written. Prints the folder
/// and the files unless `quiet`.
pub fn save_out(
    o: &OutArgs,
    (name, json): (&str, &impl serde::Serialize),
    extra: Vec<(String, Vec<u8>)>,
    figs: &[Figure],
    quiet: bool,
) -> Result<(), CliError> {
    let Some(dir) = &o.out else {
        return Ok(());
    };
    let mut files = vec![(
        format!("{name}.json"),
        (serde_json::to_string_pretty(json).expect("JSON") + "\n").into_bytes(),
    )];
    files.extend(extra);
    if o.figures.plots {
        files.extend(render_figures(figs, o.figures.png)?);
    }
    let names = write_files(dir, files)?;
    if !quiet {
        println!("\nwrote {}: {}", dir.display(), names.join(", "));
    }
    Ok(())
}
