//! Backward probe readings against the opal diffuser's closed forms
//! (`tests/solve/opal.rs`): illuminance under the panel `π L F`, luminance on top
//! `τ L F`, and illuminance 1 m above it, each within 3 standard errors.

use crate::solve::opal::{LUMINANCE, TAU, exact_above, factor};
use std::f64::consts::PI;
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use ugo::geometry::Mesh;
use ugo::scene::Scene;
use ugo::trace::{TraceOptions, World, trace_probes};

#[test]
fn probes_read_the_opal_closed_forms() {
    let scene = Scene::load(Path::new("cases/opal-diffuser.toml")).unwrap();
    let world = World::new(&scene, Mesh::build(&scene.surfaces, scene.discretization.patch_size));
    let paths = AtomicU64::new(0);
    let count = |n| _ = paths.fetch_add(n, Ordering::Relaxed);
    let r = trace_probes(&world, &scene.probes, 65_536, &TraceOptions::default(), &count);
    assert_eq!(paths.into_inner(), 2 * 65_536 * scene.probes.len() as u64, "progress hears of every path");
    let centre = factor(0.5, 0.5);
    let checks = [
        ("illuminance under the panel", r[0].illuminance, PI * LUMINANCE * centre),
        ("luminance on top", r[1].luminance, TAU * LUMINANCE * centre),
        ("luminance seen from 1 m above", r[2].luminance, TAU * LUMINANCE * centre),
        ("illuminance 1 m above", r[2].illuminance, exact_above(16)),
    ];
    for (what, (value, error), exact) in checks {
        let z = (value - exact) / error;
        eprintln!("opal probe, {what}: {value:.4} ± {error:.4} against {exact:.4}, z {z:+.2}");
        assert!(error > 0.0 && z.abs() < 3.0, "{what}: z {z}");
    }
    assert_eq!((r[0].luminance, r[1].illuminance), ((0.0, 0.0), (0.0, 0.0)), "black below, nothing above");
}
