//! The contacts of a run: force and relative displacement per contact level, delivered e, impact loops.

use super::common::{fmt_mm, force, time};
use crate::output::{fmt_num, fmt_sig};
use crate::plot::axis::human;
use crate::plot::{Dash, Figure, Legend, Mark, Panel, Quantity, Series, Style, PLOT};
use crate::run_data::{ImpactData, RunData};
use pounding::contact::material_e;
use pounding_study::summary::inside::{inside, Meeting};
use pounding_study::summary::{ContactLawSummary, DampingSummary};

/// A contact level of a run: one contact element (a floor pair of a contact, or a wall's floor).
struct Level {
    /// Index of the contact in [`RunData::contacts`].
    contact: usize,
    /// Index of the element in the contact.
    element: usize,
    /// "contact west|east, floors 2-2" or "wall moat, floor 1".
    label: String,
    /// Its colour and marker shape, the same in every figure of the run.
    style: Style,
}

impl Level {
    /// Whether this level was hit: an impact, or a force at some output sample.
    fn hit(&self, d: &RunData) -> bool {
        let el = &d.contacts[self.contact].elements[self.element];
        d.impacts.iter().any(|i| self.holds(d, i)) || el.force.iter().any(|f| *f != 0.0)
    }

    /// Whether impact `i` happened at this level.
    fn holds(&self, d: &RunData, i: &crate::run_data::ImpactData) -> bool {
        i.contact == self.contact
            && i.floors == d.contacts[self.contact].elements[self.element].floors
    }
}

/// The note naming the levels that were never hit, grouped by site: "Not hit (no force): contact
/// west|east, floors 1-1, 2-2; wall moat."
fn silent_note(d: &RunData, silent: &[&Level]) -> String {
    let mut groups: Vec<(usize, Vec<String>)> = Vec::new();
    for lv in silent {
        let cd = &d.contacts[lv.contact];
        let el = &cd.elements[lv.element];
        let pair = if cd.wall {
            format!("floor {}", el.floors.0.max(el.floors.1))
        } else {
            format!("{}-{}", el.floors.0, el.floors.1)
        };
        match groups.last_mut() {
            Some(g) if g.0 == lv.contact => g.1.push(pair),
            _ => groups.push((lv.contact, vec![pair])),
        }
    }
    let parts: Vec<String> = groups
        .iter()
        .map(|(c, pairs)| {
            let cd = &d.contacts[*c];
            let what = if cd.wall { "wall" } else { "contact" };
            if single_floor(d, cd.left) && single_floor(d, cd.right) {
                format!("{what} {}", cd.name)
            } else if cd.wall {
                format!("{what} {}, {}", cd.name, pairs.join(", "))
            } else {
                format!("{what} {}, floors {}", cd.name, pairs.join(", "))
            }
        })
        .collect();
    format!(
        "Not hit (no force over the run, not drawn; their closing is in relative-displacement.svg): {}.",
        parts.join("; ")
    )
}

/// Every contact level of the run, contacts left to right, then walls; floor pairs in order.
fn contact_levels(d: &RunData) -> Vec<Level> {
    let mut out = Vec::new();
    for (c, cd) in d.contacts.iter().enumerate() {
        for (e, el) in cd.elements.iter().enumerate() {
            let what = if cd.wall { "wall" } else { "contact" };
            // Between single-floor structures (decks, one-storey buildings) a floor number tells nothing.
            let label = if single_floor(d, cd.left) && single_floor(d, cd.right) {
                format!("{what} {}", cd.name)
            } else if cd.wall {
                format!("{what} {}, floor {}", cd.name, el.floors.0.max(el.floors.1))
            } else {
                format!("{what} {}, floors {}-{}", cd.name, el.floors.0, el.floors.1)
            };
            out.push(Level {
                contact: c,
                element: e,
                label,
                style: Style::level(out.len()),
            });
        }
    }
    out
}

