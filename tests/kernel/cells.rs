//! The kernel split by direction cells: `G[(i,d),(j,m)] = F_ij^{d,m}`, and `K = B·G`.

use crate::support::{build_with, furnace};
use ugo::directions::DirectionSet;
use ugo::geometry::facing;
use ugo::kernel::{Explicit, Factored};
use ugo::transfer::form_factor::{Binning, Quadrature, binned_pair_integral, pair_integral};

#[test]
fn binned_pieces_sum_to_the_one_cell_form_factors() {
    let scene = furnace(1.0, 0.5, 1.0, 0.34);
    let set = DirectionSet::hemisphere(16);
    let binning = Binning::new(&set);
    let q = Quadrature::default();
    let p = &build_with(&scene, DirectionSet::single()).mesh.patches;
    let mut bins = Vec::new();
    let mut worst: f64 = 0.0;
    for a in p {
        for b in p.iter().filter(|b| facing(a, b)) {
            bins.clear();
            let whole = binned_pair_integral(a, b, &q, &binning, &mut bins);
            assert_eq!(whole, pair_integral(a, b, &q));
            let sum: f64 = bins.iter().map(|t| t.2).sum();
            worst = worst.max((sum - whole.adaptive).abs() / whole.adaptive);
            assert!(bins.iter().all(|t| (t.0 as usize) < 16 && (t.1 as usize) < 16));
        }
    }
    assert!(worst < 1e-12, "{worst}");
}

#[test]
fn binned_transport_is_reciprocal_cell_by_cell() {
    let model = build_with(&furnace(1.0, 0.5, 1.0, 0.34), DirectionSet::hemisphere(16));
    let g = model.kernel.g.as_double().expect("double precision by default");
    let area: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    for (r, row) in g.outer_iterator().enumerate() {
        for (c, &v) in row.iter() {
            let back = g.get(c, r).copied().unwrap_or(0.0);
            assert!((area[r / 16] * v - area[c / 16] * back).abs() <= 1e-13 * area[r / 16] * v);
        }
    }
}

#[test]
fn cell_rows_of_a_closed_room_carry_their_projected_solid_angle() {
    let scene = furnace(1.0, 0.5, 1.0, 0.2);
    let set = DirectionSet::hemisphere(16);
    let model = build_with(&scene, set.clone());
    let mut worst: f64 = 0.0;
    for (row, v) in model.kernel.g.as_double().expect("double precision by default").outer_iterator().enumerate() {
        let mu = set.cells()[row % 16].projected / std::f64::consts::PI;
        worst = worst.max((v.data().iter().sum::<f64>() / mu - 1.0).abs());
    }
    // Balanced to exactly μ_d/π: before balancing the binning left 12.6 % here.
    assert!(worst < 1e-12, "{worst}");
}

#[test]
fn explicit_and_factored_kernels_agree() {
    let mut scene = furnace(1.0, 0.5, 1.0, 0.34);
    scene.materials[0].model = ugo::material::MaterialModel::Phong { diffuse: 0.2, specular: 0.6, exponent: 20.0 };
    let model = build_with(&scene, DirectionSet::hemisphere(24));
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let factored = Factored::new(&model.kernel);
    let n = factored.dim();
    let mut state = 7u64;
    let x: Vec<f64> = (0..n)
        .map(|_| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect();
    let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
    explicit.apply(&x, &mut a);
    factored.apply(&x, &mut b);
    let diff = a.iter().zip(&b).map(|(p, q)| (p - q) * (p - q)).sum::<f64>().sqrt();
    let norm = b.iter().map(|q| q * q).sum::<f64>().sqrt();
    assert!(diff <= 1e-12 * norm, "{diff} vs {norm}");
}

#[test]
fn an_explicit_product_over_the_limit_is_refused_with_the_estimate() {
    let scene = furnace(1.0, 0.5, 1.0, 0.34);
    let model = build_with(&scene, DirectionSet::hemisphere(16));
    let err = model.kernel.explicit(1 << 10).unwrap_err().to_string();
    assert!(err.contains("explicit product") && err.contains("factored operator") && err.contains("GiB"), "{err}");
}

#[test]
fn the_memory_estimate_bounds_the_assembled_kernel() {
    let mut scene = ugo::scene::Scene::load(std::path::Path::new("cases/glossy-cornell.toml")).unwrap();
    scene.discretization.patch_size = 0.1;
    for set in [DirectionSet::single(), DirectionSet::hemisphere(64)] {
        let model = build_with(&scene, set.clone());
        let estimate = ugo::kernel::Forecast::counted(&model.mesh, scene.materials.len(), &set);
        let actual = model.kernel.g.nnz() as f64;
        eprintln!("K = {}: estimated {:.0} non-zeros, assembled {actual}", set.len(), estimate.nonzeros);
        assert!(estimate.nonzeros >= actual && estimate.nonzeros < 3.0 * actual, "{} vs {actual}", estimate.nonzeros);
    }
}
