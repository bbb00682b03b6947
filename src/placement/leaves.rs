//! The kind of place each leaf (patch) of a mesh lies in, for the field's comparison leaf
//! by leaf (issue 34, point 2; `ugo agree`): the leaves are classed as the hard probes are
//! placed (`place.rs`), from what their centroid sees around it:
//!
//! * **contact**: a concave edge of which one face is furniture (not the room's shell)
//!   lies within the leaf's diameter or [`NEAR`], whichever is larger;
//! * **edge**: a concave edge of the shell lies that near;
//! * **umbra**: none of the direct light of the sources in front of it arrives
//!   (`lights.rs`, from the centroid);
//! * **penumbra**: part of it arrives (2 to 98 %);
//! * **open**: the rest.
//!
//! Leaves that emit, or that no light can reach (`exposed` 0), or inside a solid, have no
//! class.

use super::around::{Spot, look};
use super::lights::lit;
use super::shell::Shell;
use super::sight::Sight;
use crate::luminaire::Source;
use crate::random::Rng;
use crate::trace::World;
use rayon::prelude::*;

/// A leaf within this distance of a concave edge (or within its own diameter) is near it, m.
pub const NEAR: f64 = 0.05;

/// Where a leaf lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Place {
    /// Near a concave edge with furniture.
    Contact,
    /// Near a concave edge of the room's shell.
    Edge,
    /// No direct light arrives.
    Umbra,
    /// Part of the direct light arrives.
    Penumbra,
    /// Away from edges, lit.
    Open,
}

impl Place {
    /// Every place, in the order of the output.
    pub const ALL: [Place; 5] = [Place::Contact, Place::Edge, Place::Umbra, Place::Penumbra, Place::Open];

    /// Its name in the output.
    pub fn name(&self) -> &'static str {
        match self {
            Place::Contact => "contact",
            Place::Edge => "edge",
            Place::Umbra => "umbra",
            Place::Penumbra => "penumbra",
            Place::Open => "open",
        }
    }
}

/// The place of every patch of `world`'s mesh lit by `sources` (and its emitters); `None`
/// for those without one.
pub fn places(world: &World, sources: &[Source]) -> Vec<Option<Place>> {
    let (sight, shell) = (Sight::new(world), Shell::of(&world.mesh));
    let mesh = &world.mesh;
    (0..mesh.len())
        .into_par_iter()
        .map(|i| {
            let patch = &mesh.patches[i];
            if mesh.emission[i] > 0.0 || patch.exposed <= 0.0 {
                return None;
            }
            let spot = Spot {
                patch: i,
                point: patch.centroid,
                frame: patch.frame(),
                face: patch.face,
                shell: shell.holds(patch),
            };
            let around = look(&sight, &shell, &spot, 0.0);
            if around.inside() {
                return None;
            }
            let near = patch.polygon.diameter().max(NEAR);
            let mut walls = around.walls_within(near);
            if let Some(wall) = walls.next() {
                let furniture = !(wall.shell && spot.shell) || walls.any(|w| !(w.shell && spot.shell));
                return Some(if furniture { Place::Contact } else { Place::Edge });
            }
            let share =
                lit(world, sources, spot.probe(), spot.normal(), spot.face, &mut Rng::stream(0, i as u64)).share();
            Some(match share {
                Some(s) if s < 0.02 => Place::Umbra,
                Some(s) if s < 0.98 => Place::Penumbra,
                _ => Place::Open,
            })
        })
        .collect()
}
