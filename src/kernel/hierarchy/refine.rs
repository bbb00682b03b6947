//! Refinement of links (`docs/design.md` §3b, "Links" and "Oracle"): candidate pairs of nodes are
//! evaluated in parallel (dropped when they cannot exchange light, kept as links when the
//! oracle accepts them, or marked for a split), the marked nodes are split, and their
//! children's pairs are the next round's candidates, until no candidate is left. A candidate
//! `(p, q)` covers every pair of a leaf under `p` and a leaf under `q`, and its children's
//! pairs partition that set, so every pair of leaves stays covered by exactly one link.
//! Every round starts only if no signal asked to stop and the links, candidates and tree
//! fit in the memory limit; else refinement stops with the reason ([`Stopped`]).

use super::brightness::Brightness;
use super::link::{Link, cluster_factor, element_factor};
use super::node::Node;
use super::oracle::{Oracle, cluster_bound, variation};
use super::partition::Partition;
use super::sight::{Sight, corners_see, sampled_sight, sight, stand_in_sight, stand_ins};
use super::tree::{Exposure, Tree};
use crate::directions::DirectionSet;
use crate::geometry::{Patch, facing};
use crate::interrupt::Interrupted;
use crate::kernel::TooLarge;
use crate::kernel::memory::Footprint;
use crate::progress::Progress;
use crate::transfer::exposure::Backs;
use crate::transfer::form_factor::{Binning, Quadrature};
use crate::transfer::occlusion::polygon_points;
use crate::visibility::{Blocker, Visibility};
use rayon::prelude::*;

/// What stays fixed during refinement.
pub struct Settings<'a> {
    /// The ray caster over the roots' faces.
    pub visibility: &'a Visibility,
    /// The backs of the roots' faces, for the exposed area of new elements.
    pub backs: &'a Backs,
    /// The refinement rule.
    pub oracle: Oracle,
    /// The quadrature of element factors.
    pub quadrature: &'a Quadrature,
    /// The direction cells factors are split by.
    pub directions: &'a DirectionSet,
    /// Bytes the refinement may take.
    pub memory_limit: u64,
    /// Hears of the pairs settled, a batch at a time.
    pub progress: &'a dyn Progress,
    /// When only one part's receivers are linked: a pair whose receiver lies wholly in
    /// other parts is dropped before it is evaluated, with every pair it would refine into.
    pub partition: Option<&'a Partition>,
}

/// Candidate pairs evaluated between two progress reports.
const BATCH: usize = 1 << 16;

