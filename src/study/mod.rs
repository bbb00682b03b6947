//! Pipelines that return values (`design.md` §6, the study floor): a stored solution made
//! ready to look at, the solve of a case with every method asked for, the study of
//! angular bases, and the agreement with Monte Carlo references. The command line only
//! parses its arguments, calls these and prints what they return.

mod bases;
mod openings;
mod solve;
mod view;
mod warnings;

pub use bases::{BasisRow, BasisStudy, compare_bases};
pub use solve::{Job, MonteCarlo, Solved, StudyError, solve_case};
pub use view::lit_scene;
pub use warnings::physics_warnings;
