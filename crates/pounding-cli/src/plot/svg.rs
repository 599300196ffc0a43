//! SVG rendering of a [`Figure`]. Coordinates are written to 0.01 px; long lines are thinned to the first,
//! lowest, highest and last point of each pixel column, which keeps every peak exactly.

use super::axis::Axis;
use super::font::{bold_text_width, text_width};
use super::{Dash, Figure, Legend, Mark, Panel, Series, Shape, Style};
use std::fmt::Write as _;

/// Font sizes, px.
const TITLE: f64 = 16.0;
const SUBTITLE: f64 = 12.0;
const PANEL_TITLE: f64 = 13.0;
const LABEL: f64 = 12.0;
const TICK: f64 = 11.0;
const LEGEND: f64 = 11.0;
const NOTE: f64 = 11.5;
/// Space kept clear at each side of the title and of the subtitle, px.
const TITLE_MARGIN: f64 = 10.0;
const SUBTITLE_MARGIN: f64 = 20.0;
/// Height of one legend entry, px.
const ENTRY: f64 = 16.0;
/// The font stack: DejaVu Sans (whose metrics the layout uses, and which PNGs embed), then look-alikes.
pub const FONT_FAMILY: &str = "DejaVu Sans, Verdana, Arial, Helvetica, sans-serif";

/// The figure as a standalone SVG document.
pub fn render(fig: &Figure) -> String {
    let columns = fig.columns.max(1);
    let size = Size {
        w: fig.plot.0,
        h: fig.plot.1,
    };
    let axes: Vec<(Axis, Axis)> = fig.panels.iter().map(axes_of).collect();
    // Lines that coincide, judged in pixels (where the panel is drawn does not matter).
    let sames: Vec<Vec<Option<Same>>> = fig
        .panels
        .iter()
        .zip(&axes)
        .map(|(p, (xa, ya))| coincident(p, &Map::new(xa, ya, (0.0, 0.0), size)))
        .collect();
    let places: Vec<Place> = fig
        .panels
        .iter()
        .zip(&axes)
        .zip(&sames)
        .map(|((p, (xa, ya)), same)| place_legend(p, xa, ya, size, same))
        .collect();
    // One left margin and one legend width for all panels, so that plots line up.
    let tick_w = axes
        .iter()
        .flat_map(|(_, y)| {
            y.ticks
                .iter()
                .map(move |t| text_width(&y.tick_label(*t), TICK))
        })
        .fold(0.0, f64::max);
    // Whole pixels for every edge: crisp frames, and the pixel box in data-* attributes is exact.
    let left = (10.0 + LABEL + 10.0 + tick_w + 8.0).ceil();
    let legend_w = fig
        .panels
        .iter()
        .zip(places.iter().zip(&sames))
        .filter(|(_, (pl, _))| **pl == Place::Right)
        .map(|(p, (_, same))| legend_size(p, same).0 + 16.0)
        .fold(0.0, f64::max)
        .ceil();
    let right = 18.0 + legend_w;
    let top = 28.0;
    let bottom = 8.0 + TICK + 10.0 + LABEL + 12.0;
    let cell_w = left + size.w + right;
    let width = cell_w * columns as f64;
    let cells = grid(&fig.panels, columns);
    let rows = cells.last().map_or(0, |c| c.0 + 1);
    // Small multiples sharing x: the tick labels and the x label under the bottom row only.
    let bottom_of = |row: usize| {
        if fig.share_x && row + 1 < rows {
            6.0
        } else {
            bottom
        }
    };
    // The title wraps (in the bold face it is set in) into as few lines as fit the figure, broken after a
    // comma or colon where it can. A subtitle too long for one line keeps its leading clauses (up to a
    // "; ") and hands the rest to the notes; a first clause still too long wraps the same way.
    let title = balanced(&fig.title, width - 2.0 * TITLE_MARGIN, &|t| {
        bold_text_width(t, TITLE)
    });
    let (sub, rest) = split_subtitle(&fig.subtitle, SUBTITLE, width - 2.0 * SUBTITLE_MARGIN);
    let title_h = (TITLE + 4.0) * title.len().max(1) as f64 - 4.0;
    let sub_top = 14.0 + title_h + 6.0;
    let head = (sub_top + (SUBTITLE + 4.0) * sub.len() as f64 + 6.0).ceil();
    let mut row_top = Vec::with_capacity(rows);
    let mut y = head;
    for row in 0..rows {
        row_top.push(y);
        y += top + size.h + bottom_of(row);
    }
    let notes: Vec<String> = rest
        .iter()
        .chain(&fig.notes)
        .flat_map(|n| wrap(n, NOTE, width - 40.0))
        .collect();
    let notes_top = y;
    let height = (y + if notes.is_empty() {
        0.0
    } else {
        (NOTE + 5.0) * notes.len() as f64 + 10.0
    })
    .ceil();

    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="{FONT_FAMILY}" data-figure="{id}">"#,
        w = px(width),
        h = px(height),
        id = esc(&fig.id)
    );
    let _ = write!(s, "\n<title>{}</title>", esc(&fig.title));
    let _ = write!(
        s,
        "\n<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>",
        px(width),
        px(height)
    );
    for (i, line) in title.iter().enumerate() {
        let _ = write!(
            s,
            "\n<text class=\"title\" x=\"{}\" y=\"{}\" font-size=\"{TITLE}\" font-weight=\"bold\" text-anchor=\"middle\">{}</text>",
            px(width / 2.0),
            px(10.0 + TITLE + (TITLE + 4.0) * i as f64),
            esc(line)
        );
    }
    for (i, line) in sub.iter().enumerate() {
        let _ = write!(
            s,
            "\n<text class=\"subtitle\" x=\"{}\" y=\"{}\" font-size=\"{SUBTITLE}\" fill=\"#444444\" text-anchor=\"middle\">{}</text>",
            px(width / 2.0),
            px(sub_top + SUBTITLE + (SUBTITLE + 4.0) * i as f64),
            esc(line)
        );
    }
    for (k, (panel, (xa, ya))) in fig.panels.iter().zip(&axes).enumerate() {
        let (row, col) = cells[k];
        let x0 = col as f64 * cell_w + left;
        let y0 = row_top[row] + top;
        let clip = format!("{}-clip{k}", fig.id);
        let m = Map::new(xa, ya, (x0, y0), size);
        let below = cells.contains(&(row + 1, col));
        let x_labels = !fig.share_x || !below;
        panel_svg(&mut s, panel, &m, (places[k], &sames[k]), &clip, x_labels);
    }
    for (i, line) in notes.iter().enumerate() {
        let _ = write!(
            s,
            "\n<text class=\"note\" x=\"20.00\" y=\"{}\" font-size=\"{NOTE}\" fill=\"#333333\">{}</text>",
            px(notes_top + 4.0 + NOTE + (NOTE + 5.0) * i as f64),
            esc(line)
        );
    }
    s.push_str("\n</svg>\n");
    s
}

