//! Malformed photometric files are refused with an error that names the file, the line
//! and what was expected there, never a panic.

use super::data;
use std::path::Path;
use ugo::photometry::{PhotometryError, parse_ies, parse_ldt};

fn text(name: &str) -> String {
    std::fs::read_to_string(data(name)).unwrap()
}

/// The 1-based number of the first line of `text` equal to `line` (trimmed).
fn line_of(text: &str, line: &str) -> usize {
    text.lines().position(|l| l.trim() == line).unwrap_or_else(|| panic!("no line {line:?}")) + 1
}

/// `text` with its `n`-th line (1-based) replaced by `with`.
fn replace_line(text: &str, n: usize, with: &str) -> String {
    text.lines().enumerate().map(|(i, l)| if i + 1 == n { with } else { l }).collect::<Vec<_>>().join("\n")
}

fn check(result: Result<ugo::photometry::IntensityDistribution, PhotometryError>, line: usize, fragments: &[&str]) {
    let error = result.expect_err("a malformed file was accepted");
    let shown = error.to_string();
    assert_eq!(error.line(), Some(line), "{shown}");
    assert!(shown.starts_with(&format!("bad.file: line {line}: ")), "{shown}");
    for fragment in fragments {
        assert!(shown.contains(fragment), "{shown:?} lacks {fragment:?}");
    }
}

fn ies(text: &str) -> Result<ugo::photometry::IntensityDistribution, PhotometryError> {
    parse_ies(Path::new("bad.file"), text)
}

fn ldt(text: &str) -> Result<ugo::photometry::IntensityDistribution, PhotometryError> {
    parse_ldt(Path::new("bad.file"), text)
}

#[test]
fn ies_truncated_candela_values() {
    let t = text("c-bilateral-0-180-2002.ies");
    let cut: Vec<&str> = t.lines().collect();
    let cut = cut[..cut.len() - 2].join("\n");
    let last = cut.lines().count();
    check(ies(&cut), last, &["expected candela value", "horizontal angle 180°", "end of the file"]);
}

#[test]
fn ies_non_monotonic_angles() {
    let t = text("c-bilateral-0-180-2002.ies");
    let at = line_of(&t, "15 20 25");
    check(ies(&replace_line(&t, at, "15 12 25")), at, &["vertical angles must increase", "12°, after 15°"]);
    let at = line_of(&t, "45 60 75");
    check(ies(&replace_line(&t, at, "45 60 60")), at, &["horizontal angles must increase"]);
}

#[test]
fn ies_unknown_symmetry() {
    let t = text("c-quadrant-1995.ies");
    let at = line_of(&t, "0 15 30 45 60 75 90");
    let bad = replace_line(&t, at, "0 15 30 45 60 75 120");
    check(ies(&bad), at, &["horizontal angles 0…120° imply no known symmetry", "type C"]);
    let b = text("b-front-2002.ies").replacen("-90 -85 -80", "-80 -85 -80", 1);
    assert!(ies(&b).is_err());
}

#[test]
fn ies_wrong_counts() {
    let t = text("c-axial-lambert-2002.ies");
    let header = line_of(&t, "1 3141.5927 1 19 1 1 2 0 0 0");
    let fewer = replace_line(&t, header, "1 3141.5927 1 18 1 1 2 0 0 0");
    let last = t.lines().count();
    check(ies(&fewer), last, &["unexpected '87.1557' after the 1 × 18 candela values", "counts"]);
    let more = replace_line(&t, header, "1 3141.5927 1 19 2 1 2 0 0 0");
    check(ies(&more), header + 5, &["horizontal angle 2 of 2", "got 1000"]);
    let zero = replace_line(&t, header, "1 3141.5927 1 1 1 1 2 0 0 0");
    check(ies(&zero), header, &["number of vertical angles (2 to 100000), got 1"]);
}

#[test]
fn ies_bad_values_and_header() {
    let t = text("c-axial-lambert-2002.ies");
    let values = line_of(&t, "1000 996.1947 984.8078 965.9258 939.6926 906.3078 866.0254 819.152 766.0444 707.1068");
    check(ies(&replace_line(&t, values, "1000 996 98x4 965")), values, &["expected candela value 3 of 19", "'98x4'"]);
    check(ies(&replace_line(&t, values, "1000 -996")), values, &["candela value 2 of 19", "at least 0"]);
    check(ies(&replace_line(&t, 1, "IESNA:LM-63-2077")), 1, &["expected the version line", "LM-63-2077"]);
    let header = line_of(&t, "1 3141.5927 1 19 1 1 2 0 0 0");
    check(ies(&replace_line(&t, header, "1 3141.5927 1 19 1 4 2 0 0 0")), header, &["photometric type", "got 4"]);
    check(ies(&replace_line(&t, header, "1 0 1 19 1 1 2 0 0 0")), header, &["−1 for absolute photometry"]);
    let tilt = line_of(&t, "TILT=NONE");
    check(ies(&replace_line(&t, tilt, "TILT=lamp.tlt")), tilt, &["TILT=NONE or TILT=INCLUDE", "LAMP.TLT"]);
    check(ies(&replace_line(&t, tilt, "NO TILT")), t.lines().count(), &["expected a TILT= line"]);
}

