//! Numerical methods shared by the models and the fits: the user's accuracy levels, the adaptive
//! integrator, one Levenberg–Marquardt loop, and the elementary functions every surface shares.

pub mod accuracy;
pub mod grid;
pub mod lm;
pub(crate) mod math;
pub mod ode;