/// Whether side `b` of a contact (a building, or a wall's `None`) has one floor only.
pub fn single_floor(d: &RunData, b: Option<usize>) -> bool {
    b.is_none_or(|b| d.buildings[b].floors.len() == 1)
}

/// The plot height of one of `n` small multiples, px: the usual 250 for one, less for many.
fn multiple_height(n: usize) -> f64 {
    match n {
        0 | 1 => PLOT.1,
        2 | 3 => 170.0,
        _ => 120.0,
    }
}

/// Contact forces and relative displacements, one panel per contact level (small multiples sharing the
/// time axis), and the delivered e of every ended impact against its velocity at touch.
pub fn contact_figures(d: &RunData) -> (Option<Figure>, Option<Figure>, Option<Figure>) {
    let levels = contact_levels(d);
    if levels.is_empty() {
        return (None, None, None);
    }
    let (forces, closing) = level_panels(d, &levels);
    let n = levels.len();
    // Panels for the levels that were hit; the silent ones are named in a note.
    let hit: Vec<bool> = levels.iter().map(|lv| lv.hit(d)).collect();
    let silent: Vec<&Level> = levels
        .iter()
        .zip(&hit)
        .filter(|h| !*h.1)
        .map(|h| h.0)
        .collect();
    let mut forces: Vec<Panel> = forces
        .into_iter()
        .zip(&hit)
        .filter(|p| *p.1)
        .map(|p| p.0)
        .collect();
    let m = forces.len();
    if m == 0 {
        let mut p = Panel::new("no contact level was hit", time(), force());
        p.y_range = Some((0.0, 1.0e6));
        p.x_range = d.t.first().zip(d.t.last()).map(|(a, b)| (*a, *b));
        p.legend = Legend::None;
        forces.push(p);
    }
    let force_fig = Figure {
        id: "contact-force".into(),
        title: if m == n {
            format!(
                "Contact force at each contact level ({n} level{})",
                if n == 1 { "" } else { "s" }
            )
        } else {
            format!("Contact force at the levels that were hit ({m} of {n})")
        },
        subtitle: d.subtitle.clone(),
        panels: forces,
        plot: (PLOT.0, multiple_height(m)),
        share_x: true,
        notes: vec![
            "Line: the force at the output samples with each impact's located peak inserted; markers: the \
             located peak of each impact (peak_force_N of impacts.csv). Each panel has its own force axis."
                .into(),
        ]
        .into_iter()
        .chain((!silent.is_empty()).then(|| silent_note(d, &silent)))
        .chain(
            d.impacts
                .iter()
                .any(|i| i.consumed)
                .then(|| "With a bumper, the line is the layer's and the hard law's force together and the panel's largest is their sum, as summary.json gives it; markers are each law's impacts.".to_string()),
        )
        .collect(),
        ..Figure::default()
    };
    let (masses, what) = closing_words(d);
    let closing_fig = Figure {
        id: "relative-displacement".into(),
        title: format!("Relative displacement of the contact {masses} against the gap"),
        subtitle: d.subtitle.clone(),
        panels: closing,
        plot: (PLOT.0, multiple_height(n)),
        share_x: true,
        notes: vec![format!(
            "{what}; dashed: the gap, contact above it{}. One axis for every level.",
            if d.summary.sites.iter().any(|s| s.bumper.is_some()) {
                "; dotted: a bumper's face, touched first"
            } else {
                ""
            }
        )],
        ..Figure::default()
    };

    (Some(force_fig), Some(closing_fig), restitution(d, &levels))
}

