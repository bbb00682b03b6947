//! Every fixed-length array key of the format (points, directions, pairs) is refused with
//! another number of components, naming the table, the key and the line (issue 18, item
//! 1: serde alone keeps the first three numbers of `[x, y, z, w]` and drops the rest).

use super::{BASE, LAMP, assert_error, lit, rejected};

/// `(table header, table as it would be numbered, the table's keys with {V} at the key
/// under test)`, one entry per array key.
fn cases() -> Vec<(&'static str, &'static str, String)> {
    let rect = |k: &str| {
        let keys = [("origin", "[0, 0, 0]"), ("edge_u", "[1, 0, 0]"), ("edge_v", "[0, 0, 1]")];
        let body: String = keys.iter().map(|(n, v)| format!("{n} = {}\n", if *n == k { "{V}" } else { v })).collect();
        format!("[[surface]]\nname = \"r\"\nshape = \"rectangle\"\nmaterial = \"white\"\n{body}")
    };
    let mut out = Vec::new();
    for k in ["origin", "edge_u", "edge_v"] {
        out.push(("[[surface]] #2", k, rect(k)));
    }
    let shaped = |shape: &str, keys: &str| {
        format!("[[surface]]\nname = \"s\"\nshape = \"{shape}\"\nmaterial = \"white\"\n{keys}")
    };
    out.push(("[[surface]] #2", "min", shaped("box", "min = {V}\nmax = [1, 1, 1]\n")));
    out.push(("[[surface]] #2", "max", shaped("box", "min = [0, 0, 0]\nmax = {V}\n")));
    out.push(("[[surface]] #2", "center", shaped("sphere", "center = {V}\nradius = 1\n")));
    out.push(("[[surface]] #2", "normal", shaped("disc", "center = [0, 0, 0]\nnormal = {V}\nradius = 1\n")));
    out.push(("[[surface]] #2", "vertices", shaped("polygon", "vertices = [[0, 0, 0], {V}, [0, 1, 0]]\n")));
    out.push(("[[surface]] #2", "translate", shaped("obj", "file = \"x.obj\"\ntranslate = {V}\n")));
    let probe = |k: &str| {
        let (p, n) = if k == "position" { ("{V}", "[0, 1, 0]") } else { ("[0, 0, 0]", "{V}") };
        format!("[[probe]]\nname = \"p\"\nposition = {p}\nnormal = {n}\n")
    };
    out.push(("[[probe]] #1", "position", probe("position")));
    out.push(("[[probe]] #1", "normal", probe("normal")));
    let camera = |k: &str| {
        let keys =
            [("position", "[0, 1, -2]"), ("look_at", "[0, 1, 0]"), ("up", "[0, 1, 0]"), ("resolution", "[8, 8]")];
        let body: String = keys.iter().map(|(n, v)| format!("{n} = {}\n", if *n == k { "{V}" } else { v })).collect();
        format!("[[camera]]\nname = \"c\"\n{body}")
    };
    for k in ["position", "look_at", "up", "resolution"] {
        out.push(("[[camera]] #1", k, camera(k)));
    }
    let grid = |k: &str| {
        let keys = [
            ("origin", "[0, 0, 0]"),
            ("edge_u", "[1, 0, 0]"),
            ("edge_v", "[0, 0, 1]"),
            ("resolution", "[4, 4]"),
            ("normal", "[0, 1, 0]"),
        ];
        let body: String = keys.iter().map(|(n, v)| format!("{n} = {}\n", if *n == k { "{V}" } else { v })).collect();
        format!("[[grid]]\nname = \"g\"\n{body}")
    };
    for k in ["origin", "edge_u", "edge_v", "resolution", "normal"] {
        out.push(("[[grid]] #1", k, grid(k)));
    }
    let lum = |kind: &str, keys: &str| format!("[[luminaire]]\nname = \"l\"\ntype = \"{kind}\"\n{keys}");
    out.push(("[[luminaire]] #1", "position", lum("isotropic", "flux = 1\nposition = {V}\n")));
    out.push(("[[luminaire]] #1", "aim", lum("lambertian", "intensity = 1\nposition = [0, 1, 0]\naim = {V}\n")));
    out.push(("[[luminaire]] #1", "direction", lum("parallel", "illuminance = 1\ndirection = {V}\n")));
    out
}

#[test]
fn every_array_key_refuses_another_length_naming_table_key_and_line() {
    let cases = cases();
    assert_eq!(cases.len(), 23);
    for (table, key, body) in cases {
        let pair = key == "resolution";
        let lengths: [(&str, usize); 2] =
            if pair { [("[8, 8, 8]", 3), ("[8]", 1)] } else { [("[0, 1, 0, 1]", 4), ("[0, 1]", 2)] };
        for (value, n) in lengths {
            let text = format!("{BASE}{LAMP}\n{}", body.replace("{V}", value));
            let line = text.lines().position(|l| l.contains(value)).unwrap() + 1;
            let error = rejected(&text);
            let expected =
                if pair { "expected an array of 2 numbers" } else { "expected an array of 3 numbers [x, y, z]" };
            let fragments = [format!("line {line}"), format!("invalid length {n}"), expected.to_string()];
            let fragments: Vec<&str> = fragments.iter().map(String::as_str).collect();
            assert_error(&error, table, key, &fragments);
        }
    }
}

#[test]
fn three_components_are_still_accepted() {
    super::parse(&lit("")).unwrap();
}
