//! The furnished rooms of `cases/`, written by `cases/generate/rooms.py` (issue 14, point 5):
//! they parse, hold about the number of quads (or OBJ triangles) intended, have probes,
//! grids and a camera, keep every luminaire inside the room, and are closed: every ray
//! from every luminaire meets the front of a face. The glTF dining room
//! (`cases/generate/gltf_room.py`, issue 38, point 4) reads its furniture's strips, fans and
//! texture, and is closed too.
//! The building floor of issue 36 (`cases/generate/building.py`): its rooms, their
//! luminaires, doors, windows and sky.

use glam::DVec3;
use std::path::Path;
use ugo::geometry::{Mesh, Shape};
use ugo::luminaire::LuminaireKind;
use ugo::scene::Scene;
use ugo::visibility::{Faces, NO_FACE, Visibility};

/// The seats of `cases/hall-obj.toml`: written by `make cases` (or `make test`), not committed.
const HALL_OBJ: &str = "cases/hall-obj/seats.obj";

fn load(case: &str) -> Scene {
    Scene::load(Path::new(case)).unwrap_or_else(|e| panic!("{e}"))
}

/// Quads of the case file: a rectangle or polygon is one, a box six.
fn quads(scene: &Scene) -> usize {
    let quads = |shape: &Shape| match shape {
        Shape::Box { .. } => 6,
        Shape::Mesh { .. } => 0,
        _ => 1,
    };
    scene.surfaces.iter().map(|s| quads(&s.shape)).sum()
}

fn triangles(scene: &Scene) -> usize {
    let triangles = |shape: &Shape| match shape {
        Shape::Mesh { triangles, .. } => triangles.len(),
        _ => 0,
    };
    scene.surfaces.iter().map(|s| triangles(&s.shape)).sum()
}

fn luminaires(scene: &Scene) -> Vec<DVec3> {
    let position = |kind: &LuminaireKind| match kind {
        LuminaireKind::Point(p) => p.position,
        LuminaireKind::Parallel { .. } | LuminaireKind::Window { .. } => panic!("a room lit by daylight"),
    };
    scene.luminaires.iter().map(|l| position(&l.kind)).collect()
}

/// The bounding box of the meshed scene.
fn bounds(mesh: &Mesh) -> (DVec3, DVec3) {
    let corners = mesh.patches.iter().flat_map(|p| p.polygon.vertices().iter().copied());
    corners.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// Directions spread evenly over the sphere (a Fibonacci lattice).
fn sphere_directions(n: usize) -> impl Iterator<Item = DVec3> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n).map(move |i| {
        let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
        let r = (1.0 - y * y).sqrt();
        let phi = golden * i as f64;
        DVec3::new(r * phi.cos(), y, r * phi.sin())
    })
}

/// Parses `case` and checks what every furnished room must have; returns the scene.
fn furnished(case: &str, quads_in: std::ops::Range<usize>, luminaire_count: usize) -> Scene {
    let scene = load(case);
    let n = quads(&scene);
    assert!(quads_in.contains(&n), "{case}: {n} quads, intended {quads_in:?}");
    assert_eq!(scene.luminaires.len(), luminaire_count, "{case}");
    assert!(scene.probes.len() >= 10, "{case}: {} probes", scene.probes.len());
    assert!(!scene.grids.is_empty() && !scene.cameras.is_empty(), "{case}: no grid or camera");
    assert!(scene.surfaces.iter().all(|s| s.emission.is_none()), "{case}: lit by luminaires only");
    scene
}

/// Every luminaire lies inside the room's bounding box, and every ray from it meets the
/// front of a face (none escapes, none hits the back of a one-sided face).
fn closed_around_luminaires(scene: &Scene) {
    let mesh = Mesh::build(&scene.surfaces, 4.0);
    let (lo, hi) = bounds(&mesh);
    let visibility = Visibility::build(&mesh);
    let faces = Faces::of(&mesh);
    for (luminaire, at) in scene.luminaires.iter().zip(luminaires(scene)) {
        let name = &luminaire.name;
        assert!(at.cmpgt(lo).all() && at.cmplt(hi).all(), "{name} at {at} outside the room {lo} … {hi}");
        for direction in sphere_directions(500) {
            let landing = faces.landing(&mesh, &visibility, at, direction, NO_FACE);
            let Some(hit) = landing else { panic!("{name}: the ray towards {direction} escapes") };
            assert!(hit.facing.is_some(), "{name}: the ray towards {direction} meets the back of a face");
        }
    }
}

