//! Messages that name what to change (issue 37, point 7): a size refusal names the case
//! file and its keys, in exponent form and without "inf"; `--directions -1` says what is
//! valid; a file without `/field` is said to be no solution; `ugo agree` on two scenes says
//! they differ; an IES candela value out of range names its file and line.

use super::assert_clean_failure;
use crate::support::{scratch, ugo};

const FURNACE: &str = include_str!("../../cases/furnace-box.toml");

#[test]
fn a_size_refusal_names_the_case_file_and_its_key() {
    let dir = scratch("size-key");
    let case = dir.write("tiny.toml", &FURNACE.replace("patch_size = 0.1", "patch_size = 1e-300"));
    let err = assert_clean_failure(&ugo(&["info", case.to_str().unwrap()]));
    assert!(err.contains("tiny.toml at [discretization] patch_size = 1e-300 m"), "{err}");
    assert!(!err.contains("inf") && !err.contains("000000000"), "{err}");
    let err =
        assert_clean_failure(&ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "1e-4", "-o", "/dev/null"]));
    assert!(err.contains("cases/furnace-box.toml at --patch-size 0.0001 m"), "{err}");
}

#[test]
fn a_negative_direction_count_is_answered_with_the_valid_values() {
    let err =
        String::from_utf8_lossy(&ugo(&["info", "cases/furnace-box.toml", "--directions", "-1"]).stderr).into_owned();
    assert!(err.contains("--directions must be a cell count from 1 to 65535") && !err.contains("tip:"), "{err}");
}

#[test]
fn a_file_without_field_is_said_to_be_no_solution() {
    let dir = scratch("no-field");
    let file = dir.join("other.h5");
    hdf5::File::create(&file).unwrap().create_group("mesh").unwrap();
    let err = assert_clean_failure(&ugo(&["render", file.to_str().unwrap(), "-o", dir.to_str().unwrap()]));
    assert!(err.contains("other.h5 has no /field: not a ugo solution, or written by an older version"), "{err}");
}

#[test]
fn agree_on_two_scenes_says_they_differ() {
    let dir = scratch("two-scenes");
    let solution = dir.join("res.h5");
    assert!(ugo(&["solve", "cases/furnace-box.toml", "-o", solution.to_str().unwrap()]).status.success());
    let other = dir.write("darker.toml", &FURNACE.replace("reflectance = 0.8", "reflectance = 0.5"));
    let forward = dir.join("forward.h5");
    let traced =
        ugo(&["trace", other.to_str().unwrap(), "--forward", "--photons", "10000", "-o", forward.to_str().unwrap()]);
    assert!(traced.status.success(), "{}", String::from_utf8_lossy(&traced.stderr));
    let err = assert_clean_failure(&ugo(&["agree", solution.to_str().unwrap(), forward.to_str().unwrap()]));
    assert!(err.contains("the two files hold different scenes (reflectances differ)"), "{err}");
    assert!(err.contains("darker.toml") && !err.contains("discretize"), "{err}");
}

#[test]
fn an_ies_candela_value_out_of_range_names_its_line() {
    let dir = scratch("candela");
    let case = std::fs::read_to_string("cases/cie171/5.2-point-source.toml").unwrap();
    let ies = std::fs::read_to_string("cases/cie171/lambert-1000cd.ies").unwrap();
    dir.write("huge.ies", &ies.replacen("\n1000 ", "\n1e19 ", 1));
    let case = dir.write("huge.toml", &case.replace("lambert-1000cd.ies", "huge.ies"));
    let err = assert_clean_failure(&ugo(&["info", case.to_str().unwrap()]));
    assert!(err.contains("huge.ies: line 13: expected candela value 1 of 19"), "{err}");
    assert!(err.contains("got 1e19"), "{err}");
}
