//! The push of `docs/design.md` §3b ("each node's gathered value added to all its leaves"),
//! by each leaf's own view of the sources of each bundle its ancestors gather (`bundle.rs`,
//! (3b.5), with the point factors of (3b.6)). A link `(a, q)` between elements, `a` not a
//! leaf, gathers `F^u_aq x̄_q`, its factor *without* the visible fraction its rays found
//! ([`gathered`]): those rays leave from `a`'s four stratified points, and a leaf of `a`
//! beside an armrest or under a seat pan may see none of what they saw, or past a seat what
//! they did not (a pair those rays found hidden is kept, `refine.rs`). Such a link is a
//! bundle of its own, and each leaf `i` of `a` takes the share
//!
//! `w_iaq = v_iq F̄_{i→q} / Ū_aq`
//!
//! of its light: `F̄_{i→q}` the exact point factor to the source averaged over the leaf's
//! four stratified points, `v_iq` the leaf's own visible fraction of it (its own rays, 4 or
//! 16 segments; the link's where the leaf straddles a contact, whose points inside the solid
//! see nothing), `Ū_aq` the area-weighted mean of `F̄_{i→q}` over the leaves of `a`. The
//! leaves together take `Σ_i A_i v_iq F̄_iq x̄_q`: each leaf its own gather from `q`, whatever
//! the level of the link, and the push stays linear in the field, so that balancing holds
//! the push the solve applies and light is conserved.
//!
//! The other bundles (a leaf's own links, a node's cluster sources) hold several sources:
//! `S_iab = Σ_{q ∈ b} v_iq F̄_{i→q}`, `v_iq` the link's fraction for a leaf's own links and
//! for a cluster source the leaf's own fraction of the segments from its four points to the
//! source's four stand-ins that face it (`sight.rs`) over the link's. Under an element
//! `w_iab = S_iab / Ū_ab`, `Ū_ab` the area mean of `S_iab`: the leaves share what the link
//! gathers by their own view, not more, for stand-in rays tell a cluster's visible part
//! only roughly, but alike for the leaves of one plane. Under a cluster, whose factors are
//! estimates, `w_iab = S_iab / C_ab` with `C_ab = Σ_{q ∈ b} F_aq`: each leaf its own estimate
//! with its own projected area towards the source (Sillion 1995) and its own rays, so that
//! a face hidden behind its cluster's others (a desk's panel behind a row of seat backs)
//! takes none of the light they take. `docs/hierarchy.md`, "Each leaf's own view of its
//! ancestors' sources" and "A cluster's light by each leaf's own rays", measure both.
//!
//! A leaf keeps only the bundles whose sources it sees; the weights are summed again at each
//! build (a refinement pass changes the links), but what they are summed from is not found
//! again: each leaf keeps its view of every element source it met ([`Seen`]: the mean point
//! factor and the visible fraction its rays found), which depends on the two elements alone.

use super::bundle::{Bundles, seen_by_leaves};
use super::link::{Link, axis, projected_transfer};
use super::node::{NONE, Node};
use super::sight::stand_ins;
use super::tree::Tree;
use crate::geometry::Patch;
use crate::progress::Progress;
use crate::transfer::far_field::point_factor;
use crate::transfer::occlusion::{POINTS, fraction_between, polygon_points};
use crate::visibility::{Blocker, NO_BLOCKER, Visibility};
use rayon::prelude::*;

/// Each leaf's own view of the element sources it met, sorted by source, by leaf node id.
#[derive(Debug, Default)]
pub struct SeenCache {
    views: Vec<Vec<Seen>>,
}

/// A leaf's own view of one element source, as its points and rays found it: the source's
/// node id and the free segments of the [`SEGMENTS`] in one word (ordered by source), and
/// `F̄_{i→q}`, the mean of the point factors from the leaf's four points (in f32, as every
/// build reads it).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Seen {
    key: u32,
    open: f32,
}

/// The segments between two elements' stratified points: a fraction is a whole number of them.
const SEGMENTS: u32 = (POINTS * POINTS) as u32;

/// Bits of a [`Seen`] key that hold the free segments (0 to [`SEGMENTS`]).
const FREE_BITS: u32 = 5;

