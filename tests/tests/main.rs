//! The one integration-test binary of rime.

mod bad_input;
mod cli;
mod cost;
mod extremes;
mod fuzz;
mod models;
mod physics;
mod properties;
mod reference;
mod takeaway;
