//! The solve pipeline shared by `ugo solve`, `ugo norms` and `ugo compare`: mesh,
//! assemble, run one or more methods on `x = L0 + K x`, read the probes, check the energy
//! balance, optionally record reflection orders and norms, write HDF5 (and a plot), and
//! print a summary; `compare --photons P` adds each method's agreement with a forward Monte
//! Carlo estimate of the same discretization.

use super::options::Discretize;
use super::{bar, bytes, describe, file_name, load};
use anyhow::{Context, Result, bail};
use std::path::{Path, PathBuf};
use ugo::basis::{Basis, Factorization, Reduced};
use ugo::io::{
    BasisRecord, Run, Solution, convergence_plot, write_grid_csv, write_grid_map, write_probes_csv, write_solution,
};
use ugo::kernel::{Explicit, Factored};
use ugo::model::Model;
use ugo::readout::energy::EnergyBalance;
use ugo::readout::field::Field;
use ugo::readout::grid::{GridReading, read_grids};
use ugo::readout::illuminance::{arriving, patch_illuminance};
use ugo::readout::probe::read_probes;
use ugo::scene::Scene;
use ugo::solve::norms::Norms;
use ugo::solve::orders::{OrderRecord, reflection_orders};
use ugo::solve::{Method, SolveParams, System, relative_residual, solve};
use ugo::trace::{Agreement, TraceOptions, World, agreement, trace_photons};

/// What one command asks of the pipeline.
pub struct Job {
    /// Methods to run; empty means the case's `[solver] method`.
    pub methods: Vec<Method>,
    pub tolerance: Option<f64>,
    pub max_iterations: Option<usize>,
    /// Reflection orders whose partial sums are recorded (`None`: 1, 8, 64 for `neumann`).
    pub orders: Option<Vec<usize>>,
    pub norms: bool,
    pub output: Option<PathBuf>,
    /// Suffix of the default output name (`cornell-box{suffix}.h5`).
    pub suffix: &'static str,
    pub plot: Option<PathBuf>,
    /// Solve for the coefficients of this angular basis instead of the cell values.
    pub basis: Option<Basis>,
    /// Photons of a forward Monte Carlo reference to compare every method with (`compare`).
    pub photons: Option<u64>,
    /// Seed of that reference.
    pub seed: u64,
}

