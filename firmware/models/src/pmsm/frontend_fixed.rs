//! Bit-accurate model of the PL front end `mpdtc_frontend` (oracle of the
//! Verilog, `pl-bitstream-src/rtl/mpdtc_frontend.v`): encoder count and ADC
//! averages in, the `mpdtc_core` inputs ([`FixedInputs`]) out, with no PS
//! arithmetic. Integer only; formats of the core in `super::mpdtc_fixed`.
//!
//! | quantity | format | meaning |
//! |---|---|---|
//! | electrical angle `phi` | u32, 2^-32 turn | `(pos - align) ang_scale mod 2^32` |
//! | `ang_scale` | u32 | `round(pole_pairs 2^32 / cpr) mod 2^32` |
//! | angle step `dphi` | s32, 2^-32 turn per control period | `(speed spd_scale) >> 8` (floor, low 32 bits) |
//! | `spd_scale` | u32, 2^-40 turn per (count per window) per period | `round(pole_pairs Ts 2^40 / (cpr T_window))` |
//! | `age[j]` | COEF (sQ1.16), periods | the three instants relative to the sample: `lambda - 1/2`, `lambda + 1/2`, `lambda + 3/2` |
//! | `w_ts` | COEF, rad | `sat18(round((dphi >> 8) round(2 pi 2^14) / 2^22))` |
//! | sin/cos | COEF | 1024-entry table `round(2^16 sin(2 pi i / 1024))`, linear interpolation |
//! | ADC offset | s16, ADC counts | subtracted from the average |
//! | ADC gain | s18, 2^-20 A per count (up to 0.125 A per count) | `i = sat25(round((adc - off) gain / 2^4))`, CUR |
//! | `i_alpha`, `i_beta` | CUR | `R(2a - b - c) / 3`, `R((b - c) / sqrt 3)` (amplitude invariant) |
//! | `i_d`, `i_q` | CUR | Park at `phi`: `R(c i_alpha + s i_beta)`, `R(c i_beta - s i_alpha)` |
//!
//! `R` rounds half up and saturates (`sat25(round(x / 2^16))`). Every
//! register and input is taken at its port width (its low bits, signed
//! where signed), as the RTL does.
//!
//! sin/cos error bound (every angle): table rounding <= 2^-17, linear
//! interpolation <= (2 pi / 1024)^2 / 8 = 4.71e-6, rounding of the
//! interpolated step <= 2^-17, angle truncation to 2^-26 turn <= 9.4e-8:
//! |error| <= 2.0e-5 = 1.32 COEF LSB; measured over 2^20 angles by
//! `tests::trig_error_is_within_the_written_bound` (and the `rtl-check
//! frontend` summary).
use super::mpdtc_fixed::{rnd, sat18, sat25, FixedInputs, FRAC};
use crate::fixedpoint::{rshift_round, sign_extend};

/// log2 of the sine table length.
pub const SIN_BITS: u32 = 10;
/// Sine table length (one full turn).
pub const SIN_N: usize = 1 << SIN_BITS;
/// `round(2 pi 2^14)`: rad per turn for `w_ts`.
pub const TWO_PI_Q14: i64 = 102_944;
/// Shift from (ADC counts x gain, 2^-20 A) to CUR (2^-16 A).
pub const ADC_SHIFT: u32 = 4;
/// `round(2^16 / 3)`, COEF (Clarke).
pub const ONE_THIRD: i32 = 21_845;
/// `round(2^16 / sqrt 3)`, COEF (Clarke).
pub const INV_SQRT3: i32 = 37_837;

/// Table entry `i` (any `i`, taken mod [`SIN_N`]): `round(2^16 sin(2 pi i / 1024))`.
pub fn sin_entry(i: usize) -> i32 {
    let x = core::f64::consts::TAU * (i % SIN_N) as f64 / SIN_N as f64;
    libm::round(libm::sin(x) * (1u32 << FRAC) as f64) as i32
}

/// `(cos, sin)` of the angle `phi` (2^-32 turn), COEF.
pub fn trig(phi: u32) -> (i32, i32) {
    (sin_interp(phi.wrapping_add(1 << 30)), sin_interp(phi))
}

