//! How a gather cuts the pieces of a patch crossed by a shadow edge by the light they carry
//! (`docs/design.md` §5, the gather `I_d(p)`; `docs/hierarchy.md`, "Readouts"): a piece is
//! cut further while the light it would send unoccluded exceeds a fraction (`SHADOW_CUT`,
//! `RELIT_SHADOW_CUT`) of all the point would receive unoccluded, by the field read; or, for
//! fields read alike and summed (a light scene's groups, `residual_samples.rs`), while it
//! does by any of them: every field is cut at least as finely as its own rule asks, and all
//! of them in the same pieces, so that a gather of `Σ_g f_g x_g` is the sum of theirs.

use super::field::Field;

/// The rule a gather cuts by: the fraction, and the fields it is applied to (none: the
/// field read); and below which light a patch is seen by one ray.
#[derive(Debug, Clone, Copy)]
pub struct Cut<'a> {
    /// The fraction of all the light the point would receive unoccluded.
    pub fraction: f64,
    /// The fields whose rules are united; empty for the field read alone.
    pub by: &'a [&'a Field],
    /// A patch whose light unoccluded is below this fraction of all the point would receive
    /// unoccluded, by every field, is seen by one ray to one of its stratified points
    /// chosen at random (`transfer::occlusion::sample_one`): an unbiased estimate of what its
    /// points see. 0: every patch by all its points.
    pub sampled: f64,
}

impl Cut<'static> {
    /// The rule of the field read alone.
    pub fn own(fraction: f64) -> Cut<'static> {
        Cut { fraction, by: &[], sampled: 0.0 }
    }
}

/// Per field of a [`Cut`], the light every candidate (a patch, or a patch's image in a
/// mirror) would send unoccluded, and the least light of a piece cut further.
pub(super) struct Worth {
    unoccluded: Vec<Vec<f64>>,
    least: Vec<f64>,
    sampled: Vec<f64>,
}

impl Worth {
    /// The candidates' light: `scale · (geometric[k] · max_m |L(patch(k), m)|)` by each field
    /// of `cut` (`field`, the one read, when it names none).
    pub(super) fn new(
        cut: &Cut,
        field: &Field,
        geometric: &[f64],
        patch: impl Fn(usize) -> usize,
        scale: f64,
    ) -> Worth {
        let own = [field];
        let fields = if cut.by.is_empty() { &own[..] } else { cut.by };
        let light = |f: &&Field| -> Vec<f64> {
            geometric.iter().enumerate().map(|(k, g)| scale * (g * f.brightest(patch(k)))).collect()
        };
        let unoccluded: Vec<Vec<f64>> = fields.iter().map(light).collect();
        let all: Vec<f64> = unoccluded.iter().map(|u| u.iter().sum::<f64>()).collect();
        let least = all.iter().map(|a| cut.fraction * a).collect();
        let sampled = all.iter().map(|a| cut.sampled * a).collect();
        Worth { unoccluded, least, sampled }
    }

    /// Whether candidate `k` sends light by any field.
    pub(super) fn lit(&self, k: usize) -> bool {
        self.unoccluded.iter().any(|u| u[k] > 0.0)
    }

    /// The light candidate `k` would send unoccluded, summed over the fields.
    pub(super) fn light(&self, k: usize) -> f64 {
        self.unoccluded.iter().map(|u| u[k]).sum()
    }

    /// Whether candidate `k` is seen by one ray ([`Cut::sampled`]).
    pub(super) fn sampled(&self, k: usize) -> bool {
        self.unoccluded.iter().zip(&self.sampled).all(|(u, sampled)| u[k] < *sampled)
    }

    /// Whether a piece of area `piece` of candidate `k` (of area `area`) is cut further.
    pub(super) fn cuts(&self, k: usize, area: f64, piece: f64) -> bool {
        self.unoccluded.iter().zip(&self.least).any(|(u, least)| u[k] / area * piece > *least)
    }
}
