//! `/kernel/hierarchy` of the HDF5 dump (issue 36, `docs/kernel-file.md`, "The hierarchical
//! kernel"): the hierarchy of `docs/design.md` §3b saved so that ugo applies it again without
//! refining and other programs rebuild `G = diag(receive) P Λ R diag(send)` from it.
//!
//! Layout (N leaves, T tree nodes by id, L links, depth-first positions for the operator):
//! `tree/{parent, level}` (T; u32 with 4294967295 at the top, u8 with 255 for a cluster)
//! and `tree/leaf_node` (N, u32); `links/{receiver, source}` (L, u32 node ids),
//! `links/{factor, visible}` (L, f64), `links/sight` (L, u8: 0 clear, 1 partial, 2
//! occluded), `links/pieces/{indptr, d, m, f}` (the cell split, CSR by link; empty for one
//! cell); `operator/{parent, weight, cluster}` (by position: parent position, share of the
//! parent's exposed area, 1 for a cluster), `operator/facing_share` (T×6: under a cluster,
//! the node's share of each of its parent's six facing areas), `operator/leaf_position`
//! (N), `operator/push/{indptr, bundle, share}` (CSR by leaf), `operator/gather/{indptr,
//! source, d, m, f}` (CSR by bundle; `d` = 65535 for light that arrives from all cells alike,
//! `μ_d/π` each; `m` of a cluster source names one of its six facing values),
//! `operator/{receive, send}` (N) and the attributes `links`, `balance_correction`,
//! `balance_sweeps`, `balance_row_error`; `leaves/frame` (N×3×3: each leaf's tangent,
//! bitangent and normal, which it keeps from its root) and `leaves/root_position` (N, u32:
//! its root's position in the cluster tree's depth-first order, which decides its part,
//! `partition.rs`; absent in files before it). The leaves' polygons, surfaces,
//! faces, twins and exposed areas are `/mesh` of the same file.

use super::dataset::dataset;
use super::read::{File, Why, patches};
use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::kernel::BalanceReport;
use crate::kernel::hierarchy::{Entry, FACING, Link, NONE, Operator, Parts, Sight, Skeleton, Structure};
use crate::model::StoredHierarchy;
use glam::DVec3;
use ndarray::{Array1, Array2, Array3};

/// Level stored for a cluster.
const CLUSTER: u8 = u8::MAX;

/// Writes the hierarchy of `operator` with its `structure`, the leaves' frames of `mesh`
/// and the number of `roots` into `g`.
pub(super) fn write_hierarchy_kernel(
    g: &hdf5::Group,
    operator: &Operator,
    structure: &Structure,
    mesh: &Mesh,
    roots: usize,
) -> hdf5::Result<()> {
    let tree = g.create_group("tree")?;
    dataset(&tree, "parent", &Array1::from(structure.skeleton.parent.clone()))?;
    dataset(&tree, "level", &Array1::from_iter(structure.skeleton.level.iter().map(|l| l.unwrap_or(CLUSTER))))?;
    dataset(&tree, "leaf_node", &Array1::from(operator.leaves().to_vec()))?;
    write_links(&g.create_group("links")?, &structure.links)?;
    write_operator(&g.create_group("operator")?, &operator.parts())?;
    let p = &mesh.patches;
    let frame = Array3::from_shape_fn((p.len(), 3, 3), |(i, a, c)| [p[i].tangent, p[i].bitangent, p[i].normal][a][c]);
    let leaves = g.create_group("leaves")?;
    dataset(&leaves, "frame", &frame)?;
    if let Some(position) = structure.leaf_root_positions(operator.leaves()) {
        dataset(&leaves, "root_position", &Array1::from(position))?;
    }
    g.new_attr::<u64>().create("roots")?.write_scalar(&(roots as u64))
}

