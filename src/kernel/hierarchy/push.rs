//! The push of `docs/design.md` §3b ("each node's gathered value added to all its leaves"),
//! weighted by each leaf's own view of the sources of each bundle its ancestors gather
//! (`bundle.rs`, (3b.5)). A link `(a, q)` holds the factor averaged over `a`; a leaf `i` of
//! `a` sees `q` more or less than that average (a leaf by a corner sees the adjacent walls
//! more). Each leaf takes the share `w_iab` of the light gathered in bundle `b` of its
//! ancestor `a`, from `S_iab = Σ_{q ∈ b} v_aq F̄_{i→q}`: the exact point factors to the
//! bundle's sources averaged over the leaf's four stratified points, with the leaf's own
//! visible fraction of a source the ancestor sees partly (a cluster source counts
//! with its link factor; under a cluster ancestor with the leaf's own projected area towards it
//! instead of the cluster's, so that an element facing away gets nothing, Sillion 1995).
//!
//! * Under an element, `w_iab = S_iab / S̄_ab`, `S̄_ab` the area-weighted mean of `S_iab` over
//!   the leaves of `a`: the light `a` gathers with its accurate factors is distributed, never
//!   created or lost. For a source field uniform over the bundle's sources every leaf gets its
//!   own view, so the leaves of a closed scene close whatever the level of their links; for
//!   any other field the shares are right only as far as the bundle's sources are alike,
//!   which is why emitters are a bundle of their own.
//! * Under a cluster, whose factors are estimates, `w_iab = S_iab / C_ab` with
//!   `C_ab = Σ_{q ∈ b} F_aq`: each leaf gets its own estimate `S_iab x̄_q` (normalising by
//!   `S̄_ab` instead was measured worse: CIE 171 5.8 at ρ = 0.95 and tolerance 1e-2 absorbs
//!   7.0 % too much flux, against 2.3 % this way).
//!
//! `S_iab` depends only on the leaf and on the bundle's links, and a refinement pass after
//! the first changes a few thousand of a million links: each build keeps every leaf's
//! `S_iab` with a fingerprint of the bundle's links ([`SeenCache`]) and reuses it while the
//! fingerprint holds (the lecture hall's later builds: 3.1–3.5 s each before). A refinement
//! pass changes a few links in most bundles of the large ancestors, so most bundles' `S_iab`
//! are summed again: each leaf also keeps its own visible fraction of every source its rays
//! found partly visible ([`Fraction`]; all 16 segments cast, where a clear or hidden source
//! took 4), which depends on the two elements alone and is read back instead of cast again
//! (the office's second build: 29–32 s before, 17 s with them; `docs/performance.md`).

use super::bundle::Bundles;
use super::link::{Link, axis};
use super::node::NONE;
use super::sight::Sight;
use super::tree::Tree;
use crate::geometry::Patch;
use crate::progress::Progress;
use crate::random::mix;
use crate::transfer::far_field::point_factor;
use crate::transfer::occlusion::{POINTS, polygon_points, visible_fraction};
use crate::visibility::{NO_BLOCKER, Visibility};
use rayon::prelude::*;

/// Each leaf's `S_iab` of the last build, by leaf node id: `(a, fingerprint of the bundle's
/// links, S_iab)`; and its own visible fractions of the sources it cast rays to, sorted by
/// source.
#[derive(Debug, Default)]
pub struct SeenCache {
    rows: Vec<Vec<Seen>>,
    fractions: Vec<Vec<Fraction>>,
}

/// One leaf's `S_iab`: `(a or b, fingerprint of the bundle's links, S_iab)`.
type Seen = (u32, u64, f64);

/// A leaf's own visible fraction of one element source, as its rays found it: the source's
/// node id and the free segments of the [`SEGMENTS`] in one word (ordered by source).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Fraction(u32);

/// The segments between two elements' stratified points: a fraction is a whole number of them.
const SEGMENTS: u32 = (POINTS * POINTS) as u32;

/// Bits of a [`Fraction`] that hold the free segments (0 to [`SEGMENTS`]).
const FREE_BITS: u32 = 5;

impl Fraction {
    /// The fraction `fraction` of `source`; none when the node id does not fit beside it
    /// (then it is cast again when asked).
    fn new(source: u32, fraction: f64) -> Option<Fraction> {
        let free = (fraction * f64::from(SEGMENTS)) as u32;
        (source < 1 << (32 - FREE_BITS)).then_some(Fraction(source << FREE_BITS | free))
    }

