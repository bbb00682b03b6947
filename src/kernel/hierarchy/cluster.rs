//! The cluster tree above the input elements (`docs/design.md` §3b, "Clusters"; Smits, Arvo &
//! Greenberg 1994, Sillion 1995): a binary tree built by median splits of the elements'
//! bounding-box centres along the longest axis, so that the initial linking starts from one
//! self-link of the top cluster instead of all k² pairs of the k input elements.

use super::node::NONE;
use glam::DVec3;

/// Builds clusters over the elements `ids` (they become the leaves of the cluster tree;
/// `centres[id]` is element `id`'s centre), adding each cluster over its two members with
/// `add`, and returns the top node: a cluster, the only element, or [`NONE`] when `ids` is
/// empty.
pub fn build(centres: &[DVec3], ids: &mut [u32], add: &mut dyn FnMut(&[u32]) -> u32) -> u32 {
    match ids.len() {
        0 => NONE,
        1 => ids[0],
        n => {
            let axis = longest_axis(centres, ids);
            let key = |id: &u32| centres[*id as usize][axis];
            ids.select_nth_unstable_by(n / 2, |a, b| key(a).total_cmp(&key(b)));
            let (left, right) = ids.split_at_mut(n / 2);
            let members = [build(centres, left, add), build(centres, right, add)];
            add(&members)
        }
    }
}

/// The axis along which the centres of `ids` spread most.
fn longest_axis(centres: &[DVec3], ids: &[u32]) -> usize {
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for &id in ids {
        let c = centres[id as usize];
        lo = lo.min(c);
        hi = hi.max(c);
    }
    let extent = hi - lo;
    if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    }
}
