//! Planar polygons with holes (a wall less its windows and doors), cut into the convex
//! pieces the rest of ugo meshes, by a slab sweep.
//!
//! Owns the one decomposition of an outline less its holes: the plane is cut into slabs
//! across the outline's first edge at every vertex, and each slab into the trapezoids
//! between the edges that cross it; a trapezoid belongs to the region when it lies inside
//! the outline and inside no hole (each ring's edges toggle its side). So the pieces cover
//! exactly the outline less the union of the holes, a hole may touch the outline (a door
//! at the floor) or another hole, and the same sweep measures how much of a hole lies
//! outside the outline or inside another hole ([`hole_faults`]), for validation. An
//! axis-aligned rectangle less axis-aligned rectangles gives rectangles: a wall with one
//! window gives the four rectangles one would model by hand.

use super::polygon::ConvexPolygon;
use glam::{DVec2, DVec3};

/// Coordinates closer than this fraction of the outline's size are one (a slab no wider
/// is round-off).
const SNAP: f64 = 1e-9;

/// The convex pieces (triangles and quads) covering `outline` less `holes`, facing the
/// outline's front (counter-clockwise seen from it). The holes lie in the outline's plane.
pub fn holed_pieces(outline: &[DVec3], holes: &[Vec<DVec3>]) -> Vec<ConvexPolygon> {
    let plane = Plane::of(outline);
    let tiny = SNAP * plane.size;
    sweep(&plane, outline, holes)
        .into_iter()
        .filter(|cell| cell.rings[0] && !cell.rings[1..].contains(&true) && cell.area() > tiny * tiny)
        .filter_map(|cell| cell.polygon(&plane, tiny))
        .collect()
}

/// What is wrong with the holes of an outline, as areas (m²): of each hole, the part
/// outside the outline, and of each pair of holes, the part they share.
#[derive(Debug, Clone, PartialEq)]
pub struct HoleFaults {
    /// The area of hole `j` outside the outline, m².
    pub outside: Vec<f64>,
    /// `(j, k, area)`: holes `j < k` overlap over `area` m² (only pairs that do).
    pub overlaps: Vec<(usize, usize, f64)>,
}

/// How much of each hole lies outside `outline` and which holes overlap, m².
pub fn hole_faults(outline: &[DVec3], holes: &[Vec<DVec3>]) -> HoleFaults {
    let plane = Plane::of(outline);
    let mut faults = HoleFaults { outside: vec![0.0; holes.len()], overlaps: Vec::new() };
    for cell in sweep(&plane, outline, holes) {
        let within: Vec<usize> = (0..holes.len()).filter(|&j| cell.rings[j + 1]).collect();
        let area = cell.area();
        if !cell.rings[0] {
            within.iter().for_each(|&j| faults.outside[j] += area);
        }
        for (n, &j) in within.iter().enumerate() {
            for &k in &within[n + 1..] {
                match faults.overlaps.iter_mut().find(|(a, b, _)| (*a, *b) == (j, k)) {
                    Some(pair) => pair.2 += area,
                    None => faults.overlaps.push((j, k, area)),
                }
            }
        }
    }
    faults
}

/// The outline's plane: an origin, the unit first edge `e1` (the sweep's axis), `e2` across
/// it in the plane, the front normal, and the outline's size (its largest extent from the
/// first vertex).
struct Plane {
    origin: DVec3,
    e1: DVec3,
    e2: DVec3,
    size: f64,
}

impl Plane {
    fn of(outline: &[DVec3]) -> Plane {
        let origin = outline[0];
        let newell: DVec3 = (0..outline.len()).map(|i| outline[i].cross(outline[(i + 1) % outline.len()])).sum();
        let normal = newell.normalize();
        let e1 = (outline[1] - origin).normalize();
        let size = outline.iter().map(|p| p.distance(origin)).fold(0.0, f64::max);
        Plane { origin, e1, e2: normal.cross(e1), size }
    }

    fn flat(&self, p: DVec3) -> DVec2 {
        DVec2::new((p - self.origin).dot(self.e1), (p - self.origin).dot(self.e2))
    }

