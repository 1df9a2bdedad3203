//! Bit-accurate fixed-point model of the MPDTC PL core (oracle of the Verilog).
//!
//! Same algorithm as [`super::mpdtc_ref`] (read its interpretations 1-14),
//! rewritten as integer arithmetic a pipelined core with DSP48E1 slices
//! (25 x 18 multiplier + 48-bit adder) computes bit-exactly. No division, no
//! floating point, no trigonometry inside the core: sin/cos come in as inputs
//! (the encoder front end's LUT), every constant that needs a division is a
//! parameter register written by the PS.
//!
//! Formats (also in `docs/mpdtc-fixed.md`). `sQm.n`: two's complement,
//! 1 sign bit, m integer bits, n fraction bits (width 1 + m + n).
//!
//! | name | format | width | range | LSB | used for |
//! |---|---|---|---|---|---|
//! | CUR | sQ8.16 | 25 | [-256, 256) A | 15.3 uA | currents, current increments per period (A), band, limits |
//! | COEF | sQ1.16 | 18 | [-2, 2) | 1.53e-5 | `a`, `w Ts`, cos/sin, `lambda`, gains |
//! | TRQ | sQ3.14 | 18 | [-8, 8) N m | 61 uN m | torque reference |
//! | KINV | sQ8.16 | 25 | [-256, 256) A/N m | | `1 / k_T` |
//! | CSQ | sQ8.8 (17 bits, held in 18) | 18 | [-256, 256) A | 3.9 mA | second operand of the square (cost): `CUR >> 8` (floor), wiring in the core |
//! | MAG | uQ13.11 in s25 | 25 | [0, 8192) A^2 | 4.9e-4 A^2 | `|I|^2` |
//! | WGT | sQ3.14 | 18 | [0, 8) | 6.1e-5 | `2^(n p)` (or `2^(2 n p)`), n = 0..3 |
//! | COST | uQ16.25 (< 2^41) | 43 (kept 48) | exact | | `WGT * MAG`, compared, never rounded |
//!
//! Arithmetic rules (every operation of [`decide`] uses only these):
//! - **Product** `COEF x CUR` is exact (43 bits, 32 fraction bits). A *MAC
//!   expression* sums exact products, exact voltage steps and CUR addends
//!   aligned by `<< 16` in a 48-bit accumulator (no overflow: every sum
//!   here is below 2^45), then **rounds** once: `+ 2^15`, arithmetic shift
//!   right by 16 (round half up), then **saturates** to 25 bits
//!   (`R(x)`). A CUR addend `y << 16` has 16 zero low bits, so it commutes
//!   with the rounding: `R(m + (y << 16)) = sat25(((m + 2^15) >> 16) + y)`;
//!   the core adds such terms before or after the shift, whichever keeps
//!   one multiplier and one adder per pipeline stage.
//! - **Voltage steps**: the step of a known state (S[k-1] at the first
//!   angle, S[k] at the second) enters its MAC exactly (`volt_exact`, four
//!   products per angle); the candidates' steps at the third angle are
//!   integer sums of two rounded legs (`legs`, `cand_step`), so opposite
//!   states give exactly opposite steps and 000, 111 exactly 0. The core
//!   uses `U0 = 2 (U0/2)`: the `u0` register is not read.
//! - **Add/sub** of CUR values saturates to 25 bits.
//! - **Clamp** to a symmetric limit register `L` (CUR): `min(max(x, -L), L)`.
//! - Overflow argument: currents of the drive stay below 64 A (the inverter
//!   trips far below), so CUR (256 A) has 2 bits of headroom over every
//!   sum of two currents; saturation only triggers on faults and is then
//!   harmless (the decision is still a valid switch state).

use super::mpdtc_ref::{CostNorm, MpdtcConfig, SWITCH_WEIGHT};
use super::params::ParamError;
use crate::fixedpoint::{round_scaled, rshift_round, saturate};

