//! Probes on the walls beside the glossy Cornell box's Phong floor (issue 34;
//! docs/accuracy.md, "The glossy Cornell box"): the case at its own settings (the uniform
//! kernel at 0.055 m, K = 64), read at the distinct corner and edge probes of its committed
//! references that stand on a wall at most 10 cm above the floor. Each sees the floor's
//! patches from a few centimetres at grazing angles, where the light a glossy patch sends
//! towards the probe follows the direction to it across the patch. Read at each shadow
//! piece's centroid, they were up to 34 % off (+34.2 % at 5 cm above the floor beneath the
//! lamp, −14.3 % at 2 cm in a corner); read piece by piece within twice the lobe's half
//! width (`readout/gather.rs`, `LOBE_PIECE`), within 0.94 % (mean 0.37 %), held to those
//! figures rounded up to the next 0.1 % plus 0.1 %, as the other classes of `mod.rs`.

use super::{bench_scene, read, reference};

#[test]
#[ignore = "about a minute: make test-long"]
fn probes_beside_a_glossy_floor_read_its_lobe_piece_by_piece() {
    let reference = reference("glossy-cornell");
    let mut scene = bench_scene("glossy-cornell", &reference);
    let beside_the_floor = |i: usize| {
        let probe = &reference.probes[i];
        let class = &reference.class[i];
        (class.starts_with("corner") || class.starts_with("edge"))
            && probe.position.y <= 0.1001
            && probe.normal.y.abs() < 0.5
    };
    let mut picked: Vec<usize> = Vec::new();
    for i in (0..reference.probes.len()).filter(|&i| beside_the_floor(i)) {
        let p = &reference.probes[i];
        if !picked.iter().any(|&j| reference.probes[j].position == p.position && reference.probes[j].normal == p.normal)
        {
            picked.push(i);
        }
    }
    scene.probes = picked.iter().map(|&i| reference.probes[i].clone()).collect();
    let readings = read(&scene);
    let errors: Vec<f64> =
        readings.iter().zip(&picked).map(|(r, &i)| 100.0 * (r.illuminance / reference.illuminance[i] - 1.0)).collect();
    let largest = errors.iter().fold(0.0_f64, |a, e| a.max(e.abs()));
    let mean = errors.iter().map(|e| e.abs()).sum::<f64>() / errors.len() as f64;
    eprintln!(
        "glossy Cornell, {} probes beside the floor: errors {errors:.2?} %; mean |error| {mean:.2} %, largest {largest:.2} %",
        picked.len()
    );
    assert_eq!(picked.len(), 22);
    assert!(largest < 1.1, "largest error {largest:.2} %");
    assert!(mean < 0.5, "mean |error| {mean:.2} %");
}
