//! The correction near geometry (`docs/design.md` (5.4), `readout/correction.rs`) where the
//! field is exact: in a white furnace every point's gathered luminance is the patches'
//! own, so a probe 1 cm from the room's edge, whose neighbouring 0.5 m patches lie far
//! closer than their size, is corrected by nothing.

use super::{readings, room};

#[test]
fn a_furnace_is_corrected_by_nothing_near_its_edges() {
    // ρ = 0.8, every face emitting 10 cd/m²: L = 10 / (1 − 0.8) = 50 cd/m² everywhere, and
    // E = π L on every receiver inside the room (its own face's emission excluded: E = π L).
    let probes = "[[probe]]\nname = \"floor by the edge\"\nposition = [0.3, 0.001, 0.01]\nnormal = [0, 1, 0]\n\
                  [[probe]]\nname = \"in the corner\"\nposition = [0.01, 0.01, 0.01]\nnormal = [1, 1, 1]\n";
    let read = readings(&format!("{}{probes}", room(1.0, 0.8, 10.0)));
    let exact = std::f64::consts::PI * 50.0;
    for r in &read {
        eprintln!("{}: E {:.6} lx (exact {exact:.6}), correction {:.3e} lx", r.name, r.illuminance, r.correction);
        assert!(r.correction.abs() < 1e-6 * exact, "{}: corrected by {:.3e} lx", r.name, r.correction);
        assert!((r.illuminance / exact - 1.0).abs() < 1e-4, "{}: {} lx", r.name, r.illuminance);
    }
}
