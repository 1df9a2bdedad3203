//! The fixed-point helpers every fixed-point model shares (the MPDTC core's
//! `pmsm::mpdtc_fixed` and front end `pmsm::frontend_fixed`, the MPDCC
//! FPGA model's `mpdcc::mpdcc_fixed` with its formats in `mpdcc::formats`),
//! and so the rules of the RTL they are the oracle of. Each model writes its
//! formats (Q notation, width, range) next to its code and builds its
//! word-sized operations from these.
//!
//! - [`rshift_round`]: `x / 2^s` rounded half up (towards +inf), exact for
//!   every `i64` and every shift: `s = 0` returns `x`, `s >= 64` returns 0
//!   (every `i64` is within half an LSB of 0 then), and it never overflows
//!   (`i64::MAX` shifted by 1 gives `2^62`). In Verilog it is
//!   `(x + (1 << (s - 1))) >>> s` on a word wide enough not to overflow,
//!   which is what the cores build.
//! - [`saturate`]: clamp to a signed `bits`-bit word (saturation, never
//!   wrap-around: a wrapped current would flip sign).
//! - [`sign_extend`]: the low `bits` bits as a signed value (a port of that
//!   width).
//! - [`round_scaled`]: the one quantizer of `f64` values (parameter
//!   registers, run-time inputs): `x 2^frac` rounded to nearest, ties away
//!   from zero (`libm::round`); NaN stays NaN for the caller to reject.

/// `x / 2^s`, rounded half up; see the module doc for the edge cases.
#[inline]
pub const fn rshift_round(x: i64, s: u32) -> i64 {
    match s {
        0 => x,
        // floor(x / 2^s) plus the bit below the cut: the same as
        // (x + 2^(s-1)) >> s, without the addition that could overflow.
        1..=63 => (x >> s) + ((x >> (s - 1)) & 1),
        _ => 0,
    }
}

/// `x` clamped to the signed `bits`-bit range `[-2^(bits-1), 2^(bits-1) - 1]`,
/// `bits` in 1..=64.
#[inline]
pub const fn saturate(x: i64, bits: u32) -> i64 {
    let max = ((1u64 << (bits - 1)) - 1) as i64;
    let min = -max - 1;
    if x > max {
        max
    } else if x < min {
        min
    } else {
        x
    }
}

/// The low `bits` bits of `x` as a signed value, `bits` in 1..=64.
#[inline]
pub const fn sign_extend(x: i64, bits: u32) -> i64 {
    (x << (64 - bits)) >> (64 - bits)
}

/// `x 2^frac` rounded to nearest, ties away from zero; NaN and infinities
/// pass through (scaling by a power of two is exact).
#[inline]
pub fn round_scaled(x: f64, frac: u32) -> f64 {
    libm::round(libm::ldexp(x, frac as i32))
}

#[cfg(test)]
mod tests {
    use super::{round_scaled, rshift_round, saturate, sign_extend};

    /// Hand-computed words at the edges of 16, 18 and 25 bits.
    #[test]
    fn saturates_and_sign_extends() {
        assert_eq!(saturate(40_000, 16), 32_767);
        assert_eq!(saturate(-40_000, 16), -32_768);
        assert_eq!(saturate(-5, 16), -5);
        assert_eq!(saturate(1 << 20, 18), (1 << 17) - 1);
        assert_eq!(saturate(-(1 << 30), 25), -(1 << 24));
        assert_eq!(saturate(i64::MIN, 64), i64::MIN);
        assert_eq!(saturate(i64::MAX, 64), i64::MAX);
        assert_eq!(sign_extend(0xFFFF, 16), -1);
        assert_eq!(sign_extend(0x7FFF, 16), 32_767);
        assert_eq!(sign_extend(0x2_0000, 18), -(1 << 17));
        assert_eq!(sign_extend(0x1_2345, 16), 0x2345);
    }

    /// Ties go away from zero; powers of two scale exactly.
    #[test]
    fn round_scaled_ties_away_from_zero() {
        assert_eq!(round_scaled(0.5 / 8192.0, 13), 1.0);
        assert_eq!(round_scaled(-0.5 / 8192.0, 13), -1.0);
        assert_eq!(round_scaled(0.49 / 8192.0, 13), 0.0);
        assert_eq!(round_scaled(1.25, 16), 81_920.0);
        assert!(round_scaled(f64::NAN, 16).is_nan());
    }

    /// Hand-computed cases, including the ties (which go up) and both ends
    /// of the shift range.
    #[test]
    fn rounds_half_up_at_every_shift() {
        assert_eq!(rshift_round(3 << 15, 16), 2); // 1.5 -> 2
        assert_eq!(rshift_round(-(3 << 15), 16), -1); // -1.5 -> -1
        assert_eq!(rshift_round((3 << 15) - 1, 16), 1); // just below 1.5
        assert_eq!(rshift_round(-5, 1), -2); // -2.5 -> -2
        assert_eq!(rshift_round(-6, 2), -1); // -1.5 -> -1
        assert_eq!(rshift_round(7, 0), 7);
        assert_eq!(rshift_round(-7, 0), -7);
        assert_eq!(rshift_round(i64::MAX, 1), 1 << 62);
        assert_eq!(rshift_round(i64::MIN, 1), i64::MIN / 2);
        assert_eq!(rshift_round(i64::MAX, 63), 1);
        assert_eq!(rshift_round(i64::MIN, 63), -1);
        assert_eq!(rshift_round(i64::MAX, 64), 0);
        assert_eq!(rshift_round(i64::MIN, 200), 0);
    }

    /// The same as the textbook `(x + half) >> s` wherever that one does
    /// not overflow, against an `i128` evaluation.
    #[test]
    fn agrees_with_the_wide_formula() {
        let mut rng = crate::testrng::Rng(0x1234_5678_9ABC_DEF1);
        for i in 0..20_000u32 {
            let x = rng.next_u64() as i64;
            let s = i % 66;
            let want = if s == 0 {
                x
            } else if s >= 64 {
                0
            } else {
                ((x as i128 + (1i128 << (s - 1))) >> s) as i64
            };
            assert_eq!(rshift_round(x, s), want, "x {x} s {s}");
        }
    }
}
