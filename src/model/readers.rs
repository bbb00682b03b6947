//! The readings that steer the hierarchy's refinement (`docs/design.md` (3b.3b)): every
//! point probe and grid point as a receiver, with the luminaires' direct light on it, and
//! its direct sensitivity to each leaf's light, `∂E_k/∂x_{l,m} = π F_{k→l} V_{k,l}` (the
//! exact point-to-polygon factor, one ray to the leaf's centroid for its visibility, the
//! cell `m` that faces the point), divided by the reading `E_k` so that each reading counts
//! by its relative error, and the largest over the readings kept per unknown: a sum would
//! grow with a grid's resolution, where neighbouring points read the same leaves.

use crate::directions::DirectionSet;
use crate::geometry::{Frame, Mesh};
use crate::luminaire::{Source, arriving_at};
use crate::scene::{ProbeKind, Scene};
use crate::sky::READING;
use crate::transfer::contour::point_to_patch;
use crate::visibility::{NO_FACE, Visibility, standoff};
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// A receiver whose reading steers the refinement.
#[derive(Debug, Clone, Copy)]
pub struct Reader {
    point: DVec3,
    normal: DVec3,
    /// The luminaires' direct illuminance on it, lx.
    direct: f64,
}

/// The scene's point probes and grid points as readers, with the `sources`' direct light.
pub fn readers(scene: &Scene, sources: &[Source], visibility: &Visibility, directions: &DirectionSet) -> Vec<Reader> {
    let probes = scene.probes.iter().filter(|p| p.kind == ProbeKind::Point).map(|p| (p.position, p.normal));
    let grids = scene.grids.iter().flat_map(|g| g.points().into_iter().map(move |p| (p, g.normal)));
    let at: Vec<(DVec3, DVec3)> = probes.chain(grids).collect();
    at.into_par_iter()
        .map(|(point, normal)| {
            let frame = Frame::around(normal);
            let light = arriving_at(sources, visibility, directions, point, &frame, NO_FACE, READING);
            Reader { point, normal, direct: PI * light.iter().sum::<f64>() }
        })
        .collect()
}

/// Each unknown's direct share of the readings on the leaves `leaves` with the field `x`
/// (`x[leaf·K + m]`): `max_k (∂E_k/∂x)/E_k`.
pub fn direct_importance(
    readers: &[Reader],
    leaves: &Mesh,
    visibility: &Visibility,
    directions: &DirectionSet,
    x: &[f64],
) -> Vec<f64> {
    let lift = standoff(leaves);
    // a few readers a task: each task folds into its own vector of every unknown
    let per_task = readers.len().div_ceil(4 * rayon::current_num_threads()).max(1);
    readers
        .par_iter()
        .with_min_len(per_task)
        .fold(
            || vec![0.0_f64; x.len()],
            |mut v, reader| {
                let seen = sensitivity(reader, leaves, visibility, directions, lift);
                let reading = reader.direct + seen.iter().map(|&(i, s)| s * x[i]).sum::<f64>();
                if reading > 0.0 {
                    seen.iter().for_each(|&(i, s)| v[i] = v[i].max(s / reading));
                }
                v
            },
        )
        .reduce(
            || vec![0.0_f64; x.len()],
            |mut a, b| {
                a.iter_mut().zip(&b).for_each(|(a, b)| *a = (*a).max(*b));
                a
            },
        )
}

/// `(unknown, π F V)` for every leaf the reader sees.
fn sensitivity(
    reader: &Reader,
    leaves: &Mesh,
    visibility: &Visibility,
    directions: &DirectionSet,
    lift: f64,
) -> Vec<(usize, f64)> {
    let k = directions.len();
    let eye = reader.point + reader.normal * lift;
    let mut out = Vec::new();
    for (l, patch) in leaves.patches.iter().enumerate() {
        let towards = reader.point - patch.centroid;
        if towards.dot(patch.normal) <= 0.0 {
            continue;
        }
        let factor = point_to_patch(reader.point, reader.normal, patch);
        if factor <= 0.0 || !visibility.visible(eye, patch.centroid + patch.normal * lift, [NO_FACE, patch.face]) {
            continue;
        }
        let cell = if k == 1 { 0 } else { directions.lookup(patch.frame().local(towards.normalize())) };
        out.push((l * k + cell, PI * factor));
    }
    out
}
