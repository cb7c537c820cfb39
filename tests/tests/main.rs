//! The one integration-test binary of rime.

mod bad_input;
mod batch;
mod cli;
mod cli_usability;
mod collision;
mod cost;
mod explorer_model;
mod exported;
mod extremes;
mod fuzz;
mod measured;
mod models;
mod physics;
mod properties;
mod reference;
mod takeaway;
mod thresholds;