/// The words of `relative-displacement.svg`: the masses that meet ("floors", "decks") and what is drawn
/// ("u_left - u_right of each pair of contact floors (for a wall, the floor's displacement towards it)").
fn closing_words(d: &RunData) -> (String, String) {
    let meet = |wall: bool| -> Vec<Meeting> {
        d.summary
            .sites
            .iter()
            .filter(|c| c.is_wall() == wall)
            .map(|c| Meeting::of_summary(&d.summary, c))
            .collect()
    };
    let (pairs, walls) = (meet(false), meet(true));
    let all: Vec<Meeting> = pairs.iter().chain(&walls).copied().collect();
    let what = match (pairs.is_empty(), walls.is_empty()) {
        (false, false) => format!(
            "u_left \u{2212} u_right of each pair of contact {} (for a wall, the {}'s displacement towards it)",
            inside(&pairs).masses,
            inside(&walls).mass
        ),
        (false, true) => format!(
            "u_left \u{2212} u_right of each pair of contact {}",
            inside(&pairs).masses
        ),
        _ => format!("the {}'s displacement towards the wall", inside(&walls).mass),
    };
    (inside(&all).masses, what)
}

/// For each contact level: its force over time, and its closing against its gap (on one range for every
/// level).
fn level_panels(d: &RunData, levels: &[Level]) -> (Vec<Panel>, Vec<Panel>) {
    let t_range = (
        d.t.first().copied().unwrap_or(0.0),
        d.t.last().copied().unwrap_or(1.0),
    );
    let mut forces = Vec::new();
    let mut closing = Vec::new();
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for lv in levels {
        let cd = &d.contacts[lv.contact];
        let el = &cd.elements[lv.element];
        let mine: Vec<_> = d.impacts.iter().filter(|i| lv.holds(d, i)).collect();
        let consumed = mine.iter().filter(|i| i.consumed).count();
        // One peak per site, as the terminal and summary.json give it (a bumper's layer and the hard law
        // behind it push together); a site of several levels: this level's own.
        let site = &d.summary.sites[lv.contact];
        let peak = if cd.elements.len() == 1 {
            site.peak_force
        } else {
            mine.iter()
                .map(|i| i.peak_force)
                .chain(el.force.iter().copied())
                .fold(0.0, f64::max)
        };
        let mut title = format!(
            "{}: {} impact{}",
            lv.label,
            mine.len() - consumed,
            if mine.len() - consumed == 1 { "" } else { "s" }
        );
        if consumed > 0 {
            title += &format!(", bumper consumed in {consumed}");
        }
        if !mine.is_empty() {
            title += &format!(", largest {}", human(peak, "N", 3));
        }
        let mut p = Panel::new(title, time(), force());
        p.x_range = Some(t_range);
        p.y_zero = true;
        p.legend = Legend::None;
        // The samples, with each impact's located peak inserted, so the curve reaches its true peak.
        let peaks: Vec<(f64, f64)> = mine
            .iter()
            .map(|i| (i.time_of_peak_force, i.peak_force))
            .collect();
        let (t, f) = merge(&d.t, &el.force, &peaks);
        p.series.push(Series::line(&lv.label, t, f, lv.style));
        if !mine.is_empty() {
            p.series.push(Series::points(
                format!("{}: peak of each impact", lv.label),
                mine.iter().map(|i| i.time_of_peak_force).collect(),
                mine.iter().map(|i| i.peak_force).collect(),
                Style {
                    width: 1.6,
                    ..lv.style
                },
            ));
        }
        forces.push(p);

        // A wall's side does not move relative to the ground.
        let u = |b: Option<usize>, f: usize, k: usize| {
            b.map_or(0.0, |b| d.buildings[b].floors[f - 1][k])
        };
        let rel: Vec<f64> = (0..d.t.len())
            .map(|k| u(cd.left, el.floors.0, k) - u(cd.right, el.floors.1, k))
            .collect();
        for &v in rel.iter().chain([&cd.gap]) {
            (lo, hi) = (lo.min(v), hi.max(v));
        }
        // A bumper is touched before the gap closes: at the gap less its thickness.
        let face = site.bumper.as_ref().map(|b| cd.gap - b.thickness);
        let mut q = Panel::new(
            match face {
                Some(f) => format!(
                    "{}: bumper face at {} mm, gap {} mm",
                    lv.label,
                    fmt_mm(f),
                    fmt_mm(cd.gap)
                ),
                None => format!("{}: gap {} mm", lv.label, fmt_mm(cd.gap)),
            },
            time(),
            Quantity::new("u_left \u{2212} u_right", "m"),
        );
        if let Some(f) = face {
            q.series.push(Series {
                label: format!("bumper face ({} mm): contact above", fmt_mm(f)),
                mark: Mark::HLine(f),
                style: Style {
                    dash: Dash::Dotted,
                    ..Style::reference()
                },
            });
        }
        q.x_range = Some(t_range);
        q.legend = Legend::None;
        q.series
            .push(Series::line(&lv.label, d.t.clone(), rel, lv.style));
        q.series.push(Series {
            label: format!("gap ({} mm): contact above", fmt_mm(cd.gap)),
            mark: Mark::HLine(cd.gap),
            style: Style::reference(),
        });
        closing.push(q);
    }
    // One range for every level: the gap line at one height, and the levels compare at a glance.
    let pad = 0.04 * (hi - lo);
    for q in &mut closing {
        q.y_range = Some((lo - pad, hi + pad));
    }
    (forces, closing)
}

