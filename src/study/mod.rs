//! Pipelines that return values (`docs/design.md` §6, the study floor): a stored solution made
//! ready to look at, the solve of a case with every method asked for, its light scenes by
//! superposition, the study of angular bases, the convergence rates a spectrum predicts,
//! the agreement with Monte Carlo references, and the measurements of `ugo bench`
//! ([`bench`]). The command line only parses its arguments, calls these and prints what
//! they return.

mod after_solve;
mod bases;
pub mod bench;
mod daylight_alone;
mod error;
mod grid_points;
mod group_light;
mod kernel;
mod light_scenes;
mod mirror_cells;
mod near;
mod openings;
mod readout_error;
mod solve;
mod spectrum;
mod view;
mod warnings;

pub use after_solve::read_out_solved;
pub use bases::{BasisRow, BasisStudy, compare_bases};
pub use error::StudyError;
pub use kernel::{KernelError, model_with_kernel};
pub use light_scenes::{GroupSolves, dimmed, lit_light_scene, solve_light_scenes};
pub use readout_error::ReadoutError;
pub use solve::{Job, solve_case};
pub use spectrum::{Rate, chebyshev_rate, measured_rate, rates};
pub use view::{lit_scene, lit_scene_with};
pub use warnings::physics_warnings;
