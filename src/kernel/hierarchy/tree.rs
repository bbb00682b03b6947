//! The element trees and the cluster tree above them, in one arena (`docs/design.md` §3b,
//! "Element trees"): every input element (a patch of the coarse mesh) is a root; an element
//! splits lazily into 4 pieces, the two sides of a two-sided element together: strips along
//! a cut of its root that crosses it (`cuts.rs`, §3b "Cuts"), else those of
//! `ConvexPolygon::split_even` (quads by their edges, triangles by their edge midpoints).
//! Node ids never change: the arena only grows.

use super::cluster;
use super::node::{FACING, Kind, NONE, Node, longest_edge};
use super::vector_areas::VectorAreas;
use crate::geometry::{ConvexPolygon, Cut, Mesh, Patch};

/// How a new element's exposed area is measured, m².
pub type Exposure<'a> = dyn Fn(&Patch) -> f64 + Sync + 'a;

/// Every node of the hierarchy.
#[derive(Debug, Clone)]
pub struct Tree {
    nodes: Vec<Node>,
    /// Child lists: a node's children are a contiguous run.
    children: Vec<u32>,
    top: u32,
    /// The lines each root's elements split along where one crosses them (`cuts.rs`), by
    /// root id; empty until [`Tree::set_cuts`].
    cuts: Vec<Vec<Cut>>,
    /// Each cluster member's openness within its cluster along the axes (`openness.rs`), by
    /// node id; empty until [`Tree::set_open`] (1 for every node past its end).
    open: Vec<[f64; FACING]>,
    /// Each cluster's vector areas (`vector_areas.rs`), by node id (empty for elements).
    areas: Vec<VectorAreas>,
}

impl Tree {
    /// The roots are the patches of `roots` (node `i` is patch `i`, with exposed area
    /// `exposed[i]`, m²), clustered above; `albedo[m]` is material `m`'s largest albedo.
    pub fn new(roots: &Mesh, albedo: &[f64], exposed: &[f64]) -> Tree {
        let nodes = roots
            .patches
            .iter()
            .zip(&roots.emission)
            .zip(exposed)
            .map(|((p, &e), &exposed)| {
                let albedo = albedo.get(p.material as usize).copied().unwrap_or(1.0);
                Node::element(Patch { exposed, ..*p }, p.twin, 0, albedo, e)
            })
            .collect();
        let mut tree =
            Tree { nodes, children: Vec::new(), top: NONE, cuts: Vec::new(), open: Vec::new(), areas: Vec::new() };
        let mut ids: Vec<u32> = (0..roots.len() as u32).collect();
        let centres: Vec<glam::DVec3> = tree.nodes.iter().map(Node::centre).collect();
        tree.top = cluster::build(&centres, &mut ids, &mut |members| tree.add_cluster(members));
        tree
    }

    /// Sets the lines along which each root's elements split (`cuts.rs`), by root id.
    pub(super) fn set_cuts(&mut self, cuts: Vec<Vec<Cut>>) {
        self.cuts = cuts;
    }

    /// Sets each cluster member's openness within its cluster (`openness.rs`), by node id.
    pub(super) fn set_open(&mut self, open: Vec<[f64; FACING]>) {
        self.open = open;
    }

    /// Node `id`'s openness within its cluster along each axis (`openness.rs`).
    pub fn open(&self, id: u32) -> [f64; FACING] {
        self.open.get(id as usize).copied().unwrap_or([1.0; FACING])
    }

    /// Sets cluster `id`'s facing areas and vector areas (`openness.rs`).
    pub(super) fn set_facing(&mut self, id: u32, facing: [f64; FACING], areas: VectorAreas) {
        self.nodes[id as usize].facing = facing;
        self.areas[id as usize] = areas;
    }

    /// Node `id`'s vector areas: an element's one, a cluster's kept ones (`vector_areas.rs`).
    pub fn vector_areas(&self, id: u32) -> VectorAreas {
        let node = &self.nodes[id as usize];
        match node.patch() {
            Some(patch) => VectorAreas::face(node.exposed, patch.normal),
            None => self.areas[id as usize].clone(),
        }
    }

    /// Exposed area of node `id`'s elements projected onto a plane across the unit direction
    /// `u`, counting those that face `u`, m² (`docs/design.md` (3b.2), (3b.9)): an element's
    /// `A max(0, n·u)`, a cluster's `Σ_g max(0, m_g·u)` over its vector areas.
    pub fn projected(&self, id: u32, u: glam::DVec3) -> f64 {
        let node = &self.nodes[id as usize];
        match node.patch() {
            Some(patch) => node.exposed * patch.normal.dot(u).max(0.0),
            None => self.areas[id as usize].projected(u),
        }
    }

    /// The node at the top: the root cluster (or the only element, or [`NONE`] when empty).
    pub fn top(&self) -> u32 {
        self.top
    }

    /// The node `id`.
    pub fn node(&self, id: u32) -> &Node {
        &self.nodes[id as usize]
    }

    /// Number of nodes, clusters and elements.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// True when the tree has no nodes.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The children of node `id` (empty for a leaf).
    pub fn children(&self, id: u32) -> &[u32] {
        let n = &self.nodes[id as usize];
        &self.children[n.first_child as usize..(n.first_child + n.child_count) as usize]
    }

