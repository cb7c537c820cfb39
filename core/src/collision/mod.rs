//! Inside one collision: the time course ξ(t), ξ'(t), the normal force F(t), the phases, and the
//! energy ledger (docs/physics.md#collision).
//!
//! The trajectory is the one the ε_N of [`Contact::normal`](crate::Contact::normal) comes from: the same integrators
//! (`normal::viscoelastic`, `normal::layer`) hand their dense output to a recorder, and closed-form
//! phases (the offset reading's crushing, Eq. (9); the literal reading's coast and way out through
//! the layer) are sampled from their closed forms. Levels served by a table (fast, precise)
//! integrate live at the level's tolerance (rtol 1e-9, 1e-13) for the trajectory; `t_c`, `xi_max`,
//! `eps_n` and `status` are [`Contact::normal`](crate::Contact::normal)'s own. Sampling costs in proportion to the points
//! asked; every ledger term is a quadrature of its own force over the trajectory.
//!
//! Units are SI; ξ' > 0 while the grains approach; F > 0 pushes them apart.
//!
//! The kinematics of the two grains in three dimensions (the relative surface velocity of Eq. (2),
//! applying ε_N and ε_T by one impulse) are in [`kinematics`]; the time course needs feature `alloc`.

pub mod kinematics;
#[cfg(feature = "alloc")]
mod time_course;
#[cfg(feature = "alloc")]
pub use time_course::*;
