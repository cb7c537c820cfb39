//! # rime-core
//!
//! Contact models for slow collisions of icy grains, after Hertzsch (2002), *A model for surface
//! effects in slow collisions of icy grains*, Planet. Space Sci. 50, 1387–1397 ("Eq. N" below is that
//! paper's equation N). Decisions where the paper is ambiguous or wrong are documented in
//! `docs/physics.md` of the repository.
//!
//! * [`Scene`] — grains, bulk material and optional effects (layer, adhesion, friction).
//! * [`Contact`] — constants derived once from a scene; [`Contact::normal`] gives ε_N (Eq. (4)–(17)).
//! * [`ode`] — our Dormand–Prince 5(4) stepper with dense output and event location.
//! * [`atlas`] — published ice measurements with provenance; [`stick`] — sticking thresholds;
//!   `fit_scene` (feature `alloc`) — scene parameters fitted to data, with standard errors.
//!
//! ```
//! use rime_core::{Accuracy, Contact, Preset, Status};
//!
//! let scene = Preset::IceFrost.scene();
//! let contact = Contact::new(&scene)?;
//! // Eq. (10): g_s = √R_eff η* D^(3/2) / m_eff ≈ 6.6 µm/s for this preset.
//! let slow = contact.normal(1e-6, Accuracy::Precise)?;
//! assert_eq!(slow.status, Status::StuckInLayer);
//! let fast = contact.normal(1e-2, Accuracy::Precise)?;
//! assert!(fast.eps > 0.0 && fast.eps < 1.0);
//! # Ok::<(), rime_core::Error>(())
//! ```
//!
//! The crate is `#![no_std]` (its error implements `core::error::Error`); feature `std`
//! (default) adds the platform's libm, `alloc` adds the `Vec` helpers, `serde` the JSON form of
//! scenes, `explorer` (needs only `alloc`) the explorer model
//! shared by the terminal and the web page, `plot` (needs `std`) rendering of figures with plotters,
//! `json` (needs `std`) what the web page's binding does with JSON text (`explorer::page`).

#![no_std]
// `!(x > 0.0)` deliberately treats NaN as invalid; index loops mirror the formulas they implement.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

pub mod accuracy;
pub mod analytic;
pub mod atlas;
pub mod batch;
#[cfg(feature = "alloc")]
pub mod collision;
pub mod contact;
pub mod dem;
pub mod error;
pub mod explorer;
pub mod figure;
pub mod fit;
#[cfg(feature = "alloc")]
pub mod fit_scene;
pub mod kinematics;
pub mod limits;
mod math;
pub mod merge;
pub mod models;
pub mod normal;
pub mod numerics;
pub mod ode;
pub mod params;
pub mod ring;
#[cfg(feature = "alloc")]
pub mod ring_sizes;
pub mod scene;
pub mod stick;
pub mod sweep;
pub mod tangential;
pub mod tidal;
pub mod units;
#[cfg(all(feature = "serde", feature = "alloc"))]
pub mod wire;
#[cfg(feature = "json")]
pub mod wire_read;

pub use accuracy::Accuracy;
pub use contact::Contact;
pub use error::{Error, Result};
pub use kinematics::GrainState;
/// The dimensionless master curve of Eq. (4) and its generated Chebyshev tables (they live with the
/// viscoelastic model, [`normal::viscoelastic::master`]).
pub use normal::viscoelastic::master;
pub use normal::{Normal, Status};
pub use scene::{
    Adhesion, AdhesionModulus, Bulk, ContactEnd, Damping, DampingFormula, Friction, Grains, JkrEnd,
    Layer, LayerReading, Plasticity, Preset, Scene, SlidingLaw, Viscosities,
};
pub use tangential::{StickClass, Tangential};
pub use tidal::{Tidal, TidalInput};
