//! Bit-accurate model of the FPGA MPDCC core (paper 001, Secs. IV-VI): the
//! datapath of the central scheduler (quantization, lazy check, common terms
//! of eq. (14)) and of the explorer units (extrapolation at `k + L`, linear
//! interpolation, Algorithm 2, cost), in explicit integer arithmetic with the
//! formats of [`super::formats`]. The control flow of Algorithm 1 is in
//! [`super::scheduler`], the clock-cycle count in [`super::cycles`]. The
//! design notes, measurements and the formats table are in
//! docs/mpdcc-fpga.md.
//!
//! This model is the oracle for the future Verilog core: every rounding,
//! saturation and word width below is part of the specification.
//!
//! # Prediction model (eqs. 4, 9, 13, 14, 17-18), as implemented
//! With `T = T_s,pu`, `t = m L T` (node `m = 1, 2, 4, 8`) and `v_abc(s)` held:
//!
//! ```text
//! Delta i_s  = t [ -i_s/tau_s + X_m/(D tau_r) psi_r - X_m/D omega_r J psi_r + X_r/D K v ]
//!              + p (t omega_r)^2 psi_r                          (eq. 9a: forward Euler + correction)
//! Delta i_s* = t omega_s J i_s*                                 (eq. 14b, A_0 - I)
//! Delta x_inv= t B_inv(s) i_s,abc(k)                            (eq. 18b)
//! ```
//!
//! The voltage part is done per phase, `K^-1 K v = v - mean(v)`, so
//! `K^-1 (X_r/D t K v) = (X_r/(3D)) t (3 v_x - v_a - v_b - v_c)`: one
//! multiply per phase, no `sqrt(3)` on the candidate path.
//!
//! # Accuracy options ([`FpgaConfig`]; all on in [`Structure::CORE`], the
//! specification of the Verilog core; all off in `Structure::PAPER`, a research option)
//! Measured against the exact model, the paper's structure leaves errors of
//! several 0.01 pu at `k+L` and, worse, the single chord through `k` and
//! `k+L` misses the curvature of the current trajectories beyond `L`. Each
//! option is a cheap, higher-order term or a better interpolant:
//! - `ref_second_order`, `third_order`: the reference and back-EMF rotations
//!   to second/third order (`1 - theta^2/2`, `theta - theta^3/6`).
//! - `stator_damping`: the `-1/tau_s` row of `F^2 t^2/2`, i.e. the machine
//!   rates times `(1 - t/(2 tau_s))` (design-time constants).
//! - `capacitor_drift`: the output voltage at mid-interval, `v(k) + Delta
//!   v/2`, because `v_n` and `v_ph` move along the prediction (eq. 18b).
//!   This was the largest single error (0.01 pu rms at `k+32`).
//! - `exact_first_step`: feasibility at `k+1` and `J_dl` from the one-step
//!   prediction (the lazy check's), not from the interpolation.
//! - `nodes = 3`: piecewise-linear interpolation through `k+L`, `k+2L`,
//!   `k+4L` (all nodes from the same products by shifts), one Algorithm-2
//!   search per piece.
//! - `current_midpoint` (off by default): eq. (18b) with the mid-interval
//!   current; it did not reduce the mismatch measurably.
//!
//! # Interpretations (the paper leaves these open)
//! - **Increments, not absolute states**: `y(k+L) - y(k)` is computed
//!   directly (never `A(L) x` minus `x`), which avoids cancellation in 16 bits.
//! - **Wide accumulation**: products are exact (`16 x 16` or `18 x 16`, as a
//!   Zynq DSP48E1 takes `25 x 18`) and summed exactly in 48 bits, rounded once
//!   to Q2.13. The paper's Fig. 3 block has a 16-bit adder; on our target the
//!   DSP48E1 post-adder is 48 bits wide at no cost.
//! - **One step from its own products**: the lazy check uses first-order
//!   products with one-step coefficients (f17) plus the `L^2`/`L^3` groups
//!   shifted by `2 lambda`/`3 lambda`, so the `L`-step corrections do not
//!   leak into it (error <= 4 LSB, tested).
//! - **Interpolation** (eq. 20) keeps `a_j = y~_j(k)` and
//!   `b_j = Delta_j / L`; the division by `L` is folded into Algorithm 2
//!   ([`super::binsearch`]), exactly.
//! - **Cost** `J = f_s / L* + lambda_n v_n(k+L*)^2` with `1/L*` from a
//!   reciprocal ROM (UQ1.17, 18 bits) and `v_n(k+L*)` interpolated on the
//!   piece containing `L*`. `J` is UQ15.17 in a `u32`; `+inf` (`L* = 0`) is
//!   `u32::MAX`.
//! - **Bounds** are rounded to nearest (rounding them inward keeps the
//!   FPGA-driven loop strictly inside but makes it disagree with the
//!   reference whenever the reference rides a bound within an LSB).
//! - **Correction factor `p`** is a parameter ([`FpgaConfig::p_correction`]);
//!   see [`p_taylor`] and docs/mpdcc-fpga.md for what the paper's 0.21096 is
//!   and what our machine needs.

use super::anpc;
use super::binsearch::{self, Lj, SearchRange};
use super::controller::{Controller, CtrlState, Decision, StateError};
use super::formats::{self, konst, mul, sat16, sub, F_C, F_I, F_SMALL};
use super::params::DriveParams;
use super::scheduler::{self, Explorer, ExplorerResult};
use crate::fixedpoint::rshift_round;

/// Fractional bits of the wide accumulator (products of Q1.14 coefficients
/// with Q1.14 flux; Q2.13 operands are shifted left by one).
pub const F_W: u32 = 28;
/// Fractional bits of the cost register `J` (UQ15.17).
pub const F_COST: u32 = 17;
/// Fractional bits of the reciprocal ROM (UQ1.17, 18-bit words).
pub const F_RECIP: u32 = 17;
/// Fractional bits of `lambda_n` (UQ8.8).
pub const F_LAMBDA: u32 = 8;
/// `J = +inf` (`L* = 0`).
pub const COST_INF: u32 = u32::MAX;

/// The paper's model correction factor (Table I).
pub const P_PAPER: f64 = 0.21096;

/// `p` from the second-order Taylor term of the exact discretization:
/// `e^{F t}` has `t^2/2 (F^2)_{13} = t^2/2 (X_m/D omega_r^2 - ...)`, so the
/// `omega_r^2` part of the `(i_alpha, psi_alpha)` entry is
/// `(X_m / (2D)) (t omega_r)^2`, which eq. (9a) writes as `p (t omega_r)^2`.
pub fn p_taylor(m: &super::params::MachineParams) -> f64 {
    m.x_m_pu / (2.0 * m.d_pu())
}

