//! `[[probe]]` kinds (issue 17, item 7): each kind's keys and defaults, and every mistake
//! named by its table and key.

use super::{assert_error, lit, parse, rejected};
use glam::DVec3;
use ugo::scene::ProbeKind;

const PROBE: &str = "[[probe]] \"p\" (#1)";

fn probe(keys: &str) -> String {
    lit(&format!("[[probe]]\nname = \"p\"\nposition = [0, 1, 0]\n{keys}\n"))
}

#[test]
fn every_kind_takes_its_keys_and_defaults() {
    let scene = parse(&probe("normal = [0, 2, 0]")).unwrap();
    assert_eq!((scene.probes[0].kind, scene.probes[0].normal), (ProbeKind::Point, DVec3::Y), "point by default");
    let scene = parse(&probe("kind = \"luminance_meter\"\ndirection = [0, 0, -3]")).unwrap();
    assert_eq!(scene.probes[0].kind, ProbeKind::LuminanceMeter { fov_deg: 1.0 }, "1° by default");
    assert_eq!(scene.probes[0].normal, DVec3::NEG_Z);
    let scene = parse(&probe("kind = \"cylindrical\"")).unwrap();
    assert_eq!((scene.probes[0].kind, scene.probes[0].normal), (ProbeKind::Cylindrical, DVec3::Y), "vertical");
    let scene = parse(&probe("kind = \"semi_cylindrical\"\ndirection = [2, 5, 0]")).unwrap();
    assert_eq!(scene.probes[0].kind, ProbeKind::SemiCylindrical { axis: DVec3::Y });
    assert!((scene.probes[0].normal - DVec3::X).length() < 1e-15, "the facing direction, across the axis");
}

#[test]
fn bad_kinds_and_keys_are_named() {
    let error = rejected(&probe("kind = \"goniometer\""));
    assert_error(&error, PROBE, "kind", &["\"goniometer\"", "\"luminance_meter\"", "\"semi_cylindrical\""]);
    assert_error(&rejected(&probe("")), PROBE, "normal", &["needs `normal`"]);
    let error = rejected(&probe("kind = \"cylindrical\"\nnormal = [0, 1, 0]"));
    assert_error(&error, PROBE, "normal", &["a \"cylindrical\" probe takes only axis"]);
    let error = rejected(&probe("kind = \"luminance_meter\"\ndirection = [0, 0, 1]\nfov_deg = 0"));
    assert_error(&error, PROBE, "fov_deg", &["greater than 0 and at most 180"]);
    let error = rejected(&probe("kind = \"semi_cylindrical\"\ndirection = [0, -1, 0]"));
    assert_error(&error, PROBE, "direction", &["parallel to the axis"]);
    let error = rejected(&probe("kind = \"luminance_meter\"\ndirection = [0, 0, 1]\nfov = 2"));
    assert!(error.key() == "fov" && error.message().contains("line"), "{error}");
}
