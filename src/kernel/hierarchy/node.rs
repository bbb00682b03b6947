//! One node of the hierarchy (`docs/design.md` §3b, "Element trees" and "Clusters"): a cluster
//! of input elements or a planar element of one surface, with what the oracle and the
//! operator need to know about it (area, bounding box, largest albedo, emission).

use crate::geometry::{ConvexPolygon, Patch};
use glam::DVec3;

/// Marks a missing node (no parent, no twin).
pub const NONE: u32 = u32::MAX;

/// What a node is.
#[derive(Debug, Clone, Copy)]
#[allow(clippy::large_enum_variant)] // clusters are a small fraction of the nodes
pub enum Kind {
    /// A set of input elements (Smits–Arvo–Greenberg 1994, Sillion 1995).
    Cluster,
    /// A planar piece of one surface; `level` 0 is an input (root) element. A two-sided
    /// element's back is its `twin`; the two split together.
    Element {
        /// The element's polygon, frame, material and exposed area, as a patch.
        patch: Patch,
        /// The node of its back-to-back twin (`NONE` for a one-sided element).
        twin: u32,
        /// Its depth below its root element (0 for a root).
        level: u8,
    },
}

/// A node: its kind, its place in the tree and its summaries.
#[derive(Debug, Clone, Copy)]
pub struct Node {
    /// Cluster or element.
    pub kind: Kind,
    /// Index of the parent node (`NONE` at the top).
    pub parent: u32,
    /// Children are `Tree::children[first_child..first_child + child_count]`.
    pub first_child: u32,
    /// Number of children (0 for a leaf).
    pub child_count: u32,
    /// Area of the elements under it, m² (both sides of a two-sided element count).
    pub area: f64,
    /// The part of `area` outside every solid (`Patch::exposed`), m².
    pub exposed: f64,
    /// Axis-aligned bounding box, m.
    pub lo: DVec3,
    /// Upper corner of the bounding box, m (`lo` the lower).
    pub hi: DVec3,
    /// Largest fraction of arriving light any element under it reflects or transmits.
    pub albedo: f64,
    /// Emitted luminance of an element, cd/m² (0 for a cluster).
    pub emission: f64,
    /// Exposed area facing each axis direction (`+x, −x, +y, −y, +z, −z`), m²: an element's
    /// `A_e max(0, ±n_e·axis)`; a cluster's its children's times their openness within it
    /// (`openness.rs`, (3b.8)), which weigh its facing values (`facing_weights`).
    pub facing: [f64; FACING],
}

/// The axis directions a cluster's exposed area is kept facing (`Node::facing`), and its
/// light by: `+x, −x, +y, −y, +z, −z`.
pub const FACING: usize = 6;

impl Node {
    /// An unsplit element of `patch`.
    pub fn element(patch: Patch, twin: u32, level: u8, albedo: f64, emission: f64) -> Node {
        let (lo, hi) = polygon_bounds(&patch.polygon);
        let n = patch.normal;
        let facing = [n.x, -n.x, n.y, -n.y, n.z, -n.z].map(|c| patch.exposed * c.max(0.0));
        Node {
            kind: Kind::Element { patch, twin, level },
            parent: NONE,
            first_child: 0,
            child_count: 0,
            area: patch.area,
            exposed: patch.exposed,
            lo,
            hi,
            albedo,
            emission,
            facing,
        }
    }

    /// True for an element partly inside a solid (exposed area strictly between 0 and its
    /// area): it lies across a contact line.
    pub fn straddles_contact(&self) -> bool {
        self.patch().is_some() && self.exposed > 0.0 && self.exposed < self.area * (1.0 - 1e-9)
    }

    /// True for an element no part of which lies inside or against a solid.
    pub fn wholly_exposed(&self) -> bool {
        self.patch().is_some() && self.exposed >= self.area * (1.0 - 1e-9)
    }

    /// How a cluster's light towards the unit direction `u` is made of its [`FACING`]
    /// values (`docs/design.md` (3b.7)): `|u_a| facing[a, sign u_a]` for each axis `a`, at
    /// that value's index, 0 elsewhere, over their sum (all 0 where nothing faces `u`). Its
    /// elements facing `u` send it, each by its projected area, exactly when they are
    /// axis-aligned; what faces away (the undersides of a row of seats seen from the
    /// ceiling) sends none.
    pub fn facing_weights(&self, u: DVec3) -> [f64; FACING] {
        let mut weights = [0.0; FACING];
        for (a, c) in [u.x, u.y, u.z].into_iter().enumerate() {
            let at = 2 * a + usize::from(c < 0.0);
            weights[at] = c.abs() * self.facing[at];
        }
        let sum: f64 = weights.iter().sum();
        weights.map(|w| if sum > 0.0 { w / sum } else { 0.0 })
    }

    /// The patch of an element, `None` for a cluster.
    pub fn patch(&self) -> Option<&Patch> {
        match &self.kind {
            Kind::Element { patch, .. } => Some(patch),
            Kind::Cluster => None,
        }
    }

    /// True when the node has no children.
    pub fn is_leaf(&self) -> bool {
        self.child_count == 0
    }

    /// Diagonal of the bounding box, m.
    pub fn diagonal(&self) -> f64 {
        (self.hi - self.lo).length()
    }

    /// Centre of the bounding box, m.
    pub fn centre(&self) -> DVec3 {
        0.5 * (self.lo + self.hi)
    }

    /// Shortest distance between the two bounding boxes, m (0 when they touch or overlap).
    pub fn box_distance(&self, other: &Node) -> f64 {
        let gap = (self.lo - other.hi).max(other.lo - self.hi).max(DVec3::ZERO);
        gap.length()
    }

    /// True when some corner of the bounding box lies strictly in front of `patch`'s plane.
    pub fn reaches_front_of(&self, patch: &Patch) -> bool {
        let eps = 1e-9 * patch.area.sqrt();
        (0..8).any(|c| {
            let corner = DVec3::new(
                if c & 1 == 0 { self.lo.x } else { self.hi.x },
                if c & 2 == 0 { self.lo.y } else { self.hi.y },
                if c & 4 == 0 { self.lo.z } else { self.hi.z },
            );
            (corner - patch.centroid).dot(patch.normal) > eps
        })
    }
}

/// Bounding box of a polygon.
pub fn polygon_bounds(polygon: &ConvexPolygon) -> (DVec3, DVec3) {
    let v = polygon.vertices();
    v.iter().fold((v[0], v[0]), |(lo, hi), p| (lo.min(*p), hi.max(*p)))
}

/// Longest edge of a polygon, m: the size compared with the smallest element size.
pub fn longest_edge(polygon: &ConvexPolygon) -> f64 {
    let v = polygon.vertices();
    (0..v.len()).map(|i| v[i].distance(v[(i + 1) % v.len()])).fold(0.0, f64::max)
}