/// Build-time choices of the FPGA core: the frozen core, the one the Verilog
/// `mpdcc_core` implements (its arithmetic is [`Structure::CORE`]). Only the
/// number of explorers and the design-time value of `p` are free; both
/// change constants or the cycle count, never the structure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FpgaConfig {
    /// Number of explorer units `n` (1..=16).
    pub explorers: u32,
    /// Model correction factor `p` of eq. (4)/(9b).
    pub p_correction: f64,
}

impl FpgaConfig {
    /// The core with two explorers (Sec. VII-A) and `p` from [`p_taylor`].
    pub fn core(m: &super::params::MachineParams) -> Self {
        Self::with_p(p_taylor(m))
    }

    /// [`FpgaConfig::core`] with another `p`.
    pub fn with_p(p_correction: f64) -> Self {
        Self {
            explorers: 2,
            p_correction,
        }
    }
}

/// The datapath's structure: which accuracy terms and how many
/// interpolation nodes. [`Structure::CORE`] is the specification of the
/// Verilog core; other structures (the paper's, design sweeps) are research
/// options, built only with the `mpdcc-research` feature
/// ([`MpdccFixed::research`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Structure {
    /// Add the second-order term `-(omega_s L T)^2/2 i*` to the reference
    /// rotation `A_0` of eq. (14b) (the paper has first order only).
    pub ref_second_order: bool,
    /// Judge feasibility at `k+1` and `J_dl` with the one-step prediction
    /// (as the lazy check does) instead of the interpolated `a_j + Delta_j/L`.
    pub exact_first_step: bool,
    /// Third-order rotation terms: an `L^3` group `-(theta^2/6)` times the
    /// first-order rotation terms of `omega_r` and `omega_s`, i.e. `sin(theta)`
    /// to third order (the paper stops at second order, `p`).
    pub third_order: bool,
    /// Second-order stator damping: the machine rates over `t = m L T`
    /// scaled by `(1 - t/(2 tau_s))` (the `-1/tau_s` row of `F^2 t^2/2`,
    /// which multiplies the whole current rate), an `L^2` group.
    pub stator_damping: bool,
    /// Use the mid-interval output voltage: the phase and dc-link capacitor
    /// voltages drift over the `l` steps (eq. 18b), which moves `v_abc(s)`;
    /// the mean voltage is `v(k) + Delta v(l)/2` (trapezoid, second order).
    pub capacitor_drift: bool,
    /// Use the mid-interval phase current in eq. (18b): the capacitor
    /// voltages integrate `i(k) + Delta i(l)/2` instead of `i(k)` held
    /// (trapezoid, second order; `Delta i` from the candidate's prediction).
    pub current_midpoint: bool,
    /// Interpolation nodes `K` (1..=4): 1 = the paper's single chord from
    /// `k` to `k+L` (eq. 20); `K > 1` = piecewise linear through
    /// `k + 2^i L`, `i < K`, the last piece extended to `N_bar` (as many
    /// nodes as fit below `N_bar` are used).
    pub nodes: u32,
}

impl Structure {
    /// The frozen core: the paper's structure plus the accuracy options (all
    /// but `current_midpoint`) and four interpolation nodes. Costs: a dozen
    /// multiplies in the scheduler, about 30 block operations and three more
    /// search pieces per candidate (docs/mpdcc-fpga.md, [`super::cycles`]).
    pub const CORE: Structure = Structure {
        ref_second_order: true,
        exact_first_step: true,
        third_order: true,
        stator_damping: true,
        capacitor_drift: true,
        current_midpoint: false,
        nodes: 4,
    };

    /// As the paper describes it: first-order reference rotation,
    /// interpolated first step, one chord.
    #[cfg(feature = "mpdcc-research")]
    pub const PAPER: Structure = Structure {
        ref_second_order: false,
        exact_first_step: false,
        third_order: false,
        stator_damping: false,
        capacitor_drift: false,
        current_midpoint: false,
        nodes: 1,
    };
}

/// Why the FPGA model cannot be built for these parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FpgaError {
    /// A parameter failed [`DriveParams::validate`].
    Params(super::params::ParamError),
    /// A coefficient does not fit its 16-bit format (name of the coefficient).
    CoefficientRange(&'static str),
    /// `explorers` outside 1..=16.
    Explorers,
    /// `p_correction` not finite or outside 0..=8.
    Correction,
    /// `nodes` outside 1..=4.
    Nodes,
}

impl core::fmt::Display for FpgaError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            FpgaError::Params(e) => write!(f, "{e}"),
            FpgaError::CoefficientRange(n) => {
                write!(f, "FPGA coefficient `{n}` does not fit its 16-bit format")
            }
            FpgaError::Explorers => write!(f, "explorers must be in 1..=16"),
            FpgaError::Correction => write!(f, "p_correction must be finite and in 0..=8"),
            FpgaError::Nodes => write!(f, "nodes must be in 1..=4"),
        }
    }
}

/// Design-time constants (ROM / parameter registers), raw integers.
#[derive(Debug, Clone, PartialEq)]
pub struct Coeffs {
    /// `lambda = log2 L`.
    pub lambda: u32,
    /// `M = log2 N_bar` (search bits).
    pub m_bits: u32,
    /// `N_bar`, steps.
    pub n_bar: u32,
    /// `L T / tau_s`, Q1.14.
    pub c_tau: i16,
    /// `L T X_m / (D tau_r)`, Q1.14.
    pub c_r: i16,
    /// `L T X_m / D` (times `omega_r` at run time), Q1.14.
    pub c_w: i16,
    /// `p (L T)^2` (times `omega_r^2` at run time), Q1.14.
    pub c_p: i16,
    /// `L T` (times `omega_s` at run time), Q1.14.
    pub c_s: i16,
    /// `L T X_r / (3 D)` (times `3 v_x - sum v`), Q1.14.
    pub g3: i16,
    /// `L T / (2 C_dc)` (times `i_x`), Q1.14.
    pub c_n: i16,
    /// `L T / C_ph` (times `i_x`), Q1.14.
    pub c_ph: i16,
    /// `sqrt(3)/2`, Q1.14.
    pub s3h: i16,
    /// `V_dc / 2`, Q2.13.
    pub v_dc_half: i16,
    /// `V_dc / 4` (phase capacitor reference), Q2.13.
    pub v_ph_ref: i16,
    /// Bounds `[delta_i x3, v_n, v_ph x3]`, Q2.13.
    pub bnd: [i16; 7],
    /// `lambda_n`, UQ8.8.
    pub lambda_n: u16,
    /// `round(2^17 / l)` for `l = 0..=N_bar` (entry 0 unused), UQ1.17.
    pub recip: heapless::Vec<u32, 1025>,
    /// [`Structure::ref_second_order`].
    pub ref_second_order: bool,
    /// [`Structure::exact_first_step`].
    pub exact_first_step: bool,
    /// [`Structure::third_order`].
    pub third_order: bool,
    /// `(L T)^2 / 6`, Q1.14 (third-order rotation term).
    pub c_3: i16,
    /// [`Structure::capacitor_drift`].
    pub capacitor_drift: bool,
    /// [`Structure::current_midpoint`].
    pub current_midpoint: bool,
    /// [`Structure::nodes`].
    pub nodes: u32,
    /// Stator damping `L T/(2 tau_s)` (0 without the option), Q1.14.
    pub c_d: i16,
    /// `g3 c_d`, Q1.14.
    pub gd: i16,
    /// One-step coefficients (lazy check, first step), f17: `T/tau_s`.
    pub c_tau1: i16,
    /// `T X_m/(D tau_r)`, f17.
    pub c_r1: i16,
    /// `T X_m/D`, f17.
    pub c_w1: i16,
    /// `T`, f17.
    pub c_s1: i16,
    /// `T X_r/(3D)`, f17.
    pub g3_1: i16,
}