/// Interpolated sine: entry `phi >> 22` plus the step to the next entry
/// times the next 16 bits of `phi`, rounded.
pub fn sin_interp(phi: u32) -> i32 {
    let i = (phi >> (32 - SIN_BITS)) as usize;
    let f = ((phi >> (16 - SIN_BITS)) & 0xFFFF) as i64;
    let t0 = sin_entry(i);
    let t1 = sin_entry(i + 1);
    t0 + rshift_round((t1 - t0) as i64 * f, 16) as i32
}

/// Registers of the front end (written by the PS, or latched by the PL).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FrontendParams {
    /// `ENC_CPR`, counts per mechanical revolution (16 bits).
    pub cpr: u32,
    /// Encoder count at the rotor's d axis on phase a (`MPDTC_ALIGN_POS`).
    pub align_pos: u32,
    /// `round(pole_pairs 2^32 / cpr) mod 2^32`.
    pub ang_scale: u32,
    /// `round(pole_pairs Ts 2^40 / (cpr T_window))`.
    pub spd_scale: u32,
    /// The three instants, periods after the sample, COEF.
    pub age: [i32; 3],
    /// ADC offsets, counts (s16).
    pub adc_off: [i32; 3],
    /// ADC gains, 2^-20 A per count (s18).
    pub adc_gain: [i32; 3],
}

/// Inputs of one control period.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FrontendInputs {
    /// `ENC_POS` (16 bits).
    pub pos: u32,
    /// `ENC_SPEED`, counts per window (s16).
    pub speed: i32,
    /// Averaged ADC results a, b, c (s16).
    pub adc: [i32; 3],
    /// Torque reference, TRQ (passed through).
    pub t_ref: i32,
}

/// Outputs: the core's inputs and the intermediate values the RTL shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FrontendOutputs {
    /// The `mpdtc_core` inputs.
    pub core: FixedInputs,
    /// Electrical angle at the sample, 2^-32 turn.
    pub phi: u32,
    /// Angle step per control period, 2^-32 turn.
    pub dphi: i32,
    /// `(i_alpha, i_beta)`, CUR.
    pub i_ab: (i32, i32),
}

/// The low `bits` bits of `x` as a signed value (a port of that width).
#[inline]
fn sx(x: i32, bits: u32) -> i64 {
    sign_extend(x as i64, bits)
}

