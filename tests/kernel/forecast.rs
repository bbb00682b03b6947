//! The forecast before meshing (issue 18, item 3): element counts without the elements,
//! facing pairs from the coarsest elements, and the refusal of a model over the memory
//! limit before anything is allocated.

use crate::support::{build, furnace};
use glam::DVec3;
use std::time::Instant;
use ugo::directions::{DirectionSet, Scheme};
use ugo::geometry::{Mesh, Shape, element_count, tessellate};
use ugo::kernel::{Forecast, Need};
use ugo::model::{Model, ModelError};
use ugo::scene::{Hierarchical, KernelKind};

#[test]
fn element_counts_equal_the_tessellation_of_every_shape() {
    let shapes = [
        Shape::Rectangle { origin: DVec3::ZERO, edge_u: DVec3::new(1.3, 0.0, 0.0), edge_v: DVec3::new(0.0, 0.2, 0.7) },
        Shape::Polygon {
            vertices: [[0., 0.], [2., 0.], [2., 1.], [1., 1.], [1., 2.], [0., 2.]]
                .map(|[x, z]| DVec3::new(x, 0.0, z))
                .to_vec(),
        },
        Shape::Polygon {
            vertices: [[0., 0.], [1., 0.], [1.2, 0.9], [0., 1.]].map(|[x, z]| DVec3::new(x, 0.0, z)).to_vec(),
        },
        Shape::Box { min: DVec3::ZERO, max: DVec3::new(1.0, 0.3, 2.2), rotate_y_deg: 30.0 },
        Shape::Disc { center: DVec3::ZERO, normal: DVec3::Y, radius: 0.8 },
        Shape::Sphere { center: DVec3::ZERO, radius: 0.5 },
        Shape::Mesh {
            file: "t.obj".into(),
            triangles: vec![[DVec3::ZERO, DVec3::X, DVec3::Z], [DVec3::X, DVec3::new(2.0, 1.0, 0.0), DVec3::Z]],
        },
    ];
    for shape in &shapes {
        for h in [10.0, 0.5, 0.13, 0.05] {
            assert_eq!(element_count(shape, h), tessellate(shape, h).len() as f64, "{shape:?} at {h}");
        }
    }
}

#[test]
fn the_forecast_of_a_closed_box_counts_its_facing_pairs_exactly() {
    let scene = furnace(1.0, 0.5, 1.0, 0.1);
    let f = Model::forecast(&scene);
    let mesh = Mesh::build(&scene.surfaces, 0.1);
    let counted = Forecast::counted(&mesh, 1, &scene.discretization.directions.set());
    assert_eq!(f.patches, 600.0);
    assert_eq!(f.facing_pairs, counted.facing_pairs);
    assert_eq!(f.nonzeros, counted.nonzeros);
    assert!(f.peak_bytes() >= counted.peak_bytes());
    // K = 16 spreads each pair over cells: within a factor of two of the mesh's estimate.
    let k16 = DirectionSet::hemisphere(16);
    let f = Forecast::uniform(&scene.surfaces, 1, 0.1, &k16);
    let counted = Forecast::counted(&mesh, 1, &k16);
    assert!((f.nonzeros / counted.nonzeros - 1.0).abs() < 0.5, "{} against {}", f.nonzeros, counted.nonzeros);
    build(&scene);
}

#[test]
fn tiny_patch_sizes_are_refused_before_meshing_with_the_estimate() {
    for h in [1e-4, 1e-6, 1e-12, 1e-300, 5e-324] {
        let scene = furnace(1.0, 0.5, 1.0, h);
        let started = Instant::now();
        let result = Model::build(&scene, &ugo::progress::Silent);
        let Err(ModelError::TooLarge(e)) = result else { panic!("patch_size {h}: not refused before meshing") };
        let Need::Model(forecast) = &e.need else { panic!("patch_size {h}: refused as a matrix") };
        assert!(started.elapsed().as_secs_f64() < 1.0, "patch_size {h}: {:?}", started.elapsed());
        let message = e.to_string();
        for fragment in
            ["patches", "facing pairs", "non-zeros", "GiB", "--patch-size", "--memory-limit", "--kernel hierarchical"]
        {
            assert!(message.contains(fragment), "{message} lacks {fragment}");
        }
        assert!(forecast.patches >= 6.0 / (h * h) * 0.99 || forecast.patches.is_infinite(), "{message}");
    }
}

#[test]
fn the_material_blocks_count_in_the_forecast() {
    // One patch per face, but 65535 cells: each material's K × K block is 34 GB.
    let scene = furnace(1.0, 0.5, 1.0, 2.0);
    let k = DirectionSet::hemisphere(65535);
    let f = Forecast::uniform(&scene.surfaces, 1, 2.0, &k);
    assert_eq!(f.block_bytes, 65535.0 * 65535.0 * 8.0);
    let mut scene = scene;
    scene.discretization.directions = Scheme::Cells(65535);
    scene.discretization.memory_limit = 16 << 30;
    let Err(ModelError::TooLarge(e)) = Model::build(&scene, &ugo::progress::Silent) else {
        panic!("65535 cells accepted under 16 GiB")
    };
    assert!(e.to_string().contains("material blocks"), "{e}");
}

#[test]
fn the_hierarchy_forecasts_its_roots_and_its_most_leaves() {
    let mut scene = furnace(1.0, 0.5, 1.0, 0.01);
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size: 0.25,
        link_tolerance: 0.1,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    let f = Model::forecast(&scene);
    assert_eq!(f.patches, 6.0 * 16.0);
    assert_eq!(f.leaves, Some(6.0 * 200.0 * 200.0), "the uniform mesh at patch_size / 2");
    assert_eq!(f.nonzeros, 0.0);
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size: 1e-9,
        link_tolerance: 0.1,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    let Err(ModelError::TooLarge(e)) = Model::build(&scene, &ugo::progress::Silent) else {
        panic!("a hierarchy of 6e18 roots accepted")
    };
    assert!(e.to_string().contains("roots of the hierarchy"), "{e}");
}
