//! Grid plans (issue 17, item 1): seen from the side the normal points to, never mirrored
//! (a bright cell lands in the quadrant where a viewer on that side sees it), with the
//! map's options read from the case.

use crate::support::scratch;
use glam::DVec3;
use std::path::Path;
use ugo::io::{GridPlan, Overlay, colour, write_grid_map};
use ugo::readout::grid::GridReading;
use ugo::scene::{Grid, MapScale, MapStyle, Scene, Target};

/// A grid of 8 × 4 cells over `origin + s·edge_u + t·edge_v`, dark but for the cell
/// `(i, j)` of 100 lx.
pub(super) fn reading(edge_u: DVec3, edge_v: DVec3, normal: DVec3, (i, j): (usize, usize)) -> GridReading {
    let grid = Grid {
        name: "g".into(),
        origin: DVec3::ZERO,
        edge_u,
        edge_v,
        normal,
        resolution: [8, 4],
        map: MapStyle::default(),
        target: Target::default(),
    };
    let points = grid.points();
    let mut illuminance = vec![10.0; 32];
    illuminance[j * 8 + i] = 100.0;
    GridReading { grid, points, illuminance, direct: vec![0.0; 32], obstructed: vec![None; 32] }
}

/// Where the brightest cell is drawn, relative to the plot's centre: (+1 right, +1 up).
fn bright_quadrant(g: &GridReading, name: &str) -> (f64, f64) {
    let dir = scratch("grid-plans");
    let path = dir.join(format!("{name}.png"));
    write_grid_map(&path, g, &Overlay::default()).unwrap();
    let plan = GridPlan::of(g, &[]);
    let png = image::open(&path).unwrap().to_rgb8();
    assert_eq!((png.width(), png.height()), plan.size);
    let top = colour(1.0);
    let [left, upper, right, lower] = plan.layout.plot;
    let hits: Vec<(f64, f64)> = (upper..lower)
        .flat_map(|y| (left..right).map(move |x| (x, y)))
        .filter(|&(x, y)| png.get_pixel(x as u32, y as u32).0 == [top.0, top.1, top.2])
        .map(|(x, y)| (x as f64, y as f64))
        .collect();
    assert!(!hits.is_empty(), "{name}: no pixel of the top colour in {}", Path::new(&path).display());
    let n = hits.len() as f64;
    let (cx, cy) = (hits.iter().map(|h| h.0).sum::<f64>() / n, hits.iter().map(|h| h.1).sum::<f64>() / n);
    let (mx, my) = ((left + right) as f64 / 2.0, (upper + lower) as f64 / 2.0);
    ((cx - mx).signum(), (my - cy).signum())
}

#[test]
fn a_floor_is_drawn_as_its_plan_seen_from_above_and_a_ceiling_from_below() {
    // The bright cell lies at large x (3.5 to 4 m) and small z (0 to 0.5 m).
    let (x, z) = (DVec3::new(4.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 2.0));
    // From above (+y) in a y-up world, x runs right and z down the page: upper right. The
    // grid's own edges (x × z = −y) would mirror it; the normal decides.
    assert_eq!(bright_quadrant(&reading(x, z, DVec3::Y, (7, 0)), "floor"), (1.0, 1.0));
    // From below (−y), x still to the right, z up the page: lower right.
    assert_eq!(bright_quadrant(&reading(x, z, -DVec3::Y, (7, 0)), "ceiling"), (1.0, -1.0));
    // The same floor described with its edges swapped is the same plan.
    let swapped = reading(DVec3::new(0.0, 0.0, 2.0), DVec3::new(4.0, 0.0, 0.0), DVec3::Y, (0, 3));
    assert_eq!(bright_quadrant(&swapped, "floor-swapped"), (1.0, 1.0));
}