/// The (row, column) of each panel: row by row, `columns` to a row, a panel with `new_row` starting the next.
fn grid(panels: &[Panel], columns: usize) -> Vec<(usize, usize)> {
    let mut cells = Vec::with_capacity(panels.len());
    let (mut row, mut col) = (0, 0);
    for (k, p) in panels.iter().enumerate() {
        if k > 0 && (col == columns || (p.new_row && col > 0)) {
            (row, col) = (row + 1, 0);
        }
        cells.push((row, col));
        col += 1;
    }
    cells
}

/// The axes of a panel: fixed ranges where given, otherwise the data's (y including 0 if asked).
fn axes_of(p: &Panel) -> (Axis, Axis) {
    let (mut xl, mut xh) = p.x_range.or_else(|| p.data_range(0)).unwrap_or((0.0, 1.0));
    if p.x_zero && p.x_range.is_none() {
        (xl, xh) = (xl.min(0.0), xh.max(0.0));
    }
    let (mut yl, mut yh) = p.y_range.or_else(|| p.data_range(1)).unwrap_or((0.0, 1.0));
    if p.y_zero && p.y_range.is_none() {
        (yl, yh) = (yl.min(0.0), yh.max(0.0));
    }
    let tight_y = p.y_range.is_some();
    let y = if p.y_log {
        Axis::log(&p.y, yl, yh)
    } else {
        Axis::new(&p.y, yl, yh, tight_y)
    };
    let x = if p.x_log {
        Axis::log(&p.x, xl, xh)
    } else {
        Axis::new(&p.x, xl, xh, p.x_tight || p.x_range.is_some())
    };
    (x, y)
}

/// A subtitle no wider than `width` px at `size` px: the longest run of its "; "-separated clauses that fits
/// on one line, and the other clauses (for a note); or, if even its first clause is too long, that clause
/// wrapped over as few lines as it needs ([`balanced`]), and the rest.
fn split_subtitle(text: &str, size: f64, width: f64) -> (Vec<String>, Option<String>) {
    if text.is_empty() {
        return (Vec::new(), None);
    }
    if text_width(text, size) <= width {
        return (vec![text.to_string()], None);
    }
    let clauses: Vec<&str> = text.split("; ").collect();
    let mut k = 1;
    while k < clauses.len() && text_width(&clauses[..=k].join("; "), size) <= width {
        k += 1;
    }
    let head = clauses[..k].join("; ");
    let rest = (k < clauses.len()).then(|| clauses[k..].join("; "));
    (balanced(&head, width, &|t| text_width(t, size)), rest)
}

/// `text` on one line no wider than `width` px at `size` px: cut at the end with an ellipsis if too long.
fn one_line(text: &str, size: f64, width: f64) -> String {
    if text_width(text, size) <= width {
        return text.to_string();
    }
    let mut chars: Vec<char> = text.chars().collect();
    while !chars.is_empty() {
        chars.pop();
        let t: String = chars.iter().collect::<String>().trim_end().to_string() + "\u{2026}";
        if text_width(&t, size) <= width {
            return t;
        }
    }
    String::new()
}

/// `text` broken at spaces into lines no wider than `width` px at `size` px.
fn wrap(text: &str, size: f64, width: f64) -> Vec<String> {
    wrap_by(text, width, &|t| text_width(t, size), false)
}

