//! Visibility queries on the axis-aligned Cornell box (the layout that defeats compressed nodes).

mod hulls;
mod occluders;
mod packets;

use glam::DVec3;
use std::cell::Cell;
use std::path::Path;
use ugo::geometry::Mesh;
use ugo::scene::Scene;
use ugo::visibility::{NO_BLOCKER, NO_FACE, Visibility, VisibilityOptions};

fn cornell() -> Mesh {
    let scene = Scene::load(Path::new("cases/cornell-box.toml")).unwrap();
    Mesh::build(&scene.surfaces, 0.05)
}

#[test]
fn axis_aligned_rays_find_every_face_below_them() {
    // Regression: obvhs's CWBVH lost these hits on the unrotated room; the default must not.
    let mesh = cornell();
    let v = Visibility::build(&mesh);
    for p in &mesh.patches {
        let hit = v.closest_hit(p.centroid + 1e-3 * p.normal, -p.normal, NO_FACE).expect("a hit");
        assert_eq!(hit.face, p.face);
        assert!((hit.distance - 1e-3).abs() < 1e-6, "{}", hit.distance);
    }
}

#[test]
fn the_tall_block_hides_the_floor_behind_it_and_nothing_hides_the_open_room() {
    let mesh = cornell();
    let v = Visibility::build(&mesh);
    // From above the tall block's top, straight down to the floor under it: blocked.
    assert!(!v.visible(DVec3::new(0.37, 0.5, 0.35), DVec3::new(0.37, 0.0, 0.35), [NO_FACE, NO_FACE]));
    // Across the empty front of the room, wall to wall: clear, both ways.
    let (a, b) = (DVec3::new(0.001, 0.4, 0.05), DVec3::new(0.55, 0.4, 0.05));
    assert!(v.visible(a, b, [NO_FACE, NO_FACE]) && v.visible(b, a, [NO_FACE, NO_FACE]));
}

#[test]
fn a_ray_through_a_shared_edge_does_not_slip_between_triangles() {
    // The diagonal of every quad and the edges between patches are crossed exactly here
    // (inside the floor: its outer rim borders nothing).
    let mesh = cornell();
    let v = Visibility::build(&mesh);
    for p in mesh.patches.iter().filter(|p| p.normal.y > 0.99) {
        let interior = |c: &DVec3| c.x > 0.01 && c.x < 0.54 && c.z > 0.01 && c.z < 0.55;
        for &corner in p.polygon.vertices().iter().filter(|c| interior(c)) {
            let top = corner + DVec3::Y * 0.2;
            let hit = v.closest_hit(top, -DVec3::Y, NO_FACE);
            assert!(hit.is_some(), "lost the floor at {corner}");
        }
    }
}

#[test]
fn the_wide_and_binary_hierarchies_answer_every_query_alike() {
    // The default (compressed wide BVH, axis-aligned directions nudged) against the binary
    // tree, on segments between sample points of facing patches of the Cornell box (the
    // assembly's queries): many of them are exactly axis-aligned (opposed patches of
    // parallel walls).
    let mesh = cornell();
    let wide = Visibility::build(&mesh);
    let binary = Visibility::build_with(&mesh, VisibilityOptions { wide: false, ..VisibilityOptions::default() });
    let points: Vec<(DVec3, usize)> = (0..mesh.len())
        .step_by(7)
        .flat_map(|i| ugo::transfer::occlusion::sample_points(&mesh.patches[i]).map(|x| (x, i)))
        .collect();
    let (mut tested, mut aligned, mut different) = (0, 0, 0);
    for (i, &(a, pa)) in points.iter().enumerate() {
        for &(b, pb) in points.iter().skip(i + 1).step_by(5) {
            let (p, q) = (&mesh.patches[pa], &mesh.patches[pb]);
            if !ugo::geometry::facing(p, q) {
                continue;
            }
            let (fa, fb) = (p.face, q.face);
            let d = b - a;
            aligned += (d.x == 0.0 || d.y == 0.0 || d.z == 0.0) as usize;
            tested += 1;
            different += (wide.visible(a, b, [fa, fb]) != binary.visible(a, b, [fa, fb])) as usize;
        }
    }
    assert!(aligned > 100, "only {aligned} axis-aligned segments of {tested}");
    assert_eq!(different, 0, "{different} of {tested} segments answered differently");
}

#[test]
fn a_gathers_cached_blocker_changes_no_answer_in_the_cornell_box() {
    // A gather (`readout/gather.rs`) asks from one point for the sample points and corners
    // of every patch in turn, trying the triangle that blocked its last query first; from
    // points on the floor under and beside the blocks, in front of their feet and on their
    // sides, every answer must be the traversal's own. (In the office a few differ: the
    // cached triangle is tested without the traversal's culling of boxes within
    // `NEAREST_BOX` of the origin; docs/performance.md, "The gathers' last blocker".)
    let mesh = cornell();
    let v = Visibility::build(&mesh);
    let on = |i: usize| (mesh.patches[i].centroid + 1e-3 * mesh.patches[i].normal, mesh.patches[i].face);
    let (mut tested, mut blocked, mut different) = (0, 0, 0);
    for (p, face) in (0..mesh.len()).step_by(11).map(on) {
        let blocker = Cell::new(NO_BLOCKER);
        for s in &mesh.patches {
            let points = ugo::transfer::occlusion::sample_points(s);
            for y in points.iter().copied().chain(s.polygon.vertices().iter().map(|c| c.lerp(s.centroid, 1e-3))) {
                let plain = v.visible(p, y, [face, s.face]);
                different += (v.visible_shared(p, y, [face, s.face], &blocker) != plain) as usize;
                blocked += !plain as usize;
                tested += 1;
            }
        }
    }
    assert!(blocked > tested / 10, "only {blocked} of {tested} segments blocked");
    assert_eq!(different, 0, "{different} of {tested} segments answered differently with the cache");
}

