//! The one random number generator of ugo: SplitMix64 (Steele, Lea & Flood, OOPSLA 2014),
//! reproducible streams for the Monte Carlo estimators, the renderer's samples, the
//! memory estimate's pair sample and the benchmarks.
//!
//! A stream is keyed by `(seed, index)` (or by one key), so a result depends only on the
//! seed and the sample count, never on the number of threads or the order in which rayon
//! runs work.

/// SplitMix64: a 64-bit state advanced by the golden-ratio increment, output mixed.
#[derive(Debug, Clone)]
pub struct Rng {
    state: u64,
}

const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

impl Rng {
    /// The stream of `index` under `seed`.
    pub fn stream(seed: u64, index: u64) -> Rng {
        // Starting states scattered by the generator's own mixing function: neighbouring
        // indices start far apart on the one cycle of 2⁶⁴ states.
        Rng { state: mix(mix(seed ^ 0x5DEE_CE66_D1CE_4E5B).wrapping_add(mix(index.wrapping_add(GOLDEN)))) }
    }

    /// The stream of one `key` (any mix of pixel and sample indices).
    pub fn keyed(key: u64) -> Rng {
        Rng { state: key.wrapping_mul(GOLDEN) ^ 0x5DEE_CE66 }
    }

    /// The stream whose next state follows `state`.
    pub fn from_state(state: u64) -> Rng {
        Rng { state }
    }

    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(GOLDEN);
        mix(self.state)
    }

    /// A number in `[0, 1)` with 53 random bits.
    #[inline]
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Three uniform numbers.
    #[inline]
    pub fn uniform3(&mut self) -> [f64; 3] {
        [self.uniform(), self.uniform(), self.uniform()]
    }
}

/// SplitMix64's output function (a bijection with full avalanche).
#[inline]
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
