//! Light scenes end to end: `ugo solve` writes `/light_groups` and `/light_scenes/NAME`
//! (each light scene the weighted sum of the group fields) and each scene's CSV files,
//! `ugo render --light-scene NAME` draws it into files named after it, and an unknown
//! light scene is a clean error that lists the known ones.

use super::{assert_clean_failure, stderr};
use crate::support::{scratch, ugo};

/// A grey box lit by a ceiling disc (group "ceiling") and a bulb (no group), a probe, a
/// grid, a small camera and two light scenes.
pub(super) const CASE: &str = r#"
[discretization]
patch_size = 0.5

[solver]
method = "gmres"
tolerance = 1e-10

[[material]]
name = "grey"
type = "lambert"
reflectance = 0.5

[[surface]]
name = "room"
shape = "box"
material = "grey"
inside = true
min = [0, 0, 0]
max = [2, 2, 2]

[[surface]]
name = "lamp"
shape = "disc"
material = "grey"
center = [1, 1.99, 1]
normal = [0, -1, 0]
radius = 0.3
emission = { flux = 300 }
group = "ceiling"

[[luminaire]]
name = "bulb"
type = "isotropic"
flux = 500
position = [0.5, 1.5, 0.5]

[[probe]]
name = "floor"
position = [1, 0, 1]
normal = [0, 1, 0]

[[grid]]
name = "desk"
origin = [0.2, 0.7, 0.2]
edge_u = [1.6, 0, 0]
edge_v = [0, 0, 1.6]
resolution = [4, 4]

[[camera]]
name = "eye"
position = [1, 1, 1.9]
look_at = [1, 1, 0]
resolution = [16, 16]
samples = 1

[[light_scene]]
name = "night"
groups = { default = 0.25 }

[[light_scene]]
name = "full"
groups = { default = 1, ceiling = true }
"#;

#[test]
fn light_scenes_are_written_read_back_and_rendered_by_name() {
    let dir = scratch("light-scenes");
    let case = dir.join("box.toml");
    std::fs::write(&case, CASE).unwrap();
    let out = dir.join("box.h5");
    let o = ugo(&["solve", case.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let summary = String::from_utf8_lossy(&o.stdout);
    assert!(summary.contains("light scene \"night\"") && summary.contains("light groups"), "{summary}");
    for name in ["box-night-probes.csv", "box-night-desk.csv", "box-night-desk.png", "box-full-probes.csv"] {
        assert!(dir.join(name).exists(), "{name} is missing:\n{summary}");
    }

    let file = hdf5::File::open(&out).unwrap();
    let read = |name: &str| file.dataset(name).unwrap().read_raw::<f64>().unwrap();
    let groups = read("light_groups/luminance");
    let factors = read("light_groups/factors");
    let (count, n) = (factors.len() / 2, read("field/luminance").len());
    assert_eq!((count, groups.len()), (2, 2 * n));
    for (s, name) in ["night", "full"].iter().enumerate() {
        let field = read(&format!("light_scenes/{name}/field/luminance"));
        for i in 0..n {
            let sum: f64 = (0..count).map(|g| factors[s * count + g] * groups[g * n + i]).sum();
            assert!((field[i] - sum).abs() <= 1e-12 * sum.abs(), "{name}: patch {i}: {} against {sum}", field[i]);
        }
        let probe = read(&format!("light_scenes/{name}/probes/illuminance"));
        assert!(probe[0] > 0.0, "{name}");
    }
    // All on at factor 1 is the case's own field, to the solves' tolerance.
    let (full, own) = (read("light_scenes/full/field/luminance"), read("field/luminance"));
    assert!(full.iter().zip(&own).all(|(a, b)| (a - b).abs() <= 1e-8 * b), "full against the case's field");
    let night = read("light_scenes/night/probes/illuminance")[0];
    let full = read("light_scenes/full/probes/illuminance")[0];
    assert!(night < full, "{night} against {full}");

    let o = ugo(&["render", out.to_str().unwrap(), "--light-scene", "night", "-o", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("box-night-eye-flat.png").exists() && dir.join("box-night-eye-flat.exr").exists());
    let err = assert_clean_failure(&ugo(&["render", out.to_str().unwrap(), "--light-scene", "nigth"]));
    assert!(err.contains("no light scene \"nigth\"") && err.contains("\"night\", \"full\""), "{err}");
    let err = assert_clean_failure(&ugo(&["render", out.to_str().unwrap(), "--light-scene", "night", "--orders", "1"]));
    assert!(err.contains("--orders"), "{err}");
}
