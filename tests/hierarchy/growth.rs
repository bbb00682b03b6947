//! Links grow much slower than N²: counts at three smallest sizes of a box with a block.

use super::{box_with_block, hierarchy, options};
use ugo::directions::DirectionSet;

#[test]
fn links_grow_much_slower_than_leaves_squared() {
    let scene = box_with_block(0.5);
    let counts: Vec<(f64, f64)> = [0.2, 0.1, 0.05]
        .iter()
        .map(|&h| {
            let hier = hierarchy(&scene, 1.0, DirectionSet::single(), options(1e-2, h));
            let (leaves, links, work) = (hier.tree().leaves().len(), hier.links().len(), hier.work());
            eprintln!(
                "growth: smallest {h} m: {leaves} leaves, {links} links, {} rays, {:.2} s",
                work.rays, work.seconds
            );
            (leaves as f64, links as f64)
        })
        .collect();
    let (first, last) = (counts[0], counts[counts.len() - 1]);
    let exponent = (last.1 / first.1).ln() / (last.0 / first.0).ln();
    eprintln!("growth: links ∝ N^{exponent:.2} over N = {} … {}", first.0, last.0);
    assert!(last.0 > 4.0 * first.0, "the leaves multiply");
    assert!(exponent < 1.5, "growth exponent {exponent}");
}