impl Coeffs {
    /// Quantizes the design constants; every one must fit without saturation.
    pub fn new(p: &DriveParams, cfg: &FpgaConfig, st: &Structure) -> Result<Self, FpgaError> {
        let p_corr = cfg.p_correction;
        p.validate().map_err(FpgaError::Params)?;
        if !p_corr.is_finite() || !(0.0..=8.0).contains(&p_corr) {
            return Err(FpgaError::Correction);
        }
        let m = &p.machine;
        let c = &p.controller;
        let t = c.ts_pu(m);
        let lt = c.extrapolation_steps as f64 * t;
        let d = m.d_pu();
        // Second-order stator damping of the machine rates: over m L steps
        // they are scaled by (1 - m c_d), c_d = L T/(2 tau_s).
        let c_d = if st.stator_damping {
            lt / (2.0 * m.tau_s_pu())
        } else {
            0.0
        };
        if !(1..=MAX_NODES as u32).contains(&st.nodes) {
            return Err(FpgaError::Nodes);
        }
        // Node K sits at 2^(K-1) L, which must not pass N_bar: use as many
        // nodes as fit (down to the single chord).
        let mut nodes = st.nodes;
        while nodes > 1 && (c.extrapolation_steps << (nodes - 1)) > c.horizon_max_steps {
            nodes -= 1;
        }
        let q = |name: &'static str, v: f64, f: u32| -> Result<i16, FpgaError> {
            match konst(v, f) {
                (r, false) => Ok(r),
                (_, true) => Err(FpgaError::CoefficientRange(name)),
            }
        };
        let n_bar = c.horizon_max_steps;
        let recip = recip_rom(n_bar)?;
        let lam = libm::round(c.lambda_n * (1u32 << F_LAMBDA) as f64);
        if lam > u16::MAX as f64 {
            return Err(FpgaError::CoefficientRange("lambda_n"));
        }
        // Bounds: round to nearest (see docs/mpdcc-fpga.md: rounding them
        // inward keeps the FPGA-driven loop strictly inside but makes the
        // FPGA disagree with the reference whenever the reference rides a
        // bound within an LSB, e.g. the slow v_ph).
        let bq = |name: &'static str, v: f64| -> Result<i16, FpgaError> {
            let r = libm::floor(libm::ldexp(v, F_I as i32) + 0.5);
            if (0.0..=i16::MAX as f64).contains(&r) {
                Ok(r as i16)
            } else {
                Err(FpgaError::CoefficientRange(name))
            }
        };
        let di = bq("delta_i", c.delta_i_pu)?;
        let bn = bq("v_n_bound", c.v_n_bound_pu)?;
        let bp = bq("v_ph_bound", c.v_ph_bound_pu)?;
        Ok(Self {
            lambda: c.extrapolation_steps.trailing_zeros(),
            m_bits: n_bar.trailing_zeros(),
            n_bar,
            c_tau: q("c_tau", lt / m.tau_s_pu(), F_C)?,
            c_r: q("c_r", lt * m.x_m_pu / (d * m.tau_r_pu()), F_C)?,
            c_w: q("c_w", lt * m.x_m_pu / d, F_C)?,
            c_p: q("c_p", p_corr * lt * lt, F_C)?,
            c_s: q("c_s", lt, F_C)?,
            g3: q("g3", lt * m.x_r_pu() / (3.0 * d), F_C)?,
            c_n: q("c_n", lt / (2.0 * p.inverter.c_dc_pu), F_C)?,
            c_ph: q("c_ph", lt / p.inverter.c_ph_pu, F_C)?,
            s3h: q("s3h", 0.866_025_403_784_438_6, F_C)?,
            v_dc_half: q("v_dc_half", 0.5 * p.inverter.v_dc_pu, F_I)?,
            v_ph_ref: q("v_ph_ref", p.inverter.v_ph_ref_pu(), F_I)?,
            bnd: [di, di, di, bn, bp, bp, bp],
            lambda_n: lam as u16,
            recip,
            ref_second_order: st.ref_second_order,
            exact_first_step: st.exact_first_step,
            third_order: st.third_order,
            c_3: q("c_3", lt * lt / 6.0, F_C)?,
            capacitor_drift: st.capacitor_drift,
            current_midpoint: st.current_midpoint,
            nodes,
            c_d: q("c_d", c_d, F_C)?,
            gd: q("gd", c_d * lt * m.x_r_pu() / (3.0 * d), F_C)?,
            c_tau1: q("c_tau1", t / m.tau_s_pu(), F_SMALL)?,
            c_r1: q("c_r1", t * m.x_m_pu / (d * m.tau_r_pu()), F_SMALL)?,
            c_w1: q("c_w1", t * m.x_m_pu / d, F_SMALL)?,
            c_s1: q("c_s1", t, F_SMALL)?,
            g3_1: q("g3_1", t * m.x_r_pu() / (3.0 * d), F_SMALL)?,
        })
    }
}

impl Coeffs {
    /// The frozen core's constants ([`Structure::CORE`]) for `L = 2^lambda`,
    /// `N_bar = 2^m_bits` steps and `nodes` interpolation nodes, every
    /// register word zero: the constants of a core whose words come from its
    /// register page (the simulated PL fills them in).
    pub fn core_shape(lambda: u32, m_bits: u32, nodes: u32) -> Result<Self, FpgaError> {
        let st = Structure::CORE;
        if !(1..=MAX_NODES as u32).contains(&nodes) {
            return Err(FpgaError::Nodes);
        }
        if lambda > m_bits || m_bits > 10 {
            return Err(FpgaError::CoefficientRange("recip"));
        }
        let n_bar = 1u32 << m_bits;
        Ok(Self {
            lambda,
            m_bits,
            n_bar,
            c_tau: 0,
            c_r: 0,
            c_w: 0,
            c_p: 0,
            c_s: 0,
            g3: 0,
            c_n: 0,
            c_ph: 0,
            s3h: 0,
            v_dc_half: 0,
            v_ph_ref: 0,
            bnd: [0; 7],
            lambda_n: 0,
            recip: recip_rom(n_bar)?,
            ref_second_order: st.ref_second_order,
            exact_first_step: st.exact_first_step,
            third_order: st.third_order,
            c_3: 0,
            capacitor_drift: st.capacitor_drift,
            current_midpoint: st.current_midpoint,
            nodes,
            c_d: 0,
            gd: 0,
            c_tau1: 0,
            c_r1: 0,
            c_w1: 0,
            c_s1: 0,
            g3_1: 0,
        })
    }