fn write_links(g: &hdf5::Group, links: &[Link]) -> hdf5::Result<()> {
    let column = |f: fn(&Link) -> u32| Array1::from_iter(links.iter().map(f));
    dataset(g, "receiver", &column(|l| l.receiver))?;
    dataset(g, "source", &column(|l| l.source))?;
    dataset(g, "factor", &Array1::from_iter(links.iter().map(|l| l.factor)))?;
    dataset(g, "visible", &Array1::from_iter(links.iter().map(|l| f64::from(l.visible))))?;
    dataset(g, "sight", &Array1::from_iter(links.iter().map(|l| l.sight() as u8)))?;
    let pieces = g.create_group("pieces")?;
    let indptr = std::iter::once(0).chain(links.iter().scan(0u64, |n, l| {
        *n += l.pieces.len() as u64;
        Some(*n)
    }));
    dataset(&pieces, "indptr", &Array1::from_iter(indptr))?;
    let all = || links.iter().flat_map(|l| l.pieces.iter());
    dataset(&pieces, "d", &Array1::from_iter(all().map(|p| p.0)))?;
    dataset(&pieces, "m", &Array1::from_iter(all().map(|p| p.1)))?;
    dataset(&pieces, "f", &Array1::from_iter(all().map(|p| p.2)))
}

fn write_operator(g: &hdf5::Group, parts: &Parts) -> hdf5::Result<()> {
    dataset(g, "parent", &Array1::from(parts.parent.clone()))?;
    dataset(g, "weight", &Array1::from(parts.weight.clone()))?;
    dataset(g, "cluster", &Array1::from_iter(parts.cluster.iter().map(|&c| c as u8)))?;
    dataset(g, "facing_share", &facing_array(&parts.facing_share))?;
    dataset(g, "leaf_position", &Array1::from(parts.leaf_position.clone()))?;
    let push = g.create_group("push")?;
    dataset(&push, "indptr", &Array1::from_iter(parts.push_row.iter().map(|&r| r as u64)))?;
    dataset(&push, "bundle", &Array1::from_iter(parts.push.iter().map(|p| p.0)))?;
    dataset(&push, "share", &Array1::from_iter(parts.push.iter().map(|p| f64::from(p.1))))?;
    write_gather(g, &parts.row, &parts.entries)?;
    dataset(g, "receive", &Array1::from(parts.receive.clone()))?;
    dataset(g, "send", &Array1::from(parts.send.clone()))?;
    g.new_attr::<u64>().create("links")?.write_scalar(&(parts.links as u64))?;
    let b =
        parts.balanced.unwrap_or(BalanceReport { residual: f64::NAN, max_correction: f64::NAN, ..Default::default() });
    g.new_attr::<f64>().create("balance_correction")?.write_scalar(&b.max_correction)?;
    g.new_attr::<f64>().create("balance_row_error")?.write_scalar(&b.residual)?;
    g.new_attr::<u64>().create("balance_sweeps")?.write_scalar(&(b.iterations as u64))
}

/// The hierarchy's operator over `directions` from `/kernel/hierarchy`, checked.
pub(super) fn read_operator(file: &File, directions: &DirectionSet) -> Result<Operator, Why> {
    let at = |name: &str| format!("kernel/hierarchy/operator/{name}");
    let g = file.h5.group("kernel/hierarchy/operator")?;
    let index = |name: &str| -> Result<Vec<usize>, Why> {
        Ok(file.raw::<u64>(&at(name))?.into_iter().map(|v| v as usize).collect())
    };
    // the shares are f32 in memory (`push.rs`), written as f64
    let zip2 = |a: Vec<u32>, b: Vec<f64>| -> Result<Vec<(u32, f32)>, Why> {
        match a.len() == b.len() {
            true => Ok(a.into_iter().zip(b.into_iter().map(|s| s as f32)).collect()),
            false => Err(Why("/kernel/hierarchy/operator/push: bundle and share differ in length".into())),
        }
    };
    let (source, d, m, f) = (
        file.raw::<u32>(&at("gather/source"))?,
        file.raw::<u16>(&at("gather/d"))?,
        file.raw::<u16>(&at("gather/m"))?,
        file.raw::<f64>(&at("gather/f"))?,
    );
    if d.len() != source.len() || m.len() != source.len() || f.len() != source.len() {
        return Err(Why("/kernel/hierarchy/operator/gather: source, d, m and f differ in length".into()));
    }
    let entries = (0..source.len()).map(|i| Entry { source: source[i], d: d[i], m: m[i], f: f[i] }).collect();
    let balanced = {
        let (residual, max_correction): (f64, f64) =
            (g.attr("balance_row_error")?.read_scalar()?, g.attr("balance_correction")?.read_scalar()?);
        let iterations: u64 = g.attr("balance_sweeps")?.read_scalar()?;
        residual.is_finite().then_some(BalanceReport {
            residual,
            max_correction,
            iterations: iterations as usize,
            by_cell: false,
        })
    };
    let parts = Parts {
        leaves: file.raw::<u32>("kernel/hierarchy/tree/leaf_node")?,
        leaf_position: file.raw::<u32>(&at("leaf_position"))?,
        parent: file.raw::<u32>(&at("parent"))?,
        weight: file.raw::<f64>(&at("weight"))?,
        cluster: file.raw::<u8>(&at("cluster"))?.into_iter().map(|c| c != 0).collect(),
        facing_share: facing_rows(file.raw::<f64>(&at("facing_share"))?)?,
        push_row: index("push/indptr")?,
        push: zip2(file.raw::<u32>(&at("push/bundle"))?, file.raw::<f64>(&at("push/share"))?)?,
        row: index("gather/indptr")?,
        entries,
        links: g.attr("links")?.read_scalar::<u64>()? as usize,
        receive: file.raw::<f64>(&at("receive"))?,
        send: file.raw::<f64>(&at("send"))?,
        balanced,
    };
    Operator::from_parts(parts, directions).map_err(|e| Why(format!("/kernel/hierarchy/operator: {e}")))
}