/// `text` broken at spaces into lines no wider than `width` px as `measure` sets them; with `phrases`, a
/// line breaks after a comma, colon or semicolon when the phrase that follows fits on the next line whole.
/// A word wider than a line is broken between characters, so no line is wider than `width`.
fn wrap_by(text: &str, width: f64, measure: &dyn Fn(&str) -> f64, phrases: bool) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for phrase in phrase_split(text, phrases) {
        let joined = lines.last().map(|l| format!("{l} {phrase}"));
        if phrases && joined.is_some_and(|j| measure(&j) > width) && measure(phrase) <= width {
            // The phrase fits a line of its own: start one rather than break it.
            lines.push(String::new());
        }
        for word in phrase.split(' ').filter(|w| !w.is_empty()) {
            match lines.last_mut() {
                Some(line) if line.is_empty() => line.push_str(word),
                Some(line) if measure(&format!("{line} {word}")) <= width => {
                    line.push(' ');
                    line.push_str(word);
                }
                _ => lines.push(word.to_string()),
            }
            break_long_word(&mut lines, width, measure);
        }
    }
    lines.retain(|l| !l.is_empty());
    lines
}

/// The last line, if wider than `width` (one word too long for any line), broken between characters.
fn break_long_word(lines: &mut Vec<String>, width: f64, measure: &dyn Fn(&str) -> f64) {
    while let Some(line) = lines.last_mut() {
        let chars: Vec<char> = line.chars().collect();
        if chars.len() < 2 || measure(line) <= width {
            return;
        }
        let mut k = chars.len() - 1;
        while k > 1 && measure(&chars[..k].iter().collect::<String>()) > width {
            k -= 1;
        }
        let tail: String = chars[k..].iter().collect();
        *line = chars[..k].iter().collect();
        lines.push(tail);
    }
}

/// The phrases of `text`: the pieces ending in ", ", ": " or "; " (the mark kept), or, without `phrases`,
/// the whole text.
fn phrase_split(text: &str, phrases: bool) -> Vec<&str> {
    if !phrases {
        return vec![text];
    }
    let mut out = Vec::new();
    let mut start = 0;
    for (i, c) in text.char_indices() {
        if matches!(c, ',' | ':' | ';') && text[i + 1..].starts_with(' ') {
            out.push(&text[start..=i]);
            start = i + 2;
        }
    }
    out.push(&text[start..]);
    out
}

/// `text` in the fewest lines no wider than `width` px (as `measure` sets them) that phrase-wise wrapping
/// gives, made as even as they can be: the narrowest width that still gives that many lines.
fn balanced(text: &str, width: f64, measure: &dyn Fn(&str) -> f64) -> Vec<String> {
    let lines = wrap_by(text, width, measure, true);
    if lines.len() < 2 {
        return lines;
    }
    let widest_word = text.split(' ').map(measure).fold(0.0, f64::max);
    let (mut lo, mut hi) = (widest_word.min(width), width);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if wrap_by(text, mid, measure, true).len() <= lines.len() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    wrap_by(text, hi, measure, true)
}

/// A pixel coordinate as written: two decimals.
fn px(v: f64) -> String {
    format!("{v:.2}")
}

/// XML text and attribute escaping.
pub fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

fn stroke(st: &Style) -> String {
    let dash = match st.dash {
        Dash::Solid => String::new(),
        Dash::Dashed => format!(" stroke-dasharray=\"{} {}\"", px(6.0), px(3.5)),
        Dash::Dotted => format!(" stroke-dasharray=\"{} {}\"", px(1.5), px(2.5)),
    };
    format!(
        "stroke=\"{}\" stroke-width=\"{}\"{dash}",
        st.color,
        px(st.width)
    )
}

/// Width and height of a plot area (inside the frame), px.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Size {
    w: f64,
    h: f64,
}

/// Maps data to pixels inside one plot area.
struct Map<'a> {
    xa: &'a Axis,
    ya: &'a Axis,
    x0: f64,
    y0: f64,
    size: Size,
}

impl<'a> Map<'a> {
    fn new(xa: &'a Axis, ya: &'a Axis, (x0, y0): (f64, f64), size: Size) -> Self {
        Self {
            xa,
            ya,
            x0,
            y0,
            size,
        }
    }
    fn px(&self, v: f64) -> f64 {
        self.x0 + self.xa.fraction(v) * self.size.w
    }
    fn py(&self, v: f64) -> f64 {
        self.y0 + self.size.h - self.ya.fraction(v) * self.size.h
    }
}

