//! The Monte Carlo estimators (`src/trace/`): furnaces, the material sampler, forward
//! against the direct solve, backward against the deterministic image, and the
//! `trace`/`agree`/`compare --photons` commands.

mod backward;
mod cli;
mod daylight;
mod difference;
mod forward;
mod forward_daylight;
mod furnace;
mod probe;
mod sampling;
