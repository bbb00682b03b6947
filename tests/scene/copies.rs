//! Copies of a `[[surface]]` (`array`, `transforms`; issue 38 point 4): 24 desks of an OBJ
//! file placed by one array are the 24 desks written out, one table each (the same
//! triangles to round-off, the same solve), and 24 box desks likewise; a turn by
//! `transforms` is the turn worked out by hand (a box about the vertical through its
//! centre, a rectangle about a horizontal axis through a pivot, a mesh like its own
//! `rotate_deg`); every mistake is named by file, table, key and line.

use super::{BASE, LAMP, assert_error, parse, rejected};
use crate::support::scratch;
use glam::DVec3;
use ugo::geometry::Shape;
use ugo::progress::Silent;
use ugo::scene::Scene;
use ugo::study::{Job, solve_case};

/// A desk top, 1.2 × 0.03 × 0.6 m, as an OBJ box of 12 triangles, its corner at the origin.
const DESK: &str = "v 0 0 0\nv 0.6 0 0\nv 0.6 0 1.2\nv 0 0 1.2\nv 0 0.03 0\nv 0.6 0.03 0\nv 0.6 0.03 1.2\nv 0 0.03 1.2\n\
f 1 2 3\nf 1 3 4\nf 5 8 7\nf 5 7 6\nf 1 5 6\nf 1 6 2\nf 2 6 7\nf 2 7 3\nf 3 7 8\nf 3 8 4\nf 4 8 5\nf 4 5 1\n";

/// A 9 × 3.2 × 7 m room under a bulb with `desks`, and probes on three desks and the floor.
fn classroom(desks: &str) -> String {
    let mut text = String::from(
        "[discretization]\npatch_size = 0.5\nkernel = \"uniform\"\n\n[[material]]\nname = \"white\"\ntype = \"lambert\"\n\
         reflectance = 0.6\n\n[[material]]\nname = \"desk\"\ntype = \"lambert\"\nreflectance = 0.45\n\n\
         [[luminaire]]\nname = \"bulb\"\ntype = \"isotropic\"\nflux = 20000\nposition = [4.5, 3, 3.5]\n\n\
         [[surface]]\nname = \"room\"\nshape = \"box\"\nmaterial = \"white\"\ninside = true\nmin = [0, 0, 0]\n\
         max = [9, 3.2, 7]\n\n",
    );
    text += desks;
    for (name, position) in [
        ("desk 1-1", "[2.3, 0.75, 1.1]"),
        ("desk 4-3", "[5.6, 0.75, 4.1]"),
        ("desk 6-4", "[7.8, 0.75, 5.6]"),
        ("floor", "[4.5, 0, 3.2]"),
    ] {
        text += &format!("[[probe]]\nname = \"{name}\"\nposition = {position}\nnormal = [0, 1, 0]\n\n");
    }
    text
}

/// The desk of column `i`, row `j` (from 0): 1.1 m apart along x, 1.5 m along z.
fn corner(i: usize, j: usize) -> [f64; 3] {
    [2.0 + 1.1 * i as f64, 0.72, 0.5 + 1.5 * j as f64]
}

/// A number as one writes it by hand (to the centimetre), not as the array adds it up.
fn written(x: f64) -> String {
    format!("{:.2}", x)
}

fn mesh_desk(name: &str, translate: [f64; 3], extra: &str) -> String {
    let [x, y, z] = translate.map(written);
    format!(
        "[[surface]]\nname = \"{name}\"\nshape = \"mesh\"\nmaterial = \"desk\"\nfile = \"desk.obj\"\n\
         translate = [{x}, {y}, {z}]\n{extra}\n"
    )
}

fn box_desk(name: &str, [x, y, z]: [f64; 3], extra: &str) -> String {
    let (min, max) = ([x, y, z].map(written), [x + 0.6, y + 0.03, z + 1.2].map(written));
    format!(
        "[[surface]]\nname = \"{name}\"\nshape = \"box\"\nmaterial = \"desk\"\nmin = [{}, {}, {}]\nmax = [{}, {}, {}]\n\
         {extra}\n",
        min[0], min[1], min[2], max[0], max[1], max[2]
    )
}

const ARRAY: &str = "array = { count = [6, 4], step = [[1.1, 0, 0], [0, 0, 1.5]] }";

/// Loads `text` as `case.toml` beside `desk.obj`.
fn load(text: &str) -> Scene {
    let dir = scratch("copies");
    dir.write("desk.obj", DESK);
    Scene::load(&dir.write("case.toml", text)).unwrap_or_else(|e| panic!("{e}"))
}

