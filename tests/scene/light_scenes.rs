//! `[lighting]`, `group` keys and `[[light_scene]]` tables: the groups a case's sources
//! form, the factors of its light scenes, the maintenance factor applied to every source,
//! and each mistake an error that names the table, the key and the line.

use super::{BASE, LAMP, assert_error, lit, parse, rejected};
use ugo::geometry::Emission;
use ugo::luminaire::LuminaireKind;
use ugo::scene::DEFAULT_GROUP;

/// Two isotropic bulbs, the first in the group "left", the second in none.
const BULBS: &str = r#"
[[luminaire]]
name = "a"
type = "isotropic"
flux = 1000
position = [1, 2, 1]
group = "left"

[[luminaire]]
name = "b"
type = "isotropic"
flux = 500
position = [2, 2, 1]
"#;

/// The lamp of `LAMP` in the group "ceiling", the bulbs, and `extra`.
fn grouped(extra: &str) -> String {
    let lamp =
        LAMP.replace("emission = { luminance = 100.0 }", "emission = { luminance = 100.0 }\ngroup = \"ceiling\"");
    format!("{BASE}{lamp}{BULBS}{extra}")
}

/// The 1-based line of `text` that contains `fragment`.
fn line_of(text: &str, fragment: &str) -> String {
    let index = text.lines().position(|l| l.contains(fragment)).expect("the fragment is in the text");
    format!("line {}:", index + 1)
}

#[test]
fn sources_form_groups_and_light_scenes_give_each_a_factor() {
    let text = grouped(
        "\n[[light_scene]]\nname = \"evening\"\ngroups = { left = 0.3, ceiling = true }\n\n\
         [[light_scene]]\nname = \"off-but-b\"\ngroups = { default = 1, ceiling = false }\n",
    );
    let scene = parse(&text).unwrap();
    let l = &scene.lighting;
    let names: Vec<&str> = l.groups.iter().map(|g| g.name.as_str()).collect();
    assert_eq!(names, ["ceiling", "left", DEFAULT_GROUP]);
    assert_eq!((l.groups[0].surfaces.clone(), l.groups[0].luminaires.clone()), (vec![0], vec![]));
    assert_eq!((l.groups[1].surfaces.clone(), l.groups[1].luminaires.clone()), (vec![], vec![0]));
    assert_eq!((l.groups[2].surfaces.clone(), l.groups[2].luminaires.clone()), (vec![], vec![1]));
    assert_eq!(l.scenes.len(), 2);
    assert_eq!((l.scenes[0].name.as_str(), l.scenes[0].factors.clone()), ("evening", vec![1.0, 0.3, 0.0]));
    assert_eq!(l.scenes[1].factors, vec![0.0, 0.0, 1.0]);
    assert_eq!(l.maintenance_factor, 1.0);
}

#[test]
fn an_ungrouped_emitting_surface_is_in_the_default_group_and_a_dark_one_in_none() {
    let dark = "\n[[surface]]\nname = \"floor\"\nshape = \"disc\"\nmaterial = \"white\"\ncenter = [0, 0, 0]\n\
                normal = [0, 1, 0]\nradius = 1\n";
    let scene = parse(&lit(dark)).unwrap();
    let groups = &scene.lighting.groups;
    assert_eq!(groups.len(), 1);
    assert_eq!((groups[0].name.as_str(), groups[0].surfaces.clone()), (DEFAULT_GROUP, vec![0]));
}

#[test]
fn the_maintenance_factor_multiplies_every_source() {
    let sun = "\n[[luminaire]]\nname = \"sun\"\ntype = \"parallel\"\ndirection = [0, -1, 0]\nilluminance = 1000\n";
    let text = grouped(&format!("{sun}\n[lighting]\nmaintenance_factor = 0.8\n"));
    let scene = parse(&text).unwrap();
    assert_eq!(scene.lighting.maintenance_factor, 0.8);
    assert_eq!(scene.surfaces[0].emission, Some(Emission::Luminance(100.0 * 0.8)));
    let LuminaireKind::Point(a) = &scene.luminaires[0].kind else { panic!("a is a point source") };
    assert_eq!(a.multiplier, 0.8);
    let LuminaireKind::Parallel { illuminance, .. } = scene.luminaires[2].kind else { panic!("the sun is parallel") };
    assert_eq!(illuminance, 1000.0 * 0.8);
}

