//! The half width of a glossy lobe (`MaterialModel::lobe_width`), which the gather cuts
//! glossy pieces by (`readout/gather.rs`): at that angle from the lobe's axis the specular
//! part is half its peak, against the models' own functions.

use super::{LAMBERT, MIRROR, ggx, phong};
use std::f64::consts::FRAC_PI_2;
use ugo::material::ggx::distribution;

#[test]
fn a_phong_lobe_halves_at_its_half_width() {
    for n in [1.0, 10.0, 50.0, 1000.0] {
        let width = phong(n).lobe_width().expect("Phong has a lobe");
        let half = width.cos().powf(n);
        eprintln!("Phong n = {n}: half width {:.4} rad, cosⁿ there {half:.12}", width);
        assert!((half - 0.5).abs() < 1e-12, "n = {n}: {half}");
    }
}

#[test]
fn a_ggx_lobe_halves_at_its_half_width_of_the_reflected_direction() {
    for alpha in [0.05, 0.2, 0.5] {
        let width = ggx(alpha).lobe_width().expect("GGX has a lobe");
        // the reflected direction turns by twice the half vector
        let a2 = alpha * alpha;
        let ratio = distribution(a2, (0.5 * width).cos()) / distribution(a2, 1.0);
        eprintln!("GGX α = {alpha}: half width {width:.4} rad, D(h)/D(0) there {ratio:.12}");
        assert!((ratio - 0.5).abs() < 1e-12, "α = {alpha}: {ratio}");
    }
    // so rough that D never halves over the hemisphere of half vectors
    assert_eq!(ggx(0.9).lobe_width(), Some(FRAC_PI_2));
}

#[test]
fn lambertian_surfaces_and_mirrors_have_no_lobe() {
    assert_eq!(LAMBERT.lobe_width(), None);
    assert_eq!(MIRROR.lobe_width(), None);
}
