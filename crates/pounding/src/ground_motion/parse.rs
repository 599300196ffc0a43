//! Parsers of ground-motion text formats. They return values in the file's units; [`super::Record`]
//! converts. Errors carry the 1-based line number. [`looks_like_at2`] and [`at2_units`] read what an AT2
//! header says about the text: its layout and its units; [`text_units`] what the header of a two-column or
//! values text says about its units.

use super::{Format, ParseError, Units};

fn err(line: usize, message: impl Into<String>) -> ParseError {
    ParseError {
        line,
        message: message.into(),
    }
}

/// A token that looks like a number written with a decimal comma (`0,0063`).
fn decimal_comma(tok: &str) -> bool {
    let mut parts = tok.trim_start_matches(['-', '+']).split(',');
    matches!(
        (parts.next(), parts.next(), parts.next()),
        (Some(a), Some(b), None) if !a.is_empty() && !b.is_empty()
            && a.bytes().all(|c| c.is_ascii_digit()) && b.bytes().all(|c| c.is_ascii_digit())
    )
}

fn number(tok: &str, line: usize) -> Result<f64, ParseError> {
    match tok.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(err(line, format!("'{tok}' is not a finite number"))),
        Err(_) if decimal_comma(tok) => Err(err(
            line,
            format!(
                "'{tok}' uses a decimal comma; write '{}'",
                tok.replace(',', ".")
            ),
        )),
        Err(_) => Err(err(line, format!("'{tok}' is not a number"))),
    }
}

/// A PEER AT2 file: returns `(dt_s, values)`. The header line holding NPTS and DT is found by searching for
/// both words (any case, either order, values before or after the labels); values are read until the first
/// non-numeric token (a footer such as `*** End Data ***`) and their count must equal NPTS.
pub fn at2(text: &str) -> Result<(f64, Vec<f64>), ParseError> {
    let lines: Vec<&str> = text.lines().collect();
    let hline = header_line(&lines)
        .ok_or_else(|| err(1, "no header line with NPTS and DT in the first 40 lines"))?;
    let header = lines[hline];
    let upper = header.to_ascii_uppercase();
    let nums: Vec<f64> = upper
        .split(|c: char| c.is_whitespace() || c == ',' || c == '=')
        .filter_map(|t| t.parse::<f64>().ok())
        .collect();
    if nums.len() < 2 {
        return Err(err(
            hline + 1,
            format!("cannot read NPTS and DT from '{}'", header.trim()),
        ));
    }
    let npts_first = upper.find("NPTS") < upper.find("DT");
    let (npts, dt) = if npts_first {
        (nums[0], nums[1])
    } else {
        (nums[1], nums[0])
    };
    if !(npts >= 1.0 && npts.fract() == 0.0) {
        return Err(err(
            hline + 1,
            format!("NPTS = {npts} is not a positive whole number"),
        ));
    }
    if !(dt > 0.0 && dt.is_finite()) {
        return Err(err(
            hline + 1,
            format!("DT = {dt} is not a positive time step (s)"),
        ));
    }
    let npts = npts as usize;
    // Reserve what the file can hold (at least two characters a value), not what its header claims.
    let mut values = Vec::with_capacity(npts.min(text.len() / 2 + 1));
    'lines: for (i, l) in lines.iter().enumerate().skip(hline + 1) {
        for tok in l.split_whitespace() {
            match tok.parse::<f64>() {
                Ok(x) if x.is_finite() => values.push(x),
                _ if decimal_comma(tok) => return Err(number(tok, i + 1).unwrap_err()),
                _ if values.len() < npts => {
                    return Err(err(
                        i + 1,
                        format!("'{tok}' after {} of NPTS = {npts} values", values.len()),
                    ))
                }
                _ => break 'lines,
            }
        }
    }
    if values.len() != npts {
        return Err(err(
            lines.len(),
            format!(
                "the file has {} values but its header says NPTS = {npts}",
                values.len()
            ),
        ));
    }
    Ok((dt, values))
}

