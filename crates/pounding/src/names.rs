//! The one registry of names: every choice a user makes by name (a contact model, a storey law, a tension
//! rule, a side, a record format, ...) is an enum that implements [`Named`], declared once with its names
//! by [`named!`](crate::named). Scenario files (serde), the command line (clap, through the names), Python
//! and "did you mean" all read the same list.

use crate::words;

/// A choice among named values.
pub trait Named: Sized + Copy + 'static {
    /// What the choice is called in messages (`model`, `tension`, `side`).
    const WHAT: &'static str;
    /// Every value, in the order messages list them.
    const ALL: &'static [Self];

    /// The value's name, as scenario files, the command line and outputs write it.
    fn name(self) -> &'static str;

    /// The value called `name`, if any.
    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|v| v.name() == name)
    }

    /// Every name, in order.
    fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|v| v.name()).collect()
    }

    /// The value called `name`, or a one-line message naming it, the names allowed and the closest one:
    /// `"papii" is not allowed: one of hooke, ..., papi, ... (did you mean "papi"?)`.
    fn parse_name(name: &str) -> Result<Self, String> {
        Self::from_name(name).ok_or_else(|| unknown::<Self>(name))
    }
}

/// The message for a `given` name that is none of `T`'s: the closest name first, then the names allowed
/// (a long list cut after about 80 characters, with its count, so that the message stays one short line).
pub fn unknown<T: Named>(given: &str) -> String {
    let names = T::names();
    format!(
        "{} = {} is not allowed{}: one of {}",
        T::WHAT,
        words::quoted(given, 64),
        words::did_you_mean(given, names.iter().copied()),
        words::list(&names, 80),
    )
}

/// Declares an enum whose variants are chosen by name, with [`Named`], `Display`, `FromStr` and, behind
/// the `serde` feature, `Serialize` and `Deserialize` by name (and, behind `schema`, a JSON Schema listing
/// the names).
///
/// ```ignore
/// named! {
///     /// May the contact force become tensile?
///     pub enum Tension: "tension" {
///         /// Follows the law into tension.
///         Allow = "allow",
///         /// Clamped at 0.
///         Clamp = "clamp",
///     }
/// }
/// ```
#[macro_export]
macro_rules! named {
    (
        $(#[$m:meta])*
        pub enum $name:ident : $what:literal {
            $( $(#[$vm:meta])* $var:ident = $s:literal, )*
        }
    ) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name {
            $( $(#[$vm])* $var, )*
        }

        impl $crate::names::Named for $name {
            const WHAT: &'static str = $what;
            const ALL: &'static [Self] = &[$( $name::$var, )*];
            fn name(self) -> &'static str {
                match self {
                    $( $name::$var => $s, )*
                }
            }
        }

        impl $name {
            /// Its name, as scenario files, the command line and outputs write it.
            pub fn name(self) -> &'static str {
                <$name as $crate::names::Named>::name(self)
            }
            /// The value called `name`, if any.
            pub fn from_name(name: &str) -> Option<Self> {
                <$name as $crate::names::Named>::from_name(name)
            }
        }

        $crate::named_impls!($name);
    };
}

/// `Display`, `FromStr`, serde and JSON Schema of a [`Named`] type (for types whose [`Named`] is written
/// by hand, such as the catalogue of contact models).
#[macro_export]
macro_rules! named_impls {
    ($name:ident) => {
        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str($crate::names::Named::name(*self))
            }
        }

        impl std::str::FromStr for $name {
            type Err = String;
            fn from_str(s: &str) -> Result<Self, String> {
                <$name as $crate::names::Named>::parse_name(s)
            }
        }

        #[cfg(feature = "serde")]
        impl serde::Serialize for $name {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str($crate::names::Named::name(*self))
            }
        }

        #[cfg(feature = "serde")]
        impl<'de> serde::Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let s = <std::borrow::Cow<'de, str> as serde::Deserialize>::deserialize(d)?;
                <$name as $crate::names::Named>::parse_name(&s).map_err(serde::de::Error::custom)
            }
        }

        #[cfg(feature = "schema")]
        impl schemars::JsonSchema for $name {
            fn schema_name() -> std::borrow::Cow<'static, str> {
                stringify!($name).into()
            }
            fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
                let names = <$name as $crate::names::Named>::names();
                schemars::json_schema!({ "type": "string", "enum": names })
            }
        }
    };
}
