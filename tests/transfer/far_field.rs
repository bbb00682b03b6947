//! The far-field cubature against Lambert's contour integral and the adaptive pair rule.

use glam::DVec3;
use ugo::geometry::{ConvexPolygon, Patch};
use ugo::random::Rng;
use ugo::transfer::contour::point_to_patch;
use ugo::transfer::far_field::{FAR, far_pair_integral, is_far, point_factor};
use ugo::transfer::form_factor::{Quadrature, pair_integral};

/// A random quad (a parallelogram or a trapezoid) or triangle of size about `size` at `at`,
/// turned at random.
fn random_patch(rng: &mut Rng, at: DVec3, size: f64) -> Patch {
    let unit = |rng: &mut Rng| {
        let v = DVec3::new(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
        v.normalize_or(DVec3::X)
    };
    let (u, w) = (unit(rng), unit(rng));
    let v = u.cross(w).cross(u).normalize_or(u.any_orthonormal_vector());
    let (a, b) = (size * (0.3 + rng.uniform()), size * (0.3 + rng.uniform()));
    let taper = 0.3 + 0.7 * rng.uniform();
    let polygon = match rng.uniform() < 0.25 {
        true => ConvexPolygon::triangle(at, at + a * u, at + b * v),
        false => ConvexPolygon::quad(at, at + a * u, at + a * taper * u + b * v, at + b * v),
    };
    Patch::from_polygon(polygon, 0, 0, 0)
}

/// The same polygon facing the other way.
fn turned_over(t: &Patch) -> Patch {
    let v = t.polygon.vertices();
    let polygon = match v.len() {
        3 => ConvexPolygon::triangle(v[0], v[2], v[1]),
        _ => ConvexPolygon::quad(v[0], v[3], v[2], v[1]),
    };
    Patch::from_polygon(polygon, 0, 0, 0)
}

/// Pairs of random patches at random distances, each side's patch wholly in front of the
/// other's or not: (receiving patch, source patch), the source facing the receiver's centroid.
fn pairs(count: usize) -> Vec<(Patch, Patch)> {
    let mut rng = Rng::keyed(7);
    let mut out = Vec::new();
    while out.len() < count {
        let size = 0.05 + rng.uniform();
        let distance = size * (1.0 + 40.0 * rng.uniform());
        let s = random_patch(&mut rng, DVec3::ZERO, size);
        let dir = DVec3::new(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5).normalize();
        let source_size = size * (0.2 + 2.0 * rng.uniform());
        let mut t = random_patch(&mut rng, distance * dir, source_size);
        if (s.centroid - t.centroid).dot(t.normal) < 0.0 {
            t = turned_over(&t);
        }
        out.push((s, t));
    }
    out
}

#[test]
fn the_point_cubature_is_within_5e_4_of_the_contour_integral_where_it_is_used() {
    let (mut used, mut worst, mut near_miss) = (0, 0.0f64, 0.0f64);
    for (s, t) in pairs(20_000) {
        let (x, n) = (s.centroid, s.normal);
        let exact = point_to_patch(x, n, &t);
        let fast = point_factor(x, n, &t);
        if !is_far(x, n, &t) {
            assert_eq!(fast, exact, "the exact integral where the patch is near");
            continue;
        }
        used += 1;
        let error = (fast - exact).abs() / exact;
        worst = worst.max(error);
        // the share of the rule's error that the threshold leaves: pairs just inside it
        let radius = t.polygon.vertices().iter().map(|v| v.distance(t.centroid)).fold(0.0, f64::max);
        if 2.0 * radius > 0.8 * FAR * (x.distance(t.centroid) - radius) {
            near_miss = near_miss.max(error);
        }
    }
    eprintln!("{used} far points: largest relative error {worst:.2e} ({near_miss:.2e} within 20 % of the threshold)");
    assert!(used > 2_000, "only {used} far points");
    assert!(worst < 5e-4, "largest relative error {worst:.2e}");
}

#[test]
fn the_far_pair_integral_is_within_5e_4_of_the_adaptive_rule() {
    let quadrature = Quadrature::default();
    let (mut used, mut worst) = (0, 0.0f64);
    for (s, t) in pairs(20_000) {
        let Some(fast) = far_pair_integral(&s, &t) else { continue };
        let exact = pair_integral(&s, &t, &quadrature).adaptive;
        used += 1;
        worst = worst.max((fast - exact).abs() / exact);
    }
    eprintln!("{used} far pairs: largest relative error {worst:.2e}");
    assert!(used > 1_000, "only {used} far pairs");
    assert!(worst < 5e-4, "largest relative error {worst:.2e}");
}