/// The 0-based index of an AT2 header's line holding NPTS and DT: the first of the first 40 lines that holds
/// both words (any case).
fn header_line(lines: &[&str]) -> Option<usize> {
    lines.iter().take(40).position(|l| {
        let u = l.to_ascii_uppercase();
        u.contains("NPTS") && u.contains("DT")
    })
}

/// A line of data: at least one token, every token a number.
fn is_data(l: &str) -> bool {
    let mut toks = fields(l).peekable();
    toks.peek().is_some() && toks.all(|t| t.parse::<f64>().is_ok())
}

/// Whether `text` has the layout of a PEER AT2 record: a line holding NPTS and DT (any case; line 4 of a
/// PEER file, `NPTS=  4000, DT= .01000 SEC` or `4000 0.01000 NPTS, DT`) among its first 40 lines, before any
/// line of numbers. Comment lines (`#`, `%`) are not looked at, so a two-column file whose comments mention
/// NPTS and DT is not taken for an AT2.
pub fn looks_like_at2(text: &str) -> bool {
    for l in text.lines().take(40) {
        if is_comment(l) {
            continue;
        }
        if is_data(l) {
            return false;
        }
        let u = l.to_ascii_uppercase();
        if u.contains("NPTS") && u.contains("DT") {
            return true;
        }
    }
    false
}

/// The units an AT2 header states: `ACCELERATION TIME SERIES IN UNITS OF G` (PEER NGA), `... UNITS OF
/// CM/S/S`.
#[derive(Clone, Debug, PartialEq)]
pub struct StatedUnits {
    /// 1-based line of the statement.
    pub line: usize,
    /// The word after `UNITS OF`, as written (without trailing punctuation).
    pub stated: String,
    /// What it means; `None` for a word that is not a unit of acceleration known here.
    pub units: Option<Units>,
}

/// The unit of acceleration an AT2 header's word names: `G`; `CM/S/S`, `CM/S2`, `CM/SEC^2`, `GAL`; `M/S/S`,
/// `M/S2`; `MM/S/S`, `MM/S2` (any case, `SEC` for `S`, `**2` or `^2` for `2`).
fn header_units(word: &str) -> Option<Units> {
    let w = word
        .to_ascii_uppercase()
        .replace("SEC", "S")
        .replace("**", "^")
        .replace("^2", "2")
        .replace("/S/S", "/S2");
    match w.as_str() {
        "G" => Some(Units::G),
        "M/S2" => Some(Units::MPerS2),
        "CM/S2" | "GAL" | "GALS" => Some(Units::CmPerS2),
        "MM/S2" => Some(Units::MmPerS2),
        _ => None,
    }
}

/// What the header of the AT2 `text` says about its units (the lines before the one holding NPTS and DT):
/// `None` if it says nothing (no `UNITS OF`), else the first statement. An error if the header says the
/// record is a velocity or displacement time series (PEER's `.VT2` and `.DT2` files), not accelerations.
pub fn at2_units(text: &str) -> Result<Option<StatedUnits>, ParseError> {
    let lines: Vec<&str> = text.lines().collect();
    let end = header_line(&lines).unwrap_or(0);
    for (i, l) in lines[..end].iter().enumerate() {
        let u = l.to_ascii_uppercase();
        for kind in ["VELOCITY", "DISPLACEMENT"] {
            if u.contains(kind) && u.contains("TIME") && !u.contains("ACCELERATION") {
                return Err(err(
                    i + 1,
                    format!(
                        "the header says this is a {} time series ('{}'): give an acceleration record (PEER's *.AT2)",
                        kind.to_ascii_lowercase(),
                        l.trim()
                    ),
                ));
            }
        }
        if let Some(at) = u.find("UNITS OF") {
            let word: String = l[at + "UNITS OF".len()..]
                .split_whitespace()
                .next()
                .unwrap_or("")
                .trim_end_matches(['.', ',', ';', ':', ')'])
                .to_string();
            return Ok(Some(StatedUnits {
                line: i + 1,
                units: header_units(&word),
                stated: word,
            }));
        }
    }
    Ok(None)
}

