//! Scenes built in code for the tests (no case file involved).

pub mod gltf;

use glam::DVec3;
use std::ops::Deref;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use ugo::directions::{DirectionSet, Scheme};
use ugo::geometry::{Emission, Shape, Surface};
use ugo::kernel::Factored;
use ugo::material::MaterialModel;
use ugo::model::Model;
use ugo::scene::{Asked, Discretization, Given, Material, Scene, SolverSettings};
use ugo::solve::{SolveParams, successive_approximation};

pub fn lambert(name: &str, reflectance: f64) -> Material {
    Material { name: name.into(), model: MaterialModel::Lambert { reflectance, transmittance: 0.0 } }
}

pub fn surface(name: &str, shape: Shape, material: usize, inside: bool, emission: Option<Emission>) -> Surface {
    Surface { name: name.into(), shape, material, two_sided: false, inside, emission }
}

pub fn scene(materials: Vec<Material>, surfaces: Vec<Surface>, patch_size: f64) -> Scene {
    Scene {
        path: PathBuf::from("test.toml"),
        source: String::new(),
        name: "test".into(),
        description: String::new(),
        asked: Asked { patch_size: Some(Given::key("patch_size")(patch_size)), ..Asked::default() },
        discretization: Discretization::uniform(patch_size),
        old_spelling: Vec::new(),
        solver: SolverSettings::default(),
        materials,
        file_warnings: Vec::new(),
        surfaces,
        probes: Vec::new(),
        observers: Vec::new(),
        glare_grids: Vec::new(),
        cameras: Vec::new(),
        grids: Vec::new(),
        luminaires: Vec::new(),
        sky: None,
        lighting: ugo::scene::Lighting::default(),
        files: Vec::new(),
    }
}

/// A closed cube of side `side` seen from inside, every face emitting `luminance`.
pub fn furnace(side: f64, reflectance: f64, luminance: f64, patch_size: f64) -> Scene {
    let shape = Shape::Box { min: DVec3::ZERO, max: DVec3::splat(side), rotate_y_deg: 0.0 };
    scene(
        vec![lambert("grey", reflectance)],
        vec![surface("room", shape, 0, true, Some(Emission::Luminance(luminance)))],
        patch_size,
    )
}

/// The furnace cube (`ρ = 0.8`, emitting 1 cd/m², `patch_size` m patches) with an emitting
/// block of the same reflectance standing on its floor, rotated 20° off the patches' grid.
pub fn furnace_with_standing_block(patch_size: f64) -> Scene {
    let mut scene = furnace(1.0, 0.8, 1.0, patch_size);
    scene.materials.push(lambert("block", 0.8));
    let block = Shape::Box { min: DVec3::new(0.3, 0.0, 0.35), max: DVec3::new(0.65, 0.3, 0.62), rotate_y_deg: 20.0 };
    scene.surfaces.push(surface("block", block, 1, false, Some(Emission::Luminance(1.0))));
    scene
}

pub fn build(scene: &Scene) -> Model {
    Model::build(scene, &ugo::progress::Silent).expect("model fits in memory")
}

/// The model of `scene` with another direction set (one of the schemes a case can name).
pub fn build_with(scene: &Scene, directions: DirectionSet) -> Model {
    let scheme = Scheme::parse(directions.name()).expect("a set a case can name");
    let mut scene = scene.clone();
    scene.discretization.directions = scheme;
    let model = Model::build(&scene, &ugo::progress::Silent).expect("model fits in memory");
    assert_eq!(model.kernel.directions.name(), directions.name());
    model
}

/// A closed cube of `material`, every face emitting `luminance`.
pub fn furnace_of(material: MaterialModel, luminance: f64, patch_size: f64) -> Scene {
    let mut s = furnace(1.0, 0.5, luminance, patch_size);
    s.materials[0].model = material;
    s
}

pub fn material(name: &str, model: MaterialModel) -> Material {
    Material { name: name.into(), model }
}

