//! `ugo solve CASE -o OUT.h5`: mesh, assemble, solve by successive approximation, read
//! the probes, check the energy balance, write HDF5 and print a summary.

use super::{bar, bytes, load};
use crate::Discretize;
use anyhow::{Context, Result, bail};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use ugo::energy::EnergyBalance;
use ugo::field::Field;
use ugo::io::{Solution, write_solution};
use ugo::kernel::{Factored, LinOp};
use ugo::model::Model;
use ugo::probe::read_probes;
use ugo::solve::{SolveParams, successive_approximation};

pub fn run(
    case: &Path,
    output: Option<PathBuf>,
    d: &Discretize,
    tolerance: Option<f64>,
    max_iterations: Option<usize>,
) -> Result<()> {
    let (scene, options) = load(case, d)?;
    let params = SolveParams {
        tolerance: tolerance.unwrap_or(scene.solver.tolerance),
        max_iterations: max_iterations.unwrap_or(scene.solver.max_iterations),
    };
    if !(params.tolerance > 0.0 && params.tolerance < 1.0) {
        bail!("--tolerance must lie in (0, 1), got {}", params.tolerance);
    }
    let output = output
        .unwrap_or_else(|| PathBuf::from(format!("{}.h5", case.file_stem().unwrap_or_default().to_string_lossy())));

    let assembly = bar(0, "assembly");
    let model = Model::build(&scene, &options, &|total| assembly.set_length(total), &|done| assembly.inc(done))?;
    assembly.finish_and_clear();

    let kernel = Factored::new(&model.kernel);
    let solving = bar(params.max_iterations as u64, "solve");
    let (x, info) = successive_approximation(&kernel, &model.l0, &params, &mut |n, r| {
        solving.set_position(n as u64);
        solving.set_message(format!("{r:.1e}"));
    })?;
    solving.finish_and_clear();

    let k = model.kernel.cells();
    let field = Field::from_unknowns(&x, k);
    let mut gx = vec![0.0; kernel.dim()];
    model.kernel.apply_transport(&x, &mut gx);
    let illuminance: Vec<f64> = gx.chunks(k).map(|c| PI * c.iter().sum::<f64>()).collect();
    let energy = EnergyBalance::of(&model.mesh, &model.kernel, &model.l0, &x, scene.surfaces.len());
    let probes = read_probes(&scene.probes, &model, &field);
    let solution = Solution {
        scene: &scene,
        model: &model,
        field: &field,
        illuminance: &illuminance,
        params: &params,
        info: &info,
        energy: &energy,
        probes: &probes,
    };
    write_solution(&output, &solution).with_context(|| format!("writing {}", output.display()))?;
    summary(&solution, &output);
    Ok(())
}

fn summary(s: &Solution, output: &Path) {
    let m = s.model;
    let st = &m.stats;
    let g = &m.kernel.g;
    println!("ugo solve: {} ({})", s.scene.name, s.scene.path.display());
    println!("  patches N          {:>12}", m.mesh.len());
    println!("  direction cells K  {:>12}", m.kernel.cells());
    println!("  unknowns           {:>12}", g.rows());
    println!("  non-zeros of G     {:>12}   ({})", g.nnz(), bytes(g.nnz() as f64 * 16.0));
    println!(
        "  assembly           {:>12.3} s   ({} pairs, {} occlusion rays, balance correction {:.1e})",
        st.mesh_seconds + st.bvh_seconds + st.kernel_seconds,
        st.pairs,
        st.rays,
        st.balance.max_correction
    );
    println!(
        "  solve              {:>12.3} s   ({}, {} iterations, residual {:.2e})",
        s.info.seconds,
        s.info.method,
        s.info.iterations,
        s.info.residual()
    );
    let e = s.energy;
    println!("  flux emitted       {:>12.4} lm", e.emitted);
    println!("  flux absorbed      {:>12.4} lm", e.absorbed);
    println!("  flux escaped       {:>12.4} lm", e.escaped);
    println!("  imbalance          {:>12.3e} (relative to emitted)", e.imbalance / e.emitted);
    if !s.probes.is_empty() {
        println!("  probes                   luminance cd/m²   illuminance lx");
        for p in s.probes {
            println!("    {:<22} {:>15.4} {:>16.4}", p.name, p.luminance, p.illuminance);
        }
    }
    println!("  written            {}", output.display());
}
