//! 16-bit fixed-point formats and the integer operations of the FPGA MPDCC
//! model ([`super::mpdcc_fixed`]), written so a Verilog core can repeat them bit by
//! bit.
//!
//! # Notation
//! `Qm.f` = signed two's complement, 1 sign bit, `m` integer bits, `f`
//! fractional bits, `1 + m + f = 16`; value = raw / 2^f; range
//! `[-2^m, 2^m - 2^-f]`. `UQm.f` = unsigned, `m + f` bits.
//!
//! # Operations (one rule everywhere)
//! - **Quantize** (`f64 -> raw`, the interface registers): round to nearest,
//!   ties away from zero (`libm::round`), then saturate to the word. NaN or
//!   infinite input is an error, never a value.
//! - **Multiply** (`16 x 16 -> 32`, one DSP48 / Spartan-3 MULT18X18): exact
//!   32-bit product, then shift right to the target format with round half up
//!   ([`crate::fixedpoint::rshift_round`], the rule of every fixed-point
//!   model here), then saturate to 16 bits.
//! - **Add / subtract** (the 16-bit adder of Fig. 3): exact in 17 bits, then
//!   saturate to 16 bits.
//! - **Shift by `L = 2^lambda`**: left shifts are done in wider words where
//!   the text says so (the search comparators); no right shift of data by `L`
//!   exists in the model (see [`super::binsearch`]).
//!
//! Saturation instead of wrap-around: a wrapped current would flip sign and
//! make the controller switch the wrong way; saturating keeps the sign.
//!
//! # Formats used by the model
//! (The full table with the wide accumulator, node registers and search
//! comparators is in docs/mpdcc-fpga.md; the constants below and in
//! [`super::mpdcc_fixed`] are the source.)
//!
//! | quantity | format | range | LSB |
//! |---|---|---|---|
//! | stator current `i_s`, reference `i_s*`, output errors `y* - y`, bounds `y_bnd` | Q2.13 | +-4 pu | 1.22e-4 pu |
//! | rotor flux `psi_r` | Q1.14 | +-2 pu | 6.10e-5 pu |
//! | voltages `V_dc/2`, `v_n`, `v_ph` | Q2.13 | +-4 pu | 1.22e-4 pu |
//! | speeds `omega_r`, `omega_s` | Q2.13 | +-4 pu | 1.22e-4 pu |
//! | `L`-step model coefficients (`c_tau`, `c_w`, `g3`, ...) | Q1.14 | +-2 | 6.10e-5 |
//! | one-step model coefficients (`c_tau1`, `c_w1`, `g3_1`, ...) | f = 17 ([`F_SMALL`]) | +-0.25 | 7.6e-6 |
//! | node changes `Delta_j(mL)` | Q4.13, 18 bits | +-16 pu | 1.22e-4 pu |
//! | switching cost `J` | UQ15.17 in a u32 | 0..32768 | 7.6e-6 |
//! | reciprocal ROM `1/l` | UQ1.17, 18 bits | 0..2 | 7.6e-6 |
//! | `lambda_n` | UQ8.8 | 0..256 | 3.9e-3 |

/// Fractional bits of Q2.13 (currents, errors, bounds, voltages, speeds).
pub const F_I: u32 = 13;
/// Fractional bits of Q1.14 (rotor flux, model coefficients).
pub const F_C: u32 = 14;
/// Fractional bits of the small-coefficient format (`|c| < 0.25`).
pub const F_SMALL: u32 = 17;

/// Errors of [`quantize`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FixedError {
    /// The input was NaN or infinite.
    NotFinite,
}

/// Saturate a wide integer to i16.
#[inline]
pub fn sat16(v: i64) -> i16 {
    crate::fixedpoint::saturate(v, 16) as i16
}

