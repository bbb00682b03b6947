//! glTF 2.0 files as mesh surfaces (issue 38, point 4; `docs/scene-format.md`, "mesh"):
//! `.gltf` (JSON, its buffers embedded as base64 `data:` URIs or in files beside it) and
//! `.glb` (binary). The triangles of the file's default scene (else its first), each node's
//! transform (translation, rotation, scale or matrix) applied down the node tree, in metres
//! as glTF defines; each primitive's material a group of `mesh.rs` named after it, with its
//! base colour factor, times the mean of its base colour texture (`gltf_texture.rs`) unless
//! `materials` maps it. Triangle lists, strips and fans are read (`gltf_topology.rs`). Said
//! as warnings, not read: points and lines, emissive factors and textures.

use super::files::CaseFiles;
use super::gltf_texture::Images;
use super::gltf_topology::{has_area, triangles};
use super::gltf_uri::uri_bytes;
use super::loaded::{Group, Loaded};
use glam::{DMat4, DQuat, DVec3};
use gltf::accessor::{Accessor, DataType, Dimensions};
use gltf::json::validation::Checked;
use gltf::scene::Transform;
use gltf::{Document, Gltf, Mesh, Node, Primitive};
use std::path::Path;

/// The triangles of a glTF file, placed by its nodes, with its materials (the base colour
/// textures of those whose names `mapped` holds not read); errors name the file.
pub(super) fn load_gltf(file: &Path, files: &CaseFiles, mapped: &[&str]) -> Result<Loaded, String> {
    let shown = file.display();
    let bytes = files.read(file).map_err(|e| format!("cannot open the glTF file {shown}: {e}"))?;
    let gltf = parse(&bytes).map_err(|e| format!("cannot read the glTF file {shown} (glTF 2.0 JSON or .glb): {e}"))?;
    let buffers = buffers(file, &gltf, files)?;
    let scene = gltf.default_scene().or_else(|| gltf.scenes().next());
    let scene = scene.ok_or_else(|| format!("the glTF file {shown} has no scene"))?;
    let (groups, warnings) = groups(&gltf.document, &Images { file, buffers: &buffers, files }, mapped)?;
    let mut reading = Reading { file, buffers, nodes: gltf.nodes().len(), triangles: Vec::new(), warnings };
    for node in scene.nodes() {
        reading.node(node, DMat4::IDENTITY, 0)?;
    }
    if reading.triangles.is_empty() {
        return Err(format!("the glTF file {shown} has no triangles in its scene"));
    }
    Ok(Loaded { triangles: reading.triangles, groups, warnings: reading.warnings })
}

/// The file parsed and validated by the `gltf` crate, a primitive's `POSITION` checked
/// first: the crate's validation looks its accessor up without a bound (gltf-json 1.4.1,
/// `mesh.rs`) and would panic on a dangling one.
fn parse(bytes: &[u8]) -> Result<Gltf, String> {
    let Gltf { document, blob } = Gltf::from_slice_without_validation(bytes).map_err(|e| e.to_string())?;
    let root = document.into_json();
    let positions = Checked::Valid(gltf::Semantic::Positions);
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            if primitive.attributes.get(&positions).is_some_and(|a| a.value() >= root.accessors.len()) {
                return Err(format!("meshes[{m}].primitives[{p}].attributes.POSITION: Index out of bounds"));
            }
        }
    }
    let document = Document::from_json(root).map_err(|e| e.to_string())?;
    Ok(Gltf { document, blob })
}

/// The bytes of every buffer of the file: the GLB's binary chunk, a base64 `data:` URI or a
/// file beside it (read through `files`, so that a solution file keeps a copy).
fn buffers(file: &Path, gltf: &Gltf, files: &CaseFiles) -> Result<Vec<Vec<u8>>, String> {
    let shown = file.display();
    let read = |buffer: gltf::Buffer| {
        let index = buffer.index();
        let bytes = match buffer.source() {
            gltf::buffer::Source::Bin => gltf.blob.clone().ok_or_else(|| {
                format!("buffer #{index} of the glTF file {shown} is the binary chunk of a .glb, which it has not")
            })?,
            gltf::buffer::Source::Uri(uri) => {
                uri_bytes(file, uri, files).map_err(|e| format!("buffer #{index} of the glTF file {shown}: {e}"))?
            }
        };
        match bytes.len() < buffer.length() {
            true => Err(format!(
                "buffer #{index} of the glTF file {shown} holds {} bytes, less than its byteLength {}",
                bytes.len(),
                buffer.length()
            )),
            false => Ok(bytes),
        }
    };
    gltf.buffers().map(read).collect()
}

/// The file's materials as groups (named by their `name`, or `#i` when unnamed or when
/// another material has the same name), each of its base colour (times its texture's mean
/// unless `mapped` names it), and what of them is not read or is averaged.
fn groups(document: &Document, images: &Images, mapped: &[&str]) -> Result<(Vec<Group>, Vec<String>), String> {
    let (mut groups, mut warnings) = (Vec::new(), Vec::new());
    for (index, material) in document.materials().enumerate() {
        let named = material.name().filter(|n| document.materials().filter(|m| m.name() == Some(n)).count() == 1);
        let name = named.map_or(format!("#{index}"), str::to_string);
        let [r, g, b, _] = material.pbr_metallic_roughness().base_color_factor().map(f64::from);
        let about = format!("material \"{name}\" (#{index}) of the glTF file {}", images.file.display());
        if ![r, g, b].iter().all(|c| (0.0..=1.0).contains(c)) {
            return Err(format!("{about}: its baseColorFactor [{r}, {g}, {b}] is not within [0, 1]"));
        }
        let mut colour = [r, g, b];
        let texture = material.pbr_metallic_roughness().base_color_texture();
        if let Some(info) = texture.filter(|_| !mapped.contains(&name.as_str())) {
            let (textured, note) = images.textured(&about, info, colour)?;
            colour = textured;
            warnings.push(note);
        }
        if material.emissive_factor().iter().any(|&e| e > 0.0) || material.emissive_texture().is_some() {
            warnings.push(format!(
                "{about} emits: ignored (light comes from [[luminaire]] photometric files and surface `emission`)"
            ));
        }
        groups.push(Group { name, origin: format!("material #{index}"), colour: Some(colour) });
    }
    Ok((groups, warnings))
}

