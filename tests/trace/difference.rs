//! `ugo agree --difference` (issue 34): the picture of `(x − m)/m` per pixel has the traced
//! image's size (magnified), its colour follows the sign and the scale of a known
//! difference, a difference within 2 standard errors is grey, and a reference that is no
//! image or a path that cannot be written is refused before any work.

use crate::support::{scratch, ugo};
use std::path::Path;
use ugo::io::{LEGEND_WIDTH, WITHIN_NOISE, magnification, write_exr};
use ugo::render::Image;

/// The furnace box's 32×32 camera sees 5 cd/m² everywhere: a reference of `5/factor` with
/// standard error `error` everywhere, as `ugo trace` writes it (`X.exr`, `X-stderr.exr`).
fn reference(dir: &Path, name: &str, factor: f64, error: f64) -> String {
    let image = |v: f64| Image { width: 32, height: 32, luminance: vec![v; 32 * 32] };
    let mean = dir.join(format!("{name}.exr"));
    write_exr(&mean, &image(5.0 / factor)).unwrap();
    write_exr(&dir.join(format!("{name}-stderr.exr")), &image(error)).unwrap();
    mean.to_str().unwrap().to_string()
}

/// The colour of the picture's centre pixel, after `ugo agree --difference` wrote it.
fn centre(solution: &str, reference: &str, png: &Path, scale: &str) -> [u8; 3] {
    let p = png.to_str().unwrap();
    let o = ugo(&["agree", solution, reference, "--samples", "4", "--difference", p, "--difference-scale", scale]);
    let printed = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{printed}{}", String::from_utf8_lossy(&o.stderr));
    assert!(printed.contains("difference image") && printed.contains(png.to_str().unwrap()), "{printed}");
    let picture = image::open(png).unwrap().to_rgb8();
    let k = magnification(32, 32) as u32;
    assert!(k > 1, "a 32×32 image is magnified");
    assert_eq!(picture.dimensions(), (32 * k + LEGEND_WIDTH, (32 * k).max(240)));
    picture.get_pixel(16 * k + k / 2, 16 * k + k / 2).0
}

#[test]
fn the_difference_picture_follows_the_sign_and_scale_of_a_known_difference() {
    let dir = scratch("difference");
    let solved = dir.join("solved.h5");
    let s = solved.to_str().unwrap();
    let o = ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "0.25", "-o", s]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    // the solution 10 % above the reference: saturated red at ±5 %, a light red at ±50 %
    let above = reference(&dir, "above", 1.1, 1e-3);
    let red = centre(s, &above, &dir.join("above.png"), "5");
    assert_eq!(red, [160, 10, 20], "the top of the diverging scale");
    let light = centre(s, &above, &dir.join("above-50.png"), "50");
    assert!(light[0] > 230 && light[1] > 150 && light[1] < 240 && light[0] > light[2] + 30, "{light:?}");
    // 10 % below: saturated blue
    let below = reference(&dir, "below", 0.9, 1e-3);
    assert_eq!(centre(s, &below, &dir.join("below.png"), "5"), [5, 48, 160], "the bottom of the diverging scale");
    // 10 % above but within 2 standard errors of a noisy reference: grey
    let noisy = reference(&dir, "noisy", 1.1, 0.5);
    assert_eq!(centre(s, &noisy, &dir.join("noisy.png"), "5"), [WITHIN_NOISE.0, WITHIN_NOISE.1, WITHIN_NOISE.2]);
}

#[test]
fn a_difference_needs_a_traced_image_and_a_writable_path() {
    let dir = scratch("difference-refused");
    let solved = dir.join("solved.h5");
    let s = solved.to_str().unwrap();
    assert!(ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "0.25", "-o", s]).status.success());
    let image = reference(&dir, "image", 1.0, 1e-3);
    let refused = |args: &[&str]| {
        let o = ugo(&[&["agree", s][..], args].concat());
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        assert!(!o.status.success() && err.starts_with("ugo: error:") && !err.contains("panicked"), "{err}");
        assert!(!String::from_utf8_lossy(&o.stdout).contains("rms z"), "refused before the comparison");
        err
    };
    let png = dir.join("d.png");
    let p = png.to_str().unwrap();
    assert!(refused(&[s, "--difference", p]).contains("--difference draws a traced image's pixels"));
    let missing = dir.join("no-such-folder/d.png");
    let err = refused(&[&image, "--difference", missing.to_str().unwrap()]);
    assert!(err.contains("no-such-folder") && err.contains("does not exist"), "{err}");
    assert!(refused(&[&image, "--difference", dir.to_str().unwrap()]).contains("it is a folder"));
    assert!(refused(&[&image, "--difference", p, "--difference-scale", "0"]).contains("--difference-scale"));
    assert!(!png.exists());
}