/// `f64 -> raw` with `frac` fractional bits: round half away from zero,
/// saturate. Returns whether it saturated.
pub fn quantize(v: f64, frac: u32) -> Result<(i16, bool), FixedError> {
    if !v.is_finite() {
        return Err(FixedError::NotFinite);
    }
    let scaled = crate::fixedpoint::round_scaled(v, frac);
    let clamped = scaled.clamp(i16::MIN as f64, i16::MAX as f64);
    Ok((clamped as i16, clamped != scaled))
}

/// `raw -> f64`.
#[inline]
pub fn to_f64(raw: i16, frac: u32) -> f64 {
    libm::ldexp(raw as f64, -(frac as i32))
}

/// Saturating 16-bit add.
#[inline]
pub fn add(a: i16, b: i16) -> i16 {
    sat16(a as i64 + b as i64)
}

/// Saturating 16-bit subtract.
#[inline]
pub fn sub(a: i16, b: i16) -> i16 {
    sat16(a as i64 - b as i64)
}

/// `a (fa) * b (fb) -> (f_out)`: exact product, round half up, saturate.
/// Requires `fa + fb >= f_out`.
#[inline]
pub fn mul(a: i16, fa: u32, b: i16, fb: u32, f_out: u32) -> i16 {
    debug_assert!(fa + fb >= f_out);
    sat16(crate::fixedpoint::rshift_round(
        a as i64 * b as i64,
        fa + fb - f_out,
    ))
}

/// Quantize a design-time constant (model coefficient): finite by
/// construction of the validated parameters, so NaN maps to 0 and the
/// saturation flag is returned for the caller's range check.
pub fn konst(v: f64, frac: u32) -> (i16, bool) {
    quantize(v, frac).unwrap_or((0, true))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantize_rounds_and_saturates() {
        assert_eq!(quantize(1.0, F_I), Ok((8192, false)));
        assert_eq!(quantize(-1.0, F_I), Ok((-8192, false)));
        // Half an LSB rounds away from zero.
        assert_eq!(quantize(0.5 / 8192.0, F_I), Ok((1, false)));
        assert_eq!(quantize(-0.5 / 8192.0, F_I), Ok((-1, false)));
        assert_eq!(quantize(0.49 / 8192.0, F_I), Ok((0, false)));
        assert_eq!(quantize(4.0, F_I), Ok((i16::MAX, true)));
        assert_eq!(quantize(-4.0, F_I), Ok((i16::MIN, false)));
        assert_eq!(quantize(-5.0, F_I), Ok((i16::MIN, true)));
        assert_eq!(quantize(f64::NAN, F_I), Err(FixedError::NotFinite));
        assert_eq!(quantize(f64::INFINITY, F_I), Err(FixedError::NotFinite));
    }

    #[test]
    fn mul_rounds_half_up_and_saturates() {
        // 0.5 (Q1.14) * 1.5 (Q2.13) = 0.75 (Q2.13).
        assert_eq!(mul(8192, F_C, 12288, F_I, F_I), 6144);
        // 1 LSB * 0.5 = half an LSB -> rounds up to 1; -half -> 0 (half up).
        assert_eq!(mul(1, F_I, 8192, F_C, F_I), 1);
        assert_eq!(mul(-1, F_I, 8192, F_C, F_I), 0);
        // 1.9999 * 3.9999 saturates in Q2.13.
        assert_eq!(mul(i16::MAX, F_C, i16::MAX, F_I, F_I), i16::MAX);
        assert_eq!(mul(i16::MIN, F_C, i16::MAX, F_I, F_I), i16::MIN);
    }

    #[test]
    fn add_saturates() {
        assert_eq!(add(30000, 30000), i16::MAX);
        assert_eq!(sub(-30000, 30000), i16::MIN);
        assert_eq!(add(-5, 3), -2);
    }

    #[test]
    fn round_trip_within_half_lsb() {
        for k in -1000..1000 {
            let v = k as f64 * 0.003_7;
            let (r, sat) = quantize(v, F_I).unwrap();
            assert!(!sat);
            assert!((to_f64(r, F_I) - v).abs() <= 0.5 / 8192.0 + 1e-15);
        }
    }
}
