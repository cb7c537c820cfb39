//! One file per subcommand: its body (argument checks beyond crate::cli, computation, rendering);
//! crate::main only parses and dispatches. The contract is docs/cli.md.

pub mod bench;
pub mod collision;
pub mod compare;
pub mod curve;
pub mod data;
pub mod eps;
pub mod explore;
pub mod export;
pub mod figures;
pub mod fit;
pub mod help;
pub mod kernel;
pub mod lammps;
pub mod map;
pub mod ring;
pub mod scene;
pub mod stick;
pub mod tangential;
pub mod tidal;
