//! `[[luminaire]]` tables: valid luminaires of every type, and every mistake named by its
//! table and key; a bad photometric file by its path and line.

use super::{BASE, CASE, assert_error, parse, rejected};
use crate::support::scratch;
use glam::DVec3;
use std::path::Path;
use ugo::luminaire::LuminaireKind;
use ugo::photometry::Distribution;
use ugo::scene::Scene;

/// A floor and `luminaires`, nothing else emitting.
fn with(luminaires: &str) -> String {
    format!(
        "{BASE}\n[[surface]]\nname = \"floor\"\nshape = \"rectangle\"\nmaterial = \"white\"\norigin = [0, 0, 0]\nedge_u = [0, 0, 1]\nedge_v = [1, 0, 0]\n{luminaires}"
    )
}

const LAMP: &str = "[[luminaire]] \"lamp\" (#1)";

fn point(scene: &Scene, i: usize) -> &ugo::luminaire::PointLuminaire {
    match &scene.luminaires[i].kind {
        LuminaireKind::Point(p) => p,
        other => panic!("{other:?}"),
    }
}

#[test]
fn luminaires_of_every_type_light_a_scene_without_emitting_surfaces() {
    let dir = scratch("luminaires");
    let file = std::fs::read_to_string("tests/data/photometry/c-axial-lambert-2002.ies").unwrap();
    dir.write("down.ies", &file);
    dir.write("quad.ldt", &std::fs::read_to_string("tests/data/photometry/isym4-quadrant.ldt").unwrap());
    let text = with(
        r#"
[[luminaire]]
name = "bulb"
type = "isotropic"
flux = 1000
position = [0.5, 2, 0.5]

[[luminaire]]
name = "downlight"
type = "lambertian"
intensity = 300
position = [0.5, 2, 0.5]
aim = [0, -2, 0]

[[luminaire]]
name = "spot"
type = "ies"
file = "down.ies"
position = [0.2, 2, 0.2]
aim = [1, -1, 0]
rotate_deg = 30
multiplier = 0.8

[[luminaire]]
name = "panel"
type = "eulumdat"
file = "quad.ldt"
position = [0.7, 2, 0.7]

[[luminaire]]
name = "sun"
type = "parallel"
direction = [0, -1, 1]
illuminance = 50000
"#,
    );
    let case = dir.write("case.toml", &text);
    let scene = Scene::load(&case).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(scene.luminaires.len(), 5);
    assert_eq!(
        point(&scene, 0).distribution,
        Distribution::Isotropic { intensity: 1000.0 / (4.0 * std::f64::consts::PI) }
    );
    assert_eq!(point(&scene, 1).distribution, Distribution::Lambertian { peak: 300.0 });
    assert_eq!(point(&scene, 1).aim, DVec3::NEG_Y);
    let spot = point(&scene, 2);
    assert_eq!((spot.rotate_deg, spot.multiplier), (30.0, 0.8));
    assert!((spot.aim - DVec3::new(1.0, -1.0, 0.0).normalize()).length() < 1e-15);
    assert_eq!(spot.file.as_deref(), Some(dir.join("down.ies").as_path()), "relative to the case file");
    assert!(matches!(&point(&scene, 3).distribution, Distribution::Table(t) if t.description.contains("Isym 4")));
    assert_eq!(point(&scene, 0).aim, DVec3::NEG_Y, "straight down by default");
    let LuminaireKind::Parallel { direction, illuminance, .. } = scene.luminaires[4].kind else { panic!() };
    assert!((direction - DVec3::new(0.0, -1.0, 1.0).normalize()).length() < 1e-15 && illuminance == 50_000.0);
}

#[test]
fn an_unknown_type_is_named_with_the_known_ones() {
    let error = rejected(&with("[[luminaire]]\nname = \"lamp\"\ntype = \"laser\"\nposition = [0, 1, 0]\n"));
    assert_error(&error, LAMP, "type", &["laser", "isotropic", "lambertian", "ies", "eulumdat", "parallel"]);
}

