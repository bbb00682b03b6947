//! The segments of one link traced together (issue 35): one traversal of obvhs's compressed
//! wide BVH for up to [`PACKET`] rays that share a direction octant, each node's quantized
//! child boxes decoded once and tested against every ray still active in it.
//!
//! Owns the packet traversal and the replay of the last-blocker cache over a sequence of
//! segments. Every answer is the one [`Visibility::visible_cached`] gives for the segments
//! taken in turn: the per-ray box test is obvhs's to the bit (the same products and sums,
//! the same `NEAREST_BOX` floor on a box's entry), the children are visited in obvhs's order
//! for the octant and a leaf's triangles in its order, so each ray finds the same first
//! blocker as its own traversal would. The cache is then replayed in order: a segment that
//! the last blocker meets is blocked; any other takes its traversal's answer, and its blocker
//! becomes the last. Rays the caller's blocker already meets are left out of the packet and
//! traced alone in the rare case the replay needs them.

use super::{Blocker, Bvh, NEAREST_BOX, Visibility};
use glam::{DVec3, Vec3A, Vec4};
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::node::{CwBvhNode, extract_byte64};
use obvhs::ray::Ray;

/// Most segments traced together.
pub const PACKET: usize = 16;

/// Lanes of a packet, one bit a ray.
type Lanes = u16;

/// A segment: its two end points and the faces they lie on (ignored).
pub type Segment = (DVec3, DVec3, [u32; 2]);

/// The deepest traversal stack (obvhs's own bound for a CwBvh).
const STACK: usize = 32;

/// A node's remaining children to visit: their base index, obvhs's group bits (the hit
/// children in the top byte, the node's `imask` in the low one) and, per child bit, the
/// lanes whose rays hit that child.
#[derive(Clone, Copy, Default)]
struct Group {
    base: u32,
    bits: u32,
    lanes: [Lanes; 8],
}

impl Visibility {
    /// The answers of [`Visibility::visible_cached`] on `segments` (at most [`PACKET`]),
    /// taken in turn with `blocker` (updated as they would update it): bit `i` is set when
    /// segment `i` is free.
    pub fn visible_together(&self, segments: &[Segment], blocker: &mut Blocker) -> Lanes {
        assert!(segments.len() <= PACKET, "{} segments in a packet", segments.len());
        let Bvh::Wide(wide) = &self.bvh else {
            return lanes_where(segments.len(), |i| {
                let (a, b, ignore) = segments[i];
                self.visible_cached(a, b, ignore, blocker)
            });
        };
        let mut rays = [None; PACKET];
        for (ray, &(a, b, _)) in rays.iter_mut().zip(segments) {
            *ray = self.segment(a, b);
        }
        let (ignore, known) = (|i: usize| segments[i].2, *blocker);
        let met = lanes_where(segments.len(), |i| rays[i].is_some_and(|r| self.blocks(known, &r, ignore(i))));
        let todo = lanes_where(segments.len(), |i| rays[i].is_some()) & !met;
        let firsts = self.traced(wide, &rays, &ignore, todo);
        lanes_where(segments.len(), |i| {
            let Some(ray) = &rays[i] else { return true };
            let blocked = if *blocker == known { met & 1 << i != 0 } else { self.blocks(*blocker, ray, ignore(i)) };
            if blocked {
                return false;
            }
            let first = if todo & 1 << i != 0 { firsts[i] } else { self.first_blocker(ray, ignore(i)) };
            if first.is_some() {
                blocker.0 = first;
            }
            first.is_none()
        })
    }

