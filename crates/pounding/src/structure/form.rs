//! What a structure is, for the words that name it: a building, an isolated building, or a deck on its
//! bearings. The engine treats them alike (floors on storeys); the outputs name them apart.

/// What a structure of a scenario is: every one is a row of floors on storeys, and the words for its parts
/// follow what it models.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// Storeys on a fixed base.
    Building,
    /// Storeys on an isolator (storey 1 of the files is the isolator; floor 1 the base slab).
    IsolatedBuilding,
    /// One mass on an isolator and nothing above it: a bridge deck (or span) on its bearings.
    Deck,
}

impl Form {
    /// The form of a structure of `storeys` storeys (an isolator counted as storey 1 if `isolated`).
    pub fn of(isolated: bool, storeys: usize) -> Self {
        match (isolated, storeys) {
            (false, _) => Form::Building,
            (true, 1) => Form::Deck,
            (true, _) => Form::IsolatedBuilding,
        }
    }

    /// The structure's noun: "building" or "deck".
    pub fn noun(self) -> &'static str {
        match self {
            Form::Building | Form::IsolatedBuilding => "building",
            Form::Deck => "deck",
        }
    }

    /// The noun of its isolator: "isolator", or a deck's "bearings".
    pub fn isolator_noun(self) -> &'static str {
        match self {
            Form::Building | Form::IsolatedBuilding => "isolator",
            Form::Deck => "bearings",
        }
    }
}
