//! Closure, reciprocity and occlusion of the form factors and of the assembled `G`.

use crate::support::{build, furnace, lambert, scene, surface};
use glam::DVec3;
use ugo::geometry::Mesh;
use ugo::geometry::facing;
use ugo::geometry::{Emission, Shape};
use ugo::transfer::form_factor::{Quadrature, form_factor};

/// Raw (unbalanced, unoccluded) form factors of every facing pair.
fn raw_matrix(mesh: &Mesh) -> Vec<Vec<f64>> {
    let q = Quadrature::default();
    let p = &mesh.patches;
    (0..p.len())
        .map(|i| {
            (0..p.len())
                .map(|j| if i != j && facing(&p[i], &p[j]) { form_factor(&p[i], &p[j], &q) } else { 0.0 })
                .collect()
        })
        .collect()
}

fn check_raw_closure_and_reciprocity(mesh: &Mesh) {
    let f = raw_matrix(mesh);
    let p = &mesh.patches;
    let mut worst_closure: f64 = 0.0;
    let mut worst_reciprocity: f64 = 0.0;
    for i in 0..p.len() {
        worst_closure = worst_closure.max((f[i].iter().sum::<f64>() - 1.0).abs());
        for j in 0..p.len() {
            let (a, b) = (p[i].area * f[i][j], p[j].area * f[j][i]);
            if a + b > 0.0 {
                worst_reciprocity = worst_reciprocity.max((a - b).abs() / a.max(b));
            }
        }
    }
    eprintln!("{} patches: closure error {worst_closure:.2e}, reciprocity error {worst_reciprocity:.2e}", p.len());
    assert!(worst_closure < 1e-3, "closure error {worst_closure}");
    assert!(worst_reciprocity < 1e-3, "reciprocity error {worst_reciprocity}");
}

#[test]
fn raw_form_factors_of_a_closed_box_close_and_are_reciprocal() {
    let s = furnace(1.0, 0.5, 1.0, 0.25);
    check_raw_closure_and_reciprocity(&Mesh::build(&s.surfaces, 0.25));
}

#[test]
fn raw_form_factors_of_a_closed_sphere_close_and_are_reciprocal() {
    let shape = Shape::Sphere { center: DVec3::ZERO, radius: 1.0 };
    let s =
        scene(vec![lambert("grey", 0.5)], vec![surface("sphere", shape, 0, true, Some(Emission::Luminance(1.0)))], 0.5);
    check_raw_closure_and_reciprocity(&Mesh::build(&s.surfaces, 0.5));
}

#[test]
fn assembled_transport_is_closed_and_reciprocal() {
    let model = build(&furnace(2.0, 0.5, 1.0, 0.4));
    let g = model.kernel.g.as_double().expect("double precision by default");
    let a: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    for (i, row) in g.outer_iterator().enumerate() {
        assert!((row.data().iter().sum::<f64>() - 1.0).abs() < 1e-12);
        for (j, &v) in row.iter() {
            let back = g.get(j, i).copied().unwrap_or(0.0);
            assert!((a[i] * v - a[j] * back).abs() <= 1e-12 * a[i] * v);
        }
    }
    let balance = model.stats.balance.expect("the uniform kernel is balanced");
    assert!(balance.max_correction < 1e-3, "{balance:?}");
}

#[test]
fn coaxial_unit_discs_one_apart() {
    let disc =
        |z: f64, n: f64| Shape::Disc { center: DVec3::new(0.0, 0.0, z), normal: DVec3::new(0.0, 0.0, n), radius: 1.0 };
    let s = scene(
        vec![lambert("black", 0.0)],
        vec![
            surface("lower", disc(0.0, 1.0), 0, false, Some(Emission::Luminance(1.0))),
            surface("upper", disc(1.0, -1.0), 0, false, None),
        ],
        0.1,
    );
    let model = build(&s);
    let p = &model.mesh.patches;
    let (mut exchange, mut area) = (0.0, 0.0);
    for (i, row) in model.kernel.g.as_double().expect("double precision by default").outer_iterator().enumerate() {
        if p[i].surface == 0 {
            area += p[i].area;
            exchange += p[i].area * row.iter().filter(|(j, _)| p[*j].surface == 1).map(|(_, v)| v).sum::<f64>();
        }
    }
    let f = exchange / area;
    eprintln!("coaxial discs: F = {f:.6}");
    assert!((f / 0.3819660 - 1.0).abs() < 5e-3, "{f}");
}

#[test]
fn an_opaque_screen_removes_the_exchange_it_hides() {
    let square = |z: f64, up: bool| {
        let (u, v) = if up { (DVec3::X, DVec3::Y) } else { (DVec3::Y, DVec3::X) };
        Shape::Rectangle { origin: DVec3::new(0.0, 0.0, z), edge_u: u, edge_v: v }
    };
    let big = Shape::Rectangle {
        origin: DVec3::new(-1.0, -1.0, 0.5),
        edge_u: DVec3::new(3.0, 0.0, 0.0),
        edge_v: DVec3::new(0.0, 3.0, 0.0),
    };
    let s = scene(
        vec![lambert("grey", 0.5)],
        vec![
            surface("bottom", square(0.0, true), 0, false, Some(Emission::Luminance(1.0))),
            surface("top", square(1.0, false), 0, false, None),
            surface("screen", big, 0, false, None),
        ],
        1.0,
    );
    let model = build(&s);
    let p = &model.mesh.patches;
    for (i, row) in model.kernel.g.as_double().expect("double precision by default").outer_iterator().enumerate() {
        for (j, _) in row.iter() {
            let pair = (p[i].surface, p[j].surface);
            assert!(pair != (0, 1) && pair != (1, 0), "bottom and top exchange through the screen");
        }
    }
}

/// Issue 17, item 6: the rows are integrated in an order that visits each once and spreads
/// the first rows over the whole mesh, so the pairs done measure the work done.
#[test]
fn the_row_order_visits_every_row_once_and_spreads_the_first_ones() {
    for n in [0, 1, 2, 3, 10, 97, 1000, 1024, 4096] {
        let stride = ugo::kernel::row_stride(n);
        let mut seen = vec![false; n];
        for k in 0..n {
            let i = k * stride % n;
            assert!(!seen[i], "n = {n}: row {i} twice");
            seen[i] = true;
        }
        if n < 100 {
            continue;
        }
        // Row i has n − i − 1 pairs: each tenth of the order holds about a tenth of them.
        let total = (n * (n - 1) / 2) as f64;
        for tenth in 0..10 {
            let pairs: usize = (tenth * n / 10..(tenth + 1) * n / 10).map(|k| n - k * stride % n - 1).sum();
            assert!((pairs as f64 / total - 0.1).abs() < 0.01, "n = {n}, tenth {tenth}: {pairs} of {total}");
        }
    }
}
