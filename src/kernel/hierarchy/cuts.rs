//! Cuts along the lines where the light changes abruptly (`docs/design.md` §3b, "Cuts"):
//! where a face stands across a narrow gap from an element, or against it (a desk top's
//! back 2 cm before a wall, a modesty panel 5 cm before it, a whiteboard on it), the lines
//! of its edges carried onto the element part what the gap or the contact hides from what
//! the room lights. An element that such a line crosses splits along it
//! (`ConvexPolygon::split_along`) instead of at its middle, so that no leaf straddles it:
//! a leaf across it sends its mean, lit by the room, into the gap from its hidden side
//! (`docs/accuracy.md`, "A slot behind a desk": +11 … +14 % behind the panel). Found once
//! from the roots alone, so that every process, and every part of a partitioned linking,
//! cuts the same tree.

use super::grading::near_pairs;
use super::slots::SLOT_FACING;
use super::tree::Tree;
use crate::geometry::{CUT_LEAST, Cut, Patch};
use glam::DVec3;
use std::collections::{HashMap, HashSet};

/// The cuts of each root of `tree` (which holds its `roots` roots and the clusters above
/// them, not split yet), by root id: the lines of the outline edges of every element that
/// faces the root, nearer than `patch_size` (m), from the front or lying against it.
pub fn of(tree: &Tree, roots: usize, patch_size: f64) -> Vec<Vec<Cut>> {
    let inner = inner_edges(tree, roots);
    let mut cuts = vec![Vec::new(); roots];
    for (p, q) in near_pairs(tree, patch_size) {
        let (Some(a), Some(b)) = (tree.node(p).patch(), tree.node(q).patch()) else { continue };
        if a.normal.dot(b.normal) >= -SLOT_FACING || !ahead(a, b) || !ahead(b, a) {
            continue;
        }
        for (to, on, from) in [(p, a, b), (q, b, a)] {
            for cut in edges(from).filter(|e| !inner.contains(&key(from.surface, *e))).filter_map(|e| across(on, e)) {
                let known = &mut cuts[to as usize];
                if !known.iter().any(|k| same(k, &cut)) {
                    known.push(cut);
                }
            }
        }
    }
    cuts
}

/// True when no vertex of `q` lies behind `p` by more than [`CUT_LEAST`]: in front of it, or
/// against it.
fn ahead(p: &Patch, q: &Patch) -> bool {
    q.polygon.vertices().iter().all(|v| (*v - p.centroid).dot(p.normal) > -CUT_LEAST)
}

/// The plane through `edge` standing across `patch`, if its line crosses the patch.
fn across(patch: &Patch, edge: [DVec3; 2]) -> Option<Cut> {
    let normal = (edge[1] - edge[0]).cross(patch.normal).try_normalize()?;
    let cut = Cut { point: edge[0], end: edge[1], normal };
    (cut.beside(&patch.polygon) && patch.polygon.split_along(cut.point, cut.normal, CUT_LEAST).is_some()).then_some(cut)
}

/// True when two cuts are one edge.
fn same(a: &Cut, b: &Cut) -> bool {
    let near = |x: DVec3, y: DVec3| x.distance(y) < 1e-9;
    (near(a.point, b.point) && near(a.end, b.end)) || (near(a.point, b.end) && near(a.end, b.point))
}

/// The edges of a patch's polygon.
fn edges(patch: &Patch) -> impl Iterator<Item = [DVec3; 2]> + '_ {
    let v = patch.polygon.vertices();
    (0..v.len()).map(move |i| [v[i], v[(i + 1) % v.len()]])
}

/// An edge of a surface, its ends rounded to a micrometre and ordered.
type EdgeKey = (u32, [i64; 6]);

fn key(surface: u32, edge: [DVec3; 2]) -> EdgeKey {
    let round = |v: DVec3| [v.x, v.y, v.z].map(|c| (c * 1e6).round() as i64);
    let (a, b) = (round(edge[0]), round(edge[1]));
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    (surface, [lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]])
}

/// The edges that two roots of one surface share in one plane: seams of its mesh, not
/// its outline.
fn inner_edges(tree: &Tree, roots: usize) -> HashSet<EdgeKey> {
    let mut seen: HashMap<(EdgeKey, [i64; 3]), u32> = HashMap::new();
    for id in 0..roots as u32 {
        let Some(p) = tree.node(id).patch() else { continue };
        let facing = [p.normal.x, p.normal.y, p.normal.z].map(|c| (c * 1e4).round() as i64);
        for e in edges(p) {
            *seen.entry((key(p.surface, e), facing)).or_default() += 1;
        }
    }
    seen.into_iter().filter(|(_, n)| *n > 1).map(|((k, _), _)| k).collect()
}
