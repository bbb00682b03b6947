//! Pixels of scenes whose answer is known: a directly seen emitter shows its luminance,
//! the back of a one-sided surface is black, a miss is 0 cd/m², and the white furnace
//! (solved by `ugo solve`) is 5 cd/m² everywhere.

use glam::DVec3;
use std::path::{Path, PathBuf};
use std::process::Command;
use ugo::directions::DirectionSet;
use ugo::geometry::Mesh;
use ugo::io::read_solution;
use ugo::render::{LitScene, render};
use ugo::scene::{Camera, Scene};

fn camera(position: [f64; 3], look_at: [f64; 3], fov_deg: f64, size: usize) -> Camera {
    Camera {
        name: "test".into(),
        position: DVec3::from_array(position),
        look_at: DVec3::from_array(look_at),
        up: DVec3::Y,
        fov_deg,
        resolution: [size, size],
        samples: 4,
    }
}

/// A 1 m square in the plane z = 0 facing +z, emitting 7 cd/m², not reflecting.
fn emitter(two_sided: bool) -> LitScene {
    let text = format!(
        "[discretization]\npatch_size = 0.25\n[[material]]\nname = \"black\"\ntype = \"lambert\"\n\
         reflectance = 0.0\n[[surface]]\nname = \"lamp\"\nshape = \"rectangle\"\nmaterial = \"black\"\n\
         origin = [-0.5, -0.5, 0.0]\nedge_u = [1.0, 0.0, 0.0]\nedge_v = [0.0, 1.0, 0.0]\n\
         two_sided = {two_sided}\nemission = {{ luminance = 7.0 }}\n"
    );
    let scene = Scene::parse(Path::new("lamp.toml"), text).expect("valid scene");
    let mesh = Mesh::build(&scene, 0.25);
    let luminance = mesh.emission.clone();
    LitScene::new(mesh, DirectionSet::single(), luminance)
}

#[test]
fn a_directly_seen_emitter_shows_its_luminance_and_a_miss_is_black() {
    let image = render(&emitter(false), &camera([0.0, 0.0, 2.0], [0.0, 0.0, 0.0], 60.0, 32));
    let at = |x: usize, y: usize| image.luminance[y * image.width + x];
    // The square spans tan⁻¹(0.25) ≈ 14° of the 30° half field: the centre 12×12 pixels see it.
    for y in 10..22 {
        for x in 10..22 {
            assert_eq!(at(x, y), 7.0, "pixel ({x}, {y})");
        }
    }
    assert_eq!(at(0, 0), 0.0);
    assert_eq!(at(31, 31), 0.0);
}

#[test]
fn the_back_of_a_one_sided_surface_is_black_and_of_a_two_sided_one_is_lit() {
    let behind = camera([0.0, 0.0, -2.0], [0.0, 0.0, 0.0], 30.0, 8);
    assert!(render(&emitter(false), &behind).luminance.iter().all(|&l| l == 0.0));
    let image = render(&emitter(true), &behind);
    assert_eq!(image.luminance[4 * 8 + 4], 7.0);
}

#[test]
fn the_furnace_box_renders_five_candela_per_square_metre_everywhere() {
    let dir = std::env::temp_dir().join(format!("ugo-render-{}-furnace", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out: PathBuf = dir.join("furnace.h5");
    let o = Command::new(env!("CARGO_BIN_EXE_ugo"))
        .args(["solve", "cases/furnace-box.toml", "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stored = read_solution(&out).unwrap();
    let camera = stored.scene.cameras[0].clone();
    assert_eq!(camera.name, "inside");
    let lit = LitScene::new(stored.mesh, stored.directions, stored.luminance);
    let image = render(&lit, &camera);
    assert_eq!(image.luminance.len(), 32 * 32);
    for l in &image.luminance {
        assert!((l - 5.0).abs() < 1e-6, "pixel luminance {l}");
    }
}

/// A two-sided grey plate under a lamp, with a camera below it.
const TWO_SIDED: &str = r#"
[discretization]
patch_size = 0.25
[[material]]
name = "grey"
type = "lambert"
reflectance = 0.5
[[surface]]
name = "plate"
shape = "rectangle"
material = "grey"
origin = [-0.5, 0.0, -0.5]
edge_u = [0.0, 0.0, 1.0]
edge_v = [1.0, 0.0, 0.0]
two_sided = true
[[surface]]
name = "lamp"
shape = "rectangle"
material = "grey"
origin = [-0.5, 1.0, -0.5]
edge_u = [1.0, 0.0, 0.0]
edge_v = [0.0, 0.0, 1.0]
emission = { luminance = 100.0 }
[[camera]]
name = "below"
position = [0.0, -1.0, 0.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 0.0, 1.0]
fov_deg = 20
resolution = [8, 8]
"#;

#[test]
fn files_without_face_records_pair_back_to_back_twins() {
    let dir = std::env::temp_dir().join(format!("ugo-render-{}-twins", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let case = dir.join("plate.toml");
    std::fs::write(&case, TWO_SIDED).unwrap();
    let out = dir.join("plate.h5");
    let o = Command::new(env!("CARGO_BIN_EXE_ugo"))
        .args(["solve", case.to_str().unwrap(), "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stored = read_solution(&out).unwrap();
    let links = |m: &Mesh| m.patches.iter().map(|p| (p.face, p.twin)).collect::<Vec<_>>();
    let recorded = links(&stored.mesh);
    assert!(recorded.iter().any(|&(_, twin)| twin != ugo::geometry::NO_TWIN));
    {
        let file = hdf5::File::open_rw(&out).unwrap();
        file.unlink("mesh/face").unwrap();
        file.unlink("mesh/twin").unwrap();
    }
    let paired = read_solution(&out).unwrap();
    assert_eq!(links(&paired.mesh), recorded);

    // From below, the plate's lower twin is seen: lit only by what the plate transmits (nothing).
    let lit = LitScene::new(stored.mesh, stored.directions, stored.luminance);
    let image = render(&lit, &stored.scene.cameras[0]);
    assert!(image.luminance.iter().all(|&l| l == 0.0), "{:?}", image.luminance);
}
