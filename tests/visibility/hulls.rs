//! Hulls the occluders know clear (`Visibility::hull_is_clear`, a gather's pieces seen
//! without rays: `visibility/between.rs`): in the Cornell box and the open box, from points
//! on the surfaces (exactly on them, as an error bar's landing points, and 1 mm in front, as
//! the probes) to every patch and each of its quarters, every segment a gather would trace
//! into a hull known clear is visible.

use glam::DVec3;
use std::path::Path;
use ugo::geometry::{ConvexPolygon, Mesh};
use ugo::scene::Scene;
use ugo::transfer::occlusion::polygon_points;
use ugo::visibility::Visibility;

/// `(segments into hulls known clear, of them blocked, segments in all, blocked in all)`
/// from every `step`-th patch's centre (on it and 1 mm in front) to every patch and quarter.
fn segments(case: &str, size: f64, step: usize) -> [usize; 4] {
    let scene = Scene::load(Path::new(case)).unwrap();
    let mesh = Mesh::build(&scene.surfaces, size);
    let v = Visibility::build_for(&scene.surfaces, &mesh);
    let mut counts = [0; 4];
    for s in mesh.patches.iter().step_by(step) {
        for p in [s.centroid, s.centroid + 1e-3 * s.normal] {
            for t in mesh.patches.iter().filter(|t| (p - t.centroid).dot(t.normal) > 0.0) {
                let quarters = t.polygon.split();
                for piece in std::iter::once(&t.polygon).chain(&quarters) {
                    let clear = v.hull_is_clear(p, piece);
                    for y in tested(piece) {
                        let blocked = !v.visible(p, y, [s.face, t.face]) as usize;
                        let add = [clear as usize, clear as usize * blocked, 1, blocked];
                        counts.iter_mut().zip(add).for_each(|(c, a)| *c += a);
                    }
                }
            }
        }
    }
    counts
}

/// The points a gather's rays go to on `piece`: its stratified points and its corners pulled
/// in by 0.1 % towards its centroid (`transfer::occlusion::piece_visibility`).
fn tested(piece: &ConvexPolygon) -> Vec<DVec3> {
    let c = piece.centroid();
    polygon_points(piece).into_iter().chain(piece.vertices().iter().map(|v| v.lerp(c, 1e-3))).collect()
}

#[test]
fn no_segment_into_a_hull_known_clear_is_blocked() {
    for (case, step) in [("cases/cornell-box.toml", 7), ("cases/open-box.toml", 5)] {
        let [clear, clear_blocked, all, blocked] = segments(case, 0.1, step);
        assert_eq!(clear_blocked, 0, "{case}: {clear_blocked} of {clear} segments into clear hulls blocked");
        assert!(clear > all / 5, "{case}: only {clear} of {all} segments known clear");
        assert!(blocked > all / 50, "{case}: only {blocked} of {all} segments blocked");
    }
}
