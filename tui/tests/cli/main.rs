//! The command line's test binary: every test that runs the `rime` binary lives here, so that Cargo
//! builds the binary under test with the tests themselves (`CARGO_BIN_EXE_rime`) and no test runs
//! `cargo build`. Library-level tests are in `tests/` (the `rime-tests` crate).

// Test code: a failed unwrap is a failed test (the workspace denies these in library code only;
// clippy's allow-*-in-tests does not reach the helpers of an integration test).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod bad_input;
mod batch;
mod bin;
mod cli;
mod cli_usability;
mod collision;
mod exit_codes;
mod explorer_model;
mod exported;
mod issue_37;
mod issue_38;
mod issue_39;
mod lammps;
mod measured;
mod models;
mod silent_numbers;
mod takeaway;
