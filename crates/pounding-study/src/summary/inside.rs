//! Why an impact inside a run delivers another e than its law's between two free bodies, in the words of
//! what met: the storeys of buildings, the isolator of an isolated building, the bearings of a deck; floors
//! or decks; each other or a wall. The terminal, the report, the figures and `summary.json` say it alike.

use super::{BuildingSummary, RunSummary, SitePlace, SiteSummary};
use pounding::analysis::{ContactSite, Scenario, SiteKind};
use pounding::structure::Form;

/// What meets at a site: two structures, or one and a wall; each structure by its index (in the scenario's
/// buildings) and its form.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Meeting {
    /// Two neighbouring structures, left and right.
    Between([(usize, Form); 2]),
    /// A structure and a wall fixed to the ground.
    Wall((usize, Form)),
}

impl Meeting {
    /// What meets at `site` of the scenario `s`.
    pub fn of_site(s: &Scenario, site: &ContactSite) -> Self {
        let side = |b: usize| (b, s.buildings()[b].structure.form());
        match site.kind {
            SiteKind::Between { left, right } => Meeting::Between([side(left), side(right)]),
            SiteKind::Wall { building, .. } => Meeting::Wall(side(building)),
        }
    }

    /// What meets at `site` of the run summarised in `s` (structures found by name; one not found counts
    /// as a building).
    pub fn of_summary(s: &RunSummary, site: &SiteSummary) -> Self {
        let side = |name: &str| {
            s.buildings
                .iter()
                .position(|b| b.name == name)
                .map_or((usize::MAX, Form::Building), |b| (b, s.buildings[b].form()))
        };
        match &site.place {
            SitePlace::Contact { between } => {
                Meeting::Between([side(&between[0]), side(&between[1])])
            }
            SitePlace::Wall { facing, .. } => Meeting::Wall(side(facing)),
        }
    }

    fn sides(&self) -> &[(usize, Form)] {
        match self {
            Meeting::Between(two) => two,
            Meeting::Wall(one) => std::slice::from_ref(one),
        }
    }
}

/// The words of what met at some sites, for the sentence that says why their impacts deliver another e.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Inside {
    /// What holds the struck masses and keeps acting on them: "the storeys", "the isolator and the
    /// storeys", "the bearings", or several of them.
    pub forces: String,
    /// The struck masses: "floors", "decks", or "floors and decks".
    pub masses: String,
    /// One of them: "floor", "deck", or "floor or deck".
    pub mass: String,
    /// Where they meet: "between buildings", "between decks", "between a building and a deck", "against a
    /// wall", several joined by "or".
    pub contact: String,
    /// How the contact can release them faster than they came: "part the floors faster than they met",
    /// "drive the decks off the wall faster than they struck it", or "part the two sides ...".
    pub part: String,
    /// The same in the past: "parted the floors faster than they met", ...
    pub parted: String,
}

/// The words for the sites `meetings` (at least one).
pub fn inside(meetings: &[Meeting]) -> Inside {
    let sides: Vec<(usize, Form)> = {
        let mut v: Vec<(usize, Form)> = meetings.iter().flat_map(|m| m.sides().to_vec()).collect();
        v.sort_by_key(|s| s.0);
        v.dedup();
        v
    };
    let has = |f: Form| sides.iter().any(|s| s.1 == f);
    let isolators = sides
        .iter()
        .filter(|s| s.1 == Form::IsolatedBuilding)
        .count();
    let mut forces = Vec::new();
    if has(Form::Deck) {
        forces.push("the bearings");
    }
    match isolators {
        0 => {}
        1 => forces.push("the isolator"),
        _ => forces.push("the isolators"),
    }
    if has(Form::Building) || has(Form::IsolatedBuilding) {
        forces.push("the storeys");
    }
    let floors = has(Form::Building) || has(Form::IsolatedBuilding);
    let (masses, mass) = match (floors, has(Form::Deck)) {
        (true, true) => ("floors and decks", "floor or deck"),
        (false, true) => ("decks", "deck"),
        _ => ("floors", "floor"),
    };
    let mut contact: Vec<&str> = Vec::new();
    for m in meetings {
        let words = match m {
            Meeting::Between([a, b]) => match (a.1 == Form::Deck, b.1 == Form::Deck) {
                (true, true) => "between decks",
                (false, false) => "between buildings",
                _ => "between a building and a deck",
            },
            Meeting::Wall(_) => "against a wall",
        };
        if !contact.contains(&words) {
            contact.push(words);
        }
    }
    let walls = meetings.iter().any(|m| matches!(m, Meeting::Wall(_)));
    let pairs = meetings.iter().any(|m| matches!(m, Meeting::Between(_)));
    let (part, parted) = match (pairs, walls) {
        (true, true) => (
            "part the two sides faster than they met".to_string(),
            "parted the two sides faster than they met".to_string(),
        ),
        (false, true) => (
            format!("drive the {masses} off the wall faster than they struck it"),
            format!("drove the {masses} off the wall faster than they struck it"),
        ),
        _ => (
            format!("part the {masses} faster than they met"),
            format!("parted the {masses} faster than they met"),
        ),
    };
    Inside {
        forces: and(&forces),
        masses: masses.to_string(),
        mass: mass.to_string(),
        contact: contact.join(" or "),
        part,
        parted,
    }
}

