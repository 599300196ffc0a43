//! The records built into the library: the 1940 El Centro N-S record, and synthetic records named by
//! their seed. Every caller (scenario files, the command line, Python) asks here what a built-in is.

use super::synthetic::Synthetic;
use super::{Format, Record, Units};

const EL_CENTRO_CSV: &str = include_str!("../../data/elcentro1940_ns.csv");

/// A record built into the library, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    /// `el-centro-1940`: the 1940 El Centro N-S record ([`Record::el_centro_1940`]).
    ElCentro1940,
    /// `synthetic-SEED`: the synthetic motion of [`Synthetic::default`] with that seed.
    Synthetic(u64),
}

impl Builtin {
    /// The names of the built-in records, as messages list them.
    pub const NAMES: &'static str = "el-centro-1940, synthetic-SEED (SEED 0, 1, 2, ...)";

    /// The built-in record called `name`: `el-centro-1940`, or `synthetic-SEED` with SEED a whole number
    /// from 0 to 2^64 - 1 written in digits without leading zeros.
    ///
    /// ```
    /// use pounding::ground_motion::Builtin;
    /// assert_eq!(Builtin::from_name("synthetic-3"), Some(Builtin::Synthetic(3)));
    /// assert_eq!(Builtin::from_name("synthetic-03"), None); // the same record must not have two names
    /// assert_eq!(Builtin::from_name("el-centro-1940").map(|b| b.name()).as_deref(), Some("el-centro-1940"));
    /// ```
    pub fn from_name(name: &str) -> Option<Builtin> {
        if name == "el-centro-1940" {
            return Some(Builtin::ElCentro1940);
        }
        let seed = name.strip_prefix("synthetic-")?;
        // Digits only: "synthetic-+1" or "synthetic-01" would name the same record twice.
        if seed.is_empty()
            || !seed.bytes().all(|b| b.is_ascii_digit())
            || (seed.len() > 1 && seed.starts_with('0'))
        {
            return None;
        }
        seed.parse().ok().map(Builtin::Synthetic)
    }

    /// Its name.
    pub fn name(&self) -> String {
        match self {
            Builtin::ElCentro1940 => "el-centro-1940".into(),
            Builtin::Synthetic(seed) => format!("synthetic-{seed}"),
        }
    }

    /// Why `units` given with this built-in record are refused (it carries its own): one line, for a
    /// scenario file, the command line and Python alike.
    pub fn units_refused(&self, units: Units) -> String {
        format!(
            "units = \"{}\" applies to a record file (file = ...); the built-in record {:?} carries its own: remove units",
            units.name(),
            self.name()
        )
    }

    /// The record.
    pub fn record(&self) -> Option<Record> {
        match self {
            Builtin::ElCentro1940 => Some(Record::el_centro_1940()),
            Builtin::Synthetic(seed) => Synthetic::default().record(&self.name(), *seed).ok(),
        }
    }
}

impl Record {
    /// The 1940 El Centro N-S record shipped with the tool (Chopra's version; see `data/PROVENANCE.md` in
    /// this crate): 1559 samples at 0.02 s from t = 0.02 s, PGA 0.3188 g.
    pub fn el_centro_1940() -> Self {
        // Parsed once per process: a study's every run asks for it (its text parse was 2 % of a two-storey
        // run's time).
        static PARSED: std::sync::OnceLock<Record> = std::sync::OnceLock::new();
        PARSED
            .get_or_init(|| {
                let r = Record::parse("el-centro-1940", EL_CENTRO_CSV, Format::TimeAcc, Units::G)
                    .expect("the built-in record parses");
                // The file adds a row (t = 0, a = 0) for the ground at rest; the record proper starts after it.
                Record::new(
                    r.name(),
                    r.dt(),
                    r.t0() + r.dt(),
                    r.accelerations()[1..].to_vec(),
                )
                .expect("the built-in record is valid")
            })
            .clone()
    }

    /// A built-in record by name ([`Builtin::from_name`]): `el-centro-1940`, or `synthetic-SEED`, the
    /// synthetic motion of [`Synthetic::default`] with that seed (Clough–Penzien noise on firm soil, 20 s at
    /// 0.01 s, PGA 3 m/s^2).
    pub fn builtin(name: &str) -> Option<Self> {
        Builtin::from_name(name)?.record()
    }

    /// The names of the built-in records, as messages list them.
    pub const BUILTINS: &'static str = Builtin::NAMES;
}