/// One control period of the front end. Pure, total (any register values).
pub fn frontend(inp: &FrontendInputs, p: &FrontendParams) -> FrontendOutputs {
    // Encoder -> electrical angle (no division: ang_scale holds pp / cpr).
    let d = (inp.pos & 0xFFFF) as i64 - (p.align_pos & 0xFFFF) as i64;
    let cnt = if d < 0 {
        d + (p.cpr & 0xFFFF) as i64
    } else {
        d
    };
    let phi = (cnt * p.ang_scale as i64) as u32;
    // Speed -> angle step per period and w Ts.
    let speed = sx(inp.speed, 16);
    let dphi = ((speed * p.spd_scale as i64) >> 8) as u32 as i32;
    let dphi24 = (dphi >> 8) as i64;
    let w_ts = sat18(rshift_round(dphi24 * TWO_PI_Q14, 22));
    let mut trig3 = [(0, 0); 3];
    for (t, &age) in trig3.iter_mut().zip(&p.age) {
        let off = ((dphi24 * sx(age, 18)) >> 8) as u32;
        *t = trig(phi.wrapping_add(off));
    }
    // ADC -> phase currents -> Clarke -> Park at the sample's angle.
    let i: [i64; 3] = core::array::from_fn(|k| {
        let diff = sx(inp.adc[k], 16) - sx(p.adc_off[k], 16);
        sat25(rshift_round(diff * sx(p.adc_gain[k], 18), ADC_SHIFT)) as i64
    });
    let al = rnd(ONE_THIRD as i64 * sat25(2 * i[0] - i[1] - i[2]) as i64);
    let be = rnd(INV_SQRT3 as i64 * sat25(i[1] - i[2]) as i64);
    let (c, s) = trig(phi);
    let (c, s) = (c as i64, s as i64);
    let i_d = rnd(c * al as i64 + s * be as i64);
    let i_q = rnd(c * be as i64 - s * al as i64);
    FrontendOutputs {
        core: FixedInputs {
            i_dq: (i_d, i_q),
            trig: trig3,
            w_ts,
            t_ref: sx(inp.t_ref, 18) as i32,
        },
        phi,
        dphi,
        i_ab: (al, be),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::TAU;

    /// Over 2^20 angles the interpolated cos/sin are within the written
    /// bound (1.32 LSB) of libm's.
    #[test]
    fn trig_error_is_within_the_written_bound() {
        let mut worst = 0.0f64;
        for k in 0..(1u64 << 20) {
            let phi = (k.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 32) as u32;
            let x = TAU * phi as f64 / 4_294_967_296.0;
            let (c, s) = trig(phi);
            worst = worst
                .max((c as f64 / 65536.0 - libm::cos(x)).abs())
                .max((s as f64 / 65536.0 - libm::sin(x)).abs());
        }
        assert!(worst <= 2.0e-5, "{worst}");
        // And not trivially: the bound is within a factor 3 of the truth.
        assert!(worst > 7.0e-6, "{worst}");
    }

    /// Hand-computed: 4096 counts, 4 pole pairs, count 512 past the
    /// alignment = 1/8 mechanical turn = half an electrical turn; a speed
    /// of 100 counts per 1 ms window at Ts = 15.625 us.
    #[test]
    fn angle_speed_and_park_by_hand() {
        let pp = 4.0;
        let cpr = 4096.0;
        let ts = 15.625e-6;
        let win = 1e-3;
        let p = FrontendParams {
            cpr: 4096,
            align_pos: 100,
            ang_scale: (pp * 4_294_967_296.0 / cpr) as u32,
            spd_scale: libm::round(pp * ts * 1_099_511_627_776.0 / (cpr * win)) as u32,
            age: [-8192, 57344, 122880], // -0.125, 0.875, 1.875 periods
            adc_off: [10, -10, 0],
            adc_gain: [10_486; 3], // 0.01 A per count
        };
        let inp = FrontendInputs {
            pos: 612,
            speed: 100,
            adc: [110, -10, -100],
            t_ref: 1234,
        };
        let o = frontend(&inp, &p);
        assert_eq!(o.phi, 1 << 31, "half an electrical turn");
        // w = 100 / 4096 rev per ms x 4 x 2 pi = 613.6 rad/s; w Ts = 9.587e-3 rad.
        let w_ts = 100.0 / cpr / win * pp * TAU * ts;
        assert!(
            (o.core.w_ts as f64 / 65536.0 - w_ts).abs() < 2e-5,
            "{}",
            o.core.w_ts
        );
        // Currents: a = 1 A, b = 0, c = -1 A: alpha = 1, beta = 1/sqrt 3;
        // at theta = pi: i_d = -alpha, i_q = -beta.
        let (id, iq) = o.core.i_dq;
        assert!((id as f64 / 65536.0 + 1.0).abs() < 1e-4, "{id}");
        assert!(
            (iq as f64 / 65536.0 + 1.0 / 3f64.sqrt()).abs() < 1e-4,
            "{iq}"
        );
        // Instant 1 is 0.875 periods ahead: cos(pi + 0.875 w Ts).
        let th1 = core::f64::consts::PI + 0.875 * w_ts;
        assert!((o.core.trig[1].0 as f64 / 65536.0 - libm::cos(th1)).abs() < 3e-5);
        assert!((o.core.trig[1].1 as f64 / 65536.0 - libm::sin(th1)).abs() < 3e-5);
        assert_eq!(o.core.t_ref, 1234);
    }

    /// Extreme values never panic.
    #[test]
    fn total_on_extreme_registers() {
        for v in [0u32, 1, 0x7FFF, 0xFFFF, u32::MAX] {
            let p = FrontendParams {
                cpr: v,
                align_pos: v,
                ang_scale: v,
                spd_scale: v,
                age: [v as i32; 3],
                adc_off: [v as i32; 3],
                adc_gain: [v as i32; 3],
            };
            let inp = FrontendInputs {
                pos: !v,
                speed: v as i32,
                adc: [!v as i32; 3],
                t_ref: v as i32,
            };
            let _ = frontend(&inp, &p);
        }
    }
}
