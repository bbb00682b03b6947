//! Segments traced together (`Visibility::visible_together`, `visibility/packet.rs`) answer
//! exactly as the same segments traced one after another with the last blocker cached
//! (`Visibility::visible_cached`), and leave the same blocker: on the segments of links
//! between patches of the Cornell box and the furnished office (4 between matching points,
//! then the other 12), on random segments across the rooms (of every direction octant) and on
//! segments grazing the faces, from 10 µm to 1 mm above them. A link's visible fraction is
//! then the same to the bit.

use glam::DVec3;
use std::path::Path;
use ugo::geometry::{Mesh, facing};
use ugo::random::Rng;
use ugo::scene::Scene;
use ugo::transfer::occlusion::{POINTS, fraction_between, sample_points};
use ugo::visibility::{Blocker, NO_BLOCKER, NO_FACE, PACKET, Segment, Visibility, VisibilityOptions};

fn mesh(case: &str, size: f64) -> Mesh {
    Mesh::build(&Scene::load(Path::new(case)).unwrap().surfaces, size)
}

/// The segments of the links between every `step`-th patch and every `step`-th other one
/// they face, as a link traces them: the 4 between matching points, then the other 12.
fn links(mesh: &Mesh, step: usize) -> Vec<Vec<Segment>> {
    let mut sets = Vec::new();
    for (i, p) in mesh.patches.iter().enumerate().step_by(step) {
        for q in mesh.patches.iter().skip(i % 3).step_by(step).filter(|q| facing(p, q)) {
            let (a, b) = (sample_points(p), sample_points(q));
            let segment = |k: usize, m: usize| (a[k], b[m], [p.face, q.face]);
            sets.push((0..POINTS).map(|k| segment(k, k)).collect());
            sets.push(
                (0..POINTS)
                    .flat_map(|k| (0..POINTS).filter(move |&m| m != k).map(move |m| (k, m)))
                    .map(|(k, m)| segment(k, m))
                    .collect(),
            );
        }
    }
    sets
}

/// Packets of random segments between points of the box around the mesh.
fn random(mesh: &Mesh, packets: usize, rng: &mut Rng) -> Vec<Vec<Segment>> {
    let (lo, hi) = bounds(mesh);
    let mut point = || lo + (hi - lo) * DVec3::from(rng.uniform3());
    (0..packets).map(|_| (0..PACKET).map(|_| (point(), point(), [NO_FACE, NO_FACE])).collect()).collect()
}

/// Packets of segments from points just above a patch (10 µm to 1 mm) to points as far above
/// other patches on the same plane's side: along the faces, grazing their triangles' edges.
fn grazing(mesh: &Mesh, step: usize, rng: &mut Rng) -> Vec<Vec<Segment>> {
    let patches = &mesh.patches;
    let mut sets = Vec::new();
    for (i, p) in patches.iter().enumerate().step_by(step) {
        let lift = 10f64.powf(-5.0 + 2.0 * rng.uniform());
        let on = |q: &ugo::geometry::Patch| {
            q.normal.dot(p.normal) > 0.999 && (q.centroid - p.centroid).dot(p.normal).abs() < 1e-9
        };
        let set: Vec<Segment> = patches
            .iter()
            .skip(i % step)
            .filter(|q| on(q))
            .take(PACKET)
            .map(|q| (p.centroid + lift * p.normal, q.polygon.vertices()[0] + lift * p.normal, [NO_FACE, NO_FACE]))
            .collect();
        sets.push(set);
    }
    sets
}

fn bounds(mesh: &Mesh) -> (DVec3, DVec3) {
    let corners = mesh.patches.iter().flat_map(|p| p.polygon.vertices().iter().copied());
    corners.fold((DVec3::MAX, DVec3::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)))
}

