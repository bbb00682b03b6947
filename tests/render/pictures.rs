//! False-colour maps and reflection-order pictures: scale positions, end colours, the PNGs written.

use crate::support::scratch;
use ugo::io::{LEGEND_WIDTH, Scale, colour, position, write_false_colour};
use ugo::render::Image;

#[test]
fn positions_follow_the_linear_and_the_log_scale() {
    assert_eq!(position(5.0, 0.0, 10.0, Scale::Linear), 0.5);
    assert!((position(10.0, 1.0, 100.0, Scale::Log) - 0.5).abs() < 1e-15);
    assert_eq!(position(0.0, 1.0, 100.0, Scale::Log), 0.0, "below the scale is its bottom");
    assert_eq!(colour(0.0), colour(-1.0));
    assert_eq!(colour(1.0), colour(2.0));
    assert_ne!(colour(0.0), colour(1.0));
}

#[test]
fn a_uniform_image_maps_to_one_colour_beside_its_legend() {
    let image = Image { width: 8, height: 6, luminance: vec![5.0; 48] };
    let dir = scratch("false-colour");
    let path = dir.join("uniform.png");
    write_false_colour(&path, &image, Scale::Linear, "cd/m²").unwrap();
    let png = image::open(&path).unwrap().to_rgb8();
    assert_eq!(png.width(), 8 + LEGEND_WIDTH);
    assert!(png.height() >= 6);
    let top = colour(1.0);
    for y in 0..6 {
        for x in 0..8 {
            assert_eq!(png.get_pixel(x, y).0, [top.0, top.1, top.2], "pixel ({x}, {y})");
        }
    }
    assert!(!path.with_extension("png.tmp").exists());
}

#[test]
fn the_order_pictures_show_the_furnace_partial_sums() {
    let dir = scratch("orders");
    let h5 = dir.join("furnace.h5");
    let o =
        crate::support::ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "0.25", "-o", h5.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = crate::support::ugo(&["render", h5.to_str().unwrap(), "--orders", "1,8", "-o", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let png = image::open(dir.join("furnace-box-inside-flat-orders.png")).unwrap().to_rgb8();
    let width = png.width() / 2;
    // L after n reflections is (1 − 0.8ⁿ⁺¹)/(1 − 0.8) everywhere; white is the solution, 5 cd/m².
    for (panel, n) in [(0, 1), (1, 8)] {
        let l = (1.0 - 0.8f64.powi(n + 1)) / 0.2;
        let grey = (ugo::io::srgb(l / 5.0) * 255.0).round() as u8;
        let pixel = png.get_pixel(panel * width + width / 2, ugo::io::CAPTION_HEIGHT + 10).0;
        assert_eq!(pixel, [grey, grey, grey], "after {n} reflections");
    }
    let o = crate::support::ugo(&["render", h5.to_str().unwrap(), "--orders", "3", "-o", dir.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.contains("not recorded") && err.contains("1, 8, 64"), "{err}");
}
