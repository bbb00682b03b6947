//! Small convex planar polygons (triangles and quads): the shape of every patch.
//!
//! Owns the elementary geometry used by meshing (`docs/design.md` §2) and by the form
//! factors (§3): area, normal, centroid, triangle fan, distance from a point, and
//! clipping against a plane. Vertices are counter-clockwise seen from the front.

use glam::DVec3;

/// The most vertices a clipped patch can have: a planar quad cut by one plane has at most
/// 5, but a quad that the plane nearly holds can, by rounding, lie on alternate sides of it
/// at every vertex, and each of its 4 edges then gives a vertex and a crossing.
pub const MAX_CLIPPED: usize = 8;

/// A quad is cut into strips ([`ConvexPolygon::split_even`]) when its edges one way are
/// more than this many times as long as the other way's: its quarters would be as
/// elongated as it, the strips nearer squares.
pub const STRIPS: f64 = 2.0;

/// A convex planar polygon of 3 or 4 vertices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConvexPolygon {
    vertices: [DVec3; 4],
    len: u8,
}

impl ConvexPolygon {
    /// A triangle from its vertices.
    pub fn triangle(a: DVec3, b: DVec3, c: DVec3) -> Self {
        ConvexPolygon { vertices: [a, b, c, c], len: 3 }
    }

    /// A convex quad from its vertices, in order.
    pub fn quad(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Self {
        ConvexPolygon { vertices: [a, b, c, d], len: 4 }
    }

    /// A polygon from 3 or 4 vertices.
    pub fn from_slice(v: &[DVec3]) -> Self {
        match v.len() {
            3 => Self::triangle(v[0], v[1], v[2]),
            4 => Self::quad(v[0], v[1], v[2], v[3]),
            n => panic!("a patch has 3 or 4 vertices, not {n}"),
        }
    }

    /// The 3 or 4 vertices, m.
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices[..self.len as usize]
    }

    /// The same polygon seen from the other side (vertex order reversed).
    pub fn reversed(&self) -> Self {
        let mut v: Vec<DVec3> = self.vertices().to_vec();
        v.reverse();
        Self::from_slice(&v)
    }

    /// Vector area: normal times area (Newell's formula).
    pub fn vector_area(&self) -> DVec3 {
        let v = self.vertices();
        let mut s = DVec3::ZERO;
        for i in 1..v.len() - 1 {
            s += (v[i] - v[0]).cross(v[i + 1] - v[0]);
        }
        0.5 * s
    }

    /// Area, m².
    pub fn area(&self) -> f64 {
        self.vector_area().length()
    }

    /// Unit normal, by the right-hand rule over the vertex order.
    pub fn normal(&self) -> DVec3 {
        self.vector_area().normalize()
    }

    /// Area centroid.
    pub fn centroid(&self) -> DVec3 {
        let v = self.vertices();
        let (mut sum, mut weight) = (DVec3::ZERO, 0.0);
        for i in 1..v.len() - 1 {
            let a = (v[i] - v[0]).cross(v[i + 1] - v[0]).length();
            sum += a * (v[0] + v[i] + v[i + 1]) / 3.0;
            weight += a;
        }
        sum / weight
    }

    /// A uniform point: `u0` chooses the fan triangle by area, `u1, u2` the point in it
    /// (each uniform on [0, 1)).
    pub fn point_at(&self, u0: f64, u1: f64, u2: f64) -> DVec3 {
        let mut s = u0 * self.area();
        let mut chosen = None;
        for tri in self.triangles() {
            let area = 0.5 * (tri[1] - tri[0]).cross(tri[2] - tri[0]).length();
            chosen = Some(tri);
            if s < area {
                break;
            }
            s -= area;
        }
        let [a, b, c] = chosen.expect("a polygon has a triangle");
        let r = u1.sqrt();
        a * (1.0 - r) + b * (r * (1.0 - u2)) + c * (r * u2)
    }