/// Width of CUR.
pub const CUR_BITS: u32 = 25;
/// Fraction bits of CUR and COEF.
pub const FRAC: u32 = 16;
/// Fraction bits of TRQ and WGT.
pub const TRQ_FRAC: u32 = 14;
/// Right shift from the exact square (24 fraction bits) to MAG (11).
pub const MAG_SHIFT: u32 = 13;
/// Right shift from CUR to CSQ.
pub const CSQ_SHIFT: u32 = 8;

const CUR_MAX: i64 = (1 << (CUR_BITS - 1)) - 1;

/// Saturate to 25 bits.
#[inline]
pub fn sat25(x: i64) -> i32 {
    saturate(x, CUR_BITS) as i32
}

/// Saturate to 18 bits.
#[inline]
pub fn sat18(x: i64) -> i32 {
    saturate(x, 18) as i32
}

/// MAC expression: `sat25(rnd16(sum(c_i * x_i) + (y << 16)))`, COEF x CUR.
#[inline]
pub fn mac(terms: &[(i32, i32)], y: i32) -> i32 {
    let mut acc = (y as i64) << FRAC;
    for &(c, x) in terms {
        acc += c as i64 * x as i64;
    }
    sat25(rshift_round(acc, FRAC))
}

/// Saturating CUR add.
#[inline]
pub fn add(a: i32, b: i32) -> i32 {
    sat25(a as i64 + b as i64)
}

/// Saturating CUR subtract.
#[inline]
pub fn sub(a: i32, b: i32) -> i32 {
    sat25(a as i64 - b as i64)
}

/// Clamp to `[-lim, lim]` for a limit register `lim >= 0`, written as the
/// comparator chain of the hardware (`x > lim ? lim : x < -lim ? -lim : x`),
/// so a negative register value is defined too (never panics).
#[inline]
pub fn clamp(x: i32, lim: i32) -> i32 {
    if x > lim {
        lim
    } else if x < -lim {
        -lim
    } else {
        x
    }
}

/// Quantize an `f64` to `frac` fraction bits (round to nearest), checking
/// the signed `bits` range. Host side only (parameter registers, inputs).
pub fn quantize(x: f64, frac: u32, bits: u32, field: &'static str) -> Result<i32, ParamError> {
    let v = round_scaled(x, frac);
    let max = ((1i64 << (bits - 1)) - 1) as f64;
    if !(v.is_finite() && v >= -max - 1.0 && v <= max) {
        return Err(ParamError {
            field,
            reason: "out of the fixed-point range of its register",
        });
    }
    Ok(v as i32)
}

/// Quantize with saturation (for run-time inputs: never fails, NaN -> 0).
pub fn quantize_sat(x: f64, frac: u32, bits: u32) -> i32 {
    if x.is_nan() {
        return 0;
    }
    let v = round_scaled(x, frac);
    let max = ((1i64 << (bits - 1)) - 1) as f64;
    v.clamp(-max - 1.0, max) as i32
}

/// Parameter registers of the core (written by the PS; formats per field).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FixedParams {
    /// `a = 1 - R Ts / L`, COEF.
    pub a: i32,
    /// Measurement age `lambda`, COEF (0.375 -> 24576).
    pub lambda: i32,
    /// `U0 = (Ts / L) 2/3 U_dc`, current step of a full vector per period, CUR.
    pub u0: i32,
    /// `U0 / 2`, CUR.
    pub u0_half: i32,
    /// `U0 sqrt(3) / 2`, CUR.
    pub u0_h: i32,
    /// `psi / L`, A (back-EMF term is `(w Ts) psi / L`), CUR.
    pub psi_l: i32,
    /// `1 / k_T`, A/(N m), KINV.
    pub kinv_t: i32,
    /// Band `T_tol / k_T`, CUR.
    pub tol: i32,
    /// Integrator gain `K Ts`, COEF.
    pub k_int: i32,
    /// Integrator clamp `int_limit / k_T`, CUR.
    pub int_lim: i32,
    /// Conditional integration enable (1 bit).
    pub int_conditional: bool,
    /// Observer `b Kp` (b = Ts/L), COEF.
    pub kp_o: i32,
    /// Observer `b Kp Ki Ts`, COEF.
    pub ki_o: i32,
    /// Observer clamp `b eps_max`, CUR.
    pub eta_lim: i32,
    /// Weights `2^(n p)` (squared norm) or `2^(2 n p)` (Euclidean), n =
    /// transitions 0..=3, WGT.
    pub w2: [i32; 4],
}

