//! Reproducible random numbers for the renderer: SplitMix64 seeded from a pixel, a sample
//! and a purpose, so every image is the same on every run and thread count.

/// A SplitMix64 stream.
#[derive(Debug, Clone, Copy)]
pub struct Rng(u64);

impl Rng {
    /// The stream for `key` (any mix of pixel and sample indices).
    pub fn new(key: u64) -> Rng {
        Rng(key.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0x5DEE_CE66)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in [0, 1) from 53 random bits.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}
