//! The library-level integration tests of rime (one binary). Tests that run the `rime` binary are
//! in `tui/tests/cli/`, where Cargo builds the binary with them.

mod cost;
mod extremes;
mod fuzz;
mod physics;
mod properties;
mod reference;
mod request;
mod thresholds;