/// The delivered e of each ended impact against its impact velocity, one colour and shape per level, with
/// the e each contact was asked for.
fn restitution(d: &RunData, levels: &[Level]) -> Option<Figure> {
    let mut r = Panel::new(
        "",
        Quantity::new("relative velocity at touch v_i", "m/s"),
        Quantity::new("delivered e (e_post)", ""),
    );
    r.y_zero = true;
    r.x_zero = true;
    r.legend = Legend::Right;
    let (mut above, mut ended, mut top) = (0, 0, f64::NEG_INFINITY);
    // What met in the impacts above the e asked, for the words of the note.
    let mut met: Vec<Meeting> = Vec::new();
    // The impacts that ended when their clamped force vanished with penetration left (e = 1/chi).
    let mut released = Released::default();
    for lv in levels {
        let cd = &d.contacts[lv.contact];
        // Impacts on the site's face (a bumper's layer, or the law itself); the hard law behind a consumed
        // bumper acts within such an impact and is not one.
        let mine: Vec<_> = d
            .impacts
            .iter()
            .filter(|i| lv.holds(d, i) && i.e_post.is_some() && !i.consumed)
            .collect();
        if mine.is_empty() {
            continue;
        }
        // The face's law asks its own e: a bumper's, else the site's; a table or a damping constant asks
        // each impact its own (impacts.csv's e_asked).
        let asked = match &d.summary.sites[lv.contact].bumper {
            Some(b) => b.law.e,
            None => cd.e,
        };
        for i in &mine {
            let Some(e) = i.e_post else { continue };
            ended += 1;
            let wanted = i.e_asked.or(asked).unwrap_or(1.0);
            if e > wanted * (1.0 + 1e-9) {
                above += 1;
                met.push(Meeting::of_summary(
                    &d.summary,
                    &d.summary.sites[lv.contact],
                ));
            }
            top = top.max(e);
        }
        r.series.push(Series::points(
            &lv.label,
            mine.iter().map(|i| i.v_i).collect(),
            mine.iter().filter_map(|i| i.e_post).collect(),
            Style {
                width: 1.8,
                ..lv.style
            },
        ));
        // Thornton's spheres ask no e: the e their law delivers between free bodies at each v_i (it depends
        // on the level's effective mass), as a line through the impacts' e_asked.
        let law = match &d.summary.sites[lv.contact].bumper {
            Some(b) => &b.law,
            None => &d.summary.sites[lv.contact].law,
        };
        released.add(d, (lv.contact, asked), law, &mine);
        if let DampingSummary::YieldPressure { .. } = law.damping_parameter {
            let mut own: Vec<(f64, f64)> = mine
                .iter()
                .filter_map(|i| i.e_asked.map(|e| (i.v_i, e)))
                .collect();
            own.sort_by(|a, b| a.0.total_cmp(&b.0));
            r.series.push(Series::line(
                format!("e of the spheres at v_i, free bodies ({})", lv.label),
                own.iter().map(|p| p.0).collect(),
                own.iter().map(|p| p.1).collect(),
                Style {
                    width: 1.2,
                    dash: Dash::Dotted,
                    ..lv.style
                },
            ));
        }
    }
    let v_max = d
        .impacts
        .iter()
        .filter(|i| i.e_post.is_some())
        .fold(0.0f64, |a, i| a.max(i.v_i));
    r.series.extend(requested(d, v_max));
    (ended > 0).then(|| {
        let mut notes = Vec::new();
        if above > 0 {
            notes.push(above_note(above, ended, top, &met));
        }
        if released.count > 0 {
            notes.push(released.note(ended));
        }
        Figure {
            id: "impact-restitution".into(),
            title: "Delivered coefficient of restitution of each impact, by contact level".into(),
            subtitle: d.subtitle.clone(),
            panels: vec![r],
            notes,
            ..Figure::default()
        }
    })
}