    fn source(self) -> u32 {
        self.0 >> FREE_BITS
    }

    fn fraction(self) -> f64 {
        f64::from(self.0 & ((1 << FREE_BITS) - 1)) / f64::from(SEGMENTS)
    }
}

/// A leaf's fractions: those of the last build (sorted by source) and those cast now.
struct Fractions<'a> {
    before: &'a [Fraction],
    now: Vec<Fraction>,
}

impl Fractions<'_> {
    /// The leaf's visible fraction of `source`: from the last build, or `cast`, and kept
    /// when it is partial (all [`SEGMENTS`] were cast; a clear or hidden one took four).
    fn of(&mut self, source: u32, cast: impl FnOnce() -> f64) -> f64 {
        if let Ok(k) = self.before.binary_search_by_key(&source, |f| f.source()) {
            return self.before[k].fraction();
        }
        let fraction = cast();
        if fraction > 0.0 && fraction < 1.0 {
            self.now.extend(Fraction::new(source, fraction));
        }
        fraction
    }
}

impl SeenCache {
    /// Forgets the cast fractions (refinement is over: no later operator will reuse them).
    pub fn forget_fractions(&mut self) {
        self.fractions = Vec::new();
    }

    /// Keeps each leaf's fractions cast now (`now`, by `leaves`) beside those of the last
    /// build, sorted by source; those of nodes that are no longer leaves are dropped.
    fn keep_fractions(&mut self, nodes: usize, leaves: &[u32], now: Vec<Vec<Fraction>>) {
        let mut fresh: Vec<Option<Vec<Fraction>>> = vec![None; nodes];
        leaves.iter().zip(now).for_each(|(&leaf, now)| fresh[leaf as usize] = Some(now));
        self.fractions.resize_with(nodes, Vec::new);
        self.fractions.par_iter_mut().zip(fresh).for_each(|(own, fresh)| match fresh {
            None => *own = Vec::new(),
            Some(fresh) if !fresh.is_empty() => {
                own.extend(fresh);
                own.sort_unstable();
                own.dedup_by_key(|f| f.source());
                own.shrink_to_fit();
            }
            Some(_) => {}
        });
    }
}

/// Leaves whose push rows are made between two progress reports.
const PUSH_BATCH: usize = 1 << 14;

/// For each leaf (in `leaves` order), the bundles its ancestors (itself included) receive,
/// as `(bundle, weight)`, CSR; `cache` is read and replaced; `progress` hears of the leaves
/// done, a batch at a time.
pub fn push_rows(
    tree: &Tree,
    visibility: &Visibility,
    (links, bundles): (&[Link], &Bundles),
    leaves: &[u32],
    cache: &mut SeenCache,
    progress: &dyn Progress,
) -> (Vec<usize>, Vec<(u32, f64)>) {
    let fingerprints: Vec<u64> =
        (0..bundles.len()).into_par_iter().map(|b| fingerprint(links, bundles.links_of(b))).collect();
    let previous = std::mem::take(&mut cache.rows);
    let cached = |leaf: u32, a: u32, b: usize| {
        let row = previous.get(leaf as usize)?;
        row.iter().find(|e| e.0 == a && e.1 == fingerprints[b]).map(|e| e.2)
    };
    let before = &cache.fractions;
    let row_of = |&leaf: &u32| {
        let mut row = Vec::new();
        let before = before.get(leaf as usize).map_or(&[][..], Vec::as_slice);
        let mut fractions = Fractions { before, now: Vec::new() };
        // Seconds on a large tree: a signal leaves the rest empty (`crate::interrupt`).
        if crate::interrupt::asked() {
            return (row, Vec::new());
        }
        let Some(patch) = tree.node(leaf).patch().filter(|p| p.exposed > 0.0) else { return (row, Vec::new()) };
        let mut a = leaf;
        while a != NONE {
            for b in bundles.of_node(a) {
                let s = cached(leaf, a, b).unwrap_or_else(|| {
                    let own = bundles.links_of(b);
                    seen(tree, visibility, links, own, a, (leaf, patch), &mut fractions)
                });
                row.push((b as u32, fingerprints[b], s));
            }
            a = tree.node(a).parent;
        }
        (row, fractions.now)
    };
    // minutes on a building's million leaves: told a batch at a time
    let what = format!("the operator's push on {} leaves: leaves done", leaves.len());
    let mut rows: Vec<Vec<Seen>> = Vec::with_capacity(leaves.len());
    let mut fractions: Vec<Vec<Fraction>> = Vec::with_capacity(leaves.len());
    for batch in leaves.chunks(PUSH_BATCH) {
        let (r, f): (Vec<Vec<Seen>>, Vec<Vec<Fraction>>) = batch.par_iter().map(row_of).unzip();
        rows.extend(r);
        fractions.extend(f);
        progress.at(rows.len() as u64, &what);
    }
    cache.keep_fractions(tree.len(), leaves, fractions);
    cache.rows = vec![Vec::new(); tree.len()];
    for (row, &leaf) in rows.iter().zip(leaves) {
        cache.rows[leaf as usize] = row.iter().map(|&(b, f, s)| (bundles.receiver[b as usize], f, s)).collect();
    }
    let rows: Vec<Vec<(u32, f64)>> =
        rows.into_iter().map(|r| r.into_iter().map(|(b, _, s)| (b, s)).collect()).collect();
    // S̄_ab: Σ A_i^exp S_iab / Σ A_i over the leaves of an element a, so that the leaves'
    // exposed areas take all the flux a bundle gathers
    let (mut sum, mut area) = (vec![0.0; bundles.len()], vec![0.0; bundles.len()]);
    for (row, &leaf) in rows.iter().zip(leaves) {
        let node = tree.node(leaf);
        for &(b, s) in row {
            sum[b as usize] += node.exposed * s;
            area[b as usize] += node.area;
        }
    }
    let mut row = Vec::with_capacity(rows.len() + 1);
    row.push(0);
    for r in &rows {
        row.push(row[row.len() - 1] + r.len());
    }
    let entries = rows.into_iter().flatten().map(|(b, s)| {
        let bu = b as usize;
        let total = match tree.node(bundles.receiver[bu]).patch() {
            Some(_) => sum[bu] / area[bu],
            None => bundles.links_of(bu).iter().map(|&l| links[l as usize].factor).sum(),
        };
        (b, if total > 0.0 { s / total } else { 1.0 })
    });
    (row, entries.collect())
}

