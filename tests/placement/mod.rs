//! Tests of the hard probes' placement (`ugo::placement`, issue 34): on a closed 1 m room
//! with a lamp under its ceiling, a block on the floor, a board held in the air and two
//! books on it 2 cm apart, every class gets probes where its name says.

mod leaves;

use glam::DVec3;
use std::path::Path;
use std::sync::OnceLock;
use ugo::geometry::Mesh;
use ugo::placement::{Class, OFFSET, Options, Placed, Placement, place};
use ugo::scene::Scene;
use ugo::visibility::{NO_FACE, Visibility};

/// The room, its lamp and its material; the solids are added from [`SOLIDS`].
const ROOM: &str = r#"
[scene]
name = "placement"

[discretization]
patch_size = 0.1

[[material]]
name = "white"
type = "lambert"
reflectance = 0.5

[[surface]]
name = "lamp"
shape = "rectangle"
material = "white"
origin = [0.4, 0.999, 0.4]
edge_u = [0.2, 0, 0]
edge_v = [0, 0, 0.2]
emission = { luminance = 1000.0 }
"#;

/// The boxes of the case: the room (seen from inside), then the solids standing in it: the
/// block, the board and the books.
const SOLIDS: [(DVec3, DVec3); 4] = [
    (DVec3::new(0.6, 0.0, 0.2), DVec3::new(0.8, 0.3, 0.4)),
    (DVec3::new(0.1, 0.4, 0.5), DVec3::new(0.5, 0.42, 0.9)),
    (DVec3::new(0.15, 0.42, 0.6), DVec3::new(0.2, 0.6, 0.8)),
    (DVec3::new(0.22, 0.42, 0.6), DVec3::new(0.27, 0.6, 0.8)),
];

/// A `[[surface]]` box table.
fn box_table(name: &str, (lo, hi): (DVec3, DVec3), inside: bool) -> String {
    format!(
        "\n[[surface]]\nname = \"{name}\"\nshape = \"box\"\nmaterial = \"white\"\nmin = [{}, {}, {}]\nmax = [{}, {}, {}]\ninside = {inside}\n",
        lo.x, lo.y, lo.z, hi.x, hi.y, hi.z
    )
}

const COUNT: usize = 8;

fn scene() -> Scene {
    let mut case = ROOM.to_string() + &box_table("room", (DVec3::ZERO, DVec3::ONE), true);
    for (k, &solid) in SOLIDS.iter().enumerate() {
        case += &box_table(&format!("solid {k}"), solid, false);
    }
    Scene::parse(Path::new("placement.toml"), case).expect("the test case is valid")
}

fn placed() -> &'static Placement {
    static PLACED: OnceLock<Placement> = OnceLock::new();
    PLACED.get_or_init(|| place(&scene(), &Options { count: COUNT, seed: 7, candidates: 40_000 }))
}

fn of(class: Class) -> Vec<&'static Placed> {
    let probes: Vec<_> = placed().probes.iter().filter(|p| p.class == class).collect();
    assert_eq!(probes.len(), COUNT, "{} probes of {}", probes.len(), class.name());
    probes
}

/// Distances from `p` to the room's six walls, smallest first.
fn to_walls(p: DVec3) -> Vec<f64> {
    let mut d = vec![p.x, 1.0 - p.x, p.y, 1.0 - p.y, p.z, 1.0 - p.z];
    d.sort_by(f64::total_cmp);
    d
}

/// Distance from `p` to a solid box.
fn to_solid((lo, hi): (DVec3, DVec3), p: DVec3) -> f64 {
    (lo - p).max(p - hi).max(DVec3::ZERO).length()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-5
}

#[test]
fn a_corner_probe_lies_its_distance_from_two_walls_and_off_the_third() {
    for class in ugo::placement::EDGES.map(Class::Corner) {
        let d = class.distance().expect("a corner has a distance");
        for p in of(class) {
            let w = to_walls(p.position);
            assert!(close(w[0], OFFSET) && close(w[1], d) && close(w[2], d), "{}: {w:?}", p.name());
            assert!(SOLIDS.iter().all(|&s| to_solid(s, p.position) > 0.0), "{} inside a solid", p.name());
        }
    }
}

#[test]
fn an_edge_probe_lies_its_distance_from_one_wall_and_three_times_farther_from_the_others() {
    for class in ugo::placement::EDGES.map(Class::Edge) {
        let d = class.distance().expect("an edge has a distance");
        for p in of(class) {
            let w = to_walls(p.position);
            assert!(close(w[0], OFFSET) && close(w[1], d) && w[2] > 3.0 * d, "{}: {w:?}", p.name());
        }
    }
}