impl FixedParams {
    /// Register values for a reference configuration (host side). Errors:
    /// `L_d != L_q` (the core's torque is linear in `i_q`), or a value out
    /// of its register range.
    pub fn from_config(cfg: &MpdtcConfig) -> Result<Self, ParamError> {
        let m = &cfg.model;
        let p = &cfg.params;
        if libm::fabs(m.l_d_h - m.l_q_h) > 1e-12 {
            return Err(ParamError {
                field: "l_q_h",
                reason: "the fixed-point core needs L_d = L_q",
            });
        }
        let ts = p.control_period_s;
        let b = ts / m.l_d_h;
        let u0 = b * m.u_dc_v * 2.0 / 3.0;
        let kt = 1.5 * m.pole_pairs as f64 * cfg.torque_psi_wb();
        let q = |x: f64, f: &'static str| quantize(x, FRAC, CUR_BITS, f);
        let qc = |x: f64, f: &'static str| quantize(x, FRAC, 18, f);
        // The core always compares `w2[n] |I|^2`: for the squared norm
        // `w2 = 2^(n p)`, for the Euclidean norm `2^(2 n p)` (same order as
        // `2^(n p) |I|`).
        let e = match p.cost_norm {
            CostNorm::Squared => 1.0,
            CostNorm::Euclidean => 2.0,
        };
        let mut w2 = [0; 4];
        for (n, w) in w2.iter_mut().enumerate() {
            *w = quantize(
                libm::exp2(e * n as f64 * p.p_weight),
                TRQ_FRAC,
                18,
                "p_weight",
            )?;
        }
        Ok(Self {
            a: qc(1.0 - m.r_s_ohm * ts / m.l_d_h, "r_s_ohm")?,
            lambda: qc(p.meas_age_periods, "meas_age_periods")?,
            u0: q(u0, "u_dc_v")?,
            u0_half: q(0.5 * u0, "u_dc_v")?,
            u0_h: q(0.5 * libm::sqrt(3.0) * u0, "u_dc_v")?,
            psi_l: q(m.psi_pm_wb / m.l_d_h, "psi_pm_wb")?,
            kinv_t: q(1.0 / kt, "torque_psi_wb")?,
            tol: q(p.t_tol_nm / kt, "t_tol_nm")?,
            k_int: qc(p.k_int_per_s * ts, "k_int_per_s")?,
            int_lim: q(p.int_limit_nm / kt, "int_limit_nm")?,
            int_conditional: p.int_conditional,
            kp_o: qc(b * p.obs_kp_v_per_a, "obs_kp_v_per_a")?,
            ki_o: qc(b * p.obs_kp_v_per_a * p.obs_ki_per_s * ts, "obs_ki_per_s")?,
            eta_lim: q(b * p.obs_limit_v, "obs_limit_v")?,
            w2,
        })
    }
}

/// Inputs of one period (from the ADC/encoder front end).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FixedInputs {
    /// Measured `(i_d, i_q)` (averaged), CUR.
    pub i_dq: (i32, i32),
    /// `(cos, sin)` of the rotor angle at the middles of [k-1, k], [k, k+1],
    /// [k+1, k+2], COEF.
    pub trig: [(i32, i32); 3],
    /// Electrical angle increment per period `w Ts`, rad, COEF.
    pub w_ts: i32,
    /// Torque reference `T*_origin[k]`, TRQ.
    pub t_ref: i32,
}

