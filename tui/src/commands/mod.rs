//! Subcommands with their own files: argument parsing and rendering (docs/cli.md).

pub mod collision;
pub mod compare;
pub mod data;
pub mod fit;
pub mod stick;
