//! False-colour maps: the scale's positions, the colours at its ends, and the PNG written.

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
    let path = scratch("false-colour").join("uniform.png");
    write_false_colour(&path, &image, Scale::Linear).unwrap();
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
