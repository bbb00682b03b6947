//! Tessellation of every scene shape into planar convex elements of a target edge length.
//!
//! Owns the meshing rule of `docs/design.md` §2: parametric shapes (rectangle, convex quad,
//! disc, sphere) are cut into a grid of planar quads (triangles where a grid edge
//! collapses, at poles and centres); polygons are triangulated by ear clipping and, like
//! OBJ triangles, split into `m²` similar triangles; a polygon with holes is cut into
//! trapezoids (`holes.rs`), each meshed as a polygon. Elements face the shape's front.

use super::holes::holed_pieces;
use super::polygon::ConvexPolygon;
use super::surface::Shape;
use glam::{DMat3, DVec3};
use std::f64::consts::PI;

/// The elements of `shape` with edges no longer than about `h`.
pub fn tessellate(shape: &Shape, h: f64) -> Vec<ConvexPolygon> {
    match shape {
        Shape::Rectangle { origin, edge_u, edge_v } => parallelogram(*origin, *edge_u, *edge_v, h),
        Shape::Polygon { vertices } => polygon(vertices, h),
        Shape::Holed { outline, holes } => {
            holed_pieces(outline, holes).iter().flat_map(|piece| polygon(piece.vertices(), h)).collect()
        }
        Shape::Box { min, max, rotate_y_deg } => cuboid(*min, *max, *rotate_y_deg, h),
        Shape::Disc { center, normal, radius } => disc(*center, *normal, *radius, h),
        Shape::Sphere { center, radius } => sphere(*center, *radius, h),
        Shape::Mesh { triangles, .. } => triangles.iter().flat_map(|t| triangle(t[0], t[1], t[2], h)).collect(),
    }
}

/// How many elements [`tessellate`] makes of `shape` at edge length `h`, counted without
/// making them (in floating point, so that a count past any memory stays a number): the
/// grids' `nu × nv`, the triangles' `m²`. An upper bound where a grid cell collapses.
pub fn element_count(shape: &Shape, h: f64) -> f64 {
    let cuts = |length: f64| (length / h).ceil().max(1.0);
    let triangle = |a: DVec3, b: DVec3, c: DVec3| cuts(a.distance(b).max(b.distance(c)).max(c.distance(a))).powi(2);
    match shape {
        Shape::Rectangle { edge_u, edge_v, .. } => cuts(edge_u.length()) * cuts(edge_v.length()),
        Shape::Polygon { vertices } => polygon_count(vertices, h),
        Shape::Holed { outline, holes } => {
            holed_pieces(outline, holes).iter().map(|piece| polygon_count(piece.vertices(), h)).sum()
        }
        Shape::Box { min, max, .. } => {
            let [x, y, z] = (*max - *min).to_array().map(cuts);
            2.0 * (x * y + y * z + z * x)
        }
        Shape::Disc { radius, .. } => cuts(*radius) * cuts(2.0 * PI * radius).max(16.0),
        Shape::Sphere { radius, .. } => cuts(PI * radius).max(4.0) * cuts(2.0 * PI * radius).max(8.0),
        Shape::Mesh { triangles, .. } => triangles.iter().map(|t| triangle(t[0], t[1], t[2])).sum(),
    }
}

/// [`element_count`] of a polygon: its quad grid or its triangles' `m²`.
fn polygon_count(vertices: &[DVec3], h: f64) -> f64 {
    let cuts = |length: f64| (length / h).ceil().max(1.0);
    let normal = newell_normal(vertices);
    if vertices.len() == 4 && is_convex(vertices, normal) {
        let [a, b, c, d] = [vertices[0], vertices[1], vertices[2], vertices[3]];
        return cuts((b - a).length().max((c - d).length())) * cuts((d - a).length().max((c - b).length()));
    }
    let triangle = |[a, b, c]: [DVec3; 3]| cuts(a.distance(b).max(b.distance(c)).max(c.distance(a))).powi(2);
    ear_clip(vertices, normal).into_iter().map(triangle).sum()
}

fn divisions(length: f64, h: f64) -> usize {
    ((length / h).ceil() as usize).max(1)
}

