//! Reading a solve back from its HDF5 file (the layout of `hdf5_file.rs`): the stored
//! scene, the patch geometry and the luminance field (with its standard errors when the
//! file holds a Monte Carlo estimate), enough to look at or compare the result again.

use super::IoError;
use crate::directions::{DirectionSet, Scheme};
use crate::geometry::{ConvexPolygon, Mesh, NO_TWIN, Patch};
use crate::scene::Scene;
use crate::scene::{CaseFile, CaseFiles, SceneError};
use glam::DVec3;
use hdf5::types::VarLenUnicode;
use std::path::{Path, PathBuf};

/// A solve as stored: the scene, its patches and the luminance of each (patch, cell).
pub struct StoredSolution {
    /// The case, parsed again from the stored text (cameras included).
    pub scene: Scene,
    /// The patches rebuilt from `/mesh/vertices` (emission from `/field/emission`).
    pub mesh: Mesh,
    /// The direction cells of the stored field.
    pub directions: DirectionSet,
    /// Luminance of patch `i` in cell `k` at `i·K + k`, cd/m².
    pub luminance: Vec<f64>,
    /// `(n, Σ_{m≤n} KᵐL0)` from `/orders`, when the solve recorded reflection orders.
    pub orders: Vec<(usize, Vec<f64>)>,
    /// The standard error of every luminance (`/field/standard_error`), when the file
    /// holds a Monte Carlo estimate (`ugo trace --forward`).
    pub standard_error: Option<Vec<f64>>,
    /// The `method` attribute (`"forward"` for a Monte Carlo estimate).
    pub method: String,
}

/// Opens `path` and reads the scene, mesh, direction set and luminance field.
///
/// A file that is not ugo's is refused with what is wrong, never a panic: a named pipe
/// (before opening it), ids that point past the stored scene or mesh, non-finite
/// vertices or luminances, and declared sizes larger than the file could hold (a dataset
/// of 10⁹ elements in a small file is refused before anything is allocated).
pub fn read_solution(path: &Path) -> std::result::Result<StoredSolution, IoError> {
    let (file, bytes) = open(path)?;
    if !file.link_exists("field") {
        return Err(IoError::NoField { path: path.to_path_buf() });
    }
    read_from(&File { h5: &file, bytes }).map_err(|Why(why)| IoError::NotASolution { path: path.to_path_buf(), why })
}

/// Opens `path` as HDF5 (refusing a named pipe before opening it), with its size on disk.
pub(super) fn open(path: &Path) -> std::result::Result<(hdf5::File, u64), IoError> {
    let open = |why: String| IoError::Open { path: path.to_path_buf(), why };
    crate::scene::regular_file(path).map_err(|e| open(e.to_string()))?;
    let bytes = std::fs::metadata(path).map_err(|e| open(e.to_string()))?.len();
    let file = hdf5::File::open(path).map_err(|e| open(e.to_string()))?;
    Ok((file, bytes))
}

/// What is wrong with a file's layout.
pub(super) struct Why(pub(super) String);

impl From<hdf5::Error> for Why {
    fn from(e: hdf5::Error) -> Why {
        Why(e.to_string())
    }
}

impl From<SceneError> for Why {
    fn from(e: SceneError) -> Why {
        Why(format!("its stored scene: {e}"))
    }
}

pub(super) type Result<T> = std::result::Result<T, Why>;

macro_rules! why {
    ($($reason:tt)*) => {
        Why(format!($($reason)*))
    };
}

macro_rules! bail {
    ($($reason:tt)*) => {
        return Err(Why(format!($($reason)*)))
    };
}

/// An open solution file and its size on disk, bytes.
pub(super) struct File<'a> {
    pub(super) h5: &'a hdf5::File,
    pub(super) bytes: u64,
}

impl File<'_> {
    /// The dataset `name`, if its declared size fits in the file (ugo stores datasets
    /// uncompressed, so a larger one is not ugo's and would allocate without bound).
    pub(super) fn dataset(&self, name: &str, element: usize) -> Result<hdf5::Dataset> {
        if !self.h5.link_exists(name) {
            bail!("it has no /{name}");
        }
        let d = self.h5.dataset(name)?;
        let declared = (d.size() as u128) * element as u128;
        if declared > self.bytes as u128 {
            bail!(
                "/{name} declares {} elements ({declared} bytes), more than the file's {} bytes",
                d.size(),
                self.bytes
            );
        }
        Ok(d)
    }

    pub(super) fn f64s(&self, name: &str) -> Result<ndarray::ArrayD<f64>> {
        Ok(self.dataset(name, 8)?.read_dyn::<f64>()?)
    }

    pub(super) fn raw<T: hdf5::H5Type>(&self, name: &str) -> Result<Vec<T>> {
        Ok(self.dataset(name, std::mem::size_of::<T>())?.read_raw::<T>()?)
    }
}

