//! ugo's own occlusion traversal over the flat four-wide tree ([`Quad`]): the four boxes
//! of a node tested side by side against precomputed inverse directions (portable code
//! the compiler turns into SIMD), a fixed stack, and an early exit at the first triangle
//! hit.

use super::quad::{MAX_DEPTH, Node, Quad, is_leaf, leaf_range};
use obvhs::ray::Ray;

/// A ray as the slab test reads it: the inverse direction, the origin times it, which
/// of each axis's bounds is met first, and the interval.
struct Slabs {
    inv: [f32; 3],
    origin_inv: [f32; 3],
    /// `2a` when the direction's component `a` is positive (the lower bound first), else `2a + 1`.
    near: [usize; 3],
    tmin: f32,
    tmax: f32,
}

impl Slabs {
    fn of(ray: &Ray) -> Slabs {
        let (o, d) = (ray.origin.to_array(), ray.direction.to_array());
        let inv = [1.0 / d[0], 1.0 / d[1], 1.0 / d[2]];
        let near = |a: usize| 2 * a + usize::from(d[a] < 0.0);
        Slabs {
            inv,
            origin_inv: [o[0] * inv[0], o[1] * inv[1], o[2] * inv[2]],
            near: [near(0), near(1), near(2)],
            tmin: ray.tmin,
            tmax: ray.tmax,
        }
    }

    /// Bit `k` set when the ray meets child `k`'s box within its interval.
    #[inline(always)]
    fn hits(&self, node: &Node) -> u32 {
        let [nx, ny, nz] = self.near;
        let (x0, y0, z0) = (&node.bounds[nx], &node.bounds[ny], &node.bounds[nz]);
        let (x1, y1, z1) = (&node.bounds[nx ^ 1], &node.bounds[ny ^ 1], &node.bounds[nz ^ 1]);
        let ([ix, iy, iz], [ox, oy, oz]) = (self.inv, self.origin_inv);
        let mut enter = [0.0; 4];
        let mut leave = [0.0; 4];
        for k in 0..4 {
            enter[k] = max(max(x0[k] * ix - ox, y0[k] * iy - oy), max(z0[k] * iz - oz, self.tmin));
            leave[k] = min(min(x1[k] * ix - ox, y1[k] * iy - oy), min(z1[k] * iz - oz, self.tmax));
        }
        let mut mask = 0;
        for k in 0..4 {
            mask |= u32::from(enter[k] <= leave[k]) << k;
        }
        mask
    }
}

/// The larger of two numbers, in the form that compiles to one `maxps` lane.
#[inline(always)]
fn max(a: f32, b: f32) -> f32 {
    if a > b { a } else { b }
}

/// The smaller of two numbers, in the form that compiles to one `minps` lane.
#[inline(always)]
fn min(a: f32, b: f32) -> f32 {
    if a < b { a } else { b }
}

impl Quad {
    /// The first triangle found (not necessarily the nearest) that `ray` crosses within its
    /// interval, among those `skip` does not exclude.
    pub fn any_hit(&self, ray: &Ray, skip: impl Fn(usize) -> bool) -> Option<usize> {
        let slabs = Slabs::of(ray);
        let mut stack = [0u32; 3 * MAX_DEPTH + 1];
        let (mut top, mut code) = (0, self.root);
        loop {
            if is_leaf(code) {
                if let Some(id) = leaf_range(code).find(|&id| !skip(id) && self.tris[id].hit(ray) < f32::INFINITY) {
                    return Some(id);
                }
            } else {
                let node = &self.nodes[code as usize];
                let mut mask = slabs.hits(node);
                while mask != 0 {
                    stack[top] = node.child[mask.trailing_zeros() as usize];
                    top += 1;
                    mask &= mask - 1;
                }
            }
            if top == 0 {
                return None;
            }
            top -= 1;
            code = stack[top];
        }
    }
}