    /// The datapath is the frozen core's ([`Structure::CORE`]): the
    /// structure flags a Verilog `mpdcc_core` implements.
    pub fn is_core_structure(&self) -> bool {
        let st = Structure::CORE;
        self.ref_second_order == st.ref_second_order
            && self.exact_first_step == st.exact_first_step
            && self.third_order == st.third_order
            && self.capacitor_drift == st.capacitor_drift
            && self.current_midpoint == st.current_midpoint
    }
}

/// `round(2^17 / l)` for `l = 0..=n_bar` (entry 0 unused: `L* = 0` costs
/// `+inf`), UQ1.17.
fn recip_rom(n_bar: u32) -> Result<heapless::Vec<u32, 1025>, FpgaError> {
    let mut recip = heapless::Vec::new();
    for l in 0..=n_bar {
        let r = recip_word(l);
        recip
            .push(r)
            .map_err(|_| FpgaError::CoefficientRange("recip"))?;
    }
    Ok(recip)
}

/// The sampled state in its interface registers (Alg. 1's "writes it into
/// registers"), raw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Inputs {
    /// `i_s,alpha_beta`, Q2.13.
    pub i_ab: [i16; 2],
    /// `psi_r,alpha_beta`, Q1.14.
    pub psi_ab: [i16; 2],
    /// `v_n`, Q2.13.
    pub v_n: i16,
    /// `v_ph,abc`, Q2.13.
    pub v_ph: [i16; 3],
    /// `i_s*,alpha_beta(k)`, Q2.13.
    pub i_ref_ab: [i16; 2],
    /// `omega_r`, Q2.13.
    pub omega_r: i16,
    /// `omega_s`, Q2.13.
    pub omega_s: i16,
    /// `s(k-1)`.
    pub s_prev: [u8; 3],
    /// Some input saturated while quantizing.
    pub saturated: bool,
}

impl Inputs {
    /// Quantizes a (checked) controller state; NaN/inf and bad positions are
    /// rejected by [`CtrlState::check`] first.
    pub fn quantize(st: &CtrlState) -> Result<Self, StateError> {
        st.check()?;
        let mut sat = false;
        let mut q = |v: f64, f: u32| -> i16 {
            // check() guarantees finiteness.
            let (r, s) = formats::quantize(v, f).unwrap_or((0, true));
            sat |= s;
            r
        };
        let i_ab = [q(st.x_m[0], F_I), q(st.x_m[1], F_I)];
        let psi_ab = [q(st.x_m[2], F_C), q(st.x_m[3], F_C)];
        let v_n = q(st.v_n_pu, F_I);
        let v_ph = [
            q(st.v_ph_pu[0], F_I),
            q(st.v_ph_pu[1], F_I),
            q(st.v_ph_pu[2], F_I),
        ];
        let i_ref_ab = [q(st.i_ref_ab_pu[0], F_I), q(st.i_ref_ab_pu[1], F_I)];
        let omega_r = q(st.omega_r_pu, F_I);
        let omega_s = q(st.omega_s_pu, F_I);
        Ok(Self {
            i_ab,
            psi_ab,
            v_n,
            v_ph,
            i_ref_ab,
            omega_r,
            omega_s,
            s_prev: st.s_prev,
            saturated: sat,
        })
    }
}

/// `K^-1` of eq. (1) on Q2.13 words: `[x_a, -x_a/2 + s3h x_b, -x_a/2 - s3h x_b]`
/// with `x_a/2` rounded half up and `s3h x_b` rounded to Q2.13.
pub fn inv_clarke_q(x: [i16; 2], s3h: i16) -> [i16; 3] {
    let h = rshift_round(x[0] as i64, 1);
    let r = mul(s3h, F_C, x[1], F_I, F_I) as i64;
    [x[0], sat16(-h + r), sat16(-h - r)]
}

/// Round a wide value with `f` fractional bits to Q2.13 (half up, saturate).
#[inline]
fn to_q13(w: i64, f: u32) -> i16 {
    sat16(rshift_round(w, f - F_I))
}

/// Terms common to all candidates (Sec. V-A), computed by the scheduler.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Common {
    /// Output errors at `k`, `a_j = y*_j(k) - y_j(k)`: `[i_abc, v_n, v_ph,abc]`, Q2.13.
    pub e0: [i16; 7],
    /// Switch-independent error change over `m L` steps for the nodes
    /// `m = 1, 2, 4, 8`, abc, Q2.13 (`[0]` is eq. 14's `k+L` term).
    pub dn: [[i16; 3]; MAX_NODES],
    /// Same over one step (lazy check), abc, Q2.13.
    pub dn_1: [i16; 3],
    /// `i_s,abc(k)`, Q2.13.
    pub i_abc: [i16; 3],
    /// `L T/(2 C_dc) i_x`, wide (f27).
    pub pn: [i64; 3],
    /// `L T/C_ph i_x`, wide (f27).
    pub pph: [i64; 3],
    /// Reference change over `m L` steps (`m = 1, 2, 4, 8`), abc, Q2.13.
    pub dref: [[i16; 3]; MAX_NODES],
    /// Registers copied for the explorers: `v_n`, `v_ph`, Q2.13.
    pub v_n: i16,
    /// Phase capacitor voltages, Q2.13.
    pub v_ph: [i16; 3],
}