/// Every written-out desk `desk i-j` and the array's `desk-i-j` have the same shape to 1e-12 m.
fn same_desks(arrayed: &Scene, by_hand: &Scene) {
    let mut compared = 0;
    for s in &arrayed.surfaces {
        let Some(rest) = s.name.strip_prefix("desk-") else { continue };
        let twin = &by_hand.surfaces[by_hand.surface_index(&format!("desk {rest}")).unwrap()];
        let points = |shape: &Shape| match shape {
            Shape::Mesh { triangles, .. } => triangles.iter().flatten().copied().collect::<Vec<DVec3>>(),
            Shape::Box { min, max, .. } => vec![*min, *max],
            other => panic!("{other:?}"),
        };
        let (a, b) = (points(&s.shape), points(&twin.shape));
        assert_eq!(a.len(), b.len());
        assert!(a.iter().zip(&b).all(|(p, q)| p.distance(*q) < 1e-12), "{}: {a:?} against {b:?}", s.name);
        assert_eq!((s.material, s.two_sided, s.inside), (twin.material, twin.two_sided, twin.inside));
        compared += 1;
    }
    assert_eq!(compared, 24);
    assert_eq!(arrayed.surfaces.len(), by_hand.surfaces.len());
}

/// The classroom with 24 desks made by `desk` placed by one array, and written out one table
/// each; checked to be the same desks.
fn arrayed_and_written_out(desk: fn(&str, [f64; 3], &str) -> String) -> (Scene, Scene) {
    let arrayed = load(&classroom(&desk("desk", corner(0, 0), ARRAY)));
    let mut desks = String::new();
    for i in 0..6 {
        for j in 0..4 {
            desks += &desk(&format!("desk {}-{}", i + 1, j + 1), corner(i, j), "");
        }
    }
    let by_hand = load(&classroom(&desks));
    same_desks(&arrayed, &by_hand);
    (arrayed, by_hand)
}

#[test]
fn twenty_four_obj_desks_by_an_array_are_the_desks_written_out_and_solve_alike() {
    let (arrayed, by_hand) = arrayed_and_written_out(mesh_desk);
    assert_eq!(arrayed.files.len(), 1, "one OBJ file");
    let (a, b) = (
        solve_case(&arrayed, &Job::default(), &Silent).unwrap(),
        solve_case(&by_hand, &Job::default(), &Silent).unwrap(),
    );
    for (p, q) in a.probes.iter().zip(&b.probes) {
        eprintln!("{}: {:.6} lx arrayed, {:.6} lx written out", p.name, p.illuminance, q.illuminance);
        assert!(
            (p.illuminance / q.illuminance - 1.0).abs() < 1e-9,
            "{}: {} against {}",
            p.name,
            p.illuminance,
            q.illuminance
        );
    }
}

#[test]
fn twenty_four_box_desks_by_an_array_are_the_desks_written_out() {
    let (arrayed, _) = arrayed_and_written_out(box_desk);
    let names: Vec<&str> = arrayed.surfaces.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(&names[1..4], ["desk-1-1", "desk-1-2", "desk-1-3"]);
    assert_eq!(names[24], "desk-6-4");
}

