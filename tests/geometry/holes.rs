//! Polygons with holes (`geometry/holes.rs`): the convex pieces cover exactly the outline
//! less the holes, checked against the shoelace areas and point by point (a lattice of
//! points off every boundary lies in exactly one piece when it is in the outline and in no
//! hole, in none otherwise), on a wall with a window (the four rectangles one models by
//! hand), a door at the floor beside a touching window, and a concave outline with a
//! triangle and a quad cut out, tilted, in both vertex orders; the meshed elements add up
//! to the same area; and the faults (a hole reaching outside, two overlapping) are measured
//! exactly.

use glam::{DVec2, DVec3};
use ugo::geometry::{ConvexPolygon, Shape, hole_faults, holed_pieces, tessellate};

/// A plane `origin + u·e1 + v·e2`.
struct Plane {
    origin: DVec3,
    e1: DVec3,
    e2: DVec3,
}

const WALL: Plane = Plane { origin: DVec3::new(0.0, 0.0, 7.0), e1: DVec3::X, e2: DVec3::Y };

fn tilted() -> Plane {
    let e1 = DVec3::new(2.0, 1.0, -2.0) / 3.0;
    Plane { origin: DVec3::new(0.3, 0.17, 0.29), e1, e2: DVec3::new(1.0, 2.0, 2.0) / 3.0 }
}

fn place(plane: &Plane, ring: &[[f64; 2]]) -> Vec<DVec3> {
    ring.iter().map(|&[u, v]| plane.origin + u * plane.e1 + v * plane.e2).collect()
}

fn rect(u0: f64, v0: f64, u1: f64, v1: f64) -> Vec<[f64; 2]> {
    vec![[u0, v0], [u1, v0], [u1, v1], [u0, v1]]
}

fn shoelace(ring: &[[f64; 2]]) -> f64 {
    let n = ring.len();
    (0..n).map(|i| ring[i][0] * ring[(i + 1) % n][1] - ring[(i + 1) % n][0] * ring[i][1]).sum::<f64>().abs() / 2.0
}

/// Strictly inside the ring (even-odd), or `None` within `eps` of its boundary.
fn inside(ring: &[[f64; 2]], p: DVec2, eps: f64) -> Option<bool> {
    let n = ring.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (DVec2::from(ring[i]), DVec2::from(ring[(i + 1) % n]));
        let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        if p.distance(a + t * (b - a)) < eps {
            return None;
        }
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            odd = !odd;
        }
    }
    Some(odd)
}

/// The piece strictly contains `q` (in the plane's coordinates), or `None` near its edge.
fn piece_contains(piece: &ConvexPolygon, plane: &Plane, q: DVec2, eps: f64) -> Option<bool> {
    let flat: Vec<[f64; 2]> = piece
        .vertices()
        .iter()
        .map(|&p| [(p - plane.origin).dot(plane.e1), (p - plane.origin).dot(plane.e2)])
        .collect();
    inside(&flat, q, eps)
}

/// The pieces of `outline` less `holes` (in `plane`) cover exactly the region.
fn covers_exactly(plane: &Plane, outline: &[[f64; 2]], holes: &[Vec<[f64; 2]>]) -> Vec<ConvexPolygon> {
    let holes3: Vec<Vec<DVec3>> = holes.iter().map(|h| place(plane, h)).collect();
    let pieces = holed_pieces(&place(plane, outline), &holes3);
    let n = outline.len();
    let signed: f64 =
        (0..n).map(|i| outline[i][0] * outline[(i + 1) % n][1] - outline[(i + 1) % n][0] * outline[i][1]).sum();
    let normal = plane.e1.cross(plane.e2) * signed.signum();
    let area: f64 = pieces.iter().map(|p| p.area()).sum();
    let exact = shoelace(outline) - holes.iter().map(|h| shoelace(h)).sum::<f64>();
    assert!((area - exact).abs() < 1e-12 * exact, "pieces {area} m², outline less holes {exact} m²");
    for p in &pieces {
        assert!(p.area() > 0.0 && p.normal().dot(normal) > 1.0 - 1e-12, "{p:?} faces the outline's front");
        let v = p.vertices();
        let n = v.len();
        assert!((0..n).all(|i| (v[(i + 1) % n] - v[i]).cross(v[(i + 2) % n] - v[(i + 1) % n]).dot(normal) > 0.0));
    }
    let (lo, hi) =
        outline.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(l, h), &p| (l.min(p.into()), h.max(p.into())));
    let eps = 1e-9;
    let mut checked = 0;
    for i in 0..97 {
        for j in 0..89 {
            let q = lo
                + (hi - lo)
                    * DVec2::new((i as f64 + 0.5 * 2f64.sqrt()) / 97.0, (j as f64 + 0.5 * 3f64.sqrt() - 0.3) / 89.0);
            let Some(in_outline) = inside(outline, q, eps) else { continue };
            let Some(in_holes) = holes.iter().map(|h| inside(h, q, eps)).collect::<Option<Vec<bool>>>() else {
                continue;
            };
            let Some(hits) = pieces.iter().map(|p| piece_contains(p, plane, q, eps)).collect::<Option<Vec<bool>>>()
            else {
                continue;
            };
            let expected = usize::from(in_outline && !in_holes.contains(&true));
            assert_eq!(hits.iter().filter(|&&h| h).count(), expected, "point {q} of the plane");
            checked += 1;
        }
    }
    assert!(checked > 8000, "{checked} points off the boundaries");
    pieces
}

