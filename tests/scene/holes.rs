//! `holes` of a rectangle or polygon `[[surface]]`: read into a `Shape::Holed` whose mesh
//! has the area of the surface less its holes, and every mistake (a hole outside the
//! surface, two overlapping, a polygon's hole off its plane, `at` on a polygon, a hole
//! covering everything) named by file, table, key and line.

use super::{BASE, CASE, LAMP, assert_error, parse, rejected};
use glam::DVec3;
use ugo::geometry::{Shape, tessellate};

/// A 4 × 3 m wall (edge_u along x, edge_v up) with the given `holes = …` line.
fn wall(holes: &str) -> String {
    format!(
        "{BASE}{LAMP}\n[[surface]]\nname = \"wall\"\nshape = \"rectangle\"\nmaterial = \"white\"\norigin = [0, 0, 2]\n\
         edge_u = [4, 0, 0]\nedge_v = [0, 3, 0]\nholes = {holes}\n"
    )
}

/// A right-angled triangle in the plane y = 0 with the given `holes = …` line.
fn polygon(holes: &str) -> String {
    format!(
        "{BASE}{LAMP}\n[[surface]]\nname = \"roof\"\nshape = \"polygon\"\nmaterial = \"white\"\n\
         vertices = [[0, 0, 0], [0, 0, 4], [4, 0, 0]]\nholes = {holes}\n"
    )
}

const WALL: &str = "[[surface]] \"wall\" (#2)";
const ROOF: &str = "[[surface]] \"roof\" (#2)";

fn area(shape: &Shape) -> f64 {
    tessellate(shape, 0.1).iter().map(|e| e.area()).sum()
}

#[test]
fn a_wall_with_a_window_and_a_door_and_a_roof_with_a_skylight_are_read() {
    let text = wall("[{ at = [0.5, 0.9], size = [1.5, 1.2] }, { at = [2.5, 0], size = [0.9, 2.1] }]");
    let scene = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let shape = &scene.surfaces[1].shape;
    let Shape::Holed { outline, holes } = shape else { panic!("{shape:?}") };
    assert_eq!(outline.len(), 4);
    let window = [[0.5, 0.9, 2.0], [2.0, 0.9, 2.0], [2.0, 2.1, 2.0], [0.5, 2.1, 2.0]].map(DVec3::from_array);
    assert!(holes[0].iter().zip(window).all(|(p, q)| p.distance(q) < 1e-15), "{holes:?}");
    assert!((area(shape) - (12.0 - 1.8 - 1.89)).abs() < 1e-12, "{}", area(shape));
    let skylight = "[{ vertices = [[0.5, 0, 0.5], [1.5, 0, 0.5], [0.5, 0, 1.5]] }]";
    let scene = parse(&polygon(skylight)).unwrap_or_else(|e| panic!("{e}"));
    assert!((area(&scene.surfaces[1].shape) - (8.0 - 0.5)).abs() < 1e-12);
}

#[test]
fn a_hole_outside_the_surface_is_named_with_its_line() {
    let e = rejected(&wall("[{ at = [3.5, 1], size = [1, 1] }]"));
    assert_error(
        &e,
        WALL,
        "holes[1].at",
        &["line 26:", "reaches beyond the surface", "4.5 m along edge_u", "4 m long"],
    );
    assert_eq!(e.file(), std::path::Path::new(CASE));
    let e = rejected(&wall("[{ at = [1, 1], size = [1, 5] }]"));
    assert_error(&e, WALL, "holes[1].size", &["larger than the surface", "5 m along edge_v", "3 m long"]);
    let e = rejected(&wall("[{ at = [-0.5, 1], size = [1, 1] }]"));
    assert_error(&e, WALL, "holes[1].at", &["at least 0 m along edge_u"]);
    let e = rejected(&wall("[{ vertices = [[3, 1, 2], [5, 1, 2], [3, 2, 2]] }]"));
    assert_error(&e, WALL, "holes[1]", &["hole #1 reaches outside the surface", "2.5000e-1 m²"]);
}

#[test]
fn overlapping_holes_are_named() {
    let e = rejected(&wall("[{ at = [0.5, 0.5], size = [1, 1] }, { at = [1, 1], size = [1, 1] }]"));
    assert_error(&e, WALL, "holes[2]", &["hole #2 overlaps hole #1", "2.5000e-1 m²"]);
    // touching holes share no area: a window on a door
    parse(&wall("[{ at = [0.5, 0], size = [1, 2] }, { at = [1.5, 1], size = [1, 1] }]"))
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn holes_that_leave_nothing_are_refused() {
    let e = rejected(&wall("[{ at = [0, 0], size = [4, 3] }]"));
    assert_error(&e, WALL, "holes[1]", &["leave nothing of the surface"]);
}

#[test]
fn a_polygon_hole_must_lie_in_the_plane_and_a_polygon_takes_no_rectangle_hole() {
    let e = rejected(&polygon("[{ vertices = [[0.5, 0, 0.5], [1.5, 0.1, 0.5], [0.5, 0, 1.5]] }]"));
    assert_error(&e, ROOF, "holes[1].vertices", &["vertex #2", "off the surface's plane"]);
    let e = rejected(&polygon("[{ at = [0.5, 0.5], size = [1, 1] }]"));
    assert_error(&e, ROOF, "holes[1].vertices", &["a polygon's holes are polygons"]);
    let e = rejected(&polygon("[{ vertices = [[0.5, 0, 0.5], [1.5, 0, 0.5]] }]"));
    assert_error(&e, ROOF, "holes[1].vertices", &["at least 3 vertices"]);
    let e = rejected(&wall("[{ at = [0.5, 0.5] }]"));
    assert_error(&e, WALL, "holes[1].size", &["give `at` and `size`"]);
    let e = rejected(&wall("[{ at = [0.5, 0.5], size = [1, 1], vertices = [[0, 0, 2], [1, 0, 2], [0, 1, 2]] }]"));
    assert_error(&e, WALL, "holes[1].vertices", &["not both"]);
    let e = rejected(&wall("[{ at = [0.5, 0.5], sise = [1, 1] }]"));
    assert!(e.to_string().contains("unknown field `sise`"), "{e}");
}

#[test]
fn holes_belong_to_rectangles_and_polygons_only() {
    let text = format!(
        "{BASE}{LAMP}\n[[surface]]\nname = \"d\"\nshape = \"disc\"\nmaterial = \"white\"\ncenter = [0, 0, 0]\n\
         normal = [0, 1, 0]\nradius = 1\nholes = [{{ at = [0, 0], size = [1, 1] }}]\n"
    );
    assert_error(&rejected(&text), "[[surface]] \"d\" (#2)", "holes", &["not a key of shape \"disc\""]);
}
