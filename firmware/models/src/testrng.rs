//! The one seedable pseudo-random generator of every randomized test and
//! RTL vector set in the workspace (model tests here, `rtl-sim`'s vectors):
//! SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number
//! generators", OOPSLA 2014). Deterministic for a seed, no dependency, not
//! for anything but tests: a failing seed reproduces on every machine.

/// SplitMix64 state; `Rng(seed)` starts a stream.
#[derive(Debug, Clone)]
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform integer in `lo..=hi` (`lo <= hi`).
    pub fn range(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (hi as i64 - lo as i64 + 1) as u64;
        (lo as i64 + (self.next_u64() % span) as i64) as i32
    }

    /// Uniform in `[0, 1)`, 53 random bits.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[a, b)`.
    pub fn uniform(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
}

#[cfg(test)]
mod tests {
    use super::Rng;

    /// The first outputs for seed 0, from the published reference
    /// sequence of SplitMix64 (the same constants as `java.util.SplittableRandom`).
    #[test]
    fn matches_the_reference_sequence() {
        let mut r = Rng(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(r.next_u64(), 0x06C4_5D18_8009_454F);
    }

    /// Ranges stay inside their bounds and reach both ends.
    #[test]
    fn ranges_are_inclusive_and_bounded() {
        let mut r = Rng(7);
        let (mut lo, mut hi) = (false, false);
        for _ in 0..1000 {
            let v = r.range(-2, 2);
            assert!((-2..=2).contains(&v));
            lo |= v == -2;
            hi |= v == 2;
            let u = r.uniform(-1.5, 0.5);
            assert!((-1.5..0.5).contains(&u));
        }
        assert!(lo && hi);
    }
}
