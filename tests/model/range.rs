//! Values out of range in the source term and the kernel are caught when the model is
//! built, named by what holds them and where (issue 18, item 2). The scene's limits keep
//! every case file far below them, so the scenes here are changed after validation, as a
//! library caller could.

use crate::support::furnace;
use glam::DVec3;
use ugo::kernel::{Precision, Transport, TransportMatrix};
use ugo::luminaire::{Luminaire, LuminaireKind, PointLuminaire};
use ugo::material::MaterialModel;
use ugo::model::{Model, ModelError, check_transport};
use ugo::photometry::Distribution;
use ugo::scene::{Hierarchical, KernelKind, Scene};

fn refused(scene: &Scene) -> String {
    match Model::build(scene, &ugo::progress::Silent) {
        Ok(_) => panic!("a model with values out of range was built"),
        Err(e) => {
            assert!(matches!(e, ModelError::OutOfRange(_)), "{e}");
            let text = e.to_string();
            assert!(text.starts_with("value out of range:"), "{text}");
            assert!(!text.contains("converge") && !text.contains("spectral"), "{text}");
            text
        }
    }
}

fn hierarchical(mut scene: Scene) -> Scene {
    let root_size = scene.discretization.patch_size;
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size,
        link_tolerance: 1e-2,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    scene.discretization.patch_size = 0.25;
    scene
}

#[test]
fn an_emission_whose_square_overflows_is_named_in_the_source_term() {
    // 1e200 cd/m² is finite, but ‖L0‖₂ is not: every solver would fail on it.
    let scene = furnace(1.0, 0.5, 1e200, 0.5);
    for scene in [scene.clone(), hierarchical(scene)] {
        let text = refused(&scene);
        assert!(text.contains("the source term L0") && text.contains("surface \"room\""), "{text}");
        assert!(text.contains("1e200") && text.contains("overflows"), "{text}");
    }
}

#[test]
fn a_nan_emission_is_named_at_its_surface() {
    let text = refused(&furnace(1.0, 0.5, f64::NAN, 0.5));
    assert!(text.contains("own emission L_e") && text.contains("NaN") && text.contains("\"room\""), "{text}");
}

#[test]
fn a_luminaire_whose_flux_overflows_is_named() {
    let mut scene = furnace(1.0, 0.5, 1.0, 0.5);
    let kind = LuminaireKind::Point(PointLuminaire {
        position: DVec3::splat(0.5),
        aim: DVec3::NEG_Y,
        rotate_deg: 0.0,
        multiplier: 1.0,
        distribution: Distribution::Isotropic { intensity: 1e308 },
        file: None,
    });
    scene.luminaires.push(Luminaire { name: "lamp".into(), kind });
    let text = refused(&scene);
    assert!(text.contains("luminaire \"lamp\"") && text.contains("inf"), "{text}");
}

#[test]
fn a_material_block_that_is_not_finite_is_named_by_material() {
    let mut scene = furnace(1.0, 0.5, 1.0, 0.5);
    scene.materials[0].model = MaterialModel::Lambert { reflectance: f64::NAN, transmittance: 0.0 };
    for scene in [scene.clone(), hierarchical(scene)] {
        let text = refused(&scene);
        assert!(text.contains("reflection ρ̄ block of the material \"grey\"") && text.contains("NaN"), "{text}");
    }
}

#[test]
fn a_form_factor_that_is_not_finite_is_named_by_both_patches() {
    let scene = furnace(1.0, 0.5, 1.0, 0.5);
    let model = crate::support::build(&scene);
    let mut g = model.kernel.g.as_double().unwrap().clone();
    let (row, column) = (5, g.outer_view(5).unwrap().indices()[2]);
    *g.get_mut(row, column).unwrap() = f64::INFINITY;
    let g = Transport::Uniform(TransportMatrix::new(g, Precision::Double));
    let text = check_transport(&scene, &model.mesh, &g, 1).unwrap_err().to_string();
    let expected = format!("the form factor G to patch {column} of surface \"room\", cell 0 is inf at patch 5 of");
    assert!(text.starts_with("value out of range: ") && text.contains(&expected), "{text}");
}
