//! The explorer model shared by every surface (terminal, web page, exports).
//!
//! Limits, ranges and their notes are defined here once, so that the terminal explorer, the web page
//! and the subcommands cannot drift apart. Pure functions: no I/O, no clocks.

pub mod frame;
pub mod limits;
pub mod range;
