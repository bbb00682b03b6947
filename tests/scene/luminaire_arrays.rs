//! `array = { … }` of a `[[luminaire]]` (issue 17, item 2): an array is exactly the
//! luminaires it stands for written out one by one (scene and solution), the rectangle
//! form spreads them as documented, and every bad value is named by file, table, key and line.

use super::{BASE, LAMP, assert_error, parse, rejected};
use crate::support::{build, solve};
use glam::DVec3;
use ugo::luminaire::LuminaireKind;
use ugo::scene::Scene;

/// A closed grey room (2 m × 2.5 m × 3 m, patches of 0.5 m) with `luminaires` in it.
fn room(luminaires: &str) -> String {
    let base = BASE.replace("patch_size = 0.1", "patch_size = 0.5");
    format!(
        "{base}\n[[surface]]\nname = \"room\"\nshape = \"box\"\nmaterial = \"white\"\nmin = [0, 0, 0]\nmax = [2, 2.5, 3]\ninside = true\n{luminaires}"
    )
}

const TABLE: &str = "[[luminaire]] \"lamp\" (#1)";

/// A lambertian downlight table named `name` at `position`, aimed and grouped, plus `extra` lines.
fn lamp(name: &str, position: Option<[f64; 3]>, extra: &str) -> String {
    let at = position.map_or(String::new(), |p| format!("position = [{}, {}, {}]\n", p[0], p[1], p[2]));
    format!(
        "[[luminaire]]\nname = \"{name}\"\ntype = \"lambertian\"\nintensity = 120\naim = [0.2, -1, 0.1]\nmultiplier = 0.9\ngroup = \"hall\"\n{at}{extra}\n"
    )
}

fn positions(scene: &Scene) -> Vec<DVec3> {
    scene
        .luminaires
        .iter()
        .map(|l| match &l.kind {
            LuminaireKind::Point(p) => p.position,
            other => panic!("{other:?}"),
        })
        .collect()
}

