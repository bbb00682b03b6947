//! Smooth shading: the flat patch values interpolated across the patches of one surface.
//!
//! Each corner of a patch holds the area-weighted mean of `L(j, k_j)` over the patches `j`
//! of the same surface, facing the same side, that share that vertex (`k_j` the cell of
//! patch `j` holding the direction to the eye); a hit point interpolates its patch's
//! corners with Wachspress coordinates (barycentric on triangles, bilinear on
//! parallelograms). Surfaces are not blended into each other, so corners between walls
//! stay sharp. This is a picture of the field, not a better solution: the gather is.
//!
//! Leaves of the hierarchical kernel meet at T-junctions: a corner of two small leaves
//! lies at the midpoint of a larger neighbour's edge, which interpolates only between its
//! own two corners. Such a corner is *anchored*: it takes the mean of that edge's ends
//! (recursively, for corners at quarter points and for ends that are anchored in turn), so
//! both sides of the edge interpolate the same values and the picture has no seam.

use super::solved::Solved;
use crate::geometry::{Mesh, NO_TWIN, Patch};
use glam::DVec3;
use std::collections::HashMap;

/// The patches around every vertex of every patch.
pub struct Corners {
    /// Vertex ids of each patch's corners (in polygon order).
    corner: Vec<[u32; 4]>,
    /// Patches sharing each vertex id.
    around: Vec<Vec<u32>>,
    /// The ends of the larger edge whose midpoint a vertex is (a T-junction), if any.
    anchor: Vec<Option<[u32; 2]>>,
}

/// A vertex: its surface, side (of a two-sided element) and quantized position.
type VertexKey = (u32, bool, [i64; 3]);

/// How many halvings of an edge are searched for T-junctions (a leaf 2¹⁶ times smaller
/// than its neighbour would be the limit).
const DEEPEST_SPLIT: usize = 16;

impl Corners {
    /// The corners of every patch of `mesh`, shared between patches of the same surface and
    /// side (T-junctions of the hierarchy's leaves included).
    pub fn of(mesh: &Mesh) -> Corners {
        let quantum = 1e-7 * mesh.extent().max(f64::MIN_POSITIVE);
        let key = |p: &Patch, i: usize, v: DVec3| -> VertexKey {
            // Back-to-back twins share vertices but not sides: the side is part of the key.
            let side = p.twin != NO_TWIN && p.twin < i as u32;
            (p.surface, side, (v / quantum).round().as_i64vec3().to_array())
        };
        let mut ids: HashMap<VertexKey, u32> = HashMap::new();
        let mut around: Vec<Vec<u32>> = Vec::new();
        let mut corner = Vec::with_capacity(mesh.len());
        for (i, p) in mesh.patches.iter().enumerate() {
            let mut slots = [u32::MAX; 4];
            for (slot, v) in slots.iter_mut().zip(p.polygon.vertices()) {
                let next = around.len() as u32;
                let id = *ids.entry(key(p, i, *v)).or_insert(next);
                if id == next {
                    around.push(Vec::new());
                }
                around[id as usize].push(i as u32);
                *slot = id;
            }
            corner.push(slots);
        }
        let mut anchor = vec![None; around.len()];
        for (i, p) in mesh.patches.iter().enumerate() {
            let v = p.polygon.vertices();
            for e in 0..v.len() {
                let (a, b) = (e, (e + 1) % v.len());
                let ends = ([corner[i][a], corner[i][b]], [v[a], v[b]]);
                anchor_midpoints(&|x| ids.get(&key(p, i, x)).copied(), ends, DEEPEST_SPLIT, &mut anchor);
            }
        }
        Corners { corner, around, anchor }
    }

    /// The interpolated luminance of `patch` at `q` towards the unit direction `towards`.
    pub fn smooth(&self, lit: &Solved, patch: usize, q: DVec3, towards: DVec3) -> f64 {
        let p = &lit.mesh.patches[patch];
        let v = p.polygon.vertices();
        let weights = wachspress(v, p.normal, q);
        let mut sum = 0.0;
        for (c, w) in weights.iter().take(v.len()).enumerate() {
            if *w != 0.0 {
                sum += w * self.value(lit, self.corner[patch][c], towards, DEEPEST_SPLIT);
            }
        }
        sum
    }

    /// The value at vertex `id`: the mean of an anchored vertex's edge ends, else the
    /// area-weighted mean of the patches around it.
    fn value(&self, lit: &Solved, id: u32, towards: DVec3, depth: usize) -> f64 {
        if let (Some([a, b]), 1..) = (self.anchor[id as usize], depth) {
            return 0.5 * (self.value(lit, a, towards, depth - 1) + self.value(lit, b, towards, depth - 1));
        }
        let (mut value, mut area) = (0.0, 0.0);
        for &j in &self.around[id as usize] {
            let a = lit.mesh.patches[j as usize].area;
            value += a * lit.flat(j as usize, towards);
            area += a;
        }
        value / area
    }
}

/// Anchors the vertex at the midpoint of the edge `ends` (ids and positions), if there is
/// one, to the edge's ends, and searches both halves in turn; `id_at` finds the vertex
/// at a position on the same surface and side.
fn anchor_midpoints(
    id_at: &dyn Fn(DVec3) -> Option<u32>,
    ([a, b], [pa, pb]): ([u32; 2], [DVec3; 2]),
    depth: usize,
    anchor: &mut [Option<[u32; 2]>],
) {
    let middle = 0.5 * (pa + pb);
    let Some(m) = id_at(middle).filter(|_| depth > 0) else { return };
    if anchor[m as usize].is_none() {
        anchor[m as usize] = Some([a, b]);
    }
    anchor_midpoints(id_at, ([a, m], [pa, middle]), depth - 1, anchor);
    anchor_midpoints(id_at, ([m, b], [middle, pb]), depth - 1, anchor);
}

/// Wachspress coordinates of `q` in the convex polygon `v` (3 or 4 vertices) of normal
/// `n`, written without divisions so that points on an edge are exact; points slightly
/// outside are clamped onto the polygon.
fn wachspress(v: &[DVec3], n: DVec3, q: DVec3) -> [f64; 4] {
    let m = v.len();
    let area = |a: DVec3, b: DVec3, c: DVec3| 0.5 * n.dot((b - a).cross(c - a));
    // edge[j]: the triangle (q, v_j, v_j+1); corner[j]: the triangle (v_j-1, v_j, v_j+1).
    let mut edge = [0.0; 4];
    let mut weights = [0.0; 4];
    for j in 0..m {
        edge[j] = area(q, v[j], v[(j + 1) % m]).max(0.0);
    }
    for (j, w) in weights.iter_mut().enumerate().take(m) {
        let corner = area(v[(j + m - 1) % m], v[j], v[(j + 1) % m]);
        let others: f64 = (0..m).filter(|&k| k != j && k != (j + m - 1) % m).map(|k| edge[k]).product();
        *w = corner * others;
    }
    let total: f64 = weights.iter().sum();
    if total > 0.0 {
        weights.iter_mut().for_each(|w| *w /= total);
    } else {
        weights[..m].fill(1.0 / m as f64);
    }
    weights
}