/// The note of `above` of `ended` impacts delivering more than their e asked (the largest `top`), in the words
/// of what met in them: "... in a contact between buildings, the storeys keep acting on the floors ...".
fn above_note(above: usize, ended: usize, top: f64, met: &[Meeting]) -> String {
    let w = inside(met);
    let mut note = format!(
        "{above} of {ended} impacts {} above the requested e{}: each contact law is calibrated to deliver e \
         between two free bodies, but in a contact {}, {} keep acting on the {} while they touch \
         (docs/verification.md, \"Impacts inside a run\").",
        if above == 1 { "lies" } else { "lie" },
        if top > 1.0 {
            format!(" (up to {})", fmt_sig(top, 4))
        } else {
            String::new()
        },
        w.contact,
        w.forces,
        w.masses
    );
    if top > 1.0 {
        note.push_str(&format!(" Above 1, {} {}.", w.forces, w.parted));
    }
    note
}

/// The impacts that ended when the force of their clamped Hunt–Crossley-type law, `k d^n (1 + chi d'/v_i)`,
/// vanished: at the parting speed `d' = -v_i/chi`, with penetration left, so that they delivered exactly
/// `e = 1/chi` (`1/((D/K) v_i)` with a damping constant), whatever e the law was asked.
#[derive(Default)]
struct Released {
    /// How many, and how many of them lie above the e asked.
    count: usize,
    above: usize,
    /// Each law concerned ("1/chi = 0.698 (the bumper of moat-east, chi = 1.4328)") and how many of its
    /// impacts.
    laws: Vec<(String, usize)>,
    /// Whether some were on a bumper's layer, and some not.
    bumper: bool,
    direct: bool,
    /// What met in them.
    met: Vec<Meeting>,
}

impl Released {
    /// Counts the ended impacts `mine` of site `site`, of law `law` (asked `asked`, unless an impact was
    /// asked its own), that delivered its 1/chi (to 1e-9).
    fn add(
        &mut self,
        d: &RunData,
        (site, asked): (usize, Option<f64>),
        law: &ContactLawSummary,
        mine: &[&ImpactData],
    ) {
        let at = |i: &ImpactData| {
            let ceiling = match law.damping_parameter {
                DampingSummary::Chi { value } => 1.0 / value,
                DampingSummary::DampingConstant { value } => 1.0 / (value * i.v_i),
                _ => return false,
            };
            i.e_post
                .is_some_and(|e| (e - ceiling).abs() <= 1e-9 * ceiling)
        };
        let n = mine.iter().filter(|i| at(i)).count();
        if n == 0 {
            return;
        }
        self.above += mine
            .iter()
            .filter(|i| at(i))
            .filter(|i| {
                let wanted = i.e_asked.or(asked).unwrap_or(1.0);
                i.e_post.is_some_and(|e| e > wanted * (1.0 + 1e-9))
            })
            .count();
        let sum = &d.summary.sites[site];
        let whose = match sum.bumper {
            Some(_) => format!("the bumper of {}", sum.name),
            None if sum.is_wall() => format!("wall {}", sum.name),
            None => format!("contact {}", sum.name),
        };
        let which = match law.damping_parameter {
            DampingSummary::Chi { value } => format!(
                "1/chi = {} ({whose}, chi = {})",
                fmt_sig(1.0 / value, 4),
                fmt_sig(value, 5)
            ),
            DampingSummary::DampingConstant { value } => {
                format!("1/((D/K) v_i) ({whose}, D/K = {} s/m)", fmt_sig(value, 5))
            }
            _ => unreachable!("only these laws are counted"),
        };
        match self.laws.iter_mut().find(|l| l.0 == which) {
            Some(l) => l.1 += n,
            None => self.laws.push((which, n)),
        }
        self.count += n;
        self.bumper |= sum.bumper.is_some();
        self.direct |= sum.bumper.is_none();
        self.met.push(Meeting::of_summary(&d.summary, sum));
    }