fn parallelogram(o: DVec3, u: DVec3, v: DVec3, h: f64) -> Vec<ConvexPolygon> {
    let (nu, nv) = (divisions(u.length(), h), divisions(v.length(), h));
    grid(nu, nv, u.cross(v), |s, t| o + s * u + t * v)
}

/// A planar simple polygon: convex quads keep a quad grid, anything else is triangulated.
fn polygon(vertices: &[DVec3], h: f64) -> Vec<ConvexPolygon> {
    let normal = newell_normal(vertices);
    if vertices.len() == 4 && is_convex(vertices, normal) {
        let [a, b, c, d] = [vertices[0], vertices[1], vertices[2], vertices[3]];
        let longest = (b - a).length().max((c - d).length());
        let widest = (d - a).length().max((c - b).length());
        let bilinear = |s: f64, t: f64| a.lerp(b, s).lerp(d.lerp(c, s), t);
        return grid(divisions(longest, h), divisions(widest, h), normal, bilinear);
    }
    ear_clip(vertices, normal).into_iter().flat_map(|[a, b, c]| triangle(a, b, c, h)).collect()
}

/// Six outward-facing rectangles, rotated about the vertical axis through the centre.
fn cuboid(min: DVec3, max: DVec3, rotate_y_deg: f64, h: f64) -> Vec<ConvexPolygon> {
    let centre = 0.5 * (min + max);
    let rotation = DMat3::from_rotation_y(rotate_y_deg.to_radians());
    let corner = |x: f64, y: f64, z: f64| {
        let p = DVec3::new(
            if x > 0.5 { max.x } else { min.x },
            if y > 0.5 { max.y } else { min.y },
            if z > 0.5 { max.z } else { min.z },
        );
        centre + rotation * (p - centre)
    };
    let faces = [
        // origin, end of edge u, end of edge v; u × v points outward
        ([0., 0., 0.], [0., 0., 1.], [0., 1., 0.]), // x = min
        ([1., 0., 0.], [1., 1., 0.], [1., 0., 1.]), // x = max
        ([0., 0., 0.], [1., 0., 0.], [0., 0., 1.]), // y = min
        ([0., 1., 0.], [0., 1., 1.], [1., 1., 0.]), // y = max
        ([0., 0., 0.], [0., 1., 0.], [1., 0., 0.]), // z = min
        ([0., 0., 1.], [1., 0., 1.], [0., 1., 1.]), // z = max
    ];
    faces
        .iter()
        .flat_map(|(o, u, v)| {
            let o = corner(o[0], o[1], o[2]);
            parallelogram(o, corner(u[0], u[1], u[2]) - o, corner(v[0], v[1], v[2]) - o, h)
        })
        .collect()
}

fn disc(center: DVec3, normal: DVec3, radius: f64, h: f64) -> Vec<ConvexPolygon> {
    let (e1, e2) = normal.any_orthonormal_pair();
    let sectors = divisions(2.0 * PI * radius, h).max(16);
    let rings = divisions(radius, h);
    let point = |s: f64, t: f64| {
        let phi = 2.0 * PI * t;
        center + radius * s * (phi.cos() * e1 + phi.sin() * e2)
    };
    grid(rings, sectors, normal, point)
}

fn sphere(center: DVec3, radius: f64, h: f64) -> Vec<ConvexPolygon> {
    let rings = divisions(PI * radius, h).max(4);
    let sectors = divisions(2.0 * PI * radius, h).max(8);
    let point = |s: f64, t: f64| {
        let (theta, phi) = (PI * s, 2.0 * PI * t);
        center + radius * DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
    };
    let mut elements = Vec::with_capacity(rings * sectors);
    for e in grid(rings, sectors, DVec3::ZERO, point) {
        let outward = e.centroid() - center;
        elements.push(if e.vector_area().dot(outward) < 0.0 { e.reversed() } else { e });
    }
    elements
}

/// `m²` similar triangles of a triangle, `m` chosen from its longest edge.
fn triangle(a: DVec3, b: DVec3, c: DVec3, h: f64) -> Vec<ConvexPolygon> {
    let m = divisions(a.distance(b).max(b.distance(c)).max(c.distance(a)), h);
    let p = |i: usize, j: usize| a + (b - a) * (i as f64 / m as f64) + (c - a) * (j as f64 / m as f64);
    let mut out = Vec::with_capacity(m * m);
    for j in 0..m {
        for i in 0..m - j {
            out.push(ConvexPolygon::triangle(p(i, j), p(i + 1, j), p(i, j + 1)));
            if i + j + 1 < m {
                out.push(ConvexPolygon::triangle(p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)));
            }
        }
    }
    out
}