fn panel_svg(
    s: &mut String,
    p: &Panel,
    m: &Map,
    (place, same): (Place, &[Option<Same>]),
    clip: &str,
    x_labels: bool,
) {
    let (xa, ya) = (m.xa, m.ya);
    let (x0, y0) = (m.x0, m.y0);
    let (x1, y1) = (x0 + m.size.w, y0 + m.size.h);
    let _ = write!(
        s,
        "\n<g class=\"panel\" data-title=\"{}\" data-x-scale=\"{}\" data-y-scale=\"{}\" data-x-lo=\"{}\" data-x-hi=\"{}\" data-y-lo=\"{}\" data-y-hi=\"{}\" \
         data-left=\"{}\" data-right=\"{}\" data-top=\"{}\" data-bottom=\"{}\">",
        esc(&p.title),
        if xa.log { "log" } else { "linear" },
        if ya.log { "log" } else { "linear" },
        xa.lo,
        xa.hi,
        ya.lo,
        ya.hi,
        px(x0),
        px(x1),
        px(y0),
        px(y1)
    );
    let _ = write!(
        s,
        "\n<clipPath id=\"{clip}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>",
        px(x0),
        px(y0),
        px(m.size.w),
        px(m.size.h)
    );
    // Grid and ticks.
    let mut grid = String::new();
    let mut labels = String::new();
    for &t in &xa.ticks {
        let x = m.px(t);
        let _ = write!(grid, "M{} {}V{}", px(x), px(y0), px(y1));
        if !x_labels {
            continue;
        }
        let _ = write!(
            labels,
            "\n<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            px(x),
            px(y1 + 6.0 + TICK),
            esc(&xa.tick_label(t))
        );
    }
    for &t in &ya.ticks {
        let y = m.py(t);
        let _ = write!(grid, "M{} {}H{}", px(x0), px(y), px(x1));
        let _ = write!(
            labels,
            "\n<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            px(x0 - 6.0),
            px(y + 0.35 * TICK),
            esc(&ya.tick_label(t))
        );
    }
    let _ = write!(
        s,
        "\n<path class=\"grid\" d=\"{grid}\" stroke=\"#e2e2e2\" stroke-width=\"1\" fill=\"none\"/>"
    );
    let _ = write!(
        s,
        "\n<g class=\"ticks\" font-size=\"{TICK}\" fill=\"#222222\">{labels}\n</g>"
    );
    // Axis labels and title.
    if x_labels {
        let _ = write!(
            s,
            "\n<text class=\"xlabel\" x=\"{}\" y=\"{}\" font-size=\"{LABEL}\" text-anchor=\"middle\">{}</text>",
            px((x0 + x1) / 2.0),
            px(y1 + 6.0 + TICK + 10.0 + LABEL),
            esc(&xa.label)
        );
    }
    let ylx = x0
        - 8.0
        - (ya.ticks.iter())
            .map(|t| text_width(&ya.tick_label(*t), TICK))
            .fold(0.0, f64::max)
        - 10.0;
    let _ = write!(
        s,
        "\n<text class=\"ylabel\" x=\"{}\" y=\"{}\" font-size=\"{LABEL}\" text-anchor=\"middle\" transform=\"rotate(-90 {} {})\">{}</text>",
        px(ylx),
        px((y0 + y1) / 2.0),
        px(ylx),
        px((y0 + y1) / 2.0),
        esc(&ya.label)
    );
    if !p.title.is_empty() {
        let _ = write!(
            s,
            "\n<text class=\"ptitle\" x=\"{}\" y=\"{}\" font-size=\"{PANEL_TITLE}\">{}</text>",
            px(x0),
            px(y0 - 9.0),
            esc(&one_line(&p.title, PANEL_TITLE, m.size.w))
        );
    }
    // Data, clipped to the plot area. Lines that coincide with an earlier one are drawn in dashes that
    // leave gaps, so that each of them shows.
    let _ = write!(s, "\n<g clip-path=\"url(#{clip})\">");
    for (ser, c) in p.series.iter().zip(same) {
        series_svg(s, ser, m, c.map(|c| (c, &p.series[c.root].label)));
    }
    s.push_str("\n</g>");
    // Markers are not clipped: a dot on the largest value, at the frame, stays whole.
    for ser in p.series.iter().filter(|s| s.style.marker) {
        markers_svg(s, ser, m);
    }
    let _ = write!(
        s,
        "\n<rect class=\"frame\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#222222\" stroke-width=\"1\"/>",
        px(x0),
        px(y0),
        px(m.size.w),
        px(m.size.h)
    );
    legend_svg(s, p, place, (x0, y0, x1), same);
    s.push_str("\n</g>");
}

/// The pixel points a series draws (lines thinned as drawn), for placing the legend.
fn pixels(ser: &Series, m: &Map) -> Vec<(f64, f64)> {
    match &ser.mark {
        Mark::Line { x, y } | Mark::Points { x, y } => {
            let pts: Vec<(f64, f64)> = x
                .iter()
                .zip(y)
                .filter(|(a, b)| a.is_finite() && b.is_finite())
                .map(|(a, b)| (m.px(*a), m.py(*b)))
                .collect();
            if matches!(ser.mark, Mark::Line { .. }) {
                thin(&pts, m.size.w).into_iter().map(|i| pts[i]).collect()
            } else {
                pts
            }
        }
        Mark::HLine(v) => (0..=20)
            .map(|i| (m.x0 + m.size.w * f64::from(i) / 20.0, m.py(*v)))
            .collect(),
        Mark::Rug(_) => Vec::new(),
    }
}

/// A line drawn over an earlier one it coincides with: the earlier one (`root`), its place among the copies
/// of that line (1, 2, ...) and the number of lines in the group (the root included).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Same {
    root: usize,
    rank: usize,
    group: usize,
}

/// Length of a dash of coinciding lines, px.
const DASH: f64 = 6.0;

