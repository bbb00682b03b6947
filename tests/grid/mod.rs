//! Illuminance grids: the gathered illuminance under a Lambertian rectangle against the
//! closed-form point-to-rectangle factor, the statistics, and `ugo solve` writing the
//! CSVs (grid and probes) and the map.

mod points;

use crate::support::{build, corner_factor, lambert, rectangle, scene, scratch, solve, surface, ugo};
use glam::DVec3;
use std::f64::consts::PI;
use ugo::geometry::Emission;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::grid::GridReading;
use ugo::scene::Grid;

/// `E = π L F` at `(x, 0, z)` facing up under the rectangle `[x0, x1] × [z0, z1]` at
/// height `h` (superposition of the four corner factors, docs/references.md item 1).
fn exact(l: f64, (x0, x1): (f64, f64), (z0, z1): (f64, f64), h: f64, x: f64, z: f64) -> f64 {
    let f = |a: f64, b: f64| a.signum() * b.signum() * corner_factor(a.abs(), b.abs(), h);
    let factor = f(x1 - x, z1 - z) - f(x0 - x, z1 - z) - f(x1 - x, z0 - z) + f(x0 - x, z0 - z);
    PI * l * factor
}

/// A 1 × 1 m lamp of 1000 cd/m² at height 1 m facing down, over a black floor when `floor`.
fn lamp_scene(floor: bool) -> ugo::scene::Scene {
    let lamp = rectangle([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let mut surfaces = vec![surface("lamp", lamp, 0, false, Some(Emission::Luminance(1000.0)))];
    if floor {
        surfaces.push(surface("floor", rectangle([-1.0, 0.0, -1.0], [0.0, 0.0, 3.0], [3.0, 0.0, 0.0]), 0, false, None));
    }
    scene(vec![lambert("black", 0.0)], surfaces, 0.25)
}

fn grid(y: f64) -> Grid {
    Grid {
        name: "floor".into(),
        origin: DVec3::new(-0.5, y, -0.5),
        edge_u: DVec3::new(2.0, 0.0, 0.0),
        edge_v: DVec3::new(0.0, 0.0, 2.0),
        normal: DVec3::Y,
        resolution: [5, 4],
        map: Default::default(),
        target: Default::default(),
    }
}

fn check_against_closed_form(floor: bool) {
    let scene = lamp_scene(floor);
    let model = build(&scene);
    let field = Field::from_unknowns(&solve(&model), 1);
    let reading = GridReading::of(&grid(0.0), &model, &field, &Silent);
    assert_eq!(reading.points.len(), 20);
    for (p, e) in reading.points.iter().zip(&reading.illuminance) {
        let reference = exact(1000.0, (0.0, 1.0), (0.0, 1.0), 1.0, p.x, p.z);
        assert!((e / reference - 1.0).abs() < 1e-2, "at {p}: {e} lx, closed form {reference} lx");
        assert!((e / reference - 1.0).abs() < 1e-3, "at {p}: {e} lx, closed form {reference} lx (0.1 %)");
    }
    let st = reading.stats();
    let mean = reading.illuminance.iter().sum::<f64>() / 20.0;
    assert!((st.average - mean).abs() < 1e-12 * mean);
    let min = reading.illuminance.iter().copied().fold(f64::INFINITY, f64::min);
    assert_eq!(st.min, min);
    assert!((st.u0 - min / mean).abs() < 1e-12 && st.max > st.average && st.average > st.min);
}

#[test]
fn grid_in_free_space_matches_the_closed_form_under_a_lambertian_rectangle() {
    check_against_closed_form(false);
}

#[test]
fn grid_on_a_floor_matches_the_closed_form_under_a_lambertian_rectangle() {
    check_against_closed_form(true);
}

#[test]
fn grid_points_are_cell_centres_row_by_row() {
    let points = grid(0.25).points();
    assert_eq!(points.len(), 20);
    let expected =
        [(0, [-0.3, 0.25, -0.25]), (1, [0.1, 0.25, -0.25]), (5, [-0.3, 0.25, 0.25]), (19, [1.3, 0.25, 1.25])];
    for (i, p) in expected {
        assert!(points[i].distance(DVec3::from(p)) < 1e-12, "point {i}: {}", points[i]);
    }
}

const CASE: &str = r#"
[discretization]
patch_size = 0.25

[[material]]
name = "white"
type = "lambert"
reflectance = 0.5

[[surface]]
name = "lamp"
shape = "rectangle"
origin = [0.0, 1.0, 0.0]
edge_u = [1.0, 0.0, 0.0]
edge_v = [0.0, 0.0, 1.0]
material = "white"
emission = { luminance = 1000.0 }

[[grid]]
name = "work plane"
origin = [-0.5, 0.0, -0.5]
edge_u = [2.0, 0.0, 0.0]
edge_v = [0.0, 0.0, 2.0]
resolution = [6, 3]
normal = [0.0, 1.0, 0.0]

[[probe]]
name = "under a corner"
position = [1.0, 0.0, 1.0]
normal = [0.0, 1.0, 0.0]
"#;

#[test]
fn solve_writes_each_grid_as_csv_and_a_map_in_lux() {
    let dir = scratch("grid-cli");
    let case = dir.join("lamp.toml");
    std::fs::write(&case, CASE).unwrap();
    let h5 = dir.join("lamp.h5");
    let o = ugo(&["solve", case.to_str().unwrap(), "-o", h5.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{out}");
    assert!(out.contains("E_avg lx") && out.contains("work plane"), "{out}");
    let csv = std::fs::read_to_string(dir.join("lamp-work_plane.csv")).unwrap();
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('u'))
        .map(|l| l.split(',').take(8).map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 18);
    for r in &rows {
        let reference = exact(1000.0, (0.0, 1.0), (0.0, 1.0), 1.0, r[2], r[4]);
        assert!((r[5] / reference - 1.0).abs() < 1e-2, "{r:?}: closed form {reference}");
    }
    assert!(csv.contains("# E_avg") && csv.contains(" ± ") && csv.contains("U0"), "{csv}");
    assert!(rows.iter().all(|r| r[7] == 1.0) && csv.contains("u,v,x,y,z,E_lx,E_error_lx,counted,left_out_by"), "{csv}");
    // Nothing but the lamp, which nothing lights: one more bounce changes nothing, no bar.
    assert!(rows.iter().all(|r| (0.0..1e-6 * r[5]).contains(&r[6])), "bars on an exact field: {csv}");
    let map = image::open(dir.join("lamp-work_plane.png")).unwrap();
    assert!(map.width() > 400 && map.height() >= 240);
    let probes = std::fs::read_to_string(dir.join("lamp-probes.csv")).unwrap();
    let probe: Vec<&str> = probes.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(probe[0], "\"under a corner\"");
    let e: f64 = probe[8].parse().unwrap();
    assert!((e / (PI * 1000.0 * corner_factor(1.0, 1.0, 1.0)) - 1.0).abs() < 1e-3, "{probes}");
    let file = hdf5::File::open(&h5).unwrap();
    let e = file.dataset("grids/work plane/illuminance").unwrap().read_2d::<f64>().unwrap();
    assert_eq!(e.shape(), [3, 6]);
    let counted = file.dataset("grids/work plane/counted").unwrap().read_2d::<u8>().unwrap();
    assert!(counted.shape() == [3, 6] && counted.iter().all(|&c| c == 1));
    let avg: f64 = file.group("grids/work plane").unwrap().attr("E_avg").unwrap().read_scalar().unwrap();
    assert!((avg - rows.iter().map(|r| r[5]).sum::<f64>() / 18.0).abs() < 1e-6 * avg);
    let error = file.dataset("grids/work plane/error").unwrap().read_2d::<f64>().unwrap();
    assert!(error.shape() == [3, 6] && error.iter().zip(&rows).all(|(&d, r)| (d - r[6]).abs() <= 1e-3 * d));
    let avg_bar: f64 = file.group("grids/work plane").unwrap().attr("E_avg_error").unwrap().read_scalar().unwrap();
    assert!((avg_bar - error.iter().sum::<f64>() / 18.0).abs() < 1e-9 * avg, "E_avg's bar is the points' mean bar");
    assert!(out.contains(&format!("{avg:.4} ± ")), "{out}");
}
