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

// The tree by concern: the scene's input side; the pair's laws (normal, tangential, other
// models); one collision; numerics; fits; measured data; what the law does elsewhere; figures;
// the explorer shared by every surface (feature `explorer`); the wire to the web page.
pub mod applications;
pub mod collision;
pub mod data;
pub mod error;
#[cfg(feature = "explorer")]
pub mod explorer;
pub mod figure;
pub mod fit;
#[cfg(feature = "alloc")]
pub mod format;
pub mod models;
pub mod normal;
pub mod numerics;
pub mod scene;
pub mod tangential;
#[cfg(all(feature = "serde", feature = "alloc"))]
pub mod wire;
#[cfg(feature = "json")]
pub mod wire_read;

// The paths the modules had before they moved into folders (issue 36) keep working.
#[doc(no_inline)]
pub use applications::{dem, merge, ring, stick, tidal};
#[cfg(feature = "alloc")]
#[doc(no_inline)]
pub use applications::{kernel, ring_sizes};
#[doc(no_inline)]
pub use collision::kinematics;
#[doc(no_inline)]
pub use data::atlas;
#[doc(no_inline)]
pub use figure::sweep;
#[cfg(feature = "alloc")]
#[doc(no_inline)]
pub use fit::scene as fit_scene;
#[doc(no_inline)]
pub use normal::{analytic, batch};
#[doc(no_inline)]
pub use numerics::{accuracy, ode};
#[doc(no_inline)]
pub use scene::{contact, limits, params, units};

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