/// For each series of `p`, the earlier labelled line it coincides with, if any: both run over the same x
/// span and no point of either lies farther than 0.5 % of the plot's height from the other (in pixels, so
/// that a log axis is judged as drawn).
fn coincident(p: &Panel, m: &Map) -> Vec<Option<Same>> {
    let n = p.series.len();
    let mut same: Vec<Option<Same>> = vec![None; n];
    let lines: Vec<Option<Vec<(f64, f64)>>> = p
        .series
        .iter()
        .map(|s| match s.mark {
            Mark::Line { .. } if !s.label.is_empty() => Some(pixels(s, m)),
            _ => None,
        })
        .collect();
    let tol = 0.005 * m.size.h;
    for i in 0..n {
        let Some(a) = &lines[i] else { continue };
        for j in 0..i {
            let Some(b) = &lines[j] else { continue };
            if same[j].is_some() || !close(a, b, tol) {
                continue;
            }
            same[i] = Some(Same {
                root: j,
                rank: 0,
                group: 0,
            });
            break;
        }
    }
    // Number the copies of each root.
    for j in 0..n {
        let copies: Vec<usize> = (0..n)
            .filter(|&i| same[i].is_some_and(|c| c.root == j))
            .collect();
        for (r, &i) in copies.iter().enumerate() {
            same[i] = Some(Same {
                root: j,
                rank: r + 1,
                group: copies.len() + 1,
            });
        }
    }
    same
}

/// Whether two drawn lines (pixels) coincide within `tol` px: the same x span, and every point of each
/// within `tol` of the other line.
fn close(a: &[(f64, f64)], b: &[(f64, f64)], tol: f64) -> bool {
    let (Some(a0), Some(a1), Some(b0), Some(b1)) = (a.first(), a.last(), b.first(), b.last())
    else {
        return false;
    };
    let span = |v: &[(f64, f64)]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.0), hi.max(p.0))
            })
    };
    let (sa, sb) = (span(a), span(b));
    if (sa.0 - sb.0).abs() > tol.max(1.0) || (sa.1 - sb.1).abs() > tol.max(1.0) {
        return false;
    }
    let _ = (a0, a1, b0, b1);
    within(a, b, tol) && within(b, a, tol)
}

/// Whether every point of `a` lies within `tol` px of the polyline `b`: by interpolation at the same x when
/// `b` runs left to right, else by the distance to its nearest segment (for loops; long ones are not
/// compared).
fn within(a: &[(f64, f64)], b: &[(f64, f64)], tol: f64) -> bool {
    let monotone = b.windows(2).all(|w| w[1].0 >= w[0].0);
    if monotone {
        return a.iter().all(|&(x, y)| {
            let k = b.partition_point(|p| p.0 < x);
            let mut best = f64::INFINITY;
            // Every point of b at this x (a vertical run) and the segment across it.
            let mut i = k;
            while i < b.len() && b[i].0 <= x {
                best = best.min((b[i].1 - y).abs());
                i += 1;
            }
            if k > 0 && k < b.len() {
                let (p, q) = (b[k - 1], b[k]);
                let f = if q.0 > p.0 {
                    (x - p.0) / (q.0 - p.0)
                } else {
                    0.0
                };
                best = best.min((p.1 + f * (q.1 - p.1) - y).abs());
            }
            best <= tol
        });
    }
    if a.len().saturating_mul(b.len()) > 4_000_000 {
        return false;
    }
    a.iter().all(|&pt| {
        b.windows(2)
            .any(|w| segment_distance(pt, w[0], w[1]) <= tol)
            || (b.len() == 1 && segment_distance(pt, b[0], b[0]) <= tol)
    })
}

/// Distance from `p` to the segment `a`-`b`, px.
fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let f = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - f * dx).hypot(p.1 - a.1 - f * dy)
}

/// The stroke of a line that coincides with an earlier one: dashes of [`DASH`] px, one every `group` dashes,
/// shifted by its rank, so that the earlier line shows in the remaining gaps.
fn same_stroke(st: &Style, c: Same) -> String {
    let period = DASH * c.group as f64;
    format!(
        "stroke=\"{}\" stroke-width=\"{}\" stroke-dasharray=\"{} {}\" stroke-dashoffset=\"{}\"",
        st.color,
        px(st.width),
        px(DASH),
        px(period - DASH),
        px(-DASH * (c.rank - 1) as f64)
    )
}

/// The legend text of a series: its label, and the line it coincides with.
fn legend_label(p: &Panel, k: usize, same: &[Option<Same>]) -> String {
    let ser = &p.series[k];
    match same[k] {
        Some(c) => format!("{} (same as {})", ser.label, short_name(p, c.root)),
        None => ser.label.clone(),
    }
}

/// The label of series `k` without its parenthesis ("hunt-crossley (e_post 0.65)" → "hunt-crossley"),
/// unless another label of the panel starts the same ("Anagnostopoulos (kelvin-voigt, clamped)").
fn short_name(p: &Panel, k: usize) -> String {
    let of = &p.series[k].label;
    match of.split_once(" (") {
        Some((head, _))
            if !p
                .series
                .iter()
                .enumerate()
                .any(|(i, s)| i != k && s.label.starts_with(head)) =>
        {
            head.to_string()
        }
        _ => of.clone(),
    }
}

