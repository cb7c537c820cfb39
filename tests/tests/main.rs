//! The one integration-test binary of rime.

mod physics;
