//! What a grid's plan draws over its cells (issue 37, point 5): a luminaire switched off in
//! a light scene is a hollow marker, a dimmed one carries its level, and the outlines of
//! furniture cut by the grid's plane are drawn at the box's section.

use super::grid_map::reading;
use crate::support::{rectangle, scratch, surface};
use glam::{DVec3, Vec3Swizzles};
use image::RgbImage;
use ugo::geometry::{Mesh, Shape, section};
use ugo::io::{GridPlan, Overlay, write_grid_map};
use ugo::luminaire::{Light, Source, frame};
use ugo::photometry::Distribution;
use ugo::readout::grid::GridReading;

/// A 4 × 2 m floor grid (x right, z down the page).
fn floor() -> GridReading {
    reading(DVec3::new(4.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 2.0), DVec3::Y, (0, 0))
}

fn drawn(g: &GridReading, name: &str, overlay: &Overlay) -> RgbImage {
    let dir = scratch("plan-marks");
    let path = dir.join(format!("{name}.png"));
    write_grid_map(&path, g, overlay).unwrap();
    image::open(&path).unwrap().to_rgb8()
}

/// The pixel of the world point `p` on the plan of `g` with luminaires at `lamps`.
fn pixel_of(g: &GridReading, lamps: &[DVec3], p: DVec3) -> (u32, u32) {
    let plan = GridPlan::of(g, lamps);
    let q = plan.layout.pixel(plan.frame.plan(p));
    (q.x.round() as u32, q.y.round() as u32)
}

#[test]
fn a_switched_off_luminaire_is_hollow_and_a_dimmed_one_carries_its_level() {
    let g = floor();
    let at = DVec3::new(2.0, 2.5, 1.0);
    let light = Light::Point {
        position: at,
        frame: frame(DVec3::NEG_Y, 0.0),
        distribution: Distribution::Isotropic { intensity: 100.0 },
        scale: 1.0,
    };
    let full = [Source { name: "lamp".into(), light, dimmed: 1.0 }];
    let (off, half) = ([full[0].scaled(0.0)], [full[0].scaled(0.5)]);
    let none = drawn(&g, "none", &Overlay::default());
    let on = drawn(&g, "full", &Overlay { sources: &full, section: &[] });
    let hollow = drawn(&g, "off", &Overlay { sources: &off, section: &[] });
    let dimmed = drawn(&g, "dimmed", &Overlay { sources: &half, section: &[] });
    let (x, y) = pixel_of(&g, &[at], at);
    assert_eq!(on.get_pixel(x, y).0, [0, 0, 0], "the cross of a luminaire at full output");
    assert_ne!(hollow.get_pixel(x, y), on.get_pixel(x, y), "off differs from full at the luminaire's pixel");
    assert_eq!(hollow.get_pixel(x, y), none.get_pixel(x, y), "an switched-off marker is hollow");
    assert_ne!(hollow.get_pixel(x + 7, y), none.get_pixel(x + 7, y), "its ring is drawn");
    let label = |png: &RgbImage| {
        (x + 10..x + 45)
            .flat_map(|i| (y - 6..y + 7).map(move |j| (i, j)))
            .filter(|&(i, j)| png.get_pixel(i, j).0.iter().all(|&c| c < 60))
            .count()
    };
    assert_eq!(label(&on), 0, "no level beside a luminaire at full output");
    assert!(label(&dimmed) > 10, "the level of a dimmed luminaire is written beside it");
    assert_eq!(dimmed.get_pixel(x, y).0, [0, 0, 0], "a dimmed luminaire keeps its cross");
}

#[test]
fn a_box_crossing_the_work_plane_is_drawn_at_its_section() {
    let mut g = floor();
    g.grid.origin.y = 0.75;
    let desk = Shape::Box { min: DVec3::new(1.0, 0.0, 0.5), max: DVec3::new(2.0, 0.9, 1.5), rotate_y_deg: 0.0 };
    let low = Shape::Box { min: DVec3::new(3.0, 0.0, 0.5), max: DVec3::new(3.5, 0.7, 1.5), rotate_y_deg: 0.0 };
    let ground = rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [4.0, 0.0, 0.0]);
    let surfaces = vec![
        surface("desk", desk, 0, false, None),
        surface("low", low, 0, false, None),
        surface("floor", ground, 0, false, None),
    ];
    let mesh = Mesh::build(&surfaces, 0.25);
    let cut = section(&mesh, g.grid.origin, g.grid.normal);
    let length: f64 = cut.iter().map(|[a, b]| (*b - *a).length()).sum();
    assert!((length - 4.0).abs() < 1e-9, "the desk's perimeter at 0.75 m, 4 m: {length}");
    for end in cut.iter().flatten() {
        let on_side = [end.x - 1.0, end.x - 2.0, end.z - 0.5, end.z - 1.5].iter().any(|d| d.abs() < 1e-9);
        let within = (1.0..=2.0).contains(&end.x) && (0.5..=1.5).contains(&end.z);
        assert!((end.y - 0.75).abs() < 1e-9 && on_side && within, "{end} is not on the desk's section");
    }
    let plain = drawn(&g, "no-section", &Overlay::default());
    let outlined = drawn(&g, "section", &Overlay { sources: &[], section: &cut });
    for side in
        [DVec3::new(1.5, 0.75, 0.5), DVec3::new(2.0, 0.75, 1.0), DVec3::new(1.5, 0.75, 1.5), DVec3::new(1.0, 0.75, 1.0)]
    {
        let (x, y) = pixel_of(&g, &[], side);
        assert_eq!(outlined.get_pixel(x, y).0, [40, 40, 40], "the section at {}", side.xz());
        assert_ne!(plain.get_pixel(x, y).0, [40, 40, 40]);
    }
    let (x, y) = pixel_of(&g, &[], DVec3::new(3.25, 0.75, 1.0));
    assert_eq!(outlined.get_pixel(x, y), plain.get_pixel(x, y), "the low box under the plane is not drawn");
}
