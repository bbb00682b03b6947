//! A part file (issue 36, point 4) reads back as it was linked: every link, its ends'
//! addresses, factor, visible fraction and cell pieces, and the counts; read for another
//! part's rows, only its links into clusters.

use crate::support::scratch;
use ugo::directions::Scheme;
use ugo::io::{read_part, read_part_for, write_part};
use ugo::kernel::hierarchy::Part;
use ugo::model::{Fingerprint, link_part};
use ugo::progress::Silent;
use ugo::scene::{Asked, Given, KernelAsked, KernelKind, Scene};

#[test]
fn a_part_file_reads_back_as_linked() {
    let mut scene = Scene::load(std::path::Path::new("cases/glossy-cornell.toml")).expect("the case loads");
    let asked = Asked {
        patch_size: Some(Given::flag("--patch-size")(0.1)),
        root_size: Some(Given::flag("--root-size")(0.4)),
        kernel: Some(Given::flag("--kernel")(KernelAsked::Hierarchical)),
        directions: Some(Scheme::Cells(4)),
        ..Asked::default()
    };
    scene.discretize(&asked).expect("discretized");
    let KernelKind::Hierarchical(parameters) = scene.discretization.kernel else { panic!("hierarchical") };
    let links = link_part(&scene, parameters, Part { index: 1, count: 2 }, &Silent).expect("linked");
    assert!(links.links.iter().any(|l| !l.pieces.is_empty() && !l.receiver.path.is_empty()));
    let dir = scratch("part-file");
    let path = dir.join("p.h5");
    write_part(&path, &Fingerprint::of(&scene), &links).expect("written");
    let back = read_part(&path).expect("read");
    assert_eq!(back.fingerprint, Fingerprint::of(&scene));
    assert_eq!(back.links.links, links.links);
    assert_eq!(back.links.splits, links.splits);
    assert!(!links.splits.is_empty(), "the part's linking split elements");
    assert_eq!(
        (back.links.cut, back.links.own_roots, back.links.partition),
        (links.cut, links.own_roots, links.partition)
    );
    let own = read_part_for(&path, Some(Part { index: 1, count: 2 })).expect("read for its own rows");
    assert_eq!(own.links.links, links.links);
    let other = read_part_for(&path, Some(Part { index: 0, count: 2 })).expect("read for part 0's rows");
    let into_clusters: Vec<_> =
        links.links.iter().filter(|l| l.receiver.top as usize >= links.roots).cloned().collect();
    assert!(into_clusters.len() < links.links.len(), "the links into elements are left out");
    assert_eq!(other.links.links, into_clusters);
    assert_eq!(other.links.splits, links.splits);
}