/// State registers of the core.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FixedState {
    /// `S[k]` (applied over [k, k+1]).
    pub s_applied: u8,
    /// `S[k-1]`.
    pub s_prev: u8,
    /// Observer outputs of the previous period `(eta_d, eta_q)`, CUR.
    pub eta_prev: (i32, i32),
    /// Integrator output `x` (A), CUR.
    pub x: i32,
    /// Previous decision had a candidate in the band (integrator enable).
    pub band_reached: bool,
    /// Previous original reference in current units, CUR.
    pub iq_ref_prev: i32,
    /// Observer estimates `(i_hat_d, i_hat_q)`, CUR.
    pub i_hat: (i32, i32),
    /// Observer integrals `(nu_d, nu_q)`, CUR.
    pub nu: (i32, i32),
}

/// Outputs of one period.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FixedOutputs {
    /// `S[k+1]`, bits `SaSbSc`.
    pub s_next: u8,
    /// Modified reference in current units `i_q*`, CUR.
    pub iq_ref: i32,
    /// Observer outputs `(eta_d, eta_q)` (= b eps), CUR.
    pub eta: (i32, i32),
    /// Delay-compensated `I_hat[k+1]`, CUR.
    pub i1: (i32, i32),
    /// Per candidate `(i_d, i_q)` at k+2, CUR.
    pub i2: [(i32, i32); 8],
    /// Per candidate `|i_q* - i_q2|`, CUR.
    pub err: [i32; 8],
    /// Per candidate cost `w2[n] |I|^2` (COST).
    pub cost2: [i64; 8],
    /// State for the next period.
    pub next: FixedState,
}

/// Rounds an exact 32-fraction-bit sum to CUR: `sat25((x + 2^15) >> 16)`.
#[inline]
pub fn rnd(x: i64) -> i32 {
    sat25(rshift_round(x, FRAC))
}

/// Exact product COEF x CUR (43 bits, 32 fraction bits).
#[inline]
fn p(c: i32, x: i32) -> i64 {
    c as i64 * x as i64
}

/// `(alpha2, beta)` of switch state `s` (bits `SaSbSc`): its voltage vector
/// in the stator frame is `U0 (alpha2 / 2, beta sqrt(3) / 2)`, with
/// `alpha2 = 2 Sa - Sb - Sc` in -2..=2 and `beta = Sb - Sc` in -1..=1.
#[inline]
fn alpha_beta(s: u8) -> (i64, i64) {
    let (a, b, c) = (((s >> 2) & 1) as i64, ((s >> 1) & 1) as i64, (s & 1) as i64);
    (2 * a - b - c, b - c)
}

/// Exact dq current step of state `s` at the angle `(c, s)` (32 fraction
/// bits): `(alpha2 (U0/2) c + beta U0h s, -alpha2 (U0/2) s + beta U0h c)`,
/// the rotation of the stator-frame vector into the rotor frame. Four
/// products per angle (`U0/2 c`, `U0/2 s`, `U0h c`, `U0h s`); 000 and 111
/// give exactly 0. Used at the angles of [k-1, k] and [k, k+1], where one
/// state is known and its step enters the MAC unrounded.
fn volt_exact(p_: &FixedParams, (c, s): (i32, i32), st: u8) -> (i64, i64) {
    let (al, be) = alpha_beta(st);
    (
        al * p(c, p_.u0_half) + be * p(s, p_.u0_h),
        -al * p(s, p_.u0_half) + be * p(c, p_.u0_h),
    )
}

