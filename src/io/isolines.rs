//! Lines of equal value through a lattice of samples (marching squares): the isolux lines
//! of a grid's plan, through its calculation points.
//!
//! Each square of four neighbouring samples is crossed where the level lies between two
//! corners, at the linearly interpolated point of that edge; a square with two crossings
//! holds one segment, one with four (a saddle) two, paired by the value at its centre.

/// Segments of the line `value = level` through `values` (row by row, `nu` per row, `nv`
/// rows), in lattice coordinates: `(a, b)` is sample `a` of row `b`.
pub fn isolines(values: &[f64], [nu, nv]: [usize; 2], level: f64) -> Vec<[(f64, f64); 2]> {
    let mut segments = Vec::new();
    if values.len() != nu * nv {
        return segments;
    }
    for b in 0..nv.saturating_sub(1) {
        for a in 0..nu.saturating_sub(1) {
            // Corners counter-clockwise from (a, b).
            let corners = [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)];
            let v = corners.map(|(i, j)| values[j * nu + i]);
            let mut crossings = Vec::with_capacity(4);
            for e in 0..4 {
                let (p, q) = (corners[e], corners[(e + 1) % 4]);
                let (vp, vq) = (v[e], v[(e + 1) % 4]);
                if (vp >= level) != (vq >= level) {
                    let t = (level - vp) / (vq - vp);
                    let at = |x: usize, y: usize| x as f64 + t * (y as f64 - x as f64);
                    crossings.push((at(p.0, q.0), at(p.1, q.1)));
                }
            }
            match crossings[..] {
                [p, q] => segments.push([p, q]),
                [p, q, r, s] => {
                    // A saddle: where the centre sides with corners 0 and 2, the lines cut
                    // off corners 1 and 3; else corners 0 and 2.
                    let centre = v.iter().sum::<f64>() / 4.0;
                    if (centre >= level) == (v[0] >= level) {
                        segments.extend([[p, q], [r, s]]);
                    } else {
                        segments.extend([[s, p], [q, r]]);
                    }
                }
                _ => {}
            }
        }
    }
    segments
}
