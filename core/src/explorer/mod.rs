//! The explorer model shared by every surface (terminal, web page, exports).
//!
//! Limits, ranges and their notes are defined here once, so that the terminal explorer, the web page
//! and the subcommands cannot drift apart. Pure functions: no I/O, no clocks.
//!
//! The palette ([`palette`]) needs nothing and number formatting ([`format`]) needs `alloc`, so
//! that figures and command-line output can use them without the `explorer` feature; the limits
//! and range policy come with `explorer`; the web page's binding logic (JSON text in, the wire out:
//! [`page`], [`session`], [`catalogue`], [`share`]) with `json`.

#[cfg(feature = "json")]
pub mod catalogue;
#[cfg(feature = "explorer")]
pub mod collision_rows;
#[cfg(feature = "explorer")]
pub mod figures;
#[cfg(feature = "alloc")]
pub use crate::format;
#[cfg(feature = "explorer")]
pub mod frame;
pub use crate::figure::words as help;
#[cfg(feature = "json")]
pub mod json_path;
#[cfg(feature = "explorer")]
pub mod limits;
#[cfg(feature = "json")]
pub mod page;
pub use crate::figure::palette;
#[cfg(feature = "explorer")]
pub mod range;
#[cfg(feature = "explorer")]
pub mod records;
#[cfg(feature = "explorer")]
pub mod request;
#[cfg(feature = "explorer")]
pub mod ring;
#[cfg(feature = "json")]
pub mod session;
#[cfg(feature = "json")]
pub mod share;
#[cfg(feature = "explorer")]
pub mod thresholds;
#[cfg(feature = "explorer")]
pub mod tidal;
#[cfg(feature = "explorer")]
pub mod warning;
#[cfg(all(feature = "serde", feature = "alloc"))]
pub use crate::wire;
