//! The flat four-wide BVH of ugo's own occlusion traversal: obvhs's binary tree, its
//! leaves merged by obvhs's surface-area collapse (up to [`LEAF`] triangles), turned into
//! nodes of four children whose boxes lie side by side (a structure of arrays, one node in
//! two cache lines, parents before their children), the leaves' triangles stored
//! contiguously in the order the tree reaches them.
//!
//! Every box is widened so that the box test never drops a triangle the triangle test
//! would hit: by ten times the test's barycentric slack times the triangle's longest edge,
//! and by `1e-5` of the scene's largest coordinate for the `f32` rounding of the slab test.

use super::triangle::Tri;
use glam::Vec3A;
use obvhs::{
    aabb::Aabb,
    bvh2::{Bvh2, leaf_collapser::collapse},
    triangle::Triangle,
};
use std::ops::Range;

/// The most triangles a leaf holds.
const LEAF: u32 = 4;

/// The cost of a box test in units of a triangle test, for the surface-area collapse.
const BOX_COST: f32 = 3.0;

/// Children of a node whose box is the empty box (never hit).
const EMPTY: u32 = u32::MAX;

/// Set in a child's code when it is a leaf: then bits 27–30 hold its triangle count less
/// one, and bits 0–26 its first triangle.
const LEAF_BIT: u32 = 1 << 31;

/// The deepest tree the traversal's fixed stack can hold (three pending children a level).
pub const MAX_DEPTH: usize = 80;

/// A node: the boxes of its four children and their codes.
#[repr(C, align(64))]
#[derive(Debug, Clone, Copy)]
pub struct Node {
    /// `bounds[2a]` the children's lower bounds along axis `a`, `bounds[2a + 1]` the upper.
    pub bounds: [[f32; 4]; 6],
    /// Each child: a node's index, a leaf's code, or [`EMPTY`].
    pub child: [u32; 4],
}

/// The tree, its triangles in leaf order and the face of each.
pub struct Quad {
    /// The nodes, the root first unless the whole tree is one leaf.
    pub nodes: Vec<Node>,
    /// The root's code (a node's index or a leaf).
    pub root: u32,
    /// The triangles in leaf order.
    pub tris: Vec<Tri>,
    /// The face of each triangle, same order.
    pub faces: Vec<u32>,
}

/// True when `code` names a leaf (or an empty child).
#[inline(always)]
pub fn is_leaf(code: u32) -> bool {
    code & LEAF_BIT != 0
}

/// The triangles of the leaf `code`.
#[inline(always)]
pub fn leaf_range(code: u32) -> Range<usize> {
    let first = (code & ((1 << 27) - 1)) as usize;
    first..first + ((code >> 27) & 15) as usize + 1
}

impl Quad {
    /// The tree over `triangles` (with the face of each) from obvhs's binary tree `bvh`,
    /// whose leaves hold one (possibly split) triangle each.
    pub fn collapse(bvh: &Bvh2, triangles: &[Triangle], face_of: &[u32]) -> Quad {
        let mut bvh = bvh.clone();
        collapse(&mut bvh, LEAF, BOX_COST);
        let reach = triangles.iter().flat_map(|t| [t.v0, t.v1, t.v2]).fold(0.0f32, |m, v| m.max(v.abs().max_element()));
        let mut b = Builder {
            bvh: &bvh,
            triangles,
            face_of,
            pad: 1e-5 * reach,
            quad: Quad { nodes: Vec::new(), root: 0, tris: Vec::new(), faces: Vec::new() },
        };
        if bvh.nodes.is_empty() {
            b.quad.nodes.push(Node { bounds: EMPTY_BOUNDS, child: [EMPTY; 4] });
            return b.quad;
        }
        let (root, _, depth) = b.build(0);
        assert!(depth <= MAX_DEPTH, "a BVH {depth} levels deep (at most {MAX_DEPTH})");
        b.quad.root = root;
        b.quad
    }
}

/// The bounds of a node whose four children are empty.
const EMPTY_BOUNDS: [[f32; 4]; 6] = {
    let (lo, hi) = ([f32::INFINITY; 4], [f32::NEG_INFINITY; 4]);
    [lo, hi, lo, hi, lo, hi]
};

/// The collapse's state.
struct Builder<'a> {
    bvh: &'a Bvh2,
    triangles: &'a [Triangle],
    face_of: &'a [u32],
    /// The widening for rounding, m.
    pad: f32,
    quad: Quad,
}

impl Builder<'_> {
    /// The code, box and depth of the subtree under binary node `id`.
    fn build(&mut self, id: usize) -> (u32, Aabb, usize) {
        if self.bvh.nodes[id].is_leaf() {
            let first = self.quad.tris.len();
            let bounds = self.gather(id);
            let count = self.quad.tris.len() - first;
            assert!(first < 1 << 27, "more than 2^27 triangles");
            return (LEAF_BIT | ((count as u32 - 1) << 27) | first as u32, bounds, 0);
        }
        let kids = self.widest(id);
        let slot = self.quad.nodes.len();
        self.quad.nodes.push(Node { bounds: EMPTY_BOUNDS, child: [EMPTY; 4] });
        let (mut node, mut bounds, mut depth) = (self.quad.nodes[slot], Aabb::empty(), 0);
        for (k, &kid) in kids.iter().enumerate() {
            let (code, b, d) = self.build(kid);
            node.child[k] = code;
            for a in 0..3 {
                node.bounds[2 * a][k] = b.min[a];
                node.bounds[2 * a + 1][k] = b.max[a];
            }
            bounds = bounds.union(&b);
            depth = depth.max(d + 1);
        }
        self.quad.nodes[slot] = node;
        (slot as u32, bounds, depth)
    }

    /// Up to four binary nodes under `id` that become its children: the largest of them
    /// split while fewer than four and one is not a leaf.
    fn widest(&self, id: usize) -> Vec<usize> {
        let first = self.bvh.nodes[id].first_index as usize;
        let mut kids = vec![first, first + 1];
        while kids.len() < 4 {
            let area = |&(_, &k): &(usize, &usize)| self.bvh.nodes[k].aabb.half_area();
            let Some((at, _)) = kids
                .iter()
                .enumerate()
                .filter(|(_, k)| !self.bvh.nodes[**k].is_leaf())
                .max_by(|a, b| area(a).total_cmp(&area(b)))
            else {
                break;
            };
            let split = self.bvh.nodes[kids[at]].first_index as usize;
            kids[at] = split;
            kids.push(split + 1);
        }
        kids
    }

    /// Appends the triangles of the binary leaf `id` and returns their widened box.
    fn gather(&mut self, id: usize) -> Aabb {
        let node = &self.bvh.nodes[id];
        let first = node.first_index as usize;
        let mut bounds = Aabb::empty();
        for &prim in &self.bvh.primitive_indices[first..first + node.prim_count as usize] {
            let t = &self.triangles[prim as usize];
            let edge = (t.v1 - t.v0).length().max((t.v2 - t.v1).length()).max((t.v0 - t.v2).length());
            let pad = Vec3A::splat(self.pad + 10.0 * super::triangle::EDGE_SLACK * edge);
            bounds = bounds.union(&Aabb::new(node.aabb.min - pad, node.aabb.max + pad));
            self.quad.tris.push(Tri::of(t));
            self.quad.faces.push(self.face_of[prim as usize]);
        }
        bounds
    }
}
