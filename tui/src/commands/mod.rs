//! Subcommand bodies, one file each.

pub mod compare;