impl Seen {
    /// The view of `source`; none when the node id does not fit beside the segments (then
    /// it is found again when asked).
    fn new(source: u32, (open, fraction): (f32, f64)) -> Option<Seen> {
        let free = (fraction * f64::from(SEGMENTS)).round() as u32;
        (source < 1 << (32 - FREE_BITS)).then_some(Seen { key: source << FREE_BITS | free, open })
    }

    fn source(self) -> u32 {
        self.key >> FREE_BITS
    }

    fn fraction(self) -> f64 {
        f64::from(self.key & ((1 << FREE_BITS) - 1)) / f64::from(SEGMENTS)
    }
}

/// A leaf's views: those of the last build (sorted by source) and those found now; and
/// the triangle that blocked its last ray, tried first by the next (the sources hidden
/// from a leaf under a desk are mostly hidden by the same few triangles).
struct Views<'a> {
    before: &'a [Seen],
    now: Vec<Seen>,
    blocker: Blocker,
}

impl Views<'_> {
    /// The leaf's `(F̄_{i→q}, visible fraction)` of `source`: from the last build, or
    /// `look`ed for (with the leaf's last blocker) and kept.
    fn of(&mut self, source: u32, look: impl FnOnce(&mut Blocker) -> (f64, f64)) -> (f64, f64) {
        if let Ok(k) = self.before.binary_search_by_key(&source, |s| s.source()) {
            return (f64::from(self.before[k].open), self.before[k].fraction());
        }
        let (open, fraction) = look(&mut self.blocker);
        let open = open as f32;
        self.now.extend(Seen::new(source, (open, fraction)));
        (f64::from(open), fraction)
    }
}

impl SeenCache {
    /// Forgets the leaves' views (refinement is over: no later operator will reuse them).
    pub fn forget(&mut self) {
        self.views = Vec::new();
    }

    /// Keeps each leaf's views found now (`now`, by `leaves`) beside those of the last
    /// build, sorted by source; those of nodes that are no longer leaves are dropped.
    fn keep(&mut self, nodes: usize, leaves: &[u32], now: Vec<Vec<Seen>>) {
        let mut fresh: Vec<Option<Vec<Seen>>> = vec![None; nodes];
        leaves.iter().zip(now).for_each(|(&leaf, now)| fresh[leaf as usize] = Some(now));
        self.views.resize_with(nodes, Vec::new);
        self.views.par_iter_mut().zip(fresh).for_each(|(own, fresh)| match fresh {
            None => *own = Vec::new(),
            Some(fresh) if fresh.is_empty() => {}
            Some(fresh) => {
                // the first build's views moved, not copied: they are most of its memory
                match own.is_empty() {
                    true => *own = fresh,
                    false => own.extend(fresh),
                }
                own.sort_unstable_by_key(|s| s.key);
                own.dedup_by_key(|s| s.source());
                own.shrink_to_fit();
            }
        });
    }
}

/// Leaves whose push rows are made between two progress reports.
const PUSH_BATCH: usize = 1 << 14;

/// A leaf's sums over one bundle's sources: `S` and `U` of the module's text, and what
/// its element ancestor's mean `Ū` is taken of: `U`, or `S` for clusters' light shared
/// out by the leaves' own rays.
#[derive(Debug, Clone, Copy, Default)]
struct Sums {
    seen: f64,
    open: f64,
    shared: f64,
}

/// Each bundle's exposed-area sum of its leaves' `shared` sums, and their area, as the
/// batches of leaves are made (`Ū_ab` is their ratio).
struct Opens {
    sum: Vec<f64>,
    area: Vec<f64>,
}

impl Opens {
    /// Adds one leaf's `row` (`node` the leaf).
    fn add(&mut self, node: &Node, row: &[(u32, Sums)]) {
        for (b, s) in row {
            self.sum[*b as usize] += node.exposed * s.shared;
            self.area[*b as usize] += node.area;
        }
    }
}

