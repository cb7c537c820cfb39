//! Measured data: the atlas of laboratory collisions and material properties, each entry with its
//! source.

pub mod atlas;
