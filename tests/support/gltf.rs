//! Small glTF 2.0 files written by the tests (issue 38, point 4): one buffer of `f32`
//! positions then `u32` indices, each index list a primitive's accessor, then optionally
//! an image (buffer view 2), around the JSON the test gives (nodes, meshes, materials,
//! scenes, images); written as a `.gltf` with the buffer embedded in base64, as a `.glb`,
//! or as a `.gltf` beside its `.bin`.

use base64::Engine;
use serde_json::{Value, json};

/// The eight corners of the unit cube, corner `x + 2y + 4z` at `(x, y, z)`.
pub fn cube_corners() -> Vec<[f32; 3]> {
    (0..8).map(|i| [(i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32]).collect()
}

/// The unit cube's twelve triangles, counter-clockwise seen from outside: −z, +z, −x, +x, −y, +y.
pub fn cube_triangles() -> Vec<u32> {
    let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3]];
    quads.iter().flat_map(|[a, b, c, d]| [*a, *b, *c, *a, *c, *d]).collect()
}

/// The same cube as OBJ text (faces in the same order).
pub fn cube_obj() -> String {
    let corners = cube_corners().iter().map(|[x, y, z]| format!("v {x} {y} {z}\n")).collect::<String>();
    let triangles = cube_triangles();
    let faces = triangles.chunks(3).map(|t| format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1));
    corners + &faces.collect::<String>()
}

/// A glTF document: `positions` are accessor 0; index list `i` of `indices` is accessor
/// `i + 1`; `image`, when not empty, is buffer view 2 (an image's `bufferView`); `document`
/// holds the rest (`scene`, `scenes`, `nodes`, `meshes`, `materials`, `textures`, `images`).
pub struct Document {
    pub positions: Vec<[f32; 3]>,
    pub indices: Vec<Vec<u32>>,
    pub image: Vec<u8>,
    pub document: Value,
}

impl Document {
    /// The buffer: positions, then every index list, then the image.
    fn bin(&self) -> Vec<u8> {
        let floats = self.positions.iter().flatten().flat_map(|x| x.to_le_bytes());
        let indices = self.indices.iter().flatten().flat_map(|i| i.to_le_bytes());
        floats.chain(indices).chain(self.image.iter().copied()).collect()
    }

    /// The whole JSON, its one buffer described by `buffer`.
    fn json(&self, buffer: Value) -> Value {
        let position_bytes = 12 * self.positions.len();
        let axis = |f: fn(f32, f32) -> f32| (0..3).map(|a| self.positions.iter().map(|p| p[a]).reduce(f)).collect();
        let (min, max): (Vec<_>, Vec<_>) = (axis(f32::min), axis(f32::max));
        let mut accessors = vec![json!({ "bufferView": 0, "componentType": 5126, "count": self.positions.len(),
                                         "type": "VEC3", "min": min, "max": max })];
        let mut offset = 0;
        for list in &self.indices {
            accessors.push(json!({ "bufferView": 1, "byteOffset": offset, "componentType": 5125,
                                   "count": list.len(), "type": "SCALAR" }));
            offset += 4 * list.len();
        }
        let mut whole = self.document.clone();
        whole["asset"] = json!({ "version": "2.0" });
        whole["buffers"] = json!([buffer]);
        whole["bufferViews"] = json!([
            { "buffer": 0, "byteOffset": 0, "byteLength": position_bytes },
            { "buffer": 0, "byteOffset": position_bytes, "byteLength": offset },
        ]);
        if !self.image.is_empty() {
            let view = json!({ "buffer": 0, "byteOffset": position_bytes + offset, "byteLength": self.image.len() });
            whole["bufferViews"].as_array_mut().unwrap().push(view);
        }
        whole["accessors"] = json!(accessors);
        whole
    }

    /// A `.gltf` whose buffer is a base64 `data:` URI.
    pub fn embedded(&self) -> String {
        let bin = self.bin();
        let uri =
            format!("data:application/octet-stream;base64,{}", base64::engine::general_purpose::STANDARD.encode(&bin));
        self.json(json!({ "byteLength": bin.len(), "uri": uri })).to_string()
    }

    /// A `.gltf` naming its buffer `bin_name`, and the bytes of that file.
    pub fn external(&self, bin_name: &str) -> (String, Vec<u8>) {
        let bin = self.bin();
        (self.json(json!({ "byteLength": bin.len(), "uri": bin_name })).to_string(), bin)
    }

    /// A `.glb`: the JSON chunk and the binary chunk, each padded to four bytes.
    pub fn binary(&self) -> Vec<u8> {
        let bin = self.bin();
        let mut text = self.json(json!({ "byteLength": bin.len() })).to_string().into_bytes();
        text.resize(text.len().div_ceil(4) * 4, b' ');
        let mut data = bin;
        data.resize(data.len().div_ceil(4) * 4, 0);
        let length = 12 + 8 + text.len() + 8 + data.len();
        let mut glb = Vec::new();
        for word in [0x4654_6C67, 2, length as u32, text.len() as u32, 0x4E4F_534A] {
            glb.extend_from_slice(&u32::to_le_bytes(word));
        }
        glb.extend_from_slice(&text);
        glb.extend_from_slice(&(data.len() as u32).to_le_bytes());
        glb.extend_from_slice(&0x004E_4942u32.to_le_bytes());
        glb.extend_from_slice(&data);
        glb
    }
}