fn read_from(file: &File) -> Result<StoredSolution> {
    let h5 = file.h5;
    let scene_file = text(h5, "scene_file")?;
    let scene = Scene::parse_with(Path::new(&scene_file), text(h5, "scene_text")?, case_files(file)?)?;
    let name = text(h5, "directions")?;
    let scheme = Scheme::parse(&name).ok_or_else(|| why!("unknown direction set \"{name}\""))?;
    // The cell count the name declares must be the field's before the set is built.
    let declared = file.dataset("field/luminance", 8)?.shape();
    if let Scheme::Cells(k) = scheme
        && declared.get(1) != Some(&k)
    {
        bail!("/field/luminance has shape {declared:?}, but the file names {k} direction cells");
    }
    let directions = scheme.set();
    let luminance = file.f64s("field/luminance")?;
    let k = directions.len();
    let shape = luminance.shape().to_vec();
    if shape.len() != 3 || shape[1] != k {
        bail!("/field/luminance has shape {shape:?}, expected N×{k}×1");
    }
    let patches = patches(file)?;
    let n = patches.len();
    if shape[0] != n {
        bail!("/field/luminance has {} patches, /mesh/vertices {n}", shape[0]);
    }
    if let Some((i, l)) = luminance.iter().enumerate().find(|(_, l)| !l.is_finite()) {
        bail!("/field/luminance[{i}] = {l}, not a finite luminance");
    }
    let emission = file.f64s("field/emission")?;
    let emission: Vec<f64> = (0..n).map(|i| emission.get([i, 0, 0]).copied().unwrap_or(0.0)).collect();
    let materials = scene.materials.len();
    if let Some(i) = patches.iter().position(|p| p.material as usize >= materials) {
        bail!("/mesh/material_id[{i}] = {}, but the stored scene has {materials} materials", patches[i].material);
    }
    let surfaces = scene.surfaces.len();
    if let Some(i) = patches.iter().position(|p| p.surface as usize >= surfaces) {
        bail!("/mesh/surface_id[{i}] = {}, but the stored scene has {surfaces} surfaces", patches[i].surface);
    }
    let faces = patches.iter().map(|p| p.face as usize + 1).max().unwrap_or(0);
    let mesh = Mesh { patches, emission, faces };
    let luminance: Vec<f64> = luminance.iter().copied().collect();
    let orders = if h5.group("orders").is_ok() { orders(file, n * k)? } else { Vec::new() };
    let standard_error = match h5.dataset("field/standard_error") {
        Ok(_) => {
            let e = file.raw::<f64>("field/standard_error")?;
            if e.len() != n * k {
                bail!("/field/standard_error holds {} values, expected {n}×{k}", e.len());
            }
            if let Some((i, e)) = e.iter().enumerate().find(|(_, e)| !(e.is_finite() && **e >= 0.0)) {
                bail!("/field/standard_error[{i}] = {e}, not a standard error");
            }
            Some(e)
        }
        Err(_) => None,
    };
    let method = text(h5, "method")?;
    Ok(StoredSolution { scene, mesh, directions, luminance, orders, standard_error, method })
}

/// The stored copies of the case's files (`/case_files`), or the disk for older files.
fn case_files(file: &File) -> Result<CaseFiles> {
    let Ok(group) = file.h5.group("case_files") else { return Ok(CaseFiles::disk()) };
    let paths = file.raw::<VarLenUnicode>("case_files/paths")?;
    let files = paths
        .iter()
        .enumerate()
        .map(|(i, p)| {
            Ok(CaseFile { path: PathBuf::from(p.as_str()), bytes: file.raw::<u8>(&format!("case_files/{i}"))? })
        })
        .collect::<Result<Vec<_>>>()?;
    let _ = group;
    Ok(CaseFiles::stored(files))
}

