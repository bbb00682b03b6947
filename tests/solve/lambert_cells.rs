//! Direction cells change nothing for Lambertian materials: the Cornell box of
//! `cases/cornell-box.toml` (0.08 m patches, 519 patches) solved with `K = 1` and with
//! `K = 128` cells gives the same luminance for every patch in every cell.
//!
//! The blocks are constant in the cells (`ρ̄ ≡ r`) and, before balancing, the cells of
//! each pair of patches sum to its one-cell form factor to round-off. Balancing row by
//! `(patch, cell)` then moves exchange between pairs by up to the binning's error where a
//! patch is fully enclosed, so the two differ at the level of that discretization error.
//! Measured: max relative difference 4.5e-4, over every (patch, cell).

use crate::support::{build_with, solve};
use std::path::Path;
use ugo::directions::DirectionSet;
use ugo::scene::Scene;

const CELLS: usize = 128;

#[test]
fn lambertian_cornell_box_is_the_same_with_one_and_with_128_cells() {
    let mut scene = Scene::load(Path::new("cases/cornell-box.toml")).unwrap();
    scene.discretization.patch_size = 0.08;
    let one = solve(&build_with(&scene, DirectionSet::single()));
    let many = solve(&build_with(&scene, DirectionSet::hemisphere(CELLS)));
    let (mut worst, mut squares, mut count) = (0.0f64, 0.0, 0usize);
    for (i, &l) in one.iter().enumerate().filter(|&(_, &l)| l > 0.0) {
        for &m in &many[i * CELLS..(i + 1) * CELLS] {
            let r = m / l - 1.0;
            worst = worst.max(r.abs());
            squares += r * r;
            count += 1;
        }
    }
    let rms = (squares / count as f64).sqrt();
    eprintln!("cornell, K = 1 against K = {CELLS}: {} patches lit, max {worst:.1e}, rms {rms:.1e}", count / CELLS);
    assert!(one.len() > 500 && count > 500 * CELLS);
    assert!(worst < 1e-3, "max relative difference {worst}");
}
