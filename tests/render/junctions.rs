//! Smooth shading across T-junctions: leaves of different levels of the hierarchical
//! kernel meet where a corner of two small leaves lies at the midpoint of a larger
//! neighbour's edge. The image must have no seam there.

use glam::DVec3;
use std::path::Path;
use ugo::directions::DirectionSet;
use ugo::geometry::{ConvexPolygon, Mesh, Patch};
use ugo::render::{LitScene, Shading, render};
use ugo::scene::{Camera, Scene};

/// The unit square in z = 0 facing +z as three leaves of 0.5 m and, in its corner
/// `[0.5, 1]²`, four of 0.25 m: two T-junctions, at (0.75, 0.5) and (0.5, 0.75).
fn leaves() -> Mesh {
    let square = |x: f64, y: f64, s: f64| {
        let p = |u: f64, v: f64| DVec3::new(x + u * s, y + v * s, 0.0);
        ConvexPolygon::quad(p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0))
    };
    let mut polygons = vec![square(0.0, 0.0, 0.5), square(0.5, 0.0, 0.5), square(0.0, 0.5, 0.5)];
    polygons.extend(square(0.5, 0.5, 0.5).split());
    let patches: Vec<Patch> =
        polygons.into_iter().enumerate().map(|(i, q)| Patch::from_polygon(q, 0, 0, i as u32)).collect();
    Mesh { emission: vec![0.0; patches.len()], faces: patches.len(), patches }
}

/// The largest difference between neighbouring pixels, across rows and columns.
fn largest_step(image: &ugo::render::Image) -> f64 {
    let at = |x: usize, y: usize| image.luminance[y * image.width + x];
    let mut step: f64 = 0.0;
    for y in 0..image.height {
        for x in 0..image.width {
            if x + 1 < image.width {
                step = step.max((at(x + 1, y) - at(x, y)).abs());
            }
            if y + 1 < image.height {
                step = step.max((at(x, y + 1) - at(x, y)).abs());
            }
        }
    }
    step
}

#[test]
fn smooth_shading_has_no_seam_at_t_junctions_between_leaves_of_two_levels() {
    let mesh = leaves();
    // A field that varies in both directions and is not linear: the mean of the small
    // leaves at a T-junction differs from the interpolation along the large edge by
    // about 2.5 cd/m² (the seam before corners were anchored).
    let field = |p: DVec3| 10.0 + 8.0 * p.x * p.x + 5.0 * p.y;
    let luminance: Vec<f64> = mesh.patches.iter().map(|p| field(p.centroid)).collect();
    let scene = Scene::parse(
        Path::new("square.toml"),
        "[discretization]\npatch_size = 0.5\n[[material]]\nname = \"grey\"\ntype = \"lambert\"\n\
         reflectance = 0.5\n[[surface]]\nname = \"square\"\nshape = \"rectangle\"\nmaterial = \"grey\"\n\
         origin = [0, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 1, 0]\nemission = { luminance = 1.0 }\n"
            .to_string(),
    )
    .expect("valid materials");
    let materials = vec![scene.materials[0].model.clone()];
    let mut lit = LitScene::new(mesh, DirectionSet::single(), luminance, materials);
    lit.set_shading(Shading::Smooth);
    // Seen face on from 2 m with a 24° field: the image lies within [0.075, 0.925]² and
    // crosses both junctions' edges.
    let camera = Camera {
        name: "square".into(),
        position: DVec3::new(0.5, 0.5, 2.0),
        look_at: DVec3::new(0.5, 0.5, 0.0),
        up: DVec3::Y,
        fov_deg: 24.0,
        resolution: [170, 170],
        samples: 1,
    };
    let image = render(&lit, &camera);
    // A pixel spans 0.005 m; the interpolated field changes by well under 0.5 cd/m² over
    // that anywhere but at a seam.
    let step = largest_step(&image);
    assert!(step < 0.5, "largest step between neighbouring pixels {step:.3} cd/m²");
}