/// `S_iab` of `leaf` under `a`, whose bundle's links are `own`: from an ancestor, each
/// element source's factor with the leaf's own visible fraction of it (the link's is the
/// ancestor's, an average over lit and shadowed leaves), unless the leaf straddles a
/// contact; the leaf's fractions are read from or kept in `fractions`.
fn seen(
    tree: &Tree,
    visibility: &Visibility,
    links: &[Link],
    own: &[u32],
    a: u32,
    leaf: (u32, &Patch),
    fractions: &mut Fractions,
) -> f64 {
    let (id, patch) = leaf;
    let under_cluster = tree.node(a).patch().is_none();
    // a leaf across a contact: its points inside the solid see nothing
    let straddles = tree.node(id).straddles_contact();
    let points = polygon_points(&patch.polygon);
    let mut blocker = NO_BLOCKER;
    own.iter()
        .map(|&l| {
            let link = &links[l as usize];
            let source = tree.node(link.source);
            match source.patch() {
                Some(q) => {
                    let f: f64 = points.iter().map(|&x| point_factor(x, patch.normal, q)).sum();
                    let visible = match a == id || f == 0.0 || straddles || link.sight() == Sight::Clear {
                        true => f64::from(link.visible),
                        false => fractions.of(link.source, || {
                            visible_fraction(visibility, patch, &points, q, &polygon_points(&q.polygon), &mut blocker)
                                .fraction
                        }),
                    };
                    visible * f / points.len() as f64
                }
                None if under_cluster => {
                    // the link's factor with the leaf's own projected area for the cluster's
                    let (u, _) = axis(tree.node(a), source);
                    let projected = tree.node(a).projected(u);
                    if projected > 0.0 {
                        link.factor * tree.node(a).area * patch.normal.dot(u).max(0.0) / projected
                    } else {
                        0.0
                    }
                }
                None => link.factor,
            }
        })
        .sum()
}

/// A fingerprint of the links `own` (indices into `links`) that does not depend on their
/// order: the wrapping sum of a mixed hash of each link's source, factor and visible fraction.
fn fingerprint(links: &[Link], own: &[u32]) -> u64 {
    own.iter().fold(0u64, |sum, &l| {
        let link = &links[l as usize];
        let h = u64::from(link.source)
            ^ link.factor.to_bits().rotate_left(21)
            ^ u64::from(link.visible.to_bits()).rotate_left(42);
        sum.wrapping_add(mix(h))
    })
}
