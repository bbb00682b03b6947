//! Where a model's size is set, for a refusal as too large for memory (issue 37, point
//! 7): the case file and its `[discretization]` keys, or the options that overrode them,
//! each number quoted in exponent form when huge or tiny.

use super::options::Discretize;
use std::path::Path;
use ugo::scene::{KernelKind, Scene, number};
use ugo::study::StudyError;

/// `case` and the keys that set its size: `patch_size`, and `root_size` for the hierarchy.
pub fn sized_by(case: &Path, d: &Discretize, scene: &Scene) -> String {
    let s = &scene.discretization;
    let mut keys = vec![key(d.patch_size, "patch_size", s.patch_size)];
    if let KernelKind::Hierarchical(h) = s.kernel {
        keys.push(key(d.root_size, "root_size", h.root_size));
    }
    format!("{} at {}", case.display(), keys.join(", "))
}

fn key(flag: Option<f64>, name: &str, value: f64) -> String {
    match flag {
        Some(_) => format!("--{} {} m", name.replace('_', "-"), number(value)),
        None => format!("[discretization] {name} = {} m", number(value)),
    }
}

/// `e`, preceded by where the size is set when it is a refusal as too large.
pub fn located(e: StudyError, case: &Path, d: &Discretize, scene: &Scene) -> anyhow::Error {
    match e.too_large() {
        true => anyhow::Error::from(e).context(sized_by(case, d, scene)),
        false => e.into(),
    }
}
