//! The one rounding shift of every fixed-point model (the MPDTC core's
//! `pmsm::mpdtc_fixed` and the MPDCC FPGA model's `mpdcc::formats`), and so
//! of the RTL they are the oracle of.
//!
//! Rule: `rshift_round(x, s)` is `x / 2^s` rounded half up (towards +inf),
//! exact for every `i64` and every shift: `s = 0` returns `x`, `s >= 64`
//! returns 0 (every `i64` is within half an LSB of 0 then), and it never
//! overflows (`i64::MAX` shifted by 1 gives `2^62`). In Verilog it is
//! `(x + (1 << (s - 1))) >>> s` on a word wide enough not to overflow,
//! which is what the cores build.

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

#[cfg(test)]
mod tests {
    use super::rshift_round;

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
        let mut x: i64 = 0x1234_5678_9ABC_DEF1;
        for i in 0..20_000u32 {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
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
