//! A probe in the near field of a patch (issue 14; `docs/hierarchy.md`, "The floor probe at
//! the short block's foot"): a probe's reading gathers every patch's luminance, constant
//! over the patch (`readout::gather`, `docs/design.md` §5), with the exact factor of each. From a
//! distance `d` below [`NEAR`] of the patch's size `D` the probe sees mostly the part of
//! the patch nearest to it, while the value it reads is the patch's mean. Where the light
//! on the patch varies (at a contact, along a shadow) that is an error of several per cent:
//! the Cornell box's floor probe,
//! 1 cm in front of a block whose lowest leaves are 2–6 cm across, reads 2.4 % high with
//! every patch of the uniform 2.5 cm mesh right (forward Monte Carlo), and the hierarchy
//! at its defaults 2.5 %. A point sensor's and a luminance meter's reading is corrected
//! there (`readout::correction`, `docs/design.md` (5.4)); the warning stays, because the
//! correction gathers from the same field and cannot mend a patch whose mean is wrong.
//! Warned, naming the nearest such patch, for the first few such probes; the others
//! counted in one warning.

use crate::io::Warning;
use crate::model::Model;
use crate::scene::{ProbeKind, Scene};
use glam::DVec3;

/// Distance below which a patch is in a probe's near field, as a share of its diameter.
/// Measured on the Cornell box's floor probe: +2.5, +2.2 and +2.4 % at 0.17, 0.25 and 0.29
/// of the nearest patch's size (the hierarchy's defaults, the uniform kernel at 0.03 and
/// 0.025 m); the office's desk probes, at 0.51 of a monitor's leaf, within 0.5 %.
pub const NEAR: f64 = 0.4;

/// Probes named one by one before the rest are counted in one warning: a benchmark's
/// hundreds of probes by corners and contacts (`crate::placement`) are near patches by design.
pub const LISTED: usize = 3;

/// One warning per probe that lies within [`NEAR`] of a patch's diameter from a patch it
/// can see (in front of the probe, off the surface the probe lies on), for the first
/// [`LISTED`] such probes; one more that counts the others.
pub fn near_patches(scene: &Scene, model: &Model, out: &mut Vec<Warning>) {
    let near = scene.probes.iter().filter_map(|p| nearest(model, p.position, facing(p.kind, p.normal)).map(|n| (p, n)));
    let mut others = 0;
    for (k, (probe, (i, distance))) in near.enumerate() {
        if k >= LISTED {
            others += 1;
            continue;
        }
        let patch = &model.mesh.patches[i];
        out.push(Warning::NearPatch {
            probe: probe.name.clone(),
            distance,
            surface: scene.surfaces[patch.surface as usize].name.clone(),
            diameter: patch.polygon.diameter(),
            near: NEAR,
        });
    }
    if others > 0 {
        out.push(Warning::MoreNearPatches { count: others, near: NEAR });
    }
}

/// The direction whose half-space a probe gathers from: its normal for a point sensor and a
/// luminance meter; none for the cylindrical kinds (they gather all around).
fn facing(kind: ProbeKind, normal: DVec3) -> Option<DVec3> {
    match kind {
        ProbeKind::Point | ProbeKind::LuminanceMeter { .. } => Some(normal),
        ProbeKind::Cylindrical | ProbeKind::SemiCylindrical { .. } => None,
    }
}

/// The patch with the smallest distance-to-diameter ratio below [`NEAR`] (exposed, not in
/// the probe's plane, partly in front of it), with its distance, m.
fn nearest(model: &Model, p: DVec3, n: Option<DVec3>) -> Option<(usize, f64)> {
    let mesh = &model.mesh;
    let touch = 1e-6 * mesh.extent();
    let in_front = |v: &DVec3| n.is_none_or(|n| (*v - p).dot(n) > touch);
    mesh.patches
        .iter()
        .enumerate()
        .filter(|(_, s)| s.exposed > 0.0 && s.polygon.vertices().iter().any(in_front))
        .filter_map(|(i, s)| {
            let (d, size) = (s.polygon.distance_to(p), s.polygon.diameter());
            (d > touch && d < NEAR * size).then_some((i, d, d / size))
        })
        .min_by(|a, b| a.2.total_cmp(&b.2))
        .map(|(i, d, _)| (i, d))
}
