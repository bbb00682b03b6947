//! ugo's own four-wide occlusion traversal against obvhs's: the same answer on every
//! segment, hits and misses alike.

use super::cornell;
use glam::DVec3;
use ugo::geometry::{Mesh, facing};
use ugo::random::Rng;
use ugo::transfer::occlusion::sample_points;
use ugo::visibility::{NO_BLOCKER, NO_FACE, Visibility, VisibilityOptions};

/// The assembly's segments (between the sample points of facing patches, many exactly
/// axis-aligned) and as many random ones between points inside the room, ignoring random
/// faces or none.
fn segments(mesh: &Mesh) -> Vec<(DVec3, DVec3, [u32; 2])> {
    let mut rng = Rng::stream(35, 0);
    let n = mesh.len() as u64;
    let mut out = Vec::new();
    while out.len() < 20_000 {
        let (p, q) = (&mesh.patches[(rng.next_u64() % n) as usize], &mesh.patches[(rng.next_u64() % n) as usize]);
        if facing(p, q) {
            let (a, b) =
                (sample_points(p)[(rng.next_u64() % 4) as usize], sample_points(q)[(rng.next_u64() % 4) as usize]);
            out.push((a, b, [p.face, q.face]));
        }
    }
    let inside = |rng: &mut Rng| DVec3::from(rng.uniform3()) * DVec3::new(0.556, 0.5488, 0.5592);
    for _ in 0..20_000 {
        let face = if rng.uniform() < 0.5 { NO_FACE } else { mesh.patches[(rng.next_u64() % n) as usize].face };
        out.push((inside(&mut rng), inside(&mut rng), [face, NO_FACE]));
    }
    out
}

/// Every segment answered alike by the two traversals, alone and with a blocker cache.
fn agree(mesh: &Mesh, obvhs: VisibilityOptions) {
    let old = Visibility::build_with(mesh, obvhs);
    let own = Visibility::build_with(mesh, VisibilityOptions { own: true, ..obvhs });
    let (mut blocked, mut cached) = (0, [NO_BLOCKER; 2]);
    for (a, b, ignore) in segments(mesh) {
        let answer = old.visible(a, b, ignore);
        assert_eq!(own.visible(a, b, ignore), answer, "{a} → {b} ignoring {ignore:?}");
        assert_eq!(own.visible_cached(a, b, ignore, &mut cached[0]), answer, "{a} → {b}, cached");
        assert_eq!(old.visible_cached(a, b, ignore, &mut cached[1]), answer, "{a} → {b}, cached");
        blocked += usize::from(!answer);
    }
    assert!((5_000..35_000).contains(&blocked), "{blocked} of 40,000 segments blocked");
}

#[test]
fn the_own_traversal_answers_every_segment_as_obvhs_does() {
    let mesh = cornell();
    agree(&mesh, VisibilityOptions::default());
    agree(&mesh, VisibilityOptions { wide: false, ..VisibilityOptions::default() });
    agree(&mesh, VisibilityOptions { rotate: true, ..VisibilityOptions::default() });
}