    /// The note: how many of the `ended` impacts, of which law, and why (after the note of those above the
    /// e asked, which these are among when they lie above it too).
    fn note(&self, ended: usize) -> String {
        let n = self.count;
        let verb = if n == 1 { "delivers" } else { "deliver" };
        let who = if self.above == n {
            format!("Of these, {n} {verb}")
        } else {
            format!("{n} of {ended} impacts {verb}")
        };
        let laws: Vec<String> = self
            .laws
            .iter()
            .map(|(l, k)| {
                if self.laws.len() > 1 {
                    format!("{l}: {k}")
                } else {
                    l.clone()
                }
            })
            .collect();
        let left = match (self.bumper, self.direct) {
            (true, false) => "with the bumper still compressed",
            (true, true) => "with penetration left (a bumper still compressed)",
            _ => "with penetration left",
        };
        let (its, these) = if n == 1 {
            ("its", "this contact")
        } else {
            ("their", "these contacts")
        };
        format!(
            "{who} exactly 1/chi of {its} law, {}: a Hunt\u{2013}Crossley-type force k d^n (1 + chi d'/v_i), \
             clamped at zero, vanishes when the parting speed d' reaches v_i/chi, and {these} ended there, \
             {left}, because the {} moved away faster than the law's force could follow (the law's own e \
             holds between free bodies only).",
            laws.join("; "),
            inside(&self.met).masses
        )
    }
}

/// The e each contact asks (a bumper its own): one dashed line for contacts given the same e, and the curve
/// `e(v_i)` of a table (held beyond its rows) or of a damping constant, up to `v_max` (m/s).
fn requested(d: &RunData, v_max: f64) -> Vec<Series> {
    let mut given: Vec<(f64, Vec<String>)> = Vec::new();
    let mut curves: Vec<(String, Vec<f64>, Vec<f64>)> = Vec::new();
    for (cd, site) in d.contacts.iter().zip(&d.summary.sites) {
        let (law, name) = match &site.bumper {
            Some(b) => (&b.law, format!("{} bumper", cd.name)),
            None => (&site.law, cd.name.clone()),
        };
        if let Some(rows) = &law.e_table {
            let top = v_max.max(rows.last().map_or(0.0, |r| r[0]));
            let first = rows.first().map_or(1.0, |r| r[1]);
            let last = rows.last().map_or(1.0, |r| r[1]);
            let v = std::iter::once(0.0)
                .chain(rows.iter().map(|r| r[0]))
                .chain([top]);
            let e = std::iter::once(first)
                .chain(rows.iter().map(|r| r[1]))
                .chain([last]);
            curves.push((
                format!("requested e(v_i), table ({name})"),
                v.collect(),
                e.collect(),
            ));
        } else if let DampingSummary::DampingConstant { value: c } = law.damping_parameter {
            let v: Vec<f64> = (0..=60).map(|k| v_max * f64::from(k) / 60.0).collect();
            let e = v.iter().map(|v| material_e(c * v)).collect();
            let label = format!("e(v_i) of D/K = {} s/m ({name})", fmt_num(c));
            curves.push((label, v, e));
        } else if let Some(e) = law.e {
            // An elastic contact asks none (it delivers 1).
            match given.iter_mut().find(|g| g.0 == e) {
                Some(g) => g.1.push(name),
                None => given.push((e, vec![name])),
            }
        }
    }
    let several = given.len() + curves.len() > 1;
    let style = |k: usize| Style {
        width: 1.4,
        // Several requests: dashes, then dots.
        dash: [Dash::Dashed, Dash::Dotted][k % 2],
        ..Style::reference()
    };
    let mut out: Vec<Series> = given
        .iter()
        .enumerate()
        .map(|(k, (e, names))| Series {
            label: if several {
                format!("requested e = {} ({})", fmt_num(*e), names.join(", "))
            } else {
                format!("requested e = {}", fmt_num(*e))
            },
            mark: Mark::HLine(*e),
            style: style(k),
        })
        .collect();
    for (k, (label, v, e)) in curves.into_iter().enumerate() {
        out.push(Series::line(label, v, e, style(given.len() + k)));
    }
    out
}

