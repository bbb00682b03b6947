//! `/kernel` of the HDF5 dump (issue 15, `docs/kernel-file.md`): the uniform kernel
//! `K = B·G` and source term `L0 = L_e + B·D` of `docs/design.md` §2–§3, stored so that ugo
//! reuses them instead of assembling and other programs read them with h5py and scipy.
//!
//! Layout (N patches, K cells, M materials, Q luminaires; vectors flat, `x[i·K + k]`):
//! `G/{data,indices,indptr}` in CSR with the attribute `shape` (`scipy.sparse.csr_matrix(
//! (data, indices, indptr), shape)` reads it; data f64, or f32 with `--precision f32`;
//! indices int32, int64 past 2³¹), `B/{reflection,transmission}` (M×K×K, row = outgoing
//! cell; zeros where a material does not transmit) and `B/transmits` (M, u8),
//! `patch_material` (N, u32), `twin` (N, u32; 4294967295 for none), `direct/arriving`
//! (`D`, N·K, cd/m²) and `direct/intercepted` (Q, lm; attribute `rays`), `emission`
//! (`L_e`, N, cd/m²), `L0` (N·K, cd/m²), `fingerprint` (one attribute per part: its
//! hash in hex and `<part>_summary`), and attributes `format`, `directions`, `precision`.
//! `B` acts on patch `i` as `y_i = ρ̄_{m(i)} z_i + τ̄_{m(i)} z_{twin(i)}`.

use super::IoError;
use super::dataset::{dataset, text_attr};
use super::hierarchy_kernel::{read_hierarchy, read_operator, write_hierarchy_kernel};
use super::read::{File, Why, open, text};
use crate::directions::Scheme;
use crate::geometry::NO_TWIN;
use crate::kernel::{Kernel, Transport, TransportMatrix};
use crate::luminaire::DirectLight;
use crate::material::Block;
use crate::model::{Fingerprint, HierarchyRecord, KERNEL_FORMAT, Model, Part, Stamp, StoredHierarchy};
use ndarray::{Array1, Array3, ArrayView1};
use sprs::{CsMatI, SpIndex};
use std::path::Path;

/// A kernel as read from `/kernel`.
pub struct StoredKernel {
    /// The fingerprint of the case that saved it.
    pub fingerprint: Fingerprint,
    /// `G` (the uniform kernel's), the direction set, the blocks, each patch's material and twin.
    pub kernel: Kernel,
    /// The luminaires' direct light `D` as the saving solve had it.
    pub direct: DirectLight,
    /// `L0 = L_e + B·D` as the saving solve had it.
    pub l0: Vec<f64>,
    /// What a hierarchical kernel holds besides its operator (`hierarchy_kernel.rs`);
    /// `None` for the uniform kernel.
    pub hierarchy: Option<StoredHierarchy>,
}

/// The value of the attribute `kernel` of a hierarchical kernel's `/kernel` (a uniform
/// kernel's has `uniform`, or none in files before issue 36).
const HIERARCHICAL: &str = "hierarchical";