/// The push's rows of `leaves` under the links of `bundles`, CSR: for each leaf (in
/// `leaves` order) the bundles of its ancestors (itself included) whose light it takes,
/// `(bundle, w_iab)`, those it sees nothing of left out; `cache` keeps the leaves' views of
/// their sources from one build to the next; `progress` hears of the leaves done, a batch
/// at a time.
pub fn push_rows(
    tree: &Tree,
    visibility: &Visibility,
    (links, bundles): (&[Link], &Bundles),
    leaves: &[u32],
    cache: &mut SeenCache,
    progress: &dyn Progress,
) -> (Vec<usize>, Vec<(u32, f32)>) {
    let before = &cache.views;
    let row_of = |&leaf: &u32| {
        let mut row = Vec::new();
        let before = before.get(leaf as usize).map_or(&[][..], Vec::as_slice);
        let mut views = Views { before, now: Vec::new(), blocker: NO_BLOCKER };
        // Seconds on a large tree: a signal leaves the rest empty (`crate::interrupt`).
        if crate::interrupt::asked() {
            return (row, Vec::new());
        }
        let Some(patch) = tree.node(leaf).patch().filter(|p| p.exposed > 0.0) else { return (row, Vec::new()) };
        let view = View { tree, visibility, links };
        let mut by_rays = true;
        loop {
            let mut a = leaf;
            while a != NONE {
                for b in bundles.of_node(a) {
                    let own = bundles.links_of(b);
                    row.push((b as u32, view.sums(own, a, (leaf, patch), by_rays, &mut views)));
                }
                a = tree.node(a).parent;
            }
            // a sliver in a slot whose sixteen segments meet none of the sources its
            // ancestors see: its rays do not resolve the slot, the links' own fractions stand
            let blind = row.iter().all(|(_, s)| s.seen == 0.0) && row.iter().any(|(_, s)| s.open > 0.0);
            if !(blind && by_rays) {
                break;
            }
            by_rays = false;
            row.clear();
        }
        (row, views.now)
    };
    // minutes on a building's million leaves: told a batch at a time
    let what = format!("the operator's push on {} leaves: leaves done", leaves.len());
    let mut opens = Opens { sum: vec![0.0; bundles.len()], area: vec![0.0; bundles.len()] };
    let (mut row, mut entries) = (Vec::with_capacity(leaves.len() + 1), Vec::new());
    row.push(0);
    let mut views: Vec<Vec<Seen>> = Vec::with_capacity(leaves.len());
    for batch in leaves.chunks(PUSH_BATCH) {
        let (rows, now): (Vec<_>, Vec<_>) = batch.par_iter().map(row_of).unzip();
        for (r, &leaf) in rows.iter().zip(batch) {
            opens.add(tree.node(leaf), r);
            // a source a leaf does not see gives it nothing (a bundle whose leaves see none
            // of its sources, `open` 0, shares its light out evenly: kept)
            entries.extend(r.iter().filter(|(_, s)| s.seen > 0.0 || s.open == 0.0).map(|(b, s)| (*b, s.seen as f32)));
            row.push(entries.len());
        }
        views.extend(now);
        progress.at((row.len() - 1) as u64, &what);
    }
    cache.keep(tree.len(), leaves, views);
    let totals = totals(tree, (links, bundles), &opens);
    entries.iter_mut().for_each(|(b, w)| *w = shared(f64::from(*w), totals[*b as usize]) as f32);
    (row, entries)
}

/// `seen / total`, 1 where a bundle's total is 0.
fn shared(seen: f64, total: f64) -> f64 {
    if total > 0.0 { seen / total } else { 1.0 }
}

/// Each bundle's total to share out: under an element the area-weighted mean of the leaves'
/// `open` sums (`Ū_ab`), under a cluster `Σ_q F^u_aq`.
fn totals(tree: &Tree, (links, bundles): (&[Link], &Bundles), opens: &Opens) -> Vec<f64> {
    (0..bundles.len())
        .map(|b| match tree.node(bundles.receiver[b]).patch() {
            Some(_) if opens.area[b] > 0.0 => opens.sum[b] / opens.area[b],
            Some(_) => 0.0,
            None => bundles.links_of(b).iter().map(|&l| gathered(tree, &links[l as usize])).sum(),
        })
        .collect()
}

/// The factor by which the link gathers: without the visible fraction its rays found where
/// the leaves see its source by their own ([`seen_by_leaves`]; as it is when those rays saw
/// nothing: 0), else its own.
pub(super) fn gathered(tree: &Tree, link: &Link) -> f64 {
    match (seen_by_leaves(tree, link), link.visible > 0.0) {
        (true, true) => link.factor / f64::from(link.visible),
        (true, false) | (false, true) => link.factor,
        (false, false) => 0.0,
    }
}