#[test]
fn ies_bad_tilt_record() {
    let t = text("c-isotropic-tilt-2002.ies");
    let angles = line_of(&t, "0 45 90");
    check(ies(&replace_line(&t, angles, "0 45 30")), angles, &["tilt angles must increase"]);
    let geometry = line_of(&t, "TILT=INCLUDE") + 1;
    check(ies(&replace_line(&t, geometry, "7")), geometry, &["lamp-to-luminaire geometry", "1 to 3"]);
}

#[test]
fn ldt_unknown_symmetry_indicator() {
    let t = text("isym4-quadrant.ldt");
    check(ldt(&replace_line(&t, 3, "5")), 3, &["symmetry indicator Isym", "0 to 4", "got 5"]);
}

#[test]
fn ldt_truncated_intensities() {
    let t = text("isym2-c0-c180.ldt");
    let cut: Vec<&str> = t.lines().collect();
    let cut = cut[..cut.len() - 3].join("\n");
    let last = cut.lines().count();
    check(ldt(&cut), last, &["expected intensity 17 of 19 in plane C180°", "end of the file"]);
}

#[test]
fn ldt_non_monotonic_gamma_angles() {
    let t = text("isym3-c90-c270.ldt");
    let first_gamma = line_of(&t, "345") + 1;
    check(
        ldt(&replace_line(&t, first_gamma + 3, "5")),
        first_gamma + 3,
        &["γ-angles must increase", "γ-angle 4 of 19"],
    );
}

#[test]
fn ldt_counts_that_do_not_match_the_symmetry() {
    let t = text("isym3-c90-c270.ldt");
    let first_c = line_of(&t, "345") - 23;
    let gap = replace_line(&t, first_c + 18, "275");
    check(ldt(&gap), first_c, &["with Isym 3 (line 3)", "13 C-planes from C90° to C270°", "hold 12", "end planes"]);
    let extra = format!("{t}12.5\n");
    check(ldt(&extra), t.lines().count() + 1, &["unexpected '12.5' after the 13 × 19 intensities"]);
}

#[test]
fn ldt_text_where_a_number_belongs() {
    let t = text("isym0-none.ldt");
    check(ldt(&replace_line(&t, 29, "1O00")), 29, &["total flux of lamp set 1", "'1O00'"]);
    check(ldt(&replace_line(&t, 4, "twenty-four")), 4, &["number of C-planes Mc", "'twenty-four'"]);
}

#[test]
fn a_missing_file_is_named() {
    let error = ugo::photometry::read_ies(Path::new("tests/data/photometry/none.ies")).unwrap_err();
    assert_eq!(error.line(), None);
    assert!(error.to_string().contains("none.ies: cannot read the file"), "{error}");
}

#[test]
fn ies_1995_photometric_factor_must_be_positive() {
    let t = text("c-quadrant-1995.ies");
    let n = line_of(&t, "1 1 10");
    for factor in ["0", "-1"] {
        let bad = replace_line(&t, n, &format!("1 {factor} 10"));
        check(ies(&bad), n, &["expected the ballast-lamp photometric factor (greater than 0)"]);
    }
}

#[test]
fn ies_values_that_overflow_with_their_multiplier_are_refused() {
    let t = text("c-quadrant-1995.ies");
    let n = line_of(&t, "1 3141.5927 1 19 7 1 2 0 0 0");
    let bad = replace_line(&t, n, "1 3141.5927 1e306 19 7 1 2 0 0 0");
    check(ies(&bad), n, &["overflow"]);
}

#[test]
fn ldt_light_output_ratio_must_be_a_percentage() {
    let t = text("isym1-axial-isotropic.ldt");
    // LORL is line 23, the conversion factor line 24.
    for lorl in ["1e308", "-5", "100.5"] {
        check(ldt(&replace_line(&t, 23, lorl)), 23, &["LORL (0 to 100 %)"]);
    }
    check(ldt(&replace_line(&t, 24, "1e306")), 24, &["overflow"]);
}
