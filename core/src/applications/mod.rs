//! What the law does elsewhere: in a planetary ring ([`ring`], [`ring_sizes`]), in a dust code
//! ([`stick`], [`kernel`] for every pair of sizes), near a planet ([`tidal`]), and inside the codes that simulate many grains
//! ([`dem`] for LAMMPS, [`merge`] for REBOUND's collision handler).

pub mod dem;
#[cfg(feature = "alloc")]
pub mod kernel;
pub mod merge;
pub mod ring;
#[cfg(feature = "alloc")]
pub mod ring_sizes;
pub mod stick;
pub mod tidal;