/// Writes the kernel of `model` (the uniform `G`, or the hierarchy with the structure its
/// record kept) and its `fingerprint` into the group `g`.
pub(super) fn write_kernel(g: &hdf5::Group, model: &Model, fingerprint: &Fingerprint) -> hdf5::Result<()> {
    let kernel = &model.kernel;
    match (&kernel.g, &model.hierarchy) {
        (Transport::Uniform(matrix), _) => {
            let csr = g.create_group("G")?;
            match matrix {
                TransportMatrix::Double(m) => write_csr(&csr, m)?,
                TransportMatrix::Single(m) => write_csr(&csr, m)?,
            }
            text_attr(g, "kernel", "uniform")?;
        }
        (Transport::Hierarchical(operator), Some(HierarchyRecord { structure: Some(structure), roots, .. })) => {
            let h = g.create_group("hierarchy")?;
            write_hierarchy_kernel(&h, operator, structure, &model.mesh, *roots)?;
            text_attr(g, "kernel", HIERARCHICAL)?;
        }
        (Transport::Hierarchical(_), _) => return Err("the hierarchy was built without its links kept".into()),
    }
    write_blocks(g, &kernel.blocks, kernel.cells())?;
    dataset(g, "patch_material", &Array1::from(kernel.patch_material.clone()))?;
    dataset(g, "twin", &Array1::from(kernel.twin.clone()))?;
    let direct = g.create_group("direct")?;
    dataset(&direct, "arriving", &Array1::from(model.direct.arriving.clone()))?;
    dataset(&direct, "intercepted", &Array1::from(model.direct.intercepted.clone()))?;
    dataset(&direct, "least", &Array1::from(model.direct.least.clone()))?;
    direct.new_attr::<u64>().create("rays")?.write_scalar(&(model.direct.rays as u64))?;
    dataset(g, "emission", &Array1::from(model.mesh.emission.clone()))?;
    dataset(g, "L0", &Array1::from(model.l0.clone()))?;
    write_fingerprint(&g.create_group("fingerprint")?, fingerprint)?;
    g.new_attr::<u32>().create("format")?.write_scalar(&KERNEL_FORMAT)?;
    text_attr(g, "directions", kernel.directions.name())?;
    text_attr(g, "precision", kernel.g.precision().name())
}

/// Every part of `fingerprint` as two text attributes of `f`: the hash in hex and the summary.
pub(super) fn write_fingerprint(f: &hdf5::Group, fingerprint: &Fingerprint) -> hdf5::Result<()> {
    for s in &fingerprint.stamps {
        text_attr(f, s.part.name(), &format!("{:016x}", s.hash))?;
        text_attr(f, &format!("{}_summary", s.part.name()), &s.summary)?;
    }
    Ok(())
}

/// `data`, `indices` and `indptr` of `m` (indices as int32 when they fit) and its `shape`.
fn write_csr<N: hdf5::H5Type + Copy, I: SpIndex>(g: &hdf5::Group, m: &CsMatI<N, I>) -> hdf5::Result<()> {
    g.new_dataset_builder().with_data(ArrayView1::from(m.data())).create("data")?;
    let indptr = m.indptr();
    let indptr = indptr.raw_storage();
    if m.nnz() < i32::MAX as usize && m.rows() < i32::MAX as usize {
        let narrow = |v: &[I]| Array1::from_iter(v.iter().map(|i| i.index() as i32));
        dataset(g, "indices", &narrow(m.indices()))?;
        dataset(g, "indptr", &narrow(indptr))?;
    } else {
        let wide = |v: &[I]| Array1::from_iter(v.iter().map(|i| i.index() as i64));
        dataset(g, "indices", &wide(m.indices()))?;
        dataset(g, "indptr", &wide(indptr))?;
    }
    g.new_attr::<i64>().shape(2).create("shape")?.write_raw(&[m.rows() as i64, m.cols() as i64])
}

/// Reads `/kernel` of `path`, checking every index and size against the others.
pub fn read_kernel(path: &Path) -> Result<StoredKernel, IoError> {
    let (h5, bytes) = open(path)?;
    let file = File { h5: &h5, bytes };
    if h5.group("kernel").is_err() {
        let why = "the file has no /kernel group: write one with `ugo solve CASE --save-kernel`".to_string();
        return Err(IoError::NotAKernel { path: path.to_path_buf(), why });
    }
    read_from(&file).map_err(|Why(why)| IoError::NotAKernel { path: path.to_path_buf(), why })
}

