//! With tolerance 0 and smallest size `h`, the hierarchy links every pair at the leaves and
//! agrees with the explicit (balanced) kernel assembled on the same leaf mesh.

use super::{box_with_block, hierarchy, options, relative_difference};
use crate::support::furnace;
use ugo::directions::DirectionSet;
use ugo::kernel::{Factored, Kernel, Precision, Transport, TransportMatrix, assemble};
use ugo::scene::Scene;
use ugo::transfer::form_factor::Quadrature;
use ugo::visibility::Visibility;

fn compare(scene: Scene, directions: DirectionSet, limit: f64) {
    let h = hierarchy(&scene, 1.0, directions.clone(), options(0.0, 0.25));
    let op = h.operator();
    let leaves = h.leaf_mesh();
    let visibility = Visibility::build(&leaves);
    let t = assemble(&leaves, &visibility, &directions, &Quadrature::default(), &|_| {}).unwrap();
    let kernel = Kernel {
        g: Transport::Explicit(TransportMatrix::new(t.g, Precision::Double)),
        directions: directions.clone(),
        blocks: blocks(&scene, &directions),
        patch_material: leaves.patches.iter().map(|p| p.material).collect(),
        twin: leaves.patches.iter().map(|p| p.twin).collect(),
    };
    let explicit = Factored::new(&kernel);
    assert_eq!(op.dim(), explicit.dim());
    let x: Vec<f64> = (0..op.dim()).map(|i| 1.0 + 0.5 * (i as f64 * 0.37).sin()).collect();
    let (mut a, mut b) = (vec![0.0; x.len()], vec![0.0; x.len()]);
    op.apply(&x, &mut a);
    explicit.apply(&x, &mut b);
    let difference = relative_difference(&a, &b);
    eprintln!(
        "hierarchy vs explicit, K = {}: {} leaves, {} links ({} explicit pairs), max |Δ(Kx)|/max|Kx| = {difference:.2e}",
        directions.len(),
        leaves.len(),
        op.links(),
        t.pairs
    );
    assert!(difference < limit, "difference {difference}");
}

fn blocks(scene: &Scene, directions: &DirectionSet) -> Vec<ugo::material::Block> {
    scene.materials.iter().map(|m| m.model.block(directions)).collect()
}

#[test]
fn tolerance_zero_agrees_with_the_explicit_kernel_on_the_leaves() {
    // no occlusion: both close exactly and their factors agree
    compare(furnace(1.0, 0.5, 1.0, 1.0), DirectionSet::single(), 1e-5);
    // a block casting shadows: the two close to different visibility estimates where the
    // 4 × 4 segments see it partly (explicit: adaptive row sums, hierarchy: point factors)
    compare(box_with_block(0.5), DirectionSet::single(), 1e-2);
}
