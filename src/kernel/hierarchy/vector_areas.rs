//! A cluster's exposed area as a few vector areas (`docs/design.md` (3b.9)): the sums
//! `m_g = Σ o_e A_e n_e` over its elements of one normal, so that its projected area
//! across a unit direction, `P(u) = Σ_g max(0, m_g·u)` (3b.2), is exact for elements of at
//! most [`MOST`] normals in any orientation (a furnished room of turned tables and
//! shelves), where the per-axis sums of its facing areas (3b.8) are exact only for
//! axis-aligned ones (a cube turned 45° about the vertical shows twice its area along the
//! normal of one of its sides).
//! Beyond [`MOST`] normals the two closest merge: their sum is still exact for every
//! direction that both face or both face away from.

use super::node::FACING;
use glam::DVec3;

/// Most vector areas a cluster keeps.
pub const MOST: usize = 16;

/// Cosine above which two normals count as one.
const SAME: f64 = 1.0 - 1e-12;

/// A cluster's vector areas, m² (empty for an element: its patch has its one normal).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct VectorAreas(Vec<DVec3>);

impl VectorAreas {
    /// The one vector area of a face of exposed area `exposed` (m²) and unit normal `normal`.
    pub fn face(exposed: f64, normal: DVec3) -> VectorAreas {
        VectorAreas(if exposed > 0.0 { vec![exposed * normal] } else { Vec::new() })
    }

    /// Adds `member`'s vector areas, each times `open`, the member's openness along the six
    /// axis directions (`openness.rs`) mixed by the squares of its direction's components:
    /// exactly `o_{Dc}` for a face turned to the axis direction `c`, as in (3b.8).
    pub fn add(&mut self, member: &VectorAreas, open: &[f64; FACING]) {
        for &m in &member.0 {
            let n = m.normalize();
            let mix = [n.x, -n.x, n.y, -n.y, n.z, -n.z];
            let openness: f64 = mix.iter().zip(open).map(|(c, o)| c.max(0.0).powi(2) * o).sum();
            if openness > 0.0 {
                self.insert(m * openness);
            }
        }
    }

    /// Projected area across the unit direction `u`, counting what faces `u`, m²:
    /// `Σ_g max(0, m_g·u)`.
    pub fn projected(&self, u: DVec3) -> f64 {
        self.0.iter().map(|m| m.dot(u).max(0.0)).sum()
    }

    /// Adds `m` to the vector area of its normal, or as a new one; beyond [`MOST`], the two
    /// whose normals are closest merge.
    fn insert(&mut self, m: DVec3) {
        let n = m.normalize();
        if let Some(same) = self.0.iter_mut().find(|k| k.normalize().dot(n) > SAME) {
            *same += m;
            return;
        }
        self.0.push(m);
        if self.0.len() > MOST {
            let (i, j) = self.closest();
            let merged = self.0.swap_remove(j);
            self.0[i] += merged;
        }
    }

    /// The two vector areas whose normals are closest, `i < j`.
    fn closest(&self) -> (usize, usize) {
        let units: Vec<DVec3> = self.0.iter().map(|m| m.normalize()).collect();
        let pairs = (0..units.len()).flat_map(|i| (i + 1..units.len()).map(move |j| (i, j)));
        pairs.max_by(|&(a, b), &(c, d)| units[a].dot(units[b]).total_cmp(&units[c].dot(units[d]))).unwrap_or((0, 1))
    }
}
