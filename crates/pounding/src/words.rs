//! Words of one-line messages: "did you mean" for a misspelt name, counts with their nouns, numbers in their
//! shortest form, and messages kept short whatever they echo.

/// `given` without case, spaces, `-` and `_`: `Hunt_Crossley` and `huntcrossley` read alike.
fn squash(s: &str) -> String {
    s.chars()
        .filter(|c| !matches!(c, '-' | '_' | ' '))
        .flat_map(char::to_lowercase)
        .collect()
}

/// Edit distance (insertions, deletions, substitutions; an adjacent swap counts one) between `a` and `b`.
fn distance(a: &[char], b: &[char]) -> usize {
    // Optimal string alignment, three rolling rows.
    let mut prev2 = vec![0; b.len() + 1];
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut row = vec![0; b.len() + 1];
    for i in 1..=a.len() {
        row[0] = i;
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            row[j] = (prev[j] + 1).min(row[j - 1] + 1).min(prev[j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                row[j] = row[j].min(prev2[j - 2] + 1);
            }
        }
        std::mem::swap(&mut prev2, &mut prev);
        std::mem::swap(&mut prev, &mut row);
    }
    prev[b.len()]
}

/// The name of `allowed` that `given` most likely meant: the same name written another way
/// (`huntcrossley`, `Hunt_Crossley`), or the closest within a few edits (a third of its length, at least
/// one, at most three). `None` if nothing is that close.
pub fn closest<'a>(given: &str, allowed: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let g: Vec<char> = squash(given).chars().collect();
    let mut best: Option<(usize, &str)> = None;
    for name in allowed {
        let n: Vec<char> = squash(name).chars().collect();
        let d = distance(&g, &n);
        let limit = (n.len() / 3).clamp(1, 3);
        if d <= limit && best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, name));
        }
    }
    best.map(|(_, name)| name)
}

/// ` (did you mean "x"?)` for the closest allowed name, or nothing.
pub fn did_you_mean<'a>(given: &str, allowed: impl IntoIterator<Item = &'a str>) -> String {
    closest(given, allowed).map_or(String::new(), |n| format!(" (did you mean {n:?}?)"))
}

/// `s` quoted as Rust writes strings; over `max` characters (as written, escapes included) cut as
/// [`compact`] cuts a quoted name, with an ellipsis inside the quotes and its length:
/// `"LLLL..." (5000 characters)`. A name echoed in a message stays short whatever was given.
pub fn quoted(s: &str, max: usize) -> String {
    let whole = format!("{s:?}");
    if whole.chars().count() <= max + 2 {
        return whole;
    }
    let mut head = String::new();
    let mut len = 0;
    for c in s.chars() {
        let e: String = c.escape_debug().collect();
        len += e.chars().count();
        if len > max.saturating_sub(8) {
            break;
        }
        head.push_str(&e);
    }
    format!("\"{head}...\" ({} characters)", s.chars().count())
}

/// `names` joined with `, `, cut after the names that fit in about `max` characters with `, ... (N in all)`:
/// a list of what is allowed that ends its line whole, however many names it has.
pub fn list<S: AsRef<str>>(names: &[S], max: usize) -> String {
    let mut out = String::new();
    for (k, n) in names.iter().enumerate() {
        let n = n.as_ref();
        if k > 0 && out.len() + 2 + n.len() > max {
            out.push_str(&format!(", ... ({} in all)", names.len()));
            break;
        }
        if k > 0 {
            out.push_str(", ");
        }
        out.push_str(n);
    }
    out
}

/// `x` as a message shows it: the shortest text that reads back to the same value, in plain digits from
/// 1e-5 up to 1e16 (`0.02`, `-1`, `250000`) and in scientific notation outside (`1e300`, `2.5e-9`), `NaN`,
/// `inf`. Rust's `{}` writes 1e300 with 301 digits.
pub fn number(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-5..1e16).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The unit of a contact stiffness of exponent `n`: `N/m` for 1, else `N/m^n` (`N/m^1.5`).
pub fn stiffness_unit(n: f64) -> String {
    if n == 1.0 {
        "N/m".to_string()
    } else {
        format!("N/m^{}", number(n))
    }
}

/// Longest quoted text a message echoes whole, characters.
const QUOTE_MAX: usize = 64;
/// Longest bracketed list a message echoes whole, characters.
const LIST_MAX: usize = 120;
/// Longest run of digits a message echoes whole (a number longer than this was written in full).
const DIGITS_MAX: usize = 24;

