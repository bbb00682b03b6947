//! Clipping a patch against a plane (`ConvexPolygon::clip_above`): a quad with two
//! opposite vertices on the plane and the others below it (a probe's plane through a
//! hierarchy element's diagonal, met by the hard probes of issue 34 on the Cornell box)
//! wrote six vertices into room for five and panicked; a vertex on the plane is now kept
//! once, and a quad the plane nearly holds cannot overflow either.

use glam::DVec3;
use ugo::geometry::{ConvexPolygon, MAX_CLIPPED};

fn clipped(quad: [DVec3; 4]) -> Vec<DVec3> {
    let mut out = [DVec3::ZERO; MAX_CLIPPED];
    let n = ConvexPolygon::from_slice(&quad).clip_above(DVec3::ZERO, DVec3::Z, &mut out);
    out[..n].to_vec()
}

#[test]
fn a_quad_touching_the_plane_along_its_diagonal_leaves_nothing_above() {
    let quad = [
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, -1.0),
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(0.0, -1.0, -1.0),
    ];
    assert!(clipped(quad).is_empty());
}

#[test]
fn a_vertex_on_the_plane_is_kept_once() {
    let quad =
        [DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0, 0.0, 1.0), DVec3::new(1.0, 1.0, 1.0), DVec3::new(0.0, 1.0, 1.0)];
    assert_eq!(clipped(quad), quad.to_vec());
}

#[test]
fn a_quad_on_alternate_sides_of_the_plane_at_every_vertex_does_not_overflow() {
    let e = 1e-17;
    let quad = [DVec3::new(0.0, 0.0, e), DVec3::new(1.0, 0.0, -e), DVec3::new(1.0, 1.0, e), DVec3::new(0.0, 1.0, -e)];
    assert!(clipped(quad).len() <= MAX_CLIPPED);
}