#[test]
fn a_contact_probe_lies_its_distance_from_the_foot_of_a_solid() {
    for class in ugo::placement::CONTACTS.map(Class::Contact) {
        let d = class.distance().expect("a contact has a distance");
        for p in of(class) {
            let mut near: Vec<f64> = SOLIDS.iter().map(|&s| to_solid(s, p.position)).collect();
            near.extend(to_walls(p.position));
            near.sort_by(f64::total_cmp);
            assert!(close(near[0], OFFSET) && close(near[1], d), "{}: {near:?}", p.name());
            let by_solid =
                SOLIDS.iter().any(|&s| close(to_solid(s, p.position), OFFSET) || close(to_solid(s, p.position), d));
            assert!(by_solid, "{}: no solid at {d} m or on one", p.name());
        }
    }
}

#[test]
fn undersides_face_down_under_the_board_and_the_floor_under_it_faces_up() {
    let (lo, hi) = SOLIDS[1];
    let below = |p: DVec3| p.x > lo.x && p.x < hi.x && p.z > lo.z && p.z < hi.z;
    for p in of(Class::Underside) {
        assert!(close(p.position.y, lo.y - OFFSET) && p.normal.y < -0.99 && below(p.position), "{}", p.name());
    }
    for p in of(Class::Under) {
        assert!(close(p.position.y, OFFSET) && p.normal.y > 0.99 && below(p.position), "{}", p.name());
    }
}

#[test]
fn a_gap_probe_faces_the_next_book_2_cm_away() {
    for p in of(Class::Gap) {
        let x = p.position.x;
        assert!(
            close(x, 0.2 + OFFSET) && p.normal.x > 0.99 || close(x, 0.22 - OFFSET) && p.normal.x < -0.99,
            "{}",
            p.name()
        );
    }
}

/// The lamp's points seen from a probe, out of 400 on a grid.
fn lamp_points_seen(visibility: &Visibility, p: &Placed) -> usize {
    let grid =
        (0..400).map(|k| DVec3::new(0.4 + 0.01 * (k % 20) as f64 + 0.005, 0.999, 0.4 + 0.01 * (k / 20) as f64 + 0.005));
    grid.filter(|&q| (q - p.position).dot(p.normal) > 0.0 && visibility.visible(p.position, q, [NO_FACE, NO_FACE]))
        .count()
}

#[test]
fn an_umbra_probe_sees_no_point_of_the_lamp_and_a_penumbra_probe_some() {
    let scene = scene();
    let visibility = Visibility::build(&Mesh::build(&scene.surfaces, 0.1));
    for p in of(Class::Umbra) {
        assert_eq!(lamp_points_seen(&visibility, p), 0, "{}", p.name());
        assert!(p.position.y < 0.999, "{}: the lamp is in front", p.name());
    }
    for p in of(Class::Penumbra) {
        let seen = lamp_points_seen(&visibility, p);
        assert!(seen > 0 && seen < 400, "{}: {seen} of 400", p.name());
    }
}

#[test]
fn open_probes_stand_away_from_the_walls_with_nothing_in_front() {
    for p in of(Class::Open) {
        let w = to_walls(p.position);
        let ahead = (1..=50).map(|k| p.position + p.normal * (0.01 * k as f64));
        let blocked = ahead.flat_map(|q| SOLIDS.map(|s| to_solid(s, q))).any(|d| d == 0.0);
        let own = w[0] <= OFFSET + 1e-9;
        assert!(w[usize::from(own)] >= 0.3 - 1e-9 && !blocked, "{}: {w:?}", p.name());
    }
}

#[test]
fn the_dimmest_are_drawn_and_the_same_seed_gives_the_same_probes() {
    assert_eq!(of(Class::Dim).len(), COUNT);
    let again = place(&scene(), &Options { count: COUNT, seed: 7, candidates: 40_000 });
    assert_eq!(&again, placed());
    let other = place(&scene(), &Options { count: COUNT, seed: 8, candidates: 40_000 });
    assert_ne!(other.probes[0].position, placed().probes[0].position);
}

#[test]
fn every_probe_is_named_by_its_class_and_number() {
    let names: std::collections::BTreeSet<String> = placed().probes.iter().map(Placed::name).collect();
    assert_eq!(names.len(), placed().probes.len());
    assert!(names.contains("corner-5cm/007") && names.contains("contact-1cm/000"), "{names:?}");
}
