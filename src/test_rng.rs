//! The deterministic generator the crate's unit tests draw their inputs from (xorshift64:
//! fast, reproducible, no dependency), and the edge values of the 16-bit-split arithmetic
//! they all try. Test builds only.

/// Values at and just past the `i16` range and zero, where a split into 16-bit halves
/// changes form.
pub(crate) const I16_EDGES: [i64; 7] = [0, 1, -1, 32767, -32768, 32768, -32769];

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
