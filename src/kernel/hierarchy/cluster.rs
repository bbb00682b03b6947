//! The cluster tree above the input elements (`design.md` §3b, "Clusters"; Smits, Arvo &
//! Greenberg 1994, Sillion 1995): a binary tree built by median splits of the elements'
//! bounding-box centres along the longest axis, so that the initial linking starts from one
//! self-link of the top cluster instead of all k² pairs of the k input elements.

use super::node::NONE;
use super::tree::Tree;
use glam::DVec3;

/// Builds clusters over the elements `ids` (they become the leaves of the cluster tree)
/// and returns the top node: a cluster, the only element, or [`NONE`] when `ids` is empty.
pub fn build(tree: &mut Tree, ids: &mut [u32]) -> u32 {
    match ids.len() {
        0 => NONE,
        1 => ids[0],
        n => {
            let axis = longest_axis(tree, ids);
            let key = |id: &u32| tree.node(*id).centre()[axis];
            ids.select_nth_unstable_by(n / 2, |a, b| key(a).total_cmp(&key(b)));
            let (left, right) = ids.split_at_mut(n / 2);
            let members = [build(tree, left), build(tree, right)];
            tree.add_cluster(&members)
        }
    }
}

/// The axis along which the centres of `ids` spread most.
fn longest_axis(tree: &Tree, ids: &[u32]) -> usize {
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for &id in ids {
        let c = tree.node(id).centre();
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