/// Eq. (14) and the error terms at `k`: the scheduler's common terms.
pub fn common_terms(k: &Coeffs, x: &Inputs) -> Common {
    let lam = k.lambda;
    // Run-time coefficients (16-bit registers, rounded).
    let kw = mul(k.c_w, F_C, x.omega_r, F_I, F_C);
    let w2 = mul(x.omega_r, F_I, x.omega_r, F_I, F_I);
    let kp = mul(k.c_p, F_C, w2, F_I, F_C);
    let ks = mul(k.c_s, F_C, x.omega_s, F_I, F_C);
    // Third order (an L^3 term): kw3 = kw (L T omega_r)^2/6 and
    // ks3 = ks (L T omega_s)^2/6, so that kw - kw3 ~ sin(theta_r) X_m/D.
    let (kw3, ks3) = if k.third_order {
        let tr = mul(k.c_3, F_C, w2, F_I, F_C);
        let s2 = mul(x.omega_s, F_I, x.omega_s, F_I, F_I);
        let ts = mul(k.c_3, F_C, s2, F_I, F_C);
        (mul(kw, F_C, tr, F_C, F_C), mul(ks, F_C, ts, F_C, F_C))
    } else {
        (0, 0)
    };
    let p = |a: i16, b: i16| a as i64 * b as i64; // exact product
    let [ia, ib] = x.i_ab;
    let [pa, pb] = x.psi_ab;
    let [ra, rb] = x.i_ref_ab;
    // Natural response rates times L (f28): -c_tau i + c_r psi - kw J psi.
    let nat_a = -(p(k.c_tau, ia) << 1) + p(k.c_r, pa) + p(kw, pb);
    let nat_b = -(p(k.c_tau, ib) << 1) + p(k.c_r, pb) - p(kw, pa);
    // Terms growing with L^2 (f28): the correction p (L T omega_r)^2 psi and,
    // optionally, the second-order reference rotation (theta^2/2) i*.
    let (k2a, k2b) = if k.ref_second_order {
        let k2 = mul(ks, F_C, ks, F_C + 1, F_C); // theta^2 / 2
        (p(k2, ra) << 1, p(k2, rb) << 1)
    } else {
        (0, 0)
    };
    let cor_a = p(kp, pa) + k2a;
    let cor_b = p(kp, pb) + k2b;
    // Reference rotation times L (f28): ks J i*.
    let ref_a = -(p(ks, rb) << 1);
    let ref_b = p(ks, ra) << 1;
    // Error change: Delta i* - Delta i_nat.
    let rate_a = ref_a - nat_a;
    let rate_b = ref_b - nat_b;
    // Third-order group (f28): minus the L^3 parts of the two rotations,
    // -(-ks3 J i*) + (-kw3 J psi) with J = [0 -1; 1 0].
    let cub_a = (p(ks3, rb) << 1) + p(kw3, pb);
    let cub_b = -(p(ks3, ra) << 1) - p(kw3, pa);
    // Stator damping (f28): the machine part of the rate, -nat, loses
    // m^2 c_d nat over m L steps.
    let dmp_a = p(k.c_d, to_q13(nat_a, F_W)) << 1;
    let dmp_b = p(k.c_d, to_q13(nat_b, F_W)) << 1;
    // Node m L: m (ref - nat) + m^2 (c_d nat - cor) + m^3 cub.
    let node = |m: i64, r: i64, d: i64, c2: i64, c3: i64| m * r + m * m * (d - c2) + m * m * m * c3;
    let dn: [[i16; 3]; MAX_NODES] = core::array::from_fn(|i| {
        let m = 1i64 << i;
        let ab = [
            to_q13(node(m, rate_a, dmp_a, cor_a, cub_a), F_W),
            to_q13(node(m, rate_b, dmp_b, cor_b, cub_b), F_W),
        ];
        inv_clarke_q(ab, k.s3h)
    });
    // One step (f31): own first-order products with the f17 one-step
    // coefficients (so the L-step damping does not leak into the lazy
    // check), plus the L^2 and L^3 groups divided by L^2 and L^3.
    let kw1 = mul(k.c_w1, F_SMALL, x.omega_r, F_I, F_SMALL);
    let ks1 = mul(k.c_s1, F_SMALL, x.omega_s, F_I, F_SMALL);
    let nat1_a = -(p(k.c_tau1, ia) << 1) + p(k.c_r1, pa) + p(kw1, pb);
    let nat1_b = -(p(k.c_tau1, ib) << 1) + p(k.c_r1, pb) - p(kw1, pa);
    let rate1_a = -(p(ks1, rb) << 1) - nat1_a;
    let rate1_b = (p(ks1, ra) << 1) - nat1_b;
    let f1 = F_SMALL + F_C; // 31
    let up = f1 - F_W; // 3
    let d1 = [
        to_q13(
            rate1_a - rshift_round(cor_a << up, 2 * lam) + rshift_round(cub_a << up, 3 * lam),
            f1,
        ),
        to_q13(
            rate1_b - rshift_round(cor_b << up, 2 * lam) + rshift_round(cub_b << up, 3 * lam),
            f1,
        ),
    ];
    // Reference change over m L (f28): rotation to third order.
    let dref: [[i16; 3]; MAX_NODES] = core::array::from_fn(|i| {
        let m = 1i64 << i;
        let ab = [
            to_q13(m * ref_a - m * m * k2a + m * m * m * (p(ks3, rb) << 1), F_W),
            to_q13(m * ref_b - m * m * k2b - m * m * m * (p(ks3, ra) << 1), F_W),
        ];
        inv_clarke_q(ab, k.s3h)
    });
    let i_abc = inv_clarke_q(x.i_ab, k.s3h);
    let e_ab = [sub(ra, ia), sub(rb, ib)];
    let e_abc = inv_clarke_q(e_ab, k.s3h);
    let mut e0 = [0i16; 7];
    e0[..3].copy_from_slice(&e_abc);
    e0[3] = sat16(-(x.v_n as i64));
    for ph in 0..3 {
        e0[4 + ph] = sub(k.v_ph_ref, x.v_ph[ph]);
    }
    Common {
        e0,
        dn,
        dn_1: inv_clarke_q(d1, k.s3h),
        i_abc,
        pn: i_abc.map(|i| p(k.c_n, i)),
        pph: i_abc.map(|i| p(k.c_ph, i)),
        dref,
        v_n: x.v_n,
        v_ph: x.v_ph,
    }
}

/// Wide (f30) one-step voltage terms `g3_1 (3 v_x - sum v)` of candidate
/// `s` (`g3_1` is f17); the `L`-step ones are in [`node_deltas`].
fn voltage_terms_1(k: &Coeffs, c: &Common, s: [u8; 3]) -> [i64; 3] {
    let inv = inverter_terms(c, s);
    let mut v = [0i64; 3];
    for ph in 0..3 {
        let pos = &anpc::TABLE[(s[ph] & 7) as usize];
        v[ph] = pos.rail as i64 * k.v_dc_half as i64
            + pos.n_coef as i64 * c.v_n as i64
            + pos.ph_coef as i64 * c.v_ph[ph] as i64;
        if k.capacitor_drift {
            // Mid-interval voltage over one step: v(k) + Delta v(L)/(2L);
            // Delta v_n = -inv[0], Delta v_ph = -inv[1+ph] (f27), rounded to
            // Q2.13.
            let dv = -(pos.n_coef as i64) * inv[0] - pos.ph_coef as i64 * inv[1 + ph];
            v[ph] += rshift_round(dv, F_C + 1 + k.lambda);
        }
    }
    let sum = v[0] + v[1] + v[2];
    // u_x = 3 v_x - sum v: exact, < 2^17 in magnitude (an 18-bit operand).
    v.map(|vx| k.g3_1 as i64 * (3 * vx - sum))
}

/// Wide (f27) inverter error changes over `L` steps: `[v_n, v_ph,abc]`.
fn inverter_terms(c: &Common, s: [u8; 3]) -> [i64; 4] {
    let mut d = [0i64; 4];
    for ph in 0..3 {
        let pos = &anpc::TABLE[(s[ph] & 7) as usize];
        // e_vn = -v_n, dv_n = -L T/(2C) sum np i  =>  de_vn = +sum np P_n.
        d[0] += pos.np_current as i64 * c.pn[ph];
        // e_ph = ref - v_ph, dv_ph = L T/C_ph c(s) i  =>  de_ph = -c(s) P_ph.
        d[1 + ph] = -(pos.ph_current as i64) * c.pph[ph];
    }
    d
}

