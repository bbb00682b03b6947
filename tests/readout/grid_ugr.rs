//! A `[[grid]]`'s UGR fed by `[[glare_grid]]`s (`docs/scene-format.md`, "A grid's UGR";
//! issue 38): a glare grid's `grid` is validated naming file, table, key and line, and a
//! glare grid naming a grid with a `ugr` target satisfies it alone.

use super::room;
use std::path::Path;
use ugo::scene::Scene;

/// A `[[grid]]` named `name` on the floor of the 4 m room, with the `target` `ugr`.
fn grid(name: &str, ugr: f64) -> String {
    format!(
        "[[grid]]\nname = \"{name}\"\norigin = [0.5, 0.8, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n\
         resolution = [3, 3]\nnormal = [0, 1, 0]\ntarget = {{ ugr = {ugr} }}\n"
    )
}

/// A 3 × 2 `[[glare_grid]]` at 1.2 m looking four ways, named `name`, naming the grid `grid`.
fn glare_grid(name: &str, grid: &str) -> String {
    format!(
        "[[glare_grid]]\nname = \"{name}\"\norigin = [0.5, 1.2, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n\
         resolution = [3, 2]\nlook = [1, 0, 0]\nview_step_deg = 90\ngrid = \"{grid}\"\n"
    )
}

#[test]
fn a_glare_grids_grid_is_validated_and_satisfies_a_ugr_target() {
    let base = room(4.0, 0.5, 10.0) + &grid("desk", 19.0);
    let parse = |more: &str| Scene::parse(Path::new("cases/test.toml"), format!("{base}{more}"));
    let error = parse(&glare_grid("desks", "bench")).expect_err("a grid of no [[grid]]").to_string();
    let line = base.lines().count() + 9;
    for words in ["cases/test.toml", "[[glare_grid]] \"desks\" (#1)", "grid", "names no [[grid]]", "\"bench\""] {
        assert!(error.contains(words), "{words}: {error}");
    }
    assert!(error.contains(&format!("line {line}:")), "line {line}: {error}");
    let unread = parse("").expect_err("a `ugr` target nothing reads").to_string();
    for words in ["[[grid]] \"desk\" (#1)", "target", "needs an [[observer]] or a [[glare_grid]]", "grid = \"desk\""] {
        assert!(unread.contains(words), "{words}: {unread}");
    }
    let scene = parse(&glare_grid("desks", "desk")).unwrap_or_else(|e| panic!("{e}"));
    let g = &scene.glare_grids[0];
    assert_eq!(g.grid.as_deref(), Some("desk"));
    assert!(g.observers().iter().all(|o| o.grid.as_deref() == Some("desk")));
}