/// A marker of `shape` and radius `r` at `(cx, cy)`, px: a circle, or a path that carries its centre as
/// `data-cx`, `data-cy`.
fn marker(s: &mut String, shape: Shape, cx: f64, cy: f64, r: f64) {
    let d = match shape {
        Shape::Circle => return circle(s, cx, cy, r),
        Shape::Square => {
            let h = 0.89 * r;
            format!(
                "M{} {}h{}v{}h{}z",
                px(cx - h),
                px(cy - h),
                px(2.0 * h),
                px(2.0 * h),
                px(-2.0 * h)
            )
        }
        Shape::Diamond => {
            let h = 1.25 * r;
            format!(
                "M{} {}L{} {}L{} {}L{} {}z",
                px(cx),
                px(cy - h),
                px(cx + h),
                px(cy),
                px(cx),
                px(cy + h),
                px(cx - h),
                px(cy)
            )
        }
        Shape::Triangle | Shape::TriangleDown => {
            let h = 1.35 * r;
            let sgn = if shape == Shape::Triangle { 1.0 } else { -1.0 };
            format!(
                "M{} {}L{} {}L{} {}z",
                px(cx),
                px(cy - sgn * h),
                px(cx + 0.866 * h),
                px(cy + sgn * 0.5 * h),
                px(cx - 0.866 * h),
                px(cy + sgn * 0.5 * h)
            )
        }
        Shape::Hexagon => {
            let h = 1.1 * r;
            let mut d = String::new();
            for k in 0..6 {
                let a = std::f64::consts::PI / 3.0 * k as f64;
                let _ = write!(
                    d,
                    "{}{} {}",
                    if k == 0 { "M" } else { "L" },
                    px(cx + h * a.cos()),
                    px(cy + h * a.sin())
                );
            }
            d + "z"
        }
    };
    let _ = write!(
        s,
        "<path data-cx=\"{}\" data-cy=\"{}\" d=\"{d}\"/>",
        px(cx),
        px(cy)
    );
}

fn series_svg(s: &mut String, ser: &Series, m: &Map, same: Option<(Same, &String)>) {
    let label = esc(&ser.label);
    match &ser.mark {
        Mark::Line { x, y } => {
            let pts: Vec<(f64, f64)> = x
                .iter()
                .zip(y)
                .filter(|(a, b)| a.is_finite() && b.is_finite())
                .map(|(a, b)| (m.px(*a), m.py(*b)))
                .collect();
            let keep = thin(&pts, m.size.w);
            let mut d = String::with_capacity(keep.len() * 16);
            for (k, &i) in keep.iter().enumerate() {
                if k > 0 {
                    d.push(' ');
                }
                let _ = write!(d, "{},{}", px(pts[i].0), px(pts[i].1));
            }
            let (stroke, of) = match same {
                Some((c, of)) => (
                    same_stroke(&ser.style, c),
                    format!(" data-same-as=\"{}\"", esc(of)),
                ),
                None => (stroke(&ser.style), String::new()),
            };
            let _ = write!(
                s,
                "\n<polyline class=\"line\" data-label=\"{label}\"{of} fill=\"none\" stroke-linejoin=\"round\" {stroke} points=\"{d}\"/>"
            );
        }
        Mark::Points { x, y } => {
            let _ = write!(
                s,
                "\n<g class=\"points\" data-label=\"{label}\" fill=\"{}\" fill-opacity=\"0.85\" stroke=\"#ffffff\" stroke-width=\"0.6\">",
                ser.style.color
            );
            for (a, b) in x.iter().zip(y) {
                marker(
                    s,
                    ser.style.shape,
                    m.px(*a),
                    m.py(*b),
                    ser.style.width + 1.2,
                );
            }
            s.push_str("</g>");
        }
        Mark::HLine(v) => {
            let y = m.py(*v);
            let _ = write!(
                s,
                "\n<line class=\"hline\" data-label=\"{label}\" data-value=\"{v}\" x1=\"{}\" x2=\"{}\" y1=\"{}\" y2=\"{}\" {}/>",
                px(m.x0),
                px(m.x0 + m.size.w),
                px(y),
                px(y),
                stroke(&ser.style)
            );
        }
        Mark::Rug(t) => {
            let mut d = String::new();
            for &v in t {
                let _ = write!(d, "M{} {}v{}", px(m.px(v)), px(m.y0), px(9.0));
            }
            let _ = write!(
                s,
                "\n<path class=\"rug\" data-label=\"{label}\" data-count=\"{}\" d=\"{d}\" fill=\"none\" {}/>",
                t.len(),
                stroke(&ser.style)
            );
        }
    }
}

/// A legend's marker of `shape` and radius `r` at `(cx, cy)`, px, filled with `color`, on a line of its own.
fn legend_dot(s: &mut String, cx: f64, cy: f64, r: f64, color: &str, shape: Shape) {
    let _ = write!(s, "\n<g fill=\"{color}\">");
    marker(s, shape, cx, cy, r);
    s.push_str("</g>");
}

/// One dot of radius `r` at `(cx, cy)`, px.
fn circle(s: &mut String, cx: f64, cy: f64, r: f64) {
    let _ = write!(
        s,
        "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>",
        px(cx),
        px(cy),
        px(r)
    );
}

