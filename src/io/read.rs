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
    pub scene: Scene,
    /// The patches rebuilt from `/mesh/vertices` (emission from `/field/emission`).
    pub mesh: Mesh,
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
pub fn read_solution(path: &Path) -> std::result::Result<StoredSolution, IoError> {
    let file = hdf5::File::open(path).map_err(|e| IoError::Open { path: path.to_path_buf(), why: e.to_string() })?;
    read_from(&file).map_err(|Why(why)| IoError::NotASolution { path: path.to_path_buf(), why })
}

/// What is wrong with a file's layout.
struct Why(String);

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

type Result<T> = std::result::Result<T, Why>;

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

fn read_from(file: &hdf5::File) -> Result<StoredSolution> {
    let scene_file = text(file, "scene_file")?;
    let scene = Scene::parse_with(Path::new(&scene_file), text(file, "scene_text")?, case_files(file)?)?;
    let name = text(file, "directions")?;
    let directions = Scheme::parse(&name).ok_or_else(|| why!("unknown direction set \"{name}\""))?.set();
    let luminance = file.dataset("field/luminance")?.read_dyn::<f64>()?;
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
    let emission = file.dataset("field/emission")?.read_dyn::<f64>()?;
    let emission: Vec<f64> = (0..n).map(|i| emission.get([i, 0, 0]).copied().unwrap_or(0.0)).collect();
    let materials = scene.materials.len();
    if let Some(i) = patches.iter().position(|p| p.material as usize >= materials) {
        bail!("/mesh/material_id[{i}] = {}, but the stored scene has {materials} materials", patches[i].material);
    }
    let faces = patches.iter().map(|p| p.face as usize + 1).max().unwrap_or(0);
    let mesh = Mesh { patches, emission, faces };
    let luminance: Vec<f64> = luminance.iter().copied().collect();
    let orders = if file.group("orders").is_ok() { orders(file, n * k)? } else { Vec::new() };
    let standard_error = match file.dataset("field/standard_error") {
        Ok(d) => {
            let e = d.read_raw::<f64>()?;
            if e.len() != n * k {
                bail!("/field/standard_error holds {} values, expected {n}×{k}", e.len());
            }
            Some(e)
        }
        Err(_) => None,
    };
    let method = text(file, "method")?;
    Ok(StoredSolution { scene, mesh, directions, luminance, orders, standard_error, method })
}

/// The stored copies of the case's files (`/case_files`), or the disk for older files.
fn case_files(file: &hdf5::File) -> Result<CaseFiles> {
    let Ok(group) = file.group("case_files") else { return Ok(CaseFiles::disk()) };
    let paths = group.dataset("paths")?.read_raw::<VarLenUnicode>()?;
    let files = paths
        .iter()
        .enumerate()
        .map(|(i, p)| {
            Ok(CaseFile { path: PathBuf::from(p.as_str()), bytes: group.dataset(&i.to_string())?.read_raw::<u8>()? })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(CaseFiles::stored(files))
}

/// The partial sums of `/orders/{orders,partial_sums}`, each `size` long.
fn orders(file: &hdf5::File, size: usize) -> Result<Vec<(usize, Vec<f64>)>> {
    let which = file.dataset("orders/orders")?.read_raw::<u64>()?;
    let sums = file.dataset("orders/partial_sums")?.read_raw::<f64>()?;
    if sums.len() != which.len() * size {
        bail!("/orders/partial_sums holds {} values, expected {} orders × {size}", sums.len(), which.len());
    }
    Ok(which.iter().zip(sums.chunks(size)).map(|(&n, sum)| (n as usize, sum.to_vec())).collect())
}

/// The patches from `/mesh/{vertices,vertex_count,surface_id,material_id}` and, when
/// stored, `/mesh/{face,twin}`; older files get faces by pairing back-to-back twins.
fn patches(file: &hdf5::File) -> Result<Vec<Patch>> {
    let vertices = file.dataset("mesh/vertices")?.read_dyn::<f64>()?;
    let count = file.dataset("mesh/vertex_count")?.read_raw::<u8>()?;
    let surface = file.dataset("mesh/surface_id")?.read_raw::<u32>()?;
    let material = file.dataset("mesh/material_id")?.read_raw::<u32>()?;
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
        patches.push(Patch::from_polygon(ConvexPolygon::from_slice(&v), surface[i], material[i], i as u32));
    }
    match (file.dataset("mesh/face"), file.dataset("mesh/twin")) {
        (Ok(face), Ok(twin)) => {
            let (face, twin) = (face.read_raw::<u32>()?, twin.read_raw::<u32>()?);
            if face.len() != n || twin.len() != n || twin.iter().any(|&t| t != NO_TWIN && t as usize >= n) {
                bail!("/mesh/face or /mesh/twin does not match the patches");
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

fn text(file: &hdf5::File, name: &str) -> Result<String> {
    let value: VarLenUnicode =
        file.attr(name).and_then(|a| a.read_scalar()).map_err(|e| why!("attribute `{name}`: {e}"))?;
    Ok(value.as_str().to_string())
}
