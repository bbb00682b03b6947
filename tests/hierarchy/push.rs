//! The leaves' views of their sources kept between operator builds
//! (`push.rs`, `SeenCache`): after a refinement pass the operator (`G`) built with what was
//! kept is the one built afresh (a fraction read back wrong by 1 % fails it).

use super::{box_with_block, hierarchy, kernel, options, relative_difference, solver};
use ugo::directions::DirectionSet;
use ugo::geometry::Emission;
use ugo::kernel::hierarchy::{Operator, Options, SeenCache};
use ugo::progress::Silent;
use ugo::solve::Method;

#[test]
fn kept_push_weights_give_the_operator_built_afresh() {
    // the room dark, the block lit: the solved field differs from the first guess (the
    // ambient term) and the pass refines links of elements above the leaves
    let mut scene = box_with_block(0.8);
    scene.surfaces[0].emission = None;
    scene.surfaces[1].emission = Some(Emission::Luminance(100.0));
    let directions = DirectionSet::single();
    // unbalanced: the balancing factors would follow any difference of the weights
    let mut h = hierarchy(&scene, 0.5, directions.clone(), Options { balance: false, ..options(3e-2, 0.05) });
    let first = kernel(&mut h);
    let x = solver(Method::Neumann)(&first, &h.emission(), 1.0).unwrap();
    let refined = h.refine(&x, None, &Silent).expect("the pass fits in memory");
    assert!(refined > 0, "the solved field refines some links");
    let kept = h.operator(&Silent);
    let fresh = Operator::new(h.tree(), (h.visibility(), h.links()), &directions, &mut SeenCache::default(), &Silent);
    let y: Vec<f64> = (0..kept.dim()).map(|i| 1.0 + (i % 7) as f64).collect();
    let (mut a, mut b) = (vec![0.0; y.len()], vec![0.0; y.len()]);
    kept.arriving(&y, &mut a);
    fresh.arriving(&y, &mut b);
    let difference = relative_difference(&a, &b);
    eprintln!(
        "push weights kept: {refined} links refined, {} leaves, max |Δ(Gx)|/max|Gx| = {difference:.1e}",
        kept.dim()
    );
    assert!(difference < 1e-14, "{difference}");
}