/// The force–penetration loops of the strongest impacts (at most [`LOOPS_PER_LEVEL`]) of each contact level,
/// from impact-loops.csv (none for a folder without it).
pub fn impact_loops(d: &RunData) -> Option<Figure> {
    let levels = contact_levels(d);
    let mut panels = Vec::new();
    for lv in &levels {
        let mut mine: Vec<_> = d
            .loops
            .iter()
            .filter(|l| lv.holds(d, &d.impacts[l.impact]))
            .collect();
        if mine.is_empty() {
            continue;
        }
        let total = mine.len();
        let hard = mine.iter().filter(|l| d.impacts[l.impact].consumed).count();
        mine.sort_by(|a, b| {
            d.impacts[b.impact]
                .peak_force
                .total_cmp(&d.impacts[a.impact].peak_force)
        });
        mine.truncate(LOOPS_PER_LEVEL);
        let mut p = Panel::new(
            if hard > 0 {
                // Loops of the impacts on the bumper and of the hard law behind it when it was consumed.
                format!(
                    "{}: top {} of {total} ({hard} consumed)",
                    lv.label,
                    mine.len()
                )
            } else if total > mine.len() {
                format!("{}: top {} of {total}", lv.label, mine.len())
            } else {
                format!(
                    "{}: {total} impact{}",
                    lv.label,
                    if total == 1 { "" } else { "s" }
                )
            },
            Quantity::new("penetration", "m"),
            force(),
        );
        p.x_zero = true;
        p.y_zero = true;
        for (rank, l) in mine.iter().enumerate() {
            let i = &d.impacts[l.impact];
            let dash = [Dash::Solid, Dash::Dashed, Dash::Dotted][rank % 3];
            let st = Style {
                dash,
                width: 1.5,
                ..lv.style
            };
            p.series.push(Series::line(
                format!(
                    "#{} at {} s: {}",
                    l.impact + 1,
                    fmt_sig(i.time, 4),
                    human(i.peak_force, "N", 3)
                ),
                l.penetration.clone(),
                l.force.clone(),
                st,
            ));
        }
        // The located peaks.
        let peak_of = |l: &&crate::run_data::LoopData| {
            let k = (0..l.force.len())
                .max_by(|&a, &b| l.force[a].total_cmp(&l.force[b]))
                .unwrap_or(0);
            (l.penetration[k], l.force[k])
        };
        let pk: Vec<(f64, f64)> = mine.iter().map(peak_of).collect();
        p.series.push(Series::points(
            "",
            pk.iter().map(|p| p.0).collect(),
            pk.iter().map(|p| p.1).collect(),
            Style {
                width: 1.6,
                ..lv.style
            },
        ));
        panels.push(p);
    }
    if panels.is_empty() {
        return None;
    }
    let columns = panels.len().min(2);
    Some(Figure {
        id: "impact-loops".into(),
        title: "Force against penetration of the strongest impacts, by contact level".into(),
        subtitle: d.subtitle.clone(),
        columns,
        plot: (360.0, 220.0),
        panels,
        notes: std::iter::once(
            "Every accepted integration step of each impact and its located peak (marker), from \
             impact-loops.csv; the area inside a loop is the energy the impact dissipated. Legend: impact \
             number in impacts.csv, time of touch, peak force."
                .to_string(),
        )
        .chain(d.impacts.iter().any(|i| i.consumed).then(|| {
            "With a bumper, \"consumed\" counts the loops of the hard law behind it once the layer was \
             consumed: each within an impact on the bumper, not an impact of its own."
                .to_string()
        }))
        .collect(),
        ..Figure::default()
    })
}