/// The leaves (`/mesh` with `/kernel/hierarchy/leaves/frame`), the tree's skeleton and
/// links, and the leaves' cuts `least`; `n` leaves expected.
pub(super) fn read_hierarchy(file: &File, n: usize, least: Vec<f64>) -> Result<StoredHierarchy, Why> {
    let mut leaves = patches(file)?;
    let frame = file.f64s("kernel/hierarchy/leaves/frame")?;
    if leaves.len() != n || frame.shape() != [n, 3, 3] || least.len() != n {
        return Err(Why(format!(
            "/mesh, /kernel/hierarchy/leaves/frame and /kernel/direct/least do not all hold {n} leaves"
        )));
    }
    let exposed = file.raw::<f64>("mesh/exposed_areas")?;
    if exposed.len() != n || exposed.iter().any(|a| !(a.is_finite() && *a >= 0.0)) {
        return Err(Why(format!("/mesh/exposed_areas does not hold {n} exposed areas")));
    }
    if frame.iter().any(|v| !v.is_finite()) {
        return Err(Why("/kernel/hierarchy/leaves/frame holds a non-finite value".into()));
    }
    for (i, p) in leaves.iter_mut().enumerate() {
        let axis = |a: usize| DVec3::new(frame[[i, a, 0]], frame[[i, a, 1]], frame[[i, a, 2]]);
        (p.tangent, p.bitangent, p.normal, p.exposed) = (axis(0), axis(1), axis(2), exposed[i]);
    }
    let roots = file.h5.group("kernel/hierarchy")?.attr("roots")?.read_scalar::<u64>()? as usize;
    Ok(StoredHierarchy { leaves, least, roots, structure: structure(file)? })
}