/// Error changes `Delta_j` of candidate `s` over one step (`one_step`),
/// Q2.13 (lazy check, first step, `J_dl`); for `l = L` see [`node_deltas`].
pub fn deltas(k: &Coeffs, c: &Common, s: [u8; 3], one_step: bool) -> [i16; 7] {
    if !one_step {
        return node_deltas(k, c, s, 0).map(|v| sat16(v as i64));
    }
    let sh = k.lambda;
    let g = voltage_terms_1(k, c, s);
    let inv = inverter_terms(c, s);
    // Voltage term: f30 (f17 x Q2.13) to Q2.13.
    let mut d = [0i16; 7];
    for ph in 0..3 {
        d[ph] = sub(c.dn_1[ph], sat16(rshift_round(g[ph], F_SMALL)));
    }
    if !k.current_midpoint {
        for j in 0..4 {
            d[3 + j] = sat16(rshift_round(inv[j], F_C + sh));
        }
        return d;
    }
    let cur = [d[0] as i64, d[1] as i64, d[2] as i64];
    let w = midpoint_inverter(k, c, s, cur, 1, sh, c.dref[0]);
    for j in 0..4 {
        d[3 + j] = sat16(w[j]);
    }
    d
}

/// Eq. (18b) with the mid-interval current over `m L` steps (`m = 1` and
/// `sh = lambda` for one step): returns the inverter entries from the
/// current entries `d[0..3]` (already computed).
fn midpoint_inverter(
    k: &Coeffs,
    c: &Common,
    s: [u8; 3],
    d: [i64; 3],
    m: i64,
    sh: u32,
    dref: [i16; 3],
) -> [i64; 4] {
    // Phase current change, Q2.13: Delta i = Delta i* - Delta e.
    let di: [i64; 3] = core::array::from_fn(|ph| rshift_round(dref[ph] as i64, sh) - d[ph]);
    // m P(i + Delta i/2) = (2 m P(i) + m c Delta i) / 2; the products are
    // exact (f27), one rounding at the end.
    let mut w = [0i64; 4];
    for ph in 0..3 {
        let pos = &anpc::TABLE[(s[ph] & 7) as usize];
        let qn = m * k.c_n as i64 * di[ph];
        let qp = m * k.c_ph as i64 * di[ph];
        w[0] += pos.np_current as i64 * (((m * c.pn[ph]) << 1) + qn);
        w[1 + ph] = -(pos.ph_current as i64) * (((m * c.pph[ph]) << 1) + qp);
    }
    w.map(|v| rshift_round(v, F_C + 1 + sh).clamp(-NODE_MAX, NODE_MAX))
}

/// Most interpolation nodes (`k + L`, `+2L`, `+4L`, `+8L`).
pub const MAX_NODES: usize = 4;

/// Node changes of one candidate: `[node][output]`, Q4.13.
pub type Nodes = [[i32; 7]; MAX_NODES];

/// Node registers are 18-bit Q4.13: values beyond +-2^17 saturate.
pub const NODE_MAX: i64 = (1 << 17) - 1;

/// Error changes of candidate `s` over `m L` steps for node `i` (`m = 2^i`:
/// 1, 2, 4, 8 for `i = 0..=3`), in 18-bit Q4.13 node registers.
///
/// Voltage part: with `u0 = 3 v - sum v` at `k` and `uh` the same of half the
/// capacitor-drift change `Delta v(L)/2` (option `capacitor_drift`), the
/// damped voltage term over `m L` is `m g3 (u0 + m uh) - m^2 gd u0`.
pub fn node_deltas(k: &Coeffs, c: &Common, s: [u8; 3], i: usize) -> [i32; 7] {
    let i = i.min(MAX_NODES - 1);
    let m = 1i64 << i;
    let inv = inverter_terms(c, s);
    let mut v0 = [0i64; 3];
    let mut vh = [0i64; 3];
    for ph in 0..3 {
        let pos = &anpc::TABLE[(s[ph] & 7) as usize];
        v0[ph] = pos.rail as i64 * k.v_dc_half as i64
            + pos.n_coef as i64 * c.v_n as i64
            + pos.ph_coef as i64 * c.v_ph[ph] as i64;
        if k.capacitor_drift {
            // Delta v_n = -inv[0], Delta v_ph = -inv[1+ph] (f27), halved.
            let dv = -(pos.n_coef as i64) * inv[0] - pos.ph_coef as i64 * inv[1 + ph];
            vh[ph] = rshift_round(dv, F_C + 1);
        }
    }
    let s0 = v0[0] + v0[1] + v0[2];
    let sh_ = vh[0] + vh[1] + vh[2];
    let mut d = [0i32; 7];
    for ph in 0..3 {
        let u0 = 3 * v0[ph] - s0;
        let uh = 3 * vh[ph] - sh_;
        // f27 products: g3 u0, g3 uh, gd u0.
        let g = m * (k.g3 as i64 * u0) + m * m * (k.g3 as i64 * uh) - m * m * (k.gd as i64 * u0);
        let v = c.dn[i][ph] as i64 - rshift_round(g, F_C);
        d[ph] = v.clamp(-NODE_MAX, NODE_MAX) as i32;
    }
    if k.current_midpoint {
        let cur = [d[0] as i64, d[1] as i64, d[2] as i64];
        let w = midpoint_inverter(k, c, s, cur, m, 0, c.dref[i]);
        for j in 0..4 {
            d[3 + j] = w[j] as i32;
        }
    } else {
        for j in 0..4 {
            d[3 + j] = rshift_round(m * inv[j], F_C).clamp(-NODE_MAX, NODE_MAX) as i32;
        }
    }
    d
}

/// Lazy check (Alg. 1, line 1): all seven `|y~(k+1)| <= y_bnd` with `s(k-1)`.
pub fn lazy_ok(k: &Coeffs, c: &Common, s_prev: [u8; 3]) -> bool {
    let d1 = deltas(k, c, s_prev, true);
    (0..7).all(|j| (c.e0[j] as i32 + d1[j] as i32).abs() <= k.bnd[j] as i32)
}

/// Smallest `M` with `2^M >= n` (at least 1).
fn bits_for(n: u32) -> u32 {
    (32 - (n.max(2) - 1).leading_zeros()).max(1)
}