/// `words` joined as a sentence lists them: "a", "a and b", "a, b and c".
fn and(words: &[&str]) -> String {
    match words {
        [] => String::new(),
        [one] => (*one).to_string(),
        [head @ .., last] => format!("{} and {last}", head.join(", ")),
    }
}

/// What dissipates a run's hysteretic energy, for its label ("storey hysteresis"): "storey", "isolator",
/// "bearing", or several ("isolator and storey"), from what yields: the inelastic storeys above any
/// isolator, the inelastic isolators of buildings, the inelastic bearings of decks. With nothing inelastic,
/// what the run has: "storey", or a bridge's "bearing".
pub fn hysteresis_of(buildings: &[BuildingSummary]) -> String {
    let (mut storey, mut isolator, mut bearing) = (false, false, false);
    for b in buildings {
        for &j in &b.inelastic_storeys {
            match (j, b.form()) {
                (1, Form::Deck) => bearing = true,
                (1, Form::IsolatedBuilding) => isolator = true,
                _ => storey = true,
            }
        }
    }
    if !(storey || isolator || bearing) {
        storey = buildings.iter().any(|b| b.form() != Form::Deck);
        bearing = !storey && !buildings.is_empty();
    }
    let mut words = Vec::new();
    if bearing {
        words.push("bearing");
    }
    if isolator {
        words.push("isolator");
    }
    if storey || words.is_empty() {
        words.push("storey");
    }
    and(&words)
}

/// The note of a site's delivered e in `summary.json`: what it is, and why it differs from the e asked.
pub fn delivered_e_note(meeting: Meeting) -> String {
    let w = inside(&[meeting]);
    format!(
        "separation over approach velocity; the calibration is exact for two free bodies, and, in a contact {}, \
         {}, the damping and other forces on the {} act during each contact (docs/verification.md, \"Impacts \
         inside a run\")",
        w.contact, w.forces, w.masses
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_words_follow_the_structures() {
        let b = |i| (i, Form::Building);
        let iso = |i| (i, Form::IsolatedBuilding);
        let deck = |i| (i, Form::Deck);
        let w = inside(&[Meeting::Between([b(0), b(1)])]);
        assert_eq!(
            (
                w.forces.as_str(),
                w.masses.as_str(),
                w.contact.as_str(),
                w.part.as_str()
            ),
            (
                "the storeys",
                "floors",
                "between buildings",
                "part the floors faster than they met"
            )
        );
        // An isolated building in its moat: two walls, one isolator.
        let w = inside(&[Meeting::Wall(iso(0)), Meeting::Wall(iso(0))]);
        assert_eq!(
            (w.forces.as_str(), w.contact.as_str(), w.part.as_str()),
            (
                "the isolator and the storeys",
                "against a wall",
                "drive the floors off the wall faster than they struck it"
            )
        );
        // A bridge: decks on bearings, joints and abutments.
        let w = inside(&[Meeting::Between([deck(0), deck(1)]), Meeting::Wall(deck(0))]);
        assert_eq!(
            (
                w.forces.as_str(),
                w.masses.as_str(),
                w.contact.as_str(),
                w.part.as_str()
            ),
            (
                "the bearings",
                "decks",
                "between decks or against a wall",
                "part the two sides faster than they met"
            )
        );
        let w = inside(&[Meeting::Between([deck(0), iso(1)]), Meeting::Wall(iso(2))]);
        assert_eq!(w.forces, "the bearings, the isolators and the storeys");
        assert_eq!(w.masses, "floors and decks");
        assert_eq!(w.contact, "between a building and a deck or against a wall");
    }
}