fn read_from(file: &File) -> Result<StoredKernel, Why> {
    let g = file.h5.group("kernel")?;
    let format: u32 = g.attr("format")?.read_scalar()?;
    if format != KERNEL_FORMAT {
        return Err(Why(format!("kernel format {format}, this ugo reads format {KERNEL_FORMAT}")));
    }
    let name = text(&g, "directions")?;
    let directions = Scheme::parse(&name).ok_or_else(|| Why(format!("unknown direction set \"{name}\"")))?.set();
    let k = directions.len();
    let patch_material = file.raw::<u32>("kernel/patch_material")?;
    let twin = file.raw::<u32>("kernel/twin")?;
    let n = patch_material.len();
    if twin.len() != n || twin.iter().any(|&t| t != NO_TWIN && t as usize >= n) {
        return Err(Why("/kernel/twin does not match /kernel/patch_material".into()));
    }
    let blocks = blocks(file, k)?;
    if let Some(i) = patch_material.iter().position(|&m| m as usize >= blocks.len()) {
        return Err(Why(format!("/kernel/patch_material[{i}] names no block of /kernel/B")));
    }
    let hierarchical = text(&g, "kernel").is_ok_and(|kind| kind == HIERARCHICAL);
    let transport = match hierarchical {
        true => Transport::Hierarchical(Box::new(read_operator(file, &directions)?)),
        false => Transport::Uniform(csr(file, n * k)?),
    };
    let values = |name: &str, len: usize, valid: fn(&f64) -> bool, what: &str| -> Result<Vec<f64>, Why> {
        let v = file.raw::<f64>(&format!("kernel/{name}"))?;
        if v.len() != len || !v.iter().all(valid) {
            return Err(Why(format!("/kernel/{name} holds {} values (expected {len} {what} ones)", v.len())));
        }
        Ok(v)
    };
    let vector = |name: &str, len: usize| values(name, len, |x| x.is_finite(), "finite");
    let arriving = vector("direct/arriving", n * k)?;
    let intercepted = file.raw::<f64>("kernel/direct/intercepted")?;
    let rays: u64 = g.group("direct")?.attr("rays")?.read_scalar()?;
    let l0 = vector("L0", n * k)?;
    let fingerprint = fingerprint(&g.group("fingerprint")?)?;
    // A hierarchy's leaves keep their cuts: a group's light (`Model::source_term_of`) is cut
    // as the solve cut it, so that it adds up to the stored `D` (`docs/light-scenes.md`).
    // +∞ on a leaf that reflects nothing (a lamp's surface): none of its light is worth cutting
    let least = if hierarchical { values("direct/least", n, |x| *x >= 0.0, "non-negative")? } else { Vec::new() };
    let direct = DirectLight { arriving, intercepted, rays: rays as usize, least: least.clone() };
    let hierarchy = hierarchical.then(|| read_hierarchy(file, n, least)).transpose()?;
    if transport.rows() != n * k {
        return Err(Why(format!(
            "/kernel holds an operator of {} unknowns for {n} patches × {k} cells",
            transport.rows()
        )));
    }
    let kernel = Kernel::new(transport, directions, blocks, patch_material, twin);
    Ok(StoredKernel { fingerprint, kernel, direct, l0, hierarchy })
}

/// `/kernel/B` as blocks of `k` cells.
fn blocks(file: &File, k: usize) -> Result<Vec<Block>, Why> {
    let reflect = file.f64s("kernel/B/reflection")?;
    let transmit = file.f64s("kernel/B/transmission")?;
    let transmits = file.raw::<u8>("kernel/B/transmits")?;
    let m = transmits.len();
    if reflect.shape() != [m, k, k] || transmit.shape() != [m, k, k] {
        return Err(Why(format!("/kernel/B holds blocks of shape {:?}, expected {m}×{k}×{k}", reflect.shape())));
    }
    if reflect.iter().chain(transmit.iter()).any(|v| !v.is_finite()) {
        return Err(Why("/kernel/B holds a non-finite value".into()));
    }
    let values = |a: &ndarray::ArrayD<f64>, i: usize| a.index_axis(ndarray::Axis(0), i).iter().copied().collect();
    Ok((0..m).map(|i| Block::new(k, values(&reflect, i), (transmits[i] != 0).then(|| values(&transmit, i)))).collect())
}