/// `l_j` of one output over the interpolation pieces: the paper's single
/// chord (eq. 20) through `k` and `k+L`, or (`K` nodes at `k + 2^i L`,
/// `i < K`) the chords `[k, k+L]`, `[k+L, k+2L]`, `[k+2L, k+4L]`, ..., the
/// last one extended to `N_bar`. Piece `i >= 1` is `2^(i-1) L` long, a power
/// of two, so each piece is one exact Algorithm-2 search with its own cap;
/// the next piece is searched only when the previous one is capped (still
/// inside at its end). Returns `(l_j, cycles)`.
pub fn lane(k: &Coeffs, e0: i32, nodes: &Nodes, j: usize) -> (u32, u32) {
    let bnd = k.bnd[j] as i32;
    let lam = k.lambda;
    let big_l = 1u32 << lam;
    if k.nodes == 1 {
        let r = SearchRange {
            m_bits: k.m_bits,
            l_up: k.n_bar,
            l_low: 0,
        };
        let sr = binsearch::lj_search(e0, nodes[0][j], bnd, lam, r);
        return (sr.lj.value().unwrap_or(0), sr.cycles);
    }
    let kn = k.nodes as usize;
    let mut cycles = 0;
    for i in 0..kn {
        // Piece i: from node i-1 (or k) to node i.
        let (a, d, ls, start) = if i == 0 {
            (e0, nodes[0][j], lam, 0u32)
        } else {
            let ls = lam + i as u32 - 1;
            (
                e0 + nodes[i - 1][j],
                nodes[i][j] - nodes[i - 1][j],
                ls,
                big_l << (i - 1),
            )
        };
        let last = i + 1 == kn;
        let cap = if last { k.n_bar - start } else { 1u32 << ls };
        let r = SearchRange {
            m_bits: bits_for(cap),
            l_up: cap,
            l_low: 0,
        };
        let sr = binsearch::lj_search(a, d, bnd, ls, r);
        cycles += sr.cycles;
        match sr.lj {
            Lj::Capped(_) if !last => {}
            Lj::Capped(c) | Lj::Exact(c) => return (start + c, cycles),
            Lj::Below => return (start, cycles),
        }
    }
    (k.n_bar, cycles)
}

/// One explorer evaluation (Sec. VI) of candidate `s`.
pub fn explore(k: &Coeffs, c: &Common, s_prev: [u8; 3], s: [u8; 3]) -> ExplorerResult {
    let nodes: Nodes = core::array::from_fn(|i| {
        if i < k.nodes as usize {
            node_deltas(k, c, s, i)
        } else {
            [0; 7]
        }
    });
    let d = nodes[0].map(|v| sat16(v as i64));
    let d1 = if k.exact_first_step {
        Some(deltas(k, c, s, true))
    } else {
        None
    };
    let mut l_star = k.n_bar;
    let mut lane_cycles = 0;
    let mut j_dl = i32::MIN;
    for (j, &dj) in d.iter().enumerate() {
        let (lj, cyc) = lane(k, c.e0[j] as i32, &nodes, j);
        lane_cycles = lane_cycles.max(cyc);
        l_star = l_star.min(lj);
        // Error at k+1 for eq. (15): one-step prediction or interpolation.
        let e1 = match d1 {
            Some(d1) => c.e0[j] as i64 + d1[j] as i64,
            None => c.e0[j] as i64 + rshift_round(dj as i64, k.lambda),
        };
        j_dl = j_dl.max((e1.abs() - k.bnd[j] as i64) as i32);
    }
    if d1.is_some() {
        // Feasibility at k+1 decided by the one-step prediction: L* = 0 if it
        // leaves a bound (or a_j is already outside), else at least 1.
        let inside_k = (0..7).all(|j| (c.e0[j] as i32).abs() <= k.bnd[j] as i32);
        l_star = if j_dl > 0 || !inside_k {
            0
        } else {
            l_star.max(1)
        };
    }
    let fs = anpc::switch_transitions(s_prev, s);
    let cost = if l_star == 0 {
        COST_INF
    } else {
        let evn = sat16(c.e0[3] as i64 + v_n_change(k, &nodes, l_star));
        sequence_cost(k, fs, l_star, evn)
    };
    ExplorerResult {
        s,
        l_star,
        fs,
        cost,
        j_dl,
        lane_cycles,
        deltas: d,
    }
}

/// Interpolated change of the `v_n` error after `l` steps (for the terminal
/// weight), on the piece that contains `l` (the last piece extended).
fn v_n_change(k: &Coeffs, nodes: &Nodes, l: u32) -> i64 {
    lane_change(k, nodes, l, 3)
}

// --- switching-horizon hooks (used by `super::horizon_fixed`) ---

/// `J = f_s / l + lambda_n e_vn^2` (UQ15.17, saturated below
/// [`COST_INF`]) for `f_s` device turn-ons over `l >= 1` steps and the
/// terminal neutral-point error `e_vn` (Q2.13): `1/l` is
/// [`recip_word`]`(l)`, the reciprocal ROM's entry for `l <= N_bar`.
pub fn sequence_cost(k: &Coeffs, fs: u32, l: u32, evn: i16) -> u32 {
    let r = match k.recip.get(l as usize) {
        Some(&r) => r,
        None => recip_word(l),
    };
    let jsw = fs as u64 * r as u64; // f17
    let sq = evn as i64 * evn as i64; // f26
    let jl = rshift_round(sq * k.lambda_n as i64, 2 * F_I + F_LAMBDA - F_COST) as u64;
    (jsw + jl).min(COST_INF as u64 - 1) as u32
}

/// `round(2^17 / l)` (UQ1.17), 0 for `l = 0`: one word of the reciprocal ROM.
pub fn recip_word(l: u32) -> u32 {
    ((1u32 << F_RECIP) + l / 2).checked_div(l).unwrap_or(0)
}

/// Interpolated change of output lane `j` over `l` steps (Q2.13, not
/// saturated): the chord through `k` and node 0 up to `L`, then the piece
/// of the node polyline containing `l` (the search lanes' own model).
pub fn lane_change(k: &Coeffs, nodes: &Nodes, l: u32, j: usize) -> i64 {
    let lam = k.lambda;
    let big_l = 1u32 << lam;
    let n = |i: usize| nodes[i][j] as i64;
    if k.nodes == 1 || l <= big_l {
        return rshift_round(l as i64 * n(0), lam);
    }
    // Piece i >= 1 spans [2^(i-1) L, 2^i L], length 2^(i-1) L.
    let mut i = 1usize;
    while i + 1 < k.nodes as usize && l > big_l << i {
        i += 1;
    }
    let start = big_l << (i - 1);
    let ls = lam + i as u32 - 1;
    n(i - 1) + rshift_round((l - start) as i64 * (n(i) - n(i - 1)), ls)
}

// --- end of switching-horizon hooks ---

/// The FPGA MPDCC core: coefficients, the scheduler and `n` explorers.
#[derive(Debug, Clone)]
pub struct MpdccFixed {
    coeffs: Coeffs,
    cfg: FpgaConfig,
    last: Option<scheduler::Outcome>,
}

/// The explorer units as the scheduler sees them.
struct Units<'a> {
    k: &'a Coeffs,
    c: &'a Common,
    s_prev: [u8; 3],
}

