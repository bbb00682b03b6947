//! Random facing patch pairs of a mesh, reproducible: the bench's occlusion segments and
//! links are drawn on them.

use crate::geometry::{Mesh, Patch, facing};
use crate::random::Rng;

/// `count` draws of `make` on random facing patch pairs (reproducible), or `None` when no
/// facing pair turns up in `1000 · count` draws.
pub fn facing_pairs<T>(
    mesh: &Mesh,
    count: usize,
    mut make: impl FnMut(&Patch, &Patch, &mut Rng) -> T,
) -> Option<Vec<T>> {
    let n = mesh.len() as u64;
    if n < 2 {
        return None;
    }
    let mut rng = Rng::stream(0x2545_F491_4F6C_DD1D, 0);
    let mut out = Vec::with_capacity(count);
    for _ in 0..1000 * count.max(1) {
        if out.len() == count {
            break;
        }
        let (i, j) = ((rng.next_u64() % n) as usize, (rng.next_u64() % n) as usize);
        let (a, b) = (&mesh.patches[i], &mesh.patches[j]);
        if i == j || !facing(a, b) {
            continue;
        }
        out.push(make(a, b, &mut rng));
    }
    (!out.is_empty()).then_some(out)
}
