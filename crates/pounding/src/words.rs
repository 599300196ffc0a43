//! Words of one-line messages: "did you mean" for a misspelt name, and counts with their nouns.

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

/// `s` quoted as Rust writes strings, cut after `max` characters with an ellipsis: a name echoed in a
/// message stays short whatever was given.
pub fn quoted(s: &str, max: usize) -> String {
    match s.char_indices().nth(max) {
        Some((i, _)) => format!("{:?}...", &s[..i]),
        None => format!("{s:?}"),
    }
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
