//! Form factors against closed forms (`docs/references.md`, configuration factors).

use glam::DVec3;
use ugo::geometry::{ConvexPolygon, Patch};
use ugo::transfer::contour::point_to_polygon;
use ugo::transfer::form_factor::{Quadrature, form_factor};

fn square(origin: DVec3, u: DVec3, v: DVec3) -> Patch {
    Patch::from_polygon(ConvexPolygon::quad(origin, origin + u, origin + u + v, origin + v), 0, 0, 0)
}

const X: DVec3 = DVec3::X;
const Y: DVec3 = DVec3::Y;
const Z: DVec3 = DVec3::Z;

#[test]
fn point_to_parallel_rectangle_corner() {
    // Element at the origin facing +z, unit square 1 above with a corner over it, facing down.
    let p = square(Z, Y, X);
    assert!(p.normal.dot(-Z) > 0.999);
    let f = point_to_polygon(DVec3::ZERO, Z, &p.polygon);
    assert!((f - 0.1385316).abs() < 1e-7, "{f}");
}

#[test]
fn point_to_perpendicular_rectangle() {
    // Rectangle in the plane y = 1, x ∈ [0,1], z ∈ [0,1], facing the element (−y).
    let p = square(Y, X, Z);
    assert!(p.normal.dot(-Y) > 0.999);
    let f = point_to_polygon(DVec3::ZERO, Z, &p.polygon);
    assert!((f - 0.0557342).abs() < 1e-7, "{f}");
}

#[test]
fn point_behind_polygon_sees_nothing() {
    let p = square(Z, X, Y); // faces +z, away from the origin
    assert_eq!(point_to_polygon(DVec3::ZERO, Z, &p.polygon), 0.0);
}

#[test]
fn parallel_opposed_unit_squares() {
    let a = square(DVec3::ZERO, X, Y);
    let b = square(Z, Y, X);
    let f = form_factor(&a, &b, &Quadrature::default());
    assert!((f / 0.1998249 - 1.0).abs() < 5e-3, "{f}");
    eprintln!("parallel: {f:.7}");
}

#[test]
fn perpendicular_unit_squares_sharing_an_edge() {
    let floor = square(DVec3::ZERO, X, Y); // faces +z
    let wall = square(DVec3::ZERO, Z, X); // in y = 0, faces +y
    assert!(wall.normal.dot(Y) > 0.999);
    let f = form_factor(&floor, &wall, &Quadrature::default());
    assert!((f / 0.2000438 - 1.0).abs() < 5e-3, "{f}");
    let g = form_factor(&wall, &floor, &Quadrature::default());
    assert!((g / 0.2000438 - 1.0).abs() < 5e-3, "{g}");
    eprintln!("perpendicular: {f:.7} {g:.7}");
}
