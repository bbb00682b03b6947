//! 5.4, luminous flux conservation: an isotropic 10 000 lm source in a black room; every
//! lumen lands on a surface, `Φ_surfaces / Φ = 1`.

use super::{Solved, compare, solved, solved_hierarchically};
use ugo::readout::energy::EnergyBalance;
use ugo::readout::illuminance::patch_illuminance;

#[test]
fn cie_5_4_flux_lands_on_the_surfaces() {
    check_5_4(&solved("5.4-flux-conservation"));
}

/// Issue 14.4: the same through the hierarchy.
#[test]
fn cie_5_4_flux_lands_on_the_surfaces_through_the_hierarchy() {
    check_5_4(&solved_hierarchically("5.4-flux-conservation"));
}

fn check_5_4(s: &Solved) {
    let flux = s.model.sources[0].flux().expect("a point source");
    let landed = s.model.direct.intercepted[0];
    let areas: f64 = s.model.mesh.patches.iter().map(|p| p.area).sum();
    let illuminance = patch_illuminance(&s.model.direct.arriving, 1);
    let weighted: f64 = s.model.mesh.patches.iter().zip(&illuminance).map(|(p, e)| p.area * e).sum();
    eprintln!(
        "5.4: Φ = {flux:.6} lm (file 10000 lm), on the {areas} m² of surfaces {landed:.6} lm, Σ A E_s = {weighted:.6} lm"
    );
    compare("5.4", &[("Φ_surfaces/Φ", 1.0, landed / flux)]);
    assert!((landed / flux - 1.0).abs() < 1e-9, "isotropic light is integrated exactly: {}", landed / flux - 1.0);
    assert!((weighted / landed - 1.0).abs() < 1e-12);
    assert!((flux / 10_000.0 - 1.0).abs() < 1e-6, "the file's table integrates to its lumens: {flux}");

    let energy = EnergyBalance::of(&s.model, &s.x, 1);
    assert!((energy.emitted / flux - 1.0).abs() < 1e-12 && (energy.absorbed / flux - 1.0).abs() < 1e-9, "{energy:?}");
    assert!(energy.escaped.abs() < 1e-6 * flux, "{energy:?}");

    let centre = s.probe("floor centre");
    let exact = 10_000.0 / (4.0 * std::f64::consts::PI) / 1.5f64.powi(2);
    assert!((centre.illuminance / exact - 1.0).abs() < 1e-6, "{} vs {exact}", centre.illuminance);
}
