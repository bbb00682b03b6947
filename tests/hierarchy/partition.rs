//! The partitioned linking (issue 36, point 4): the links each part's own linking keeps for
//! the receivers it owns, joined by their ends' addresses, are the one-process linking's,
//! factor for factor, and the partition puts every root in exactly one part.

use super::{box_with_block, hierarchy, options};
use std::collections::BTreeMap;
use ugo::directions::DirectionSet;
use ugo::kernel::hierarchy::{Address, Hierarchy, Link, Options, Part, Tree};

type Key = (Address, Address);

/// The links of `h` (those its partition owns, when it has one) by their ends' addresses.
fn by_address(h: &Hierarchy) -> BTreeMap<Key, Link> {
    let tree = h.tree();
    let owned = |link: &&Link| h.partition().is_none_or(|p| p.owns(tree, link.receiver));
    let keyed = h.links().iter().filter(owned).map(|l| ((tree.address(l.receiver), tree.address(l.source)), l.clone()));
    let mut out = BTreeMap::new();
    for (key, link) in keyed {
        assert!(out.insert(key, link).is_none(), "two links between the same nodes");
    }
    out
}

/// A link with its ends' ids cleared (ids follow the order of splits, addresses do not).
fn content(link: &Link) -> Link {
    Link { receiver: 0, source: 0, ..link.clone() }
}

fn joined_parts_equal_one_process(directions: DirectionSet, count: u32) {
    let scene = box_with_block(0.6);
    let settings = Options { passes: 1, ..options(2e-2, 0.125) };
    let whole = by_address(&hierarchy(&scene, 0.5, directions.clone(), settings));
    let mut joined = BTreeMap::new();
    let mut per_part = Vec::new();
    for index in 0..count {
        let part = Some(Part { index, count });
        let h = hierarchy(&scene, 0.5, directions.clone(), Options { part, ..settings });
        let partition = h.partition().expect("a part's hierarchy knows its partition");
        let roots: Vec<u32> = (0..h.tree().len() as u32).filter(|&id| h.tree().address(id).top == id).collect();
        let in_part =
            roots.iter().filter(|&&r| h.tree().node(r).patch().is_some()).map(|&r| partition.mask(h.tree(), r));
        let masks: Vec<u64> = in_part.collect();
        assert!(masks.iter().all(|m| m.count_ones() == 1), "every root in exactly one part");
        assert!((0..count).all(|i| masks.iter().any(|m| m & (1 << i) != 0)), "no part empty");
        let mine = by_address(&h);
        per_part.push(mine.len());
        for (key, link) in mine {
            assert!(joined.insert(key, link).is_none(), "a link owned by two parts");
        }
    }
    eprintln!("partition: {} links in one process, {per_part:?} in {count} parts", whole.len());
    assert_eq!(joined.len(), whole.len(), "as many links joined as in one process");
    for ((key, a), (other, b)) in joined.iter().zip(&whole) {
        assert_eq!(key, other, "the same links");
        assert_eq!(content(a), content(b), "the same factor, sight and pieces");
    }
}

#[test]
fn two_parts_join_into_the_one_process_links() {
    joined_parts_equal_one_process(DirectionSet::single(), 2);
}

#[test]
fn three_parts_with_cells_join_into_the_one_process_links() {
    joined_parts_equal_one_process(DirectionSet::hemisphere(8), 3);
}

#[test]
fn bad_parts_are_refused_by_name() {
    let refused = |s: &str| s.parse::<Part>().expect_err(s).to_string();
    assert_eq!("1/2".parse::<Part>(), Ok(Part { index: 1, count: 2 }));
    assert!(refused("2/2").contains("below the number of parts (0 to 1)"), "{}", refused("2/2"));
    assert!(refused("0/0").contains("at least 1"), "{}", refused("0/0"));
    assert!(refused("1-2").contains("expected i/n"), "{}", refused("1-2"));
    assert!(refused("a/2").contains("expected i/n"), "{}", refused("a/2"));
    assert!(refused("0/65").contains("at most 64"), "{}", refused("0/65"));
}

/// A pair of twins is cut from the same side whichever of them is asked to split, so that
/// an address names the same piece in every process (a part's linking may split the back
/// of a pane that the one process split from the front): the building's parts read
/// weights 0.17 apart from the one process's before.
#[test]
fn twins_are_cut_alike_whichever_side_is_split() {
    let scene = ugo::scene::Scene::load(std::path::Path::new("cases/opal-diffuser.toml")).expect("the case loads");
    let mesh = ugo::geometry::Mesh::build(&scene.surfaces, 0.5);
    let exposed: Vec<f64> = mesh.patches.iter().map(|p| p.polygon.area()).collect();
    let albedo = vec![0.5; scene.materials.len()];
    let front = (0..mesh.patches.len()).find(|&i| mesh.patches[i].twin != ugo::geometry::NO_TWIN).expect("a pane");
    let back = mesh.patches[front].twin as usize;
    let area = |p: &ugo::geometry::Patch| p.polygon.area();
    let (mut a, mut b) = (Tree::new(&mesh, &albedo, &exposed), Tree::new(&mesh, &albedo, &exposed));
    a.split(front as u32, &area);
    b.split(back as u32, &area);
    for root in [front as u32, back as u32] {
        let centres = |t: &Tree| -> Vec<glam::DVec3> {
            t.children(root).iter().map(|&c| t.node(c).patch().expect("an element").polygon.centroid()).collect()
        };
        assert_eq!(centres(&a).len(), 4);
        let close = centres(&a).iter().zip(&centres(&b)).all(|(p, q)| (*p - *q).length() < 1e-12);
        assert!(close, "root {root}: {:?} against {:?}", centres(&a), centres(&b));
    }
}