#[test]
fn every_probe_of_the_cornell_box_finds_the_surface_it_lies_on() {
    // Regression: the floor probe missed the floor at every mesh and read, as a meter in
    // free space, the ceiling above it: the lookup's ray started 5.6e-5 m above the floor,
    // inside the 1e-4 m within which obvhs's wide traversal drops boxes (NEAREST_BOX).
    let scene = Scene::load(Path::new("cases/cornell-box.toml")).unwrap();
    let expected = ["floor", "back wall", "ceiling front"];
    for size in [0.1, 0.08, 0.05, 0.035, 0.03] {
        let mesh = Mesh::build(&scene.surfaces, size);
        let (v, faces) = (Visibility::build(&mesh), ugo::visibility::Faces::of(&mesh));
        for (probe, name) in scene.probes.iter().zip(expected) {
            let found = faces.under(&mesh, &v, probe.position, probe.normal);
            let surface = found.map(|i| scene.surfaces[mesh.patches[i].surface as usize].name.as_str());
            assert_eq!(surface, Some(name), "probe \"{}\" at {size} m", probe.name);
        }
    }
}

#[test]
fn a_ray_escapes_exactly_when_it_hits_nothing() {
    // The any-hit query that daylight uses (`escapes`) against the nearest-hit query, on the
    // open Cornell box (its front is open, so many rays leave): from every third patch's
    // centroid, 64 directions over its hemisphere, the patch's own face ignored.
    let mesh = cornell();
    let v = Visibility::build(&mesh);
    let (mut rays, mut escaped, mut different) = (0, 0, 0);
    for p in mesh.patches.iter().step_by(3) {
        let frame = p.frame();
        for k in 0..64 {
            let (cos, phi) = ((k as f64 + 0.5) / 64.0, k as f64 * 2.399_963_229_728_653);
            let sin = (1.0 - cos * cos).sqrt();
            let d = frame.world(DVec3::new(sin * phi.cos(), sin * phi.sin(), cos));
            let escapes = v.escapes(p.centroid, d, p.face);
            rays += 1;
            escaped += escapes as usize;
            different += (escapes != v.closest_hit(p.centroid, d, p.face).is_none()) as usize;
        }
    }
    assert!(escaped > rays / 10 && escaped < rays * 9 / 10, "{escaped} of {rays} escaped");
    assert_eq!(different, 0, "{different} of {rays} rays answered differently");
}

/// From each patch at `size` of `case` facing its first opening: how many patches face it,
/// how many shafts are found empty, how many patches have a blocked ray among 400 through a
/// grid over the opening, and how many of those had an empty shaft.
fn shafts(case: &str, size: f64) -> [usize; 4] {
    let scene = Scene::load(Path::new(case)).unwrap();
    let window = scene.luminaires.iter().find_map(|l| match &l.kind {
        ugo::luminaire::LuminaireKind::Window { window, .. } => Some(window.polygon),
        _ => None,
    });
    let window = window.expect("the case has an opening");
    let mesh = Mesh::build(&scene.surfaces, size);
    let v = Visibility::build(&mesh);
    let [a, b, _, d] = [0, 1, 2, 3].map(|i| window.vertices()[i]);
    let mut counts = [0; 4];
    for p in &mesh.patches {
        let x = p.centroid;
        if window.vertices().iter().all(|w| (*w - x).dot(p.normal) <= 0.0) {
            continue;
        }
        let clear = v.shaft_is_empty(x, p.normal, &window, p.face);
        let escaping = (0..400).all(|k| {
            let (s, t) = (((k % 20) as f64 + 0.5) / 20.0, ((k / 20) as f64 + 0.5) / 20.0);
            let y = a + s * (b - a) + t * (d - a);
            (y - x).dot(p.normal) <= 0.0 || v.escapes(x, y - x, p.face)
        });
        let found = [true, clear, !escaping, clear && !escaping];
        counts.iter_mut().zip(found).for_each(|(c, f)| *c += f as usize);
    }
    eprintln!(
        "{case}: {} patches face the opening, {} empty shafts, {} with a blocked ray",
        counts[0], counts[1], counts[2]
    );
    counts
}

#[test]
fn an_empty_shaft_lets_every_ray_through_the_opening_out() {
    // The classroom's window band (cut into its south wall), desks, whiteboard and the wall
    // around the opening in the way or not; and CIE 171's room under an overhang outside
    // its opening, which stops rays beyond the opening.
    let [facing, empty, blocked, wrong] = shafts("cases/classroom.toml", 0.25);
    assert_eq!(wrong, 0, "{wrong} empty shafts had a blocked ray");
    assert!(empty > facing / 4 && blocked > facing / 10, "the test must see both kinds");
    let [_, empty, blocked, wrong] = shafts("cases/cie171/5.13-overhang-1.0.toml", 0.5);
    assert_eq!(wrong, 0, "{wrong} empty shafts had a blocked ray under the overhang");
    assert!(empty > 0 && blocked > 0, "the test must see both kinds");
}
