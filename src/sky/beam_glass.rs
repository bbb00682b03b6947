//! The glass a parallel beam (the sun of `[sky]`, or a `type = "parallel"` luminaire) passes
//! on its way in through the `[[window]]` openings (`docs/daylight.md`, "The sun through
//! glass").
//!
//! Parallel light is a boundary condition of the equation of `docs/design.md` §1 like the
//! sky: its illuminance at a point `x` of normal `n` is `E_n cos θ V(x) T(x)`, `V` whether
//! the ray from `x` towards the source leaves the scene and
//!
//! `T(x) = Π_j τ_j(θ_j) M_j`
//!
//! over the openings `j` that ray crosses: the glazing's directional transmittance at the
//! beam's incidence `θ_j` on the opening (`glazing.rs`) times the window's maintenance
//! factor, exactly what the sky seen through the same opening in the same direction is
//! multiplied by (`window.rs`, and the window's sky scaled by `M`). An unglazed opening with
//! `M = 1` is a hole and is not listed. The product is the Monte Carlo tracer's rule for a
//! ray through several openings (`crate::trace`).

use super::Opening;
use glam::DVec3;

/// The openings that attenuate a beam crossing them: glazed, or kept at `M < 1`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BeamGlass {
    panes: Vec<Pane>,
}

/// One opening a beam may cross.
#[derive(Debug, Clone, PartialEq)]
pub struct Pane {
    /// The window's name.
    pub name: String,
    /// The opening and its glazing.
    pub opening: Opening,
    /// The window's maintenance factor `M`, in (0, 1].
    pub maintenance: f64,
}

impl Pane {
    /// `τ(θ) M` of a beam from the unit direction `towards` (towards the source).
    pub fn share(&self, towards: DVec3) -> f64 {
        let cos = towards.dot(self.opening.polygon.normal());
        self.maintenance * self.opening.glazing.map_or(1.0, |g| g.transmittance(cos))
    }
}

impl BeamGlass {
    /// The panes among `panes` that attenuate: glazed, or with `M < 1`.
    pub fn new(panes: impl IntoIterator<Item = Pane>) -> BeamGlass {
        let panes = panes.into_iter().filter(|p| p.opening.glazing.is_some() || p.maintenance < 1.0).collect();
        BeamGlass { panes }
    }

    /// The attenuating openings.
    pub fn panes(&self) -> &[Pane] {
        &self.panes
    }

    /// `T(x)`: the share of a beam from the unit direction `towards` (towards the source)
    /// that arrives at `x`, the product of `τ(θ) M` of every listed opening the ray from
    /// `x` along `towards` crosses (1 when it crosses none). Whether the ray leaves the
    /// scene is the caller's.
    pub fn share(&self, x: DVec3, towards: DVec3) -> f64 {
        self.panes
            .iter()
            .filter(|p| p.opening.polygon.crossing(x, towards).is_some())
            .map(|p| p.share(towards))
            .product()
    }

    /// The share of the beam on a piece of a surface whose test points `points` see the
    /// source as `escapes` says, `seen` of them (a fraction): `seen T` when `T` is the same
    /// at every point (the piece lies wholly behind one glass, or behind none), else the
    /// mean of `V T` over the points, `escapes` asked again.
    pub fn over_points(&self, points: &[DVec3], towards: DVec3, seen: f64, escapes: &dyn Fn(DVec3) -> bool) -> f64 {
        if self.panes.is_empty() || points.is_empty() {
            return seen;
        }
        let shares: Vec<f64> = points.iter().map(|&x| self.share(x, towards)).collect();
        if shares.iter().all(|&s| s == shares[0]) {
            return seen * shares[0];
        }
        let lit: f64 = points.iter().zip(&shares).filter(|&(&x, _)| escapes(x)).map(|(_, s)| s).sum();
        lit / points.len() as f64
    }
}