#[test]
fn an_array_is_the_luminaires_written_one_by_one_in_the_scene_and_the_solution() {
    let array = room(&lamp(
        "lamp",
        Some([0.5, 2.4, 0.75]),
        "array = { rows = 2, columns = 3, row_spacing = 1.5, column_spacing = 0.5 }",
    ));
    let mut one_by_one = String::new();
    for (r, z) in [(1, 0.75), (2, 2.25)] {
        for (c, x) in [(1, 0.5), (2, 1.0), (3, 1.5)] {
            one_by_one += &lamp(&format!("lamp-{r}-{c}"), Some([x, 2.4, z]), "");
        }
    }
    let (array, one_by_one) = (parse(&array).unwrap(), parse(&room(&one_by_one)).unwrap());
    assert_eq!(array.luminaires, one_by_one.luminaires, "bitwise the same luminaires, named NAME-row-column");
    assert_eq!(array.lighting, one_by_one.lighting, "all in the table's group");
    let (a, b) = (solve(&build(&array)), solve(&build(&one_by_one)));
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = a.iter().zip(&b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    assert!(worst <= 1e-12 * scale, "solutions differ by {worst:e} of {scale:e}");
}

#[test]
fn a_rectangle_spreads_its_luminaires_at_cell_centres_or_at_the_edge_offsets() {
    let centred = room(&lamp(
        "lamp",
        None,
        "array = { rows = 2, columns = 2, origin = [0, 2.4, 0], edge_u = [2, 0, 0], edge_v = [0, 0, 3] }",
    ));
    let expected = [[0.5, 0.75], [1.5, 0.75], [0.5, 2.25], [1.5, 2.25]].map(|[x, z]| DVec3::new(x, 2.4, z));
    assert_eq!(positions(&parse(&centred).unwrap()), expected);
    let offset = room(&lamp(
        "lamp",
        None,
        "array = { rows = 1, columns = 3, origin = [0, 2.4, 0], edge_u = [2, 0, 0], edge_v = [0, 0, 3], offset = [0.25, 0.5] }",
    ));
    let got = positions(&parse(&offset).unwrap());
    let expected = [0.25, 1.0, 1.75].map(|x| DVec3::new(x, 2.4, 1.5));
    assert!(got.iter().zip(&expected).all(|(a, b)| (*a - *b).length() < 1e-15), "{got:?}");
}

/// The error of `array = { KEYS }` on a table with `position` (or none), and the line of `array`.
fn refused(keys: &str, position: Option<[f64; 3]>) -> (ugo::scene::SceneError, String) {
    let text = room(&lamp("lamp", position, &format!("array = {{ {keys} }}")));
    let line = text.lines().position(|l| l.starts_with("array")).unwrap() + 1;
    (rejected(&text), format!("line {line}"))
}

#[test]
fn bad_arrays_are_named_by_table_key_and_line() {
    let at = Some([0.5, 2.4, 0.5]);
    let (error, line) = refused("rows = 0, columns = 2, column_spacing = 1", at);
    assert_error(&error, TABLE, "array.rows", &[&line, "count from 1", "got 0"]);
    let (error, line) = refused("rows = 2, columns = 2, row_spacing = -1, column_spacing = 1", at);
    assert_error(&error, TABLE, "array.row_spacing", &[&line, "greater than 0", "got -1"]);
    let (error, line) = refused("rows = 2, columns = 1", at);
    assert_error(&error, TABLE, "array.row_spacing", &[&line, "need `row_spacing`"]);
    let both = "rows = 1, columns = 2, column_spacing = 1, origin = [0, 2, 0], edge_u = [1, 0, 0], edge_v = [0, 0, 1]";
    let (error, line) = refused(both, None);
    assert_error(&error, TABLE, "array.origin", &[&line, "not both", "`column_spacing` and `origin`"]);
    let (error, line) = refused("rows = 1, columns = 2, column_spacing = 1", None);
    assert_error(&error, TABLE, "position", &[&line, "starts at `position`"]);
    let rectangle = "rows = 1, columns = 2, origin = [0, 2, 0], edge_u = [1, 0, 0], edge_v = [0, 0, 1]";
    let (error, line) = refused(rectangle, at);
    assert_error(&error, TABLE, "position", &[&line, "give no `position`"]);
    let (error, line) = refused(&format!("{rectangle}, offset = [0.5, 0]"), None);
    assert_error(&error, TABLE, "array.offset", &[&line, "less than half its edge"]);
    let (error, _) = refused("rows = 1, columns = 2, column_spacing = 1, axis_u = [0, 0, 2]", at);
    assert_error(&error, TABLE, "array.axis_v", &["parallel"]);
}

#[test]
fn a_misspelled_array_key_or_a_name_taken_by_a_member_is_refused() {
    let text = room(&lamp("lamp", Some([0.5, 2.4, 0.5]), "array = { rows = 1, colums = 2 }"));
    let error = rejected(&text);
    assert!(error.key().ends_with("colums") && error.message().contains("line"), "{error}");
    let text = lit_with(&format!(
        "{}{}",
        lamp("lamp-1-2", Some([0.0, 1.0, 0.0]), ""),
        lamp("lamp", Some([0.5, 2.4, 0.5]), "array = { rows = 1, columns = 2, column_spacing = 1 }")
    ));
    assert_error(&rejected(&text), "[[luminaire]] \"lamp\" (#2)", "name", &["\"lamp-1-2\"", "#1"]);
    let parallel = "[[luminaire]]\nname = \"sun\"\ntype = \"parallel\"\ndirection = [0, -1, 0]\nilluminance = 5\narray = { rows = 1, columns = 1 }\n";
    assert_error(&rejected(&lit_with(parallel)), "[[luminaire]] \"sun\" (#1)", "array", &["takes only"]);
}

fn lit_with(extra: &str) -> String {
    format!("{BASE}{LAMP}{extra}")
}

/// `group_by` (issue 38, point 2): the members of an array dim by row, by column or one by
/// one, in groups named after the table's `group` (or its name without one).
#[test]
fn group_by_puts_each_row_column_or_member_in_a_group_of_its_own() {
    let keys = "array = { rows = 2, columns = 3, row_spacing = 1.5, column_spacing = 0.5, group_by = \"BY\" }";
    let of = |by: &str, group: bool| {
        let mut text = lamp("lamp", Some([0.5, 2.4, 0.75]), &keys.replace("BY", by));
        if !group {
            text = text.replace("group = \"hall\"\n", "");
        }
        let scene = parse(&room(&text)).unwrap();
        let groups = scene.lighting.groups.iter().map(|g| (g.name.clone(), g.luminaires.clone()));
        groups.collect::<Vec<(String, Vec<usize>)>>()
    };
    let named = |list: &[(&str, &[usize])]| -> Vec<(String, Vec<usize>)> {
        list.iter().map(|(n, l)| (n.to_string(), l.to_vec())).collect()
    };
    assert_eq!(of("row", true), named(&[("hall-row-1", &[0, 1, 2]), ("hall-row-2", &[3, 4, 5])]));
    let columns = [("lamp-column-1", &[0, 3][..]), ("lamp-column-2", &[1, 4]), ("lamp-column-3", &[2, 5])];
    assert_eq!(of("column", false), named(&columns));
    let members = of("member", true);
    assert_eq!(members.len(), 6);
    assert_eq!(members[4], ("hall-2-2".to_string(), vec![4]));
    // a light scene names the new groups
    let scene = lamp("lamp", Some([0.5, 2.4, 0.75]), &keys.replace("BY", "row"));
    let text = room(&format!(
        "{scene}\n[[light_scene]]\nname = \"front\"\ngroups = {{ hall-row-1 = 1, hall-row-2 = 0.25 }}\n"
    ));
    let lighting = parse(&text).unwrap().lighting;
    assert_eq!(lighting.scenes[0].factors, vec![1.0, 0.25]);
    let (error, line) =
        refused("rows = 1, columns = 2, column_spacing = 1, group_by = \"diagonal\"", Some([0.5, 2.4, 0.5]));
    assert_error(&error, TABLE, "array.group_by", &[&line, "\"row\", \"column\" or \"member\"", "\"diagonal\""]);
}
