//! A part's rows from the part files (issue 36, point 4; `docs/petsc.md`, "The operator
//! from the part files") are the one-process operator's rows: the same tree and leaves,
//! the parts' bundles in turn the one-process bundles with the same gathered pieces, each
//! own leaf's push shares, `L0` and direct light the one-process leaf's, on a room whose
//! leaves are split along a luminaire's light before the solve.

use std::path::Path;
use ugo::kernel::hierarchy::{BundleKey, Part};
use ugo::model::{Model, PartLinks, PartRows, link_part, part_rows};
use ugo::progress::Silent;
use ugo::scene::{Hierarchical, KernelKind, Scene};

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300)
}

/// Push shares, held in f32: within one rounding of each other (the part sums its leaves'
/// views in another order).
fn close_shares(a: f32, b: f32) -> bool {
    (a - b).abs() <= f32::EPSILON * a.abs().max(b.abs())
}

#[test]
#[ignore = "about a minute: make test-long"]
fn the_parts_rows_are_the_one_process_operators_rows() {
    let mut scene = Scene::load(Path::new("cases/office.toml")).expect("the case loads");
    scene.discretization.patch_size = 0.4;
    let parameters = Hierarchical { root_size: 1.0, link_tolerance: 2e-2, passes: 1 };
    scene.discretization.kernel = KernelKind::Hierarchical(parameters);
    let whole = Model::build_to_save(&scene, &Silent).expect("built in one process");
    let op = whole.kernel.g.hierarchy().expect("a hierarchy").parts();
    let count = 2;
    let part = |index| Part { index, count };
    let links: Vec<PartLinks> = (0..count).map(|i| link_part(&scene, parameters, part(i), &Silent).unwrap()).collect();
    let joined: Vec<&PartLinks> = links.iter().collect();
    let rows: Vec<PartRows> =
        (0..count).map(|i| part_rows(&scene, parameters, part(i), &joined, &Silent).expect("rows")).collect();
    let k = whole.l0.len() / op.leaves.len();
    assert!(rows.iter().all(|r| r.rows.parent == op.parent && r.rows.leaf_position == op.leaf_position));
    assert!(rows.iter().all(|r| r.rows.weight.iter().zip(&op.weight).all(|(a, b)| close(*a, *b))));
    assert!(
        rows.iter().all(|r| r.rows.facing_share == op.facing_share),
        "the clusters' facing shares as in one process"
    );
    let tiles = rows.windows(2).all(|w| w[0].rows.own_leaves.end == w[1].rows.own_leaves.start);
    assert!(tiles && rows[0].rows.own_leaves.start == 0 && rows[1].rows.own_leaves.end == op.leaves.len());
    let keys: Vec<BundleKey> = rows.iter().flat_map(|r| r.rows.bundles.iter().copied()).collect();
    assert!(keys.windows(2).all(|w| w[0] < w[1]), "the parts' bundles follow on in the one-process order");
    assert_eq!(keys.len() + 1, op.row.len(), "as many bundles as in one process");
    let mut b = 0;
    for r in &rows {
        for local in 0..r.rows.bundles.len() {
            let mine = &r.rows.entries[r.rows.row[local]..r.rows.row[local + 1]];
            assert_eq!(mine, &op.entries[op.row[b]..op.row[b + 1]], "bundle {b}'s pieces");
            b += 1;
        }
    }
    for r in &rows {
        for (l, leaf) in r.rows.own_leaves.clone().enumerate() {
            let mine = &r.rows.push[r.rows.push_row[l]..r.rows.push_row[l + 1]];
            let theirs = &op.push[op.push_row[leaf]..op.push_row[leaf + 1]];
            assert_eq!(mine.len(), theirs.len(), "leaf {leaf}'s push");
            for ((key, share), (bundle, other)) in mine.iter().zip(theirs) {
                assert_eq!(keys.binary_search(key), Ok(*bundle as usize), "leaf {leaf}'s bundles");
                assert!(close_shares(*share, *other), "leaf {leaf}'s share {share} against {other}");
            }
        }
        let (a, e) = (r.rows.own_leaves.start * k, r.rows.own_leaves.end * k);
        assert!(r.l0.iter().zip(&whole.l0[a..e]).all(|(x, y)| close(*x, *y)), "L0 of part {}", r.part);
        assert!(r.arriving.iter().zip(&whole.direct.arriving[a..e]).all(|(x, y)| close(*x, *y)));
    }
    let history = &whole.hierarchy.as_ref().expect("the record").history;
    assert!(history[0].source_splits > 0, "leaves were split along the light before the solve");
    eprintln!("{} leaves, {} bundles in {count} parts", op.leaves.len(), keys.len());
}
