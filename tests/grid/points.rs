//! Grid points that do not stand in the room (issue 37, point 1): a point inside a solid
//! or under a surface nearer than the spacing is left out of `E_avg`, `E_min`, `E_max` and
//! `U0`, counted and named in a warning; a grid facing away from every source is warned
//! about, one facing it is not; `--strict` refuses left-out points before the solve.

use super::{grid, lamp_scene};
use crate::support::{build, lambert, rectangle, solve, surface};
use glam::DVec3;
use ugo::geometry::Shape;
use ugo::io::Warning;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::grid::GridReading;
use ugo::study::{Job, StudyError, solve_case};

/// The lamp over a floor, a block (0.7–1.4 × 0–0.5 × 0.6–1.4 m) standing on it and a
/// shelf facing down at 0.45 m over the corner `x, z < 0`: on the grid at 0.25 m (cells
/// 0.4 × 0.5 m), points 13, 14, 18 and 19 lie inside the block and point 0 0.2 m under
/// the shelf.
fn furnished() -> ugo::scene::Scene {
    let mut scene = lamp_scene(true);
    scene.materials.push(lambert("grey", 0.5));
    let block = Shape::Box { min: DVec3::new(0.7, 0.0, 0.6), max: DVec3::new(1.4, 0.5, 1.4), rotate_y_deg: 0.0 };
    scene.surfaces.push(surface("block", block, 1, false, None));
    let shelf = rectangle([-0.5, 0.45, -0.5], [0.4, 0.0, 0.0], [0.0, 0.0, 0.5]);
    scene.surfaces.push(surface("shelf", shelf, 1, false, None));
    scene
}

const LEFT_OUT: [usize; 5] = [0, 13, 14, 18, 19];

#[test]
fn points_inside_a_solid_or_under_a_near_surface_are_left_out_of_the_statistics() {
    let scene = furnished();
    let model = build(&scene);
    let field = Field::from_unknowns(&solve(&model), 1);
    let reading = GridReading::of(&grid(0.25), &model, &field, &Silent);
    let left: Vec<usize> = (0..20).filter(|&i| reading.obstructed[i].is_some()).collect();
    assert_eq!(left, LEFT_OUT);
    let shelf = reading.obstructed[0].as_ref().unwrap();
    assert!(!shelf.inside && (shelf.distance - 0.2).abs() < 1e-6 && shelf.surface == 3, "{shelf:?}");
    assert!(LEFT_OUT[1..].iter().all(|&i| reading.obstructed[i].as_ref().is_some_and(|o| o.inside && o.surface == 2)));
    assert!(LEFT_OUT[1..].iter().all(|&i| reading.illuminance[i] == 0.0), "inside the block is dark");
    let counted: Vec<f64> = (0..20).filter(|i| !LEFT_OUT.contains(i)).map(|i| reading.illuminance[i]).collect();
    let mean = counted.iter().sum::<f64>() / 15.0;
    let min = counted.iter().copied().fold(f64::INFINITY, f64::min);
    let st = reading.stats();
    assert_eq!((st.counted, st.min), (15, min));
    assert!((st.average - mean).abs() < 1e-12 * mean && (st.u0 - min / mean).abs() < 1e-12);
    assert!(st.u0 > 0.0, "no silent zero");
}

#[test]
fn the_left_out_points_are_counted_and_named_in_a_warning() {
    let mut scene = furnished();
    scene.grids.push(grid(0.25));
    let solved = solve_case(&scene, &Job::default(), &Silent).unwrap();
    let warning = solved.warnings.iter().find(|w| matches!(w, Warning::GridPointsLeftOut { .. })).unwrap();
    let text = warning.to_string();
    for part in ["5 of its 20 points", "(u 0, v 0) 0.200 m under \"shelf\"", "(u 3, v 2) inside \"block\"", "1 more"] {
        assert!(text.contains(part), "{text} lacks {part}");
    }
    assert!(!solved.warnings.iter().any(|w| matches!(w, Warning::GridFacesAway { .. })), "{:?}", solved.warnings);
}

/// The model alone shows the points left out: `--strict` refuses them before the solve.
#[test]
fn strict_refuses_left_out_points_before_the_solve() {
    let mut scene = furnished();
    scene.grids.push(grid(0.25));
    let strict = Job { strict: true, ..Job::default() };
    match solve_case(&scene, &strict, &Silent) {
        Err(StudyError::Strict(found)) => {
            assert!(found.iter().any(|w| matches!(w, Warning::GridPointsLeftOut { left_out: 5, .. })), "{found:?}")
        }
        other => panic!("not refused before the solve: {:?}", other.map(|s| s.warnings)),
    }
}

#[test]
fn a_grid_facing_away_from_every_source_is_warned_about() {
    let mut scene = lamp_scene(true);
    let mut down = grid(0.25);
    down.normal = DVec3::NEG_Y;
    scene.grids.push(down);
    let solved = solve_case(&scene, &Job::default(), &Silent).unwrap();
    let away: Vec<String> =
        solved.warnings.iter().filter(|w| matches!(w, Warning::GridFacesAway { .. })).map(|w| w.to_string()).collect();
    assert_eq!(away.len(), 1, "{:?}", solved.warnings);
    assert!(away[0].contains("grid \"floor\"") && away[0].contains("faces away"), "{}", away[0]);
}