#[test]
fn the_office_is_furnished_closed_and_lit_from_inside() {
    let scene = furnished("cases/office.toml", 900..1200, 12);
    assert_eq!(scene.discretization.patch_size, 0.15);
    let hierarchical = ugo::scene::Hierarchical {
        root_size: 1.0,
        link_tolerance: 1e-2,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    };
    assert_eq!(scene.discretization.kernel, ugo::scene::KernelKind::Hierarchical(hierarchical));
    let books = scene.surfaces.iter().filter(|s| s.name.starts_with("bookshelf, book")).count();
    assert!(books >= 24, "{books} books");
    let turned =
        scene.surfaces.iter().filter(|s| matches!(s.shape, Shape::Box { rotate_y_deg, .. } if rotate_y_deg != 0.0));
    assert!(turned.count() >= 20, "some furniture is turned");
    assert!(scene.grids.iter().any(|g| g.name == "work plane"));
    let groups: Vec<(&str, usize)> =
        scene.lighting.groups.iter().map(|g| (g.name.as_str(), g.luminaires.len())).collect();
    assert_eq!(groups, [("meeting", 6), ("desks", 6)], "two groups of downlights for its light scenes");
    let scenes: Vec<&str> = scene.lighting.scenes.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(scenes, ["meeting", "evening"]);
    closed_around_luminaires(&scene);
}

#[test]
fn the_lecture_hall_is_furnished_closed_and_lit_from_inside() {
    let scene = furnished("cases/lecture-hall.toml", 2700..3300, 32);
    let seats = scene.surfaces.iter().filter(|s| s.name.ends_with(", pan")).count();
    assert_eq!(seats, 140);
    closed_around_luminaires(&scene);
}

#[test]
fn the_seat_room_is_two_of_the_halls_tiers_closed_and_lit_from_inside() {
    let scene = load("cases/seat-room.toml");
    assert_eq!(quads(&scene), 194);
    assert_eq!(scene.luminaires.len(), 4);
    let seats = scene.surfaces.iter().filter(|s| s.name.ends_with(", pan")).count();
    assert_eq!(seats, 8, "two rows of four seats");
    let hall = load("cases/lecture-hall.toml");
    let pan = |scene: &Scene| -> Shape {
        scene.surfaces.iter().find(|s| s.name.ends_with("seat 1, pan")).expect("a pan").shape.clone()
    };
    let size = |shape: Shape| match shape {
        Shape::Box { min, max, .. } => max - min,
        other => panic!("a pan is a box, not {other:?}"),
    };
    assert!(size(pan(&scene)).abs_diff_eq(size(pan(&hall)), 1e-9), "the hall's seats");
    closed_around_luminaires(&scene);
}

#[test]
fn the_hall_of_meshed_seats_has_two_hundred_thousand_triangles() {
    if !Path::new(HALL_OBJ).exists() {
        eprintln!("skipped: {HALL_OBJ} has not been generated (`make cases` or `python3 cases/generate/rooms.py`)");
        return;
    }
    let scene = furnished("cases/hall-obj.toml", 1000..1600, 32);
    let n = triangles(&scene);
    assert!((100_000..1_000_000).contains(&n), "{n} triangles");
    let hall = load("cases/lecture-hall.toml");
    let (lo, hi) = bounds(&Mesh::build(&hall.surfaces, 4.0));
    for surface in &scene.surfaces {
        if let Shape::Mesh { triangles, .. } = &surface.shape {
            let inside = |p: &DVec3| p.cmpgt(lo).all() && p.cmplt(hi).all();
            assert!(triangles.iter().flatten().all(inside), "{}: a triangle outside the hall", surface.name);
        }
    }
    assert!(luminaires(&scene).iter().all(|p| p.cmpgt(lo).all() && p.cmplt(hi).all()));
}

