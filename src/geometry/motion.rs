//! Rigid motions of shapes: a surface's copies (furniture instancing), each turned about an
//! axis through a pivot and moved, `p ↦ R·(p − pivot) + pivot + translate`.
//!
//! Owns how each shape carries a motion: points move, edges and normals turn, a mesh's
//! triangles move (the file is not read again). A box stays axis-aligned only when it
//! turns about the vertical: it then keeps its size, its centre moves and its
//! `rotate_y_deg` grows by the angle; about another axis it has no box form.

use super::surface::Shape;
use glam::{DMat3, DVec3};

/// A turn by `angle_deg` about the unit `axis` through `pivot` (counter-clockwise seen from
/// the axis's tip), then a move by `translate`, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// The unit axis of the turn.
    pub axis: DVec3,
    /// The angle of the turn, degrees.
    pub angle_deg: f64,
    /// A point of the axis, m.
    pub pivot: DVec3,
    /// The move after the turn, m.
    pub translate: DVec3,
}

impl Motion {
    /// A move by `translate` alone.
    pub fn translation(translate: DVec3) -> Motion {
        Motion { axis: DVec3::Y, angle_deg: 0.0, pivot: DVec3::ZERO, translate }
    }

    fn rotation(&self) -> DMat3 {
        DMat3::from_axis_angle(self.axis, self.angle_deg.to_radians())
    }

    /// Where the point `p` goes.
    pub fn point(&self, p: DVec3) -> DVec3 {
        match self.angle_deg == 0.0 {
            true => p + self.translate,
            false => self.rotation() * (p - self.pivot) + self.pivot + self.translate,
        }
    }

    /// Where the vector `v` (an edge, a normal) turns.
    pub fn vector(&self, v: DVec3) -> DVec3 {
        match self.angle_deg == 0.0 {
            true => v,
            false => self.rotation() * v,
        }
    }

    /// `shape` moved; none for a box turned about an axis other than the vertical.
    pub fn shape(&self, shape: &Shape) -> Option<Shape> {
        let points = |v: &[DVec3]| v.iter().map(|&p| self.point(p)).collect::<Vec<_>>();
        Some(match shape {
            Shape::Rectangle { origin, edge_u, edge_v } => Shape::Rectangle {
                origin: self.point(*origin),
                edge_u: self.vector(*edge_u),
                edge_v: self.vector(*edge_v),
            },
            Shape::Polygon { vertices } => Shape::Polygon { vertices: points(vertices) },
            Shape::Holed { outline, holes } => {
                Shape::Holed { outline: points(outline), holes: holes.iter().map(|h| points(h)).collect() }
            }
            Shape::Box { min, max, rotate_y_deg } => return self.cuboid(*min, *max, *rotate_y_deg),
            Shape::Disc { center, normal, radius } => {
                Shape::Disc { center: self.point(*center), normal: self.vector(*normal), radius: *radius }
            }
            Shape::Sphere { center, radius } => Shape::Sphere { center: self.point(*center), radius: *radius },
            Shape::Mesh { file, triangles } => Shape::Mesh {
                file: file.clone(),
                triangles: triangles.iter().map(|t| t.map(|p| self.point(p))).collect(),
            },
        })
    }

    fn cuboid(&self, min: DVec3, max: DVec3, rotate_y_deg: f64) -> Option<Shape> {
        if self.angle_deg == 0.0 {
            return Some(Shape::Box { min: min + self.translate, max: max + self.translate, rotate_y_deg });
        }
        let up = self.axis.dot(DVec3::Y);
        if (up.abs() - 1.0).abs() > 1e-12 {
            return None;
        }
        let (centre, half) = (0.5 * (min + max), 0.5 * (max - min));
        let moved = self.point(centre);
        Some(Shape::Box {
            min: moved - half,
            max: moved + half,
            rotate_y_deg: rotate_y_deg + up.signum() * self.angle_deg,
        })
    }
}
