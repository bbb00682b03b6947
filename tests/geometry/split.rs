//! A polygon cut in four (`geometry/polygon.rs`): `split` by midpoints, `split_even` into
//! strips across a long quad, so that the hierarchy's elements stay near squares (the
//! office's 2 cm whiteboard rims, split by midpoints, became leaves of 2.5 mm × 12.5 cm).

use glam::DVec3;
use ugo::geometry::ConvexPolygon;

/// The lengths of a quad's edges one way and the other way (the means of opposite edges).
fn sides(q: &ConvexPolygon) -> (f64, f64) {
    let v = q.vertices();
    (0.5 * (v[0].distance(v[1]) + v[3].distance(v[2])), 0.5 * (v[0].distance(v[3]) + v[1].distance(v[2])))
}

/// Checks that `pieces` tile `whole`: same total area, each piece with `whole`'s normal,
/// its centroid inside it, their centroids distinct.
fn tiles(whole: &ConvexPolygon, pieces: &[ConvexPolygon; 4]) {
    let area: f64 = pieces.iter().map(|p| p.area()).sum();
    assert!((area - whole.area()).abs() < 1e-12 * whole.area(), "{area} against {}", whole.area());
    for p in pieces {
        assert!(p.normal().dot(whole.normal()) > 1.0 - 1e-12, "a piece turned over");
        assert!(whole.distance_to(p.centroid()) < 1e-12, "a piece's centroid outside");
    }
    for (i, a) in pieces.iter().enumerate() {
        assert!(pieces[i + 1..].iter().all(|b| a.centroid().distance(b.centroid()) > 1e-9), "two pieces coincide");
    }
}

#[test]
fn a_long_quad_is_cut_into_strips_across_its_long_way() {
    for (a, b) in [(1.0, 0.02), (0.02, 1.0), (0.3, 0.1), (0.1, 0.3)] {
        let q =
            ConvexPolygon::quad(DVec3::ZERO, DVec3::new(a, 0.0, 0.0), DVec3::new(a, b, 0.0), DVec3::new(0.0, b, 0.0));
        let pieces = q.split_even();
        tiles(&q, &pieces);
        for p in &pieces {
            let (x, y) = sides(p);
            let (long, short) = (x.max(y), x.min(y));
            let expected = ((a.max(b) / 4.0).max(a.min(b)), (a.max(b) / 4.0).min(a.min(b)));
            let quarter = (p.area() - 0.25 * q.area()).abs() < 1e-12;
            assert!(
                quarter && (long - expected.0).abs() < 1e-12 && (short - expected.1).abs() < 1e-12,
                "{a} x {b}: a piece {x} x {y}"
            );
        }
    }
}

#[test]
fn a_near_square_quad_and_a_triangle_are_cut_by_midpoints() {
    let q = ConvexPolygon::quad(DVec3::ZERO, DVec3::X, DVec3::new(1.2, 0.6, 0.0), DVec3::new(0.1, 0.55, 0.0));
    assert_eq!(q.split_even(), q.split());
    tiles(&q, &q.split_even());
    let t = ConvexPolygon::triangle(DVec3::ZERO, DVec3::new(1.0, 0.0, 0.0), DVec3::new(0.5, 0.01, 0.0));
    assert_eq!(t.split_even(), t.split());
}

#[test]
fn a_quad_is_cut_along_a_line_parallel_to_its_edges_and_nowhere_else() {
    // a 1 × 0.9 m wall piece in the plane z = 0, the line y = 0.715 across it
    let wall = ConvexPolygon::quad(
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 0.9, 0.0),
        DVec3::new(0.0, 0.9, 0.0),
    );
    let (t, pieces) = wall.split_along(DVec3::new(0.3, 0.715, 0.0), DVec3::Y, 1e-3).expect("the line crosses it");
    assert!((t - 0.715 / 0.9).abs() < 1e-12, "{t}");
    tiles(&wall, &pieces);
    let tops: Vec<f64> = pieces.iter().map(|p| p.vertices().iter().map(|v| v.y).fold(f64::MIN, f64::max)).collect();
    let bottoms: Vec<f64> = pieces.iter().map(|p| p.vertices().iter().map(|v| v.y).fold(f64::MAX, f64::min)).collect();
    assert!(tops.iter().chain(&bottoms).any(|y| (y - 0.715).abs() < 1e-12), "a boundary on the line: {tops:?}");
    assert!(
        pieces.iter().all(|p| {
            let (lo, hi) = p.vertices().iter().fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v.y), hi.max(v.y)));
            hi <= 0.715 + 1e-12 || lo >= 0.715 - 1e-12
        }),
        "a piece across the line"
    );
    // the same along the other edges: x = 0.25
    assert!(wall.split_along(DVec3::new(0.25, 0.0, 0.0), DVec3::X, 1e-3).is_some());
    // askew, beside it, within 1 mm of its edge, or a triangle: not cut
    assert!(wall.split_along(DVec3::new(0.5, 0.5, 0.0), DVec3::new(1.0, 1.0, 0.0).normalize(), 1e-3).is_none());
    assert!(wall.split_along(DVec3::new(0.0, 1.2, 0.0), DVec3::Y, 1e-3).is_none());
    assert!(wall.split_along(DVec3::new(0.0, 0.8995, 0.0), DVec3::Y, 1e-3).is_none());
    let triangle = ConvexPolygon::triangle(DVec3::ZERO, DVec3::X, DVec3::Y);
    assert!(triangle.split_along(DVec3::new(0.0, 0.5, 0.0), DVec3::Y, 1e-3).is_none());
}
