//! `ugo info CASE`: what the case will cost, before any assembly: first from the surfaces'
//! closed forms, before meshing (a model over the memory limit is refused there), then
//! counted on the mesh.

use super::options::Discretize;
use super::{bytes, describe, load};
use anyhow::{Context, Result};
use std::path::Path;
use ugo::kernel::{Forecast, figure};
use ugo::luminaire::Source;
use ugo::model::Model;
use ugo::scene::{KernelKind, number};

pub fn run(case: &Path, asked: &Discretize) -> Result<()> {
    let scene = load(case, asked)?;
    let d = &scene.discretization;
    let forecast = Model::forecast(&scene);
    print_forecast(&forecast, d.kernel.name());
    // (a choice of the hierarchy is told on stderr as the case loads)
    if let (Some(chosen), KernelKind::Uniform) = (d.chosen_by_size, d.kernel) {
        say!("  kernel             not given: {chosen}");
    }
    forecast.check(d.memory_limit).with_context(|| super::size_key::sized_by(case, asked, &scene))?;
    let mesh = Model::starting_mesh(&scene);
    let directions = d.directions.set();
    let estimate = Forecast::counted(&mesh, scene.materials.len(), &directions);
    let areas = mesh.surface_areas(scene.surfaces.len());
    say!("ugo info: {} ({})", scene.name, case.display());
    say!("  patch size         {:>12} m", number(d.patch_size));
    if let KernelKind::Hierarchical(h) = d.kernel {
        say!("  root size          {:>12} m   (link tolerance {:.0e})", h.root_size, h.link_tolerance);
    }
    say!("  surfaces           {:>12}", scene.surfaces.len());
    for (s, a) in scene.surfaces.iter().zip(&areas) {
        let n = mesh.patches.iter().filter(|p| scene.surfaces[p.surface as usize].name == s.name).count();
        say!("    {:<24} {:>6} patches  {:>10.4} m²", s.name, n, a);
    }
    if !scene.luminaires.is_empty() {
        say!("  luminaires");
        for source in scene.luminaires.iter().map(Source::of) {
            let flux = source.flux().map_or("unbounded beam".to_string(), |f| format!("{f:.4} lm"));
            say!("    {:<24} {:>16}   {}", source.name, flux, describe(&source));
        }
    }
    say!("  patches N          {:>12.0}", estimate.patches);
    say!("  direction cells K  {:>12}   ({})", estimate.cells, directions.name());
    say!("  unknowns           {:>12.0}", estimate.unknowns);
    say!("  facing pairs       {:>12.0}{}", estimate.facing_pairs, if estimate.sampled { " (sampled)" } else { "" });
    say!("  non-zeros of G     {:>12.0}   (upper bound: occlusion removes some)", estimate.nonzeros);
    say!("  kernel memory      {:>12}", bytes(estimate.kernel_bytes));
    say!("  assembly peak      {:>12}", bytes(estimate.assembly_bytes));
    say!("  memory limit       {:>12}", bytes(d.memory_limit as f64));
    Ok(())
}

/// The figures known before meshing.
fn print_forecast(f: &Forecast, assembly: &str) {
    say!("ugo info: before meshing ({assembly} kernel, from the surfaces' areas and the patch size)");
    say!("  patches N          {:>12}", figure(f.patches));
    if let Some(leaves) = f.leaves {
        say!("  leaves at most     {:>12}   (links are known only after refinement)", figure(leaves));
    } else {
        say!("  facing pairs       {:>12}{}", figure(f.facing_pairs), if f.sampled { " (sampled)" } else { "" });
        say!("  non-zeros of G     {:>12}", figure(f.nonzeros));
    }
    say!("  unknowns           {:>12}   ({} cells)", figure(f.unknowns), f.cells);
    match f.leaves {
        Some(_) => say!(
            "  memory before links {:>11}   (the links' memory is checked against the limit after each refinement pass)",
            bytes(f.peak_bytes())
        ),
        None => say!("  memory at peak     {:>12}", bytes(f.peak_bytes())),
    }
}