/// Rounded leg vectors at the angle of [k+1, k+2], CUR: leg a `(U0 c,
/// -U0 s)` and leg b `(-U0/2 c + U0h s, U0/2 s + U0h c)`, each rounded once
/// (U0 = 2 U0/2); leg c is `-(a + b)`. The candidates' steps are integer
/// sums of these, so opposite states (100 and 011, ...) give exactly
/// opposite steps and 000, 111 exactly 0.
fn legs(p_: &FixedParams, (c, s): (i32, i32)) -> [(i32, i32); 2] {
    [
        (rnd(2 * p(c, p_.u0_half)), rnd(-2 * p(s, p_.u0_half))),
        (
            rnd(p(s, p_.u0_h) - p(c, p_.u0_half)),
            rnd(p(s, p_.u0_half) + p(c, p_.u0_h)),
        ),
    ]
}

/// Step of candidate `s` from the rounded legs: `(Sa - Sc) a + (Sb - Sc) b`
/// (= `Sa a + Sb b + Sc c` with `c = -(a + b)`), exact integers (26 bits).
fn cand_step(l: &[(i32, i32); 2], s: u8) -> (i64, i64) {
    let (a, b, c) = (((s >> 2) & 1) as i64, ((s >> 1) & 1) as i64, (s & 1) as i64);
    let (ka, kb) = (a - c, b - c);
    (
        ka * l[0].0 as i64 + kb * l[1].0 as i64,
        ka * l[0].1 as i64 + kb * l[1].1 as i64,
    )
}