/// The scene graph being walked.
struct Reading<'a> {
    file: &'a Path,
    buffers: Vec<Vec<u8>>,
    /// The file's node count: a deeper path has a cycle.
    nodes: usize,
    triangles: Vec<(usize, [DVec3; 3])>,
    warnings: Vec<String>,
}

impl Reading<'_> {
    /// The triangles of `node` and its children, `parent` the transform above it.
    fn node(&mut self, node: Node, parent: DMat4, depth: usize) -> Result<(), String> {
        if depth > self.nodes {
            return Err(format!(
                "the glTF file {} has a cycle of nodes through node #{}",
                self.file.display(),
                node.index()
            ));
        }
        let world = parent * local(&node);
        if let Some(mesh) = node.mesh() {
            mesh.primitives().try_for_each(|p| self.primitive(&primitive_name(self.file, &mesh, &p), &p, world))?;
        }
        node.children().try_for_each(|child| self.node(child, world, depth + 1))
    }

    /// The triangles of `primitive` (called `mesh` in messages), placed by `world`.
    fn primitive(&mut self, mesh: &str, primitive: &Primitive, world: DMat4) -> Result<(), String> {
        let mode = primitive.mode();
        if !has_area(mode) {
            self.warnings.push(format!("{mesh} is made of {mode:?}, which have no area: skipped"));
            return Ok(());
        }
        let positions = primitive.get(&gltf::Semantic::Positions).ok_or_else(|| format!("{mesh} has no POSITION"))?;
        readable(&positions, &[DataType::F32], Dimensions::Vec3).map_err(|why| format!("{mesh}: POSITION {why}"))?;
        if let Some(indices) = primitive.indices() {
            let types = [DataType::U8, DataType::U16, DataType::U32];
            readable(&indices, &types, Dimensions::Scalar).map_err(|why| format!("{mesh}: its indices {why}"))?;
        }
        let reader = primitive.reader(|b| self.buffers.get(b.index()).map(Vec::as_slice));
        let outside = |what: &str| format!("{mesh}: its {what} lie outside their buffer");
        let corners: Vec<DVec3> = reader
            .read_positions()
            .ok_or_else(|| outside("positions"))?
            .map(|p| world.transform_point3(DVec3::from(p.map(f64::from))))
            .collect();
        let order: Vec<usize> = match (reader.read_indices(), primitive.indices()) {
            (Some(indices), _) => indices.into_u32().map(|i| i as usize).collect(),
            (None, Some(_)) => return Err(outside("indices")),
            (None, None) => (0..corners.len()).collect(),
        };
        let faces = triangles(mode, &order).map_err(|why| format!("{mesh} {why}"))?;
        let group = primitive.material().index().map_or(0, |m| m + 1);
        for face in faces {
            let corner = |i: usize| {
                let count = corners.len();
                corners
                    .get(i)
                    .copied()
                    .ok_or_else(|| format!("{mesh}: vertex index {i} is out of range ({count} vertices)"))
            };
            self.triangles.push((group, [corner(face[0])?, corner(face[1])?, corner(face[2])?]));
        }
        Ok(())
    }
}

/// The node's own transform, in double precision (a rotation's quaternion normalized there).
fn local(node: &Node) -> DMat4 {
    match node.transform() {
        Transform::Matrix { matrix } => DMat4::from_cols_array_2d(&matrix.map(|c| c.map(f64::from))),
        Transform::Decomposed { translation, rotation, scale } => {
            let turn = DQuat::from_array(rotation.map(f64::from));
            let turn = if turn.length() > 0.0 { turn.normalize() } else { turn };
            let (scale, translation) = (DVec3::from(scale.map(f64::from)), DVec3::from(translation.map(f64::from)));
            DMat4::from_scale_rotation_translation(scale, turn, translation)
        }
    }
}

/// `mesh "NAME" (#m), primitive #p of the glTF file FILE`, for messages.
fn primitive_name(file: &Path, mesh: &Mesh, primitive: &Primitive) -> String {
    let name = mesh.name().map_or(String::new(), |n| format!("\"{n}\" "));
    let (m, p) = (mesh.index(), primitive.index());
    format!("mesh {name}(#{m}), primitive #{p} of the glTF file {}", file.display())
}

/// Whether an accessor can be read as `types` of `dimensions`: the reader of the `gltf`
/// crate reads the bytes as the type asked for and takes `count ≥ 1` for granted.
fn readable(accessor: &Accessor, types: &[DataType], dimensions: Dimensions) -> Result<(), String> {
    if !types.contains(&accessor.data_type()) || accessor.dimensions() != dimensions {
        let (t, d) = (accessor.data_type(), accessor.dimensions());
        return Err(format!("is {t:?} {d:?}, not {types:?} {dimensions:?}"));
    }
    if accessor.count() == 0 || accessor.sparse().is_some_and(|s| s.count() == 0) {
        return Err("has no elements".to_string());
    }
    if accessor.view().and_then(|v| v.stride()).is_some_and(|s| s < accessor.size()) {
        return Err(format!("has a byteStride shorter than its elements ({} bytes)", accessor.size()));
    }
    Ok(())
}
