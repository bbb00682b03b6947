//! The linking's memory check (`kernel::hierarchy::refine`, issue 37, point 7): every round
//! of refinement starts only while its links, candidate pairs and elements fit in
//! `Options::memory_limit`; beyond it the hierarchy is refused with the figures, not
//! built until the allocator aborts. And a link's own size (issue 35, point 3).

use super::{hierarchy, measured_roots, options};
use std::path::Path;
use ugo::directions::DirectionSet;
use ugo::kernel::hierarchy::{Link, Options, Sight, Stopped};
use ugo::progress::Silent;
use ugo::scene::Scene;

#[test]
fn a_linking_beyond_the_memory_limit_is_refused_with_its_figures() {
    let scene = Scene::load(Path::new("cases/cornell-box.toml")).expect("the case loads");
    let (roots, visibility) = measured_roots(&scene, 0.25);
    let blocks = scene.materials.iter().map(|m| m.model.block(&DirectionSet::single())).collect();
    let l0: Vec<f64> = roots.emission.clone();
    let tight = Options { memory_limit: 1 << 20, ..options(1e-2, 0.05) };
    let refused =
        ugo::kernel::hierarchy::Hierarchy::new(&roots, visibility, DirectionSet::single(), blocks, tight, &l0, &Silent);
    let Err(Stopped::TooLarge(too_large)) = refused else { panic!("a 1 MiB limit is not refused") };
    let message = too_large.to_string();
    eprintln!("{message}");
    assert!(message.contains("hierarchical kernel's linking") && message.contains("GiB"), "{message}");
    // the same linking within the default limit
    let built = hierarchy(&scene, 0.25, DirectionSet::single(), options(1e-2, 0.05));
    assert!(built.links().len() > 10_000, "{} links: the 1 MiB refusal tested nothing", built.links().len());
}

#[test]
fn a_link_takes_32_bytes_and_keeps_its_pieces_and_sight() {
    assert!(size_of::<Link>() <= 32, "a link takes {} bytes", size_of::<Link>());
    let one = Link::new(1, 2, 0.25, 1.0, 0.5, Vec::new());
    assert!(one.pieces.is_empty() && one.sight() == Sight::Clear);
    let pieces = vec![(0, 3, 0.125), (2, 1, 0.125)];
    let split = Link::new(1, 2, 0.25, 11.0 / 16.0, 0.5, pieces.clone());
    assert_eq!((&*split.pieces, split.sight(), f64::from(split.visible)), (&pieces[..], Sight::Partial, 11.0 / 16.0));
    assert_eq!(Link::new(1, 2, 0.0, 0.0, 0.5, Vec::new()).sight(), Sight::Occluded);
}