#[test]
fn a_key_of_another_type_is_named() {
    let text =
        with("[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nflux = 10\nposition = [0, 1, 0]\nrotate_deg = 5\n");
    assert_error(&rejected(&text), LAMP, "rotate_deg", &["\"isotropic\" luminaire takes only"]);
    let text = with(
        "[[luminaire]]\nname = \"lamp\"\ntype = \"parallel\"\ndirection = [0, -1, 0]\nilluminance = 5\nposition = [0, 1, 0]\n",
    );
    assert_error(&rejected(&text), LAMP, "position", &["\"parallel\" luminaire takes only direction, illuminance"]);
}

#[test]
fn missing_and_conflicting_values_are_named() {
    let text = with("[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nflux = 10\n");
    assert_error(&rejected(&text), LAMP, "position", &["needs `position`"]);
    let text = with("[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nposition = [0, 1, 0]\n");
    assert_error(&rejected(&text), LAMP, "flux", &["needs `flux` (lm) or `intensity` (cd)"]);
    let text =
        with("[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nflux = 1\nintensity = 1\nposition = [0, 1, 0]\n");
    assert_error(&rejected(&text), LAMP, "flux", &["not both"]);
    let text = with("[[luminaire]]\nname = \"lamp\"\ntype = \"ies\"\nposition = [0, 1, 0]\n");
    assert_error(&rejected(&text), LAMP, "file", &["needs `file`"]);
    let text = with("[[luminaire]]\nname = \"lamp\"\ntype = \"parallel\"\nilluminance = 5\n");
    assert_error(&rejected(&text), LAMP, "direction", &["needs `direction`"]);
}

#[test]
fn bad_numbers_are_named() {
    let lamp = |extra: &str| {
        with(&format!("[[luminaire]]\nname = \"lamp\"\ntype = \"lambertian\"\nposition = [0, 1, 0]\n{extra}\n"))
    };
    assert_error(&rejected(&lamp("intensity = -5")), LAMP, "intensity", &["greater than 0"]);
    assert_error(&rejected(&lamp("intensity = 5\nmultiplier = 0")), LAMP, "multiplier", &["greater than 0"]);
    assert_error(&rejected(&lamp("intensity = 5\naim = [0, 0, 0]")), LAMP, "aim", &["non-zero"]);
    assert_error(&rejected(&lamp("intensity = nan")), LAMP, "intensity", &["finite"]);
}

#[test]
fn a_misspelled_key_and_a_duplicate_name_are_refused() {
    let error =
        rejected(&with("[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nflux = 1\npostion = [0, 1, 0]\n"));
    assert!(error.table().starts_with("[[luminaire]]") && error.key() == "postion", "{error}");
    let one = "[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nflux = 1\nposition = [0, 1, 0]\n";
    let error = rejected(&with(&format!("{one}{one}")));
    assert_error(&error, "[[luminaire]] \"lamp\" (#2)", "name", &["duplicate"]);
}

#[test]
fn a_missing_or_malformed_photometric_file_names_its_path_and_line() {
    let text = with("[[luminaire]]\nname = \"lamp\"\ntype = \"ies\"\nfile = \"no-such.ies\"\nposition = [0, 1, 0]\n");
    let error = rejected(&text);
    assert_error(&error, LAMP, "file", &["no-such.ies", "cannot read the file"]);
    assert!(error.message().contains(&Path::new(CASE).parent().unwrap().join("no-such.ies").display().to_string()));

    let dir = scratch("bad-ldt");
    let good = std::fs::read_to_string("tests/data/photometry/isym1-axial-isotropic.ldt").unwrap();
    let bad: Vec<&str> = good.lines().map(|l| if l.trim() == "1" { "one" } else { l }).collect();
    dir.write("bad.ldt", &bad.join("\n"));
    let case = dir.write(
        "case.toml",
        &with("[[luminaire]]\nname = \"lamp\"\ntype = \"eulumdat\"\nfile = \"bad.ldt\"\nposition = [0, 1, 0]\n"),
    );
    let error = Scene::load(&case).unwrap_err();
    assert_eq!((error.table(), error.key()), (LAMP, "file"), "{error}");
    assert!(error.message().contains("bad.ldt: line 2: expected the type indicator Ityp"), "{error}");
}

#[test]
fn a_scene_without_surface_emission_or_luminaires_is_still_refused() {
    let error = rejected(&with(""));
    assert!(error.message().contains("nothing emits light") && error.message().contains("[[luminaire]]"), "{error}");
    assert!(
        parse(&with("[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nflux = 1\nposition = [0, 1, 0]\n")).is_ok()
    );
}