/// Quads of the parametric map `f` over `[0,1]²`, `nu × nv` cells; an edge that
/// collapses to a point (pole, centre) turns its quad into a triangle. Elements face
/// `front` when it is non-zero.
fn grid(nu: usize, nv: usize, front: DVec3, f: impl Fn(f64, f64) -> DVec3) -> Vec<ConvexPolygon> {
    let mut out = Vec::with_capacity(nu * nv);
    let at = |i: usize, j: usize| f(i as f64 / nu as f64, j as f64 / nv as f64);
    for i in 0..nu {
        for j in 0..nv {
            let corners = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            let scale = corners[0].distance(corners[2]).max(corners[1].distance(corners[3]));
            let mut v: Vec<DVec3> = Vec::with_capacity(4);
            for p in corners {
                if v.iter().all(|q| q.distance(p) > 1e-9 * scale) {
                    v.push(p);
                }
            }
            if v.len() < 3 {
                continue;
            }
            let e = ConvexPolygon::from_slice(&v);
            out.push(if e.vector_area().dot(front) < 0.0 { e.reversed() } else { e });
        }
    }
    out
}

fn newell_normal(v: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for i in 0..v.len() {
        n += v[i].cross(v[(i + 1) % v.len()]);
    }
    n.normalize()
}

fn is_convex(v: &[DVec3], normal: DVec3) -> bool {
    (0..v.len()).all(|i| {
        let (a, b, c) = (v[i], v[(i + 1) % v.len()], v[(i + 2) % v.len()]);
        (b - a).cross(c - b).dot(normal) > 0.0
    })
}

/// Below this fraction of the polygon's squared size, twice a corner's area is round-off.
const FLAT: f64 = 1e-10;

/// Ear clipping of a simple planar polygon (counter-clockwise about `normal`) into
/// triangles of positive area. A corner of no area to round-off (a straight angle, a
/// fold) is dropped without a triangle; a vertex on an ear's boundary, to round-off,
/// blocks the ear as one inside it does (clipping it would leave a fold).
fn ear_clip(vertices: &[DVec3], normal: DVec3) -> Vec<[DVec3; 3]> {
    let size = vertices.iter().map(|v| v.distance(vertices[0])).fold(0.0, f64::max);
    let flat = FLAT * size * size;
    // twice the signed area of the corner at b, positive when convex
    let turn = |[a, b, c]: [DVec3; 3]| (b - a).cross(c - b).dot(normal);
    let mut idx: Vec<usize> = (0..vertices.len()).collect();
    let mut out = Vec::with_capacity(vertices.len() - 2);
    while idx.len() >= 3 {
        let n = idx.len();
        let corner = |k: usize| [vertices[idx[(k + n - 1) % n]], vertices[idx[k]], vertices[idx[(k + 1) % n]]];
        if let Some(k) = (0..n).find(|&k| turn(corner(k)).abs() <= flat) {
            idx.remove(k);
            continue;
        }
        let ear = (0..n).find(|&k| {
            let [a, b, c] = corner(k);
            turn([a, b, c]) > 0.0
                && idx.iter().all(|&m| {
                    let p = vertices[m];
                    p == a || p == b || p == c || !inside_triangle(p, a, b, c, normal, flat)
                })
        });
        // A simple polygon always has an ear; on round-off, clip the most convex corner.
        let k = ear.unwrap_or_else(|| (0..n).max_by(|&i, &j| turn(corner(i)).total_cmp(&turn(corner(j)))).unwrap_or(0));
        out.push(corner(k));
        idx.remove(k);
    }
    out
}

/// True when `p` lies in the closed triangle `abc`, or within `tolerance` (twice an area) of it.
fn inside_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3, n: DVec3, tolerance: f64) -> bool {
    (b - a).cross(p - a).dot(n) >= -tolerance
        && (c - b).cross(p - b).dot(n) >= -tolerance
        && (a - c).cross(p - c).dot(n) >= -tolerance
}