/// `msg` with what it echoes kept short, so that any message fits its line: a number written out in full
/// (`1000...0`, 301 digits) in its shortest form (`1e300`), a name quoted (`"..."`) or in backticks (serde's
/// `` `...` ``) over 64 characters cut with an ellipsis and its length, a bracketed list over 120 characters
/// cut after its first entries with an ellipsis and its count. The rest of the message, and what it says is
/// allowed, is kept whole.
pub fn compact(msg: &str) -> String {
    let c: Vec<char> = msg.chars().collect();
    let mut out = String::with_capacity(msg.len().min(1024));
    let mut i = 0;
    while i < c.len() {
        // An unmatched quote or bracket (`expected \"`) is plain text.
        let end = match c[i] {
            '"' => closing_quote(&c, i),
            '[' => closing_bracket(&c, i),
            '`' => c[i + 1..]
                .iter()
                .position(|&b| b == '`')
                .map_or(c.len(), |k| i + 1 + k),
            _ => 0,
        };
        if end >= c.len() {
            out.push(c[i]);
            i += 1;
            continue;
        }
        match c[i] {
            q @ ('"' | '`') => {
                let inner = &c[i + 1..end.min(c.len())];
                if inner.len() > QUOTE_MAX {
                    let head: String = inner[..QUOTE_MAX - 8].iter().collect();
                    out.push_str(&format!("{q}{head}...{q} ({} characters)", inner.len()));
                } else {
                    out.extend(&c[i..(end + 1).min(c.len())]);
                }
                i = end + 1;
            }
            '[' => {
                let list: String = c[i..(end + 1).min(c.len())].iter().collect();
                if list.chars().count() > LIST_MAX {
                    out.push_str(&cut_list(&c[i..(end + 1).min(c.len())]));
                } else {
                    out.push_str(&compact_numbers(&list));
                }
                i = end + 1;
            }
            _ => {
                let start = i;
                while i < c.len() && !matches!(c[i], '"' | '[' | '`') {
                    i += 1;
                }
                let plain: String = c[start..i].iter().collect();
                out.push_str(&compact_numbers(&plain));
            }
        }
    }
    out
}

/// The index of the quote that closes the one at `open` (a backslash escapes), or the end.
fn closing_quote(c: &[char], open: usize) -> usize {
    let mut j = open + 1;
    while j < c.len() {
        match c[j] {
            '\\' => j += 2,
            '"' => return j,
            _ => j += 1,
        }
    }
    c.len()
}

/// The index of the bracket that closes the one at `open` (brackets inside quotes do not count), or the
/// end.
fn closing_bracket(c: &[char], open: usize) -> usize {
    let (mut depth, mut j) = (0usize, open);
    while j < c.len() {
        match c[j] {
            '"' => j = closing_quote(c, j),
            '[' => depth += 1,
            ']' => {
                depth -= 1;
                if depth == 0 {
                    return j;
                }
            }
            _ => {}
        }
        j += 1;
    }
    c.len()
}

/// A long list cut after the entries that fit, with an ellipsis and the count of its top-level entries.
fn cut_list(list: &[char]) -> String {
    let (mut depth, mut entries, mut cut) = (0usize, 1usize, None);
    let mut j = 0;
    while j < list.len() {
        match list[j] {
            '"' => j = closing_quote(list, j),
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            ',' if depth == 1 => {
                entries += 1;
                if j < LIST_MAX - 40 {
                    cut = Some(j);
                }
            }
            _ => {}
        }
        j += 1;
    }
    let head: String = list[..cut.unwrap_or(1).min(LIST_MAX - 40)].iter().collect();
    let head = compact(&head);
    format!("{head}, ...] ({entries} entries)")
}

/// Every run of more than 24 digits (a number written out in full) in its shortest form.
fn compact_numbers(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < c.len() {
        if !c[i].is_ascii_digit() {
            out.push(c[i]);
            i += 1;
            continue;
        }
        let start = i;
        while i < c.len() && (c[i].is_ascii_digit() || c[i] == '.') {
            i += 1;
        }
        let digits: String = c[start..i].iter().collect();
        match digits.parse::<f64>() {
            Ok(x) if digits.len() > DIGITS_MAX && x.is_finite() => out.push_str(&number(x)),
            _ => out.push_str(&digits),
        }
    }
    out
}

