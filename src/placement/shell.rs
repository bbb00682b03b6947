//! The room's shell: the faces of the scene's bounding box, where its floor, ceiling and
//! outer walls lie. A patch belongs to the shell when its normal is within 8° of an axis,
//! pointing into the box, and each of its vertices lies within [`SLACK`] of the box's face
//! it looks away from (the Cornell box's red wall leans by 0.7°). Every other patch is
//! furniture: blocks, desks, boards, books.

use crate::geometry::{Mesh, Patch};
use glam::DVec3;

/// How far a shell patch's vertices may lie from the bounding box's face, m.
pub const SLACK: f64 = 0.02;

/// The scene's bounding box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shell {
    lo: DVec3,
    hi: DVec3,
}

impl Shell {
    /// The bounding box of `mesh`'s vertices.
    pub fn of(mesh: &Mesh) -> Shell {
        let vertices = mesh.patches.iter().flat_map(|p| p.polygon.vertices().iter());
        let (lo, hi) = vertices.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        Shell { lo, hi }
    }

    /// True when `patch` lies on a face of the box, facing in.
    pub fn holds(&self, patch: &Patch) -> bool {
        (0..3).any(|axis| {
            let along = patch.normal[axis];
            if along.abs() < 0.99 {
                return false;
            }
            let face = if along > 0.0 { self.lo[axis] } else { self.hi[axis] };
            patch.polygon.vertices().iter().all(|v| (v[axis] - face).abs() <= SLACK)
        })
    }
}
