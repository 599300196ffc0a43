//! The one list of element laws. Adding a law is a file (its type, implementing [`ElementLaw`], and for a
//! device its parameters, implementing [`Device`]) and one line here: the line makes it a variant of
//! [`Law`], dispatched statically, and a device also a `model` of `[[device]]` ([`DeviceLaw`]), with its
//! name for scenario files, messages and outputs.

use super::device::{self, Device, Parameter};
use super::storey;
use super::{
    Affine, Contact, ElementEnergy, ElementLaw, Event, RateGate, Scales, Transition, Watch,
};
use crate::Error;

/// Declares [`Law`] (every law), its [`ElementLaw`] dispatch, and [`DeviceLaw`] (the devices' parameters,
/// by model name).
macro_rules! registry {
    (
        laws { $( $(#[$lm:meta])* $lv:ident($lt:ty), )* }
        devices { $( $(#[$dm:meta])* $dv:ident($dt:ty) = $dn:literal, )* }
    ) => {
        /// Every element law, with its phase: a variant per law type (`element/registry.rs`).
        // A contact carries its prepared law (hundreds of bytes) beside storeys of tens: boxing it would put a
        // pointer chase into every force evaluation, and a run holds only tens of elements.
        #[allow(clippy::large_enum_variant)]
        #[derive(Clone, Debug)]
        pub enum Law {
            $( $(#[$lm])* $lv($lt), )*
            $( $(#[$dm])* $dv($dt), )*
        }

        $( impl From<$lt> for Law {
            fn from(law: $lt) -> Self {
                Law::$lv(law)
            }
        } )*
        $( impl From<$dt> for Law {
            fn from(law: $dt) -> Self {
                Law::$dv(law)
            }
        } )*

        /// Calls `$call` on the law of whichever variant `$law` is.
        macro_rules! dispatch {
            ($law:expr, $l:ident => $call:expr) => {
                match $law {
                    $( Law::$lv($l) => $call, )*
                    $( Law::$dv($l) => $call, )*
                }
            };
        }

        impl ElementLaw for Law {
            fn name(&self) -> &'static str {
                dispatch!(self, l => l.name())
            }
            #[inline]
            fn states(&self) -> usize {
                dispatch!(self, l => l.states())
            }
            fn state_tolerances(&self, scales: &Scales, out: &mut [f64]) {
                dispatch!(self, l => l.state_tolerances(scales, out))
            }
            fn work_states(&self) -> std::ops::Range<usize> {
                dispatch!(self, l => l.work_states())
            }
            // Always: the right-hand side's loop over the elements calls it, and left to itself the compiler
            // has inlined it there in one build and not in the next (8 % of a bridge run).
            #[inline(always)]
            fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
                dispatch!(self, l => l.evaluate(x, v, s, ds))
            }
            // Always, for the same reason: the peaks' and the driver's loops over elements.
            #[inline(always)]
            fn force(&self, x: f64, v: f64, s: &[f64]) -> f64 {
                dispatch!(self, l => l.force(x, v, s))
            }
            #[inline]
            fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
                dispatch!(self, l => l.energy(x, s))
            }
            #[inline]
            fn affine(&self) -> Option<Affine> {
                dispatch!(self, l => l.affine())
            }
            fn constant_force(&self) -> bool {
                dispatch!(self, l => l.constant_force())
            }
            fn affine_rates(&self, a: &Affine, out: &mut [[f64; 3]]) -> bool {
                dispatch!(self, l => l.affine_rates(a, out))
            }
            #[inline]
            fn watched(&self) -> &'static [Watch] {
                dispatch!(self, l => l.watched())
            }
            #[inline]
            fn event_value(&self, ev: Event, x: f64, v: f64, s: &[f64]) -> f64 {
                dispatch!(self, l => l.event_value(ev, x, v, s))
            }
            fn events_read_states(&self) -> bool {
                dispatch!(self, l => l.events_read_states())
            }
            fn apply(
                &mut self,
                ev: Event,
                x: f64,
                v: f64,
                s: &[f64],
                h: f64,
            ) -> Result<Transition, Error> {
                dispatch!(self, l => l.apply(ev, x, v, s, h))
            }
            fn gate(&self) -> Option<&RateGate> {
                dispatch!(self, l => l.gate())
            }
            fn gate_mut(&mut self) -> Option<&mut RateGate> {
                dispatch!(self, l => l.gate_mut())
            }
            #[inline]
            fn rate_event(&self, x: f64, v: f64, s: &[f64]) -> Option<f64> {
                dispatch!(self, l => l.rate_event(x, v, s))
            }
        }

        /// A device's model and parameters, as a `[[device]]` entry gives them (`model = "..."` and the
        /// model's keys, SI units).
        #[derive(Clone, Debug, PartialEq)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        #[cfg_attr(feature = "serde", serde(tag = "model"))]
        #[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
        pub enum DeviceLaw {
            $(
                $(#[$dm])*
                #[cfg_attr(feature = "serde", serde(rename = $dn))]
                $dv(<$dt as Device>::Params),
            )*
        }

        impl DeviceLaw {
            /// Every device model's name, as `model = "..."` takes it.
            pub const NAMES: &'static [&'static str] = &[$($dn),*];

            /// The model's name.
            pub fn name(&self) -> &'static str {
                match self {
                    $( DeviceLaw::$dv(_) => $dn, )*
                }
            }

            /// The device's law, at rest, its parameters checked (an error names the key).
            pub fn law(&self) -> Result<Law, Error> {
                match self {
                    $( DeviceLaw::$dv(p) => <$dt as Device>::from_params(p).map(Law::$dv), )*
                }
            }

            /// The parameters with their keys and units.
            pub fn parameters(&self) -> Vec<Parameter> {
                match self {
                    $( DeviceLaw::$dv(p) => <$dt as Device>::parameters(p), )*
                }
            }
        }
    };
}

registry! {
    laws {
        /// A bilinear storey or isolator.
        Bilinear(storey::Bilinear),
        /// A Bouc–Wen storey or isolator (a friction pendulum too).
        BoucWen(storey::BoucWen),
        /// A contact: impacts between two floors, or a floor and a wall.
        Contact(Contact),
    }
    devices {
        /// A linear spring (also the law of a linear storey or isolator).
        Spring(device::Spring) = "spring",
        /// A linear dashpot.
        Dashpot(device::Dashpot) = "dashpot",
        /// A spring and a dashpot in parallel.
        Kelvin(device::Kelvin) = "kelvin",
        /// A spring and a dashpot in series.
        Maxwell(device::Maxwell) = "maxwell",
        /// A tension-only restrainer with slack.
        Restrainer(device::Restrainer) = "restrainer",
        /// A fluid viscous damper, `F = c |v|^alpha sgn(v)`, alone or in series with a spring.
        FluidViscous(device::FluidViscous) = "fluid-viscous",
    }
}

impl Law {
    /// The law, if it is a contact's (for the recorders of impacts).
    pub fn as_contact(&self) -> Option<&Contact> {
        if let Law::Contact(c) = self {
            Some(c)
        } else {
            None
        }
    }
}
