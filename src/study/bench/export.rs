//! The files of `ugo bench --export DIR`: the benchmark's triangles, occlusion rays (with
//! ugo's answers) and transport matrix as raw little-endian arrays plus `meta.json`, so
//! that peers (Embree through `embreex`, `scipy.sparse`) time the very same work:
//! `docs/peers/peers.py`.

use super::error::BenchError;
use super::occlusion::Segment;
use crate::geometry::Mesh;
use crate::io::write_bytes;
use crate::visibility::Visibility;
use sprs::CsMat;
use std::path::Path;

/// Writes the arrays and `meta` (a JSON object completed with the sizes) into `dir`.
pub fn export(
    dir: &Path,
    mesh: &Mesh,
    visibility: &Visibility,
    segments: &[Segment],
    g: &CsMat<f64>,
    mut meta: serde_json::Value,
) -> Result<(), BenchError> {
    std::fs::create_dir_all(dir).map_err(|e| BenchError::Folder(dir.to_path_buf(), e))?;
    let mut seen = vec![false; mesh.faces];
    let mut triangles = Vec::new();
    for p in &mesh.patches {
        if !std::mem::replace(&mut seen[p.face as usize], true) {
            for tri in p.polygon.triangles() {
                triangles.extend(tri.iter().flat_map(|v| v.to_array()).map(|x| x as f32));
            }
        }
    }
    // Embree cannot ignore the two end faces as ugo does: the rays stop short of them by
    // 1e-4 of the scene's size instead (ugo's own answers ignore the faces).
    let epsilon = 1e-4 * mesh.extent();
    let mut rays = Vec::with_capacity(segments.len() * 8);
    let mut visible = Vec::with_capacity(segments.len());
    for &(a, b, ignore) in segments {
        let length = a.distance(b);
        let d = (b - a) / length;
        rays.extend([a.x, a.y, a.z, d.x, d.y, d.z, epsilon, length - epsilon].map(|x| x as f32));
        visible.push(visibility.visible(a, b, ignore) as u8);
    }
    let bytes = |values: &[f32]| values.iter().flat_map(|v| v.to_le_bytes()).collect::<Vec<u8>>();
    write(dir, "triangles.f32", &bytes(&triangles))?;
    write(dir, "rays.f32", &bytes(&rays))?;
    write(dir, "visible.u8", &visible)?;
    let u64s = |values: &[usize]| values.iter().flat_map(|&v| (v as u64).to_le_bytes()).collect::<Vec<u8>>();
    write(dir, "csr_indptr.u64", &u64s(g.indptr().raw_storage()))?;
    write(dir, "csr_indices.u64", &u64s(g.indices()))?;
    write(dir, "csr_data.f64", &g.data().iter().flat_map(|v| v.to_le_bytes()).collect::<Vec<u8>>())?;
    meta["triangles"] = (triangles.len() / 9).into();
    meta["rays"] = segments.len().into();
    meta["rows"] = g.rows().into();
    meta["nnz"] = g.nnz().into();
    write(dir, "meta.json", serde_json::to_string_pretty(&meta)?.as_bytes())
}

fn write(dir: &Path, name: &str, data: &[u8]) -> Result<(), BenchError> {
    Ok(write_bytes(&dir.join(name), data)?)
}
