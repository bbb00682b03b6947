//! glTF base colour textures (issue 38, point 4): an unmapped material reflects the
//! luminance of its `baseColorFactor` times the mean linear colour of its texture's texels
//! (sRGB decoded, alpha ignored), whether the PNG lies beside the file, in a `data:` URI or
//! in a `.glb`'s buffer view, a JPEG too; it is said once per material, with the mean; a
//! mapped material's texture is not read; an image that cannot be read is an error naming
//! the file, the material and the image.

use super::gltf::{CHAIR, load, painted};
use crate::support::gltf::Document;
use crate::support::scratch;
use base64::Engine;
use image::{ImageFormat, RgbaImage};
use serde_json::{Value, json};
use std::io::Cursor;
use ugo::material::MaterialModel;
use ugo::scene::Scene;

/// The 2 × 2 texels, sRGB-encoded, the second transparent (its alpha is ignored).
const TEXELS: [[u8; 4]; 4] = [[255, 0, 0, 255], [0, 128, 255, 0], [64, 64, 64, 255], [200, 100, 50, 128]];

fn png() -> Vec<u8> {
    let picture = RgbaImage::from_fn(2, 2, |x, y| image::Rgba(TEXELS[(2 * y + x) as usize]));
    let mut bytes = Cursor::new(Vec::new());
    picture.write_to(&mut bytes, ImageFormat::Png).unwrap();
    bytes.into_inner()
}

/// The sRGB transfer function inverted (IEC 61966-2-1), worked out here by hand.
fn linear(c: u8) -> f64 {
    let c = f64::from(c) / 255.0;
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

/// `paint` (base colour factor (0.75, 0.5, 0.25)) with a texture of the image `image`.
fn textured(image: Value) -> Document {
    let texture = json!({ "pbrMetallicRoughness":
                          { "baseColorFactor": [0.75, 0.5, 0.25, 1], "baseColorTexture": { "index": 0 } } });
    let mut document = painted(texture);
    document.document["textures"] = json!([{ "source": 0 }]);
    document.document["images"] = json!([image]);
    document
}

fn reflectance(scene: &Scene, surface: usize) -> f64 {
    match scene.materials[scene.surfaces[surface].material].model {
        MaterialModel::Lambert { reflectance, .. } => reflectance,
        ref other => panic!("{other:?}"),
    }
}

#[test]
fn a_base_colour_texture_is_averaged_to_its_mean_linear_colour() {
    let dir = scratch("gltf-texture");
    let mean = [0, 1, 2].map(|c| TEXELS.iter().map(|t| linear(t[c])).sum::<f64>() / 4.0);
    let colour = [0.75 * mean[0], 0.5 * mean[1], 0.25 * mean[2]];
    let expected = 0.2126 * colour[0] + 0.7152 * colour[1] + 0.0722 * colour[2];
    std::fs::write(dir.join("wood.png"), png()).unwrap();
    dir.write("beside.gltf", &textured(json!({ "uri": "wood.png" })).embedded());
    let uri = format!("data:image/png;base64,{}", base64::engine::general_purpose::STANDARD.encode(png()));
    dir.write("data.gltf", &textured(json!({ "uri": uri })).embedded());
    let mut glb = textured(json!({ "bufferView": 2, "mimeType": "image/png", "name": "grain" }));
    glb.image = png();
    std::fs::write(dir.join("box.glb"), glb.binary()).unwrap();
    for file in ["beside.gltf", "data.gltf", "box.glb"] {
        let scene = load(&dir, file, "").unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(scene.surfaces[1].name, format!("chair/{file}:paint"));
        let rho = reflectance(&scene, 1);
        assert!((rho - expected).abs() < 1e-15, "{file}: {rho} against {expected}");
        let notes: Vec<String> = scene.warnings().iter().map(|w| w.to_string()).collect();
        let said = |f: &str| notes.iter().filter(|n| n.contains(f)).count();
        assert_eq!(said("averaged to a uniform reflectance"), 1, "{file}: once, {notes:#?}");
        let figures = format!("[{:.4}, {:.4}, {:.4}]", mean[0], mean[1], mean[2]);
        let fragments = [file, "material \"paint\" (#0)", "image #0", &figures, &format!("ρ = {expected:.4}")];
        assert!(fragments.iter().all(|f| said(f) == 1), "{file}: {notes:#?}");
        assert!((reflectance(&scene, 2) - 0.5).abs() < 1e-15, "{file}: the untextured #1 keeps its factor");
    }
    let scene = load(&dir, "box.glb", "").unwrap();
    assert!(scene.warnings().iter().any(|w| w.message().contains("image #0 \"grain\" (buffer view #2)")));
    let scene = load(&dir, "beside.gltf", "").unwrap();
    let read: Vec<_> = scene.files.iter().map(|f| f.path.file_name().unwrap().to_string_lossy().into_owned()).collect();
    assert_eq!(read, ["beside.gltf", "wood.png"], "the image is kept with the case");
    // Mapped by `materials`, its texture is not read: a missing image is no error.
    dir.write("unread.gltf", &textured(json!({ "uri": "absent.png" })).embedded());
    let mapped = load(&dir, "unread.gltf", "materials = { paint = \"oak\" }").unwrap();
    assert_eq!(mapped.surfaces[1].name, "chair/oak");
    assert!(!mapped.warnings().iter().any(|w| w.message().contains("texture")));
}

#[test]
fn a_jpeg_texture_is_read() {
    let dir = scratch("gltf-jpeg");
    let grey = image::RgbImage::from_pixel(8, 8, image::Rgb([120, 120, 120]));
    grey.save_with_format(dir.join("grey.jpg"), ImageFormat::Jpeg).unwrap();
    dir.write("box.gltf", &textured(json!({ "uri": "grey.jpg" })).embedded());
    let scene = load(&dir, "box.gltf", "").unwrap();
    let expected = linear(120) * (0.2126 * 0.75 + 0.7152 * 0.5 + 0.0722 * 0.25);
    let rho = reflectance(&scene, 1);
    assert!((rho / expected - 1.0).abs() < 0.02, "{rho} against {expected} (a lossy grey)");
}

#[test]
fn an_image_that_cannot_be_read_is_an_error_naming_it() {
    let dir = scratch("gltf-texture-broken");
    dir.write("missing.gltf", &textured(json!({ "uri": "wood.png" })).embedded());
    dir.write("text.png", "not a picture");
    dir.write("text.gltf", &textured(json!({ "uri": "text.png" })).embedded());
    let mut dangling = textured(json!({ "uri": "wood.png" }));
    dangling.document["textures"] = json!([{ "source": 3 }]);
    dir.write("dangling.gltf", &dangling.embedded());
    for (file, fragments) in [
        (
            "missing.gltf",
            &["material \"paint\" (#0)", "image #0 (wood.png) of its base colour texture", "cannot open"][..],
        ),
        ("text.gltf", &["material \"paint\" (#0)", "image #0 (text.png)", "cannot decode it as PNG or JPEG"]),
        ("dangling.gltf", &["cannot read the glTF file", "textures[0].source: Index out of bounds"]),
    ] {
        let error = load(&dir, file, "").unwrap_err();
        assert_eq!((error.table(), error.key()), (CHAIR, "file"), "{error}");
        assert!(error.message().contains(file), "{error}");
        assert!(fragments.iter().all(|f| error.message().contains(f)), "{file}: {error}");
    }
}
