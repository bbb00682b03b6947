//! Fresnel panes (`glass = "fresnel"`, the default of a glazed `[[window]]`): the
//! directional transmittance `τ(θ)` of one or two panes of clear glass, the usual Fresnel
//! model (as in window-energy programs, e.g. LBNL WINDOW):
//! per polarisation, the air–glass reflectance `r` (Fresnel, refractive index `n`), the
//! internal transmittance `a = a₀^{1/cos θ'}` along the refracted path `θ'`, a pane's
//! `t = (1 − r)² a / (1 − r² a²)` and `ρ = r + (1 − r)² r a² / (1 − r² a²)`, two panes
//! `t² / (1 − ρ²)`; `τ` is the mean of the two polarisations. `a₀` is chosen so that one
//! pane transmits the given normal transmittance `τ_n` (`docs/daylight.md`).

/// One or two identical panes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fresnel {
    /// Refractive index of the glass.
    pub index: f64,
    /// Internal transmittance of one pane at normal incidence (absorption), in (0, 1].
    pub internal: f64,
    /// 1 or 2.
    pub panes: u8,
}

impl Fresnel {
    /// Panes of refractive index `index` of which one transmits `normal` at normal
    /// incidence; `None` when `normal` exceeds what a lossless pane transmits,
    /// `2n/(n² + 1)`.
    pub fn new(normal: f64, index: f64, panes: u8) -> Option<Fresnel> {
        let r = ((index - 1.0) / (index + 1.0)).powi(2);
        let (p, q) = ((1.0 - r).powi(2), r * r * normal);
        // q a² + p a − τ_n = 0 for the pane's internal transmittance a.
        let internal = if q == 0.0 { normal / p } else { (-p + (p * p + 4.0 * q * normal).sqrt()) / (2.0 * q) };
        (normal > 0.0 && internal <= 1.0 + 1e-12).then_some(Fresnel { index, internal: internal.min(1.0), panes })
    }

    /// The largest normal transmittance of a lossless pane of refractive index `index`.
    pub fn lossless(index: f64) -> f64 {
        2.0 * index / (index * index + 1.0)
    }

    /// `τ(θ)` for `cos θ` the cosine of the incidence on the opening.
    pub fn transmittance(&self, cos: f64) -> f64 {
        let cos = cos.abs().min(1.0);
        if cos <= 1e-9 {
            return 0.0; // grazing: everything is reflected (and 0/0 in the two-pane sum)
        }
        let n = self.index;
        let sin_t = (1.0 - cos * cos).sqrt() / n;
        let cos_t = (1.0 - sin_t * sin_t).max(0.0).sqrt();
        let rs = ((cos - n * cos_t) / (cos + n * cos_t)).powi(2);
        let rp = ((cos_t - n * cos) / (cos_t + n * cos)).powi(2);
        let a = self.internal.powf(1.0 / cos_t);
        let polarised = |r: f64| {
            let d = 1.0 - r * r * a * a;
            let t = (1.0 - r).powi(2) * a / d;
            let rho = r + (1.0 - r).powi(2) * r * a * a / d;
            if self.panes == 2 { t * t / (1.0 - rho * rho) } else { t }
        };
        0.5 * (polarised(rs) + polarised(rp))
    }
}
