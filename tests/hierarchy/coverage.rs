//! Every ordered pair of facing leaves of a closed box is covered by exactly one link
//! between an ancestor of one and an ancestor of the other (that is what keeps closure).

use super::{hierarchy, options};
use crate::support::furnace;
use ugo::directions::DirectionSet;
use ugo::geometry::facing;
use ugo::kernel::hierarchy::{Hierarchy, NONE};
use ugo::progress::Silent;

/// Leaf indices under node `id`.
fn leaves_under(h: &Hierarchy, index: &[u32], id: u32, out: &mut Vec<usize>) {
    if index[id as usize] != NONE {
        out.push(index[id as usize] as usize);
    }
    for &c in h.tree().children(id) {
        leaves_under(h, index, c, out);
    }
}

#[test]
fn every_facing_leaf_pair_is_covered_once() {
    let mut h = hierarchy(&furnace(1.0, 0.5, 1.0, 1.0), 1.0, DirectionSet::single(), options(2e-3, 0.125));
    let op = h.operator(&Silent);
    let mesh = h.leaf_mesh();
    let n = mesh.len();
    let mut index = vec![NONE; h.tree().len()];
    op.leaves().iter().enumerate().for_each(|(l, &id)| index[id as usize] = l as u32);
    let mut count = vec![0u8; n * n];
    let (mut p, mut q) = (Vec::new(), Vec::new());
    let mut levels = std::collections::BTreeSet::new();
    for link in h.links() {
        p.clear();
        q.clear();
        leaves_under(&h, &index, link.receiver, &mut p);
        leaves_under(&h, &index, link.source, &mut q);
        levels.insert((p.len(), q.len()));
        for &i in &p {
            for &j in &q {
                count[i * n + j] += 1;
            }
        }
    }
    for i in 0..n {
        for j in 0..n {
            let expected = (i != j && facing(&mesh.patches[i], &mesh.patches[j])) as u8;
            assert_eq!(count[i * n + j], expected, "leaves {i} and {j}");
        }
    }
    eprintln!(
        "coverage: {n} leaves, {} links, {} distinct (receiver leaves, source leaves) sizes",
        h.links().len(),
        levels.len()
    );
    assert!(levels.len() > 2, "links at several levels");
}