/// Impacts drawn per contact level in `impact-loops.svg`.
pub const LOOPS_PER_LEVEL: usize = 3;

/// `(t, f)` with the points `extra` inserted in time order.
fn merge(t: &[f64], f: &[f64], extra: &[(f64, f64)]) -> (Vec<f64>, Vec<f64>) {
    let mut extra = extra.to_vec();
    extra.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out_t = Vec::with_capacity(t.len() + extra.len());
    let mut out_f = Vec::with_capacity(t.len() + extra.len());
    let mut k = 0;
    for (&ti, &fi) in t.iter().zip(f) {
        while k < extra.len() && extra[k].0 < ti {
            out_t.push(extra[k].0);
            out_f.push(extra[k].1);
            k += 1;
        }
        out_t.push(ti);
        out_f.push(fi);
    }
    for &(te, fe) in &extra[k..] {
        out_t.push(te);
        out_f.push(fe);
    }
    (out_t, out_f)
}

#[cfg(test)]
mod tests {
    #[test]
    fn merged_points_keep_time_order() {
        let (t, f) = super::merge(
            &[0.0, 1.0, 2.0],
            &[0.0, 0.0, 0.0],
            &[(1.5, 9.0), (0.5, 7.0)],
        );
        assert_eq!(t, [0.0, 0.5, 1.0, 1.5, 2.0]);
        assert_eq!(f, [0.0, 7.0, 0.0, 9.0, 0.0]);
    }

    #[test]
    fn the_note_counts_in_good_grammar_and_names_what_met() {
        use pounding::structure::Form;
        use pounding_study::summary::inside::Meeting;
        let deck = |i| (i, Form::Deck);
        let one = super::above_note(1, 3, 0.9, &[Meeting::Wall(deck(0))]);
        assert!(
            one.starts_with("1 of 3 impacts lies above the requested e:"),
            "{one}"
        );
        assert!(
            one.contains("against a wall, the bearings keep acting on the decks"),
            "{one}"
        );
        assert!(!one.contains("Above 1"), "{one}");
        let two = super::above_note(2, 3, 1.2, &[Meeting::Between([deck(0), deck(1)])]);
        assert!(
            two.starts_with("2 of 3 impacts lie above the requested e (up to 1.2):"),
            "{two}"
        );
        assert!(
            two.ends_with("Above 1, the bearings parted the decks faster than they met."),
            "{two}"
        );
    }

    #[test]
    fn released_impacts_are_told_in_good_grammar() {
        use pounding::structure::Form;
        use pounding_study::summary::inside::Meeting;
        let mut one = super::Released {
            count: 1,
            above: 1,
            laws: vec![("1/chi = 1.026 (wall west, chi = 0.97487)".into(), 1)],
            bumper: false,
            direct: true,
            met: vec![Meeting::Wall((0, Form::Deck))],
        };
        let note = one.note(5);
        assert!(
            note.starts_with(
                "Of these, 1 delivers exactly 1/chi of its law, 1/chi = 1.026 (wall west"
            ),
            "{note}"
        );
        assert!(
            note.contains("this contact ended there, with penetration left, because the decks"),
            "{note}"
        );
        // Not above the e asked: said plainly.
        one.above = 0;
        assert!(one.note(5).starts_with("1 of 5 impacts delivers exactly"));
    }
}