pub fn run(case: &Path, d: &Discretize, job: Job) -> Result<()> {
    let (scene, options) = load(case, d)?;
    let params = SolveParams {
        tolerance: job.tolerance.unwrap_or(scene.solver.tolerance),
        max_iterations: job.max_iterations.unwrap_or(scene.solver.max_iterations),
        memory_limit: options.memory_limit,
        ..SolveParams::default()
    };
    if !(params.tolerance > 0.0 && params.tolerance < 1.0) {
        bail!("--tolerance must lie in (0, 1), got {}", params.tolerance);
    }
    let methods = if job.methods.is_empty() { vec![scene.solver.method] } else { job.methods.clone() };
    let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let output = job.output.clone().unwrap_or_else(|| PathBuf::from(format!("{stem}{}.h5", job.suffix)));

    let assembly = bar(0, "assembly");
    let model = Model::build(&scene, &options, &|total| assembly.set_length(total), &|done| assembly.inc(done))?;
    assembly.finish_and_clear();

    let factors =
        job.basis.map(|b| Factorization::new(b, &model.kernel.blocks, &model.kernel.directions)).transpose()?;
    let reduced = factors.as_ref().map(|f| Reduced::new(&model.kernel, f));
    let source = reduced.as_ref().map(|r| r.source(&model.l0));
    let explicit = if job.norms || methods.iter().any(Method::needs_explicit) {
        Some(Explicit(match &reduced {
            Some(r) => r.explicit(options.memory_limit)?,
            None => model.kernel.explicit(options.memory_limit)?,
        }))
    } else {
        None
    };
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let factored = Factored::new(&model.kernel);
    let mut runs: Vec<(Run, Vec<f64>)> = Vec::new();
    for method in &methods {
        let solving = bar(params.max_iterations as u64, &method.name());
        let system = match (&reduced, &source) {
            (Some(r), Some(s)) => System { operator: r, explicit: explicit.as_ref(), areas: &[], l0: s },
            _ => System::of(&model.kernel, &factored, explicit.as_ref(), &areas, &model.l0),
        };
        let result = solve(*method, &system, &params, &mut |n, r| {
            solving.set_position(n as u64);
            solving.set_message(format!("{} {r:.1e}", method.name()));
        });
        solving.finish_and_clear();
        match result {
            Ok((x, info)) => runs.push((Run { method: *method, info, difference: 0.0 }, x)),
            Err(e) if methods.len() > 1 => eprintln!("ugo: {} failed: {e}", method.name()),
            Err(e) => return Err(e.into()),
        }
    }
    if runs.is_empty() {
        bail!("every method failed");
    }
    let reference = runs.iter().position(|(r, _)| r.method == Method::Direct).unwrap_or_else(|| {
        (0..runs.len()).min_by(|&a, &b| runs[a].0.info.residual().total_cmp(&runs[b].0.info.residual())).unwrap_or(0)
    });
    let coefficients = runs[reference].1.clone();
    let x = match &reduced {
        Some(r) => r.field(&model.l0, &coefficients),
        None => coefficients.clone(),
    };
    let basis = factors.as_ref().map(|f| BasisRecord {
        factors: f,
        coefficients: &coefficients,
        full_residual: relative_residual(&factored, &model.l0, &x),
    });
    let x_ref = &coefficients;
    let scale = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (run, y) in &mut runs {
        run.difference = y.iter().zip(x_ref).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
    }
    let reference_mc = job.photons.map(|p| {
        // each run's field (a reduced solve holds basis coefficients)
        let fields: Vec<Vec<f64>> =
            runs.iter().map(|(_, y)| reduced.as_ref().map_or_else(|| y.clone(), |r| r.field(&model.l0, y))).collect();
        forward_reference(&scene, &model, p, job.seed, &fields)
    });
    let runs: Vec<Run> = runs.into_iter().map(|(r, _)| r).collect();

    let k = model.kernel.cells();
    let field = Field::from_unknowns(&x, k);
    let illuminance = patch_illuminance(&arriving(&model, &x), k);
    let energy = EnergyBalance::of(&model, &x, scene.surfaces.len());
    let probes = read_probes(&scene.probes, &model, &field);
    let grids = read_grids(&scene.grids, &model, &field);
    let orders = order_record(&job, &methods, &model);
    let norms = explicit.as_ref().filter(|_| job.norms).map(Norms::of);
    let solution = Solution {
        scene: &scene,
        model: &model,
        field: &field,
        illuminance: &illuminance,
        params: &params,
        info: &runs[reference].info,
        energy: &energy,
        probes: &probes,
        grids: &grids,
        orders: orders.as_ref(),
        runs: &runs,
        norms: norms.as_ref(),
        basis: basis.as_ref(),
    };
    write_solution(&output, &solution).with_context(|| format!("writing {}", output.display()))?;
    summary(&solution, &output);
    write_grids(&grids, &output)?;
    if !probes.is_empty() {
        let csv = PathBuf::from(format!("{}-probes.csv", output.with_extension("").display()));
        write_probes_csv(&csv, &probes)?;
        println!("  probes             {}", csv.display());
    }
    if let Some(orders) = &orders {
        print_orders(orders, &x);
    }
    if let Some(norms) = &norms {
        print_norms(norms, &params, &runs);
    }
    if runs.len() > 1 || reference_mc.is_some() {
        print_comparison(&runs, reference_mc.as_ref());
    }
    if let Some(plot) = &job.plot {
        convergence_plot(plot, &format!("{}: convergence of every method", scene.name), &runs)
            .map_err(|e| anyhow::anyhow!("writing {}: {e}", plot.display()))?;
        println!("  plot               {}", plot.display());
    }
    Ok(())
}

