//! The light arriving at an exact point by way of the plane mirrors (`docs/mirrors.md`; the
//! gather of `docs/design.md` §5):
//! each mirror `M` in front of which `p` lies is a window into the mirrored scene, so the
//! light it brings `p` is `ρ_M` times what the images `j′` of the other patches send `p`
//! through `M`'s polygon,
//!
//! `I^M_d(p) = ρ_M Σ_j Σ_m L_j(m) F_{dA(p)→P_j′}^{d,m} V_M(p, P_j′)`,
//!
//! with the exact contour-integral form factor to the image split by cells as in the
//! kernel (`m` the cell `j` sends the light in, towards the mirror point) and `V_M` the
//! share of the image's points whose segment from `p` crosses the mirror's plane inside
//! `M`, with nothing in the way before or after it (`transfer::image`). A piece of an image
//! that the mirror's edge or a shadow crosses is cut into quarters
//! (`transfer::occlusion::cut_along_shadows`), as the gather cuts along shadow edges (by
//! the rule of `cut.rs`). A Phong
//! or GGX patch's light is its final gather towards the mirror point (`glossy.rs`).
//!
//! The mirror's own stored cell values hold its reflection averaged over each direction
//! cell (the kernel's cell block, what renders read); read from this instead, a point by a
//! mirror sees the images whole. `gather.rs` takes a plane mirror's light from here, not from
//! its cells.

use crate::geometry::{ConvexPolygon, Frame, Patch};
use crate::model::Model;
use crate::readout::cut::{Cut, Worth};
use crate::readout::field::Field;
use crate::readout::glossy::{ModelSurroundings, PIECE_RAYS, has_lobe};
use crate::transfer::contour::point_to_patch;
use crate::transfer::form_factor::{Binning, binned_point};
use crate::transfer::occlusion::cut_along_shadows;
use glam::DVec3;
use rayon::prelude::*;

/// For each patch, true when it lies on one of the plane mirrors of `model`.
pub fn on_mirrors(model: &Model) -> Vec<bool> {
    let mut held = vec![false; model.mesh.patches.len()];
    model.mirrors.iter().flat_map(|m| &m.patches).for_each(|&j| held[j as usize] = true);
    held
}

/// `I^M_d(p)` summed over the mirrors: the light arriving at `p` per cell of `frame` by way
/// of the plane mirrors of `model` (`ignore`: the face `p` lies on). A piece crossed by a
/// shadow or the mirror's edge is cut further while the light it would send unoccluded
/// exceeds `cut`'s fraction of all the images' light at `p` unoccluded (as the gather's
/// `SHADOW_CUT`, `cut.rs`).
pub fn through_mirrors(model: &Model, field: &Field, p: DVec3, frame: &Frame, ignore: u32, cut: &Cut) -> Vec<f64> {
    let directions = &model.kernel.directions;
    let cells = directions.len();
    let binning = Binning::new(directions);
    let patches = &model.mesh.patches;
    let held = on_mirrors(model);
    let surroundings = ModelSurroundings::new(model, field);
    let mut sum = vec![0.0; cells];
    for mirror in model.mirrors.iter().filter(|m| m.height(p) > 0.0 && m.reflectance > 0.0) {
        let mirrored = mirror.reflect(p);
        let images: Vec<(usize, Patch, f64)> = patches
            .par_iter()
            .enumerate()
            .filter(|&(j, s)| !held[j] && mirror.in_front(s))
            .map(|(j, s)| {
                let image = mirror.image(s);
                (j, image, point_to_patch(p, frame.normal, &image).max(0.0))
            })
            .collect();
        let geometric: Vec<f64> = images.iter().map(|i| i.2).collect();
        let worth = Worth::new(cut, field, &geometric, |k| images[k].0, mirror.reflectance);
        let light = images
            .par_iter()
            .enumerate()
            .filter(|&(k, _)| worth.lit(k))
            .fold(
                || (vec![0.0; cells], Vec::new()),
                |(mut sum, mut bins), (k, (j, image, _))| {
                    let (j, real) = (*j, &patches[*j]);
                    let sees = |y: DVec3| mirror.passes(&model.visibility, p, ignore, y, real.face);
                    let worth = |piece: &ConvexPolygon| worth.cuts(k, image.area, piece.area());
                    let glossy = has_lobe(&model.materials[real.material as usize]);
                    cut_along_shadows(&image.polygon, 0, &sees, &worth, &mut |piece, seen| {
                        bins.clear();
                        binned_point(p, frame, &Patch { polygon: *piece, ..*image }, &binning, &mut bins);
                        let c = mirror.reflect(piece.centroid());
                        let towards =
                            glossy.then(|| surroundings.outgoing(j, c, (mirrored - c).normalize(), PIECE_RAYS));
                        for &(d, m, f) in bins.iter() {
                            let l = towards.unwrap_or_else(|| field.at(j, m as usize));
                            sum[d as usize] += mirror.reflectance * f * seen * l;
                        }
                    });
                    (sum, bins)
                },
            )
            .map(|(sum, _)| sum)
            .reduce(|| vec![0.0; cells], |a, b| a.iter().zip(&b).map(|(x, y)| x + y).collect());
        sum.iter_mut().zip(&light).for_each(|(s, l)| *s += l);
    }
    sum
}
