//! Parsers of ground-motion text formats. They return values in the file's units; [`super::Record`]
//! converts. Errors carry the 1-based line number.

use super::ParseError;

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
    let (hline, header) = lines
        .iter()
        .enumerate()
        .take(40)
        .find(|(_, l)| {
            let u = l.to_ascii_uppercase();
            u.contains("NPTS") && u.contains("DT")
        })
        .ok_or_else(|| err(1, "no header line with NPTS and DT in the first 40 lines"))?;
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
