//! The seeded generator of the Monte Carlo, the clearance's random candidates and the
//! randomised tests: SplitMix64 (Steele, Lea and Flood, OOPSLA 2014), small, fast and the same
//! stream on every platform, so that a seed names its samples and a failure can be replayed.
//!
//! ```
//! use model::random::Rng;
//!
//! let (mut a, mut b) = (Rng::new(7), Rng::new(7));
//! let x = a.unit();
//! assert!((0.0..1.0).contains(&x));
//! assert_eq!(x, b.unit());
//! assert!((2.0..3.0).contains(&a.uniform(2.0, 3.0)));
//! ```

/// A SplitMix64 generator.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1), on the 2^53 doubles of that grid.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}
