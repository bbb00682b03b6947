//! The Monte Carlo estimators (`src/trace/`): furnaces, forward against the direct solve,
//! backward against the deterministic image, the trace/agree/compare commands.

mod forward;
mod furnace;