#[test]
fn the_gltf_room_reads_its_strips_fans_and_texture_and_is_closed() {
    let scene = load("cases/gltf-room.toml");
    assert_eq!(triangles(&scene), 544, "lists, strips and fans, the chair placed by four nodes");
    let names: Vec<&str> = scene.surfaces[6..].iter().map(|s| s.name.as_str()).collect();
    let oak = "furniture/gltf-room/furniture.gltf:oak";
    assert_eq!(names, [oak, "furniture/metal", "furniture/gltf-room/furniture.gltf:fabric"]);
    let reflectance = |surface: usize| match scene.materials[scene.surfaces[surface].material].model {
        ugo::material::MaterialModel::Lambert { reflectance, .. } => reflectance,
        ref other => panic!("{other:?}"),
    };
    // wood.png's mean linear colour's luminance, as the generator works it out (rho = 0.1768).
    assert!((reflectance(6) - 0.1768).abs() < 5e-5, "{}", reflectance(6));
    assert_eq!(reflectance(7), 0.35, "steel mapped to metal");
    let warnings: Vec<String> = scene.warnings().iter().map(|w| w.to_string()).collect();
    assert!(warnings.iter().any(|w| w.contains("\"oak\"") && w.contains("averaged")), "{warnings:#?}");
    assert_eq!(scene.luminaires.len(), 2);
    assert!(scene.probes.len() >= 9 && !scene.cameras.is_empty());
    let (lo, hi) = (DVec3::new(0.0, -1e-9, 0.0), DVec3::new(5.0, 2.8, 4.0));
    for surface in &scene.surfaces[6..] {
        let Shape::Mesh { triangles, .. } = &surface.shape else { panic!("{}", surface.name) };
        let inside = |p: &DVec3| p.cmpgt(lo).all() && p.cmplt(hi).all();
        assert!(triangles.iter().flatten().all(inside), "{}: a triangle outside the room", surface.name);
    }
    closed_around_luminaires(&scene);
}

/// The building floor (issue 36, point 4, `cases/generate/building.py`): 28 rooms (26
/// offices, a meeting room, a stair core) and a corridor, each lit by downlights of its own
/// group, a door from every room into the corridor (two into the meeting room), a glazed
/// window in every room but the stair core and at both ends of the corridor, the sky.
#[test]
fn the_building_has_twenty_eight_rooms_lit_by_their_own_groups_doors_windows_and_sky() {
    let scene = load("cases/building.toml");
    assert_eq!(scene.discretization.patch_size, 0.15);
    let hierarchical = ugo::scene::Hierarchical {
        root_size: 1.0,
        link_tolerance: 1e-2,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    };
    assert_eq!(scene.discretization.kernel, ugo::scene::KernelKind::Hierarchical(hierarchical));
    let points = scene.luminaires.iter().filter(|l| matches!(l.kind, LuminaireKind::Point(_))).count();
    let windows = scene.luminaires.iter().filter(|l| matches!(l.kind, LuminaireKind::Window { .. })).count();
    assert_eq!((points, windows), (109, 29), "downlights and windows");
    assert!(scene.sky.is_some(), "daylight through the facade needs the sky");
    let rooms: Vec<&ugo::scene::LightGroup> =
        scene.lighting.groups.iter().filter(|g| g.name.len() == 3 && g.name != "S07" && g.name != "N08").collect();
    assert_eq!(rooms.len(), 26, "a group per office");
    assert!(rooms.iter().all(|g| g.luminaires.len() >= 3), "three downlights or more per office");
    for group in ["S07", "N08", "corridor"] {
        assert!(scene.lighting.groups.iter().any(|g| g.name == group), "no group {group}");
    }
    let doors: usize = scene
        .surfaces
        .iter()
        .filter(|s| s.name.contains("corridor wall"))
        .map(|s| match &s.shape {
            Shape::Holed { holes, .. } => holes.len(),
            _ => 0,
        })
        .sum();
    assert_eq!(doors, 29, "a door per room, two into the meeting room");
    assert!(scene.surfaces.iter().filter(|s| s.two_sided).count() >= 50, "partitions and corridor walls");
    let desks = scene.surfaces.iter().filter(|s| s.name.contains("desk") && s.name.contains(", top")).count();
    assert_eq!(desks, 28, "a desk per one-person office, two per two-person office");
    assert!(scene.probes.len() >= 3 && scene.grids.len() == 1);
    assert!(std::fs::metadata("cases/building.toml").unwrap().len() < 300_000, "the file is small: furniture copied");
}