/// (segments, blocked ones, answers or blockers that differ) over `sets`, each taken with
/// the blocker the previous one left, as a row of links is.
fn compare(v: &Visibility, sets: &[Vec<Segment>]) -> [usize; 3] {
    let (mut together, mut alone) = (NO_BLOCKER, NO_BLOCKER);
    let [mut tested, mut blocked, mut different] = [0; 3];
    for set in sets {
        let free = v.visible_together(set, &mut together);
        for (i, &(a, b, ignore)) in set.iter().enumerate() {
            let visible = v.visible_cached(a, b, ignore, &mut alone);
            different += (visible != (free & 1 << i != 0)) as usize;
            blocked += !visible as usize;
            tested += 1;
        }
        different += (together != alone) as usize;
        together = alone;
    }
    [tested, blocked, different]
}

fn check(v: &Visibility, name: &str, sets: &[Vec<Segment>]) {
    let [tested, blocked, different] = compare(v, sets);
    assert_eq!(different, 0, "{name}: {different} of {tested} answers or blockers differ");
    assert!(blocked > tested / 20 && blocked < tested, "{name}: {blocked} of {tested} segments blocked");
}

#[test]
fn segments_traced_together_answer_as_each_alone_in_the_cornell_box() {
    let mesh = mesh("cases/cornell-box.toml", 0.05);
    let rng = &mut Rng::keyed(35);
    for options in [VisibilityOptions::default(), VisibilityOptions { wide: false, ..VisibilityOptions::default() }] {
        let v = Visibility::build_with(&mesh, options);
        check(&v, "links", &links(&mesh, 13));
        check(&v, "random", &random(&mesh, 2000, rng));
        let [tested, _, different] = compare(&v, &grazing(&mesh, 3, rng));
        assert_eq!(different, 0, "grazing: {different} of {tested} answers or blockers differ");
    }
}

#[test]
fn segments_traced_together_answer_as_each_alone_in_the_office() {
    let mesh = mesh("cases/office.toml", 0.25);
    let v = Visibility::build(&mesh);
    let rng = &mut Rng::keyed(36);
    check(&v, "links", &links(&mesh, 97));
    check(&v, "random", &random(&mesh, 2000, rng));
    let [tested, _, different] = compare(&v, &grazing(&mesh, 7, rng));
    assert_eq!(different, 0, "grazing: {different} of {tested} answers or blockers differ");
}

#[test]
fn a_links_visible_fraction_is_the_one_of_its_segments_traced_alone() {
    // The reference: the 4 segments between matching points, then, when they disagree, the
    // other 12, each traced alone with the blocker cached (the code before the packets).
    let mesh = mesh("cases/office.toml", 0.25);
    let v = Visibility::build(&mesh);
    let alone = |a: &[(DVec3, u32); POINTS], b: &[(DVec3, u32); POINTS], blocker: &mut Blocker| {
        let mut free = |k: usize, m: usize| v.visible_cached(a[k].0, b[m].0, [a[k].1, b[m].1], blocker) as usize;
        let first: usize = (0..POINTS).map(|k| free(k, k)).sum();
        if first == 0 || first == POINTS {
            return (first / POINTS) as f64;
        }
        let rest: usize = (0..POINTS)
            .flat_map(|k| (0..POINTS).map(move |m| (k, m)))
            .filter(|(k, m)| k != m)
            .map(|(k, m)| free(k, m))
            .sum();
        (first + rest) as f64 / (POINTS * POINTS) as f64
    };
    let (mut partial, mut links) = (0, 0);
    for (i, p) in mesh.patches.iter().enumerate().step_by(41) {
        let (mut together, mut single) = (NO_BLOCKER, NO_BLOCKER);
        let a = sample_points(p).map(|x| (x, p.face));
        for q in mesh.patches.iter().skip(i % 5).step_by(5).filter(|q| facing(p, q)) {
            let b = sample_points(q).map(|x| (x, q.face));
            let fraction = fraction_between(&v, &a, &b, &mut together).fraction;
            assert_eq!(fraction.to_bits(), alone(&a, &b, &mut single).to_bits());
            partial += (fraction > 0.0 && fraction < 1.0) as usize;
            links += 1;
        }
    }
    assert!(partial > links / 50, "only {partial} of {links} links partly visible");
}