#[test]
fn a_wall_less_its_window_is_the_four_rectangles_modelled_by_hand() {
    let pieces = covers_exactly(&WALL, &rect(0.0, 0.0, 9.0, 3.2), &[rect(1.0, 0.9, 8.0, 2.4)]);
    let mut areas: Vec<f64> = pieces.iter().map(|p| p.area()).collect();
    areas.sort_by(f64::total_cmp);
    let expected = [5.6, 6.3, 3.2, 3.2];
    assert_eq!(pieces.len(), 4, "{pieces:?}");
    assert!(pieces.iter().all(|p| p.vertices().len() == 4));
    let mut expected = expected.to_vec();
    expected.sort_by(f64::total_cmp);
    for (a, e) in areas.iter().zip(&expected) {
        assert!((a - e).abs() < 1e-12, "{areas:?} against {expected:?}");
    }
}

#[test]
fn a_door_at_the_floor_and_a_window_touching_it_are_cut_out() {
    let door = rect(1.0, 0.0, 2.0, 2.1);
    let window = rect(2.0, 0.9, 4.5, 2.1);
    covers_exactly(&WALL, &rect(0.0, 0.0, 6.0, 3.0), &[door.clone(), window]);
    covers_exactly(&tilted(), &rect(0.0, 0.0, 6.0, 3.0), &[door]);
}

#[test]
fn a_concave_outline_less_a_triangle_and_a_quad_in_a_tilted_plane_either_way_round() {
    let l_shape = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 1.5], [1.7, 1.5], [1.7, 3.0], [0.0, 3.0]];
    let triangle = vec![[0.4, 0.3], [1.3, 0.45], [0.7, 2.6]];
    let quad = vec![[2.0, 0.2], [3.7, 0.4], [3.5, 1.2], [2.4, 1.0]];
    for reversed in [false, true] {
        let turn = |r: &Vec<[f64; 2]>| {
            let mut r = r.clone();
            if reversed {
                r.reverse();
            }
            r
        };
        let plane = tilted();
        let pieces = covers_exactly(&plane, &turn(&l_shape), &[turn(&triangle), quad.clone()]);
        let shape = Shape::Holed {
            outline: place(&plane, &turn(&l_shape)),
            holes: vec![place(&plane, &triangle), place(&plane, &quad)],
        };
        let exact: f64 = pieces.iter().map(|p| p.area()).sum();
        let elements = tessellate(&shape, 0.2);
        let meshed: f64 = elements.iter().map(|e| e.area()).sum();
        assert!((meshed - exact).abs() < 1e-12 * exact, "elements {meshed} m², pieces {exact} m²");
        assert!(elements.len() > pieces.len());
    }
}

#[test]
fn a_hole_reaching_outside_and_overlapping_holes_are_measured() {
    let outline = place(&WALL, &rect(0.0, 0.0, 4.0, 3.0));
    let out = place(&WALL, &rect(3.5, 1.0, 4.5, 2.0)); // 0.5 m² beyond the edge
    let a = place(&WALL, &rect(0.5, 0.5, 1.5, 1.5));
    let b = place(&WALL, &rect(1.25, 1.0, 2.0, 2.5)); // shares 0.25 × 0.5 with a
    let touching = place(&WALL, &rect(2.0, 0.5, 3.0, 1.0)); // touches b along an edge
    let faults = hole_faults(&outline, &[out, a, b, touching]);
    assert!((faults.outside[0] - 0.5).abs() < 1e-12, "{faults:?}");
    assert!(faults.outside[1..].iter().all(|&x| x == 0.0), "{faults:?}");
    assert_eq!(faults.overlaps.len(), 1, "{faults:?}");
    let (j, k, area) = faults.overlaps[0];
    assert_eq!((j, k), (1, 2));
    assert!((area - 0.125).abs() < 1e-12, "{faults:?}");
}