/// The dots of a line drawn with markers, at its points inside the plot area.
fn markers_svg(s: &mut String, ser: &Series, m: &Map) {
    let Mark::Line { x, y } = &ser.mark else {
        return;
    };
    let _ = write!(
        s,
        "\n<g class=\"markers\" data-label=\"{}\" fill=\"{}\">",
        esc(&ser.label),
        ser.style.color
    );
    let inside = |v: f64, a: f64, b: f64| v.is_finite() && v >= a - 0.5 && v <= b + 0.5;
    for (a, b) in x.iter().zip(y) {
        let (cx, cy) = (m.px(*a), m.py(*b));
        if inside(cx, m.x0, m.x0 + m.size.w) && inside(cy, m.y0, m.y0 + m.size.h) {
            marker(s, ser.style.shape, cx, cy, ser.style.width + 1.4);
        }
    }
    s.push_str("</g>");
}

/// Indices of the points to draw: all of them for short lines or lines that turn back in x (loops);
/// otherwise, per pixel column, the first, lowest, highest and last point, in order.
fn thin(pts: &[(f64, f64)], width: f64) -> Vec<usize> {
    let monotone = pts.windows(2).all(|w| w[1].0 >= w[0].0);
    if pts.len() <= 4 * width as usize || !monotone {
        return (0..pts.len()).collect();
    }
    let mut keep = Vec::new();
    let mut k = 0;
    while k < pts.len() {
        let column = pts[k].0.floor();
        let start = k;
        let (mut lo, mut hi) = (k, k);
        while k < pts.len() && pts[k].0.floor() == column {
            // Pixel y grows downwards: the lowest value has the largest y.
            if pts[k].1 > pts[lo].1 {
                lo = k;
            }
            if pts[k].1 < pts[hi].1 {
                hi = k;
            }
            k += 1;
        }
        let mut group = [start, lo, hi, k - 1];
        group.sort_unstable();
        for i in group {
            if keep.last() != Some(&i) {
                keep.push(i);
            }
        }
    }
    keep
}

/// Width and height of a panel's legend box, px.
fn legend_size(p: &Panel, same: &[Option<Same>]) -> (f64, f64) {
    let labelled: Vec<(usize, &Series)> = p
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.label.is_empty())
        .collect();
    let w = labelled
        .iter()
        .map(|(k, _)| text_width(&legend_label(p, *k, same), LEGEND))
        .fold(0.0, f64::max);
    (w + 40.0, labelled.len() as f64 * ENTRY + 8.0)
}

/// Where a legend goes: a corner of the plot (offset of its box from the plot's top left), or the right.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Place {
    Corner(f64, f64),
    Right,
    Nowhere,
}

/// An inside legend goes in the first corner (top right, top left, bottom right, bottom left) where it hides
/// no data; if every corner hides some, it goes to the right of the plot.
fn place_legend(p: &Panel, xa: &Axis, ya: &Axis, size: Size, same: &[Option<Same>]) -> Place {
    let (w, h) = legend_size(p, same);
    match p.legend {
        _ if h <= 8.0 => return Place::Nowhere,
        Legend::None => return Place::Nowhere,
        Legend::Right => return Place::Right,
        Legend::Inside => {}
    }
    let m = Map::new(xa, ya, (0.0, 0.0), size);
    let dots: Vec<(f64, f64)> = p.series.iter().flat_map(|s| pixels(s, &m)).collect();
    let pad = 8.0;
    let (pw, ph) = (size.w, size.h);
    let corners = [
        (pw - pad - w, pad + 10.0),
        (pad, pad + 10.0),
        (pw - pad - w, ph - pad - h),
        (pad, ph - pad - h),
    ];
    // A line between two drawn points can cross the box with both points outside: test the segments too.
    let hides = |&(cx, cy): &(f64, f64)| {
        let inside = |(x, y): (f64, f64)| {
            x >= cx - 3.0 && x <= cx + w + 3.0 && y >= cy - 3.0 && y <= cy + h + 3.0
        };
        dots.iter().any(|&d| inside(d))
            || dots.windows(2).any(|s| {
                let (a, b) = (s[0], s[1]);
                let n = ((b.0 - a.0).hypot(b.1 - a.1) / 4.0).ceil().min(400.0) as usize;
                (1..n).any(|i| {
                    let f = i as f64 / n as f64;
                    inside((a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1)))
                })
            })
    };
    corners
        .iter()
        .find(|c| !hides(c))
        .map_or(Place::Right, |&(x, y)| Place::Corner(x, y))
}