/// The partial sums of `/orders/{orders,partial_sums}`, each `size` long.
fn orders(file: &File, size: usize) -> Result<Vec<(usize, Vec<f64>)>> {
    let which = file.raw::<u64>("orders/orders")?;
    let sums = file.raw::<f64>("orders/partial_sums")?;
    if sums.len() != which.len() * size {
        bail!("/orders/partial_sums holds {} values, expected {} orders × {size}", sums.len(), which.len());
    }
    Ok(which.iter().zip(sums.chunks(size)).map(|(&n, sum)| (n as usize, sum.to_vec())).collect())
}

/// The patches from `/mesh/{vertices,vertex_count,surface_id,material_id}` and, when
/// stored, `/mesh/{face,twin}`; older files get faces by pairing back-to-back twins.
pub(super) fn patches(file: &File) -> Result<Vec<Patch>> {
    let vertices = file.f64s("mesh/vertices")?;
    let count = file.raw::<u8>("mesh/vertex_count")?;
    let surface = file.raw::<u32>("mesh/surface_id")?;
    let material = file.raw::<u32>("mesh/material_id")?;
    let n = count.len();
    if vertices.shape() != [n, 4, 3] || surface.len() != n || material.len() != n {
        bail!("/mesh datasets disagree on the number of patches");
    }
    let mut patches = Vec::with_capacity(n);
    for i in 0..n {
        let m = count[i] as usize;
        if !(3..=4).contains(&m) {
            bail!("/mesh/vertex_count[{i}] = {m}, expected 3 or 4");
        }
        let v: Vec<DVec3> =
            (0..m).map(|j| DVec3::new(vertices[[i, j, 0]], vertices[[i, j, 1]], vertices[[i, j, 2]])).collect();
        if !v.iter().all(|p| p.is_finite()) {
            bail!("/mesh/vertices[{i}] has a non-finite coordinate");
        }
        let polygon = ConvexPolygon::from_slice(&v);
        if !(polygon.area() > 0.0 && polygon.area().is_finite()) {
            bail!("/mesh/vertices[{i}] is a patch of area {}", polygon.area());
        }
        patches.push(Patch::from_polygon(polygon, surface[i], material[i], i as u32));
    }
    match (file.h5.dataset("mesh/face"), file.h5.dataset("mesh/twin")) {
        (Ok(_), Ok(_)) => {
            let (face, twin) = (file.raw::<u32>("mesh/face")?, file.raw::<u32>("mesh/twin")?);
            if face.len() != n || twin.len() != n || twin.iter().any(|&t| t != NO_TWIN && t as usize >= n) {
                bail!("/mesh/face or /mesh/twin does not match the patches");
            }
            // A face per patch at most, a twin's twin the patch itself, twins on one face.
            if let Some(i) = (0..n).find(|&i| face[i] as usize >= n) {
                bail!("/mesh/face[{i}] = {}, but there are {n} patches", face[i]);
            }
            if let Some(i) = (0..n).find(|&i| {
                let t = twin[i];
                t != NO_TWIN && (t as usize == i || twin[t as usize] != i as u32 || face[t as usize] != face[i])
            }) {
                bail!("/mesh/twin[{i}] = {} is not a back-to-back twin of patch {i}", twin[i]);
            }
            for (p, (&f, &t)) in patches.iter_mut().zip(face.iter().zip(&twin)) {
                (p.face, p.twin) = (f, t);
            }
        }
        _ => pair_twins(&mut patches),
    }
    Ok(patches)
}

/// Gives consecutive patches with the same vertices in reverse order one shared face.
fn pair_twins(patches: &mut [Patch]) {
    let mut face = 0u32;
    let mut i = 0;
    while i < patches.len() {
        let twins = i + 1 < patches.len() && reversed(&patches[i], &patches[i + 1]);
        patches[i].face = face;
        if twins {
            patches[i + 1].face = face;
            (patches[i].twin, patches[i + 1].twin) = (i as u32 + 1, i as u32);
        }
        i += if twins { 2 } else { 1 };
        face += 1;
    }
}

fn reversed(a: &Patch, b: &Patch) -> bool {
    let (a, b) = (a.polygon.vertices(), b.polygon.vertices());
    let mut b: Vec<DVec3> = b.to_vec();
    b.reverse();
    a.len() == b.len() && (0..b.len()).any(|r| a.iter().zip(b.iter().cycle().skip(r)).all(|(x, y)| x == y))
}

pub(super) fn text(file: &hdf5::Location, name: &str) -> Result<String> {
    let value: VarLenUnicode =
        file.attr(name).and_then(|a| a.read_scalar()).map_err(|e| why!("attribute `{name}`: {e}"))?;
    Ok(value.as_str().to_string())
}