/// `/kernel/G` of `rows` rows, in the precision it was stored in.
fn csr(file: &File, rows: usize) -> Result<TransportMatrix, Why> {
    let shape: Vec<i64> = file.h5.group("kernel/G")?.attr("shape")?.read_raw()?;
    if shape != [rows as i64, rows as i64] {
        return Err(Why(format!("/kernel/G has shape {shape:?}, the patches and cells give {rows}×{rows}")));
    }
    let indices = file.raw::<i64>("kernel/G/indices")?;
    let indptr = file.raw::<i64>("kernel/G/indptr")?;
    let index = |v: Vec<i64>, what: &str| -> Result<Vec<usize>, Why> {
        v.into_iter()
            .map(|i| usize::try_from(i).map_err(|_| Why(format!("/kernel/G/{what} holds the negative {i}"))))
            .collect()
    };
    let (indices, indptr) = (index(indices, "indices")?, index(indptr, "indptr")?);
    let broken = |e: sprs::errors::StructureError| Why(format!("/kernel/G is not a CSR matrix: {e}"));
    let single = file.dataset("kernel/G/data", 4)?.dtype()?.size() == 4;
    if single {
        let data = file.raw::<f32>("kernel/G/data")?;
        finite(data.iter().map(|&v| v as f64))?;
        let narrow = |v: Vec<usize>| v.into_iter().map(|i| i as u32).collect::<Vec<u32>>();
        let m = CsMatI::try_new((rows, rows), narrow(indptr), narrow(indices), data).map_err(|e| broken(e.3))?;
        Ok(TransportMatrix::Single(m))
    } else {
        let data = file.raw::<f64>("kernel/G/data")?;
        finite(data.iter().copied())?;
        let m = CsMatI::try_new((rows, rows), indptr, indices, data).map_err(|e| broken(e.3))?;
        Ok(TransportMatrix::Double(m))
    }
}

fn finite(mut values: impl Iterator<Item = f64>) -> Result<(), Why> {
    match values.position(|v| !v.is_finite()) {
        Some(i) => Err(Why(format!("/kernel/G/data[{i}] is not finite"))),
        None => Ok(()),
    }
}

/// The stamps of `/kernel/fingerprint` (parts this ugo does not know are skipped).
pub(super) fn fingerprint(g: &hdf5::Group) -> Result<Fingerprint, Why> {
    let mut stamps = Vec::new();
    for part in Part::ALL {
        let Ok(hex) = text(g, part.name()) else { continue };
        let hash = u64::from_str_radix(&hex, 16).map_err(|e| Why(format!("fingerprint {}: {e}", part.name())))?;
        let summary = text(g, &format!("{}_summary", part.name())).unwrap_or_default();
        stamps.push(Stamp { part, hash, summary });
    }
    Ok(Fingerprint { stamps })
}

/// The material blocks `blocks` of `k` cells as `B/reflection`, `B/transmission` (M × K × K,
/// zeros where a material does not transmit) and `B/transmits` (M, u8) in `g`.
pub(super) fn write_blocks(g: &hdf5::Group, blocks: &[Block], k: usize) -> hdf5::Result<()> {
    let b = g.create_group("B")?;
    dataset(&b, "reflection", &Array3::from_shape_fn((blocks.len(), k, k), |(m, a, d)| blocks[m].at(a, d)))?;
    let transmit = |m: usize, a: usize, d: usize| blocks[m].transmit_at(a, d).unwrap_or(0.0);
    dataset(&b, "transmission", &Array3::from_shape_fn((blocks.len(), k, k), |(m, a, d)| transmit(m, a, d)))?;
    dataset(&b, "transmits", &Array1::from_iter(blocks.iter().map(|b| b.transmits() as u8)))
}