    /// The first blocker each ray of `todo` meets, traced in packets of one octant each.
    fn traced(
        &self,
        wide: &CwBvh,
        rays: &[Option<Ray>; PACKET],
        ignore: &dyn Fn(usize) -> [u32; 2],
        mut todo: Lanes,
    ) -> [Option<usize>; PACKET] {
        let mut firsts = [None; PACKET];
        let ray = |i: u32| rays[i as usize].expect("a ray in every lane to trace");
        while todo != 0 {
            let octant = octant_inv4(ray(todo.trailing_zeros()).direction);
            let packet = lanes_of(todo).filter(|&i| octant_inv4(ray(i).direction) == octant).fold(0, |m, i| m | 1 << i);
            self.traverse(wide, rays, ignore, packet, octant, &mut firsts);
            todo &= !packet;
        }
        firsts
    }

    /// obvhs's traversal (its `traverse!`) for the rays of `packet`, all of octant `octant`:
    /// each lane stops at its first blocker, written to `firsts`.
    fn traverse(
        &self,
        wide: &CwBvh,
        rays: &[Option<Ray>; PACKET],
        ignore: &dyn Fn(usize) -> [u32; 2],
        packet: Lanes,
        octant: u32,
        firsts: &mut [Option<usize>; PACKET],
    ) {
        if wide.nodes.is_empty() {
            return;
        }
        let mut stack = [Group::default(); STACK];
        let mut depth = 0;
        let mut group = Group { base: 0, bits: 0x8000_0000, lanes: [0, 0, 0, 0, 0, 0, 0, packet] };
        let mut done: Lanes = 0;
        let mut hits = [0u32; PACKET];
        loop {
            while group.bits & 0xff00_0000 != 0 {
                let offset = firstbithigh(group.bits);
                let (bits, lanes) = (group.bits, group.lanes[offset as usize - 24] & !done);
                group.bits &= !(1 << offset);
                if group.bits & 0xff00_0000 != 0 {
                    stack[depth] = group;
                    depth += 1;
                }
                if lanes == 0 {
                    break; // nothing to enter: on with the rest of the group, just pushed
                }
                let slot = (offset - 24) ^ (octant & 0xff);
                let node = &wide.nodes[(group.base + (bits & !(u32::MAX << slot)).count_ones()) as usize];
                let union = node_hits(node, rays, lanes, octant, &mut hits);
                self.leaves(node, rays, ignore, lanes, union & 0x00ff_ffff, &hits, &mut done, firsts);
                group =
                    Group { base: node.child_base_idx, bits: union & 0xff00_0000 | node.imask as u32, lanes: [0; 8] };
                for i in lanes_of(lanes & !done) {
                    for (b, l) in group.lanes.iter_mut().enumerate() {
                        *l |= (((hits[i as usize] >> (24 + b)) & 1) as Lanes) << i;
                    }
                }
            }
            if depth == 0 || done == packet {
                return;
            }
            depth -= 1;
            group = stack[depth];
        }
    }

    /// Tests the triangles of `node`'s leaves that the lanes' rays hit (bits `triangles` of
    /// their hit masks), highest bit first as obvhs does, each lane up to its first blocker.
    #[allow(clippy::too_many_arguments)]
    fn leaves(
        &self,
        node: &CwBvhNode,
        rays: &[Option<Ray>; PACKET],
        ignore: &dyn Fn(usize) -> [u32; 2],
        lanes: Lanes,
        mut triangles: u32,
        hits: &[u32; PACKET],
        done: &mut Lanes,
        firsts: &mut [Option<usize>; PACKET],
    ) {
        while triangles != 0 {
            let bit = firstbithigh(triangles);
            triangles &= !(1 << bit);
            let id = (node.primitive_base_idx + bit) as usize;
            for i in lanes_of(lanes & !*done).filter(|&i| hits[i as usize] & 1 << bit != 0) {
                let ray = rays[i as usize].as_ref().expect("a ray in every traced lane");
                if self.meets(id, ray, ignore(i as usize)) < f32::INFINITY {
                    firsts[i as usize] = Some(id);
                    *done |= 1 << i;
                }
            }
        }
    }
}

