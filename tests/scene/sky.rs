//! `[sky]` and `[[window]]`: a daylit scene is read into a sky and one source per opening
//! (and the sun); every mistake is named by its table and key.

use super::{BASE, assert_error, parse, rejected};
use ugo::luminaire::LuminaireKind;
use ugo::sky::{Distribution, Glazing};

const FLOOR: &str = "[[surface]]\nname = \"floor\"\nshape = \"rectangle\"\nmaterial = \"white\"\norigin = [0, 0, 0]\nedge_u = [0, 0, 1]\nedge_v = [1, 0, 0]\n";
const WINDOW: &str = "[[window]]\nname = \"roof\"\norigin = [0, 1, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\n";

fn daylit(sky: &str) -> String {
    format!("{BASE}{FLOOR}[sky]\n{sky}\n{WINDOW}")
}

#[test]
fn a_sky_with_a_window_and_the_sun_is_read() {
    let scene = parse(&daylit(
        "type = \"clear\"\nlatitude_deg = 52.5\nlongitude_deg = 13.4\ndate = \"2026-06-21\"\ntime = \"12:08\"\n\
         timezone_h = 1\nzenith_luminance = 5000\nground_reflectance = 0.3\nsun_illuminance = 80000",
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let sky = scene.sky.as_ref().expect("a sky");
    assert_eq!(sky.distribution, Distribution::General(12));
    assert!((sky.zenith_luminance - 5000.0).abs() < 1e-9);
    assert!((sky.sun.y.asin().to_degrees() - 61.0).abs() < 0.2, "{}", sky.sun);
    assert!(sky.sun.z > 0.0 && sky.sun.x.abs() < 0.01, "the sun is due south, towards +z: {}", sky.sun);
    let names: Vec<&str> = scene.luminaires.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(names, ["roof", "sun"]);
    match &scene.luminaires[1].kind {
        LuminaireKind::Parallel { direction, illuminance, .. } => {
            assert!((*direction + sky.sun).length() < 1e-12 && *illuminance == 80_000.0)
        }
        other => panic!("{other:?}"),
    }
    assert!(
        (sky.ground_luminance() - 0.3 * (sky.horizontal_illuminance + 80_000.0 * sky.sun.y) / std::f64::consts::PI)
            .abs()
            < 1e-9
    );
}

#[test]
fn daylight_mistakes_are_named_by_table_and_key() {
    let e = rejected(&daylit(
        "type = \"overcast\"\nsun_altitude_deg = 60\nsun_azimuth_deg = 180\ngruond_reflectance = 0.2",
    ));
    assert_error(&e, "[sky]", "gruond_reflectance", &["unknown field"]);
    let e = rejected(&daylit("type = 16\nsun_altitude_deg = 60\nsun_azimuth_deg = 180"));
    assert_error(&e, "[sky]", "type", &["overcast", "1 to 15"]);
    let e = rejected(&daylit("type = \"overcast\"\nsun_altitude_deg = 60"));
    assert_error(&e, "[sky]", "sun_altitude_deg", &["latitude_deg"]);
    let e =
        rejected(&daylit("type = 3\nlatitude_deg = 52\nlongitude_deg = 13\ndate = \"2026-02-30\"\ntime = \"12:00\""));
    assert_error(&e, "[sky]", "date", &["YYYY-MM-DD"]);
    let e = rejected(&daylit("type = 3\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\nground_reflectance = 1.5"));
    assert_error(&e, "[sky]", "ground_reflectance", &["at most 1"]);
    let e = rejected(&daylit("type = 3\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\nnorth = [0, 1, 0]"));
    assert_error(&e, "[sky]", "north", &["horizontal"]);
    let e = rejected(&format!("{BASE}{FLOOR}{WINDOW}"));
    assert_error(&e, "[[window]] \"roof\" (#1)", "", &["[sky]"]);
    let glazed =
        format!("{BASE}{FLOOR}[sky]\ntype = 5\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\n{WINDOW}panes = 2\n");
    assert_error(&rejected(&glazed), "[[window]] \"roof\" (#1)", "panes", &["transmittance"]);
    let clear = format!(
        "{BASE}{FLOOR}[sky]\ntype = 5\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\n{WINDOW}transmittance = 0.97\n"
    );
    assert_error(&rejected(&clear), "[[window]] \"roof\" (#1)", "transmittance", &["at most 0.9"]);
    let flat = WINDOW.replace("edge_v = [0, 0, 1]", "edge_v = [2, 0, 0]");
    let e = rejected(&format!("{BASE}{FLOOR}[sky]\ntype = 5\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\n{flat}"));
    assert_error(&e, "[[window]] \"roof\" (#1)", "edge_v", &["no area"]);
}

#[test]
fn a_window_of_cie_171_glass_is_read_and_its_mistakes_named() {
    let sky = "[sky]\ntype = 5\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\n";
    let scene = parse(&format!("{BASE}{FLOOR}{sky}{WINDOW}glass = \"cie171\"\n")).unwrap_or_else(|e| panic!("{e}"));
    match &scene.luminaires[0].kind {
        LuminaireKind::Window { window, .. } => assert_eq!(window.glazing, Some(Glazing::Cie171)),
        other => panic!("{other:?}"),
    }
    let fresnel = parse(&format!("{BASE}{FLOOR}{sky}{WINDOW}glass = \"fresnel\"\ntransmittance = 0.88\n"));
    match &fresnel.unwrap_or_else(|e| panic!("{e}")).luminaires[0].kind {
        LuminaireKind::Window { window, .. } => assert!(matches!(window.glazing, Some(Glazing::Fresnel(_)))),
        other => panic!("{other:?}"),
    }
    let window = "[[window]] \"roof\" (#1)";
    let both = format!("{BASE}{FLOOR}{sky}{WINDOW}glass = \"cie171\"\ntransmittance = 0.88\n");
    assert_error(&rejected(&both), window, "transmittance", &["cie171"]);
    let panes = format!("{BASE}{FLOOR}{sky}{WINDOW}glass = \"cie171\"\npanes = 2\n");
    assert_error(&rejected(&panes), window, "panes", &["cie171"]);
    let bare = format!("{BASE}{FLOOR}{sky}{WINDOW}glass = \"fresnel\"\n");
    assert_error(&rejected(&bare), window, "transmittance", &["normal transmittance"]);
    let misspelt = rejected(&format!("{BASE}{FLOOR}{sky}{WINDOW}glass = \"cie-171\"\n"));
    assert_eq!(misspelt.key(), "glass", "{misspelt}");
    assert!(misspelt.message().contains("cie171") && misspelt.message().contains("line "), "{misspelt}");
}
