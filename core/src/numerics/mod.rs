//! Numerical methods shared by the models and the fits.

pub mod lm;
