//! `ugo solve --basis …` and `ugo compare --bases …` end to end, and clear refusals.

use crate::support::{scratch, ugo};

fn text(o: &std::process::Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

const COARSE: [&str; 4] = ["--patch-size", "0.15", "--directions", "16"];

#[test]
fn solve_in_a_basis_writes_the_coefficients_and_the_factors() {
    let dir = scratch("basis-solve");
    let h5 = dir.join("glossy.h5");
    let args = [
        &["solve", "cases/glossy-cornell.toml", "--basis", "sh", "--lmax", "1", "-o", h5.to_str().unwrap()],
        &COARSE[..],
    ];
    let o = ugo(&args.concat());
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("sh:1") && text(&o).contains("residual of the field in the full system"), "{}", text(&o));
    let file = hdf5::File::open(&h5).unwrap();
    let c = file.dataset("basis/coefficients").unwrap().read_2d::<f64>().unwrap();
    let n = file.dataset("mesh/areas").unwrap().read_1d::<f64>().unwrap().len();
    assert_eq!(c.shape(), [n, 4]);
    let psi = file.dataset("basis/psi").unwrap().read_dyn::<f64>().unwrap();
    assert_eq!(psi.shape()[1..], [16, 4]);
    let rank: f64 = file.group("basis").unwrap().attr("rank").unwrap().read_scalar().unwrap();
    assert_eq!(rank, 4.0);
}

#[test]
fn compare_tables_the_bases_against_the_full_solution() {
    let dir = scratch("basis-compare");
    let plot = dir.join("bases.png");
    let args = [
        &["compare", "cases/glossy-cornell.toml", "--methods", "gmres", "--bases", "full,sh:0,sh:1,svd:1,svd:4"][..],
        &["--plot", plot.to_str().unwrap()],
        &COARSE[..],
    ];
    let o = ugo(&args.concat());
    assert!(o.status.success(), "{}", text(&o));
    for row in ["full", "sh:0", "sh:1", "svd:1", "svd:4"] {
        assert!(text(&o).lines().any(|l| l.trim_start().starts_with(row)), "no row {row}: {}", text(&o));
    }
    assert!(image::open(&plot).is_ok());
}

#[test]
fn bad_basis_options_are_refused_clearly() {
    // A writable output (checked before the work) that the refused solves never write.
    let dir = scratch("bad-basis");
    let out = dir.join("x.h5");
    for (args, expected) in [
        (vec!["--basis", "sh"], "--lmax"),
        (vec!["--basis", "svd", "--rank", "0"], "--rank R ≥ 1"),
        (vec!["--basis", "wavelet", "--rank", "2"], "`sh` or `svd`"),
        (vec!["--basis", "sh", "--lmax", "4"], "only 16 cells"),
    ] {
        let all =
            [&["solve", "cases/glossy-cornell.toml", "-o", out.to_str().unwrap()][..], &COARSE[..], &args[..]].concat();
        let o = ugo(&all);
        assert!(!o.status.success() && !text(&o).contains("panicked"), "{args:?}: {}", text(&o));
        assert!(text(&o).contains(expected), "{args:?}: {}", text(&o));
    }
    let o = ugo(&["compare", "cases/glossy-cornell.toml", "--bases", "full,sh"]);
    assert!(!o.status.success() && text(&o).contains("unknown basis \"sh\""), "{}", text(&o));
}
