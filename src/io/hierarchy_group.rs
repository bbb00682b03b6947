//! `/hierarchy` of the HDF5 dump (`docs/design.md` §3b, §8): what the hierarchical kernel made.
//! `leaf_level` and `leaf_root` give each patch of `/mesh` (a leaf element) its level
//! (0 = a root) and the root element it lies in; `element_links` counts links between two
//! elements by the deeper level; `passes/` holds the refinement history, one entry per
//! pass. Written only for a hierarchical model.

use super::dataset::dataset;
use crate::kernel::BalanceReport;
use crate::kernel::hierarchy::Pass;
use crate::model::HierarchyRecord;
use ndarray::Array1;

pub(super) fn write_hierarchy(g: &hdf5::Group, h: &HierarchyRecord) -> hdf5::Result<()> {
    let c = &h.census;
    dataset(g, "leaf_level", &Array1::from(c.leaf_level.clone()))?;
    dataset(g, "leaf_root", &Array1::from(c.leaf_root.clone()))?;
    dataset(g, "element_links", &Array1::from(c.element_links.iter().map(|&n| n as u64).collect::<Vec<_>>()))?;
    let attributes = [
        ("link_tolerance", h.parameters.link_tolerance),
        ("root_size_m", h.parameters.root_size),
        ("patch_size_m", h.patch_size),
        ("roots", h.roots as f64),
        ("cluster_links", c.cluster_links as f64),
        ("clear_links", c.clear as f64),
        ("partial_links", c.partial as f64),
    ];
    for (name, value) in attributes {
        g.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    let passes = g.create_group("passes")?;
    let column = |f: fn(&Pass) -> f64| Array1::from_iter(h.history.iter().map(f));
    dataset(&passes, "links", &column(|p| p.links as f64))?;
    dataset(&passes, "refined", &column(|p| p.refined as f64))?;
    dataset(&passes, "source_splits", &column(|p| p.source_splits as f64))?;
    dataset(&passes, "leaves", &column(|p| p.leaves as f64))?;
    dataset(&passes, "nodes", &column(|p| p.nodes as f64))?;
    dataset(&passes, "rays", &column(|p| p.rays as f64))?;
    dataset(&passes, "epsilon_cd_m2", &column(|p| p.epsilon))?;
    dataset(&passes, "seconds", &column(|p| p.seconds))?;
    dataset(&passes, "operator_seconds", &column(|p| p.operator_seconds))?;
    dataset(&passes, "solve_seconds", &column(|p| p.solve_seconds))?;
    // balancing to the leaves' closures (NaN: the pass's operator was not balanced)
    let balance = |f: fn(&BalanceReport) -> f64| {
        Array1::from_iter(h.history.iter().map(|p| p.balance.as_ref().map_or(f64::NAN, f)))
    };
    dataset(&passes, "balance_correction", &balance(|b| b.max_correction))?;
    dataset(&passes, "balance_sweeps", &balance(|b| b.iterations as f64))?;
    dataset(&passes, "balance_row_error", &balance(|b| b.residual))?;
    Ok(())
}