/// The hit masks of `node`'s children for every ray of `lanes` (obvhs's
/// `CwBvhNode::intersect_ray`, to the bit), into `hits`; returns their union.
#[inline(always)]
fn node_hits(
    node: &CwBvhNode,
    rays: &[Option<Ray>; PACKET],
    lanes: Lanes,
    octant: u32,
    hits: &mut [u32; PACKET],
) -> u32 {
    let (child_bits, bit_index) = node.get_child_and_index_bits(octant);
    let contribution: [u32; 8] = std::array::from_fn(|c| extract_byte64(child_bits, c) << extract_byte64(bit_index, c));
    let x = planes(&node.child_min_x, &node.child_max_x, octant & 4 != 0);
    let y = planes(&node.child_min_y, &node.child_max_y, octant & 2 != 0);
    let z = planes(&node.child_min_z, &node.child_max_z, octant & 1 != 0);
    let (extent, p) = (node.compute_extent(), Vec3A::from(node.p));
    let nearest = Vec4::splat(NEAREST_BOX as f32);
    let mut union = 0;
    for i in lanes_of(lanes) {
        let ray = rays[i as usize].as_ref().expect("a ray in every traced lane");
        let (scale, shift) = (extent * ray.inv_direction, (p - ray.origin) * ray.inv_direction);
        let at = |planes: &Planes, end: usize, half: usize, axis: usize| {
            planes[end][half] * Vec4::splat(scale[axis]) + Vec4::splat(shift[axis])
        };
        let mut entered = 0;
        for half in 0..2 {
            let near = at(&x, 0, half, 0).max(at(&y, 0, half, 1).max(at(&z, 0, half, 2))).max(nearest);
            let far = at(&x, 1, half, 0).min(at(&y, 1, half, 1).min(at(&z, 1, half, 2))).min(Vec4::splat(ray.tmax));
            entered |= near.cmple(far).bitmask() << (4 * half);
        }
        let hit = (0..8).filter(|c| entered & 1 << c != 0).fold(0, |h, c| h | contribution[c]);
        hits[i as usize] = hit;
        union |= hit;
    }
    union
}

/// A node's eight child planes across one axis, four children a vector: the planes a ray
/// of the octant enters by (`[0]`) and leaves by (`[1]`).
type Planes = [[Vec4; 2]; 2];

/// The [`Planes`] of the quantized `lo` and `hi` sides, for a ray going up the axis when
/// `positive` (obvhs's choice of `q_lo` and `q_hi`).
#[inline(always)]
fn planes(lo: &[u8; 8], hi: &[u8; 8], positive: bool) -> Planes {
    let half = |q: &[u8; 8], h: usize| {
        Vec4::new(q[4 * h].into(), q[4 * h + 1].into(), q[4 * h + 2].into(), q[4 * h + 3].into())
    };
    let (enter, leave) = if positive { (lo, hi) } else { (hi, lo) };
    [[half(enter, 0), half(enter, 1)], [half(leave, 0), half(leave, 1)]]
}

/// obvhs's `firstbithigh`: the index of the highest set bit.
#[inline(always)]
fn firstbithigh(value: u32) -> u32 {
    31 - value.leading_zeros()
}

/// obvhs's child-order code of a direction's octant, repeated in four bytes.
fn octant_inv4(d: Vec3A) -> u32 {
    (if d.x < 0.0 { 0 } else { 0x0404_0404 })
        | (if d.y < 0.0 { 0 } else { 0x0202_0202 })
        | (if d.z < 0.0 { 0 } else { 0x0101_0101 })
}

/// The lanes of `mask`, lowest first.
fn lanes_of(mut mask: Lanes) -> impl Iterator<Item = u32> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let i = mask.trailing_zeros();
            mask &= mask - 1;
            i
        })
    })
}

/// The lanes `0..n` for which `yes` holds, asked in order.
fn lanes_where(n: usize, mut yes: impl FnMut(usize) -> bool) -> Lanes {
    (0..n).fold(0, |m, i| if yes(i) { m | 1 << i } else { m })
}
