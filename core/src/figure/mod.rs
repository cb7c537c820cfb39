//! What a figure shows — series, axes, log scales, labels, units, markers, bands, class maps — with
//! no drawing. One description serves every surface: feature `plot` renders it with plotters to SVG
//! and PNG (`render_svg`, `render_png`); the terminal and the web page draw the same data.
//!
//! [`paper`] builds the paper's Figs. 2–4 from the model, and [`experiments`] holds the
//! experimental context (Bridges et al. 1984; Heißelmann et al. 2010; Hill et al. 2015).
//!
//! The module also holds what every figure and every surface writes with: the palette
//! ([`palette`], no features), the number formats ([`format`], `alloc`) and the words ([`words`]:
//! citation, glossary, parameter help), so that figures and command-line output need nothing of
//! the explorer.

#[cfg(feature = "alloc")]
mod description;
#[cfg(feature = "alloc")]
pub use crate::format;
pub mod palette;
pub mod sweep;
pub mod words;
#[cfg(feature = "alloc")]
pub use description::*;

#[cfg(feature = "alloc")]
mod ticks;
#[cfg(feature = "alloc")]
pub use ticks::{Corner, IMAGE_LABELS, Tick, decimal_label};

#[cfg(feature = "plot")]
#[cfg_attr(docsrs, doc(cfg(feature = "plot")))]
mod render;
#[cfg(feature = "plot")]
pub use render::{render_png, render_svg};