/// `n` and its noun, singular for one: `1 storey`, `3 storeys`, `0 impacts`. `plural` is the noun's plural
/// when it is not `singular` + `s`.
pub fn count(n: usize, singular: &str, plural: Option<&str>) -> String {
    match (n, plural) {
        (1, _) => format!("1 {singular}"),
        (_, Some(p)) => format!("{n} {p}"),
        (_, None) => format!("{n} {singular}s"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_shown_in_their_shortest_form() {
        assert_eq!(number(1e300), "1e300");
        assert_eq!(number(0.02), "0.02");
        assert_eq!(number(-1.0), "-1");
        assert_eq!(number(2.5e-9), "2.5e-9");
        assert_eq!(number(f64::NAN), "NaN");
        // Each reads back to the same value.
        for x in [1e300, 0.1 + 0.2, 123456.789, 7.3e-12, 1e16] {
            assert_eq!(number(x).parse::<f64>().unwrap(), x);
        }
    }

    #[test]
    fn a_message_keeps_what_it_says_and_shortens_what_it_echoes() {
        let full = format!("scale = {} is not allowed: 0 < scale <= 1e6", 1e300);
        assert_eq!(
            compact(&full),
            "scale = 1e300 is not allowed: 0 < scale <= 1e6"
        );
        let name = "L".repeat(5000);
        let long = compact(&format!(
            "building {name:?}: name too long; allowed: 1 to 64 bytes"
        ));
        assert_eq!(
            long,
            format!(
                "building \"{}...\" (5000 characters): name too long; allowed: 1 to 64 bytes",
                "L".repeat(56)
            )
        );
        let list: Vec<String> = (0..3000).map(|i| format!("n{i}")).collect();
        let msg = compact(&format!("between = {list:?} is not allowed: two names"));
        assert!(
            msg.len() < 160 && msg.ends_with(", ...] (3000 entries) is not allowed: two names"),
            "{msg}"
        );
        assert!(msg.starts_with("between = [\"n0\", \"n1\", "), "{msg}");
        // Names in backticks (serde's unknown fields) are cut the same way.
        let key = "k".repeat(5000);
        assert_eq!(
            compact(&format!("unknown field `{key}`, expected `a` or `b`")),
            format!(
                "unknown field `{}...` (5000 characters), expected `a` or `b`",
                "k".repeat(56)
            )
        );
        // An unmatched quote or bracket is text: nothing after it is lost.
        let open = format!("expected `\"` or `[` at {}", "x".repeat(200));
        assert_eq!(compact(&open), open);
        // Short names, lists and numbers pass unchanged.
        let plain = "contact.0.gap = -0.01 is not allowed: gap >= 0 (m); [\"A\", \"B\"] \"x\"";
        assert_eq!(compact(plain), plain);
    }

    #[test]
    fn long_names_are_quoted_as_compact_cuts_them_and_lists_end_with_their_count() {
        assert_eq!(quoted("papi", 64), "\"papi\"");
        let q = quoted(&"m".repeat(500), 64);
        assert_eq!(q, format!("\"{}...\" (500 characters)", "m".repeat(56)));
        // compact leaves it as it is: one cut, one length.
        assert_eq!(compact(&q), q);
        // Escapes count as written, and are never split.
        let q = quoted(&"\u{1b}".repeat(100), 64);
        assert!(
            q.starts_with("\"\\u{1b}") && q.ends_with("...\" (100 characters)"),
            "{q}"
        );
        assert_eq!(compact(&q), q);
        let names: Vec<String> = (0..40).map(|i| format!("`name{i}`")).collect();
        let l = list(&names, 100);
        assert!(l.len() < 120 && l.ends_with(", ... (40 in all)"), "{l}");
        assert!(l.starts_with("`name0`, `name1`, "), "{l}");
        assert_eq!(list(&["a", "b"], 100), "a, b");
    }

    const MODELS: [&str; 5] = [
        "hunt-crossley",
        "hertz",
        "hertzdamp",
        "lankarani-nikravesh",
        "kelvin-voigt",
    ];

    #[test]
    fn names_written_another_way_are_found() {
        assert_eq!(closest("huntcrossley", MODELS), Some("hunt-crossley"));
        assert_eq!(closest("Hunt_Crossley", MODELS), Some("hunt-crossley"));
        assert_eq!(closest("KelvinVoigt", MODELS), Some("kelvin-voigt"));
    }

    #[test]
    fn small_slips_are_found_and_far_words_are_not() {
        assert_eq!(
            closest("lankarani-nikravseh", MODELS),
            Some("lankarani-nikravesh")
        );
        assert_eq!(closest("hertzdmp", MODELS), Some("hertzdamp"));
        // Exact wins over a near neighbour.
        assert_eq!(closest("hertz", MODELS), Some("hertz"));
        assert_eq!(closest("steel", MODELS), None);
        assert_eq!(closest("", MODELS), None);
        assert_eq!(
            did_you_mean("scael", ["scale", "units"]),
            " (did you mean \"scale\"?)"
        );
        assert_eq!(did_you_mean("xyz", ["scale", "units"]), "");
    }

    #[test]
    fn counts_agree_with_their_nouns() {
        assert_eq!(count(1, "storey", None), "1 storey");
        assert_eq!(count(2, "storey", None), "2 storeys");
        assert_eq!(count(0, "impact", None), "0 impacts");
        assert_eq!(count(3, "body", Some("bodies")), "3 bodies");
    }

    #[test]
    fn distance_counts_edits() {
        let d = |a: &str, b: &str| {
            distance(
                &a.chars().collect::<Vec<_>>(),
                &b.chars().collect::<Vec<_>>(),
            )
        };
        assert_eq!(d("kitten", "sitting"), 3);
        assert_eq!(d("ab", "ba"), 1);
        assert_eq!(d("", "abc"), 3);
        assert_eq!(d("abc", "abc"), 0);
    }
}