impl Explorer for Units<'_> {
    fn evaluate(&mut self, s: [u8; 3]) -> ExplorerResult {
        explore(self.k, self.c, self.s_prev, s)
    }
}

impl MpdccFixed {
    /// Builds the core; rejects invalid parameters and coefficients that do
    /// not fit their formats.
    pub fn new(p: &DriveParams, cfg: FpgaConfig) -> Result<Self, FpgaError> {
        Self::build(p, cfg, &Structure::CORE)
    }

    /// A core with another datapath structure (the paper's, design sweeps):
    /// research only, not what the Verilog implements.
    #[cfg(feature = "mpdcc-research")]
    pub fn research(p: &DriveParams, cfg: FpgaConfig, st: Structure) -> Result<Self, FpgaError> {
        Self::build(p, cfg, &st)
    }

    fn build(p: &DriveParams, cfg: FpgaConfig, st: &Structure) -> Result<Self, FpgaError> {
        if !(1..=16).contains(&cfg.explorers) {
            return Err(FpgaError::Explorers);
        }
        Ok(Self {
            coeffs: Coeffs::new(p, &cfg, st)?,
            cfg,
            last: None,
        })
    }

    /// The design constants.
    pub fn coeffs(&self) -> &Coeffs {
        &self.coeffs
    }

    /// The configuration.
    pub fn config(&self) -> &FpgaConfig {
        &self.cfg
    }

    /// Details of the last decision (candidate results, cycles).
    pub fn last_outcome(&self) -> Option<&scheduler::Outcome> {
        self.last.as_ref()
    }

    /// One decision from already-quantized inputs (the bit-exact entry point
    /// a Verilog test bench drives).
    pub fn decide_raw(&self, x: &Inputs) -> scheduler::Outcome {
        decide(&self.coeffs, x, self.cfg.explorers)
    }
}

/// One decision of a core with constants `k` and `n` explorers from
/// already-quantized inputs: [`MpdccFixed::decide_raw`] for constants that
/// come from elsewhere (the register page of the simulated PL).
pub fn decide(k: &Coeffs, x: &Inputs, n: u32) -> scheduler::Outcome {
    let c = common_terms(k, x);
    let lazy = lazy_ok(k, &c, x.s_prev);
    let mut units = Units {
        k,
        c: &c,
        s_prev: x.s_prev,
    };
    // Cycle model of the configured explorer structure.
    let model = if k.nodes == 1 && !k.exact_first_step {
        super::cycles::CycleModel::paper()
    } else {
        super::cycles::CycleModel::default()
    };
    scheduler::run(x.s_prev, lazy, n, &model, &mut units)
}

impl Controller for MpdccFixed {
    fn name(&self) -> &'static str {
        "fpga"
    }

    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let x = Inputs::quantize(st)?;
        let out = self.decide_raw(&x);
        let d = out.decision;
        self.last = Some(out);
        Ok(d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The piecewise lane against a direct scan of the piecewise-linear
    /// interpolant in exact integer arithmetic: `L*_j` = largest `l <= N_bar`
    /// with every `l' in [0, l]` inside the bound. Nodes at `2^i L`.
    #[test]
    fn piecewise_lane_matches_scan() {
        let p = DriveParams::default();
        let f = MpdccFixed::new(&p, FpgaConfig::core(&p.machine)).unwrap();
        let k = f.coeffs();
        let kn = k.nodes as usize;
        assert!(kn >= 3);
        let big_l = 1i64 << k.lambda;
        let mut s: u64 = 0x1234_5678_9ABC_DEF1;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for _ in 0..20_000 {
            let v = next();
            let bnd = 1 + (v % 1200) as i64;
            let e0 = ((v >> 12) % 3000) as i64 - 1500;
            let mut nodes = [[0i32; 7]; MAX_NODES];
            let mut d = ((v >> 24) % 2001) as i64 - 1000;
            let mut w = next();
            for node in nodes.iter_mut().take(kn) {
                node[0] = d as i32;
                // Next node: roughly twice the change, with a random bend.
                d = 2 * d + (w % 801) as i64 - 400;
                w >>= 10;
            }
            let mut kk = k.clone();
            kk.bnd[0] = bnd as i16;
            let (lj, _) = lane(&kk, e0 as i32, &nodes, 0);
            let nv = |i: usize| e0 + nodes[i][0] as i64;
            // inside(l), scaled by the length of the piece containing l.
            let inside = |l: i64| -> bool {
                if l <= big_l {
                    return (e0 * big_l + l * nodes[0][0] as i64).abs() <= bnd * big_l;
                }
                let mut i = 1;
                while i + 1 < kn && l > big_l << i {
                    i += 1;
                }
                let (start, len) = (big_l << (i - 1), big_l << (i - 1));
                (nv(i - 1) * len + (l - start) * (nv(i) - nv(i - 1))).abs() <= bnd * len
            };
            let mut want = 0u32;
            if inside(0) {
                while (want as i64) < k.n_bar as i64 && inside(want as i64 + 1) {
                    want += 1;
                }
            }
            assert_eq!(lj, want, "e0={e0} nodes={:?} bnd={bnd}", &nodes[..kn]);
        }
    }

    /// The decision does not depend on the number of explorers (only the
    /// cycle count does), and more explorers never take more cycles.
    #[test]
    fn decision_independent_of_explorer_count() {
        let p = DriveParams::default();
        let mk = |n| {
            let mut c = FpgaConfig::core(&p.machine);
            c.explorers = n;
            MpdccFixed::new(&p, c).unwrap()
        };
        let (f1, f2, f6) = (mk(1), mk(2), mk(6));
        let mut searched = 0;
        for code in 0..512u32 {
            let th = code as f64 * 0.37;
            let st = CtrlState {
                x_m: [
                    libm::cos(th) + 0.1 * libm::sin(7.0 * th),
                    libm::sin(th) - 0.1 * libm::cos(5.0 * th),
                    0.3 * libm::cos(th) + 0.8 * libm::sin(th),
                    0.3 * libm::sin(th) - 0.8 * libm::cos(th),
                ],
                v_n_pu: 0.01,
                v_ph_pu: [0.48, 0.5, 0.47],
                omega_r_pu: 0.991,
                omega_s_pu: 1.0,
                i_ref_ab_pu: [libm::cos(th), libm::sin(th)],
                s_prev: [(code >> 6) as u8, ((code >> 3) & 7) as u8, (code & 7) as u8],
            };
            let x = Inputs::quantize(&st).unwrap();
            let (a, b, c) = (f1.decide_raw(&x), f2.decide_raw(&x), f6.decide_raw(&x));
            assert_eq!(a.decision, b.decision);
            assert_eq!(a.decision, c.decision);
            assert!(c.cycles <= b.cycles && b.cycles <= a.cycles);
            if !a.results.is_empty() {
                searched += 1;
                assert!(c.cycles < a.cycles);
            }
        }
        assert!(searched > 100);
    }
}
