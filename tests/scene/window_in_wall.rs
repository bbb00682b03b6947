//! A `[[window]]` placed in its wall (`wall`, `at`, `size`): the wall gets the hole and the
//! opening is made in it. A daylit room so cut solves to the numbers of the same room
//! modelled by hand, four rectangles around the opening: to round-off when the hand made
//! rectangles are the pieces the cut makes (piers full height, sill and lintel between),
//! within the discretization when they are sliced the other way (sill and lintel full
//! width: 7.1e-6 at most at 0.25 m patches). Mistakes (a window larger than its wall, beyond it, overlapping another, in a
//! wall that is no rectangle or does not exist, both placements) are named by file,
//! table, key and line.

use super::{assert_error, parse, rejected};
use ugo::geometry::Shape;
use ugo::io::Solution;
use ugo::luminaire::LuminaireKind;
use ugo::progress::Silent;
use ugo::study::{Job, solve_case};

/// A 4 × 2.5 × 3 m room (x, y, z) under the overcast sky, its south wall (z = 0) given by
/// `south`, the window by `window`; probes on the floor, the ceiling and the north wall;
/// uniform patches of 0.25 m (named: the size rule would take the hierarchy at that size).
fn room(south: &str, window: &str) -> String {
    let rectangle = |name: &str, origin: &str, u: &str, v: &str, material: &str| {
        format!(
            "[[surface]]\nname = \"{name}\"\nshape = \"rectangle\"\nmaterial = \"{material}\"\norigin = {origin}\n\
             edge_u = {u}\nedge_v = {v}\n\n"
        )
    };
    let mut text = String::from(
        "[discretization]\npatch_size = 0.25\nkernel = \"uniform\"\n\n[[material]]\nname = \"wall\"\ntype = \"lambert\"\nreflectance = 0.6\n\n\
         [sky]\ntype = \"overcast\"\nhorizontal_illuminance = 10000\n\n",
    );
    text += &rectangle("floor", "[0, 0, 0]", "[0, 0, 3]", "[4, 0, 0]", "wall");
    text += &rectangle("ceiling", "[0, 2.5, 0]", "[4, 0, 0]", "[0, 0, 3]", "wall");
    text += &rectangle("north wall", "[0, 0, 3]", "[0, 2.5, 0]", "[4, 0, 0]", "wall");
    text += &rectangle("west wall", "[0, 0, 0]", "[0, 2.5, 0]", "[0, 0, 3]", "wall");
    text += &rectangle("east wall", "[4, 0, 0]", "[0, 0, 3]", "[0, 2.5, 0]", "wall");
    text += south;
    text += window;
    for (name, position, normal) in [
        ("floor", "[2, 0, 1.5]", "[0, 1, 0]"),
        ("floor at the back", "[3, 0, 2.6]", "[0, 1, 0]"),
        ("ceiling", "[2, 2.5, 1.5]", "[0, -1, 0]"),
        ("north wall", "[2, 1.2, 3]", "[0, 0, -1]"),
    ] {
        text += &format!("[[probe]]\nname = \"{name}\"\nposition = {position}\nnormal = {normal}\n\n");
    }
    text
}

/// The south wall in one table, the window cut into it (1 m from the west wall, sill 0.9 m).
fn cut() -> String {
    let south = "[[surface]]\nname = \"south wall\"\nshape = \"rectangle\"\nmaterial = \"wall\"\n\
                 origin = [0, 0, 0]\nedge_u = [4, 0, 0]\nedge_v = [0, 2.5, 0]\n\n";
    let window = "[[window]]\nname = \"window\"\nwall = \"south wall\"\nat = [1, 0.9]\nsize = [2, 1.2]\n\n";
    room(south, window)
}

/// The south wall as four rectangles `(origin, edge_u, edge_v)` and the window by its corners.
fn by_hand(pieces: [(&str, &str, &str); 4]) -> String {
    let mut south = String::new();
    for (i, (origin, u, v)) in pieces.into_iter().enumerate() {
        south += &format!(
            "[[surface]]\nname = \"south wall {i}\"\nshape = \"rectangle\"\nmaterial = \"wall\"\norigin = {origin}\n\
             edge_u = {u}\nedge_v = {v}\n\n"
        );
    }
    let window = "[[window]]\nname = \"window\"\norigin = [1, 0.9, 0]\nedge_u = [2, 0, 0]\nedge_v = [0, 1.2, 0]\n\n";
    room(&south, window)
}

/// Piers full height, sill and lintel between them: the pieces the cut makes.
const PIERS_FULL: [(&str, &str, &str); 4] = [
    ("[0, 0, 0]", "[1, 0, 0]", "[0, 2.5, 0]"),
    ("[1, 0, 0]", "[2, 0, 0]", "[0, 0.9, 0]"),
    ("[1, 2.1, 0]", "[2, 0, 0]", "[0, 0.4, 0]"),
    ("[3, 0, 0]", "[1, 0, 0]", "[0, 2.5, 0]"),
];

/// Sill and lintel full width, piers between them.
const SILL_FULL: [(&str, &str, &str); 4] = [
    ("[0, 0, 0]", "[4, 0, 0]", "[0, 0.9, 0]"),
    ("[0, 2.1, 0]", "[4, 0, 0]", "[0, 0.4, 0]"),
    ("[0, 0.9, 0]", "[1, 0, 0]", "[0, 1.2, 0]"),
    ("[3, 0.9, 0]", "[1, 0, 0]", "[0, 1.2, 0]"),
];

fn solved(text: String) -> Solution {
    let scene = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    solve_case(&scene, &Job::default(), &Silent).unwrap_or_else(|e| panic!("{e}"))
}

