//! The one random number generator of ugo: SplitMix64 (Steele, Lea & Flood, OOPSLA 2014),
//! reproducible streams for the Monte Carlo estimators, the renderer's samples, the
//! memory estimate's pair sample and the benchmarks; and the stratified point sets the
//! final gather draws its directions from ([`Stratified`]).
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

    /// The next 64 random bits (SplitMix64).
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

/// The `n` points of a Hammersley set in the unit square, `(r/n, φ₂(r))` with `φ₂` the
/// base-2 radical inverse, shifted together by one random offset modulo 1 (Cranley &
/// Patterson 1976): each point is uniform, so an estimate over them is unbiased, and every
/// interval of the square's dyadic grids of area `1/n` holds one point when `n` is a power
/// of two, so the error falls about as `1/n` rather than `1/√n` on smooth integrands. A
/// third coordinate `φ₃(r)` (base 3, shifted alike) makes it the three-dimensional set, for
/// a sampler that also chooses among its components.
#[derive(Debug, Clone, Copy)]
pub struct Stratified {
    n: usize,
    shift: [f64; 3],
}

impl Stratified {
    /// The set of `n` points (at least 1), shifted by one offset drawn from `rng`.
    pub fn new(n: usize, rng: &mut Rng) -> Stratified {
        Stratified { n: n.max(1), shift: rng.uniform3() }
    }

    /// Point `r` of the set, `r < n`.
    #[inline]
    pub fn point(&self, r: usize) -> [f64; 2] {
        let radical = (r as u32).reverse_bits() as f64 / 4_294_967_296.0;
        [(r as f64 / self.n as f64 + self.shift[0]).fract(), (radical + self.shift[1]).fract()]
    }

    /// Point `r` of the three-dimensional set, `(r/n, φ₂(r), φ₃(r))` shifted.
    #[inline]
    pub fn point3(&self, r: usize) -> [f64; 3] {
        let [u, v] = self.point(r);
        [u, v, (ternary_inverse(r) + self.shift[2]).fract()]
    }
}

/// `φ₃(r)`: the digits of `r` in base 3 mirrored about the point.
fn ternary_inverse(mut r: usize) -> f64 {
    let (mut value, mut scale) = (0.0, 1.0 / 3.0);
    while r > 0 {
        value += (r % 3) as f64 * scale;
        r /= 3;
        scale /= 3.0;
    }
    value
}

/// SplitMix64's output function (a bijection with full avalanche).
#[inline]
pub fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