    /// The triangles of a fan from vertex 0.
    pub fn triangles(&self) -> impl Iterator<Item = [DVec3; 3]> + '_ {
        let v = self.vertices();
        (1..v.len() - 1).map(move |i| [v[0], v[i], v[i + 1]])
    }

    /// Longest distance between two vertices.
    pub fn diameter(&self) -> f64 {
        let v = self.vertices();
        let mut d: f64 = 0.0;
        for i in 0..v.len() {
            for j in i + 1..v.len() {
                d = d.max(v[i].distance(v[j]));
            }
        }
        d
    }

    /// Euclidean distance from `p` to the closed polygon.
    pub fn distance_to(&self, p: DVec3) -> f64 {
        let n = self.normal();
        let v = self.vertices();
        let q = p - n * n.dot(p - v[0]);
        let inside = (0..v.len()).all(|i| (v[(i + 1) % v.len()] - v[i]).cross(q - v[i]).dot(n) >= 0.0);
        if inside {
            return (p - q).length();
        }
        (0..v.len()).map(|i| segment_distance(p, v[i], v[(i + 1) % v.len()])).fold(f64::INFINITY, f64::min)
    }

    /// The distance `t > 0` at which the ray `x + t·d` crosses the polygon, if it does (a
    /// ray in its plane never does).
    pub fn crossing(&self, x: DVec3, d: DVec3) -> Option<f64> {
        let n = self.normal();
        let v = self.vertices();
        let across = d.dot(n);
        if across.abs() <= 1e-12 {
            return None;
        }
        let t = (v[0] - x).dot(n) / across;
        if t <= 0.0 || !t.is_finite() {
            return None;
        }
        let q = x + d * t;
        let inside = (0..v.len()).all(|i| (v[(i + 1) % v.len()] - v[i]).cross(q - v[i]).dot(n) >= 0.0);
        inside.then_some(t)
    }

    /// Four pieces of about a quarter each (a quad by the midpoints of its edges and its
    /// centre, a triangle by the midpoints of its edges), covering it exactly.
    pub fn split(&self) -> [ConvexPolygon; 4] {
        let v = self.vertices();
        let mid = |i: usize, j: usize| 0.5 * (v[i] + v[j]);
        if v.len() == 3 {
            let (ab, bc, ca) = (mid(0, 1), mid(1, 2), mid(2, 0));
            return [
                Self::triangle(v[0], ab, ca),
                Self::triangle(ab, v[1], bc),
                Self::triangle(ca, bc, v[2]),
                Self::triangle(ab, bc, ca),
            ];
        }
        let (ab, bc, cd, da) = (mid(0, 1), mid(1, 2), mid(2, 3), mid(3, 0));
        let c = 0.25 * (v[0] + v[1] + v[2] + v[3]);
        [
            Self::quad(v[0], ab, c, da),
            Self::quad(ab, v[1], bc, c),
            Self::quad(c, bc, v[2], cd),
            Self::quad(da, c, cd, v[3]),
        ]
    }

    /// Four pieces of about a quarter each, as near squares as a cut in four allows: a quad
    /// whose edges one way are more than [`STRIPS`] times as long as the other way's is cut
    /// into four strips across its long way (a 2 cm × 1 m board's edge into four 2 × 25 cm
    /// strips, not four 1 × 50 cm slivers); any other polygon as [`ConvexPolygon::split`].
    /// The pieces cover it exactly, in its orientation.
    pub fn split_even(&self) -> [ConvexPolygon; 4] {
        let v = self.vertices();
        if v.len() != 4 {
            return self.split();
        }
        let (one_way, other_way) =
            (v[0].distance(v[1]) + v[3].distance(v[2]), v[0].distance(v[3]) + v[1].distance(v[2]));
        let strip = |a: [DVec3; 2], b: [DVec3; 2], k: usize| {
            let at = |e: [DVec3; 2], t: f64| e[0].lerp(e[1], t);
            let (t0, t1) = (k as f64 / 4.0, (k + 1) as f64 / 4.0);
            Self::quad(at(a, t0), at(a, t1), at(b, t1), at(b, t0))
        };
        if one_way > STRIPS * other_way {
            std::array::from_fn(|k| strip([v[0], v[1]], [v[3], v[2]], k))
        } else if other_way > STRIPS * one_way {
            std::array::from_fn(|k| strip([v[1], v[2]], [v[0], v[3]], k))
        } else {
            self.split()
        }
    }

    /// Four strips with one boundary on the plane through `point` with unit `normal`, when
    /// the polygon is a quad with two opposite edges parallel to that plane and the plane
    /// crosses it at least `least` (m) from both: the part on each side halved, so that the
    /// pieces beside the line are the finer. With where it crosses, as a share `t` of the
    /// way between those edges. `None` for a triangle, a plane askew to the edges, or one
    /// beside the quad or within `least` of its edges. (A two-by-two grid, the parts halved
    /// along the line instead, read the slot room's probes behind the desk 6 % bright
    /// against 1.5 %: `docs/hierarchy.md`, "Cuts".)
    pub fn split_along(&self, point: DVec3, normal: DVec3, least: f64) -> Option<(f64, [ConvexPolygon; 4])> {
        let v = self.vertices();
        if v.len() != 4 {
            return None;
        }
        let d: [f64; 4] = std::array::from_fn(|i| (v[i] - point).dot(normal));
        let slack = 1e-9 * self.diameter();
        // edges (a, b) and (e, c) parallel to the plane, the strips running from the first to the second
        let across = |a: usize, b: usize, c: usize, e: usize| {
            let parallel = (d[a] - d[b]).abs() <= slack && (d[e] - d[c]).abs() <= slack;
            let t = d[a] / (d[a] - d[e]);
            let width = v[a].distance(v[e]).min(v[b].distance(v[c]));
            let strip = |s: f64, u: f64| {
                Self::quad(v[a].lerp(v[e], s), v[b].lerp(v[c], s), v[b].lerp(v[c], u), v[a].lerp(v[e], u))
            };
            (parallel && t * width >= least && (1.0 - t) * width >= least).then(|| {
                (t, [strip(0.0, 0.5 * t), strip(0.5 * t, t), strip(t, 0.5 * (1.0 + t)), strip(0.5 * (1.0 + t), 1.0)])
            })
        };
        across(0, 1, 2, 3).or_else(|| across(1, 2, 3, 0))
    }

    /// Hands `visit` its pieces as seen from `x` within the angle `spread` (a piece's diameter
    /// over its distance from `x`): quarters ([`ConvexPolygon::split`]) while a piece's
    /// diameter exceeds `spread` times its distance, at most `depth` levels deep.
    pub fn pieces_within(&self, x: DVec3, spread: f64, depth: u32, visit: &mut dyn FnMut(&ConvexPolygon)) {
        if depth > 0 && self.diameter() > spread * self.distance_to(x) {
            self.split().iter().for_each(|part| part.pieces_within(x, spread, depth - 1, visit));
        } else {
            visit(self);
        }
    }

    /// The solid angle it subtends at `x`, sr (Van Oosterom & Strackee, IEEE Trans. Biomed.
    /// Eng. 30 (1983), per fan triangle); 0 when `x` lies in its plane.
    pub fn solid_angle(&self, x: DVec3) -> f64 {
        self.triangles()
            .map(|[a, b, c]| {
                let (a, b, c) = (a - x, b - x, c - x);
                let (la, lb, lc) = (a.length(), b.length(), c.length());
                let det = a.dot(b.cross(c)).abs();
                let div = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
                2.0 * det.atan2(div)
            })
            .sum()
    }

    /// The part on the side `(x − origin)·normal ≥ 0` (Sutherland–Hodgman), written into
    /// `out`; returns its vertex count (0 when nothing is left).
    pub fn clip_above(&self, origin: DVec3, normal: DVec3, out: &mut [DVec3; MAX_CLIPPED]) -> usize {
        let v = self.vertices();
        let mut n = 0;
        for i in 0..v.len() {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            let (da, db) = ((a - origin).dot(normal), (b - origin).dot(normal));
            if da >= 0.0 {
                out[n] = a;
                n += 1;
            }
            // strictly across: a vertex on the plane is kept once, not again as a crossing
            if (da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0) {
                out[n] = a + (b - a) * (da / (da - db));
                n += 1;
            }
        }
        if n < 3 { 0 } else { n }
    }
}

fn segment_distance(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
    p.distance(a + t * ab)
}
