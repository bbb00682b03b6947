//! The study of angular bases (`docs/design.md` §4, kernel factorization): one case solved in
//! the full cell basis and in several factored bases (hemispherical harmonics, truncated
//! SVD), each with its error against the full angular solution, its unknowns, the memory
//! of its assembled operator, its time and its residual in the full system.

use super::error::StudyError;
use crate::basis::{Basis, Factorization, Reduced};
use crate::kernel::Factored;
use crate::model::Model;
use crate::progress::Progress;
use crate::scene::Scene;
use crate::solve::{Method, SolveParams, System, relative_residual, solve};
use std::time::Instant;

/// One line of the study.
pub struct BasisRow {
    /// The basis, as `--bases` names it (`full`, `sh:L`, `svd:R`).
    pub name: String,
    /// Unknowns of the solved system.
    pub unknowns: usize,
    /// Bytes of the assembled operator (the explicit `B·G` or `Φᵀ G Ψ`).
    pub memory: f64,
    /// Wall time of the solve, s.
    pub seconds: f64,
    /// Iterations of the solve.
    pub iterations: usize,
    /// Relative L² error of the field.
    pub error: f64,
    /// Largest error relative to the largest luminance.
    pub max_error: f64,
    /// `‖L0 + K x − x‖₂/‖L0‖₂` of the field in the full system.
    pub residual: f64,
}

/// The model of a case and one row per basis (`None`: the full cell basis).
pub struct BasisStudy {
    /// The case's model, shared by every row.
    pub model: Model,
    /// One row per basis, in the order asked.
    pub rows: Vec<BasisRow>,
}

/// Solves `scene` with `method` in the full basis and in each of `bases`.
pub fn compare_bases(
    scene: &Scene,
    bases: &[Option<Basis>],
    method: Method,
    params: SolveParams,
    progress: &dyn Progress,
) -> Result<BasisStudy, StudyError> {
    let params = SolveParams { memory_limit: scene.discretization.memory_limit, ..params };
    let model = Model::build(scene, progress)?;
    let factored = Factored::new(&model.kernel);
    let start = Instant::now();
    let system = System::of(&model.kernel, &factored, None, &[], &model.l0);
    let (reference, info) = solve(method, &system, &params, &mut |_, _| {})?;
    let full_seconds = start.elapsed().as_secs_f64();
    let norm = |v: &mut dyn Iterator<Item = f64>| v.map(|e| e * e).sum::<f64>().sqrt();
    let scale = norm(&mut reference.iter().copied());
    let peak = reference.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let n = model.mesh.len();
    let mut rows = Vec::new();
    for basis in bases {
        let row = match basis {
            None => BasisRow {
                name: "full".into(),
                unknowns: reference.len(),
                memory: model.kernel.explicit_nonzeros() * 16.0,
                seconds: full_seconds,
                iterations: info.iterations,
                error: 0.0,
                max_error: 0.0,
                residual: relative_residual(&factored, &model.l0, &reference),
            },
            Some(b) => {
                let start = Instant::now();
                let factors = Factorization::new(*b, &model.kernel.blocks, &model.kernel.directions)?;
                let reduced = Reduced::new(&model.kernel, &factors);
                let source = reduced.source(&model.l0);
                let system = System { operator: &reduced, explicit: None, areas: &[], l0: &source };
                let (c, info) = solve(method, &system, &params, &mut |_, _| {})?;
                let x = reduced.field(&model.l0, &c);
                let seconds = start.elapsed().as_secs_f64();
                let diff: Vec<f64> = x.iter().zip(&reference).map(|(a, r)| a - r).collect();
                BasisRow {
                    name: b.name(),
                    unknowns: n * factors.m,
                    memory: reduced.explicit_nonzeros() * 16.0,
                    seconds,
                    iterations: info.iterations,
                    error: norm(&mut diff.iter().copied()) / scale,
                    max_error: diff.iter().fold(0.0f64, |m, v| m.max(v.abs())) / peak,
                    residual: relative_residual(&factored, &model.l0, &x),
                }
            }
        };
        rows.push(row);
    }
    Ok(BasisStudy { model, rows })
}
