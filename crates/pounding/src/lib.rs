//! # pounding
//!
//! Contact force models for collisions between bodies and earthquake-induced pounding between adjacent
//! structures, with exact calibration of their damping and event-located single-impact analysis.
//!
//! Units are SI throughout: m, s, kg, N; ground accelerations in m/s^2; a contact stiffness `k` of exponent
//! `n` is in N/m^n.
//!
//! ## Two buildings pounding under El Centro 1940
//!
//! A 3-storey and a 5-storey shear building 10 mm apart, their floors at the same height linked by contact
//! elements of Papi & Toopchi-Nezhad (2022) (`papi`, restitution `e = 0.65`):
//!
//! ```
//! use pounding::analysis::{Building, LinkSpec, Scenario};
//! use pounding::contact::{ContactModel, Model};
//! use pounding::ground_motion::Record;
//! use pounding::structure::ShearBuilding;
//!
//! let low = ShearBuilding::builder()
//!     .masses([4.0e5, 4.0e5, 3.5e5]) // kg, floor 1 upwards
//!     .stiffnesses([6.0e8, 5.0e8, 4.0e8]) // N/m, storey 1 upwards
//!     .heights([3.0; 3]) // m
//!     .damping_ratio(0.05)
//!     .build()?;
//! let tall = ShearBuilding::builder()
//!     .masses([3.0e5; 5])
//!     .stiffnesses([2.0e8, 1.8e8, 1.6e8, 1.4e8, 1.2e8])
//!     .heights([3.0; 5])
//!     .build()?; // damping ratio 0.05 unless set
//! let row = vec![
//!     Building { name: "low".into(), structure: low },
//!     Building { name: "tall".into(), structure: tall },
//! ];
//! let scenario = Scenario::new(row, Record::el_centro_1940())?
//!     .with_duration(3.0)? // s (the whole record is 31.2 s)
//!     .with_contact(LinkSpec {
//!         between: ["low".into(), "tall".into()],
//!         gap: 0.01, // m, at rest
//!         floors: None, // every pair of floors at the same height: (1, 1), (2, 2), (3, 3)
//!         contact: ContactModel::new(Model::Papi, 2.0e9, 0.65)?, // k in N/m, e
//!         bumper: None,
//!         seat: None,
//!     })?;
//! let results = scenario.run()?;
//!
//! let roof = results.buildings[1].peak_displacement[4]; // m, tall building's roof, relative to the ground
//! let site = &results.sites[0]; // the contact between "low" and "tall"
//! println!("roof {roof:.3} m, {} impacts, peak force {:.3e} N", site.impacts, site.peak_force);
//! assert!(site.impacts > 0 && site.peak_force > 0.0);
//! assert_eq!(site.impacts, results.impacts.len()); // each impact is listed in `results.impacts`
//! assert!(results.energy.relative_error < 1e-4); // input = kinetic + strain + damping + contact
//! # Ok::<(), pounding::Error>(())
//! ```
//!
//! A recorded ground motion is read from a file's text in one call; the format (PEER AT2 by its header,
//! else two columns) and the units (those the AT2 header states, else g) are found from the text:
//! `Record::read("RSN6_IMPVALL.I_I-ELC180", &std::fs::read_to_string(path)?, None, None)?`
//! ([`ground_motion::Record::read`]; give `Some(Format::..)` or `Some(Units::..)` to set them).
//!
//! ## Where to read more
//!
//! In the repository's `docs/` folder: `docs/contact-models.md` (the models, their damping formulas and
//! sources, and `#5-choosing-the-contact-stiffness`), `docs/scenarios.md` (scenario files: the schema of
//! `pounding::scenario`, behind the `serde` feature, and how record files are read) and
//! `docs/verification.md` (what the numbers are checked against: exact solutions, convergence, OpenSees).
//!
//! ## Modules
//!
//! - [`contact`]: the catalogue of models, their damping formulas and exact calibration, including the
//!   model of Papi & Toopchi-Nezhad (2022).
//! - [`impact`]: one impact (two bodies, or a ball dropped on a slab), integrated with located events, and
//!   the exact relations it must agree with.
//! - [`element`]: everything that adds a force: storeys (linear, bilinear, Bouc–Wen) and contacts.
//! - [`engine`]: degrees of freedom, elements and the one driver that locates every event.
//! - [`integrate`]: the adaptive Dormand–Prince stepper with dense output and Brent's root finder.
//! - [`ground_motion`]: records (AT2, time/acceleration, values; built-in El Centro 1940), PGA/PGV/PGD.
//! - [`structure`]: lumped-mass shear buildings, their modes and Rayleigh damping.
//! - [`analysis`]: time-history analysis of pounding between adjacent buildings under a ground motion.
//! - [`separation`]: the separation neighbours need, from a run without contact, and the code rules.
//! - [`fragility`]: lognormal fragility functions fitted to the runs of a study.
//! - [`limits`]: the sizes the library accepts.
//! - [`paper`]: the reproduction of the comparison in Papi & Toopchi-Nezhad (2022) (its Table 1).
//!
//! The library does no file or terminal I/O; the `pounding` command-line tool does.

pub(crate) mod error;

pub mod analysis;
pub mod calibration;
pub mod contact;
pub mod element;
pub mod engine;
pub mod fit;
pub mod fragility;
pub mod ground_motion;
pub mod impact;
pub mod integrate;
pub mod limits;
pub mod names;
pub mod paper;
#[cfg(feature = "serde")]
pub mod scenario;
pub mod separation;
pub mod structure;
pub mod units;
pub mod words;

pub use error::Error;
