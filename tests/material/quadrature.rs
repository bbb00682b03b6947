//! Independent reference integrals for the glossy models, written from the formulas alone:
//! composite Gauss–Legendre over the outgoing polar and azimuth angles `(θ, φ)`, with the
//! panels split where the integrand has a kink, so no lobe sampling is shared with src/material.

use std::f64::consts::{FRAC_PI_2, PI};

/// `n`-point Gauss–Legendre nodes and weights on `[-1, 1]` (Newton on `P_n`).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for j in 2..=n {
                    let p2 = ((2 * j - 1) as f64 * x * p1 - (j - 1) as f64 * p0) / j as f64;
                    (p0, p1) = (p1, p2);
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let step = p1 / dp;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// A composite rule: each interval between consecutive `breaks` cut into `panels` panels
/// of the rule `gl`.
pub fn composite(breaks: &[f64], panels: usize, gl: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for w in breaks.windows(2) {
        let h = (w[1] - w[0]) / panels as f64;
        for p in 0..panels {
            let mid = w[0] + (p as f64 + 0.5) * h;
            out.extend(gl.iter().map(|&(x, wt)| (mid + 0.5 * h * x, 0.5 * h * wt)));
        }
    }
    out
}

/// Accuracy of the reference integrals: panels per interval and nodes per panel.
#[derive(Clone, Copy, Debug)]
pub struct Rule {
    pub panels: usize,
    pub nodes: usize,
}

/// The rule of the tests: within 1e-7 of a 3× finer rule (`reference_integrals_converge`).
pub const REFERENCE: Rule = Rule { panels: 2, nodes: 10 };

/// Sorted interval breaks inside `[lo, hi]`: the ends, `inner`, and for each `(centre,
/// scale)` a geometric grading `centre ± scale·2^j` that resolves a peak of any width
/// down to `scale`.
fn breaks(lo: f64, hi: f64, inner: &[f64], peaks: &[(f64, f64)]) -> Vec<f64> {
    let mut b: Vec<f64> = inner.to_vec();
    for &(centre, scale) in peaks {
        b.push(centre);
        let mut step = scale;
        while step < hi - lo {
            b.extend([centre - step, centre + step]);
            step *= 2.0;
        }
    }
    b.retain(|&x| x > lo + 1e-12 && x < hi - 1e-12);
    b.extend([lo, hi]);
    b.sort_by(f64::total_cmp);
    b.dedup_by(|x, y| (*x - *y).abs() < 1e-12);
    b
}

/// Directional-hemispherical reflectance of the normalized Phong lobe with `k_s = 1`,
/// `a(θ_i) = (n+2)/(2π) ∫ max(0, cos α)ⁿ cosθ dω`, incoming direction at `φ = 0`, so
/// `cos α = cosθ cosθ_i − sinθ sinθ_i cos φ` (angle to the mirror direction).
pub fn phong_albedo(n: f64, theta_i: f64, rule: Rule) -> f64 {
    let gl = gauss_legendre(rule.nodes);
    let (ci, si) = (theta_i.cos(), theta_i.sin());
    // the lobe (width 1/√n about θ_i, φ = π) and the kink where cos α = 0 starts to cut the ring
    let width = 0.25 / n.max(1.0).sqrt();
    let peaks = [(theta_i, width), (FRAC_PI_2 - theta_i, width)];
    let thetas = composite(&breaks(0.0, FRAC_PI_2, &[], &peaks), rule.panels, &gl);
    let mut total = 0.0;
    for (theta, wt) in thetas {
        let (a, b) = (theta.cos() * ci, theta.sin() * si);
        // cos α = a − b cos φ grows with φ on [0, π]; it is positive from φ0 on
        let phi0 = if b <= a.abs() { if a > 0.0 { 0.0 } else { continue } } else { (a / b).acos() };
        let phis = composite(&breaks(phi0, PI, &[], &[(PI, width)]), rule.panels, &gl);
        let inner: f64 = phis.iter().map(|&(phi, wp)| wp * power((a - b * phi.cos()).max(0.0), n)).sum();
        total += wt * 2.0 * inner * theta.sin() * theta.cos();
    }
    (n + 2.0) / (2.0 * PI) * total
}

/// `x^n`, exactly by squaring for the integer exponents of the tests.
fn power(x: f64, n: f64) -> f64 {
    if n.fract() == 0.0 && n.abs() < 1e6 { x.powi(n as i32) } else { x.powf(n) }
}

