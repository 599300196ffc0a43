//! How a record's text is read: the units of its accelerations and its format.

use crate::Error;

/// Units of the accelerations in a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Units {
    /// Multiples of standard gravity, 9.80665 m/s^2.
    G,
    /// m/s^2.
    MPerS2,
    /// cm/s^2 (gal): 0.01 m/s^2.
    CmPerS2,
    /// mm/s^2: 0.001 m/s^2.
    MmPerS2,
}

impl Units {
    /// The spellings [`Units::parse`] accepts, as messages list them.
    pub const ALLOWED: &'static str =
        "one of g, m/s2 (or m/s^2), cm/s2 (or cm/s^2, gal), mm/s2 (or mm/s^2)";

    /// The factor to m/s^2.
    pub fn to_m_per_s2(self) -> f64 {
        match self {
            Units::G => crate::units::STANDARD_GRAVITY,
            Units::MPerS2 => 1.0,
            Units::CmPerS2 => 0.01,
            Units::MmPerS2 => 0.001,
        }
    }

    /// The units called `name`: `g`; `m/s2` or `m/s^2`; `cm/s2`, `cm/s^2` or `gal`; `mm/s2` or `mm/s^2`
    /// (any case, surrounding spaces ignored). The one reading of a units name: scenario files
    /// (`units = "gal"`) and the command line (`--units gal`) both use it. Anything else is
    /// [`Error::Choice`] naming `units`, the value and the spellings allowed.
    ///
    /// ```
    /// use pounding::ground_motion::Units;
    /// assert_eq!(Units::parse("gal")?, Units::CmPerS2);
    /// assert_eq!("m/s^2".parse::<Units>()?, Units::MPerS2);
    /// let e = Units::parse("m/s").unwrap_err().to_string();
    /// assert_eq!(e, r#"units = "m/s" is not allowed: one of g, m/s2 (or m/s^2), cm/s2 (or cm/s^2, gal), mm/s2 (or mm/s^2)"#);
    /// # Ok::<(), pounding::Error>(())
    /// ```
    pub fn parse(name: &str) -> Result<Units, Error> {
        match name.trim().to_ascii_lowercase().as_str() {
            "g" => Ok(Units::G),
            "m/s2" | "m/s^2" => Ok(Units::MPerS2),
            "cm/s2" | "cm/s^2" | "gal" => Ok(Units::CmPerS2),
            "mm/s2" | "mm/s^2" => Ok(Units::MmPerS2),
            _ => Err(Error::Choice {
                name: "units",
                value: format!("{name:?}"),
                allowed: Self::ALLOWED.into(),
            }),
        }
    }

    /// The name the tool prints: `g`, `m/s^2`, `cm/s^2` or `mm/s^2`.
    pub fn name(self) -> &'static str {
        match self {
            Units::G => "g",
            Units::MPerS2 => "m/s^2",
            Units::CmPerS2 => "cm/s^2",
            Units::MmPerS2 => "mm/s^2",
        }
    }
}

impl std::str::FromStr for Units {
    type Err = Error;
    /// [`Units::parse`].
    fn from_str(s: &str) -> Result<Self, Error> {
        Units::parse(s)
    }
}

impl std::fmt::Display for Units {
    /// [`Units::name`].
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A text record that could not be read: the 1-based line and what is wrong.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("line {line}: {message}")]
pub struct ParseError {
    /// 1-based line number (0 if it concerns the whole file).
    pub line: usize,
    /// What is wrong, and what is expected.
    pub message: String,
}

/// Text formats of ground-motion records.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Format {
    /// PEER AT2: header with NPTS and DT, then values.
    At2,
    /// Two columns: time (s) and acceleration; uniform steps.
    TimeAcc,
    /// Acceleration values only, with the given time step (s).
    Values {
        /// Time step, s.
        dt: f64,
    },
}

#[cfg(feature = "serde")]
impl serde::Serialize for Units {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

/// Units are read by [`Units::parse`], whatever spelling a file uses (`gal`, `m/s^2`, ...).
#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for Units {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = <std::borrow::Cow<'de, str> as serde::Deserialize>::deserialize(d)?;
        Units::parse(&s).map_err(serde::de::Error::custom)
    }
}

/// Units are written as a name [`Units::parse`] reads.
#[cfg(feature = "schema")]
impl schemars::JsonSchema for Units {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "Units".into()
    }
    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        schemars::json_schema!({
            "type": "string",
            "description": "Units of the accelerations: g, m/s2 (or m/s^2), cm/s2 (or cm/s^2, gal), mm/s2 (or mm/s^2), any case"
        })
    }
}