/// Why refinement stopped before every candidate was settled.
#[derive(Debug, thiserror::Error)]
pub enum Stopped {
    /// A signal asked the process to stop.
    #[error(transparent)]
    Interrupted(#[from] Interrupted),
    /// The next round would not fit in the memory limit.
    #[error(transparent)]
    TooLarge(#[from] TooLarge),
}

/// What became of one candidate.
enum Outcome {
    Drop,
    Split(u32),
    Keep(Link),
}

/// Refines `candidates` into `links`; `brightness` (per node) grows with the tree, new
/// nodes taking their parent's. Returns the occlusion rays traced.
pub fn refine(
    tree: &mut Tree,
    brightness: &mut Brightness,
    settings: &Settings,
    mut candidates: Vec<(u32, u32)>,
    links: &mut Vec<Link>,
) -> Result<usize, Stopped> {
    let binning = (settings.directions.len() > 1).then(|| Binning::new(settings.directions));
    let (mut rays, mut round, mut settled) = (0, 0, 0);
    while !candidates.is_empty() {
        if let Some(partition) = settings.partition {
            candidates.retain(|&(p, _)| partition.overlaps(tree, p));
        }
        let (held, pending) = (links.len(), candidates.len());
        let stop = || {
            crate::interrupt::check(|| {
                format!("the hierarchical kernel's linking ({held} links, {pending} candidate pairs to settle)")
            })
        };
        stop()?;
        footprint(tree, held, pending, settings.directions.len()).check(settings.memory_limit)?;
        round += 1;
        // A round can take minutes: a signal skips the rest of its pairs, and ends it; the
        // pairs settled are told a batch at a time.
        let mut outcomes: Vec<(Outcome, usize)> = Vec::with_capacity(pending);
        for batch in candidates.chunks(BATCH) {
            outcomes.par_extend(batch.par_iter().map(|&(p, q)| match crate::interrupt::asked() {
                true => (Outcome::Drop, 0),
                false => evaluate(tree, brightness, settings, binning.as_ref(), p, q),
            }));
            settled += batch.len() as u64;
            let what = format!("linking, round {round} ({pending} pairs, {held} links before it): pairs settled");
            settings.progress.at(settled, &what);
        }
        stop()?;
        let mut split = Vec::new();
        for ((outcome, r), &(p, q)) in outcomes.into_iter().zip(&candidates) {
            rays += r;
            match outcome {
                Outcome::Drop => {}
                Outcome::Keep(link) => links.push(link),
                Outcome::Split(n) => split.push((p, q, n)),
            }
        }
        candidates = Vec::with_capacity(4 * split.len());
        for &(p, q, n) in &split {
            split_node(tree, brightness, n, &|e| settings.backs.exposed_area(settings.visibility, e));
            children_pairs(tree, p, q, n, &mut candidates);
        }
    }
    Ok(rays)
}

/// What a round holds: the links so far, and the candidates, each of which may become a
/// link or split into up to four pairs; with the tree's nodes.
fn footprint(tree: &Tree, links: usize, candidates: usize, cells: usize) -> Footprint {
    let pairs = links + 4 * candidates;
    let bytes = (pairs * size_of::<Link>() + tree.len() * size_of::<Node>()) as f64;
    Footprint {
        what: "hierarchical kernel's linking (links, candidate pairs and elements)",
        bytes,
        nonzeros: pairs as f64,
        patches: tree.len(),
        cells,
    }
}

/// Splits `n` (a no-op for a cluster or an element already split); new nodes inherit
/// their parent's brightness.
pub fn split_node(tree: &mut Tree, brightness: &mut Brightness, n: u32, exposed: &Exposure<'_>) {
    tree.split(n, exposed);
    brightness.grow(tree);
}

/// The pairs that replace `(p, q)` once `n` (one of them) is split.
pub fn children_pairs(tree: &Tree, p: u32, q: u32, n: u32, out: &mut Vec<(u32, u32)>) {
    let children = tree.children(n);
    if p == q {
        out.extend(children.iter().flat_map(|&a| children.iter().map(move |&b| (a, b))));
    } else if n == p {
        out.extend(children.iter().map(|&c| (c, q)));
    } else {
        out.extend(children.iter().map(|&c| (p, c)));
    }
}

fn evaluate(
    tree: &Tree,
    brightness: &Brightness,
    settings: &Settings,
    binning: Option<&Binning>,
    p: u32,
    q: u32,
) -> (Outcome, usize) {
    // The last occluder is remembered within a pair, never across pairs: which pairs a
    // worker settles follows rayon's split, and the cached triangle's own test answers a
    // grazing ray otherwise than the traversal, so a shared cache made the links depend
    // on the number of threads.
    let blocker = &mut Blocker::default();
    let (a, b) = (tree.node(p), tree.node(q));
    if p == q {
        // a planar element does not see itself; a cluster's self-link is always split
        return (if a.patch().is_some() { Outcome::Drop } else { Outcome::Split(p) }, 0);
    }
    if let Some(n) = settings.oracle.at_contact(tree, p, q) {
        return (Outcome::Split(n), 0);
    }
    match (a.patch(), b.patch()) {
        (Some(pa), Some(pb)) => elements(tree, brightness.weight(p, q), settings, binning, (p, pa), (q, pb), blocker),
        _ => clusters(tree, brightness.weight(p, q), settings, p, q, blocker),
    }
}

/// A pair with a cluster at one end (or both). The bound ignores visibility; the factor of
/// an accepted link is multiplied by the visible fraction of the stand-ins' segments. A
/// pair whose stand-ins see nothing of each other is tested again from the corners of the
/// elements they stand on: four points do not stand for a cluster's view (a chair base's
/// rim sees the ceiling past its seat, the centroid of its top, the one stand-in that faces
/// up, does not). When a corner sees the other end the pair is refined, so its elements
/// decide, which drop an occluded pair only once the oracle accepts it; when none does (or
/// the pair cannot be refined) it is kept by the free share of segments drawn at random
/// between the two ends, if any is free ([`sampled_sight`]), else dropped: refined, two
/// rooms behind a wall would be refined down to their elements (`docs/hierarchy.md`,
/// "Occluded cluster links", "Occluded pairs tested by random segments").
fn clusters(
    tree: &Tree,
    brightness: f64,
    settings: &Settings,
    p: u32,
    q: u32,
    blocker: &mut Blocker,
) -> (Outcome, usize) {
    let (a, b) = (tree.node(p), tree.node(q));
    if !in_front(a, b) || !in_front(b, a) {
        return (Outcome::Drop, 0);
    }
    let bound = cluster_bound(a, b);
    let error = settings.oracle.error(a.albedo, bound, brightness);
    if settings.oracle.refines(error)
        && let Some(n) = settings.oracle.choose(tree, p, q)
    {
        return (Outcome::Split(n), 0);
    }
    let (from, to) = (stand_ins(tree, p, b.centre()), stand_ins(tree, q, a.centre()));
    let (seen, mut visible, mut rays) = stand_in_sight(settings.visibility, &from, &to, blocker);
    if seen == Sight::Occluded {
        let (open, more) = corners_see(settings.visibility, tree, p, q, blocker);
        if let Some(n) = open.then(|| settings.oracle.choose(tree, p, q)).flatten() {
            return (Outcome::Split(n), rays + more);
        }
        let (sampled, drawn) = sampled_sight(settings.visibility, tree, p, q, blocker);
        rays += more + drawn;
        if sampled <= 0.0 {
            return (Outcome::Drop, rays);
        }
        visible = sampled;
    }
    let (factor, mut pieces) = cluster_factor(tree, (p, q), settings.directions);
    pieces.iter_mut().for_each(|piece| piece.2 *= visible);
    (Outcome::Keep(Link::new(p, q, visible * factor, visible, bound, pieces)), rays)
}

/// False when `a` is an element and `b` lies wholly behind its plane.
fn in_front(a: &Node, b: &Node) -> bool {
    a.patch().is_none_or(|patch| b.reaches_front_of(patch))
}

/// A pair of elements.
fn elements(
    tree: &Tree,
    brightness: f64,
    settings: &Settings,
    binning: Option<&Binning>,
    (p, a): (u32, &Patch),
    (q, b): (u32, &Patch),
    blocker: &mut Blocker,
) -> (Outcome, usize) {
    if !facing(a, b) {
        return (Outcome::Drop, 0);
    }
    let oracle = &settings.oracle;
    let albedo = tree.node(p).albedo;
    let v = variation(a, b);
    let split = oracle.choose(tree, p, q);
    // the bound is at least the spread: a pair the spread alone refines is split unseen
    if oracle.refines(oracle.error(albedo, v.spread, brightness))
        && let Some(n) = split
    {
        return (Outcome::Split(n), 0);
    }
    let (mut seen, mut visible, mut rays) = sight(settings.visibility, a, b, blocker);
    // the light varies over the pair when a shadow boundary may cross it (4 or 16 blocked
    // segments do not prove that nothing passes) or some sample points see nothing of the
    // other element (their segments say nothing about visibility)
    let straddles = straddles(a, b) || straddles(b, a);
    let bound = if seen == Sight::Clear && !straddles { v.spread } else { v.largest };
    if oracle.refines(oracle.error(albedo, bound, brightness))
        && let Some(n) = split
    {
        return (Outcome::Split(n), rays);
    }
    // an occluded pair is kept with its factor unoccluded and visible fraction 0 when some
    // corner of `a` sees one of `b`: the leaves under `p` see `b` by their own rays
    // (`push.rs`), and some of them past what hid it from `a`'s four points (a chair's base
    // past its seat: `docs/hierarchy.md`, "A bundle per source"). Kept whether or not `p` is
    // a leaf now: it may be split later, and what a part's linking finds must not depend on
    // the order in which the tree was split (`model/part_rows.rs`). When no corner sees,
    // segments drawn at random decide, the pair kept as partly seen by their free share.
    if seen == Sight::Occluded {
        let (open, more) = corners_see(settings.visibility, tree, p, q, blocker);
        rays += more;
        if !open {
            let (sampled, drawn) = sampled_sight(settings.visibility, tree, p, q, blocker);
            rays += drawn;
            if sampled <= 0.0 {
                return (Outcome::Drop, rays);
            }
            (visible, seen) = (sampled, Sight::Partial);
        }
    }
    let open = if seen == Sight::Occluded { 1.0 } else { visible };
    let (factor, pieces) = element_factor(a, b, open, settings.quadrature, binning);
    if factor <= 0.0 {
        return (Outcome::Drop, rays);
    }
    (Outcome::Keep(Link::new(p, q, factor, visible, bound, pieces)), rays)
}

/// True when some sample point of `a` is not in front of `b`'s plane: the segments from it
/// say nothing about the light `a` gets from `b`, so its visibility test is not trusted.
fn straddles(a: &Patch, b: &Patch) -> bool {
    polygon_points(&a.polygon).iter().any(|&x| (x - b.centroid).dot(b.normal) <= 0.0)
}