/// `/kernel/hierarchy/{tree, links}`.
fn structure(file: &File) -> Result<Structure, Why> {
    let parent = file.raw::<u32>("kernel/hierarchy/tree/parent")?;
    let level = file.raw::<u8>("kernel/hierarchy/tree/level")?;
    let nodes = parent.len();
    if level.len() != nodes || parent.iter().any(|&p| p != NONE && p as usize >= nodes) {
        return Err(Why("/kernel/hierarchy/tree: parent and level do not make a tree".into()));
    }
    let level = level.into_iter().map(|l| (l != CLUSTER).then_some(l)).collect();
    let at = |name: &str| format!("kernel/hierarchy/links/{name}");
    let (receiver, source) = (file.raw::<u32>(&at("receiver"))?, file.raw::<u32>(&at("source"))?);
    let (factor, visible, sight) =
        (file.raw::<f64>(&at("factor"))?, file.raw::<f64>(&at("visible"))?, file.raw::<u8>(&at("sight"))?);
    let indptr = file.raw::<u64>(&at("pieces/indptr"))?;
    let (d, m, f) =
        (file.raw::<u16>(&at("pieces/d"))?, file.raw::<u16>(&at("pieces/m"))?, file.raw::<f64>(&at("pieces/f"))?);
    let l = receiver.len();
    let same = [source.len(), factor.len(), visible.len(), sight.len(), indptr.len().saturating_sub(1)]
        .iter()
        .all(|&x| x == l)
        && sight.iter().zip(&visible).all(|(&s, &v)| s == Sight::of(v) as u8);
    let pieces_fit = indptr.first() == Some(&0)
        && indptr.windows(2).all(|w| w[0] <= w[1])
        && indptr.last().is_some_and(|&e| e as usize == d.len() && d.len() == m.len() && d.len() == f.len());
    if !same || !pieces_fit || receiver.iter().chain(&source).any(|&id| id as usize >= nodes) {
        return Err(Why("/kernel/hierarchy/links: the links' arrays disagree (in length, or a sight not the class of its visible fraction) or name nodes beyond the tree".into()));
    }
    let links = (0..l)
        .map(|i| {
            let pieces = (indptr[i] as usize..indptr[i + 1] as usize).map(|j| (d[j], m[j], f[j])).collect();
            Link::new(receiver[i], source[i], factor[i], visible[i], 0.0, pieces)
        })
        .collect();
    let skeleton = Skeleton { parent, level };
    let root_position = root_positions(file, &skeleton)?;
    Ok(Structure { skeleton, links, root_position })
}

/// By root element, its depth-first position from `/kernel/hierarchy/leaves/root_position`
/// (each leaf's root's), or empty for a file written before it was stored.
fn root_positions(file: &File, skeleton: &Skeleton) -> Result<Vec<u32>, Why> {
    const AT: &str = "kernel/hierarchy/leaves/root_position";
    if !file.h5.link_exists(AT) {
        return Ok(Vec::new());
    }
    let (leaf_node, by_leaf) = (file.raw::<u32>("kernel/hierarchy/tree/leaf_node")?, file.raw::<u32>(AT)?);
    let roots = skeleton.level.iter().filter(|&&l| l == Some(0)).count();
    let mut position = vec![u32::MAX; roots];
    for (&leaf, &p) in leaf_node.iter().zip(&by_leaf) {
        match skeleton.root_of(leaf).and_then(|id| position.get_mut(id as usize)) {
            Some(slot) if (p as usize) < roots => *slot = p,
            _ => {
                return Err(Why(format!(
                    "/{AT}: leaf node {leaf} has no root among the {roots} roots, or a position beyond them"
                )));
            }
        }
    }
    Ok(position)
}

/// The gathered pieces `entries` by bundle (CSR rows `row`) as `gather/{indptr, source, d,
/// m, f}` in `g`.
pub(super) fn write_gather(g: &hdf5::Group, row: &[usize], entries: &[Entry]) -> hdf5::Result<()> {
    let gather = g.create_group("gather")?;
    dataset(&gather, "indptr", &Array1::from_iter(row.iter().map(|&r| r as u64)))?;
    dataset(&gather, "source", &Array1::from_iter(entries.iter().map(|e| e.source)))?;
    dataset(&gather, "d", &Array1::from_iter(entries.iter().map(|e| e.d)))?;
    dataset(&gather, "m", &Array1::from_iter(entries.iter().map(|e| e.m)))?;
    dataset(&gather, "f", &Array1::from_iter(entries.iter().map(|e| e.f)))
}

/// Facing shares as a `T × 6` array.
pub(crate) fn facing_array(shares: &[[f64; FACING]]) -> Array2<f64> {
    Array2::from_shape_vec((shares.len(), FACING), shares.as_flattened().to_vec()).expect("six a row")
}

/// Facing shares from a `T × 6` array read flat.
pub(crate) fn facing_rows(flat: Vec<f64>) -> Result<Vec<[f64; FACING]>, Why> {
    match flat.len() % FACING {
        0 => Ok(flat.chunks(FACING).map(|c| std::array::from_fn(|i| c[i])).collect()),
        _ => Err(Why(format!("/kernel/hierarchy/operator/facing_share: {} values, not six a node", flat.len()))),
    }
}
