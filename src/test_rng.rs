//! The deterministic generator the crate's unit tests draw their inputs from (xorshift64:
//! fast, reproducible, no dependency). Test builds only.

/// Xorshift64 state; any non-zero seed.
pub(crate) struct Rng(pub u64);

impl Rng {
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// Uniform in `[0, 1)`, 53 bits.
    pub fn unit01(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}
