//! The visibility part of `ugo bench`: occlusion rays like the assembly's (segments
//! between stratified points of random facing patch pairs) through the default layout,
//! and optionally through every layout (binary or compressed wide BVH, obvhs build
//! preset, scene turned by a generic rotation or not) with a correctness column counting
//! the axis-aligned rays, one dropped onto every patch along its normal, that failed to
//! find that patch ("lost"). Also the dense-LU timings of `--lu`.

use glam::DVec3;
use rayon::prelude::*;
use std::time::Instant;
use ugo::geometry::Mesh;
use ugo::geometry::facing;
use ugo::random::Rng;
use ugo::visibility::{BuildPreset, NO_FACE, Visibility, VisibilityOptions};

/// A segment between two faces, ignoring both.
pub type Segment = (DVec3, DVec3, [u32; 2]);

/// Occlusion rays per second through `visibility` (all threads of the current pool).
pub fn rays_per_second(visibility: &Visibility, segments: &[Segment]) -> f64 {
    let t = Instant::now();
    let seen: usize = segments.par_iter().map(|(a, b, f)| visibility.visible(*a, *b, *f) as usize).sum();
    std::hint::black_box(seen);
    segments.len() as f64 / t.elapsed().as_secs_f64()
}

/// Every layout on the same segments, as a table.
pub fn all_layouts(mesh: &Mesh, segments: &[Segment]) {
    println!(
        "  {:<8} {:<7} {:<7} {:>10} {:>14} {:>9} {:>6}",
        "bvh", "preset", "rotated", "build ms", "rays/s", "visible", "lost"
    );
    for wide in [false, true] {
        for preset in [BuildPreset::Fast, BuildPreset::Medium, BuildPreset::Slow] {
            for rotate in [false, true] {
                let t = Instant::now();
                let v = Visibility::build_with(mesh, VisibilityOptions { wide, rotate, preset });
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
}

/// `count` segments between interior points of random facing patch pairs (reproducible),
/// or `None` when no facing pair turns up in `1000 · count` draws (a scene of one plate,
/// or of luminaires and a floor only, has nothing to time).
pub fn segments(mesh: &Mesh, count: usize) -> Option<Vec<Segment>> {
    let n = mesh.len() as u64;
    if n < 2 {
        return None;
    }
    let mut rng = Rng::stream(0x2545_F491_4F6C_DD1D, 0);
    let mut out = Vec::with_capacity(count);
    for _ in 0..1000 * count.max(1) {
        if out.len() == count {
            break;
        }
        let (i, j) = ((rng.next_u64() % n) as usize, (rng.next_u64() % n) as usize);
        let (a, b) = (&mesh.patches[i], &mesh.patches[j]);
        if i == j || !facing(a, b) {
            continue;
        }
        let pa = ugo::transfer::occlusion::sample_points(a)[(rng.next_u64() % 4) as usize];
        let pb = ugo::transfer::occlusion::sample_points(b)[(rng.next_u64() % 4) as usize];
        out.push((pa, pb, [a.face, b.face]));
    }
    (!out.is_empty()).then_some(out)
}

/// Times the dense LU (factor and solve) of an `n × n` matrix like `I − K` in faer and in
/// nalgebra, and checks both residuals.
pub fn dense_lu(n: usize) {
    let entry = |i: usize, j: usize| {
        let h = ((i * 7919 + j * 104_729) % 1000) as f64 / 1000.0;
        if i == j { 1.0 } else { -0.8 * h / n as f64 }
    };
    let b: Vec<f64> = (0..n).map(|i| 1.0 + (i % 3) as f64).collect();
    let residual = |x: &[f64]| {
        (0..n).map(|i| (0..n).map(|j| entry(i, j) * x[j]).sum::<f64>() - b[i]).map(f64::abs).fold(0.0, f64::max)
    };
    let t = Instant::now();
    let a = faer::Mat::<f64>::from_fn(n, n, entry);
    let x = faer::linalg::solvers::Solve::solve(&a.partial_piv_lu(), faer::Col::<f64>::from_fn(n, |i| b[i]));
    let faer_seconds = t.elapsed().as_secs_f64();
    let faer_x: Vec<f64> = (0..n).map(|i| x[i]).collect();
    let t = Instant::now();
    let a = nalgebra::DMatrix::<f64>::from_fn(n, n, entry);
    let x = a.lu().solve(&nalgebra::DVector::from_column_slice(&b)).unwrap_or_else(|| nalgebra::DVector::zeros(n));
    let nalgebra_seconds = t.elapsed().as_secs_f64();
    let flops = 2.0 / 3.0 * (n as f64).powi(3);
    println!(
        "dense LU n = {n}: faer {faer_seconds:.3} s ({:.1} GFLOP/s, residual {:.1e}), nalgebra {nalgebra_seconds:.3} s ({:.1} GFLOP/s, residual {:.1e})",
        flops / faer_seconds / 1e9,
        residual(&faer_x),
        flops / nalgebra_seconds / 1e9,
        residual(x.as_slice())
    );
}