/// One control period of the core. Pure function of (state, inputs, params).
///
/// Every model step (eq. 5/10) is one MAC expression, rounded once:
/// `next = R(a i + (w Ts) J i_x + u + (eta << 16))` with `R(x) = sat25((x +
/// 2^15) >> 16)`, `J i = (i_q, -i_d)` and the back-EMF term `-(w Ts) psi/L`
/// on the q axis. Terms with 16 zero low bits (`eta << 16`, `nu << 16`,
/// `x << 16`, `i_m << 16`) commute with the rounding, so the core may add
/// them before or after the shift.
pub fn decide(st: &FixedState, inp: &FixedInputs, p_: &FixedParams) -> FixedOutputs {
    let g = inp.w_ts;
    let im = inp.i_dq;
    let gpsi = p(g, p_.psi_l);
    let sh = |x: i32| (x as i64) << FRAC;

    // Measurement age (interpretation 14): i0 = im + lambda (full - im),
    // as one MAC: R(lambda full + (im << 16) - lambda im).
    let v0 = volt_exact(p_, inp.trig[0], st.s_prev);
    let full = (
        rnd(p(p_.a, im.0) + p(g, im.1) + v0.0 + sh(st.eta_prev.0)),
        rnd(p(p_.a, im.1) - p(g, im.0) - gpsi + v0.1 + sh(st.eta_prev.1)),
    );
    let i0 = (
        rnd(p(p_.lambda, full.0) + sh(im.0) - p(p_.lambda, im.0)),
        rnd(p(p_.lambda, full.1) + sh(im.1) - p(p_.lambda, im.1)),
    );

    // Eq. (13) in current units: x += K Ts (iq*_prev - i_q0), enabled when
    // the previous decision reached the band (if `int_conditional`).
    let x = if st.band_reached || !p_.int_conditional {
        clamp(
            rnd(p(p_.k_int, st.iq_ref_prev) - p(p_.k_int, i0.1) + sh(st.x)),
            p_.int_lim,
        )
    } else {
        st.x
    };
    // T* -> A: TRQ (14 frac) x KINV (16 frac) -> 30 frac -> CUR (16).
    let iq_orig = sat25(rshift_round(inp.t_ref as i64 * p_.kinv_t as i64, TRQ_FRAC));
    let iq_ref = add(iq_orig, x);

    // Observer (14)-(16) per axis, parallel model: kp (i0 - i_hat) + nu as
    // one MAC, then the clamp.
    let obs = |k: i32, i0: i32, ih: i32, nu: i32| rnd(p(k, i0) - p(k, ih) + sh(nu));
    let eta = (
        clamp(obs(p_.kp_o, i0.0, st.i_hat.0, st.nu.0), p_.eta_lim),
        clamp(obs(p_.kp_o, i0.1, st.i_hat.1, st.nu.1), p_.eta_lim),
    );
    let nu = (
        clamp(obs(p_.ki_o, i0.0, st.i_hat.0, st.nu.0), p_.eta_lim),
        clamp(obs(p_.ki_o, i0.1, st.i_hat.1, st.nu.1), p_.eta_lim),
    );

    // Eq. (10): i1 and the observer's own prediction from i_hat.
    let v1 = volt_exact(p_, inp.trig[1], st.s_applied);
    let v1 = (v1.0, v1.1 - gpsi);
    let i1 = (
        rnd(p(p_.a, i0.0) + p(g, i0.1) + v1.0 + sh(eta.0)),
        rnd(p(p_.a, i0.1) - p(g, i0.0) + v1.1 + sh(eta.1)),
    );
    let i_hat = (
        rnd(p(p_.a, st.i_hat.0) + p(g, i0.1) + v1.0 + sh(eta.0)),
        rnd(p(p_.a, st.i_hat.1) - p(g, i0.0) + v1.1 + sh(eta.1)),
    );

    // Eq. (11) for the 8 candidates.
    let l2 = legs(p_, inp.trig[2]);
    let base = (
        p(p_.a, i1.0) + p(g, i1.1),
        p(p_.a, i1.1) - p(g, i1.0) - gpsi,
    );
    let mut out = FixedOutputs {
        iq_ref,
        eta,
        i1,
        ..Default::default()
    };
    for s in 0..8u8 {
        let v2 = cand_step(&l2, s);
        let i2 = (
            rnd(base.0 + ((v2.0 + eta.0 as i64) << FRAC)),
            rnd(base.1 + ((v2.1 + eta.1 as i64) << FRAC)),
        );
        let err = (iq_ref as i64 - i2.1 as i64).abs().min(CUR_MAX) as i32;
        // CSQ = floor(CUR / 2^8): the square's second operand, 17 bits.
        let (dc, qc) = ((i2.0 >> CSQ_SHIFT) as i64, (i2.1 >> CSQ_SHIFT) as i64);
        let sq = i2.0 as i64 * dc + i2.1 as i64 * qc;
        let mag = sat25(rshift_round(sq, MAG_SHIFT)) as i64;
        let n = (SWITCH_WEIGHT[st.s_applied as usize & 7][s as usize]).trailing_zeros() as usize;
        out.i2[s as usize] = i2;
        out.err[s as usize] = err;
        out.cost2[s as usize] = mag * p_.w2[n] as i64;
    }
    out.s_next = select(&out.err, &out.cost2, p_.tol, st.s_applied);
    out.next = FixedState {
        s_applied: out.s_next,
        s_prev: st.s_applied,
        eta_prev: eta,
        x,
        band_reached: out.err.iter().any(|&e| e <= p_.tol),
        iq_ref_prev: iq_orig,
        i_hat,
        nu,
    };
    out
}

/// Band logic with the reference's tie rules (in band: least cost; none in
/// band: least error; ties: fewer transitions from `s_applied`, then lowest
/// index). In hardware: 8 parallel keys, a 3-level compare tree.
pub fn select(err: &[i32; 8], cost2: &[i64; 8], tol: i32, s_applied: u8) -> u8 {
    let key = |s: usize| {
        let n = ((s as u8 ^ s_applied) & 7).count_ones() as i64;
        if err[s] <= tol {
            (0i64, cost2[s], n)
        } else {
            (1i64, err[s] as i64, n)
        }
    };
    let mut best = 0usize;
    for s in 1..8 {
        if key(s) < key(best) {
            best = s;
        }
    }
    best as u8
}