/// What a leaf's view of its ancestors' sources needs.
struct View<'a> {
    tree: &'a Tree,
    visibility: &'a Visibility,
    links: &'a [Link],
}

impl View<'_> {
    /// The [`Sums`] of `leaf` under `a` over the links `own` of one bundle, by the leaf's own
    /// rays when `by_rays` (its views read from or kept in `views`), else by the links'
    /// fractions.
    fn sums(&self, own: &[u32], a: u32, leaf: (u32, &Patch), by_rays: bool, views: &mut Views) -> Sums {
        let (id, patch) = leaf;
        // a leaf across a contact: its points inside the solid see nothing
        let own_rays = by_rays && a != id && !self.tree.node(id).straddles_contact();
        let points = polygon_points(&patch.polygon);
        let from = points.map(|x| (x, patch.face));
        let mut sums = Sums::default();
        for &l in own {
            let link = &self.links[l as usize];
            let by_leaf = seen_by_leaves(self.tree, link);
            let cluster_by_rays = !by_leaf && own_rays;
            let (open, visible) = match (by_leaf, own_rays) {
                (true, true) => views.of(link.source, |blocker| {
                    let open = self.open_factor(link, a, (id, &points), true);
                    if open <= 0.0 {
                        return (open, 0.0);
                    }
                    let to = stand_ins(self.tree, link.source, patch.centroid);
                    (open, fraction_between(self.visibility, &from, &to, blocker).fraction)
                }),
                (true, false) => (self.open_factor(link, a, (id, &points), true), f64::from(link.visible)),
                // a cluster's light by the leaf's own rays to its stand-ins in place of the
                // link's: the leaf may lie behind its receiver cluster's faces turned to it
                (false, true) => {
                    let open = self.open_factor(link, a, (id, &points), false);
                    if open <= 0.0 {
                        continue;
                    }
                    let (_, own) = views.of(link.source, |blocker| {
                        let to = stand_ins(self.tree, link.source, patch.centroid);
                        (0.0, fraction_between(self.visibility, &from, &to, blocker).fraction)
                    });
                    (open, own / f64::from(link.visible))
                }
                (false, false) => (self.open_factor(link, a, (id, &points), false), 1.0),
            };
            if open <= 0.0 {
                continue;
            }
            sums.seen += visible * open;
            sums.open += open;
            sums.shared += if cluster_by_rays { visible * open } else { open };
        }
        sums
    }

    /// `F̄_{i→q}` of the leaf (its stratified `points`) to the link's source: an element's
    /// exact point factors, unoccluded where the leaf sees it by its own rays (`by_leaf`),
    /// else times the link's visible fraction; a cluster's link factor, with the leaf's own
    /// projected area under a cluster ancestor `a`, and under an element ancestor scaled by
    /// the leaf's own projected transfer against the ancestor's (its own direction and
    /// distance to the cluster: a leaf in a room's far corner takes less of a cluster in its
    /// middle than one beneath it).
    fn open_factor(&self, link: &Link, a: u32, (id, points): (u32, &[glam::DVec3; POINTS]), by_leaf: bool) -> f64 {
        let (leaf, source) = (self.tree.node(id), self.tree.node(link.source));
        let patch = leaf.patch().expect("a leaf is an element");
        if let Some(q) = source.patch() {
            let f = points.iter().map(|&x| point_factor(x, patch.normal, q)).sum::<f64>() / POINTS as f64;
            return if by_leaf { f } else { f * f64::from(link.visible) };
        }
        let ancestor = self.tree.node(a);
        if ancestor.patch().is_some() {
            let whole = projected_transfer(self.tree, a, link.source);
            return if whole > 0.0 {
                link.factor * projected_transfer(self.tree, id, link.source) / whole
            } else {
                0.0
            };
        }
        let (u, _) = axis(ancestor, source);
        let projected = self.tree.projected(a, u);
        match projected > 0.0 {
            true => link.factor * ancestor.area * patch.normal.dot(u).max(0.0) / projected,
            false => 0.0,
        }
    }
}
