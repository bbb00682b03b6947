//! Every method stops at the iteration where a value out of range first appears and says
//! so, with the unknown's patch and surface; never "no convergence … residual NaN" nor a
//! spectral radius (issue 18, item 2). The model's own checks (`tests/model/range.rs`)
//! refuse such values before a solve; here they are put into a built model, as a library
//! caller could.

use crate::support::{build, furnace};
use ugo::kernel::{Explicit, Factored};
use ugo::material::Block;
use ugo::model::{Model, locate};
use ugo::solve::{Method, SolveError, SolveParams, System, solve};

const METHODS: [Method; 7] = [
    Method::Neumann,
    Method::GaussSeidel,
    Method::Southwell,
    Method::Gmres { restart: 30 },
    Method::Bicgstab,
    Method::Direct,
    Method::DirectSparse,
];

fn attempt(model: &Model, method: Method) -> SolveError {
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let factored = Factored::new(&model.kernel);
    let system = System::of(&model.kernel, &factored, Some(&explicit), &areas, &model.l0);
    let params = SolveParams { tolerance: 1e-12, max_iterations: 2000, ..SolveParams::default() };
    match solve(method, &system, &params, &mut |_, _| {}) {
        Ok(_) => panic!("{}: a solution from values out of range", method.name()),
        Err(e) => e,
    }
}

fn out_of_range(e: &SolveError, method: Method) -> String {
    let text = e.to_string();
    assert!(matches!(e, SolveError::OutOfRange(_)), "{}: {text}", method.name());
    assert!(text.starts_with("value out of range:"), "{text}");
    assert!(!text.contains("no convergence") && !text.contains("spectral"), "{text}");
    text
}

#[test]
fn a_nan_in_the_kernel_stops_every_method_at_once_named_by_patch_and_surface() {
    let scene = furnace(1.0, 0.5, 1.0, 0.5);
    let mut model = build(&scene);
    model.kernel.blocks[0] = Block::new(1, vec![f64::NAN], None);
    for method in METHODS {
        let e = attempt(&model, method);
        let text = out_of_range(&e, method);
        assert!(text.contains("NaN"), "{text}");
        if let SolveError::OutOfRange(r) = &e {
            assert!(r.iteration.is_none_or(|n| n <= 1), "{}: found at iteration {:?}", method.name(), r.iteration);
        }
        let named = locate(e, &scene, &model.mesh, model.l0.len()).to_string();
        assert!(named.contains("patch 0 of surface \"room\", cell 0"), "{named}");
    }
}

#[test]
fn a_solution_whose_norm_overflows_is_out_of_range_not_singular() {
    // L0 = 1e153 cd/m² on 24 unknowns: ‖L0‖₂ is finite, the solution 1e154 of ρ = 0.9 is
    // finite in every value, but its norm is not.
    let mut model = build(&furnace(1.0, 0.9, 1.0, 0.5));
    model.l0.iter_mut().for_each(|l| *l *= 1e153);
    for method in [Method::Neumann, Method::Gmres { restart: 30 }, Method::Bicgstab, Method::Direct] {
        let text = out_of_range(&attempt(&model, method), method);
        assert!(text.contains("overflows") && text.contains("although every value is finite"), "{text}");
    }
}

#[test]
fn a_source_term_whose_norm_overflows_is_refused_before_the_first_iteration() {
    let mut model = build(&furnace(1.0, 0.5, 1.0, 0.5));
    model.l0.iter_mut().for_each(|l| *l *= 1e160);
    for method in METHODS {
        let text = out_of_range(&attempt(&model, method), method);
        assert!(text.contains("before its first iteration") && text.contains("‖L0‖₂ overflows"), "{text}");
    }
}