#[test]
fn a_turned_box_rectangle_and_mesh_are_the_turns_worked_out_by_hand() {
    let turned = box_desk(
        "desk",
        [1.0, 0.0, 1.0],
        "transforms = [{ rotate_deg = 90 }, { translate = [0, 0, 2], rotate_deg = -30 }]",
    );
    let scene = parse(&format!("{BASE}{LAMP}{}", turned.replace("\"desk\"\nmin", "\"white\"\nmin")))
        .unwrap_or_else(|e| panic!("{e}"));
    let centre = DVec3::new(1.3, 0.015, 1.6);
    let half = DVec3::new(0.3, 0.015, 0.6);
    let boxes: Vec<&Shape> = scene.surfaces[1..].iter().map(|s| &s.shape).collect();
    for (shape, (moved, angle)) in boxes.iter().zip([(centre, 90.0), (centre + DVec3::new(0.0, 0.0, 2.0), -30.0)]) {
        let Shape::Box { min, max, rotate_y_deg } = shape else { panic!("{shape:?}") };
        assert!((*min - (moved - half)).length() < 1e-12 && (*max - (moved + half)).length() < 1e-12, "{shape:?}");
        assert_eq!(*rotate_y_deg, angle);
    }
    assert_eq!(scene.surfaces[1].name, "desk-1");
    // a rectangle turned 90° about x through the pivot [0, 1, 0], then moved 1 m along z
    let rectangle = "[[surface]]\nname = \"r\"\nshape = \"rectangle\"\nmaterial = \"white\"\norigin = [0, 1, 0]\n\
                     edge_u = [1, 0, 0]\nedge_v = [0, 0, 2]\n\
                     transforms = [{ rotate_axis = [1, 0, 0], rotate_deg = 90, pivot = [0, 1, 0], translate = [0, 0, 1] }]\n";
    let scene = parse(&format!("{BASE}{LAMP}{rectangle}")).unwrap_or_else(|e| panic!("{e}"));
    let Shape::Rectangle { origin, edge_u, edge_v } = &scene.surfaces[1].shape else { panic!() };
    assert!((*origin - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15, "{origin}");
    assert!(
        (*edge_u - DVec3::X).length() < 1e-15 && (*edge_v - DVec3::new(0.0, -2.0, 0.0)).length() < 1e-15,
        "{edge_v}"
    );
    // a mesh turned by `transforms` about the origin is the mesh turned by its own keys
    let by_copy = load(&classroom(&mesh_desk(
        "desk",
        [0.0; 3],
        "transforms = [{ rotate_deg = 30, pivot = [0, 0, 0], translate = [3, 0, 2] }]",
    )));
    let by_keys = load(&classroom(&mesh_desk("desk", [3.0, 0.0, 2.0], "rotate_deg = 30")));
    let points = |s: &Scene| match &s.surfaces[1].shape {
        Shape::Mesh { triangles, .. } => triangles.clone(),
        other => panic!("{other:?}"),
    };
    let (a, b) = (points(&by_copy), points(&by_keys));
    assert!(a.iter().flatten().zip(b.iter().flatten()).all(|(p, q)| p.distance(*q) < 1e-14));
}

const S: &str = "[[surface]] \"desk\" (#2)";

fn desk(extra: &str) -> String {
    format!("{BASE}{LAMP}{}", box_desk("desk", [1.0, 0.0, 1.0], extra).replace("\"desk\"\nmin", "\"white\"\nmin"))
}

#[test]
fn copy_mistakes_are_named_by_table_key_and_line() {
    let e = rejected(&desk("array = { count = [6, 0], step = [[1, 0, 0], [0, 0, 1]] }"));
    assert_error(&e, S, "array.count", &["line ", "from 1 to 10000, got 0"]);
    let e = rejected(&desk("array = { count = [6, 4], step = [[1, 0, 0]] }"));
    assert_error(&e, S, "array.step", &["one step", "2 counts, 1 steps"]);
    let e = rejected(&desk("array = { count = [3], step = [[0, 0, 0]] }"));
    assert_error(&e, S, "array.step", &["coincide"]);
    let e = rejected(&desk("array = { count = [200, 200], step = [[1, 0, 0], [0, 0, 1]] }"));
    assert_error(&e, S, "array.count", &["40000 copies", "at most 10000"]);
    let e = rejected(&desk("array = { count = [2], step = [[1, 0, 0]] }\ntransforms = [{ translate = [1, 0, 0] }]"));
    assert_error(&e, S, "transforms", &["not both"]);
    let e = rejected(&desk("transforms = []"));
    assert_error(&e, S, "transforms", &["1 to 10000 transforms, got 0"]);
    let e = rejected(&desk("transforms = [{ translate = [1, 0, 0] }, { rotate_axis = [1, 0, 0], rotate_deg = 10 }]"));
    assert_error(&e, S, "transforms[2].rotate_axis", &["a box turns only about the vertical axis"]);
    let e = rejected(&desk("transforms = [{ rotate_axis = [0, 0, 0], rotate_deg = 10 }]"));
    assert_error(&e, S, "transforms[1].rotate_axis", &["non-zero"]);
    let e = rejected(&desk("transforms = [{ rotate_deg = nan }]"));
    assert_error(&e, S, "transforms[1].rotate_deg", &["finite"]);
    let e = rejected(&desk("transforms = [{ turn = 10 }]"));
    assert!(e.to_string().contains("unknown field `turn`"), "{e}");
    let clash = desk("array = { count = [2], step = [[1, 0, 0]] }").replace("name = \"lamp\"", "name = \"desk-2\"");
    assert_error(
        &rejected(&clash),
        S,
        "name",
        &["the copy \"desk-2\" has the name of another surface ([[surface]] #1)"],
    );
}