/// The units a column name states: a suffix `_g`, `_m_per_s2`, `_cm_per_s2`, `_mm_per_s2`, `_gal` (the tool's
/// own `acceleration_m_per_s2`), or a unit in brackets, `acc(g)`, `acceleration [m/s2]`, `a (cm/s^2)` (any
/// case). `None` for a name that states no unit of acceleration.
fn column_units(name: &str) -> Option<Units> {
    let n = name.trim().to_ascii_lowercase();
    if let Some(open) = n.find(['(', '[']) {
        let inner = n[open + 1..].trim_end_matches([')', ']']).trim();
        return header_units(inner);
    }
    [
        ("_m_per_s2", Units::MPerS2),
        ("_cm_per_s2", Units::CmPerS2),
        ("_mm_per_s2", Units::MmPerS2),
        ("_m_per_s^2", Units::MPerS2),
        ("_cm_per_s^2", Units::CmPerS2),
        ("_mm_per_s^2", Units::MmPerS2),
        ("_gal", Units::CmPerS2),
        ("_g", Units::G),
    ]
    .into_iter()
    .find(|(suffix, _)| n.ends_with(suffix))
    .map(|(_, u)| u)
}

/// A statement `units = "m/s2"` (or `units: g`) in a comment line, as the tool writes in the records it makes
/// (`# read with units = "m/s2"`): the word after it, without quotes.
fn comment_units(line: &str) -> Option<String> {
    let lower = line.to_ascii_lowercase();
    let at = lower.find("units")?;
    let rest = line[at + "units".len()..].trim_start();
    let rest = rest.strip_prefix(['=', ':'])?.trim_start();
    let word: String = rest
        .trim_start_matches(['"', '\''])
        .chars()
        .take_while(|c| !matches!(c, '"' | '\'' | ',' | ';' | ')') && !c.is_whitespace())
        .collect();
    (!word.is_empty()).then_some(word)
}

/// What a two-column or values text says about its units before its data: a comment stating
/// `units = "..."` (`comment_units`) and the name of the acceleration column of a header line
/// (`column_units`: the last name of the line). `None` if it says nothing; an error if two statements
/// disagree. A stated word that is not a unit known here has `units: None`.
pub fn text_units(text: &str) -> Result<Option<StatedUnits>, ParseError> {
    let mut found: Option<StatedUnits> = None;
    for (i, l) in text.lines().enumerate() {
        let t = l.trim();
        let statement = if t.starts_with('#') || t.starts_with('%') {
            comment_units(t).map(|w| StatedUnits {
                line: i + 1,
                units: Units::parse(&w).ok(),
                stated: w,
            })
        } else if t.is_empty() {
            None
        } else if fields(t).any(|tok| tok.parse::<f64>().is_ok()) {
            // The data begin: nothing after them is a header.
            break;
        } else {
            let last = fields(t).last().unwrap_or("");
            column_units(last).map(|u| StatedUnits {
                line: i + 1,
                stated: last.to_string(),
                units: Some(u),
            })
        };
        match (&found, statement) {
            (None, Some(s)) => found = Some(s),
            (Some(f), Some(s)) if f.units != s.units => {
                return Err(err(
                    s.line,
                    format!(
                    "the text states its units twice, differently: {:?} on line {} and {:?} here",
                    f.stated, f.line, s.stated
                ),
                ))
            }
            _ => {}
        }
    }
    Ok(found)
}

/// Splits a data line on whitespace, commas, semicolons or tabs.
fn fields(l: &str) -> impl Iterator<Item = &str> {
    l.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|t| !t.is_empty())
}

fn is_comment(l: &str) -> bool {
    let t = l.trim();
    t.is_empty() || t.starts_with('#') || t.starts_with('%')
}