/// Directional-hemispherical reflectance of the GGX specular term with `k_s = 1`:
/// `a(θ_i) = (1/π) ∫ π D(h) G₂(l,l_i) / (4 cosθ cosθ_i) cosθ dω`, with the
/// Trowbridge–Reitz `D(h) = α²/(π ((α²−1) cos²θ_h + 1)²)` and the height-correlated Smith
/// `G₂ = 1/(1 + Λ(θ) + Λ(θ_i))`, `Λ(θ) = (√(1 + α² tan²θ) − 1)/2`.
pub fn ggx_albedo(alpha: f64, theta_i: f64, rule: Rule) -> f64 {
    let gl = gauss_legendre(rule.nodes);
    let a2 = alpha * alpha;
    let lambda = |c: f64| ((1.0 + a2 * (1.0 - c * c) / (c * c)).sqrt() - 1.0) / 2.0;
    let l_in = [theta_i.sin(), 0.0, theta_i.cos()];
    // the lobe about the mirror direction is 2α wide in θ and only 2α cosθ_i in φ·sinθ
    let width = 0.25 * alpha * l_in[2];
    let thetas = composite(&breaks(0.0, FRAC_PI_2, &[], &[(theta_i, width)]), rule.panels, &gl);
    let phis: Vec<(f64, f64, f64)> = composite(&breaks(0.0, PI, &[], &[(PI, width)]), rule.panels, &gl)
        .into_iter()
        .map(|(phi, w)| (phi.cos(), phi.sin(), w))
        .collect();
    let mut total = 0.0;
    for (theta, wt) in thetas {
        let (st, ct) = theta.sin_cos();
        let g2 = 1.0 / (1.0 + lambda(ct) + lambda(l_in[2]));
        let inner: f64 = phis
            .iter()
            .map(|&(cos_phi, sin_phi, wp)| {
                let h = [st * cos_phi + l_in[0], st * sin_phi, ct + l_in[2]];
                let cos2_h = h[2] * h[2] / (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
                let denom = (a2 - 1.0) * cos2_h + 1.0;
                wp * a2 / (PI * denom * denom)
            })
            .sum();
        total += wt * 2.0 * inner * g2 * st;
    }
    total / (4.0 * l_in[2])
}

/// The cos-weighted mean of `a(θ)` over a ring `cos_bottom < cosθ ≤ cos_top`, the block
/// albedo of any of its cells: `(1/μ) ∫ a cosθ dω = 2/(c_t² − c_b²) ∫ a(c) c dc`, by
/// Gauss–Legendre in `c = cosθ`, graded towards the horizon where the lobes are clipped.
pub fn ring_average(cos_bottom: f64, cos_top: f64, nodes: usize, a: impl Fn(f64) -> f64) -> f64 {
    let peaks: &[(f64, f64)] = if cos_bottom == 0.0 { &[(0.0, 0.01)] } else { &[] };
    let integral: f64 = composite(&breaks(cos_bottom, cos_top, &[], peaks), 1, &gauss_legendre(nodes))
        .into_iter()
        .map(|(c, w)| w * a(c.acos()) * c)
        .sum();
    2.0 * integral / (cos_top * cos_top - cos_bottom * cos_bottom)
}

#[test]
fn reference_integrals_converge() {
    let finer = Rule { panels: 6, nodes: 16 };
    for theta in [0.5f64, 30.0, 80.0, 89.5].map(f64::to_radians) {
        for n in [1.0, 1000.0] {
            let error = (phong_albedo(n, theta, REFERENCE) - phong_albedo(n, theta, finer)).abs();
            assert!(error < 1e-7, "phong n = {n}, θ = {theta}: {error}");
        }
        for alpha in [0.05, 0.6] {
            let error = (ggx_albedo(alpha, theta, REFERENCE) - ggx_albedo(alpha, theta, finer)).abs();
            assert!(error < 1e-7, "ggx α = {alpha}, θ = {theta}: {error}");
        }
    }
}

#[test]
fn gauss_legendre_integrates_polynomials_exactly() {
    let rule = gauss_legendre(10);
    let integral = |p: i32| rule.iter().map(|&(x, w)| w * x.powi(p)).sum::<f64>();
    for p in 0..20 {
        let exact = if p % 2 == 0 { 2.0 / (p + 1) as f64 } else { 0.0 };
        assert!((integral(p) - exact).abs() < 1e-14, "x^{p}: {}", integral(p));
    }
}
