//! A part's rows file (issue 36, point 4; `docs/kernel-file.md`, "Rows files"): what
//! `model::part_rows` forms for one part, read by the distributed program, each rank its
//! part's file (`tools/petsc/from_parts.py`). `/rows` holds the attributes `part`, `parts`,
//! `cells`, `format`, `links`, `reaching_links`, `rays`, `seconds`, `leaves` (`first`,
//! `end`: the part's run of unknowns) and `nodes` (`first`, `end`: its run of depth-first
//! positions); `projected` (the cells' `μ_k`); `tree/{parent (u32), weight (f64), cluster
//! (u8), leaf_position (u32)}`, the whole tree; `bundles/{receiver (u32), kind (u8), source (u32)}`, its
//! bundles' keys; `gather/{indptr (u64), source (u32), d, m (u16), f (f64)}` by bundle;
//! `push/{indptr (u64), receiver (u32), kind (u8), source (u32), share (f64)}` by own leaf; by own leaf
//! `L0` and `arriving` (`x[l·K + k]`, f64), `exposed` (f64), `emits` (u8),
//! `closure/{cast, covered}` (u32), `material` and `twin` (u32, an unknown's index or
//! 4294967295); `balancing`, attributes: the rules of the sweeps (`balance.rs`) and the
//! sending factors' limit; `B/*` as in `/kernel`; and `/rows/fingerprint` as
//! `/kernel/fingerprint`.

use super::IoError;
use super::dataset::dataset;
use super::hierarchy_kernel::{facing_array, write_gather};
use super::kernel_file::{write_blocks, write_fingerprint};
use crate::kernel::hierarchy::BALANCING_RULES;
use crate::model::{Fingerprint, PartRows};
use ndarray::Array1;
use std::path::Path;

/// The layout of `/rows`.
const ROWS_FORMAT: u64 = 4;

/// Writes `rows` with the case's `fingerprint` and the cells' projected solid angles
/// `projected` to `path` (through a temporary file).
pub fn write_part_rows(
    path: &Path,
    fingerprint: &Fingerprint,
    projected: &[f64],
    rows: &PartRows,
) -> Result<(), IoError> {
    super::atomic(path, |tmp| write_to(tmp, fingerprint, projected, rows).map_err(|e| e.to_string()))
}

fn write_to(path: &Path, fingerprint: &Fingerprint, projected: &[f64], p: &PartRows) -> hdf5::Result<()> {
    let file = hdf5::File::create(path)?;
    let g = file.create_group("rows")?;
    let r = &p.rows;
    let attr = |name: &str, v: u64| g.new_attr::<u64>().create(name)?.write_scalar(&v);
    let pair = |name: &str, v: [u64; 2]| g.new_attr::<u64>().shape(2).create(name)?.write(&v);
    attr("part", u64::from(p.part.index))?;
    attr("parts", u64::from(p.part.count))?;
    attr("cells", p.cells as u64)?;
    attr("format", ROWS_FORMAT)?;
    attr("links", r.links as u64)?;
    attr("reaching_links", p.reaching as u64)?;
    attr("rays", p.rays as u64)?;
    g.new_attr::<f64>().create("seconds")?.write_scalar(&p.seconds)?;
    pair("leaves", [r.own_leaves.start as u64, r.own_leaves.end as u64])?;
    pair("nodes", [u64::from(r.own_nodes.start), u64::from(r.own_nodes.end)])?;
    dataset(&g, "projected", &Array1::from(projected.to_vec()))?;
    let tree = g.create_group("tree")?;
    dataset(&tree, "parent", &Array1::from(r.parent.clone()))?;
    dataset(&tree, "weight", &Array1::from(r.weight.clone()))?;
    dataset(&tree, "facing_share", &facing_array(&r.facing_share))?;
    dataset(&tree, "cluster", &Array1::from_iter(r.cluster.iter().map(|&c| u8::from(c))))?;
    dataset(&tree, "leaf_position", &Array1::from(r.leaf_position.clone()))?;
    let bundles = g.create_group("bundles")?;
    dataset(&bundles, "receiver", &Array1::from_iter(r.bundles.iter().map(|b| b.receiver)))?;
    dataset(&bundles, "kind", &Array1::from_iter(r.bundles.iter().map(|b| b.kind)))?;
    dataset(&bundles, "source", &Array1::from_iter(r.bundles.iter().map(|b| b.source)))?;
    write_gather(&g, &r.row, &r.entries)?;
    let push = g.create_group("push")?;
    dataset(&push, "indptr", &Array1::from_iter(r.push_row.iter().map(|&i| i as u64)))?;
    dataset(&push, "receiver", &Array1::from_iter(r.push.iter().map(|(b, _)| b.receiver)))?;
    dataset(&push, "kind", &Array1::from_iter(r.push.iter().map(|(b, _)| b.kind)))?;
    dataset(&push, "source", &Array1::from_iter(r.push.iter().map(|(b, _)| b.source)))?;
    dataset(&push, "share", &Array1::from_iter(r.push.iter().map(|(_, s)| f64::from(*s))))?;
    dataset(&g, "L0", &Array1::from(p.l0.clone()))?;
    dataset(&g, "arriving", &Array1::from(p.arriving.clone()))?;
    dataset(&g, "exposed", &Array1::from(p.exposed.clone()))?;
    dataset(&g, "emits", &Array1::from_iter(p.emits.iter().map(|&e| u8::from(e))))?;
    let closure = g.create_group("closure")?;
    dataset(&closure, "cast", &Array1::from_iter(r.closure.iter().map(|c| c.cast)))?;
    dataset(&closure, "covered", &Array1::from_iter(r.closure.iter().map(|c| c.covered)))?;
    dataset(&g, "material", &Array1::from(p.material.clone()))?;
    dataset(&g, "twin", &Array1::from(p.twin.clone()))?;
    let balancing = g.create_group("balancing")?;
    for (name, value) in BALANCING_RULES.into_iter().chain([("sending", r.sending)]) {
        balancing.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    write_blocks(&g, &p.blocks, p.cells)?;
    write_fingerprint(&g.create_group("fingerprint")?, fingerprint)
}
