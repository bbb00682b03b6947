//! Hulls the occluders know clear (`Visibility::hull_is_clear`, a gather's pieces seen
//! without rays: `visibility/between.rs`): in the Cornell box, the open box and the
//! furnished office (1,044 occluders, of which a hull's box meets few), from points
//! on the surfaces (exactly on them, as an error bar's landing points, and 1 mm in front, as
//! the probes) to every patch and each of its quarters, every segment a gather would trace
//! into a hull known clear is visible to the rays, or found blocked only by a face it
//! passes outside of or within [`SLACK`] of its edges: the rays' own `f32` slack on the
//! triangles' edges, met in the office where a segment grazes the edge of a box's side
//! (its sample points and the furniture lie on the same centimetre grid) or arrives 25 µm
//! from a rotated panel's edge. The hull's answer, visible, is the exact one there.

use glam::DVec3;
use std::path::Path;
use ugo::geometry::{ConvexPolygon, Mesh, Patch};
use ugo::scene::Scene;
use ugo::transfer::occlusion::polygon_points;
use ugo::visibility::Visibility;

/// How far inside a face's edges a segment must cross it to count as blocked by it, m.
const SLACK: f64 = 1e-4;

/// `(segments into hulls known clear, of them blocked, segments in all, blocked in all, of
/// them crossed)` from every `step`-th patch's centre (on it and 1 mm in front) to every
/// patch and quarter; a segment into a clear hull counts as blocked only when the face the
/// rays find in its way is crossed more than [`SLACK`] inside its edges.
fn segments(case: &str, size: f64, step: usize) -> [usize; 5] {
    let scene = Scene::load(Path::new(case)).unwrap();
    let mesh = Mesh::build(&scene.surfaces, size);
    let v = Visibility::build_for(&scene.surfaces, &mesh);
    let mut of_face = vec![0; mesh.faces];
    mesh.patches.iter().enumerate().for_each(|(i, p)| of_face[p.face as usize] = i);
    let mut counts = [0; 5];
    for s in mesh.patches.iter().step_by(step) {
        for p in [s.centroid, s.centroid + 1e-3 * s.normal] {
            for t in mesh.patches.iter().filter(|t| (p - t.centroid).dot(t.normal) > 0.0) {
                let quarters = t.polygon.split();
                for piece in std::iter::once(&t.polygon).chain(&quarters) {
                    let clear = v.hull_is_clear(p, piece);
                    for y in tested(piece) {
                        let blocked = !v.visible(p, y, [s.face, t.face]);
                        let truly = blocked && crossed(&v, &mesh, &of_face, p, y, s.face);
                        let add = [clear, clear && truly, true, blocked, truly].map(usize::from);
                        counts.iter_mut().zip(add).for_each(|(c, a)| *c += a);
                    }
                }
            }
        }
    }
    counts
}

/// Whether the segment from `p` (on face `own`) to `y` crosses the first face the rays find
/// along it more than [`SLACK`] inside that face's edges.
fn crossed(v: &Visibility, mesh: &Mesh, of_face: &[usize], p: DVec3, y: DVec3, own: u32) -> bool {
    let Some(hit) = v.closest_hit(p, (y - p).normalize(), own) else { return false };
    inside(&mesh.patches[of_face[hit.face as usize]], p, y)
}

/// Whether the segment from `p` to `y` crosses `face`'s polygon more than [`SLACK`] inside
/// its edges.
fn inside(face: &Patch, p: DVec3, y: DVec3) -> bool {
    let (n, corners) = (face.normal, face.polygon.vertices());
    let (hp, hy) = ((p - corners[0]).dot(n), (y - corners[0]).dot(n));
    if hp * hy >= 0.0 {
        return false;
    }
    let x = p + (y - p) * (hp / (hp - hy));
    let centroid = face.polygon.centroid();
    (0..corners.len()).all(|i| {
        let (a, b) = (corners[i], corners[(i + 1) % corners.len()]);
        let inward = n.cross(b - a).normalize();
        let inward = if inward.dot(centroid - a) < 0.0 { -inward } else { inward };
        inward.dot(x - a) > SLACK
    })
}

/// The points a gather's rays go to on `piece`: its stratified points and its corners pulled
/// in by 0.1 % towards its centroid (`transfer::occlusion::piece_visibility`).
fn tested(piece: &ConvexPolygon) -> Vec<DVec3> {
    let c = piece.centroid();
    polygon_points(piece).into_iter().chain(piece.vertices().iter().map(|v| v.lerp(c, 1e-3))).collect()
}

#[test]
fn no_segment_into_a_hull_known_clear_is_blocked() {
    // (case, patch size, every how many patches a point, least share known clear)
    let cases =
        [("cases/cornell-box.toml", 0.1, 7, 5), ("cases/open-box.toml", 0.1, 5, 5), ("cases/office.toml", 0.5, 61, 20)];
    for (case, size, step, share) in cases {
        let [clear, clear_blocked, all, blocked, crossed] = segments(case, size, step);
        assert_eq!(clear_blocked, 0, "{case}: {clear_blocked} of {clear} segments into clear hulls blocked");
        assert!(clear > all / share, "{case}: only {clear} of {all} segments known clear");
        assert!(blocked > all / 50, "{case}: only {blocked} of {all} segments blocked");
        assert!(crossed > blocked / 10 * 9, "{case}: of {blocked} blocked segments only {crossed} cross a face");
    }
}
