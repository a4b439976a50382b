//! xorshift64* (Vigna): a tiny deterministic generator for tests, so that random inputs are
//! the same on every run and platform (the product's own randomness, `dvf sweep`, uses
//! `rand_pcg`).

/// The generator; its state is the seed, any value but 0.
#[derive(Clone, Debug)]
pub struct XorShift(pub u64);

impl XorShift {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform in (−π, π].
    pub fn heading(&mut self) -> f64 {
        std::f64::consts::PI - 2.0 * std::f64::consts::PI * self.unit()
    }
}