fn order_record(job: &Job, methods: &[Method], model: &Model) -> Option<OrderRecord> {
    if job.basis.is_some() {
        return None;
    }
    let orders = match &job.orders {
        Some(o) => o.clone(),
        None if methods.contains(&Method::Neumann) => vec![1, 8, 64],
        None => return None,
    };
    if model.l0.iter().all(|&l| l == 0.0) {
        return None;
    }
    Some(reflection_orders(&Factored::new(&model.kernel), &model.l0, &orders))
}

fn summary(s: &Solution, output: &Path) {
    let m = s.model;
    let st = &m.stats;
    let g = &m.kernel.g;
    println!("ugo: {} ({})", s.scene.name, s.scene.path.display());
    println!("  patches N          {:>12}", m.mesh.len());
    println!("  direction cells K  {:>12}   ({})", m.kernel.cells(), m.kernel.directions.name());
    println!("  unknowns           {:>12}", g.rows());
    println!("  non-zeros of G     {:>12}   ({}, {})", g.nnz(), bytes(g.bytes()), g.precision().name());
    let assembly = st.mesh_seconds + st.bvh_seconds + st.kernel_seconds + st.light_seconds;
    println!(
        "  assembly           {assembly:>12.3} s   ({} pairs, {} occlusion rays, balanced by {}: correction {:.1e}, {} sweeps, row error {:.0e})",
        st.pairs,
        st.rays,
        if st.balance.by_cell { "cell" } else { "patch" },
        st.balance.max_correction,
        st.balance.iterations,
        st.balance.residual
    );
    let i = s.info;
    println!(
        "  solve              {:>12.3} s   ({}, {} iterations, residual {:.2e})",
        i.seconds,
        i.method,
        i.iterations,
        i.residual()
    );
    if let Some(b) = s.basis {
        println!(
            "  basis              {:>12}   ({} coefficients per patch, rank {}; residual of the field in the full system {:.2e})",
            b.factors.basis.name(),
            b.factors.m,
            b.factors.rank,
            b.full_residual
        );
    }
    let e = s.energy;
    if !m.sources.is_empty() {
        println!("  luminaires               emitted lm   on surfaces lm");
        for ((source, emitted), landed) in m.sources.iter().zip(&e.luminaire_emitted).zip(&m.direct.intercepted) {
            println!("    {:<22} {emitted:>12.4} {landed:>16.4}   {}", source.name, describe(source));
        }
    }
    println!("  flux emitted       {:>12.4} lm", e.emitted);
    println!("  flux absorbed      {:>12.4} lm", e.absorbed);
    println!("  flux escaped       {:>12.4} lm", e.escaped);
    println!("  imbalance          {:>12.3e} (relative to emitted)", e.imbalance / e.emitted);
    if !s.probes.is_empty() {
        println!("  probes                   luminance cd/m²   illuminance lx   of it direct lx");
        for p in s.probes {
            println!("    {:<22} {:>15.4} {:>16.4} {:>17.4}", p.name, p.luminance, p.illuminance, p.direct);
        }
    }
    println!("  written            {}", output.display());
}

/// Each grid's CSV and false-colour map beside the HDF5 file, `<stem>-<grid>.{csv,png}`.
fn write_grids(grids: &[GridReading], output: &Path) -> Result<()> {
    if grids.is_empty() {
        return Ok(());
    }
    println!("  grids                      E_avg lx     E_min lx     E_max lx      U0");
    let stem = output.with_extension("");
    for g in grids {
        let st = g.stats();
        println!("    {:<22} {:>12.4} {:>12.4} {:>12.4} {:>7.4}", g.grid.name, st.average, st.min, st.max, st.u0);
        let base = format!("{}-{}", stem.display(), file_name(&g.grid.name));
        let (csv, png) = (PathBuf::from(format!("{base}.csv")), PathBuf::from(format!("{base}.png")));
        write_grid_csv(&csv, g)?;
        write_grid_map(&png, g)?;
        println!("      {}\n      {}", csv.display(), png.display());
    }
    Ok(())
}