    fn lift(&self, q: DVec2) -> DVec3 {
        self.origin + q.x * self.e1 + q.y * self.e2
    }
}

/// An edge of ring `ring` (0 the outline, `j + 1` hole `j`), from left to right.
#[derive(Clone, Copy)]
struct Edge {
    a: DVec2,
    b: DVec2,
    ring: usize,
}

impl Edge {
    fn y(&self, x: f64) -> f64 {
        self.a.y + (self.b.y - self.a.y) * (x - self.a.x) / (self.b.x - self.a.x)
    }
}

/// The trapezoid of a slab `x0..x1` between two edges, and which rings it lies inside.
struct Cell {
    x0: f64,
    x1: f64,
    bottom: Edge,
    top: Edge,
    rings: Vec<bool>,
}

impl Cell {
    fn area(&self) -> f64 {
        let height = |x: f64| (self.top.y(x) - self.bottom.y(x)).max(0.0);
        0.5 * (self.x1 - self.x0) * (height(self.x0) + height(self.x1))
    }

    /// The trapezoid in space, a triangle where a side has no length; none if both have none.
    fn polygon(&self, plane: &Plane, tiny: f64) -> Option<ConvexPolygon> {
        let (x0, x1) = (self.x0, self.x1);
        let corners = [
            DVec2::new(x0, self.bottom.y(x0)),
            DVec2::new(x1, self.bottom.y(x1)),
            DVec2::new(x1, self.top.y(x1)),
            DVec2::new(x0, self.top.y(x0)),
        ];
        let keep = [true, true, corners[2].y - corners[1].y > tiny, corners[3].y - corners[0].y > tiny];
        let v: Vec<DVec3> = (0..4).filter(|&i| keep[i]).map(|i| plane.lift(corners[i])).collect();
        (v.len() >= 3).then(|| ConvexPolygon::from_slice(&v))
    }
}

/// Every trapezoid of the slabs between the x of the rings' vertices (snapped together
/// within [`SNAP`] of the size), with the rings it lies inside.
fn sweep(plane: &Plane, outline: &[DVec3], holes: &[Vec<DVec3>]) -> Vec<Cell> {
    let rings: Vec<Vec<DVec2>> =
        std::iter::once(outline).chain(holes.iter().map(Vec::as_slice)).map(|r| flat_ring(plane, r)).collect();
    let mut xs: Vec<f64> = rings.iter().flatten().map(|p| p.x).collect();
    xs.sort_by(f64::total_cmp);
    let snap = SNAP * plane.size;
    let mut cuts: Vec<f64> = Vec::new();
    for x in xs {
        if cuts.last().is_none_or(|&last| x - last > snap) {
            cuts.push(x);
        }
    }
    let snapped = |x: f64| cuts[cuts.partition_point(|&c| c <= x + snap).saturating_sub(1)];
    let mut edges = Vec::new();
    for (ring, points) in rings.iter().enumerate() {
        for i in 0..points.len() {
            let (p, q) = (points[i], points[(i + 1) % points.len()]);
            let (p, q) = (DVec2::new(snapped(p.x), p.y), DVec2::new(snapped(q.x), q.y));
            if p.x != q.x {
                let (a, b) = if p.x < q.x { (p, q) } else { (q, p) };
                edges.push(Edge { a, b, ring });
            }
        }
    }
    let mut cells = Vec::new();
    for slab in cuts.windows(2) {
        let (x0, x1) = (slab[0], slab[1]);
        let mid = 0.5 * (x0 + x1);
        let mut crossing: Vec<Edge> = edges.iter().copied().filter(|e| e.a.x <= x0 && e.b.x >= x1).collect();
        crossing.sort_by(|e, f| e.y(mid).total_cmp(&f.y(mid)));
        let mut inside = vec![false; rings.len()];
        for pair in crossing.windows(2) {
            inside[pair[0].ring] = !inside[pair[0].ring];
            cells.push(Cell { x0, x1, bottom: pair[0], top: pair[1], rings: inside.clone() });
        }
    }
    cells
}

fn flat_ring(plane: &Plane, ring: &[DVec3]) -> Vec<DVec2> {
    ring.iter().map(|&p| plane.flat(p)).collect()
}