/// The parallelogram `origin + s·u + t·v`, facing `u × v`.
pub fn rectangle(origin: [f64; 3], u: [f64; 3], v: [f64; 3]) -> Shape {
    Shape::Rectangle { origin: DVec3::from(origin), edge_u: DVec3::from(u), edge_v: DVec3::from(v) }
}

/// `x = L0 + K x` by successive approximation to a relative residual of 1e-10.
pub fn solve(model: &Model) -> Vec<f64> {
    let params = SolveParams { tolerance: 1e-10, max_iterations: 10_000, ..SolveParams::default() };
    successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {}).expect("converges").0
}

/// `G x`: the light arriving at every (patch, cell); `E_i = π Σ_d (G x)_{i,d}`.
pub fn arriving(model: &Model, x: &[f64]) -> Vec<f64> {
    let mut gx = vec![0.0; x.len()];
    model.kernel.apply_transport(x, &mut gx);
    gx
}

/// Differential element to a parallel rectangle `a × b` at distance `c` with a corner
/// over the element (docs/references.md, configuration factors item 1).
pub fn corner_factor(a: f64, b: f64, c: f64) -> f64 {
    let (x, y) = (a / c, b / c);
    let (sx, sy) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
    (x / sx * (y / sx).atan() + y / sy * (x / sy).atan()) / (2.0 * std::f64::consts::PI)
}

/// Nodes and weights of the 4-point Gauss–Legendre rule on [−1, 1].
const GAUSS_4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// Mean of `f(s, t)` over `[s0, s1] × [t0, t1]`: 4-point Gauss–Legendre on an `n × n` grid.
pub fn mean_over(s: (f64, f64), t: (f64, f64), n: usize, f: impl Fn(f64, f64) -> f64) -> f64 {
    let (hs, ht) = ((s.1 - s.0) / n as f64, (t.1 - t.0) / n as f64);
    let mut sum = 0.0;
    for a in 0..n {
        for b in 0..n {
            for (u, wu) in GAUSS_4 {
                for (v, wv) in GAUSS_4 {
                    let x = s.0 + hs * (a as f64 + 0.5 + 0.5 * u);
                    let y = t.0 + ht * (b as f64 + 0.5 + 0.5 * v);
                    sum += 0.25 * wu * wv * f(x, y);
                }
            }
        }
    }
    sum / (n * n) as f64
}

/// Runs the `ugo` binary.
pub fn ugo(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_ugo")).args(args).output().expect("ugo runs")
}

/// A scratch folder for one test, `ugo-test-<pid>-<n>-<name>` under the system temp dir.
///
/// It owns the folder and everything written into it, and removes them when dropped: keep
/// it bound to a variable for as long as the folder is used. The process id and a count
/// of the calls make it unique, so tests running in parallel threads never share one.
pub struct Scratch(PathBuf);

impl Scratch {
    /// Writes `text` to `file` in the folder and returns the file's path.
    pub fn write(&self, file: &str, text: &str) -> PathBuf {
        let path = self.0.join(file);
        std::fs::write(&path, text).expect("write scratch file");
        path
    }
}

impl Deref for Scratch {
    type Target = Path;

    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A fresh, empty scratch folder for one test, removed when the guard is dropped.
pub fn scratch(name: &str) -> Scratch {
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let count = COUNT.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("ugo-test-{}-{count}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temporary folder");
    Scratch(dir)
}

/// `Σ f(l, dω)` over the `m × m` midpoint grid of the parallelogram `o + s·u + t·v` seen
/// from `p`: `l` the unit direction to a piece's centre, `dω` the piece's solid angle.
pub fn over_parallelogram(o: DVec3, u: DVec3, v: DVec3, p: DVec3, m: usize, f: impl Fn(DVec3, f64) -> f64) -> f64 {
    let normal = u.cross(v).normalize();
    let area = u.cross(v).length() / (m * m) as f64;
    let mut sum = 0.0;
    for i in 0..m {
        for j in 0..m {
            let x = o + u * ((i as f64 + 0.5) / m as f64) + v * ((j as f64 + 0.5) / m as f64);
            let r = x - p;
            let l = r.normalize();
            sum += f(l, area * l.dot(normal).abs() / r.length_squared());
        }
    }
    sum
}