/// The largest relative difference of the probes' illuminance, and the readings.
fn largest_difference(a: &Solution, b: &Solution) -> f64 {
    a.probes
        .iter()
        .zip(&b.probes)
        .map(|(p, q)| {
            eprintln!("{}: {:.6} lx against {:.6} lx", p.name, p.illuminance, q.illuminance);
            (p.illuminance / q.illuminance - 1.0).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn the_window_is_cut_into_its_wall_and_opens_where_it_says() {
    let scene = parse(&cut()).unwrap_or_else(|e| panic!("{e}"));
    let wall = &scene.surfaces[scene.surface_index("south wall").unwrap()];
    let Shape::Holed { holes, .. } = &wall.shape else { panic!("{:?}", wall.shape) };
    let window = scene.luminaires.iter().find(|l| l.name == "window").unwrap();
    let LuminaireKind::Window { window: opening, .. } = &window.kind else { panic!("{window:?}") };
    assert_eq!(holes.len(), 1);
    for (p, q) in holes[0].iter().zip(opening.polygon.vertices()) {
        assert!(p.distance(*q) < 1e-15, "the hole {:?} is the opening {:?}", holes[0], opening.polygon);
    }
    assert!((opening.polygon.area() - 2.4).abs() < 1e-12);
}

#[test]
fn a_room_with_its_window_cut_solves_as_the_room_of_four_rectangles() {
    let (cut, same, other) = (solved(cut()), solved(by_hand(PIERS_FULL)), solved(by_hand(SILL_FULL)));
    let exact = largest_difference(&cut, &same);
    assert!(exact < 1e-9, "the same pieces: {exact:e}");
    let sliced = largest_difference(&cut, &other);
    eprintln!("the same pieces: {exact:.3e}; sliced the other way: {sliced:.3e}");
    assert!(sliced < 1e-4, "sliced the other way: {sliced}");
}

const SOUTH: &str = "[[surface]]\nname = \"south wall\"\nshape = \"rectangle\"\nmaterial = \"wall\"\n\
                     origin = [0, 0, 0]\nedge_u = [4, 0, 0]\nedge_v = [0, 2.5, 0]\n\n";

fn window(keys: &str) -> String {
    room(SOUTH, &format!("[[window]]\nname = \"window\"\n{keys}\n"))
}

const W: &str = "[[window]] \"window\" (#1)";

#[test]
fn a_window_larger_than_its_wall_or_beyond_it_is_named() {
    let e = rejected(&window("wall = \"south wall\"\nat = [0, 0.9]\nsize = [5, 1.2]"));
    assert_error(&e, W, "size", &["line ", "in the wall \"south wall\"", "larger than the surface", "4 m long"]);
    let e = rejected(&window("wall = \"south wall\"\nat = [3, 0.9]\nsize = [1.5, 1.2]"));
    assert_error(&e, W, "at", &["reaches beyond the surface", "4.5 m along edge_u"]);
}

#[test]
fn windows_overlapping_in_a_wall_or_its_hole_are_named() {
    let two = "[[window]]\nname = \"a\"\nwall = \"south wall\"\nat = [0.5, 0.9]\nsize = [1.5, 1.2]\n\n\
               [[window]]\nname = \"b\"\nwall = \"south wall\"\nat = [1.5, 1.5]\nsize = [1, 1]\n";
    let e = rejected(&room(SOUTH, two));
    assert_error(&e, "[[window]] \"b\" (#2)", "at", &["[[window]] \"b\" overlaps [[window]] \"a\"", "3.0000e-1 m²"]);
    let holed = SOUTH.replace("\n\n", "\nholes = [{ at = [2.5, 0], size = [1, 2.1] }]\n\n");
    let e = rejected(&room(&holed, "[[window]]\nname = \"w\"\nwall = \"south wall\"\nat = [2, 1]\nsize = [1, 1]\n"));
    assert_error(&e, "[[window]] \"w\" (#1)", "at", &["[[window]] \"w\" overlaps the wall's hole #1"]);
}

#[test]
fn a_window_needs_a_rectangle_wall_and_one_placement() {
    let e = rejected(&window("wall = \"south\"\nat = [1, 1]\nsize = [1, 1]"));
    assert_error(&e, W, "wall", &["no [[surface]] is named \"south\"", "\"south wall\""]);
    let e = rejected(&window("wall = \"south wall\"\nat = [1, 1]\nsize = [1, 1]\norigin = [0, 0, 0]"));
    assert_error(&e, W, "origin", &["give no `origin`"]);
    let e = rejected(&window("wall = \"south wall\"\nat = [1, 1]"));
    assert_error(&e, W, "size", &["needs `at`"]);
    let e = rejected(&window("at = [1, 1]\nsize = [1, 1]"));
    assert_error(&e, W, "at", &["give `wall` too"]);
    let e = rejected(&window("origin = [1, 1, 0]\nedge_u = [1, 0, 0]"));
    assert_error(&e, W, "edge_v", &["missing"]);
    let text = window("wall = \"box\"\nat = [1, 1]\nsize = [1, 1]").replace(
        "[[window]]",
        "[[surface]]\nname = \"box\"\nshape = \"box\"\nmaterial = \"wall\"\nmin = [1, 0, 1]\nmax = [2, 1, 2]\n\n[[window]]",
    );
    assert_error(&rejected(&text), W, "wall", &["is a box", "rectangle"]);
}

#[test]
fn the_case_file_is_named() {
    let e = rejected(&window("wall = \"south\"\nat = [1, 1]\nsize = [1, 1]"));
    assert!(e.to_string().starts_with("cases/test.toml: [[window]] \"window\" (#1), key `wall`: line "), "{e}");
}
