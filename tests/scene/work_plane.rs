//! `work_plane = { height, border }` of a `[[grid]]` (issue 37, point 1): the area is the
//! surfaces' plan less the border, the spacing EN 12464-1's `p = 0.2 · 5^log10(d)`, the
//! normal up; mixing it with the corner keys, or a border that leaves nothing, is refused.

use super::{BASE, assert_error, parse, rejected};
use glam::DVec3;
use ugo::scene::en12464_spacing;

const GRID: &str = "[[grid]] \"task\" (#1)";

/// A room `x × 3 × z` m seen from inside, its ceiling emitting, and a work plane.
fn room(x: f64, z: f64, work_plane: &str) -> String {
    format!(
        "{BASE}\n[[surface]]\nname = \"room\"\nshape = \"box\"\nmin = [0, 0, 0]\nmax = [{x}, 3, {z}]\n\
         inside = true\nmaterial = \"white\"\nemission = {{ luminance = 10.0 }}\n\n\
         [[grid]]\nname = \"task\"\nwork_plane = {work_plane}\n"
    )
}

#[test]
fn en12464_spacing_is_one_metre_at_ten_metres_and_a_fifth_at_one() {
    // 5^log10(10) = 5 and 5^log10(1) = 1: p = 1 m and 0.2 m exactly
    assert!((en12464_spacing(10.0) - 1.0).abs() < 1e-15 && (en12464_spacing(1.0) - 0.2).abs() < 1e-15);
    // d = 100 m: 0.2 · 25 = 5 m
    assert!((en12464_spacing(100.0) - 5.0).abs() < 1e-13);
}

#[test]
fn a_work_plane_covers_the_plan_less_its_border_at_the_standard_spacing() {
    let scene = parse(&room(11.0, 7.0, "{ height = 0.8 }")).unwrap();
    let g = &scene.grids[0];
    // area 10 × 6 m (0.5 m border by default): d = 10 m, p = 1 m, ⌈6/1⌉ × ⌈10/1⌉ points
    assert_eq!(g.origin, DVec3::new(0.5, 0.8, 0.5));
    assert_eq!((g.edge_u, g.edge_v), (DVec3::new(0.0, 0.0, 6.0), DVec3::new(10.0, 0.0, 0.0)));
    assert_eq!((g.resolution, g.normal), ([6, 10], DVec3::Y));
    let scene = parse(&room(1.0, 0.5, "{ height = 0.75, border = 0 }")).unwrap();
    // d = 1 m, p = 0.2 m: 5 × ⌈0.5/0.2⌉ = 3 points
    assert_eq!(scene.grids[0].resolution, [3, 5]);
}

#[test]
fn a_work_plane_mixed_with_corner_keys_or_left_empty_is_refused() {
    let mixed = room(4.0, 4.0, "{ height = 0.8 }") + "resolution = [2, 2]\n";
    assert_error(&rejected(&mixed), GRID, "resolution", &["give `work_plane` or"]);
    assert_error(&rejected(&room(4.0, 4.0, "{ height = 0.8, border = 2 }")), GRID, "work_plane", &["no area"]);
    assert_error(&rejected(&room(4.0, 4.0, "{ height = 4 }")), GRID, "work_plane", &["outside the scene"]);
    let none = format!(
        "{BASE}\n[[surface]]\nname = \"room\"\nshape = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n\
        inside = true\nmaterial = \"white\"\nemission = {{ luminance = 1.0 }}\n[[grid]]\nname = \"task\"\n"
    );
    assert_error(&rejected(&none), GRID, "origin", &["is missing", "work_plane"]);
}
