//! What `E / E_h` is called and where it is written (issue 37, point 3): the daylight
//! factor DF under a sky that does not depend on the sun (overcast, uniform) with no sun,
//! the daylight ratio DR otherwise; in % in the summary, both CSVs, a plan and `/daylight`.
//! A sky that does not use the sun is accepted without its position.

use crate::support::{corner_factor, scratch, ugo};
use ugo::scene::Scene;

/// A 1 × 1 m floor under a 1 × 1 m roof opening 1 m above it, a probe at its centre and a
/// grid on it, under `sky`.
fn case(sky: &str) -> String {
    format!(
        "[discretization]\npatch_size = 0.25\n[[material]]\nname = \"white\"\ntype = \"lambert\"\nreflectance = 0.5\n\
         [[surface]]\nname = \"floor\"\nshape = \"rectangle\"\nmaterial = \"white\"\norigin = [0, 0, 0]\n\
         edge_u = [0, 0, 1]\nedge_v = [1, 0, 0]\n[sky]\n{sky}\n\
         [[window]]\nname = \"roof\"\norigin = [0, 1, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\n\
         [[probe]]\nname = \"centre\"\nposition = [0.5, 0, 0.5]\nnormal = [0, 1, 0]\n\
         [[grid]]\nname = \"floor\"\norigin = [0, 0, 0]\nedge_u = [0, 0, 1]\nedge_v = [1, 0, 0]\nresolution = [2, 2]\n"
    )
}

/// Solves `sky`'s case; the summary, the probes' and the grid's CSV rows (header first).
fn solved(name: &str, sky: &str) -> (String, Vec<Vec<String>>, Vec<Vec<String>>, hdf5::File) {
    let dir = scratch(name);
    let path = dir.write("room.toml", &case(sky));
    let h5 = dir.join("room.h5");
    let o = ugo(&["solve", path.to_str().unwrap(), "-o", h5.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success(), "{out}{}", String::from_utf8_lossy(&o.stderr));
    let rows = |file: &str| -> Vec<Vec<String>> {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        text.lines().filter(|l| !l.starts_with('#')).map(|l| l.split(',').map(str::to_string).collect()).collect()
    };
    let (probes, grid) = (rows("room-probes.csv"), rows("room-floor.csv"));
    let symbol = if out.contains("DF the daylight factor") { "DF" } else { "DR" };
    assert!(dir.join(format!("room-floor-{symbol}.png")).exists(), "the {symbol} plan");
    (out, probes, grid, hdf5::File::open(&h5).unwrap())
}

fn column(rows: &[Vec<String>], name: &str) -> Vec<f64> {
    let at = rows[0].iter().position(|c| c == name).unwrap_or_else(|| panic!("no {name} in {:?}", rows[0]));
    rows[1..].iter().map(|r| r[at].parse().unwrap()).collect()
}

#[test]
fn under_the_uniform_sky_e_over_e_h_is_the_daylight_factor_in_percent_everywhere() {
    let (out, probes, grid, file) = solved("df-uniform", "type = \"uniform\"");
    assert!(out.contains("DF %") && out.contains("DF_avg %") && !out.contains("DR"), "{out}");
    // the uniform sky of E_h = 10 000 lx through the opening straight above: DF = 100 F,
    // F the factor to a 1 × 1 m square 1 m above its centre (four corner factors)
    let exact = 100.0 * 4.0 * corner_factor(0.5, 0.5, 1.0);
    let df = column(&probes, "DF_pct")[0];
    assert!((df / exact - 1.0).abs() < 1e-3, "DF {df} %, exact {exact} %");
    for (e, df) in column(&grid, "E_lx").iter().zip(column(&grid, "DF_pct")) {
        assert!((df - e / 100.0).abs() < 1e-9 * df.max(1.0), "DF {df} % from {e} lx");
    }
    let quantity: hdf5::types::VarLenUnicode =
        file.group("daylight").unwrap().attr("quantity").unwrap().read_scalar().unwrap();
    assert_eq!(quantity.as_str(), "daylight factor");
}

#[test]
fn under_a_clear_sky_with_the_sun_it_is_the_daylight_ratio() {
    let (out, probes, grid, file) =
        solved("dr-clear", "type = \"clear\"\nsun_altitude_deg = 60\nsun_azimuth_deg = 180\nsun_illuminance = 50000");
    assert!(out.contains("DR %") && out.contains("not the daylight factor") && !out.contains("DF %"), "{out}");
    assert!(column(&probes, "DR_pct")[0] > 0.0 && column(&grid, "DR_pct").len() == 4);
    let quantity: hdf5::types::VarLenUnicode =
        file.group("daylight").unwrap().attr("quantity").unwrap().read_scalar().unwrap();
    assert_eq!(quantity.as_str(), "daylight ratio");
}

#[test]
fn a_sky_that_does_not_use_the_sun_needs_no_position_and_one_that_does_is_refused_without() {
    let parse = |sky: &str| Scene::parse(std::path::Path::new("cases/test.toml"), case(sky));
    for sky in ["type = \"overcast\"", "type = 1", "type = 3", "type = \"uniform\""] {
        let scene = parse(sky).unwrap_or_else(|e| panic!("{sky}: {e}"));
        assert!(scene.sky.unwrap().gives_daylight_factor(), "{sky}");
    }
    for sky in ["type = \"clear\"", "type = 2", "type = \"overcast\"\nsun_illuminance = 50000"] {
        let error = parse(sky).expect_err(sky).to_string();
        assert!(error.contains("sun_altitude_deg") && error.contains("depends on where the sun is"), "{error}");
    }
    let sunny =
        parse("type = \"overcast\"\nsun_altitude_deg = 60\nsun_azimuth_deg = 0\nsun_illuminance = 5e4").unwrap();
    assert!(!sunny.sky.unwrap().gives_daylight_factor(), "the sun shines: a daylight ratio");
}

/// A `[[window]]` below the floor, whose light lands on no surface, is warned about, and
/// the summary's imbalance is not NaN (issue 37, point 7).
#[test]
fn a_window_no_surface_sees_is_warned_about_and_the_imbalance_is_not_nan() {
    let turned = case("type = \"overcast\"").replace(
        "origin = [0, 1, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]",
        "origin = [0, -1, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]",
    );
    let dir = scratch("dark-window");
    let path = dir.write("room.toml", &turned);
    let h5 = dir.join("room.h5");
    let o = ugo(&["solve", path.to_str().unwrap(), "-o", h5.to_str().unwrap()]);
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{out}{err}");
    assert!(err.contains("window \"roof\" lets in no light"), "{err}");
    assert!(!out.contains("NaN") && out.contains("nothing emitted"), "{out}");
}