/// Two-column time / acceleration text or CSV: returns `(t0_s, dt_s, values)`. Non-numeric lines before the
/// data are a header; after it, only comments (`#`, `%`) and blank lines may appear. Time steps must be
/// uniform to 1e-6 of dt.
pub fn time_acc(text: &str) -> Result<(f64, f64, Vec<f64>), ParseError> {
    let mut t = Vec::new();
    let mut a = Vec::new();
    let mut line_of = Vec::new();
    for (i, l) in text.lines().enumerate() {
        if is_comment(l) {
            continue;
        }
        // A semicolon-separated line with decimal commas: "0,02;0,0063".
        if l.contains(';') && l.split(';').any(|f| decimal_comma(f.trim())) {
            return Err(err(i + 1, "decimal commas; use '.' for decimals"));
        }
        let toks: Vec<&str> = fields(l).collect();
        let parsed: Result<Vec<f64>, _> = toks.iter().map(|s| number(s, i + 1)).collect();
        match parsed {
            Ok(v) if v.len() == 2 => {
                t.push(v[0]);
                a.push(v[1]);
                line_of.push(i + 1);
            }
            Ok(v) => {
                return Err(err(
                    i + 1,
                    format!(
                        "expected 2 columns (time s, acceleration), found {}",
                        v.len()
                    ),
                ))
            }
            // A line with no number at all, before the data, is a header.
            Err(_) if t.is_empty() && toks.iter().all(|s| s.parse::<f64>().is_err()) => {}
            Err(e) => return Err(e),
        }
    }
    if t.len() < 2 {
        return Err(err(text.lines().count().max(1), "fewer than 2 data rows"));
    }
    let dt = t[1] - t[0];
    if dt.is_nan() || dt <= 0.0 {
        return Err(err(
            line_of[1],
            format!("the time step {dt} s is not positive"),
        ));
    }
    // Times are printed with few digits: allow 0.1 % of dt, far below any real unevenness.
    for (k, tk) in t.iter().enumerate() {
        let expect = t[0] + k as f64 * dt;
        if (tk - expect).abs() > 1e-3 * dt {
            return Err(err(
                line_of[k],
                format!("uneven time step: t = {tk} s where {expect} s was expected (dt = {dt} s)"),
            ));
        }
    }
    Ok((t[0], dt, a))
}

/// Values separated by whitespace, any number per line (usually one); comments and blank lines skipped.
pub fn values(text: &str) -> Result<Vec<f64>, ParseError> {
    let mut out = Vec::new();
    for (i, l) in text.lines().enumerate() {
        if is_comment(l) {
            continue;
        }
        for tok in l.split_whitespace() {
            out.push(number(tok, i + 1)?);
        }
    }
    if out.is_empty() {
        return Err(err(1, "no values"));
    }
    Ok(out)
}

impl Format {
    /// The format of a record's `text` when none is given: [`Format::At2`] if the text has the layout of a
    /// PEER AT2 record ([`looks_like_at2`]: a header line holding NPTS and DT, line 4 of a PEER file,
    /// before any line of numbers), whatever the file is called; else `At2` if `file_name` ends in `.at2`
    /// (any case), so that a damaged AT2 file gets the AT2 reader's message; else [`Format::TimeAcc`].
    /// `Values` needs a time step, so it is never detected.
    ///
    /// ```
    /// use pounding::ground_motion::Format;
    /// let at2 = "PEER NGA STRONG MOTION DATABASE RECORD\nTitle\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    3, DT=   .0100 SEC\n.1 .2 .3\n";
    /// assert_eq!(Format::detect(at2, Some("renamed.txt")), Format::At2);
    /// assert_eq!(Format::detect("0.0, 0.1\n0.01, 0.2\n", Some("record.csv")), Format::TimeAcc);
    /// ```
    pub fn detect(text: &str, file_name: Option<&str>) -> Format {
        let at2_name = file_name.is_some_and(|n| {
            n.len() >= 4
                && n.is_char_boundary(n.len() - 4)
                && n[n.len() - 4..].eq_ignore_ascii_case(".at2")
        });
        if at2_name || looks_like_at2(text) {
            Format::At2
        } else {
            Format::TimeAcc
        }
    }
}