fn print_norms(n: &Norms, params: &SolveParams, runs: &[Run]) {
    let observed =
        runs.iter().find(|r| r.method == Method::Neumann).map_or("-".to_string(), |r| r.info.iterations.to_string());
    println!("  norms of K");
    println!("    ‖K‖₁             {:>12.6}", n.one);
    println!("    ‖K‖∞             {:>12.6}", n.infinity);
    println!("    ‖K‖_F            {:>12.6}", n.frobenius);
    println!(
        "    ‖K‖₂             {:>12.6}   ({} power iterations{})",
        n.two.value,
        n.two.iterations,
        converged(n.two.converged)
    );
    let r = &n.spectral_radius;
    println!("    ρ(K)             {:>12.6}   ({} power iterations{})", r.value, r.iterations, converged(r.converged));
    println!("    cond∞(I − K)     {:>12.4}", n.condition_infinity);
    println!(
        "    Neumann iterations to {:.0e}: predicted {:.1}, observed {observed}",
        params.tolerance,
        n.predicted_iterations(params.tolerance)
    );
}

fn print_orders(orders: &OrderRecord, x: &[f64]) {
    let l0 = orders.term_norms[0];
    println!(
        "  reflection orders  ‖KⁿL0‖/‖L0‖, and the partial sum's distance from the solution ‖x − Σ_(m≤n) KᵐL0‖/‖x‖"
    );
    let norm = |v: &mut dyn Iterator<Item = f64>| v.map(|e| e * e).sum::<f64>().sqrt();
    let scale = norm(&mut x.iter().copied());
    for (n, sum) in &orders.partial_sums {
        let deficit = norm(&mut sum.iter().zip(x).map(|(s, x)| x - s)) / scale;
        println!("    n = {n:<4} term {:>10.3e}   distance {:>10.3e}", orders.term_norms[*n] / l0, deficit);
    }
}

fn converged(ok: bool) -> &'static str {
    if ok { "" } else { ", NOT converged" }
}

/// The forward Monte Carlo estimate of the same discretization, and each run's agreement with it.
struct MonteCarlo {
    photons: u64,
    seconds: f64,
    agreements: Vec<Agreement>,
}

fn forward_reference(scene: &Scene, model: &Model, photons: u64, seed: u64, fields: &[Vec<f64>]) -> MonteCarlo {
    let world = World::new(scene, model.mesh.clone());
    let progress = bar(photons, "photons");
    let options = TraceOptions { seed, max_order: None };
    let estimate = trace_photons(&world, &model.kernel.directions, photons, &options, &|n| progress.inc(n));
    progress.finish_and_clear();
    let agreements = fields.iter().map(|x| agreement(x, &estimate.luminance, &estimate.luminance_error)).collect();
    MonteCarlo { photons, seconds: estimate.seconds, agreements }
}

fn print_comparison(runs: &[Run], mc: Option<&MonteCarlo>) {
    let extra =
        if mc.is_some() { format!(" {:>8} {:>8} {:>11}", "rms z", "max |z|", "rel. L1") } else { String::new() };
    println!(
        "  {:<14} {:>10} {:>13} {:>10} {:>12} {:>14}{extra}",
        "method", "iterations", "applications", "time s", "residual", "max rel. diff"
    );
    for (n, r) in runs.iter().enumerate() {
        let i = &r.info;
        let extra = mc.map_or(String::new(), |mc| {
            let a = &mc.agreements[n];
            format!(" {:>8.3} {:>8.2} {:>11.3e}", a.rms_z, a.max_abs_z, a.relative_l1)
        });
        println!(
            "  {:<14} {:>10} {:>13} {:>10.3} {:>12.2e} {:>14.2e}{extra}",
            r.method.name(),
            i.iterations,
            i.applications,
            i.seconds,
            i.residual(),
            r.difference
        );
    }
    if let Some(mc) = mc {
        println!(
            "  {:<14} {:>10} {:>13} {:>10.3}   (z: each method against this forward Monte Carlo estimate, \
             {} photons)",
            "forward MC", "-", "-", mc.seconds, mc.photons
        );
    }
}