fn legend_svg(
    s: &mut String,
    p: &Panel,
    place: Place,
    (x0, y0, x1): (f64, f64, f64),
    same_all: &[Option<Same>],
) {
    let (w, h) = legend_size(p, same_all);
    let (lx, ly) = match place {
        Place::Nowhere => return,
        Place::Right => (x1 + 14.0, y0),
        Place::Corner(dx, dy) => (x0 + dx, y0 + dy),
    };
    let _ = write!(
        s,
        "\n<g class=\"legend\" font-size=\"{LEGEND}\">\n<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#ffffff\" fill-opacity=\"0.9\" stroke=\"#bbbbbb\" stroke-width=\"0.8\"/>",
        px(lx),
        px(ly),
        px(w),
        px(h)
    );
    let labelled = p
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.label.is_empty());
    for (i, (k, ser)) in labelled.enumerate() {
        let cy = ly + 4.0 + ENTRY * (i as f64 + 0.5);
        let sx = lx + 8.0;
        let same = same_all[k];
        match ser.mark {
            Mark::Points { .. } => {
                legend_dot(
                    s,
                    sx + 11.0,
                    cy,
                    ser.style.width + 1.2,
                    ser.style.color,
                    ser.style.shape,
                );
            }
            Mark::Rug(_) => {
                let _ = write!(
                    s,
                    "\n<path d=\"M{} {}v9\" fill=\"none\" {}/>",
                    px(sx + 11.0),
                    px(cy - 4.5),
                    stroke(&ser.style)
                );
            }
            _ => {
                let _ = write!(
                    s,
                    "\n<path d=\"M{} {}h22\" fill=\"none\" {}/>",
                    px(sx),
                    px(cy),
                    match same {
                        Some(c) => same_stroke(
                            &ser.style,
                            Same {
                                rank: 1,
                                group: 2,
                                ..c
                            }
                        ),
                        None => stroke(&ser.style),
                    }
                );
                if ser.style.marker {
                    legend_dot(
                        s,
                        sx + 11.0,
                        cy,
                        ser.style.width + 1.4,
                        ser.style.color,
                        ser.style.shape,
                    );
                }
            }
        }
        let _ = write!(
            s,
            "\n<text x=\"{}\" y=\"{}\">{}</text>",
            px(sx + 28.0),
            px(cy + 0.35 * LEGEND),
            esc(&legend_label(p, k, same_all))
        );
    }
    s.push_str("\n</g>");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thinning_keeps_every_extreme() {
        // 100 000 samples of a fast oscillation with one spike: the spike and both extremes survive.
        let n = 100_000;
        let mut pts: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                (
                    i as f64 * 620.0 / n as f64,
                    100.0 + 50.0 * (i as f64 * 0.37).sin(),
                )
            })
            .collect();
        pts[54_321].1 = -400.0;
        let keep = thin(&pts, 620.0);
        assert!(keep.len() <= 4 * (620 + 1));
        assert!(keep.windows(2).all(|w| w[0] < w[1]));
        assert!(keep.contains(&54_321));
        let ys = |v: &Vec<usize>| {
            v.iter()
                .map(|&i| pts[i].1)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        assert_eq!(ys(&keep), ys(&(0..n).collect()));
    }

    #[test]
    fn long_subtitles_keep_one_line_and_lose_nothing() {
        let text = "papi, k = 1e9 N/m, e = 0.65, damping formula; m1 = 100000 kg, m2 = inf (rigid) kg, v = 1 m/s";
        let (lines, rest) = split_subtitle(text, 12.0, 300.0);
        assert_eq!(lines.len(), 1);
        assert!(text_width(&lines[0], 12.0) <= 300.0);
        assert_eq!(format!("{}; {}", lines[0], rest.unwrap()), text);
        // One clause too long: wrapped, after a comma or colon where it can, never cut.
        let run = "three-vs-eight-inelastic.toml: el-centro-1940 \u{d7} 1, 20 s, 5 impacts";
        let (lines, rest) = split_subtitle(run, 12.0, 300.0);
        assert_eq!(rest, None);
        assert_eq!(lines.join(" "), run);
        assert!(lines.len() == 2 && lines[0].ends_with(':'), "{lines:?}");
        assert!(lines.iter().all(|l| text_width(l, 12.0) <= 300.0));
        // A word longer than the line is broken between characters.
        let path = "six.toml: records/a-very-long-folder-name/another-level/with-a-long-record-file-name.csv";
        let (lines, rest) = split_subtitle(path, 12.0, 200.0);
        assert_eq!(rest, None);
        assert_eq!(lines.concat().replace(' ', ""), path.replace(' ', ""));
        assert!(lines.iter().all(|l| text_width(l, 12.0) <= 200.0));
    }

    #[test]
    fn long_titles_wrap_evenly_in_the_bold_face() {
        let title = "Force against penetration of the strongest impacts, by contact level";
        let w = |t: &str| bold_text_width(t, 16.0);
        let lines = balanced(title, 405.0, &w);
        assert_eq!(lines.join(" "), title);
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(lines.iter().all(|l| w(l) <= 405.0));
        // Even: the two lines differ by less than a third of the longer.
        assert!((w(&lines[0]) - w(&lines[1])).abs() < w(&lines[0]).max(w(&lines[1])) / 3.0);
        assert_eq!(balanced("Short", 405.0, &w), vec!["Short".to_string()]);
        assert!(balanced("", 405.0, &w).is_empty());
    }

    #[test]
    fn long_notes_wrap_at_spaces() {
        let text = "m1 = 100000 kg, m2 = inf (rigid) kg, v = 1 m/s, e_pre = 0.65, formula damping";
        let lines = wrap(text, 12.0, 200.0);
        assert!(lines.len() > 1);
        assert_eq!(lines.join(" "), text);
        assert!(lines.iter().all(|l| text_width(l, 12.0) <= 200.0));
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(esc("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
