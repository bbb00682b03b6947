//! The shadow rays of links in `ugo bench` (issue 35): the segments of links between random
//! facing patch pairs as a link traces them (`transfer::occlusion::fraction_between`: the 4
//! between matching points, the other 12 when those disagree), each link with no blocker
//! known, traced on one thread one by one (`Visibility::visible_cached`) and together
//! (`Visibility::visible_together`), the two alternating, the better of two runs each.

use super::pairs::facing_pairs;
use crate::geometry::Mesh;
use crate::transfer::occlusion::{POINTS, sample_points};
use crate::visibility::{Blocker, Segment, Visibility};
use std::time::Instant;

/// A link's segments, those between matching points first, and whether all are traced.
type Link = ([Segment; POINTS * POINTS], bool);

/// Links traced one by one and together.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkRays {
    /// Links timed.
    pub links: usize,
    /// Their rays (4 or 16 a link).
    pub rays: usize,
    /// Links per second, their segments traced one by one.
    pub alone_links_per_second: f64,
    /// Links per second, their segments traced together.
    pub together_links_per_second: f64,
}

impl LinkRays {
    /// Times `count` links between random facing patch pairs of `mesh`; `None` without a
    /// facing pair.
    pub fn measure(mesh: &Mesh, visibility: &Visibility, count: usize) -> Option<LinkRays> {
        let links = facing_pairs(mesh, count, |a, b, _| {
            let (pa, pb) = (sample_points(a), sample_points(b));
            let segment = |(k, m): (usize, usize)| (pa[k], pb[m], [a.face, b.face]);
            let order = (0..POINTS)
                .map(|k| (k, k))
                .chain((0..POINTS).flat_map(|k| (0..POINTS).map(move |m| (k, m))).filter(|(k, m)| k != m));
            let mut segments = [segment((0, 0)); POINTS * POINTS];
            segments.iter_mut().zip(order).for_each(|(s, km)| *s = segment(km));
            let first = visibility.visible_together(&segments[..POINTS], &mut Blocker::default()).count_ones();
            (segments, first != 0 && first != POINTS as u32)
        })?;
        let rays = links.iter().map(|(_, all)| if *all { POINTS * POINTS } else { POINTS }).sum();
        let (mut alone, mut together) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..2 {
            alone = alone.min(seconds(&links, |s, blocker| {
                s.iter().filter(|&&(a, b, ignore)| visibility.visible_cached(a, b, ignore, blocker)).count() as u32
            }));
            together = together.min(seconds(&links, |s, blocker| visibility.visible_together(s, blocker).count_ones()));
        }
        let n = links.len() as f64;
        Some(LinkRays {
            links: links.len(),
            rays,
            alone_links_per_second: n / alone,
            together_links_per_second: n / together,
        })
    }
}

/// Seconds to trace every link with `free` (the free segments of a set).
fn seconds(links: &[Link], free: impl Fn(&[Segment], &mut Blocker) -> u32) -> f64 {
    let t = Instant::now();
    let seen: u32 = links
        .iter()
        .map(|(segments, all)| {
            let blocker = &mut Blocker::default();
            free(&segments[..POINTS], blocker) + if *all { free(&segments[POINTS..], blocker) } else { 0 }
        })
        .sum();
    std::hint::black_box(seen);
    t.elapsed().as_secs_f64()
}
