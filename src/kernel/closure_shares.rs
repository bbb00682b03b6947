//! The kernel's closure seen from the receiver (`docs/design.md` §3b, "Balance"): for every
//! patch `i`, the share of its view that its rows receive from, `t_i = Σ_(d,j,m) G[(i,d),(j,m)]`
//! (one application `G·1`), given to each of its columns `(i, m)` beside
//! `kernel::sent_shares`'s `s_im`.
//!
//! The hierarchy is balanced so that its rows carry the leaves' closures (measured by rays
//! where its links cannot tell them), while its columns are held within a few link
//! tolerances of 1 (`kernel/hierarchy/balance.rs`). Of the light escaping from its surfaces,
//! `Σ Φ (1 − s)`, the part `Σ Φ (1 − t)` leaves through the geometry's openings and the rest,
//! `Σ Φ (t − s)`, is lost by the links themselves. The uniform kernel is balanced
//! symmetrically (its columns are its rows), and a kernel with plane mirrors receives on
//! its rows what the mirrors' images carry as well, so for both the sent shares stand for
//! the closures.

use super::operator::Kernel;
use super::transport::Transport;

/// The closure of each column's patch, flat `j·K + m` as `sent` (`kernel::sent_shares`),
/// which it is for a uniform kernel or with `mirrors` (see the module's comment).
pub fn closure_shares(kernel: &Kernel, sent: &[f64], mirrors: bool) -> Vec<f64> {
    if mirrors || !matches!(kernel.g, Transport::Hierarchical(_)) {
        return sent.to_vec();
    }
    let k = kernel.cells();
    let mut rows = vec![0.0; kernel.g.rows()];
    kernel.apply_transport(&vec![1.0; rows.len()], &mut rows);
    rows.chunks(k).flat_map(|cells| std::iter::repeat_n(cells.iter().sum::<f64>(), k)).collect()
}
