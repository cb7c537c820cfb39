//! The one integration-test binary of rime.

mod cli;
mod cost;
mod physics;
mod reference;
