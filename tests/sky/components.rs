//! `DF = SC + ERC + IRC` for every kind of probe and for grids (issue 37, point 2): a
//! cylindrical or semi-cylindrical probe takes the openings' light on its curved side, and
//! its SC is the brute-force `(1/π) ∫ L sinθ dω` (`(1/π) ∫ L sinθ (1 + cos ψ) dω`) over the
//! opening within the midpoint rule's 0.5 %.

use crate::support::over_parallelogram;
use glam::DVec3;
use std::f64::consts::PI;
use ugo::progress::Silent;
use ugo::scene::Scene;
use ugo::study::{Job, solve_case};

/// A 1 × 1 m floor (ρ 0.5) under a 1 × 1 m roof opening 1 m above it, the uniform sky of
/// 10,000 lx, and one probe of each kind 0.5 m under the opening's centre (the half
/// cylinder 0.3 m off it, facing the side where most of the opening lies).
const CASE: &str = r#"
[discretization]
patch_size = 0.25
[[material]]
name = "white"
type = "lambert"
reflectance = 0.5
[[surface]]
name = "floor"
shape = "rectangle"
material = "white"
origin = [0, 0, 0]
edge_u = [0, 0, 1]
edge_v = [1, 0, 0]
[sky]
type = "uniform"
[[window]]
name = "roof"
origin = [0, 1, 0]
edge_u = [1, 0, 0]
edge_v = [0, 0, 1]
[[probe]]
name = "point"
position = [0.5, 0.5, 0.5]
normal = [0, 1, 0]
[[probe]]
name = "meter"
kind = "luminance_meter"
position = [0.5, 0.5, 0.5]
direction = [0, 1, 0]
[[probe]]
name = "cylinder"
kind = "cylindrical"
position = [0.5, 0.5, 0.5]
[[probe]]
name = "half cylinder"
kind = "semi_cylindrical"
position = [0.2, 0.5, 0.5]
direction = [1, 0, 0]
[[grid]]
name = "floor"
origin = [0, 0, 0]
edge_u = [0, 0, 1]
edge_v = [1, 0, 0]
resolution = [3, 3]
"#;

#[test]
fn every_probe_and_grid_point_has_df_equal_to_sc_plus_erc_plus_irc() {
    let scene = Scene::parse(std::path::Path::new("cases/test.toml"), CASE.to_string()).unwrap();
    let s = solve_case(&scene, &Job::default(), &Silent).unwrap();
    let d = s.daylight.as_ref().unwrap();
    let all =
        d.probes.iter().zip(s.probes.iter().map(|p| p.name.as_str())).chain(d.grids[0].iter().map(|x| (x, "grid")));
    for (x, name) in all {
        let sum = x.sky_component + x.externally_reflected + x.internally_reflected;
        assert!((sum - x.daylight_factor).abs() < 1e-9 * x.daylight_factor, "{name}: {x:?}");
        assert!(x.sky_component > 0.0, "{name} sees the sky: {x:?}");
    }
    // the cylinders see the lit floor below: their IRC is its light
    assert!(d.probes[2].internally_reflected > 0.0 && d.probes[3].internally_reflected > 0.0);
    // SC against the brute-force integral over the opening (the uniform sky: L = E_h/π)
    let (o, u, v, p) = (DVec3::new(0.0, 1.0, 0.0), DVec3::X, DVec3::Z, DVec3::new(0.5, 0.5, 0.5));
    let across = |l: DVec3| (l - DVec3::Y * l.y).length();
    let l = 10_000.0 / PI;
    let e_z = over_parallelogram(o, u, v, p, 400, |w, dw| l * across(w) * dw) / PI;
    let q = DVec3::new(0.2, 0.5, 0.5);
    let e_sc = over_parallelogram(o, u, v, q, 400, |w, dw| l * (across(w) + w.x) * dw) / PI;
    for (x, e, name) in [(&d.probes[2], e_z, "E_z"), (&d.probes[3], e_sc, "E_sc")] {
        let sc = x.sky_component * 100.0;
        eprintln!("{name}: SC {sc:.3} lx, brute force {e:.3} lx ({:+.3} %)", 100.0 * (sc / e - 1.0));
        assert!((sc / e - 1.0).abs() < 5e-3, "{name}: SC {sc} lx, brute force {e} lx");
    }
}

#[test]
fn a_lamp_beside_the_daylight_changes_no_daylight_quantity() {
    // the same room with a 2,000 lm bulb under the opening: E holds its light, but SC, ERC,
    // IRC and DF are the daylight's alone (solved alone on the case's kernel), as without it;
    // before, DF and IRC counted the bulb's light (docs/daylight.md, "Daylight beside
    // electric light")
    let lamp = "[[luminaire]]\nname = \"bulb\"\ntype = \"isotropic\"\nflux = 2000\nposition = [0.5, 0.8, 0.5]\n";
    let solved = |case: String| {
        let scene = Scene::parse(std::path::Path::new("cases/test.toml"), case).unwrap();
        solve_case(&scene, &Job::default(), &Silent).unwrap()
    };
    let (alone, lit) = (solved(CASE.to_string()), solved(format!("{CASE}{lamp}")));
    assert!(lit.probes[0].illuminance > alone.probes[0].illuminance + 100.0, "the bulb lights the probe");
    let (a, b) = (alone.daylight.as_ref().unwrap(), lit.daylight.as_ref().unwrap());
    let pairs = a.probes.iter().zip(&b.probes).chain(a.grids[0].iter().zip(&b.grids[0]));
    for (x, y) in pairs {
        for (p, q) in [
            (x.sky_component, y.sky_component),
            (x.externally_reflected, y.externally_reflected),
            (x.internally_reflected, y.internally_reflected),
            (x.daylight_factor, y.daylight_factor),
        ] {
            assert!((p - q).abs() <= 1e-6 * x.daylight_factor, "daylight alone {x:?}, beside the bulb {y:?}");
        }
    }
}