    /// Appends a cluster over `members` (already in the arena) and returns its id.
    pub(super) fn add_cluster(&mut self, members: &[u32]) -> u32 {
        let id = self.nodes.len() as u32;
        let first = &self.nodes[members[0] as usize];
        let mut node = Node { kind: Kind::Cluster, parent: NONE, first_child: self.children.len() as u32, ..*first };
        node.child_count = members.len() as u32;
        node.area = 0.0;
        node.exposed = 0.0;
        node.emission = 0.0;
        node.facing = [0.0; 6];
        let mut areas = VectorAreas::default();
        for &m in members {
            areas.add(&self.vector_areas(m), &[1.0; FACING]);
            let member = &mut self.nodes[m as usize];
            member.parent = id;
            node.area += member.area;
            node.exposed += member.exposed;
            node.lo = node.lo.min(member.lo);
            node.hi = node.hi.max(member.hi);
            node.albedo = node.albedo.max(member.albedo);
            node.facing.iter_mut().zip(member.facing).for_each(|(f, m)| *f += m);
        }
        self.children.extend_from_slice(members);
        self.nodes.push(node);
        self.areas.resize(id as usize, VectorAreas::default());
        self.areas.push(areas);
        id
    }

    /// True when `id` has children or can get them: a cluster, or an element whose
    /// longest edge exceeds `patch_size` (m).
    pub fn can_split(&self, id: u32, patch_size: f64) -> bool {
        let node = &self.nodes[id as usize];
        match &node.kind {
            Kind::Cluster => true,
            Kind::Element { patch, .. } => !node.is_leaf() || longest_edge(&patch.polygon) > patch_size * (1.0 + 1e-9),
        }
    }

    /// Gives element `id` (and its twin) their four children, unless they have them: strips
    /// along the most central of its root's cuts that crosses it (`cuts.rs`), else
    /// `ConvexPolygon::split_even` (quarters, or strips across a long quad);
    /// `exposed` measures a child's exposed area (`transfer::exposure`). A pair of twins is
    /// cut from the side under the lower root, whichever of them is asked, so that a
    /// child's address names the same piece in every process (`address.rs`).
    pub fn split(&mut self, id: u32, exposed: &Exposure<'_>) {
        let node = self.nodes[id as usize];
        let Kind::Element { twin, .. } = node.kind else { return };
        if !node.is_leaf() {
            return;
        }
        let (id, twin) = if twin != NONE && self.root(twin) < self.root(id) { (twin, id) } else { (id, twin) };
        let Some(patch) = self.nodes[id as usize].patch().copied() else { return };
        let cuts = self.cuts.get(self.root(id) as usize).map_or(&[][..], Vec::as_slice);
        let pieces = Cut::split(&patch.polygon, cuts).unwrap_or_else(|| patch.polygon.split_even());
        let front = self.add_children(id, pieces, exposed);
        if twin == NONE {
            return;
        }
        let back = self.add_children(twin, pieces.map(|p| p.reversed()), exposed);
        for (f, b) in front.into_iter().zip(back) {
            self.set_twin(f, b);
            self.set_twin(b, f);
        }
    }

    /// The root element that element `id` is or descends from.
    pub(super) fn root(&self, mut id: u32) -> u32 {
        while let Kind::Element { level, .. } = self.nodes[id as usize].kind
            && level > 0
        {
            id = self.nodes[id as usize].parent;
        }
        id
    }

    /// Appends the elements of `polygons` as the children of element `id`; returns their ids.
    fn add_children(&mut self, id: u32, polygons: [ConvexPolygon; 4], exposed: &Exposure<'_>) -> [u32; 4] {
        let parent = self.nodes[id as usize];
        let first = self.nodes.len() as u32;
        if let Kind::Element { patch, level, .. } = parent.kind {
            for polygon in polygons {
                let mut p = Patch::from_polygon(polygon, patch.surface, patch.material, patch.face);
                inherit_frame(&mut p, &patch);
                p.exposed = exposed(&p);
                let child = Node::element(p, NONE, level + 1, parent.albedo, parent.emission);
                self.nodes.push(Node { parent: id, ..child });
            }
            self.link_children(id, first, 4);
        }
        [first, first + 1, first + 2, first + 3]
    }

    fn set_twin(&mut self, id: u32, other: u32) {
        if let Kind::Element { twin, .. } = &mut self.nodes[id as usize].kind {
            *twin = other;
        }
    }

    fn link_children(&mut self, id: u32, first: u32, count: u32) {
        let start = self.children.len() as u32;
        self.children.extend(first..first + count);
        let node = &mut self.nodes[id as usize];
        node.first_child = start;
        node.child_count = count;
    }

    /// All nodes, parents before children, each subtree contiguous (depth first from the top).
    pub fn preorder(&self) -> Vec<u32> {
        let mut order = Vec::with_capacity(self.nodes.len());
        let mut stack = Vec::new();
        if self.top != NONE {
            stack.push(self.top);
        }
        while let Some(id) = stack.pop() {
            order.push(id);
            stack.extend(self.children(id).iter().rev());
        }
        order
    }

    /// The leaf elements in depth-first order: the unknowns.
    pub fn leaves(&self) -> Vec<u32> {
        self.preorder().into_iter().filter(|&id| self.nodes[id as usize].is_leaf()).collect()
    }
}

/// A piece keeps its parent's plane and frame exactly, so that cell values of all the
/// elements of one surface are expressed in the same frame.
fn inherit_frame(piece: &mut Patch, parent: &Patch) {
    piece.normal = parent.normal;
    piece.tangent = parent.tangent;
    piece.bitangent = parent.bitangent;
}
