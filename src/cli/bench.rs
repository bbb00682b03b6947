//! `ugo bench`: throughput of the visibility queries, per BVH layout, on a case.
//!
//! Rays join random points of random facing patch pairs, as in the kernel assembly.
//! Each layout (binary or compressed wide BVH, obvhs build preset, scene turned by a
//! generic rotation or not) traces the same rays on all cores. A correctness column
//! counts the axis-aligned rays, one dropped onto every patch along its normal, that
//! failed to find that patch ("lost").

use super::load;
use crate::Discretize;
use anyhow::Result;
use glam::DVec3;
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;
use ugo::kernel::facing;
use ugo::model::Model;
use ugo::visibility::{BuildPreset, NO_FACE, Visibility, VisibilityOptions};

pub fn run(case: &Path, d: &Discretize, rays: usize) -> Result<()> {
    let (scene, options) = load(case, d)?;
    let mesh = Model::mesh(&scene, &options);
    let segments = segments(&mesh, rays);
    println!(
        "ugo bench: {} ({} patches, {} rays per layout, {} threads)",
        scene.name,
        mesh.len(),
        segments.len(),
        rayon::current_num_threads()
    );
    println!(
        "  {:<8} {:<7} {:<7} {:>10} {:>14} {:>9} {:>6}",
        "bvh", "preset", "rotated", "build ms", "rays/s", "visible", "lost"
    );
    for wide in [false, true] {
        for preset in [BuildPreset::Fast, BuildPreset::Medium, BuildPreset::Slow] {
            for rotate in [false, true] {
                let t = Instant::now();
                let v = Visibility::build_with(&mesh, VisibilityOptions { wide, rotate, preset });
                let build = t.elapsed().as_secs_f64();
                let t = Instant::now();
                let seen: usize = segments.par_iter().map(|(a, b, f)| v.visible(*a, *b, *f) as usize).sum();
                let rate = segments.len() as f64 / t.elapsed().as_secs_f64();
                let lost = mesh
                    .patches
                    .par_iter()
                    .filter(|p| {
                        let hit = v.closest_hit(p.centroid + 1e-3 * p.normal, -p.normal, NO_FACE);
                        hit.is_none_or(|h| h.face != p.face)
                    })
                    .count();
                let name = if wide { "cwbvh" } else { "bvh2" };
                let visible = 100.0 * seen as f64 / segments.len() as f64;
                let preset = format!("{preset:?}");
                let build = build * 1e3;
                println!("  {name:<8} {preset:<7} {rotate:<7} {build:>10.1} {rate:>14.3e} {visible:>8.1}% {lost:>6}");
            }
        }
    }
    Ok(())
}

/// `count` segments between interior points of random facing patch pairs.
fn segments(mesh: &ugo::geometry::Mesh, count: usize) -> Vec<(DVec3, DVec3, [u32; 2])> {
    let n = mesh.len() as u64;
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let (i, j) = ((next() % n) as usize, (next() % n) as usize);
        let (a, b) = (&mesh.patches[i], &mesh.patches[j]);
        if i == j || !facing(a, b) {
            continue;
        }
        let pa = ugo::kernel::occlusion::sample_points(a)[(next() % 4) as usize];
        let pb = ugo::kernel::occlusion::sample_points(b)[(next() % 4) as usize];
        out.push((pa, pb, [a.face, b.face]));
    }
    out
}