#[test]
fn a_maintenance_factor_outside_zero_to_one_is_refused_with_its_line() {
    for (bad, shown) in [("0", "got 0"), ("1.2", "got 1.2"), ("-0.5", "got -0.5"), ("nan", "got NaN")] {
        let text = grouped(&format!("\n[lighting]\nmaintenance_factor = {bad}\n"));
        let error = rejected(&text);
        let line = line_of(&text, "maintenance_factor");
        assert_error(&error, "[lighting]", "maintenance_factor", &[&line, "greater than 0 and at most 1", shown]);
    }
    let error = rejected(&grouped("\n[lighting]\nmaintenance = 0.8\n"));
    assert!(error.to_string().contains("unknown field `maintenance`"), "{error}");
}

#[test]
fn an_unknown_group_in_a_light_scene_is_refused_with_the_known_ones() {
    let text = grouped("\n[[light_scene]]\nname = \"evening\"\ngroups = { lfet = 0.3 }\n");
    let error = rejected(&text);
    let line = line_of(&text, "lfet");
    let fragments = [line.as_str(), "unknown group \"lfet\"", "\"ceiling\", \"left\", \"default\""];
    assert_error(&error, "[[light_scene]] \"evening\" (#1)", "groups.lfet", &fragments);
}

#[test]
fn a_negative_or_too_large_factor_is_refused() {
    let text = grouped("\n[[light_scene]]\nname = \"evening\"\ngroups = { left = -0.3 }\n");
    let line = line_of(&text, "left = -0.3");
    let error = rejected(&text);
    assert_error(&error, "[[light_scene]] \"evening\" (#1)", "groups.left", &[&line, "from 0 (off) to 1", "-0.3"]);
    let error = rejected(&grouped("\n[[light_scene]]\nname = \"evening\"\ngroups = { left = 50 }\n"));
    assert_error(&error, "[[light_scene]] \"evening\" (#1)", "groups.left", &["got 50", "a percentage?"]);
    let error = rejected(&grouped("\n[[light_scene]]\nname = \"evening\"\ngroups = { left = \"on\" }\n"));
    assert!(error.to_string().contains("light_scene"), "{error}");
}

#[test]
fn duplicate_or_unusable_light_scene_names_are_refused() {
    let text = grouped(
        "\n[[light_scene]]\nname = \"evening\"\ngroups = { left = 1 }\n\n\
         [[light_scene]]\nname = \"evening\"\ngroups = { left = 0.5 }\n",
    );
    let error = rejected(&text);
    let second = text.lines().enumerate().filter(|(_, l)| l.contains("\"evening\"")).nth(1).unwrap().0 + 1;
    let line = format!("line {second}:");
    assert_error(&error, "[[light_scene]] \"evening\" (#2)", "name", &[&line, "duplicate name", "#1"]);
    let error = rejected(&grouped("\n[[light_scene]]\nname = \"late evening\"\ngroups = { left = 1 }\n"));
    assert_error(&error, "[[light_scene]] \"late evening\" (#1)", "name", &["letters, digits"]);
    let error = rejected(&grouped("\n[[light_scene]]\nname = \"\"\ngroups = { left = 1 }\n"));
    assert_error(&error, "[[light_scene]] \"\" (#1)", "name", &["must not be empty"]);
}

#[test]
fn a_group_on_a_surface_that_does_not_emit_or_an_empty_group_is_refused() {
    let dark = "\n[[surface]]\nname = \"floor\"\nshape = \"disc\"\nmaterial = \"white\"\ncenter = [0, 0, 0]\n\
                normal = [0, 1, 0]\nradius = 1\ngroup = \"left\"\n";
    let text = lit(dark);
    let error = rejected(&text);
    let line = line_of(&text, "group = \"left\"");
    assert_error(&error, "[[surface]] \"floor\" (#2)", "group", &[&line, "no `emission`"]);
    let error = rejected(&grouped("").replace("group = \"left\"", "group = \"\""));
    assert_error(&error, "[[luminaire]] \"a\" (#1)", "group", &["must not be empty"]);
}

#[test]
fn a_misspelled_key_of_a_light_scene_is_refused() {
    let error = rejected(&grouped("\n[[light_scene]]\nname = \"evening\"\ngruops = { left = 1 }\n"));
    assert!(error.to_string().contains("unknown field `gruops`"), "{error}");
    assert!(error.table().contains("light_scene"), "{error}");
}

#[test]
fn a_light_scene_that_turns_every_group_off_is_refused() {
    let text = grouped("\n[[light_scene]]\nname = \"dark\"\ngroups = { left = 0, ceiling = false }\n");
    let line = line_of(&text, "name = \"dark\"");
    let error = rejected(&text);
    assert_error(&error, "[[light_scene]] \"dark\" (#1)", "groups", &[&line, "turns every group off", "\"left\""]);
    assert!(parse(&grouped("\n[[light_scene]]\nname = \"dim\"\ngroups = { left = 0.01 }\n")).is_ok());
}