#[test]
fn a_wall_is_drawn_upright_as_seen_from_the_side_it_faces() {
    // A wall in the plane x = 0 facing +x, 2 m along z and 3 m high; the bright cell at
    // large z and large y. A viewer at +x looking towards −x with y up has +z on the left.
    let g = reading(DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.0, 3.0, 0.0), DVec3::X, (7, 3));
    assert_eq!(bright_quadrant(&g, "wall"), (-1.0, 1.0));
}

#[test]
fn the_luminaires_near_the_grid_widen_the_plan_and_far_ones_do_not() {
    let g = reading(DVec3::new(4.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 2.0), DVec3::Y, (0, 0));
    let lamp = DVec3::new(4.3, 2.5, 1.0);
    let shows = |plan: &GridPlan| {
        let q = plan.layout.pixel(plan.frame.plan(lamp));
        let [left, top, right, bottom] = plan.layout.plot.map(f64::from);
        (left..=right).contains(&q.x) && (top..=bottom).contains(&q.y)
    };
    let alone = GridPlan::of(&g, &[]);
    assert!(!shows(&alone) && shows(&GridPlan::of(&g, &[lamp])));
    assert_eq!(GridPlan::of(&g, &[DVec3::new(40.0, 2.5, 1.0)]), alone, "a luminaire far off is left out");
}

const CASE: &str = r#"
[discretization]
patch_size = 0.5

[[material]]
name = "white"
type = "lambert"
reflectance = 0.5

[[surface]]
name = "floor"
shape = "rectangle"
origin = [0.0, 0.0, 0.0]
edge_u = [0.0, 0.0, 1.0]
edge_v = [1.0, 0.0, 0.0]
material = "white"
emission = { luminance = 1.0 }

[[grid]]
name = "plane"
origin = [0.0, 0.5, 0.0]
edge_u = [1.0, 0.0, 0.0]
edge_v = [0.0, 0.0, 1.0]
resolution = [4, 4]
normal = [0.0, 1.0, 0.0]
"#;

#[test]
fn the_map_options_are_read_from_the_grid_table_and_a_misspelled_one_is_refused() {
    let parse = |map: &str| Scene::parse(Path::new("plan.toml"), format!("{CASE}{map}\n"));
    assert_eq!(parse("").unwrap().grids[0].map, MapStyle::default());
    let style = parse(r#"map = { scale = "log", values = true, isolines = true }"#).unwrap().grids[0].map;
    assert_eq!(style, MapStyle { scale: MapScale::Log, values: true, isolines: true });
    let error = parse("map = { valuse = true }").unwrap_err().to_string();
    assert!(error.contains("plan.toml") && error.contains("valuse"), "{error}");
    let error = parse(r#"map = { scale = "logarithmic" }"#).unwrap_err().to_string();
    assert!(error.contains("logarithmic") && error.contains("linear"), "{error}");
}

#[test]
fn the_targets_are_read_from_the_grid_table_and_a_bad_one_is_refused_naming_it() {
    let parse = |target: &str| Scene::parse(Path::new("plan.toml"), format!("{CASE}{target}\n"));
    assert_eq!(parse("").unwrap().grids[0].target, Target::default());
    let target = parse("target = { em = 500, u0 = 0.6 }").unwrap().grids[0].target;
    assert_eq!(target, Target { em: Some(500.0), u0: Some(0.6), ugr: None });
    assert_eq!(parse("target = { u0 = 0.4 }").unwrap().grids[0].target, Target { em: None, u0: Some(0.4), ugr: None });
    for bad in ["target = { em = -5 }", "target = { em = 0 }", "target = { u0 = 1.5 }", "target = { u0 = 0 }"] {
        let error = parse(bad).unwrap_err().to_string();
        assert!(error.contains("plan.toml") && error.contains("plane") && error.contains("target"), "{bad}: {error}");
    }
    let error = parse("target = { ugr = 19 }").unwrap_err().to_string();
    assert!(error.contains("ugr"), "{error}");
}
